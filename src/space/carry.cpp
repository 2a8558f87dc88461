// Samples carried across a critical orientation, together (carry.hpp).
#include "space/carry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cslice::detail {

double sample_clearance(const Slice& s, int component) {
  const FreeComponent& c = s.free_components[component];
  double d = std::numeric_limits<double>::infinity();
  for (const auto& cycle : c.boundary)
    for (const ContactPiece& piece : cycle)
      d = std::min(d, distance_to_curve(piece.curve, c.sample));
  return d;
}

namespace {

// The turn the samples still on their way take together, or infinity when none is; those
// whose sample rule now holds land, those that cannot go on are lost.
double common_turn(std::vector<CarriedSample>& carried, const Slice& to, double eps, double reach,
                   double angular_tolerance, double turn_left) {
  double turn = std::numeric_limits<double>::infinity();
  for (CarriedSample& k : carried) {
    if (!k.active) continue;
    k.own_turn = 0.5 * (k.clearance - eps) / reach;
    if (k.clearance - eps > reach * turn_left) {
      k.landed = to.locate(k.p);  // its sample rule for the rest of the way
      k.active = false;
    } else if (!(k.own_turn > angular_tolerance) || k.steps >= kMaxCarrySteps) {
      k.active = false;
    } else {
      turn = std::min(turn, k.own_turn);
    }
  }
  return turn;
}

}  // namespace

int carry_samples(const Slice& from, std::vector<CarriedSample>& carried, const Slice& to,
                  double reach, double angular_tolerance,
                  const std::function<Slice(double theta)>& slice_at) {
  const double target = from.theta + wrap_angle(to.theta - from.theta);
  double theta = from.theta;
  int slices = 0;
  while (true) {
    const double turn =
        common_turn(carried, to, from.epsilon, reach, angular_tolerance, std::fabs(target - theta));
    if (turn == std::numeric_limits<double>::infinity()) return slices;
    const double next =
        target > theta ? std::min(target, theta + turn) : std::max(target, theta - turn);
    if (next == target) {
      for (CarriedSample& k : carried)
        if (k.active) k.landed = to.locate(k.p);
      return slices;
    }
    const Slice slice = slice_at(wrap_angle(next));
    ++slices;
    for (CarriedSample& k : carried) {
      if (!k.active) continue;
      const int d = slice.locate(k.p);
      k.active = d >= 0;
      if (d < 0) continue;
      k.p = slice.free_components[d].sample;
      k.clearance = sample_clearance(slice, d);
      k.steps += turn / k.own_turn;
    }
    theta = next;
  }
}

}  // namespace cslice::detail
