// Paths between two configurations (include/cslice/path.hpp, docs/path.md).
//
// Outline: each end is carried through theta into the nearest stored slice of its interval,
// which names its cell of the topology; a breadth-first search over the cells, joined by the
// events of the critical transitions, gives the cells to pass through; the path follows
// them, carrying through each interval and crossing each critical orientation through the
// event's slices (crossing.cpp), and ends inside the goal's slice and back along the goal's
// carry. Every step is certified as it is made; a final pass replaces runs of steps by longer
// certified straight motions.
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "path/planner.hpp"

namespace cslice {

namespace {

// Evaluations the first attempt, one straight certified motion from start to goal, may
// spend before the planner proper takes over.
constexpr long kDirectBudget = 256;
// Longest run of waypoints the shortcut pass tries to replace at once.
constexpr int kMaxShortcut = 256;
// Slices computed beyond the stored ones that a planner keeps between queries.
constexpr size_t kMaxCachedSlices = 4096;
// Cell routes tried, each without the crossings that failed before.
constexpr int kRouteAttempts = 6;

}  // namespace

std::string_view to_string(PathStatus s) {
  switch (s) {
    case PathStatus::found:
      return "found";
    case PathStatus::start_not_free:
      return "start_not_free";
    case PathStatus::goal_not_free:
      return "goal_not_free";
    case PathStatus::different_components:
      return "different_components";
    case PathStatus::not_found:
      return "not_found";
  }
  return "unknown";
}

PathPlanner::Impl::Impl(const Pair& p, const SlicedSpace& s, const PathOptions& o)
    : pair(p), space(s), options(o), cert(p, o.max_evaluations), query(p, s) {
  const auto& criticals = space.criticals.orientations;
  for (const CriticalOrientation& c : criticals) starts.push_back(c.theta);
  if (starts.empty()) starts.push_back(-kPi);
  for (size_t i = 0; i < starts.size(); ++i)
    ends.push_back(i + 1 < starts.size() ? starts[i + 1] : starts.front() + kTwoPi);
  stored.assign(starts.size(), {});
  critical_slices.assign(criticals.size(), -1);
  for (int i = 0; i < static_cast<int>(space.slices.size()); ++i) {
    const SpaceSlice& ss = space.slices[i];
    if (ss.kind == SliceKind::critical && !criticals.empty())
      critical_slices.at(ss.interval) = i;
    else
      stored.at(ss.interval).push_back(i);
  }
  cell_events.assign(space.topology.cells.size(), {});
  const auto& transitions = space.topology.transitions;
  for (int t = 0; t < static_cast<int>(transitions.size()); ++t)
    for (int e = 0; e < static_cast<int>(transitions[t].events.size()); ++e) {
      const TransitionEvent& ev = transitions[t].events[e];
      for (const auto* cells : {&ev.before, &ev.after})
        for (int c : *cells) cell_events.at(c).push_back({t, e});
    }
}

namespace {

// The feature of a part that an edge is (segments and arcs are features; vertices too).
int edge_feature(const Part& part, int loop, int index) {
  for (int f = 0; f < static_cast<int>(part.features.size()); ++f) {
    const Feature& feature = part.features[f];
    if (feature.kind != FeatureKind::vertex && feature.loop == loop && feature.index == index)
      return f;
  }
  return -1;
}

// The closest pair of a placed moving edge and a fixed edge, as features.
SegmentLabel nearest_features(const Pair& pair, const Pose& pose) {
  const Part moved = placed(pair.moving, pose);
  double best = std::numeric_limits<double>::infinity();
  SegmentLabel label{-1, -1};
  for (int ml = 0; ml < static_cast<int>(moved.loops.size()); ++ml)
    for (int mi = 0; mi < static_cast<int>(moved.loops[ml].edges.size()); ++mi)
      for (int fl = 0; fl < static_cast<int>(pair.fixed.loops.size()); ++fl)
        for (int fi = 0; fi < static_cast<int>(pair.fixed.loops[fl].edges.size()); ++fi) {
          const double d =
              distance_between(moved.loops[ml].edges[mi], pair.fixed.loops[fl].edges[fi]);
          if (d < best) {
            best = d;
            label = {edge_feature(pair.moving, ml, mi), edge_feature(pair.fixed, fl, fi)};
          }
        }
  return label;
}

}  // namespace

PathEnd PathPlanner::Impl::describe_end(const Pose& pose) {
  PathEnd end;
  PlacementTester tester(pair);
  end.placement = tester.classify(pose);
  const QueryAnswer a = query.query(pose);
  if (end.placement == Placement::free) {
    end.component = a.placement == Placement::free ? a.component : -1;
    end.clearance = tester.boundary_distance(pose);
    return end;
  }
  end.contact = a.placement == Placement::contact ? a.contact : nearest_features(pair, pose);
  return end;
}

bool PathPlanner::Impl::land(const Waypoint& w, Landing& out) {
  out.path = {w};
  const int interval = interval_of(w.pose.theta);
  double best_turn = std::numeric_limits<double>::infinity();
  for (int s : stored[interval]) {
    const double turn =
        turn_to(interval, w.pose.theta, interval_offset(interval, space.slices[s].theta));
    if (std::fabs(turn) < std::fabs(best_turn)) {
      best_turn = turn;
      out.slice = s;
    }
  }
  if (out.slice < 0) return fail("an interval without a stored slice");
  if (!carry(out.path, w.pose.theta + best_turn)) return false;
  const Waypoint& end = out.path.back();
  out.component = space.slices[out.slice].slice.locate({end.pose.x, end.pose.y});
  if (out.component < 0) return fail("a carried end left the free space of a stored slice");
  out.cell = space.topology.slice_cells.at(out.slice).at(out.component);
  return out.cell >= 0 || fail("a stored slice component without a cell");
}

bool PathPlanner::Impl::cell_route(int from, int to, const std::vector<BannedHop>& banned,
                                   std::vector<Hop>& hops) const {
  std::vector<Hop> reached_by(space.topology.cells.size(), Hop{-1, -1, -1});
  std::vector<int> previous(space.topology.cells.size(), -1);
  std::deque<int> queue{from};
  previous[from] = from;
  while (!queue.empty() && previous[to] < 0) {
    const int cell = queue.front();
    queue.pop_front();
    for (const auto& [t, e] : cell_events[cell]) {
      const TransitionEvent& ev = space.topology.transitions[t].events[e];
      for (const auto* cells : {&ev.before, &ev.after})
        for (int next : *cells) {
          if (previous[next] >= 0) continue;
          const BannedHop hop{cell, t, e, next};
          if (std::find(banned.begin(), banned.end(), hop) != banned.end()) continue;
          previous[next] = cell;
          reached_by[next] = {t, e, next};
          queue.push_back(next);
        }
    }
  }
  if (previous[to] < 0) return false;
  hops.clear();
  for (int c = to; c != from; c = previous[c]) hops.push_back(reached_by[c]);
  std::reverse(hops.begin(), hops.end());
  return true;
}

// Routes through the cells, and when one crossing cannot be made (a thin sliver of free space
// at a side slice, say), again without that crossing, a few times.
bool PathPlanner::Impl::route(Path& path, const Landing& start, const Landing& goal) {
  std::vector<BannedHop> banned;
  for (int attempt = 0; attempt < kRouteAttempts; ++attempt) {
    path = start.path;
    std::vector<Hop> hops;
    if (start.cell != goal.cell && !cell_route(start.cell, goal.cell, banned, hops))
      return fail("the topology joins no cells from the start's to the goal's");
    stats.cells_on_route = static_cast<int>(hops.size()) + 1;
    int cell = start.cell;
    bool crossed = true;
    for (const Hop& hop : hops) {
      if (!cross(path, cell, hop)) {
        banned.push_back({cell, hop.transition, hop.event, hop.cell});
        crossed = false;
        break;
      }
      cell = hop.cell;
    }
    if (crossed) return finish_route(path, goal);
    if (cert.exhausted()) return false;
  }
  return false;
}

// From the goal's cell into its stored slice, to where the goal's carry landed, and back
// along that carry.
bool PathPlanner::Impl::finish_route(Path& path, const Landing& goal) {
  const int interval = space.topology.cells.at(goal.cell).interval;
  const double target = interval_offset(interval, space.slices[goal.slice].theta);
  const double theta = path.back().pose.theta;
  if (!carry(path, theta + turn_to(interval, theta, target))) return false;
  const Waypoint& landed = goal.path.back();
  if (!connect_in_cell(path, {landed.pose.x, landed.pose.y}, interval,
                       &space.slices[goal.slice].slice))
    return false;
  // The goal's carry's thetas shifted by the whole turns the path made.
  const double shift = kTwoPi * std::round((path.back().pose.theta - landed.pose.theta) / kTwoPi);
  for (auto it = goal.path.rbegin() + 1; it != goal.path.rend(); ++it) {
    Waypoint w = *it;
    w.pose.theta += shift;
    path.push_back(w);
  }
  return true;
}

bool PathPlanner::Impl::verify(Path& path) {
  Path out{path.front()};
  for (size_t i = 1; i < path.size(); ++i) {
    if (cert.step_ok(out.back(), path[i])) {
      out.push_back(path[i]);
      continue;
    }
    if (!cert.straight(out.back(), path[i].pose, out))
      return fail("a step of the assembled path cannot be certified");
  }
  path = std::move(out);
  return true;
}

// Greedy: from each waypoint, the longest run (doubling its length while it succeeds) that
// one straight certified motion with fewer waypoints replaces.
Path PathPlanner::Impl::shortcut(const Path& in) {
  Path out{in.front()};
  Path piece, best;
  size_t i = 0;
  while (i + 1 < in.size()) {
    size_t best_j = i + 1;
    best = {in[i + 1]};
    for (size_t w = 2; w <= static_cast<size_t>(kMaxShortcut); w *= 2) {
      const size_t j = std::min(in.size() - 1, i + w);
      if (j <= best_j) break;
      piece.clear();
      if (!cert.straight(out.back(), in[j].pose, piece, static_cast<long>(j - i - 1)) ||
          piece.size() >= j - i)
        break;
      best_j = j;
      best = piece;
    }
    out.insert(out.end(), best.begin(), best.end());
    i = best_j;
  }
  return out;
}

PathResult PathPlanner::Impl::plan(const Pose& from_asked, const Pose& to_asked) {
  // Far orientations as their principal angles: the motions add steps to the start's theta,
  // and at 1e15 rad those sums were rounded to an eighth of a radian.
  const Pose from{from_asked.x, from_asked.y, principal_angle(from_asked.theta)};
  const Pose to{to_asked.x, to_asked.y, principal_angle(to_asked.theta)};
  // Slices, their trapezoid maps and the cells' components at side slices depend only on the
  // space: kept for later queries (side slices are needed again and again), up to a bound.
  if (computed.size() > kMaxCachedSlices) {
    computed.clear();
    maps.clear();
    slices.clear();
  }
  if (slices.empty())
    for (const SpaceSlice& s : space.slices) slices[s.theta] = &s.slice;
  stats = {};
  problem.clear();
  const long evaluations_before = cert.evaluations();

  PathResult r;
  r.reach = cert.reach();
  r.start = describe_end(from);
  r.goal = describe_end(to);
  const auto finish = [&](PathStatus status) {
    r.status = status;
    if (status != PathStatus::found) r.problem = problem;
    stats.clearance_evaluations = cert.evaluations() - evaluations_before;
    r.stats = stats;
    return r;
  };
  if (r.start.placement != Placement::free) return finish(PathStatus::start_not_free);
  if (r.goal.placement != Placement::free) return finish(PathStatus::goal_not_free);
  if (r.start.component >= 0 && r.goal.component >= 0 && r.start.component != r.goal.component)
    return finish(PathStatus::different_components);

  const auto ws = cert.evaluate(from);
  Pose goal = to;
  goal.theta = from.theta + wrap_angle(to.theta - from.theta);
  const auto wg = cert.evaluate(goal);
  if (!ws || !wg) {
    fail(std::string(ws ? "the goal" : "the start") +
         " is free but within a thousandth of the contact tolerance of contact");
    return finish(PathStatus::not_found);
  }
  Path path{*ws};
  bool found = cert.straight(*ws, goal, path, kDirectBudget);
  if (!found) {
    Landing start, end;
    if (!land(*ws, start) || !land(*wg, end)) return finish(PathStatus::not_found);
    // An end the point query could not place (inside the contact band by its own
    // evaluation) takes the component of the cell it landed in.
    if (r.start.component < 0) r.start.component = space.topology.cells[start.cell].component;
    if (r.goal.component < 0) r.goal.component = space.topology.cells[end.cell].component;
    if (r.start.component != r.goal.component) return finish(PathStatus::different_components);
    found = route(path, start, end) && verify(path);
  }
  if (!found) return finish(PathStatus::not_found);
  stats.configurations_before_shortcut = static_cast<int>(path.size());
  if (options.shortcut) path = shortcut(path);
  r.component = r.start.component >= 0 ? r.start.component : r.goal.component;
  // Principal angles, not wrap_angle's: an orientation already in [-pi, pi) is printed as
  // given (wrap_angle(0.3) is 0.2999999999999998), so the path ends exactly where asked.
  for (const Waypoint& w : path) {
    r.poses.push_back({w.pose.x, w.pose.y, principal_angle(w.pose.theta)});
    r.clearance.push_back(w.clearance);
  }
  r.poses.front() = from;
  r.poses.back() = to;
  return finish(PathStatus::found);
}

PathPlanner::PathPlanner(const Pair& pair, const SlicedSpace& space, const PathOptions& options)
    : impl_(std::make_unique<Impl>(pair, space, options)) {}
PathPlanner::~PathPlanner() = default;

PathResult PathPlanner::plan(const Pose& from, const Pose& to) {
  return impl_->plan(from, to);
}

PathResult find_path(const Pair& pair, const SlicedSpace& space, const Pose& from, const Pose& to,
                     const PathOptions& options) {
  PathPlanner planner(pair, space, options);
  return planner.plan(from, to);
}

}  // namespace cslice
