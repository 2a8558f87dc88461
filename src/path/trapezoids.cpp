// The vertical decomposition of a free component (src/path/trapezoids.hpp).
//
// Every boundary piece has the component on its left, so an x-monotone piece running towards
// +x has free space above it (a floor) and one running towards -x below it (a ceiling).
// Arcs are cut at their leftmost and rightmost points; vertical segments bound no slab and
// are left out. Walls stand at the x of every piece end; between two consecutive walls no
// piece ends, so the pieces crossing the slab keep their vertical order, and each floor
// directly below a ceiling bounds one trapezoid. Two trapezoids of neighbouring slabs meet
// where their vertical extents at the shared wall overlap: a piece through that overlap would
// bound one of them inside it.
#include "path/trapezoids.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace cslice::path_detail {

TrapezoidMap::TrapezoidMap(const FreeComponent& component, const Box& frame, double eps,
                           double min_door)
    : bounded_(component.bounded), frame_(frame), eps_(eps) {
  for (const auto& cycle : component.boundary)
    for (const ContactPiece& piece : cycle) add_piece(piece.curve);
  if (!bounded_) {
    // Counterclockwise, the free space inside: a floor at the bottom, a ceiling at the top.
    add_piece(make_segment(frame.lo, {frame.hi.x, frame.lo.y}));
    add_piece(make_segment(frame.hi, {frame.lo.x, frame.hi.y}));
  }
  build_walls(eps);
  build_trapezoids();
  build_doors(min_door);
}

void TrapezoidMap::add_piece(const Curve& c) {
  if (c.is_segment()) {
    add_monotone(c);
    return;
  }
  // Cut where the angle passes a multiple of pi (the circle's leftmost and rightmost points).
  const double a0 = c.start_angle, sweep = c.sweep;
  const double lo = std::min(a0, a0 + sweep), hi = std::max(a0, a0 + sweep);
  std::vector<double> cuts{0.0, 1.0};
  for (double k = std::ceil(lo / kPi); k * kPi < hi; k += 1.0) {
    const double t = (k * kPi - a0) / sweep;
    if (t > 0.0 && t < 1.0) cuts.push_back(t);
  }
  std::sort(cuts.begin(), cuts.end());
  Vec2 from = c.from;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    Curve part =
        make_arc(c.center, c.radius, a0 + sweep * cuts[i], sweep * (cuts[i + 1] - cuts[i]));
    part.from = from;
    if (i + 2 == cuts.size()) part.to = c.to;
    from = part.to;
    add_monotone(part);
  }
}

void TrapezoidMap::add_monotone(const Curve& c) {
  Piece p;
  p.curve = c;
  p.floor = c.to.x > c.from.x;
  p.x0 = std::min(c.from.x, c.to.x);
  p.x1 = std::max(c.from.x, c.to.x);
  if (c.is_arc()) {
    const double mid = c.start_angle + 0.5 * c.sweep;
    p.upper = std::sin(mid) > 0.0;
  }
  pieces_.push_back(p);
}

// Walls: piece ends' x, those closer than eps merged into one.
void TrapezoidMap::build_walls(double eps) {
  std::vector<double> xs;
  for (const Piece& p : pieces_) xs.insert(xs.end(), {p.x0, p.x1});
  std::sort(xs.begin(), xs.end());
  for (double x : xs)
    if (walls_.empty() || x - walls_.back() > eps) walls_.push_back(x);
  const auto wall_of = [&](double x) {
    const auto it = std::lower_bound(walls_.begin(), walls_.end(), x - eps);
    return static_cast<int>(it - walls_.begin());
  };
  for (Piece& p : pieces_) {
    p.e0 = wall_of(p.x0);
    p.e1 = wall_of(p.x1);
  }
}

void TrapezoidMap::build_trapezoids() {
  const int slabs = std::max(0, static_cast<int>(walls_.size()) - 1);
  std::vector<std::vector<int>> crossing(slabs);
  for (int i = 0; i < static_cast<int>(pieces_.size()); ++i)
    for (int j = pieces_[i].e0; j < pieces_[i].e1; ++j) crossing[j].push_back(i);
  slab_traps_.assign(slabs, {});
  std::vector<std::pair<double, int>> order;
  for (int j = 0; j < slabs; ++j) {
    const double xm = 0.5 * (walls_[j] + walls_[j + 1]);
    order.clear();
    for (int i : crossing[j]) order.push_back({y_at(i, xm), i});
    std::sort(order.begin(), order.end());
    for (size_t k = 0; k + 1 < order.size(); ++k) {
      const int lo = order[k].second, hi = order[k + 1].second;
      if (!pieces_[lo].floor || pieces_[hi].floor) continue;
      slab_traps_[j].push_back(static_cast<int>(traps_.size()));
      traps_.push_back({j, lo, hi});
    }
  }
}

// Doors across each wall: the trapezoids on either side are in vertical order, so one merge
// pass finds every overlap.
void TrapezoidMap::build_doors(double min_door) {
  trap_doors_.assign(traps_.size(), {});
  for (int j = 0; j + 1 < static_cast<int>(slab_traps_.size()); ++j) {
    const double x = walls_[j + 1];
    const std::vector<int>&left = slab_traps_[j], &right = slab_traps_[j + 1];
    size_t a = 0, b = 0;
    while (a < left.size() && b < right.size()) {
      const Trap &ta = traps_[left[a]], &tb = traps_[right[b]];
      const double ha = y_at(ta.hi, x), hb = y_at(tb.hi, x);
      const double lo = std::max(y_at(ta.lo, x), y_at(tb.lo, x)), hi = std::min(ha, hb);
      if (hi - lo > min_door) {
        const int id = static_cast<int>(doors_.size());
        doors_.push_back({{x, 0.5 * (lo + hi)}, left[a], right[b]});
        trap_doors_[left[a]].push_back(id);
        trap_doors_[right[b]].push_back(id);
      }
      (ha < hb ? a : b) += 1;
    }
  }
}

double TrapezoidMap::y_at(int piece, double x) const {
  const Piece& p = pieces_[piece];
  const Curve& c = p.curve;
  x = std::clamp(x, p.x0, p.x1);
  if (c.is_segment()) {
    const double t = (x - c.from.x) / (c.to.x - c.from.x);
    return c.from.y + std::clamp(t, 0.0, 1.0) * (c.to.y - c.from.y);
  }
  const double dx = std::clamp(x - c.center.x, -c.radius, c.radius);
  const double h = std::sqrt(std::max(0.0, c.radius * c.radius - dx * dx));
  return p.upper ? c.center.y + h : c.center.y - h;
}

bool TrapezoidMap::covers(Vec2 p) const {
  return bounded_ ||
         (p.x > frame_.lo.x && p.x < frame_.hi.x && p.y > frame_.lo.y && p.y < frame_.hi.y);
}

// The trapezoid whose interior holds p; on a wall, either neighbour's.
int TrapezoidMap::locate(Vec2 p) const {
  const int slabs = static_cast<int>(slab_traps_.size());
  const int j =
      static_cast<int>(std::upper_bound(walls_.begin(), walls_.end(), p.x) - walls_.begin()) - 1;
  for (int s : {j, j - 1, j + 1}) {
    if (s < 0 || s >= slabs || p.x < walls_[s] - eps_ || p.x > walls_[s + 1] + eps_) continue;
    for (int t : slab_traps_[s])
      if (y_at(traps_[t].lo, p.x) < p.y && p.y < y_at(traps_[t].hi, p.x)) return t;
  }
  return -1;
}

double TrapezoidMap::fraction(int trap, Vec2 p) const {
  const double lo = y_at(traps_[trap].lo, p.x), hi = y_at(traps_[trap].hi, p.x);
  return hi > lo ? std::clamp((p.y - lo) / (hi - lo), 0.0, 1.0) : 0.5;
}

Vec2 TrapezoidMap::at(const Leg& leg, double t) const {
  if (t <= 0.0) return leg.from;
  if (t >= 1.0) return leg.to;
  const double x = leg.from.x + t * (leg.to.x - leg.from.x);
  const double u0 = fraction(leg.trap, leg.from), u1 = fraction(leg.trap, leg.to);
  const double u = u0 + t * (u1 - u0);
  const double lo = y_at(traps_[leg.trap].lo, x), hi = y_at(traps_[leg.trap].hi, x);
  return {x, lo + u * (hi - lo)};
}

// Dijkstra over the doors' midpoints (nodes 2 + door), from p (node 0) to q (node 1); two
// nodes are joined when they lie on one trapezoid.
std::vector<Leg> TrapezoidMap::route(Vec2 p, Vec2 q, const std::vector<char>& banned) const {
  const int tp = covers(p) ? locate(p) : -1, tq = covers(q) ? locate(q) : -1;
  if (tp < 0 || tq < 0) return {};
  if (tp == tq) return {Leg{tp, p, q, -1, -1}};
  const int n = 2 + static_cast<int>(doors_.size());
  const auto point = [&](int node) { return node == 0 ? p : node == 1 ? q : doors_[node - 2].at; };
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<int> prev(n, -1), via(n, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> heap;
  dist[0] = 0.0;
  heap.push({0.0, 0});
  const auto relax = [&](int from, int trap) {
    const auto visit = [&](int to) {
      if (to == from || (to >= 2 && banned.size() > size_t(to - 2) && banned[to - 2])) return;
      const double d = dist[from] + distance(point(from), point(to));
      if (d < dist[to]) {
        dist[to] = d;
        prev[to] = from;
        via[to] = trap;
        heap.push({d, to});
      }
    };
    for (int door : trap_doors_[trap]) visit(2 + door);
    if (trap == tq) visit(1);
  };
  while (!heap.empty()) {
    const auto [d, node] = heap.top();
    heap.pop();
    if (d > dist[node]) continue;
    if (node == 1) break;
    if (node == 0) {
      relax(0, tp);
      continue;
    }
    relax(node, doors_[node - 2].left);
    relax(node, doors_[node - 2].right);
  }
  if (prev[1] < 0) return {};
  std::vector<Leg> legs;
  for (int node = 1; node != 0; node = prev[node])
    legs.push_back({via[node], point(prev[node]), point(node), prev[node] - 2, node - 2});
  std::reverse(legs.begin(), legs.end());
  // Two doors on one wall: a leg along the wall could touch a vertex standing on it, so go
  // by the middle of the trapezoid instead.
  std::vector<Leg> out;
  for (Leg leg : legs) {
    leg.door_from = std::max(leg.door_from, -1);
    leg.door_to = std::max(leg.door_to, -1);
    if (leg.door_from < 0 || leg.door_to < 0 || leg.from.x != leg.to.x) {
      out.push_back(leg);
      continue;
    }
    const Trap& t = traps_[leg.trap];
    const double x = 0.5 * (walls_[t.slab] + walls_[t.slab + 1]);
    const double u = 0.5 * (fraction(leg.trap, leg.from) + fraction(leg.trap, leg.to));
    const Vec2 middle{x, y_at(t.lo, x) + u * (y_at(t.hi, x) - y_at(t.lo, x))};
    out.push_back({leg.trap, leg.from, middle, leg.door_from, -1});
    out.push_back({leg.trap, middle, leg.to, -1, leg.door_to});
  }
  return out;
}

}  // namespace cslice::path_detail
