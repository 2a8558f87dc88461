// Part construction: loop nesting and orientation, features with convexity and normals, box
// and area. Runs after validation, so loops are simple and pairwise disjoint.
#include <algorithm>
#include <cmath>

#include "cslice/part.hpp"
#include "cslice/tolerance.hpp"
#include "parts/loop_queries.hpp"

namespace cslice {

std::string_view to_string(FeatureKind k) {
  switch (k) {
    case FeatureKind::segment:
      return "segment";
    case FeatureKind::arc:
      return "arc";
    case FeatureKind::vertex:
      return "vertex";
  }
  return "feature";
}

namespace {

// Nesting depth of each loop: how many other loops enclose it. Disjoint simple loops are
// either nested or apart, so one point of the loop decides (vertex 0; for a circle, its start
// point). Boxes screen out most candidates before the exact test.
std::vector<int> loop_depths(const Part& part) {
  const size_t n = part.loops.size();
  std::vector<Box> boxes(n);
  for (size_t i = 0; i < n; ++i)
    for (const Curve& c : part.loops[i].edges) boxes[i].add(bounding_box(c));
  std::vector<int> depth(n, 0);
  for (size_t i = 0; i < n; ++i) {
    const Vec2 p = part.loops[i].edges.front().from;
    for (size_t j = 0; j < n; ++j) {
      if (j == i || !boxes[j].overlaps(boxes[i])) continue;
      if (loop_encloses(part.loops[j].edges, p)) ++depth[i];
    }
  }
  return depth;
}

// Reverses the direction of travel, keeping vertex 0 where it is: new edge k runs from input
// vertex (n - k) % n to input vertex n - 1 - k.
void reverse_loop(Loop& loop) {
  std::vector<Curve> edges;
  edges.reserve(loop.edges.size());
  for (auto it = loop.edges.rbegin(); it != loop.edges.rend(); ++it) edges.push_back(reversed(*it));
  loop.edges = std::move(edges);
  loop.reversed = !loop.reversed;
}

// Material on the left: a loop at even depth bounds material from outside (counterclockwise)
// in an ordinary part and an opening (clockwise) in an enclosure; odd depths alternate.
void orient_loop(Loop& loop, bool enclosure) {
  const bool want_ccw = (loop.depth % 2 == 0) != enclosure;
  const bool is_ccw = loop_signed_area(loop.edges) > 0.0;
  if (want_ccw != is_ccw) reverse_loop(loop);
}

// With the material on the left, the outward normal is the travel tangent turned right.
Vec2 outward_normal(const Curve& c, double t) {
  return perp_right(tangent_at(c, t));
}

Feature edge_feature(const Loop& loop, int li, int ei) {
  const Curve& c = loop.edges[ei];
  Feature f;
  f.loop = li;
  f.index = ei;
  f.normal_in = outward_normal(c, 0.0);
  f.normal_out = outward_normal(c, 1.0);
  if (c.is_segment()) {
    f.kind = FeatureKind::segment;
    f.convexity = Convexity::flat;
  } else {
    // A counterclockwise arc with material on its left has the material inside its circle.
    f.kind = FeatureKind::arc;
    f.convexity = c.is_counterclockwise() ? Convexity::convex : Convexity::concave;
  }
  return f;
}

// Vertex ei joins edge ei-1 (incoming) to edge ei (outgoing). Turning left with the material
// on the left makes a corner that points out of the material: convex.
Feature vertex_feature(const Loop& loop, int li, int ei, double angular) {
  const int n = static_cast<int>(loop.edges.size());
  const Curve& in = loop.edges[(ei + n - 1) % n];
  const Curve& out = loop.edges[ei];
  const Vec2 t_in = tangent_at(in, 1.0), t_out = tangent_at(out, 0.0);
  const double turn = std::atan2(cross(t_in, t_out), dot(t_in, t_out));
  Feature f;
  f.kind = FeatureKind::vertex;
  f.loop = li;
  f.index = ei;
  f.point = out.from;
  f.normal_in = perp_right(t_in);
  f.normal_out = perp_right(t_out);
  f.turn = turn;  // the normals turn as the tangents do
  if (std::fabs(turn) <= angular)
    f.convexity = Convexity::smooth;
  else
    f.convexity = turn > 0.0 ? Convexity::convex : Convexity::concave;
  return f;
}

// Per loop, in boundary order: vertex i (the start of edge i), then edge i.
void build_features(Part& part, double angular) {
  part.features.clear();
  for (int li = 0; li < static_cast<int>(part.loops.size()); ++li) {
    const Loop& loop = part.loops[li];
    for (int ei = 0; ei < static_cast<int>(loop.edges.size()); ++ei) {
      if (!loop.is_circle()) part.features.push_back(vertex_feature(loop, li, ei, angular));
      part.features.push_back(edge_feature(loop, li, ei));
    }
  }
  for (Feature& f : part.features) set_normal_angle(part, f);
}

}  // namespace

void set_normal_angle(const Part& part, Feature& f) {
  f.normal_angle = 0.0;
  if (f.kind == FeatureKind::vertex) {
    f.normal_angle = std::atan2(f.normal_in.y, f.normal_in.x);
  } else if (f.kind == FeatureKind::segment) {
    const Curve& c = edge_of(part, f);
    const Vec2 normal = perp_right(c.to - c.from);  // unnormalised, as the contacts took it
    f.normal_angle = std::atan2(normal.y, normal.x);
  }
}

int Part::segment_count() const {
  int count = 0;
  for (const Loop& loop : loops)
    count += static_cast<int>(std::count_if(loop.edges.begin(), loop.edges.end(),
                                            [](const Curve& c) { return c.is_segment(); }));
  return count;
}

int Part::arc_count() const {
  int count = 0;
  for (const Loop& loop : loops)
    count += static_cast<int>(std::count_if(loop.edges.begin(), loop.edges.end(),
                                            [](const Curve& c) { return c.is_arc(); }));
  return count;
}

int Part::vertex_count() const {
  int count = 0;
  for (const Loop& loop : loops) count += loop.vertex_count();
  return count;
}

void finish_part(Part& part) {
  part.box = Box{};
  for (const Loop& loop : part.loops)
    for (const Curve& c : loop.edges) part.box.add(bounding_box(c));
  const std::vector<int> depth = loop_depths(part);
  double signed_area = 0.0;
  for (size_t i = 0; i < part.loops.size(); ++i) {
    Loop& loop = part.loops[i];
    loop.depth = depth[i];
    orient_loop(loop, part.enclosure);
    signed_area += loop_signed_area(loop.edges);
  }
  // Material on the left makes the sum the material area; for an enclosure (material
  // unbounded) it is minus the area of the openings, reported as a positive number.
  part.area = part.enclosure ? -signed_area : signed_area;
  // Angles only: the angular tolerance does not depend on the size.
  const double size = part.box.diagonal();
  build_features(part, make_tolerances(size > 0.0 ? size : 1.0).angular);
}

double moving_reach(const Part& moving) {
  double r = 0.0;
  for (const Loop& loop : moving.loops)
    for (const Curve& c : loop.edges) r = std::max(r, farthest_distance(c, {0.0, 0.0}));
  return r;
}

}  // namespace cslice
