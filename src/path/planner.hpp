// The path planner's state and steps, shared by the files of src/path (docs/path.md).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cslice/path.hpp"
#include "cslice/query.hpp"
#include "path/certify.hpp"
#include "path/trapezoids.hpp"

namespace cslice {

using path_detail::Path;
using path_detail::Waypoint;

struct PathPlanner::Impl {
  Impl(const Pair& pair, const SlicedSpace& space, const PathOptions& options);
  PathResult plan(const Pose& from, const Pose& to);

  // ---- Ends and route (planner.cpp) ----
  PathEnd describe_end(const Pose& pose);
  // A path from the waypoint into the nearest stored slice of its interval, and the cell it
  // lands in there.
  struct Landing {
    Path path;
    int slice = -1, component = -1, cell = -1;
  };
  bool land(const Waypoint& w, Landing& out);
  // Cells from `from` to `to`, each step through one event: (transition, event, next cell).
  struct Hop {
    int transition = 0, event = 0, cell = 0;
  };
  struct BannedHop {
    int from = 0, transition = 0, event = 0, to = 0;
    friend bool operator==(const BannedHop&, const BannedHop&) = default;
  };
  bool cell_route(int from, int to, const std::vector<BannedHop>& banned,
                  std::vector<Hop>& hops) const;
  bool route(Path& path, const Landing& start, const Landing& goal);
  bool finish_route(Path& path, const Landing& goal);
  Path shortcut(const Path& in);
  // Re-checks every step of a path, subdividing a step that is not certified (only where two
  // motions meet with round-off between them); false if one cannot be.
  bool verify(Path& path);

  // ---- Motions (motions.cpp) ----
  const Slice& slice_at(double theta);  // theta wrapped: a stored slice or one computed
  path_detail::TrapezoidMap& map_of(const Slice& slice, int component, Vec2 p, Vec2 q);
  // Turns path.back() to the unwrapped `target` theta, keeping its clearance up by moving
  // it towards the middle of its slice's free component when it drops.
  bool carry(Path& path, double target);
  bool center(Path& path);
  // Translates path.back() to q inside its slice's free component; `guide` is the slice to
  // route in (default: the one at path.back()'s theta).
  // `budget` limits the evaluations (failing quietly when spent); -1: no limit.
  bool connect_in_slice(Path& path, Vec2 q, const Slice* guide = nullptr, long budget = -1);
  // The same for two points of one cell at one theta of its interval: in the slice, or when
  // that is long and narrow, in the middle of the interval.
  bool connect_in_cell(Path& path, Vec2 q, int interval, const Slice* guide);
  // Offset of theta from the start of interval i, in [0, length) when inside it (a theta
  // just before the start, on its critical orientation, gives a small negative offset).
  double interval_offset(int interval, double theta) const;
  int interval_of(double theta) const;
  // The unwrapped turn from `theta` (in `interval`) to offset `target` of the interval.
  double turn_to(int interval, double theta, double target) const;

  // ---- Crossing a critical orientation (crossing.cpp) ----
  bool cross(Path& path, int from_cell, const Hop& hop);
  // The component of the side slice (at offset `side_offset` of the cell's interval) that
  // the cell occupies, found by carrying the cell's sample there; -1 if that fails.
  int identify(int cell, double side_offset);

  bool fail(const std::string& why) {
    if (problem.empty()) problem = why;
    return false;
  }

  const Pair& pair;
  const SlicedSpace& space;
  PathOptions options;
  path_detail::Certifier cert;
  SpaceQuery query;
  std::vector<double> starts, ends;       // intervals, as in the topology
  std::vector<std::vector<int>> stored;   // per interval: its non-critical stored slices
  std::vector<int> critical_slices;       // per critical orientation: its stored slice
  std::map<double, const Slice*> slices;  // by theta: stored and computed slices
  std::map<double, std::unique_ptr<Slice>> computed;
  std::map<std::pair<const Slice*, int>, std::unique_ptr<path_detail::TrapezoidMap>> maps;
  std::map<std::pair<int, double>, int> identified;
  std::vector<std::vector<std::pair<int, int>>> cell_events;  // per cell: (transition, event)
  PathStats stats;
  std::string problem;
};

}  // namespace cslice
