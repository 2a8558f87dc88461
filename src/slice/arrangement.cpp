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
#include <bit>
#include <cstdint>
#include <cstring>
#include <numeric>

#include "parts/loop_queries.hpp"
#include "slice/close_points.hpp"
#include "slice/edge_pieces.hpp"
#include "slice/group_by.hpp"
#include "slice/small_sort.hpp"
#include "slice/split_points.hpp"
#include "slice/trig_memo.hpp"

namespace cslice {
namespace {

// Pairs of curves that the intersection step found crossing at a vertex, and pairs it found
// tangent (touching without crossing) wherever they meet. Only asked about where three or
// more half-edges leave a vertex side by side: sorted on the first question.
class Meetings {
 public:
  void clear() {
    tangents_.clear();
    crossings_.clear();
    sorted_ = false;
  }
  // a < b throughout.
  void add_tangent(int a, int b) { tangents_.push_back(pack(a, b)); }
  void add_crossing(int vertex, int a, int b) { crossings_.push_back({pack(vertex, a), b}); }
  bool tangent(int a, int b) {
    sort();
    return std::binary_search(tangents_.begin(), tangents_.end(), pack(a, b));
  }
  bool crossing(int vertex, int a, int b) {
    sort();
    return std::binary_search(crossings_.begin(), crossings_.end(), Crossing{pack(vertex, a), b},
                              less);
  }

 private:
  struct Crossing {
    uint64_t vertex_a;
    int b;
  };
  static uint64_t pack(int hi, int lo) { return uint64_t(uint32_t(hi)) << 32 | uint32_t(lo); }
  static bool less(const Crossing& x, const Crossing& y) {
    return x.vertex_a != y.vertex_a ? x.vertex_a < y.vertex_a : x.b < y.b;
  }
  void sort() {
    if (sorted_) return;
    small_sort(tangents_.begin(), tangents_.end());
    small_sort(crossings_.begin(), crossings_.end(), less);
    sorted_ = true;
  }
  std::vector<uint64_t> tangents_;
  std::vector<Crossing> crossings_;
  bool sorted_ = false;
};

}  // namespace

// Every working array of ArrangementBuilder::build, kept between builds.
struct ArrangementBuilder::Scratch {
  SplitScratch split;
  std::vector<SplitPoint> splits;
  std::vector<std::pair<double, int>> by_x;
  BucketSortBuffers<std::pair<double, int>> by_x_buffers;
  std::vector<uint64_t> keys;
  std::vector<int> next, count;
  std::vector<Vec2> points_by_x;
  CellScratch by_cell;               // merge_points past its budget
  std::vector<int> slots, distinct;  // merge_points' exactly equal points
  std::vector<size_t> used_slots;
  std::vector<int> order, vertex_of, vertex_of_root, fill;
  std::vector<int> splits_at;              // per vertex: how many split points merged into it
  std::vector<int> piece_from, piece_to;   // per split point: build_edges' pieces from and to it
  std::vector<InsidePiece> inside_pieces;  // find_inside_pieces
  UnionFind uf;
  std::vector<int> start, along;
  std::vector<std::pair<double, int>> at_t;
  std::vector<Piece> pieces;
  struct OnCurve {  // a split point's place on its curve, and the curve's tangent there
    Vec2 point, tangent;
  };
  std::vector<OnCurve> on_curve;
  PieceScratch edge_pieces;
  Meetings meetings;
  struct Direction {
    int vertex;
    int half_edge;
    int curve;  // the contact segment the edge comes from
    double angle;
    double curvature;
    Vec2 tangent;  // unit, leaving the vertex
    Vec2 start;    // where the piece really leaves from, before snapping to the vertex
  };
  std::vector<Direction> dirs;
  // Per curve and way along it, the last direction of a segment's piece and its angle: every
  // piece of a segment leaves its vertices in one of two directions.
  struct AngleMemo {
    uint64_t x, y;  // bits of the direction
    double angle;   // atan2 of it
  };
  std::vector<AngleMemo> segment_angles;
  std::vector<int> position, comp;
  std::vector<double> area;
  // Per edge its box (the same both ways), per cycle the union of its edges' boxes: found
  // when first asked after a build (known).
  std::vector<Box> box, cycle_box;
  std::vector<char> box_known, cycle_box_known;
  std::vector<int> outer_of_component, bounded, candidates;
  struct Probe {
    Vec2 p;
    int cycle;
  };
  std::vector<Probe> probes;
  std::vector<char> placed, inside;
  std::vector<Vec2> points;
};

namespace {

using Scratch = ArrangementBuilder::Scratch;
using Direction = Scratch::Direction;

// Joins each split point to the first one at exactly the same place (Vec2 ==, so NaN
// joins nothing) and lists the first ones, in index order, in s.distinct. Many split points
// coincide exactly: a curve's end, and the same end as a hit of every curve meeting it there.
void join_equal_points(const std::vector<SplitPoint>& splits, Scratch& s, UnionFind& uf) {
  const size_t n = splits.size();
  size_t size = 16;
  while (size < 2 * n) size *= 2;
  // Open addressing on the bits of (x, y): index + 1, or 0. Left all zero for the next call
  // (the slots used are cleared one by one: clearing all would cost more on big slices).
  std::vector<int>& slot = s.slots;
  if (slot.size() != size) slot.assign(size, 0);
  s.distinct.clear();
  s.used_slots.clear();
  for (size_t i = 0; i < n; ++i) {
    const Vec2 p = splits[i].p;
    uint64_t x, y;
    std::memcpy(&x, &p.x, sizeof x);
    std::memcpy(&y, &p.y, sizeof y);
    uint64_t h = (x * 0x9E3779B97F4A7C15ull) ^ (y * 0xC2B2AE3D27D4EB4Full);
    h ^= h >> 29;
    size_t k = size_t(h) & (size - 1);
    for (; slot[k] != 0 && !(splits[slot[k] - 1].p == p); k = (k + 1) & (size - 1)) {
    }
    if (slot[k] != 0) {
      uf.unite(slot[k] - 1, int(i));
    } else {
      slot[k] = int(i) + 1;
      s.distinct.push_back(int(i));
      s.used_slots.push_back(k);
    }
  }
  for (size_t k : s.used_slots) slot[k] = 0;
}

// The distinct split points sorted by x (s.order: their indices, s.points_by_x: where they
// are): below a few thousand a bucket sort by x (small_sort.hpp: buckets by where x lies in
// its range, each sorted after), above, where that costs more, an LSD radix sort on the
// bits of x (made unsigned-comparable). Points of equal x come in any order.
void sort_points_by_x(const std::vector<SplitPoint>& splits, Scratch& s) {
  const std::vector<int>& distinct = s.distinct;
  const size_t n = distinct.size();
  std::vector<int>& order = s.order;
  std::vector<Vec2>& points = s.points_by_x;
  order.resize(n);
  points.resize(n);
  if (n < 4096) {  // the radix passes only pay off on many points
    s.by_x.resize(n);
    for (size_t i = 0; i < n; ++i) s.by_x[i] = {splits[distinct[i]].p.x, distinct[i]};
    sort_by_coordinate(
        s.by_x, [](const std::pair<double, int>& a) { return a.first; }, s.by_x_buffers);
    for (size_t i = 0; i < n; ++i) {
      order[i] = s.by_x[i].second;
      points[i] = splits[order[i]].p;
    }
    return;
  }
  std::vector<uint64_t>& key = s.keys;
  key.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double x = splits[distinct[i]].p.x;
    const double v = x == 0.0 ? 0.0 : x;  // -0 and +0 are equal
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    key[i] = bits >> 63 ? ~bits : bits | (uint64_t{1} << 63);
  }
  std::vector<int>& next = s.next;
  next.resize(n);
  std::iota(order.begin(), order.end(), 0);
  constexpr int kDigit = 11;
  constexpr uint64_t kMask = (uint64_t{1} << kDigit) - 1;
  std::vector<int>& count = s.count;
  count.resize(kMask + 2);
  for (int shift = 0; shift < 64; shift += kDigit) {
    std::fill(count.begin(), count.end(), 0);
    for (size_t i = 0; i < n; ++i) ++count[((key[i] >> shift) & kMask) + 1];
    if (size_t(*std::max_element(count.begin(), count.end())) == n)
      continue;  // every key has this digit: the pass would not move anything
    for (size_t d = 0; d + 1 < count.size(); ++d) count[d + 1] += count[d];
    for (int i : order) next[count[(key[i] >> shift) & kMask]++] = i;
    order.swap(next);
  }
  for (size_t i = 0; i < n; ++i) {
    order[i] = distinct[order[i]];
    points[i] = splits[order[i]].p;
  }
}

// Merges split points closer than eps (transitively) into vertices; fills the vertex of each
// split point (s.vertex_of) and the vertex positions (each the first point of its cluster:
// the union-find keeps the lowest index as root, so the clusters and their vertices depend
// only on which pairs are within eps, not on the order they are found in). Points at exactly
// the same place are joined first; every distance from one of them is the others' distance,
// so the rest compares the distinct points only. A sweep in x compares each point with the
// following ones less than eps further right; where many points share an x-window (a
// perfect fit where many contact segments meet) that turns quadratic, and past a budget the
// cells above take over.
void merge_points(Scratch& s, double eps, std::vector<Vec2>& vertices) {
  const std::vector<SplitPoint>& splits = s.splits;
  UnionFind& uf = s.uf;
  uf.reset(splits.size());
  join_equal_points(splits, s, uf);
  sort_points_by_x(splits, s);
  const std::vector<int>& order = s.order;
  const std::vector<Vec2>& points = s.points_by_x;
  const size_t n = points.size();
  const size_t budget = 16 * n + 256;
  size_t work = 0;
  for (size_t i = 0; i < n && work <= budget; ++i) {
    const Vec2 p = points[i];
    for (size_t j = i + 1; j < n && points[j].x - p.x <= eps; ++j) {
      ++work;
      const Vec2 q = points[j];
      if (std::fabs(q.y - p.y) <= eps && distance(p, q) <= eps) uf.unite(order[i], order[j]);
    }
  }
  if (work > budget) unite_close_by_cells(points, order, eps, uf, s.by_cell);
  const size_t count = splits.size();  // read once: the stores below could alias it
  s.vertex_of.resize(count);
  s.vertex_of_root.assign(count, -1);
  s.splits_at.resize(count);  // at most one vertex per split point
  int* vertex_of = s.vertex_of.data();
  int* vertex_of_root = s.vertex_of_root.data();
  int* splits_at = s.splits_at.data();
  std::memset(splits_at, 0, count * sizeof(int));
  for (size_t i = 0; i < count; ++i) {
    const int root = s.uf.find(int(i));
    if (vertex_of_root[root] < 0) {
      vertex_of_root[root] = int(vertices.size());
      vertices.push_back(splits[root].p);
    }
    vertex_of[i] = vertex_of_root[root];
    ++splits_at[vertex_of[i]];
  }
}

// The piece of c between parameters t0 and t1, snapped to the given ends (make_arc without
// the trigonometry for ends that are replaced anyway). A whole arc's bulge is the one its
// maker computed, when `trig` remembers it.
Curve piece_of(const Curve& c, double t0, double t1, Vec2 from, Vec2 to, TrigMemo* trig) {
  if (c.is_segment()) return make_segment(from, to);
  const double start = c.start_angle + t0 * c.sweep, sweep = (t1 - t0) * c.sweep;
  if (trig && t0 == 0.0 && t1 == 1.0)
    return make_arc_between_using(*trig, c.center, c.radius, start, sweep, from, to);
  return make_arc_between(c.center, c.radius, start, sweep, from, to);
}

// The pieces leaving simple crossings into the other curve's blocked side (edge_pieces.hpp:
// two curves crossing at a vertex of no other split point; the crossing's pair of split
// points was made one after the other), except at crossings at an angle within the angular
// tolerance. s.piece_from[i] and s.piece_to[i] name the pieces starting and ending at split
// point i, when they are pieces that do (stale entries are told by their ends).
void find_inside_pieces(Scratch& s, const std::vector<Curve>& curves, double angular_eps) {
  const std::vector<SplitPoint>& splits = s.splits;
  const std::vector<Piece>& pieces = s.pieces;
  auto from = [&](size_t i) {
    const size_t p = size_t(s.piece_from[i]);
    return p < pieces.size() && s.at_t[size_t(pieces[p].at)].second == int(i) ? int(p) : -1;
  };
  auto to = [&](size_t i) {
    const size_t p = size_t(s.piece_to[i]);
    return p < pieces.size() && s.at_t[size_t(pieces[p].at) + 1].second == int(i) ? int(p) : -1;
  };
  // The first 2 * curves are the curves' ends; meetings come in pairs from there.
  for (size_t i = 2 * curves.size(); i + 1 < splits.size(); i += 2) {
    const SplitPoint &a = splits[i], &b = splits[i + 1];
    if (a.how != Meeting::crossing) continue;
    const int vertex = s.vertex_of[i];
    if (s.splits_at[size_t(vertex)] != 2 || s.vertex_of[i + 1] != vertex || b.curve != a.met)
      continue;
    const int a_ahead = from(i), a_behind = to(i), b_ahead = from(i + 1), b_behind = to(i + 1);
    if (a_ahead < 0 || a_behind < 0 || b_ahead < 0 || b_behind < 0) continue;
    // Sine of the angle from b's tangent to a's (where the pieces start, as the vertex's
    // order of directions takes them): a leaving forward lies on b's left when > 0, and b
    // arriving on a's left; the other way round when < 0.
    const double turn = cross(s.on_curve[size_t(pieces[size_t(b_ahead)].at)].tangent,
                              s.on_curve[size_t(pieces[size_t(a_ahead)].at)].tangent);
    if (std::fabs(turn) <= angular_eps) continue;
    s.inside_pieces.push_back({turn > 0.0 ? a_ahead : b_ahead, vertex});
    s.inside_pieces.push_back({turn > 0.0 ? b_behind : a_behind, vertex});
  }
}

// The pieces of the curves between their split points, made into edges (edge_pieces.hpp).
void build_edges(Arrangement& arr, Scratch& s, const std::vector<Curve>& curves,
                 const std::vector<int>& ids, double eps, double angular_eps, TrigMemo* trig,
                 bool peel) {
  const std::vector<SplitPoint>& splits = s.splits;
  const std::vector<int>& vertex_of = s.vertex_of;
  // Split points along each curve in order of (t, index): grouped by curve, then each
  // curve's few points sorted (as compact (t, index) pairs).
  // The grouping by curve is split_points' own when it added no points after building it.
  const SplitsByCurve* grouped = s.split.grouping();
  if (!grouped)
    group_by(
        splits.size(), curves.size(), [&](size_t i) { return splits[i].curve; }, s.start, s.along,
        s.fill);
  const std::vector<int>& start = grouped ? grouped->start : s.start;
  const std::vector<int>& along = grouped ? grouped->index : s.along;
  std::vector<std::pair<double, int>>& at_t = s.at_t;
  at_t.resize(splits.size());
  const size_t count = along.size();  // read once: the stores below could alias it
  for (size_t k = 0; k < count; ++k) at_t[k] = {splits[along[k]].t, along[k]};
  // pair's operator<, spelled out.
  auto by_t = [](const std::pair<double, int>& a, const std::pair<double, int>& b) {
    return a.first < b.first || (a.first == b.first && a.second < b.second);
  };
  for (size_t c = 0; c < curves.size(); ++c)
    small_sort(at_t.begin() + start[c], at_t.begin() + start[c + 1], by_t);
  // Where each split point really is on its curve, and the curve's tangent there: one sine
  // and cosine per point of an arc (point_at and tangent_at, sharing the radial direction),
  // at an arc's ends the ones its maker took, when `trig` remembers them.
  // A segment's tangent is the same everywhere: computed once per curve (`direction`).
  Vec2 direction;
  auto on_curve = [&](const Curve& c, double t) {
    if (c.is_segment()) return Scratch::OnCurve{point_at(c, t), direction};
    const double angle = c.start_angle + t * c.sweep;
    const Vec2 radial =
        trig && (t == 0.0 || t == 1.0) ? trig->unit_vector(angle) : unit_vector(angle);
    const Vec2 p = t == 0.0 ? c.from : t == 1.0 ? c.to : c.center + c.radius * radial;
    return Scratch::OnCurve{p, c.sweep > 0.0 ? perp_left(radial) : perp_right(radial)};
  };
  std::vector<Piece>& pieces = s.pieces;
  pieces.clear();
  s.piece_from.resize(splits.size());  // not cleared: find_inside_pieces tells stale entries
  s.piece_to.resize(splits.size());
  int* piece_from = s.piece_from.data();
  int* piece_to = s.piece_to.data();
  std::vector<Scratch::OnCurve>& on = s.on_curve;  // per entry of at_t that starts or ends a piece
  on.resize(count);
  for (size_t c = 0; c < curves.size(); ++c) {
    const Curve& curve = curves[c];
    if (curve.is_segment()) direction = normalized(curve.to - curve.from);
    int known = -1;  // the entry of at_t whose place `on` holds, from the piece before
    const int last = start[c + 1] - 1;
    for (int k = start[c]; k < last; ++k) {
      const auto [ta, a] = at_t[k];
      const auto [tb, b] = at_t[k + 1];
      // Consecutive points at one vertex make no edge, except a full circle's only piece.
      if (vertex_of[a] == vertex_of[b] && (!curve.is_full_circle() || tb - ta < 0.5)) continue;
      if (known != k) on[k] = on_curve(curve, ta);
      on[k + 1] = on_curve(curve, tb);
      known = k + 1;
      piece_from[a] = piece_to[b] = int(pieces.size());
      pieces.push_back({vertex_of[a], vertex_of[b], ids[c], int(c), k});
    }
  }
  s.inside_pieces.clear();
  if (peel) find_inside_pieces(s, curves, angular_eps);
  auto curve_of = [&](const Piece& p) {
    return piece_of(curves[p.curve], at_t[p.at].first, at_t[p.at + 1].first, arr.vertices[p.u],
                    arr.vertices[p.v], trig);
  };
  // Built in place, field by field (a default edge first, then assigned, wrote each field
  // twice).
  auto emit = [&](const Piece& p) {
    arr.edges.emplace_back(p.u, p.v, curve_of(p), EdgeLabels(EdgeLabel{p.segment, true}), p.curve,
                           on[p.at].tangent, on[p.at + 1].tangent, on[p.at].point,
                           on[p.at + 1].point);
  };
  edges_from_pieces(pieces, arr.vertices.size(), eps, peel, s.inside_pieces, curve_of, emit,
                    s.edge_pieces, arr.edges);
}

// The half-edges grouped by origin, as group_by(2 * edges, vertices, origin) groups them
// (each vertex's in increasing order), read edge by edge: half-edge 2e leaves u, 2e + 1
// leaves v, with no choice by parity per half-edge.
void group_outgoing(Arrangement& arr, std::vector<int>& fill) {
  std::vector<int>& start = arr.outgoing_start;
  std::vector<int>& order = arr.outgoing_edges;
  const size_t edges = arr.edges.size(), vertices = arr.vertices.size();
  start.assign(vertices + 1, 0);
  for (size_t e = 0; e < edges; ++e) {
    ++start[arr.edges[e].u + 1];
    ++start[arr.edges[e].v + 1];
  }
  for (size_t g = 0; g < vertices; ++g) start[g + 1] += start[g];
  order.resize(2 * edges);
  fill.assign(start.begin(), start.end() - 1);
  for (size_t e = 0; e < edges; ++e) {
    order[fill[arr.edges[e].u]++] = int(2 * e);
    order[fill[arr.edges[e].v]++] = int(2 * e + 1);
  }
}

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
bool lies_clockwise(const Direction& a, const Direction& b, Meetings& meetings, double eps,
                    double angular_eps) {
  const double gap = b.angle - a.angle;
  // A tangency also joins curves leaving in opposite directions (one continuing the other);
  // only curves leaving side by side are tied.
  if (gap >= 0.5 * kPi) return false;
  const int lo = std::min(a.curve, b.curve), hi = std::max(a.curve, b.curve);
  if (a.curvature != b.curvature && (gap <= angular_eps || meetings.tangent(lo, hi)))
    return a.curvature > b.curvature;
  if (meetings.crossing(a.vertex, lo, hi)) return false;
  const Vec2 ahead_a = a.start + eps * a.tangent, ahead_b = b.start + eps * b.tangent;
  return cross(a.tangent + b.tangent, ahead_b - ahead_a) < 0.0;
}

// std::atan2(t.y, t.x) for a piece of segment `curve` leaving forward or backward, the value
// computed for an earlier piece when it left in the same direction (compared bit for bit:
// the memo outlives the slice it was filled in, and atan2 tells -0 from +0).
double segment_angle(std::vector<Scratch::AngleMemo>& memo, int curve, bool forward, Vec2 t) {
  const size_t k = 2 * size_t(curve) + (forward ? 0 : 1);
  if (memo.size() <= k) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    memo.resize(2 * k + 2,
                {std::bit_cast<uint64_t>(nan), std::bit_cast<uint64_t>(nan), std::atan2(nan, nan)});
  }
  Scratch::AngleMemo& m = memo[k];
  const uint64_t x = std::bit_cast<uint64_t>(t.x), y = std::bit_cast<uint64_t>(t.y);
  if (m.x != x || m.y != y) m = {x, y, std::atan2(t.y, t.x)};
  return m.angle;
}

// Orders the half-edges leaving each vertex counterclockwise by tangent, ties (tangent
// curves) broken by curvature: the one turning left comes later. Only vertices of degree 3
// or more need it: one or two half-edges are in counterclockwise order either way, and
// every later step reads the order cyclically (next around a face, sectors between
// neighbours), so those are left in half-edge order without computing their angles.
void order_outgoing(Arrangement& arr, Scratch& s, double eps, double angular_eps) {
  group_outgoing(arr, s.fill);
  std::vector<Direction>& dirs = s.dirs;  // by half-edge, those at vertices of degree >= 3
  dirs.resize(2 * arr.edges.size());
  const size_t vertices = arr.vertices.size();  // read once: the stores below could alias it
  for (size_t v = 0; v < vertices; ++v) {
    if (arr.outgoing_start[v + 1] - arr.outgoing_start[v] < 3) continue;
    const auto first = arr.outgoing_edges.begin() + arr.outgoing_start[v];
    const auto last = arr.outgoing_edges.begin() + arr.outgoing_start[v + 1];
    for (auto it = first; it != last; ++it) {
      const int h = *it;
      const ArrangementEdge& edge = arr.edges[h / 2];
      const bool forward = h % 2 == 0;
      const Vec2 t = forward ? edge.tangent_u : -edge.tangent_v;
      const double k = signed_curvature(edge.curve);
      Direction& x = dirs[h];
      x = {int(v),
           h,
           edge.source,
           edge.curve.is_segment() ? segment_angle(s.segment_angles, edge.source, forward, t)
                                   : std::atan2(t.y, t.x),
           forward ? k : -k,
           t,
           forward ? edge.point_u : edge.point_v};
      if (x.angle > kPi - angular_eps) x.angle -= kTwoPi;  // one representative for +-pi
    }
    small_sort(first, last, [&](int a, int b) {
      return dirs[a].angle != dirs[b].angle ? dirs[a].angle < dirs[b].angle : a < b;
    });
    // Insertion pass: nearly sorted already, only neighbours side by side move.
    for (auto i = first + 1; i < last; ++i)
      for (auto j = i;
           j > first && lies_clockwise(dirs[*(j - 1)], dirs[*j], s.meetings, eps, angular_eps); --j)
        std::iter_swap(j - 1, j);
  }
}

// Links each half-edge to the next around its left face: at its target, the half-edge just
// clockwise of its twin.
// Through plain pointers: the arrays are read and written per half-edge, and stores
// through the vectors made every other array's data pointer and size be read again.
void link_half_edges(Arrangement& arr, Scratch& s) {
  const size_t n = 2 * arr.edges.size();
  s.position.resize(n);
  arr.next.resize(n);  // every entry is set below
  int* position = s.position.data();
  int* next = arr.next.data();
  const int* start = arr.outgoing_start.data();
  const int* outgoing = arr.outgoing_edges.data();
  const int vertices = int(arr.vertices.size());
  for (int v = 0; v < vertices; ++v)
    for (int k = start[v]; k < start[v + 1]; ++k) position[outgoing[k]] = k - start[v];
  // The half-edge just clockwise of `twin` among those leaving w.
  auto clockwise_of = [&](int w, int twin) {
    const int p = position[twin];  // the one before it, cyclically (no division per edge)
    return outgoing[p > 0 ? start[w] + p - 1 : start[w + 1] - 1];
  };
  // By edge: its forward half-edge ends at v, its backward one at u (no choice by parity).
  const ArrangementEdge* edges = arr.edges.data();
  const size_t count = arr.edges.size();
  for (size_t e = 0; e < count; ++e) {
    const int h = int(2 * e);
    next[h] = clockwise_of(edges[e].v, h + 1);
    next[h + 1] = clockwise_of(edges[e].u, h);
  }
}

void vertex_components(const Arrangement& arr, Scratch& s) {
  s.uf.reset(arr.vertices.size());
  for (const ArrangementEdge& e : arr.edges) s.uf.unite(e.u, e.v);
  s.comp.resize(arr.vertices.size());
  for (size_t v = 0; v < s.comp.size(); ++v) s.comp[v] = s.uf.find(int(v));
}

// signed_area_contribution(c), with the sine of an arc's sweep from `trig` when given (an arc
// cut nowhere keeps its sweep from slice to slice).
double area_term(const Curve& c, TrigMemo* trig) {
  return trig ? signed_area_contribution_using(*trig, c) : signed_area_contribution(c);
}

void trace_cycles(Arrangement& arr, Scratch& s, TrigMemo* trig) {
  const size_t n = 2 * arr.edges.size();
  vertex_components(arr, s);
  // Per edge, once: its area term (the twin's is the negation: the chord's cross product and
  // the circular segment both change sign).
  std::vector<double>& area = s.area;
  const size_t edges = arr.edges.size();  // read once: the stores below could alias it
  area.resize(n);  // per half-edge: the walk below adds without choosing by parity
  for (size_t e = 0; e < edges; ++e) {
    area[2 * e] = area_term(arr.edges[e].curve, trig);
    area[2 * e + 1] = -area[2 * e];
  }
  // Every half-edge is listed once, in one cycle: the list is sized up front and the walk
  // writes through plain pointers (a push_back per half-edge, and the cycle count reread
  // after every store, cost more than the walk itself).
  arr.cycle_of.assign(n, -1);
  arr.cycle_half_edges.resize(n);
  int* cycle_of = arr.cycle_of.data();
  int* listed = arr.cycle_half_edges.data();
  const int* next = arr.next.data();
  const double* area_of = area.data();
  int count = 0;
  for (size_t start = 0; start < n; ++start) {
    if (cycle_of[start] >= 0) continue;
    ArrangementCycle cycle;
    cycle.first = count;
    cycle.component = s.comp[arr.origin(int(start))];
    const int id = int(arr.cycles.size());
    int h = int(start);
    do {
      cycle_of[h] = id;
      listed[count++] = h;
      cycle.area += area_of[h];
      h = next[h];
    } while (h != int(start) && cycle_of[h] < 0);
    cycle.count = count - cycle.first;
    arr.cycles.push_back(cycle);
  }
  arr.cycle_half_edges.resize(size_t(count));
}

// Even-odd containment of many points (sorted by y) in one cycle at once: each curve toggles
// only the points within its own y-range, so a long cycle costs its length plus the points
// near each curve, not its length times the points. Fills `inside`; `edge_boxes` are the
// edges' boxes.
void cycle_encloses(const Arrangement& arr, int cycle, const std::vector<Box>& edge_boxes,
                    const std::vector<Vec2>& points_by_y, std::vector<char>& inside) {
  inside.assign(points_by_y.size(), false);
  auto y_less = [](const Vec2& p, double y) { return p.y < y; };
  for (int h : arr.half_edges(cycle)) {
    const Curve& curve = arr.edges[h / 2].curve;  // parity does not depend on direction
    const Box& box = edge_boxes[h / 2];
    auto it = std::lower_bound(points_by_y.begin(), points_by_y.end(), box.lo.y, y_less);
    for (; it != points_by_y.end() && it->y <= box.hi.y; ++it)
      if (toggles_parity(curve, *it)) inside[it - points_by_y.begin()] ^= 1;
  }
}

// Lists each face's cycles: a bounded face's own cycle first, then the outer cycles of the
// components inside it in cycle order, so face cycle lists do not depend on how the faces
// were found.
void list_face_cycles(Arrangement& arr, Scratch& s) {
  const std::vector<int>& outer = s.outer_of_component;
  std::vector<int>& fill = s.fill;
  fill.assign(arr.faces.size(), 0);
  for (const ArrangementCycle& c : arr.cycles) ++fill[c.face];
  int first = 0;
  for (size_t f = 0; f < arr.faces.size(); ++f) {
    arr.faces[f].first = first;
    arr.faces[f].count = fill[f];
    first += fill[f];
    fill[f] = arr.faces[f].first;
  }
  arr.face_cycle_list.resize(arr.cycles.size());
  for (size_t c = 0; c < arr.cycles.size(); ++c)
    if (outer[arr.cycles[c].component] != int(c))
      arr.face_cycle_list[fill[arr.cycles[c].face]++] = int(c);
  for (size_t c = 0; c < arr.cycles.size(); ++c)
    if (outer[arr.cycles[c].component] == int(c))
      arr.face_cycle_list[fill[arr.cycles[c].face]++] = int(c);
}

// The box of cycle k, and those of its edges, computed on first use after a build.
const Box& cycle_box_of(const Arrangement& arr, Scratch& s, int k) {
  if (s.cycle_box_known[k]) return s.cycle_box[k];
  Box b;  // built in a local: stores to s.box would make the compiler reload it
  for (int h : arr.half_edges(k)) {
    const int e = h / 2;
    if (!s.box_known[e]) {
      s.box[e] = bounding_box(arr.edges[e].curve);
      s.box_known[e] = true;
    }
    b.add(s.box[e]);
  }
  s.cycle_box[k] = b;
  s.cycle_box_known[k] = true;
  return s.cycle_box[k];
}

// Places each outer cycle (s.probes, sorted by y) in the smallest bounded cycle of another
// component enclosing its probe point: cycles are tried smallest first (s.bounded), each
// against the still unplaced points in its box.
void place_outer_cycles(Arrangement& arr, Scratch& s) {
  const std::vector<Scratch::Probe>& probes = s.probes;
  std::sort(s.bounded.begin(), s.bounded.end(),
            [&](int a, int b) { return arr.cycles[a].area < arr.cycles[b].area; });
  s.placed.assign(probes.size(), false);
  size_t unplaced = probes.size();
  for (int k : s.bounded) {
    if (unplaced == 0) break;  // the larger cycles left would place nothing: no boxes for them
    const ArrangementCycle& o = arr.cycles[k];
    const Box& o_box = cycle_box_of(arr, s, k);
    s.candidates.clear();
    s.points.clear();
    auto it = std::lower_bound(probes.begin(), probes.end(), o_box.lo.y,
                               [](const Scratch::Probe& a, double y) { return a.p.y < y; });
    for (; it != probes.end() && it->p.y <= o_box.hi.y; ++it) {
      const size_t i = it - probes.begin();
      if (s.placed[i] || it->p.x < o_box.lo.x || it->p.x > o_box.hi.x ||
          arr.cycles[it->cycle].component == o.component)
        continue;
      s.candidates.push_back(int(i));
      s.points.push_back(it->p);
    }
    if (s.candidates.empty()) continue;
    cycle_encloses(arr, k, s.box, s.points, s.inside);
    for (size_t j = 0; j < s.candidates.size(); ++j) {
      if (!s.inside[j]) continue;
      s.placed[s.candidates[j]] = true;
      --unplaced;
      arr.cycles[probes[s.candidates[j]].cycle].face = o.face;
    }
  }
}

// Every connected component has exactly one outer cycle, the one of least signed area (a
// tree's only cycle has area 0); each of its other cycles bounds a face of its own, however
// small, so no area threshold decides topology. An outer cycle belongs to the smallest
// bounded face of another component around it, or to the unbounded face.
void assign_faces(Arrangement& arr, Scratch& s) {
  std::vector<int>& outer = s.outer_of_component;  // by component (its lowest vertex)
  outer.assign(arr.vertices.size(), -1);
  for (size_t c = 0; c < arr.cycles.size(); ++c) {
    int& o = outer[arr.cycles[c].component];
    if (o < 0 || arr.cycles[c].area < arr.cycles[o].area) o = int(c);
  }
  arr.faces.assign(1, ArrangementFace{});
  std::vector<int>& bounded = s.bounded;
  bounded.clear();
  for (size_t c = 0; c < arr.cycles.size(); ++c) {
    if (outer[arr.cycles[c].component] == int(c)) continue;
    arr.cycles[c].face = int(arr.faces.size());
    arr.faces.push_back({true});
    bounded.push_back(int(c));
  }
  // Each outer cycle is represented by its first vertex; its face is the smallest bounded
  // cycle of another component enclosing that point.
  std::vector<Scratch::Probe>& probes = s.probes;
  probes.clear();
  for (size_t c = 0; c < arr.cycles.size(); ++c) {
    if (outer[arr.cycles[c].component] != int(c)) continue;
    arr.cycles[c].face = 0;
    probes.push_back({arr.vertices[arr.origin(arr.half_edges(int(c)).front())], int(c)});
  }
  std::sort(probes.begin(), probes.end(),
            [](const Scratch::Probe& a, const Scratch::Probe& b) { return a.p.y < b.p.y; });
  // One component: no other to place (its outer cycle is the only probe), and no boxes.
  if (probes.size() > 1) place_outer_cycles(arr, s);
  list_face_cycles(arr, s);
}

// The pairs of curves the intersection step found tangent anywhere, or crossing at a vertex.
void collect_meetings(Scratch& s, size_t curves) {
  Meetings& m = s.meetings;
  m.clear();
  // A meeting makes a split point on each curve, at the same point (so at the same vertex)
  // and the same way: the one on the lower curve tells it.
  // The first 2 * curves are the curves' ends, no meetings (see split_points).
  const size_t count = s.splits.size();  // read once: the stores below could alias it
  for (size_t i = 2 * curves; i < count; ++i) {
    const SplitPoint& sp = s.splits[i];
    if (sp.how == Meeting::other || sp.curve > sp.met) continue;
    if (sp.how == Meeting::tangent)
      m.add_tangent(sp.curve, sp.met);
    else
      m.add_crossing(s.vertex_of[i], sp.curve, sp.met);
  }
}

}  // namespace

const Box& ArrangementBuilder::cycle_box(int cycle) {
  return cycle_box_of(arr_, *scratch_, cycle);
}

ArrangementBuilder::ArrangementBuilder() : scratch_(std::make_unique<Scratch>()) {}
ArrangementBuilder::~ArrangementBuilder() = default;
ArrangementBuilder::ArrangementBuilder(ArrangementBuilder&&) noexcept = default;
ArrangementBuilder& ArrangementBuilder::operator=(ArrangementBuilder&&) noexcept = default;

const Arrangement& ArrangementBuilder::build(const std::vector<Curve>& curves,
                                             const std::vector<int>& segment_ids,
                                             const Tolerances& tol, TrigMemo* trig,
                                             bool peel_dangling_edges) {
  Arrangement& arr = arr_;
  Scratch& s = *scratch_;
  arr.vertices.clear();
  arr.edges.clear();
  arr.cycles.clear();
  arr.cycle_half_edges.clear();
  split_points(curves, tol.geometric, s.split, s.splits);
  merge_points(s, tol.geometric, arr.vertices);
  build_edges(arr, s, curves, segment_ids, tol.geometric, tol.angular, trig, peel_dangling_edges);
  collect_meetings(s, curves.size());
  order_outgoing(arr, s, tol.geometric, tol.angular);
  link_half_edges(arr, s);
  trace_cycles(arr, s, trig);
  s.box.resize(arr.edges.size());
  s.box_known.assign(arr.edges.size(), false);
  s.cycle_box.resize(arr.cycles.size());
  s.cycle_box_known.assign(arr.cycles.size(), false);
  assign_faces(arr, s);
  return arr;
}

}  // namespace cslice
