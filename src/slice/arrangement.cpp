// Arrangement of contact segments.
//
// Degenerate input is the norm (parallel edges give coincident contact segments, perfect
// fits make many curves meet at one point), so every decision uses one rule: points within
// the geometric epsilon are one vertex (merged transitively by a sweep in x), a vertex on
// one curve within eps of a curve it meets is on both, pieces joining the same two vertices
// along the same curve are one edge carrying all their labels, and curves leaving a vertex
// side by side are ordered as the intersection step decided: tangent ones by curvature,
// crossing ones by direction, others by where they really are at the snapping radius.
#include "slice/arrangement.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "parts/loop_queries.hpp"

namespace cslice {
namespace {

// How the intersection step said two curves meet at a point.
enum class Meeting : char { other, tangent, crossing };

struct SplitPoint {
  int curve;
  double t;
  Vec2 p;
  int met = -1;  // the other curve, when this point is where the two touch or cross
  Meeting how = Meeting::other;
};

// (vertex, curve, curve) with the curves' indices ascending: pairs of curves that the
// intersection step found crossing at that vertex; (-1, curve, curve): pairs it found
// tangent (touching without crossing), wherever they meet.
using MeetingKey = std::array<int, 3>;
struct Meetings {
  std::vector<MeetingKey> tangents, crossings;  // sorted
};

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
  std::vector<Box> sorted(boxes.size());  // contiguous for the sweep
  for (size_t i = 0; i < order.size(); ++i) sorted[i] = boxes[order[i]];
  std::vector<std::pair<int, int>> pairs;
  for (size_t i = 0; i < sorted.size(); ++i) {
    const Box& a = sorted[i];
    for (size_t j = i + 1; j < sorted.size() && sorted[j].lo.x <= a.hi.x; ++j) {
      const Box& b = sorted[j];  // Box::overlaps, knowing b.lo.x <= a.hi.x
      if (!(b.hi.x < a.lo.x || b.lo.y > a.hi.y || b.hi.y < a.lo.y))
        pairs.emplace_back(order[i], order[j]);
    }
  }
  return pairs;
}

// Two curves that meet, and where they may run within eps of each other: a piece shared by
// both (collinear or co-circular within eps), as parameter ranges, or, for curves meeting at
// points, their whole ranges (near = true: only points within eps of the other count).
struct SharedPiece {
  int a, b;
  double a_lo, a_hi, b_lo, b_hi;
  bool near = false;
};

// Curves within eps of each other along a stretch must be cut at the same vertices there, or
// their pieces would not coincide and a third curve would cross them in an order that
// round-off decides: two lines closer than eps crossed by a third at a shallow angle get
// their crossings at points farther apart than eps. The same holds for curves that only meet
// at points, next to those points: arcs the intersection step calls tangent (a lens thinner
// than eps) and curves crossing at a shallow angle stay within eps of each other for up to
// sqrt(eps / curvature) or eps / angle. So every split point of one curve inside a shared
// piece, or within eps of a curve it meets, is copied to the other, at the same point; the
// pieces between them then merge into one edge. Two passes carry points along chains.
// Split point indices grouped by curve (counting sort): those of curve c are
// index[start[c] .. start[c + 1]).
struct SplitsByCurve {
  std::vector<int> start, index;
  SplitsByCurve(const std::vector<SplitPoint>& splits, size_t first, size_t curves)
      : start(curves + 1, 0), index(splits.size() - first) {
    for (size_t k = first; k < splits.size(); ++k) ++start[splits[k].curve + 1];
    for (size_t c = 0; c < curves; ++c) start[c + 1] += start[c];
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (size_t k = first; k < splits.size(); ++k) index[fill[splits[k].curve]++] = int(k);
  }
  std::span<const int> of(int c) const {
    return {index.data() + start[c], index.data() + start[c + 1]};
  }
};

void share_split_points(const std::vector<Curve>& curves, const std::vector<Box>& boxes,
                        const std::vector<SharedPiece>& shared, std::vector<SplitPoint>& splits,
                        double eps) {
  if (shared.empty()) return;
  size_t first_new = 0;
  for (int pass = 0; pass < 2; ++pass) {
    const SplitsByCurve fresh(splits, first_new, curves.size());
    const SplitsByCurve all = first_new == 0 ? fresh : SplitsByCurve(splits, 0, curves.size());
    // The fresh points in curve order, compact, each with where it is on its own curve.
    struct Fresh {
      double t;
      int met;
      Vec2 p, on_curve;
    };
    std::vector<Fresh> points(fresh.index.size());
    for (size_t i = 0; i < points.size(); ++i) {
      const SplitPoint& sp = splits[fresh.index[i]];
      points[i] = {sp.t, sp.met, sp.p, point_at(curves[sp.curve], sp.t)};
    }
    // A point within eps of one the curve already has would join that one's vertex anyway.
    auto has_point_near = [&](int c, Vec2 p) {
      for (int k : all.of(c))
        if (length_squared(splits[k].p - p) <= eps * eps) return true;
      return false;
    };
    std::vector<SplitPoint> added;
    for (const SharedPiece& sp : shared) {
      for (const auto& [from, to, lo, hi] :
           {std::tuple{sp.a, sp.b, sp.a_lo, sp.a_hi}, std::tuple{sp.b, sp.a, sp.b_lo, sp.b_hi}}) {
        for (int i = fresh.start[from]; i < fresh.start[from + 1]; ++i) {
          const Fresh& p = points[i];
          if (p.t < lo || p.t > hi) continue;
          if (sp.near) {
            if (p.met == to) continue;  // where the two meet: already on both
            // Measured from the curve's own point, so that a vertex carried onto a curve
            // passes on to the curves that one runs beside. Outside the other's box grown by
            // eps is farther than eps from it.
            const Vec2 q = p.on_curve;
            const Box& box = boxes[to];
            if (q.x < box.lo.x || q.x > box.hi.x || q.y < box.lo.y || q.y > box.hi.y) continue;
            if (has_point_near(to, p.p) || distance_to_curve(curves[to], q) > eps) continue;
          }
          added.push_back({to, closest_parameter(curves[to], p.p), p.p});
        }
      }
    }
    if (added.empty()) return;
    first_new = splits.size();
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
    bool piece = false;
    for (int k = 0; k < x.count; ++k) {
      const IntersectionHit& h = x.hits[k];
      // A point hit inside both curves, not a tangency, is a crossing; at an end of either
      // curve it is a touch (that curve ends there).
      const Meeting how = h.is_piece     ? Meeting::other
                          : h.is_tangent ? Meeting::tangent
                          : (h.ta0 > 0.0 && h.ta0 < 1.0 && h.tb0 > 0.0 && h.tb0 < 1.0)
                              ? Meeting::crossing
                              : Meeting::other;
      splits.push_back({i, h.ta0, h.point, j, how});
      splits.push_back({j, h.tb0, h.point, i, how});
      if (h.is_piece) {
        piece = true;
        splits.push_back({i, h.ta1, h.point_end});
        splits.push_back({j, h.tb1, h.point_end});
        shared.push_back({i, j, std::min(h.ta0, h.ta1), std::max(h.ta0, h.ta1),
                          std::min(h.tb0, h.tb1), std::max(h.tb0, h.tb1)});
      }
    }
    if (x.count > 0 && !piece) shared.push_back({i, j, 0.0, 1.0, 0.0, 1.0, true});
  }
  share_split_points(curves, boxes, shared, splits, eps);
  return splits;
}

// Indices 0 .. n - 1 sorted by x(i), ties by index: an LSD radix sort on the bits of the
// doubles (made unsigned-comparable), stable, so equal keys keep their index order.
template <class X>
std::vector<int> sorted_by_x(size_t n, X x) {
  if (n < 4096) {  // the radix passes only pay off on many points
    std::vector<std::pair<double, int>> pairs(n);
    for (size_t i = 0; i < n; ++i) pairs[i] = {x(i), int(i)};
    std::sort(pairs.begin(), pairs.end());
    std::vector<int> order(n);
    for (size_t i = 0; i < n; ++i) order[i] = pairs[i].second;
    return order;
  }
  std::vector<uint64_t> key(n);
  for (size_t i = 0; i < n; ++i) {
    const double v = x(i) == 0.0 ? 0.0 : x(i);  // -0 and +0 are equal
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    key[i] = bits >> 63 ? ~bits : bits | (uint64_t{1} << 63);
  }
  std::vector<int> order(n), next(n);
  std::iota(order.begin(), order.end(), 0);
  constexpr int kDigit = 11;
  constexpr uint64_t kMask = (uint64_t{1} << kDigit) - 1;
  std::vector<int> count(kMask + 2);
  for (int shift = 0; shift < 64; shift += kDigit) {
    std::fill(count.begin(), count.end(), 0);
    for (size_t i = 0; i < n; ++i) ++count[((key[i] >> shift) & kMask) + 1];
    if (size_t(*std::max_element(count.begin(), count.end())) == n)
      continue;  // every key has this digit: the pass would not move anything
    for (size_t d = 0; d + 1 < count.size(); ++d) count[d + 1] += count[d];
    for (int i : order) next[count[(key[i] >> shift) & kMask]++] = i;
    order.swap(next);
  }
  return order;
}

// Merges split points closer than eps (transitively) into vertices; returns the vertex of
// each split point and fills the vertex positions (each the first point of its cluster).
// A sweep in x compares each point with the following ones less than eps further right.
std::vector<int> merge_points(const std::vector<SplitPoint>& splits, double eps,
                              std::vector<Vec2>& vertices) {
  const std::vector<int> order =
      sorted_by_x(splits.size(), [&](size_t i) { return splits[i].p.x; });
  UnionFind uf(splits.size());
  for (size_t i = 0; i < order.size(); ++i) {
    const Vec2 p = splits[order[i]].p;
    for (size_t j = i + 1; j < order.size() && splits[order[j]].p.x - p.x <= eps; ++j) {
      const Vec2 q = splits[order[j]].p;
      if (std::fabs(q.y - p.y) <= eps && distance(p, q) <= eps) uf.unite(order[i], order[j]);
    }
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

// The piece of c between parameters t0 and t1, snapped to the given ends (make_arc without
// the trigonometry for ends that are replaced anyway).
Curve piece_of(const Curve& c, double t0, double t1, Vec2 from, Vec2 to) {
  if (c.is_segment()) return make_segment(from, to);
  Curve piece;
  piece.center = c.center;
  piece.radius = c.radius;
  piece.start_angle = c.start_angle + t0 * c.sweep;
  piece.sweep = std::clamp((t1 - t0) * c.sweep, -kTwoPi, kTwoPi);
  piece.from = from;
  piece.to = to;
  piece.bulge = piece.is_full_circle() ? std::numeric_limits<double>::infinity()
                                       : std::tan(piece.sweep / 4.0);
  return piece;
}

// Groups 0 .. n - 1 by key(i) in [0, keys) (counting sort, stable): the members of group g
// are order[start[g] .. start[g + 1]), in increasing i.
template <class Key>
void group_by(size_t n, size_t keys, Key key, std::vector<int>& start, std::vector<int>& order) {
  start.assign(keys + 1, 0);
  for (size_t i = 0; i < n; ++i) ++start[key(i) + 1];
  for (size_t g = 0; g < keys; ++g) start[g + 1] += start[g];
  order.resize(n);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (size_t i = 0; i < n; ++i) order[fill[key(i)]++] = int(i);
}

// Merges coincident edges (same ends, same midpoint) into the first of them, which then
// carries every label. Candidates share their pair of end vertices: pieces are grouped by
// their lower end, then sorted by the other one within each (small) group.
void merge_coincident_edges(Arrangement& arr, std::vector<ArrangementEdge>& pieces, double eps) {
  std::vector<std::pair<int, int>> end_pairs(pieces.size());  // compact: read many times
  for (size_t i = 0; i < pieces.size(); ++i)
    end_pairs[i] = {std::min(pieces[i].u, pieces[i].v), std::max(pieces[i].u, pieces[i].v)};
  auto ends = [&](int i) { return end_pairs[i]; };
  std::vector<int> start, order;
  group_by(
      pieces.size(), arr.vertices.size(), [&](size_t i) { return ends(int(i)).first; }, start,
      order);
  for (size_t g = 0; g + 1 < start.size(); ++g)
    if (start[g + 1] - start[g] > 1)
      std::sort(order.begin() + start[g], order.begin() + start[g + 1],
                [&](int a, int b) { return ends(a) != ends(b) ? ends(a) < ends(b) : a < b; });
  arr.edges.reserve(pieces.size());
  std::vector<int> kept(pieces.size(), -1);  // piece -> arrangement edge
  std::vector<Vec2> kept_mid;                // midpoint of each edge kept so far, when needed
  for (size_t i = 0; i < order.size(); ++i) {
    ArrangementEdge& e = pieces[order[i]];
    const bool after_same = i > 0 && ends(order[i - 1]) == ends(order[i]);
    const bool before_same = i + 1 < order.size() && ends(order[i + 1]) == ends(order[i]);
    if (!after_same && !before_same) {  // the only piece between its ends
      kept[order[i]] = int(arr.edges.size());
      arr.edges.push_back(std::move(e));
      continue;
    }
    const Vec2 mid = point_at(e.curve, 0.5);
    int into = -1;
    for (size_t j = i; j-- > 0 && ends(order[j]) == ends(order[i]);) {
      if (distance(kept_mid[kept[order[j]]], mid) <= eps) {
        into = kept[order[j]];
        break;
      }
    }
    if (into < 0) {
      kept[order[i]] = int(arr.edges.size());
      kept_mid.resize(arr.edges.size() + 1);
      kept_mid.back() = mid;
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
  // Split points along each curve in order of (t, index): grouped by curve, then each
  // curve's few points sorted (as compact (t, index) pairs).
  std::vector<int> start, along;
  group_by(
      splits.size(), curves.size(), [&](size_t i) { return splits[i].curve; }, start, along);
  std::vector<std::pair<double, int>> at_t(splits.size());
  for (size_t k = 0; k < along.size(); ++k) at_t[k] = {splits[along[k]].t, along[k]};
  for (size_t c = 0; c < curves.size(); ++c)
    std::sort(at_t.begin() + start[c], at_t.begin() + start[c + 1]);
  // Where each split point really is on its curve, and the curve's tangent there: one sine
  // and cosine per point of an arc (point_at and tangent_at, sharing the radial direction).
  struct OnCurve {
    Vec2 point, tangent;
  };
  auto on_curve = [&](const Curve& c, double t) {
    if (c.is_segment()) return OnCurve{point_at(c, t), normalized(c.to - c.from)};
    const Vec2 radial = unit_vector(c.start_angle + t * c.sweep);
    const Vec2 p = t == 0.0 ? c.from : t == 1.0 ? c.to : c.center + c.radius * radial;
    return OnCurve{p, c.sweep > 0.0 ? perp_left(radial) : perp_right(radial)};
  };
  std::vector<ArrangementEdge> pieces;
  pieces.reserve(splits.size());
  for (size_t c = 0; c < curves.size(); ++c) {
    const Curve& curve = curves[c];
    int cached = -1;  // the split point `at` describes
    OnCurve at{};
    for (int k = start[c]; k + 1 < start[c + 1]; ++k) {
      const auto [ta, a] = at_t[k];
      const auto [tb, b] = at_t[k + 1];
      // Consecutive points at one vertex make no edge, except a full circle's only piece.
      if (vertex_of[a] == vertex_of[b] && (!curve.is_full_circle() || tb - ta < 0.5)) continue;
      const OnCurve from = cached == a ? at : on_curve(curve, ta);
      at = on_curve(curve, tb);
      cached = b;
      ArrangementEdge& e = pieces.emplace_back();
      e.u = vertex_of[a];
      e.v = vertex_of[b];
      e.curve = piece_of(curve, ta, tb, arr.vertices[e.u], arr.vertices[e.v]);
      e.source = int(c);
      e.tangent_u = from.tangent;
      e.tangent_v = at.tangent;
      e.point_u = from.point;
      e.point_v = at.point;
      e.labels.push_back({ids[c], true});
    }
  }
  merge_coincident_edges(arr, pieces, eps);
}

struct Direction {
  int vertex;
  int half_edge;
  int curve;  // the contact segment the edge comes from
  double angle;
  double curvature;
  Vec2 tangent;  // unit, leaving the vertex
  Vec2 start;    // where the piece really leaves from, before snapping to the vertex
};

// Whether b, leaving a vertex just counterclockwise of a (by angle), really lies clockwise
// of it. The decision follows the intersection step, so the arrangement stays consistent:
// - curves it called tangent are ordered by curvature (their directions may differ by
//   round-off either way), as are directions equal to within the angular epsilon (tangent
//   by construction, e.g. one curve starting on another). This holds wherever the two leave
//   a vertex side by side, not only at their point of tangency: they run within eps of
//   each other there, and as tangent curves they never cross, even where the exact ones
//   do (a lens thinner than eps), so each keeps the side its curvature gives;
// - curves it called crossing here are ordered by direction: they change sides here;
// - any other curves leaving side by side (parallel ones too) do not cross here (one ends on the
// other, or they
//   only met through points within eps of both), so each stays on the side where it really
//   is. Snapping moved their ends by up to eps, so next to a curve one runs nearly parallel
//   to (a shallow crossing shortly before, or a lens of two nearly tangent arcs), its
//   direction may point across the other while it stays on its own side up to the vertex.
//   They are compared where they are at the snapping radius: eps along each piece from its
//   own unsnapped start, which for pieces leaving one point is the order of directions.
bool lies_clockwise(const Direction& a, const Direction& b, const Meetings& meetings, double eps,
                    double angular_eps) {
  const double gap = b.angle - a.angle;
  // A tangency also joins curves leaving in opposite directions (one continuing the other);
  // only curves leaving side by side are tied.
  if (gap >= 0.5 * kPi) return false;
  const MeetingKey key{a.vertex, std::min(a.curve, b.curve), std::max(a.curve, b.curve)};
  if (a.curvature != b.curvature &&
      (gap <= angular_eps || std::binary_search(meetings.tangents.begin(), meetings.tangents.end(),
                                                MeetingKey{-1, key[1], key[2]})))
    return a.curvature > b.curvature;
  if (std::binary_search(meetings.crossings.begin(), meetings.crossings.end(), key)) return false;
  const Vec2 ahead_a = a.start + eps * a.tangent, ahead_b = b.start + eps * b.tangent;
  return cross(a.tangent + b.tangent, ahead_b - ahead_a) < 0.0;
}

// Orders the half-edges leaving each vertex counterclockwise by tangent, ties (tangent
// curves) broken by curvature: the one turning left comes later.
void order_outgoing(Arrangement& arr, const Meetings& meetings, double eps, double angular_eps) {
  std::vector<Direction> dirs(2 * arr.edges.size());  // by half-edge
  for (size_t e = 0; e < arr.edges.size(); ++e) {
    const ArrangementEdge& edge = arr.edges[e];
    const Vec2 t0 = edge.tangent_u, t1 = -edge.tangent_v;
    const double k = signed_curvature(edge.curve);
    dirs[2 * e] = {edge.u, int(2 * e), edge.source, std::atan2(t0.y, t0.x), k, t0, edge.point_u};
    dirs[2 * e + 1] = {edge.v, int(2 * e + 1), edge.source, std::atan2(t1.y, t1.x), -k,
                       t1,     edge.point_v};
  }
  for (Direction& x : dirs)
    if (x.angle > kPi - angular_eps) x.angle -= kTwoPi;  // one representative for +-pi
  group_by(
      dirs.size(), arr.vertices.size(), [&](size_t h) { return dirs[h].vertex; },
      arr.outgoing_start, arr.outgoing_edges);
  for (size_t v = 0; v < arr.vertices.size(); ++v) {
    const auto first = arr.outgoing_edges.begin() + arr.outgoing_start[v];
    const auto last = arr.outgoing_edges.begin() + arr.outgoing_start[v + 1];
    std::sort(first, last, [&](int a, int b) {
      return dirs[a].angle != dirs[b].angle ? dirs[a].angle < dirs[b].angle : a < b;
    });
    // Insertion pass: nearly sorted already, only neighbours side by side move.
    for (auto i = first + 1; i < last; ++i)
      for (auto j = i;
           j > first && lies_clockwise(dirs[*(j - 1)], dirs[*j], meetings, eps, angular_eps); --j)
        std::iter_swap(j - 1, j);
  }
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
  // Per edge, once: its area term (the twin's is the negation: the chord's cross product and
  // the circular segment both change sign) and its box (the same both ways).
  std::vector<double> area(arr.edges.size());
  std::vector<Box> box(arr.edges.size());
  for (size_t e = 0; e < arr.edges.size(); ++e) {
    area[e] = signed_area_contribution(arr.edges[e].curve);
    box[e] = bounding_box(arr.edges[e].curve);
  }
  arr.cycle_of.assign(n, -1);
  for (size_t start = 0; start < n; ++start) {
    if (arr.cycle_of[start] >= 0) continue;
    ArrangementCycle cycle;
    cycle.component = comp[arr.origin(int(start))];
    int h = int(start);
    do {
      arr.cycle_of[h] = int(arr.cycles.size());
      cycle.half_edges.push_back(h);
      cycle.area += h % 2 == 0 ? area[h / 2] : -area[h / 2];
      cycle.box.add(box[h / 2]);
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
  Meetings meetings;
  for (size_t i = 0; i < splits.size(); ++i) {
    if (splits[i].how == Meeting::other) continue;
    const int a = splits[i].curve, b = splits[i].met;
    if (splits[i].how == Meeting::tangent)
      meetings.tangents.push_back({-1, std::min(a, b), std::max(a, b)});
    else
      meetings.crossings.push_back({vertex_of[i], std::min(a, b), std::max(a, b)});
  }
  std::sort(meetings.tangents.begin(), meetings.tangents.end());
  std::sort(meetings.crossings.begin(), meetings.crossings.end());
  order_outgoing(arr, meetings, tol.geometric, tol.angular);
  link_half_edges(arr);
  trace_cycles(arr);
  assign_faces(arr);
  return arr;
}

}  // namespace cslice
