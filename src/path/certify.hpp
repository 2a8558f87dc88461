// The clearance certificate of include/cslice/path.hpp, and motions certified by it.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "cslice/classify.hpp"
#include "cslice/path.hpp"

namespace cslice::path_detail {

// A configuration of a path with its clearance. Along a path theta is unwrapped: consecutive
// waypoints differ by the turn actually made (at most a quarter turn), never by 2 pi.
struct Waypoint {
  Pose pose;
  double clearance = 0.0;
};

using Path = std::vector<Waypoint>;

// A motion as a curve of configurations over t in [0, 1].
using Motion = std::function<Pose(double)>;

class Certifier {
 public:
  Certifier(const Pair& pair, long max_evaluations);

  // The waypoint at pose when it is free with a certifiable clearance (above the floor).
  std::optional<Waypoint> evaluate(const Pose& pose);

  // Whether the straight motion between two waypoints is certified.
  bool step_ok(const Waypoint& a, const Waypoint& b) const;

  // Appends waypoints after `a` (which must be motion(0)) up to motion(1), each certified from
  // the one before, halving the parameter range of the motion where a step is not certified.
  // On failure (a configuration on the way not free, or the budget spent) `out` is left as it
  // was and false returned.
  bool follow(const Motion& motion, const Waypoint& a, Path& out, long budget = -1);
  // The straight motion from a to b (theta unwrapped: b.theta - a.theta is the turn).
  bool straight(const Waypoint& a, const Pose& b, Path& out, long budget = -1);

  double reach() const { return reach_; }
  // Clearance a certified step keeps at every intermediate configuration: the contact
  // tolerance and a thousandth of it more, so that round-off in the distances cannot matter.
  double floor() const { return floor_; }
  long evaluations() const { return evaluations_; }
  bool exhausted() const { return evaluations_ >= max_evaluations_; }

 private:
  bool follow_range(const Motion& motion, const Waypoint& a, double ta, const Waypoint& b,
                    double tb, Path& out, long limit, int depth);

  PlacementTester tester_;
  double reach_ = 0.0, floor_ = 0.0;
  double scene_ = 0.0;  // the pair's size: round-off in placing the parts is relative to it
  long evaluations_ = 0, max_evaluations_ = 0;
};

}  // namespace cslice::path_detail
