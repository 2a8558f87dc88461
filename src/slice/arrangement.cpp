// Arrangement of contact segments.
//
// Degenerate input is the norm (parallel edges give coincident contact segments, perfect
// fits make many curves meet at one point), so every decision uses one rule: points within
// the geometric epsilon are one vertex (merged transitively through a grid), pieces joining
// the same two vertices along the same curve are one edge carrying all their labels, and
// curves leaving a vertex in the same direction are ordered by curvature.
#include "slice/arrangement.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "parts/loop_queries.hpp"

namespace cslice {
namespace {

struct SplitPoint {
  int curve;
  double t;
  Vec2 p;
  int tangent_to = -1;  // the other curve, when the intersection step called this a tangency
};

// (vertex, curve, curve) with the curves' indices ascending: pairs of curves that the
// intersection step found tangent (touching without crossing) at that vertex.
using TangentTouch = std::array<int, 3>;

class UnionFind {
 public:
  explicit UnionFind(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int a) {
    while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
    return a;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);  // the lowest index represents
  }

 private:
  std::vector<int> parent_;
};

// Every pair of curves whose boxes overlap, found by sweeping boxes sorted by their left x.
std::vector<std::pair<int, int>> candidate_pairs(const std::vector<Box>& boxes) {
  std::vector<int> order(boxes.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return boxes[a].lo.x < boxes[b].lo.x; });
  std::vector<std::pair<int, int>> pairs;
  for (size_t i = 0; i < order.size(); ++i) {
    const Box& a = boxes[order[i]];
    for (size_t j = i + 1; j < order.size() && boxes[order[j]].lo.x <= a.hi.x; ++j)
      if (a.overlaps(boxes[order[j]])) pairs.emplace_back(order[i], order[j]);
  }
  return pairs;
}

// A piece shared by two curves (collinear or co-circular within eps), as parameter ranges.
struct SharedPiece {
  int a, b;
  double a_lo, a_hi, b_lo, b_hi;
};

// Curves the intersection step calls overlapping must be cut at the same vertices along the
// shared piece, or their pieces would not coincide: two lines closer than eps crossed by a
// third at a shallow angle get their crossings at points farther apart than eps. So every
// split point of one curve inside a shared piece is copied to the other, at the same point.
// Two passes carry points along chains of overlapping curves.
void share_split_points(const std::vector<Curve>& curves, const std::vector<SharedPiece>& shared,
                        std::vector<SplitPoint>& splits) {
  if (shared.empty()) return;
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::vector<int>> on_curve(curves.size());
    for (size_t k = 0; k < splits.size(); ++k) on_curve[splits[k].curve].push_back(int(k));
    std::vector<SplitPoint> added;
    for (const SharedPiece& sp : shared) {
      for (const auto& [from, to, lo, hi] :
           {std::tuple{sp.a, sp.b, sp.a_lo, sp.a_hi}, std::tuple{sp.b, sp.a, sp.b_lo, sp.b_hi}}) {
        for (int k : on_curve[from]) {
          const SplitPoint& p = splits[k];
          if (p.t < lo || p.t > hi) continue;
          added.push_back({to, closest_parameter(curves[to], p.p), p.p, -1});
        }
      }
    }
    if (added.empty()) return;
    splits.insert(splits.end(), added.begin(), added.end());
  }
}

std::vector<SplitPoint> split_points(const std::vector<Curve>& curves, double eps) {
  std::vector<SplitPoint> splits;
  std::vector<SharedPiece> shared;
  std::vector<Box> boxes;
  for (size_t i = 0; i < curves.size(); ++i) {
    splits.push_back({int(i), 0.0, curves[i].from});
    splits.push_back({int(i), 1.0, curves[i].to});
    boxes.push_back(bounding_box(curves[i]).inflated(eps));
  }
  for (auto [i, j] : candidate_pairs(boxes)) {
    const Intersection x = intersect(curves[i], curves[j], eps);
    for (int k = 0; k < x.count; ++k) {
      const IntersectionHit& h = x.hits[k];
      const bool tangent = h.is_tangent && !h.is_piece;
      splits.push_back({i, h.ta0, h.point, tangent ? j : -1});
      splits.push_back({j, h.tb0, h.point, tangent ? i : -1});
      if (h.is_piece) {
        splits.push_back({i, h.ta1, h.point_end});
        splits.push_back({j, h.tb1, h.point_end});
        shared.push_back({i, j, std::min(h.ta0, h.ta1), std::max(h.ta0, h.ta1),
                          std::min(h.tb0, h.tb1), std::max(h.tb0, h.tb1)});
      }
    }
  }
  share_split_points(curves, shared, splits);
  return splits;
}

// Merges split points closer than eps (transitively) into vertices; returns the vertex of
// each split point and fills the vertex positions (each the first point of its cluster).
// A sweep in x compares each point with the following ones less than eps further right.
std::vector<int> merge_points(const std::vector<SplitPoint>& splits, double eps,
                              std::vector<Vec2>& vertices) {
  std::vector<std::pair<double, int>> order(splits.size());
  for (size_t i = 0; i < splits.size(); ++i) order[i] = {splits[i].p.x, int(i)};
  std::sort(order.begin(), order.end());
  UnionFind uf(splits.size());
  for (size_t i = 0; i < order.size(); ++i) {
    const Vec2 p = splits[order[i].second].p;
    for (size_t j = i + 1; j < order.size() && order[j].first - p.x <= eps; ++j)
      if (distance(p, splits[order[j].second].p) <= eps) uf.unite(order[i].second, order[j].second);
  }
  std::vector<int> vertex_of(splits.size()), vertex_of_root(splits.size(), -1);
  for (size_t i = 0; i < splits.size(); ++i) {
    const int root = uf.find(int(i));
    if (vertex_of_root[root] < 0) {
      vertex_of_root[root] = int(vertices.size());
      vertices.push_back(splits[root].p);
    }
    vertex_of[i] = vertex_of_root[root];
  }
  return vertex_of;
}

Curve piece_of(const Curve& c, double t0, double t1, Vec2 from, Vec2 to) {
  if (c.is_segment()) return make_segment(from, to);
  Curve piece = make_arc(c.center, c.radius, c.start_angle + t0 * c.sweep, (t1 - t0) * c.sweep);
  piece.from = from;
  piece.to = to;
  return piece;
}

// Merges coincident edges (same ends, same midpoint) into the first of them, which then
// carries every label. Candidates share their pair of end vertices, found by sorting.
void merge_coincident_edges(Arrangement& arr, std::vector<ArrangementEdge>& pieces, double eps) {
  std::vector<int> order(pieces.size());
  std::iota(order.begin(), order.end(), 0);
  auto ends = [&](int i) {
    return std::make_pair(std::min(pieces[i].u, pieces[i].v), std::max(pieces[i].u, pieces[i].v));
  };
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return ends(a) != ends(b) ? ends(a) < ends(b) : a < b; });
  std::vector<int> kept(pieces.size(), -1);  // piece -> arrangement edge
  for (size_t i = 0; i < order.size(); ++i) {
    ArrangementEdge& e = pieces[order[i]];
    const Vec2 mid = point_at(e.curve, 0.5);
    int into = -1;
    for (size_t j = i; j-- > 0 && ends(order[j]) == ends(order[i]);) {
      const ArrangementEdge& o = arr.edges[kept[order[j]]];
      if (kept[order[j]] >= 0 && distance(point_at(o.curve, 0.5), mid) <= eps) {
        into = kept[order[j]];
        break;
      }
    }
    if (into < 0) {
      kept[order[i]] = int(arr.edges.size());
      arr.edges.push_back(std::move(e));
      continue;
    }
    ArrangementEdge& o = arr.edges[into];
    kept[order[i]] = into;
    const bool same_way =
        o.u == e.u && o.v == e.v && (e.u != e.v || o.curve.sweep * e.curve.sweep > 0);
    for (EdgeLabel l : e.labels)
      o.labels.push_back({l.segment, same_way ? l.blocked_left : !l.blocked_left});
  }
}

void build_edges(Arrangement& arr, const std::vector<Curve>& curves, const std::vector<int>& ids,
                 const std::vector<SplitPoint>& splits, const std::vector<int>& vertex_of,
                 double eps) {
  // Split points along each curve in order: one sort of (curve, t, index) triples.
  struct Along {
    int curve;
    double t;
    int index;
    bool operator<(const Along& o) const {
      return curve != o.curve ? curve < o.curve : (t != o.t ? t < o.t : index < o.index);
    }
  };
  std::vector<Along> along(splits.size());
  for (size_t i = 0; i < splits.size(); ++i) along[i] = {splits[i].curve, splits[i].t, int(i)};
  std::sort(along.begin(), along.end());
  std::vector<ArrangementEdge> pieces;
  for (size_t k = 0; k + 1 < along.size(); ++k) {
    if (along[k].curve != along[k + 1].curve) continue;
    const size_t c = size_t(along[k].curve);
    const int a = along[k].index, b = along[k + 1].index;
    // Consecutive points at one vertex make no edge, except a full circle's only piece.
    if (vertex_of[a] == vertex_of[b] &&
        (!curves[c].is_full_circle() || splits[b].t - splits[a].t < 0.5))
      continue;
    ArrangementEdge e;
    e.u = vertex_of[a];
    e.v = vertex_of[b];
    e.curve = piece_of(curves[c], splits[a].t, splits[b].t, arr.vertices[e.u], arr.vertices[e.v]);
    e.source = int(c);
    e.tangent_u = tangent_at(curves[c], splits[a].t);
    e.tangent_v = tangent_at(curves[c], splits[b].t);
    e.labels.push_back({ids[c], true});
    pieces.push_back(std::move(e));
  }
  merge_coincident_edges(arr, pieces, eps);
}

struct Direction {
  int vertex;
  int half_edge;
  int curve;  // the contact segment the edge comes from
  double angle;
  double curvature;
};

// Whether b, leaving a vertex just counterclockwise of a (by angle), really lies clockwise
// of it because b turns right relative to a and the two only touch here. The decision
// follows the intersection step, so the arrangement stays consistent: curves it called
// tangent at this vertex are ordered by curvature (their directions may differ by round-off
// either way), curves it called crossing by direction, except directions equal to within
// the angular epsilon (tangent by construction, e.g. one curve starting on another).
bool curvature_overrides(const Direction& a, const Direction& b,
                         const std::vector<TangentTouch>& tangents, double angular_eps) {
  if (a.curvature <= b.curvature) return false;
  const double gap = b.angle - a.angle;
  if (gap <= angular_eps) return true;
  // A tangency also joins curves leaving in opposite directions (one continuing the other);
  // only curves leaving side by side are tied.
  if (gap >= 0.5 * kPi) return false;
  const TangentTouch key{a.vertex, std::min(a.curve, b.curve), std::max(a.curve, b.curve)};
  return std::binary_search(tangents.begin(), tangents.end(), key);
}

// Orders the half-edges leaving each vertex counterclockwise by tangent, ties (tangent
// curves) broken by curvature: the one turning left comes later.
void order_outgoing(Arrangement& arr, const std::vector<TangentTouch>& tangents,
                    double angular_eps) {
  std::vector<Direction> dirs;
  dirs.reserve(2 * arr.edges.size());
  for (size_t e = 0; e < arr.edges.size(); ++e) {
    const ArrangementEdge& edge = arr.edges[e];
    const Vec2 t0 = edge.tangent_u, t1 = -edge.tangent_v;
    const double k = signed_curvature(edge.curve);
    dirs.push_back({edge.u, int(2 * e), edge.source, std::atan2(t0.y, t0.x), k});
    dirs.push_back({edge.v, int(2 * e + 1), edge.source, std::atan2(t1.y, t1.x), -k});
  }
  for (Direction& x : dirs)
    if (x.angle > kPi - angular_eps) x.angle -= kTwoPi;  // one representative for +-pi
  std::sort(dirs.begin(), dirs.end(), [](const Direction& a, const Direction& b) {
    return a.vertex != b.vertex ? a.vertex < b.vertex : a.angle < b.angle;
  });
  // Insertion pass: nearly sorted already, only tangent neighbours move.
  for (size_t i = 1; i < dirs.size(); ++i)
    for (size_t j = i; j > 0 && dirs[j - 1].vertex == dirs[j].vertex &&
                       curvature_overrides(dirs[j - 1], dirs[j], tangents, angular_eps);
         --j)
      std::swap(dirs[j - 1], dirs[j]);
  // dirs is sorted by vertex: record where each vertex's run starts.
  arr.outgoing_start.assign(arr.vertices.size() + 1, 0);
  for (const Direction& x : dirs) ++arr.outgoing_start[x.vertex + 1];
  for (size_t v = 0; v < arr.vertices.size(); ++v)
    arr.outgoing_start[v + 1] += arr.outgoing_start[v];
  arr.outgoing_edges.resize(dirs.size());
  for (size_t i = 0; i < dirs.size(); ++i) arr.outgoing_edges[i] = dirs[i].half_edge;
}

// Links each half-edge to the next around its left face: at its target, the half-edge just
// clockwise of its twin.
void link_half_edges(Arrangement& arr) {
  const size_t n = 2 * arr.edges.size();
  std::vector<int> position(n);
  for (int v = 0; v < int(arr.vertices.size()); ++v) {
    const std::span<const int> out = arr.outgoing(v);
    for (size_t i = 0; i < out.size(); ++i) position[out[i]] = int(i);
  }
  arr.next.assign(n, -1);
  for (size_t h = 0; h < n; ++h) {
    const int twin = int(h) ^ 1;
    const std::span<const int> out = arr.outgoing(arr.target(int(h)));
    const int deg = int(out.size());
    arr.next[h] = out[(position[twin] - 1 + deg) % deg];
  }
}

std::vector<int> vertex_components(const Arrangement& arr) {
  UnionFind uf(arr.vertices.size());
  for (const ArrangementEdge& e : arr.edges) uf.unite(e.u, e.v);
  std::vector<int> comp(arr.vertices.size());
  for (size_t v = 0; v < comp.size(); ++v) comp[v] = uf.find(int(v));
  return comp;
}

void trace_cycles(Arrangement& arr) {
  const size_t n = 2 * arr.edges.size();
  const std::vector<int> comp = vertex_components(arr);
  arr.cycle_of.assign(n, -1);
  for (size_t start = 0; start < n; ++start) {
    if (arr.cycle_of[start] >= 0) continue;
    ArrangementCycle cycle;
    cycle.component = comp[arr.origin(int(start))];
    int h = int(start);
    do {
      arr.cycle_of[h] = int(arr.cycles.size());
      cycle.half_edges.push_back(h);
      const Curve c = arr.half_curve(h);
      cycle.area += signed_area_contribution(c);
      cycle.box.add(bounding_box(c));
      h = arr.next[h];
    } while (h != int(start) && arr.cycle_of[h] < 0);
    arr.cycles.push_back(std::move(cycle));
  }
}

// Even-odd containment of many points (sorted by y) in one cycle at once: each curve toggles
// only the points within its own y-range, so a long cycle costs its length plus the points
// near each curve, not its length times the points.
std::vector<char> cycle_encloses(const Arrangement& arr, const ArrangementCycle& c,
                                 const std::vector<Vec2>& points_by_y) {
  std::vector<char> inside(points_by_y.size(), false);
  auto y_less = [](const Vec2& p, double y) { return p.y < y; };
  for (int h : c.half_edges) {
    const Curve& curve = arr.edges[h / 2].curve;  // parity does not depend on direction
    const Box box = bounding_box(curve);
    auto it = std::lower_bound(points_by_y.begin(), points_by_y.end(), box.lo.y, y_less);
    for (; it != points_by_y.end() && it->y <= box.hi.y; ++it)
      if (toggles_parity(curve, *it)) inside[it - points_by_y.begin()] ^= 1;
  }
  return inside;
}

// Every connected component has exactly one outer cycle, the one of least signed area (a
// tree's only cycle has area 0); each of its other cycles bounds a face of its own, however
// small, so no area threshold decides topology. An outer cycle belongs to the smallest
// bounded face of another component around it, or to the unbounded face.
void assign_faces(Arrangement& arr) {
  std::unordered_map<int, int> outer_of_component;
  for (size_t c = 0; c < arr.cycles.size(); ++c) {
    auto [it, added] = outer_of_component.emplace(arr.cycles[c].component, int(c));
    if (!added && arr.cycles[c].area < arr.cycles[it->second].area) it->second = int(c);
  }
  arr.faces.assign(1, ArrangementFace{});
  std::vector<int> bounded;
  for (size_t c = 0; c < arr.cycles.size(); ++c) {
    if (outer_of_component[arr.cycles[c].component] == int(c)) continue;
    arr.cycles[c].face = int(arr.faces.size());
    arr.faces.push_back({true, {int(c)}});
    bounded.push_back(int(c));
  }
  // Each outer cycle is represented by its first vertex; its face is the smallest bounded
  // cycle of another component enclosing that point. Cycles are tried smallest first, each
  // against the still unplaced points in its box.
  std::sort(bounded.begin(), bounded.end(),
            [&](int a, int b) { return arr.cycles[a].area < arr.cycles[b].area; });
  struct Probe {
    Vec2 p;
    int cycle;
  };
  std::vector<Probe> probes;
  for (const auto& [component, c] : outer_of_component) {
    arr.cycles[c].face = 0;
    probes.push_back({arr.vertices[arr.origin(arr.cycles[c].half_edges.front())], c});
  }
  std::sort(probes.begin(), probes.end(),
            [](const Probe& a, const Probe& b) { return a.p.y < b.p.y; });
  std::vector<char> placed(probes.size(), false);
  std::vector<int> candidates;
  std::vector<Vec2> points;
  for (int k : bounded) {
    const ArrangementCycle& o = arr.cycles[k];
    candidates.clear();
    points.clear();
    auto it = std::lower_bound(probes.begin(), probes.end(), o.box.lo.y,
                               [](const Probe& a, double y) { return a.p.y < y; });
    for (; it != probes.end() && it->p.y <= o.box.hi.y; ++it) {
      const size_t i = it - probes.begin();
      if (placed[i] || it->p.x < o.box.lo.x || it->p.x > o.box.hi.x ||
          arr.cycles[it->cycle].component == o.component)
        continue;
      candidates.push_back(int(i));
      points.push_back(it->p);
    }
    if (candidates.empty()) continue;
    const std::vector<char> inside = cycle_encloses(arr, o, points);
    for (size_t j = 0; j < candidates.size(); ++j) {
      if (!inside[j]) continue;
      placed[candidates[j]] = true;
      arr.cycles[probes[candidates[j]].cycle].face = o.face;
    }
  }
  // Attach outer cycles in cycle order, so face cycle lists do not depend on hashing.
  for (size_t c = 0; c < arr.cycles.size(); ++c)
    if (outer_of_component[arr.cycles[c].component] == int(c))
      arr.faces[arr.cycles[c].face].cycles.push_back(int(c));
}

}  // namespace

Vec2 Arrangement::direction(int h) const {
  const ArrangementEdge& e = edges[h / 2];
  return h % 2 == 0 ? e.tangent_u : -e.tangent_v;
}

Curve Arrangement::half_curve(int h) const {
  const Curve& c = edges[h / 2].curve;
  return h % 2 == 0 ? c : reversed(c);
}

Arrangement build_arrangement(const std::vector<Curve>& curves, const std::vector<int>& segment_ids,
                              const Tolerances& tol) {
  Arrangement arr;
  const std::vector<SplitPoint> splits = split_points(curves, tol.geometric);
  const std::vector<int> vertex_of = merge_points(splits, tol.geometric, arr.vertices);
  build_edges(arr, curves, segment_ids, splits, vertex_of, tol.geometric);
  std::vector<TangentTouch> tangents;
  for (size_t i = 0; i < splits.size(); ++i) {
    if (splits[i].tangent_to < 0) continue;
    const int a = splits[i].curve, b = splits[i].tangent_to;
    tangents.push_back({vertex_of[i], std::min(a, b), std::max(a, b)});
  }
  std::sort(tangents.begin(), tangents.end());
  order_outgoing(arr, tangents, tol.angular);
  link_half_edges(arr);
  trace_cycles(arr);
  assign_faces(arr);
  return arr;
}

}  // namespace cslice
