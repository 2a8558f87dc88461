// Collision-free paths between two configurations (`cslice path`): a sequence of
// configurations, consecutive ones close enough that the straight motion between them
// (x, y and theta interpolated linearly, theta the short way round) is certified free by the
// clearance certificate below. docs/path.md describes the method and the output.
//
// The certificate. Let d_a and d_b be the clearances (smallest distance between the two
// parts) at two free configurations a and b, and R the moving part's reach (the farthest
// point of it from its body origin). On the straight motion from a to b no point of the
// moving part moves further than s = |p_b - p_a| + R |theta_b - theta_a| from where it was at
// a, nor from where it is at b; the distance between the parts changes no faster than the
// points move, so at every intermediate configuration it is at least (d_a + d_b - s) / 2.
// A step is certified when that bound exceeds the contact tolerance: every intermediate
// configuration is then free, as `classify` defines it.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "cslice/classify.hpp"
#include "cslice/space.hpp"

namespace cslice {

enum class PathStatus {
  found,                 // `poses` is a certified path from start to goal
  start_not_free,        // the start is blocked or in contact (`start` says which)
  goal_not_free,         // likewise the goal
  different_components,  // both free, in different 3D free components: no path exists
  not_found,             // one component, but no certified path was found (`problem` says where): a
              // passage narrower than twice the contact tolerance, or a numerical failure
};
std::string_view to_string(PathStatus s);

// What one end of the query is.
struct PathEnd {
  Placement placement = Placement::blocked;  // by the direct placement test (classify)
  int component = -1;                        // its 3D free component when free, else -1
  SegmentLabel contact{-1, -1};              // in contact: a touching moving and fixed feature
  double clearance = 0.0;                    // free: the smallest distance between the parts
};

struct PathOptions {
  // Replace runs of configurations by longer certified straight motions where possible.
  bool shortcut = true;
  // Give up (status not_found) after this many clearance evaluations.
  long max_evaluations = 1'000'000;
};

// How the answer was reached (for tests, benchmarks and reports).
struct PathStats {
  long clearance_evaluations = 0;  // placement tests with clearance
  int slices_computed = 0;         // slices computed beyond the stored ones
  int rotation_steps = 0;          // steps of the carries through theta
  int cells_on_route = 0;          // cells of the topology the route passes through
  int critical_crossings = 0;      // critical orientations crossed by the route
  int configurations_before_shortcut = 0;
};

struct PathResult {
  PathStatus status = PathStatus::not_found;
  PathEnd start, goal;
  int component = -1;  // found: the 3D free component of both ends
  // found: start first, goal last; theta in [-pi, pi). Consecutive configurations are
  // certified: clearance[i] + clearance[i + 1] - step_sweep(reach, poses[i], poses[i + 1])
  // exceeds twice the contact tolerance.
  std::vector<Pose> poses;
  std::vector<double> clearance;  // at each of `poses`
  double reach = 0.0;             // the moving part's reach R
  std::string problem;            // not found: where and why, in words
  PathStats stats;
};

// The bound s above on how far any point of the moving part moves on the straight motion
// from a to b (theta the short way round).
double step_sweep(double reach, const Pose& a, const Pose& b);

// Built once from a pair and its computed space (both must outlive it). Not thread-safe: it
// caches slices; make one per thread.
class PathPlanner {
 public:
  PathPlanner(const Pair& pair, const SlicedSpace& space, const PathOptions& options = {});
  ~PathPlanner();
  PathPlanner(const PathPlanner&) = delete;
  PathPlanner& operator=(const PathPlanner&) = delete;

  PathResult plan(const Pose& from, const Pose& to);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One query with a planner made for it.
PathResult find_path(const Pair& pair, const SlicedSpace& space, const Pose& from, const Pose& to,
                     const PathOptions& options = {});

}  // namespace cslice
