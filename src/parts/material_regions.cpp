// Regions of material standing on straight edges (see material_regions.hpp).
#include "parts/material_regions.hpp"

#include <algorithm>
#include <limits>

namespace cslice {
namespace {

// Deepest region, in lengths of its edge (see material_regions.hpp).
constexpr double kMaxDepthPerLength = 2.0;

Vec2 unit_direction(const Curve& c) {
  return normalized(c.to - c.from);
}

// Narrows [lo, hi] to the t where v0 + t (v1 - v0) lies strictly between a and b; an empty
// result has lo >= hi.
void narrow(double v0, double v1, double a, double b, double& lo, double& hi) {
  const double dv = v1 - v0;
  if (dv == 0.0) {
    if (!(v0 > a && v0 < b)) hi = lo;
    return;
  }
  double ta = (a - v0) / dv, tb = (b - v0) / dv;
  if (dv < 0.0) std::swap(ta, tb);
  lo = std::max(lo, ta);
  hi = std::min(hi, tb);
}

// The lowest height of the part of segment (p, q) (in the edge's frame) that lies above the
// edge's line and between its corner bisectors pushed out by margin; infinity when none.
double lowest_inside(Vec2 p, Vec2 q, double length, const MaterialRegion& r, double margin) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const Vec2 end{length, 0.0};
  double lo = 0.0, hi = 1.0;
  narrow(p.y, q.y, 0.0, inf, lo, hi);
  narrow(cross(r.start_side, p), cross(r.start_side, q), -inf, margin, lo, hi);
  narrow(cross(r.end_side, p - end), cross(r.end_side, q - end), -margin, inf, lo, hi);
  if (!(lo < hi)) return inf;
  return std::min(p.y + lo * (q.y - p.y), p.y + hi * (q.y - p.y));
}

struct EdgeRef {
  const Curve* curve;
  Box box;
  int loop, index;
};

// The region of edge i of the loop before other edges limit its depth; nullopt-like depth 0
// when it has none.
MaterialRegion corner_sides(const Loop& loop, int i) {
  const int n = int(loop.edges.size());
  const Curve& e = loop.edges[size_t(i)];
  const Curve& prev = loop.edges[size_t((i + n - 1) % n)];
  const Curve& next = loop.edges[size_t((i + 1) % n)];
  MaterialRegion r;
  if (n < 3 || !prev.is_segment() || !next.is_segment()) return r;
  const Vec2 along = unit_direction(e), across = perp_left(along);
  // A corner's bisector is the sum of its two edges' inward normals (convex and reflex
  // corners alike; perpendicular where they are collinear).
  const Vec2 b0 = normalized(across + perp_left(unit_direction(prev)));
  const Vec2 b1 = normalized(across + perp_left(unit_direction(next)));
  if (!is_finite(along) || !is_finite(b0) || !is_finite(b1)) return r;
  r.start_side = {dot(b0, along), dot(b0, across)};
  r.end_side = {dot(b1, along), dot(b1, across)};
  // A cusp's bisector runs along the edge: no region.
  if (r.start_side.y > 0.0 && r.end_side.y > 0.0)
    r.depth = kMaxDepthPerLength * distance(e.from, e.to);
  return r;
}

}  // namespace

// Why the edges left out of the depth search cannot come within margin of a point of the
// region higher than margin: a straight neighbour at a convex corner lies beyond the
// bisector, where points are nearer the edge's line than the neighbour's; at a reflex or
// flat corner it lies below the edge's line. Every other edge that comes within margin of
// the region meets it with its sides pushed out by margin, and limits the depth there.
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
  for (size_t f = 0; f < part.features.size(); ++f) {
    const Feature& feature = part.features[f];
    if (feature.kind != FeatureKind::segment) continue;
    const Loop& loop = part.loops[size_t(feature.loop)];
    const int n = int(loop.edges.size()), i = feature.index;
    MaterialRegion r = corner_sides(loop, i);
    if (r.depth <= 0.0) continue;
    const Curve& e = loop.edges[size_t(i)];
    const Vec2 along = unit_direction(e), across = perp_left(along);
    auto world = [&](Vec2 v) { return v.x * along + v.y * across; };
    auto local = [&](Vec2 p) { return Vec2{dot(p - e.from, along), dot(p - e.from, across)}; };
    Box reach = bounding_box(e).inflated(margin);
    reach.add(e.from + world(r.start_side * (r.depth / r.start_side.y)));
    reach.add(e.to + world(r.end_side * (r.depth / r.end_side.y)));
    reach = reach.inflated(margin);
    auto first = std::lower_bound(edges.begin(), edges.end(), reach.lo.x - widest,
                                  [](const EdgeRef& g, double x) { return g.box.lo.x < x; });
    for (auto g = first; g != edges.end() && g->box.lo.x <= reach.hi.x; ++g) {
      if (!g->box.overlaps(reach)) continue;
      if (g->loop == feature.loop &&
          (g->index == i || g->index == (i + 1) % n || g->index == (i + n - 1) % n))
        continue;
      const Curve& c = *g->curve;
      if (c.is_segment()) {
        r.depth = std::min(
            r.depth, lowest_inside(local(c.from), local(c.to), distance(e.from, e.to), r, margin));
      } else {
        // An arc: the lowest corner of its box, no higher than any of its points.
        const Box& b = g->box;
        for (Vec2 p : {b.lo, b.hi, Vec2{b.lo.x, b.hi.y}, Vec2{b.hi.x, b.lo.y}})
          r.depth = std::min(r.depth, std::max(0.0, local(p).y));
      }
    }
    regions[f] = r;
  }
  return regions;
}

}  // namespace cslice
