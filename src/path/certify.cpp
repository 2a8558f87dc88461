// The clearance certificate (include/cslice/path.hpp, docs/path.md).
//
// Derivation. A point q of the moving part (body frame) is at p + R(theta) q. On the straight
// motion from a to b, at parameter t its position moves from the one at a by
//   |t (p_b - p_a) + (R(theta_a + t dtheta) - R(theta_a)) q|
//     <= t |p_b - p_a| + 2 |q| sin(t |dtheta| / 2) <= t (|p_b - p_a| + |q| |dtheta|),
// and |q| <= reach, so by at most t s with s = |p_b - p_a| + reach |dtheta|; likewise by at
// most (1 - t) s from its position at b. The distance D between two sets changes by no more
// than the largest displacement of a point of one of them, so
//   D(t) >= max(d_a - t s, d_b - (1 - t) s) >= (d_a + d_b - s) / 2.
// With D(t) above the contact tolerance the parts neither overlap nor come within the
// tolerance: the configuration is free by `classify`. At a free configuration the parts'
// interiors are disjoint, so D is the smallest distance between their boundaries
// (PlacementTester::boundary_distance).
#include "path/certify.hpp"

#include <algorithm>
#include <cmath>

namespace cslice {

double step_sweep(double reach, const Pose& a, const Pose& b) {
  const double turn = std::fabs(wrap_angle(b.theta - a.theta));
  return std::hypot(b.x - a.x, b.y - a.y) + reach * turn;
}

namespace path_detail {
namespace {

// Halvings of a motion's parameter range before giving up on it: with clearance above the
// floor everywhere a motion needs far fewer; this only stops a motion that grazes contact.
constexpr int kMaxDepth = 48;
// Relative margin of the floor over the contact tolerance (see Certifier::floor).
constexpr double kFloorMargin = 1e-3;
// The largest turn of one step: the short way round must be the turn made.
constexpr double kMaxStepTurn = kPi / 4;

}  // namespace

Certifier::Certifier(const Pair& pair, long max_evaluations)
    : tester_(pair),
      reach_(moving_reach(pair.moving)),
      floor_(pair.tol.contact * (1.0 + kFloorMargin)),
      scene_(pair.tol.size),
      max_evaluations_(max_evaluations) {}

std::optional<Waypoint> Certifier::evaluate(const Pose& pose) {
  ++evaluations_;
  const Pose wrapped{pose.x, pose.y, wrap_angle(pose.theta)};
  if (tester_.classify(wrapped) != Placement::free) return std::nullopt;
  const double d = tester_.boundary_distance(wrapped);
  if (!(d > floor_)) return std::nullopt;
  return Waypoint{pose, d};
}

bool Certifier::step_ok(const Waypoint& a, const Waypoint& b) const {
  const double turn = std::fabs(b.pose.theta - a.pose.theta);
  if (turn > kMaxStepTurn) return false;
  const double sweep = std::hypot(b.pose.x - a.pose.x, b.pose.y - a.pose.y) + reach_ * turn;
  // Placements far out are rounded to their coordinates' last place, and so are the
  // clearances measured there (kPathRelativeRounding).
  const double magnitude = scene_ + sweep + a.clearance + b.clearance + std::fabs(a.pose.x) +
                           std::fabs(a.pose.y) + std::fabs(b.pose.x) + std::fabs(b.pose.y);
  return sweep < a.clearance + b.clearance - 2.0 * floor_ - kPathRelativeRounding * magnitude;
}

bool Certifier::follow(const Motion& motion, const Waypoint& a, Path& out, long budget) {
  const size_t mark = out.size();
  const long limit =
      budget < 0 ? max_evaluations_ : std::min(max_evaluations_, evaluations_ + budget);
  const std::optional<Waypoint> b = evaluate(motion(1.0));
  if (b && follow_range(motion, a, 0.0, *b, 1.0, out, limit, 0)) return true;
  out.resize(mark);
  return false;
}

bool Certifier::straight(const Waypoint& a, const Pose& b, Path& out, long budget) {
  const Pose p = a.pose;
  const Motion line = [p, b](double t) {
    return Pose{p.x + t * (b.x - p.x), p.y + t * (b.y - p.y), p.theta + t * (b.theta - p.theta)};
  };
  return follow(line, a, out, budget);
}

bool Certifier::follow_range(const Motion& motion, const Waypoint& a, double ta, const Waypoint& b,
                             double tb, Path& out, long limit, int depth) {
  if (step_ok(a, b)) {
    out.push_back(b);
    return true;
  }
  if (depth >= kMaxDepth || evaluations_ >= limit) return false;
  const double tm = 0.5 * (ta + tb);
  const std::optional<Waypoint> m = evaluate(motion(tm));
  if (!m) return false;
  return follow_range(motion, a, ta, *m, tm, out, limit, depth + 1) &&
         follow_range(motion, *m, tm, b, tb, out, limit, depth + 1);
}

}  // namespace path_detail
}  // namespace cslice
