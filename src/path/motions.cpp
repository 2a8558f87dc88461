// Motions of the path planner (docs/path.md): turning through theta while keeping clear of
// the fixed part (carry), moving towards the middle of a free component (center), and
// translating inside one slice's free component (connect_in_slice, through its trapezoid
// map). Every motion is certified waypoint by waypoint (src/path/certify.cpp).
#include <algorithm>
#include <cmath>

#include "parts/validate.hpp"
#include "path/planner.hpp"

namespace cslice {

namespace {

// A carry recentres when the clearance's margin above the floor has dropped below this share
// of its value after the last recentring: often enough that the turning steps (proportional to the
// clearance) stay long, rarely enough that the slices computed for it stay few.
constexpr double kRecenterBelow = 0.7;
// A recentring move is made only when it gains at least this factor of margin.
constexpr double kRecenterGain = 1.1;
// Longest turn of one carry step; the certificate allows a quarter turn per step.
constexpr double kMaxCarryStep = kPi / 8;
// Evaluations a single carry step may spend subdividing: its length is chosen so that one
// step is certified outright, so subdividing only absorbs round-off.
constexpr long kStepBudget = 64;
// Attempts at a route inside one slice, each closing a door where the last one failed.
constexpr int kRouteAttempts = 12;
// Evaluations a route inside a side slice may take before the route through the middle of
// the cell's interval is tried instead (typical routes take a few dozen).
constexpr long kSliceRouteBudget = 400;
// Stored slices this close in theta (radians) to a requested one stand in for it: the same
// orientation up to the round-off of the sums that produced the two values.
constexpr double kSameTheta = 1e-12;

// "at (x, y) past theta t", for a carry that stops.
std::string where_turning(const Pose& p) {
  return "at " + detail::format_point({p.x, p.y}) + " past theta " +
         detail::format_number(wrap_angle(p.theta));
}

}  // namespace

const Slice& PathPlanner::Impl::slice_at(double theta) {
  theta = wrap_angle(theta);
  auto it = slices.lower_bound(theta - kSameTheta);
  if (it != slices.end() && it->first <= theta + kSameTheta) return *it->second;
  auto slice = std::make_unique<Slice>(compute_slice(pair, theta));
  ++stats.slices_computed;
  const Slice* s = slice.get();
  computed[theta] = std::move(slice);
  slices[theta] = s;
  return *s;
}

path_detail::TrapezoidMap& PathPlanner::Impl::map_of(const Slice& slice, int component, Vec2 p,
                                                     Vec2 q) {
  auto& map = maps[{&slice, component}];
  if (map && map->covers(p) && map->covers(q)) return *map;
  // Around an unbounded component the frame must hold its cycles and both points with room
  // to pass around every cycle.
  const FreeComponent& fc = slice.free_components.at(component);
  Box box;
  for (const auto& cycle : fc.boundary)
    for (const ContactPiece& piece : cycle) box.add(bounding_box(piece.curve));
  box.add(p);
  box.add(q);
  const Box frame = box.inflated(std::max(box.diagonal(), pair.tol.size));
  map = std::make_unique<path_detail::TrapezoidMap>(fc, frame, pair.tol.geometric,
                                                    2.0 * cert.floor());
  return *map;
}

int PathPlanner::Impl::interval_of(double theta) const {
  const auto& criticals = space.criticals.orientations;
  if (criticals.empty()) return 0;
  theta = wrap_angle(theta);
  const auto it =
      std::upper_bound(criticals.begin(), criticals.end(), theta,
                       [](double t, const CriticalOrientation& o) { return t < o.theta; });
  const int k = static_cast<int>(it - criticals.begin()) - 1;
  return k < 0 ? static_cast<int>(criticals.size()) - 1 : k;
}

double PathPlanner::Impl::interval_offset(int interval, double theta) const {
  const double length = ends[interval] - starts[interval];
  double off = ccw_turn(starts[interval], wrap_angle(theta));
  if (off > length + 0.5 * (kTwoPi - length)) off -= kTwoPi;
  return off;
}

double PathPlanner::Impl::turn_to(int interval, double theta, double target) const {
  // With no critical orientation the one interval is the whole turn: either way round stays
  // in it, so take the shorter.
  if (space.criticals.orientations.empty())
    return wrap_angle(starts[interval] + target - wrap_angle(theta));
  return target - interval_offset(interval, theta);
}

bool PathPlanner::Impl::carry(Path& path, double target) {
  Waypoint cur = path.back();
  double reference = cur.clearance;
  while (cur.pose.theta != target) {
    if (cert.exhausted()) return fail("the evaluation budget ran out while turning");
    const double step =
        std::min(kMaxCarryStep, 0.5 * (cur.clearance - cert.floor()) / cert.reach());
    // Steps shrinking towards nothing: the free space narrows to the contact tolerance.
    if (step < pair.tol.critical_angle)
      return fail("the clearance vanishes turning " + where_turning(cur.pose));
    const double remaining = target - cur.pose.theta;
    Pose next = cur.pose;
    next.theta =
        std::fabs(remaining) <= step ? target : cur.pose.theta + std::copysign(step, remaining);
    if (!cert.straight(cur, next, path, kStepBudget))
      return fail("cannot turn " + where_turning(cur.pose));
    ++stats.rotation_steps;
    cur = path.back();
    // Margins above the floor, not clearances, decide: the steps are proportional to them.
    if (cur.clearance - cert.floor() < kRecenterBelow * (reference - cert.floor())) {
      center(path);
      cur = path.back();
      reference = cur.clearance;
    }
  }
  return true;
}

// Moves to the middle of the free component's cross-sections through the point, vertical
// then horizontal, twice: in a channel that puts it on the channel's middle line, in the
// cam's square on its centre. Cross-sections are capped at half the pair's size each way,
// so in open space the point moves no further than that.
bool PathPlanner::Impl::center(Path& path) {
  Waypoint cur = path.back();
  const Slice& s = slice_at(cur.pose.theta);
  const int comp = s.locate({cur.pose.x, cur.pose.y});
  if (comp < 0) return false;
  const FreeComponent& fc = s.free_components[comp];
  bool moved = false;
  // A bounded component's sample is about as far from its boundary as it gets: a better
  // start than the point's own neighbourhood, which may be a lobe that is closing.
  if (fc.bounded) {
    const auto w = cert.evaluate({fc.sample.x, fc.sample.y, cur.pose.theta});
    if (w && w->clearance - cert.floor() > kRecenterGain * (cur.clearance - cert.floor()) &&
        connect_in_slice(path, fc.sample, &s, kSliceRouteBudget)) {
      cur = path.back();
      moved = true;
    }
  }
  const double cap = 0.5 * pair.tol.size;
  for (int round = 0; round < 2; ++round) {
    for (Vec2 u : {Vec2{0.0, 1.0}, Vec2{1.0, 0.0}}) {
      const Vec2 p{cur.pose.x, cur.pose.y};
      const Curve line = make_segment(p - cap * u, p + cap * u);
      double lo = -cap, hi = cap;
      for (const auto& cycle : fc.boundary)
        for (const ContactPiece& piece : cycle) {
          const Intersection x = intersect(line, piece.curve, pair.tol.geometric);
          for (int h = 0; h < x.count; ++h)
            for (Vec2 q : {x.hits[h].point, x.hits[h].point_end}) {
              const double t = dot(q - p, u);
              if (t < 0)
                lo = std::max(lo, t);
              else
                hi = std::min(hi, t);
            }
        }
      const Vec2 m = p + (0.5 * (lo + hi)) * u;
      const Pose target{m.x, m.y, cur.pose.theta};
      const auto w = cert.evaluate(target);
      if (!w || w->clearance - cert.floor() < kRecenterGain * (cur.clearance - cert.floor()))
        continue;
      if (!cert.straight(cur, target, path)) continue;
      cur = path.back();
      moved = true;
    }
  }
  return moved;
}

bool PathPlanner::Impl::connect_in_slice(Path& path, Vec2 q, const Slice* guide, long budget) {
  const Waypoint start = path.back();
  const Vec2 p{start.pose.x, start.pose.y};
  if (p == q) return true;
  const double theta = start.pose.theta;
  const Slice& s = guide ? *guide : slice_at(theta);
  const int cp = s.locate(p), cq = s.locate(q);
  if (cp < 0 || cp != cq)
    return fail("the slice at theta " + detail::format_number(wrap_angle(theta)) +
                " does not put both points in one free component");
  path_detail::TrapezoidMap& map = map_of(s, cp, p, q);
  std::vector<char> banned(map.door_count(), 0);
  const size_t mark = path.size();
  const long limit = budget < 0 ? -1 : cert.evaluations() + budget;
  for (int attempt = 0; attempt < kRouteAttempts; ++attempt) {
    if (limit >= 0 && cert.evaluations() >= limit) break;
    const std::vector<path_detail::Leg> legs = map.route(p, q, banned);
    if (legs.empty()) break;
    bool ok = true;
    for (const path_detail::Leg& leg : legs) {
      const path_detail::Motion motion = [&map, leg, theta](double t) {
        const Vec2 v = map.at(leg, t);
        return Pose{v.x, v.y, theta};
      };
      const long left = limit < 0 ? -1 : std::max(0L, limit - cert.evaluations());
      if (cert.follow(motion, path.back(), path, left)) continue;
      // Close the door the failed leg was heading for (or leaving, on the last leg).
      const int door = leg.door_to >= 0 ? leg.door_to : leg.door_from;
      ok = false;
      if (door < 0) break;
      banned[door] = 1;
      break;
    }
    if (ok) return true;
    path.resize(mark);
  }
  path.resize(mark);
  if (budget >= 0) return false;  // the caller has another way
  return fail("no certified route inside the free component of the slice at theta " +
              detail::format_number(wrap_angle(theta)));
}

// A free component of a side slice can be a thin part of its cell (the fastener's slot just
// after it opens): routing through it there takes many tiny steps or fails. The cell is then
// usually wider in the middle of its interval, so both points are carried there and joined.
bool PathPlanner::Impl::connect_in_cell(Path& path, Vec2 q, int interval, const Slice* guide) {
  const std::string saved = problem;  // failures on the way here are not the answer
  if (connect_in_slice(path, q, guide, kSliceRouteBudget)) return true;
  problem = saved;
  const double theta = path.back().pose.theta;
  const double middle = 0.5 * (ends[interval] - starts[interval]);
  const double target = theta + turn_to(interval, theta, middle);
  const size_t mark = path.size();
  if (const auto w = cert.evaluate({q.x, q.y, theta})) {
    Path back{*w};
    if (carry(back, target) && carry(path, target) &&
        connect_in_slice(path, {back.back().pose.x, back.back().pose.y})) {
      path.insert(path.end(), back.rbegin() + 1, back.rend());
      return true;
    }
    path.resize(mark);
    problem = saved;
  }
  return connect_in_slice(path, q, guide);
}

}  // namespace cslice
