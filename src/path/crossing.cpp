// Crossing a critical orientation along one event of the topology (docs/path.md).
//
// The topology joins cells across critical orientation theta_k through three slices: the
// side slice before it (theta_k - side_before), the critical slice and the side slice after
// it (theta_k + side_after). Its join rules relate components of those slices when one's
// sample lies in the other (src/space/topology.cpp, `transition`). Each such relation is a
// motion here: the sample turned, at a fixed position, from one slice's theta to the
// other's, certified like every other step. Within one slice's component any two points are
// connected by connect_in_slice. A breadth-first search over the components, joined by the
// certified relations, leads from the component the path arrives in to one of the next cell.
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "parts/validate.hpp"
#include "path/planner.hpp"

namespace cslice {

namespace {

// A component of one of the three slices: 0 before, 1 critical, 2 after.
struct Place {
  int side = 0, component = 0;
  friend bool operator==(const Place&, const Place&) = default;
};

struct Relation {
  Relation(Place from, Place to, Vec2 at) : a(from), b(to), point(at) {}
  Place a, b;
  Vec2 point;     // turned from a's theta to b's
  int state = 0;  // 0 not tried, 1 certified, -1 failed
  Path motion;    // from a to b once certified
};

bool contains(const std::vector<int>& v, int x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

bool contains_place(const std::vector<Place>& v, const Place& p) {
  return std::find(v.begin(), v.end(), p) != v.end();
}

// The join rules, as motions: a sample of the before or after slice found in the critical
// slice relates the two; found in the critical slice and on the other side as well, it
// relates the two sides directly; a sample of the critical slice relates it to each side it
// is found in.
std::vector<Relation> relations(const Slice* const (&s)[3]) {
  std::vector<Relation> out;
  for (int side = 0; side < 3; ++side)
    for (const FreeComponent& c : s[side]->free_components) {
      int at[3];
      for (int o = 0; o < 3; ++o) at[o] = o == side ? c.id : s[o]->locate(c.sample);
      const Place from{side, c.id};
      if (side == 1) {
        for (int o : {0, 2})
          if (at[o] >= 0) out.emplace_back(from, Place{o, at[o]}, c.sample);
        continue;
      }
      if (at[1] < 0) continue;
      out.emplace_back(from, Place{1, at[1]}, c.sample);
      if (at[2 - side] >= 0) out.emplace_back(from, Place{2 - side, at[2 - side]}, c.sample);
    }
  return out;
}

}  // namespace

int PathPlanner::Impl::identify(int cell, double side_offset) {
  const auto key = std::make_pair(cell, side_offset);
  if (const auto it = identified.find(key); it != identified.end()) return it->second;
  int component = -1;
  const SpaceCell& c = space.topology.cells.at(cell);
  const std::string saved = problem;
  if (const auto w = cert.evaluate({c.sample.x, c.sample.y, c.sample_theta})) {
    Path path{*w};
    const double turn = turn_to(c.interval, c.sample_theta, side_offset);
    if (carry(path, c.sample_theta + turn))
      component = slice_at(path.back().pose.theta).locate({path.back().pose.x, path.back().pose.y});
  }
  problem = saved;  // a failure here only means the caller cannot tell the cells apart
  identified[key] = component;
  return component;
}

bool PathPlanner::Impl::cross(Path& path, int from_cell, const Hop& hop) {
  const CriticalTransition& t = space.topology.transitions.at(hop.transition);
  const TransitionEvent& e = t.events.at(hop.event);
  const int interval = space.topology.cells.at(from_cell).interval;
  const double length = ends[interval] - starts[interval];
  const double theta = path.back().pose.theta;
  // Side of the event the path is on: before if its cell ends at theta_k, after if it
  // starts there (both with a single critical orientation: then the nearer).
  const double inf = std::numeric_limits<double>::infinity();
  const double to_before =
      contains(e.before, from_cell) ? turn_to(interval, theta, length - t.side_before) : inf;
  const double to_after =
      contains(e.after, from_cell) ? turn_to(interval, theta, t.side_after) : inf;
  const int side = std::fabs(to_before) <= std::fabs(to_after) ? 0 : 2;
  if (!carry(path, theta + (side == 0 ? to_before : to_after))) return false;

  // Unwrapped thetas of the three slices, from the one the path is at.
  double th[3];
  th[side] = path.back().pose.theta;
  if (side == 0) {
    th[1] = th[0] + t.side_before;
    th[2] = th[1] + t.side_after;
  } else {
    th[1] = th[2] - t.side_after;
    th[0] = th[1] - t.side_before;
  }
  const Slice* const s[3] = {&slice_at(t.theta - t.side_before),
                             &space.slices.at(critical_slices.at(t.critical)).slice,
                             &slice_at(t.theta + t.side_after)};
  const Vec2 here{path.back().pose.x, path.back().pose.y};
  const Place source{side, s[side]->locate(here)};
  if (source.component < 0) return fail("lost the free component at a side slice");

  // Where the next cell is: any component of its side reached, when the event has no other
  // cell on that side; otherwise the one its sample is carried into.
  std::vector<Place> targets;
  const auto add_targets = [&](const std::vector<int>& cells, int target_side, double offset) {
    if (!contains(cells, hop.cell)) return;
    if (cells.size() == 1) {
      for (int c = 0; c < static_cast<int>(s[target_side]->free_components.size()); ++c)
        targets.push_back({target_side, c});
      return;
    }
    const int c = identify(hop.cell, offset);
    if (c >= 0) targets.push_back({target_side, c});
  };
  const int next_interval = space.topology.cells.at(hop.cell).interval;
  add_targets(e.before, 0, (ends[next_interval] - starts[next_interval]) - t.side_before);
  add_targets(e.after, 2, t.side_after);
  if (targets.empty()) return fail("cannot tell the next cell's component at a side slice");

  std::vector<Relation> rel = relations(s);
  const auto certify = [&](Relation& r) {
    if (r.state != 0) return r.state > 0;
    r.state = -1;
    const auto w = cert.evaluate({r.point.x, r.point.y, th[r.a.side]});
    if (!w) return false;
    Path motion{*w};
    if (!cert.straight(*w, {r.point.x, r.point.y, th[r.b.side]}, motion)) return false;
    r.motion = std::move(motion);
    r.state = 1;
    return true;
  };

  // Breadth-first over places; parent[] holds the relation that reached each one.
  std::vector<std::pair<Place, int>> parent{{source, -1}};
  std::deque<size_t> queue{0};
  int reached = -1;
  const auto seen = [&](const Place& p) {
    return std::any_of(parent.begin(), parent.end(), [&](const auto& q) { return q.first == p; });
  };
  while (!queue.empty() && reached < 0) {
    const size_t at = queue.front();
    queue.pop_front();
    const Place here_place = parent[at].first;
    if (contains_place(targets, here_place)) {
      reached = static_cast<int>(at);
      break;
    }
    for (int r = 0; r < static_cast<int>(rel.size()); ++r) {
      const bool forward = rel[r].a == here_place, backward = rel[r].b == here_place;
      if (!forward && !backward) continue;
      const Place next = forward ? rel[r].b : rel[r].a;
      if (seen(next) || !certify(rel[r])) continue;
      parent.push_back({next, forward ? r : -2 - r});
      queue.push_back(parent.size() - 1);
    }
  }
  if (reached < 0)
    return fail("no certified way through critical orientation " + std::to_string(t.critical) +
                " (theta " + detail::format_number(t.theta) + ")");
  // The relations from the source to the target, in order.
  std::vector<int> chain;
  for (int at = reached; parent[at].second != -1;) {
    const int code = parent[at].second;
    chain.push_back(code);
    const Relation& r = rel[code >= 0 ? code : -2 - code];
    const Place prev = code >= 0 ? r.a : r.b;
    at = static_cast<int>(
        std::find_if(parent.begin(), parent.end(), [&](const auto& q) { return q.first == prev; }) -
        parent.begin());
  }
  std::reverse(chain.begin(), chain.end());
  for (int code : chain) {
    const Relation& r = rel[code >= 0 ? code : -2 - code];
    Path motion = r.motion;
    if (code < 0) std::reverse(motion.begin(), motion.end());
    const int from_side = code >= 0 ? r.a.side : r.b.side;
    const bool joined =
        from_side == 1
            ? connect_in_slice(path, r.point, s[1])
            : connect_in_cell(path, r.point, from_side == 0 ? t.interval_before : t.interval_after,
                              s[from_side]);
    if (!joined) return false;
    path.insert(path.end(), motion.begin() + 1, motion.end());
  }
  ++stats.critical_crossings;
  return true;
}

}  // namespace cslice
