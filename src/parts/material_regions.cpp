// Regions of material standing on straight edges (see material_regions.hpp).
#include "parts/material_regions.hpp"

#include <algorithm>
#include <limits>

#include "geometry/clip.hpp"

namespace cslice {
namespace {

// Deepest region, in lengths of its edge (see material_regions.hpp).
constexpr double kMaxDepthPerLength = 2.0;
// How often a region is halved for arcs near it before it is given up, and the share of the
// margin an arc may come closer than it (see material_regions below).
constexpr int kMaxHalvings = 12;
constexpr double kArcClearanceSlack = 1e-3;

Vec2 unit_direction(const Curve& c) {
  return normalized(c.to - c.from);
}

// The lowest height of the part of segment (p, q) (in the edge's frame) that lies above the
// edge's line and between its corner bisectors pushed out by margin; infinity when none.
double lowest_inside(Vec2 p, Vec2 q, double length, const MaterialRegion& r, double margin) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const Vec2 end{length, 0.0};
  double lo = 0.0, hi = 1.0;
  bool whole = true;
  if (!narrow_to_band(p.y, q.y, 0.0, inf, lo, hi, whole) ||
      !narrow_to_band(cross(r.start_side, p), cross(r.start_side, q), -inf, margin, lo, hi,
                      whole) ||
      !narrow_to_band(cross(r.end_side, p - end), cross(r.end_side, q - end), -margin, inf, lo, hi,
                      whole))
    return inf;
  return std::min(p.y + lo * (q.y - p.y), p.y + hi * (q.y - p.y));
}

struct EdgeRef {
  const Curve* curve;
  Box box;
  int loop, index;
};

// The region of edge i of the loop before other edges limit its depth; depth 0 when it has
// none.
MaterialRegion corner_sides(const Loop& loop, int i) {
  const int n = int(loop.edges.size());
  const Curve& e = loop.edges[size_t(i)];
  const Curve& prev = loop.edges[size_t((i + n - 1) % n)];
  const Curve& next = loop.edges[size_t((i + 1) % n)];
  MaterialRegion r;
  if (n < 3) return r;
  const Vec2 along = unit_direction(e), across = perp_left(along);
  // A corner's bisector is the sum of its two edges' inward normals where they meet (convex
  // and reflex corners alike; perpendicular where they are collinear or tangent).
  const Vec2 b0 = normalized(across + perp_left(normalized(tangent_at(prev, 1.0))));
  const Vec2 b1 = normalized(across + perp_left(normalized(tangent_at(next, 0.0))));
  if (!is_finite(along) || !is_finite(b0) || !is_finite(b1)) return r;
  r.start_side = {dot(b0, along), dot(b0, across)};
  r.end_side = {dot(b1, along), dot(b1, across)};
  // A cusp's bisector runs along the edge: no region.
  if (r.start_side.y > 0.0 && r.end_side.y > 0.0)
    r.depth = kMaxDepthPerLength * distance(e.from, e.to);
  return r;
}

// The region's part higher than margin and lower than depth less margin, as a convex polygon
// in the part's frame (three or four corners); empty when its corner sides meet below margin.
std::vector<Vec2> inner_polygon(const MaterialRegion& r, double length, double margin, Vec2 origin,
                                Vec2 along, Vec2 across) {
  auto world = [&](Vec2 v) { return origin + v.x * along + v.y * across; };
  const double top = r.depth - margin;
  const Vec2 s0 = r.start_at(margin), e0 = r.end_at(margin, length);
  if (!(s0.x < e0.x)) return {};
  const Vec2 s1 = r.start_at(top), e1 = r.end_at(top, length);
  if (s1.x < e1.x) return {world(s0), world(e0), world(e1), world(s1)};
  // The sides meet between: at a r.start_side = end + b r.end_side.
  const double a = cross(Vec2{length, 0.0}, r.end_side) / cross(r.start_side, r.end_side);
  return {world(s0), world(e0), world(r.start_side * a)};
}

// Whether every point of the arc lies at least `clearance` from the convex polygon: it keeps
// that far from the polygon's sides and does not lie inside it.
bool arc_clear_of(const Curve& arc, const std::vector<Vec2>& polygon, double clearance) {
  const size_t n = polygon.size();
  bool inside = true;
  for (size_t k = 0; k < n; ++k) {
    const Vec2 a = polygon[k], b = polygon[(k + 1) % n];
    if (distance_segment_arc(make_segment(a, b), arc) < clearance) return false;
    inside = inside && cross(b - a, arc.from - a) > 0.0;
  }
  return !inside;
}

}  // namespace

// Why the edges left out of the depth search cannot come within margin of a point of the
// region higher than margin: a straight neighbour at a convex corner lies beyond the
// bisector, where points are nearer the edge's line than the neighbour's; at a reflex or
// flat corner it lies below the edge's line. Every other straight edge that comes within
// margin of the region meets it with its sides pushed out by margin, and limits the depth
// there. Arcs, neighbours or not, are checked against the region itself: its depth is halved
// until each keeps clear of the part higher than margin by the margin (less a thousandth,
// for the round-off of the distance at a corner where an arc leaves the edge tangentially
// and comes exactly that close), or the region is given up.
std::vector<MaterialRegion> material_regions(const Part& part, double margin) {
  std::vector<MaterialRegion> regions(part.features.size());
  std::vector<EdgeRef> edges;
  double widest = 0.0;
  for (size_t l = 0; l < part.loops.size(); ++l)
    for (size_t i = 0; i < part.loops[l].edges.size(); ++i) {
      const Curve& c = part.loops[l].edges[i];
      const Box box = bounding_box(c);
      edges.push_back({&c, box, int(l), int(i)});
      widest = std::max(widest, box.hi.x - box.lo.x);
    }
  std::sort(edges.begin(), edges.end(),
            [](const EdgeRef& a, const EdgeRef& b) { return a.box.lo.x < b.box.lo.x; });
  std::vector<const Curve*> near_arcs;
  for (size_t f = 0; f < part.features.size(); ++f) {
    const Feature& feature = part.features[f];
    if (feature.kind != FeatureKind::segment) continue;
    const Loop& loop = part.loops[size_t(feature.loop)];
    const int n = int(loop.edges.size()), i = feature.index;
    MaterialRegion r = corner_sides(loop, i);
    if (r.depth <= 0.0) continue;
    const Curve& e = loop.edges[size_t(i)];
    const double length = distance(e.from, e.to);
    const Vec2 along = unit_direction(e), across = perp_left(along);
    auto world = [&](Vec2 v) { return e.from + v.x * along + v.y * across; };
    auto local = [&](Vec2 p) { return Vec2{dot(p - e.from, along), dot(p - e.from, across)}; };
    Box reach = bounding_box(e).inflated(margin);
    reach.add(world(r.start_at(r.depth)));
    reach.add(world(r.end_at(r.depth, length)));
    reach = reach.inflated(margin);
    auto first = std::lower_bound(edges.begin(), edges.end(), reach.lo.x - widest,
                                  [](const EdgeRef& g, double x) { return g.box.lo.x < x; });
    for (auto g = first; g != edges.end() && g->box.lo.x <= reach.hi.x; ++g) {
      if (!g->box.overlaps(reach)) continue;
      const Curve& c = *g->curve;
      if (g->loop == feature.loop && g->index == i) continue;
      const bool neighbour =
          g->loop == feature.loop && (g->index == (i + 1) % n || g->index == (i + n - 1) % n);
      if (!c.is_segment())
        near_arcs.push_back(&c);
      else if (!neighbour)
        r.depth = std::min(r.depth, lowest_inside(local(c.from), local(c.to), length, r, margin));
    }
    const double clearance = (1.0 - kArcClearanceSlack) * margin;
    for (int halvings = 0; !near_arcs.empty() && r.depth > 2.0 * margin; ++halvings) {
      const std::vector<Vec2> inner = inner_polygon(r, length, margin, e.from, along, across);
      bool clear = !inner.empty();
      for (const Curve* arc : near_arcs) clear = clear && arc_clear_of(*arc, inner, clearance);
      if (clear) break;
      r.depth = halvings < kMaxHalvings ? 0.5 * r.depth : 0.0;
    }
    near_arcs.clear();
    regions[f] = r;
  }
  return regions;
}

}  // namespace cslice
