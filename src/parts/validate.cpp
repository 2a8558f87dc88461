#include "parts/validate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <tuple>

namespace cslice::detail {

std::string format_number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string format_point(Vec2 p) {
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "(" + std::string.
  std::string s = "(";
  s += format_number(p.x);
  s += ", ";
  s += format_number(p.y);
  s += ")";
  return s;
}

namespace {

InputError error_at(const RawPart& part, int loop, int vertex, std::string reason) {
  return InputError{"", part.name, loop, vertex, std::move(reason)};
}

// ---- Raw stage ------------------------------------------------------------------------

void add_raw_extent(const RawLoop& loop, Box& box, double& reach) {
  if (loop.is_circle) {
    box.add(loop.center - Vec2{loop.radius, loop.radius});
    box.add(loop.center + Vec2{loop.radius, loop.radius});
    reach = std::max(reach, length(loop.center) + loop.radius);
    return;
  }
  for (const RawVertex& v : loop.vertices) {
    box.add(v.p);
    reach = std::max(reach, length(v.p));
  }
}

std::optional<InputError> check_circle(const RawPart& part, int li, const Tolerances& tol) {
  const RawLoop& loop = part.loops[li];
  if (!(loop.radius > 0.0))
    return error_at(part, li, -1,
                    "circle radius must be positive, got " + format_number(loop.radius));
  if (loop.radius <= tol.geometric)
    return error_at(part, li, -1,
                    "circle radius " + format_number(loop.radius) +
                        " is not above the geometric tolerance " + format_number(tol.geometric));
  return std::nullopt;
}

// The edge starting at vertex i: long enough to have a direction, and if it is an arc, bulging
// far enough from its chord to be told apart from a segment (which also keeps its center at a
// sane distance; make_bulge_arc divides by the bulge).
std::optional<InputError> check_raw_edge(const RawPart& part, int li, int i,
                                         const Tolerances& tol) {
  const auto& vs = part.loops[li].vertices;
  const int n = static_cast<int>(vs.size());
  const int next = (i + 1) % n;
  const double chord = distance(vs[i].p, vs[next].p);
  if (chord <= tol.geometric)
    return error_at(part, li, i,
                    "zero-length edge: vertices " + std::to_string(i) + " and " +
                        std::to_string(next) + " are " + format_number(chord) +
                        " apart (geometric tolerance " + format_number(tol.geometric) + ")");
  const double sagitta = 0.5 * chord * std::fabs(vs[i].bulge);
  if (vs[i].bulge != 0.0 && sagitta <= tol.geometric)
    return error_at(part, li, i,
                    "arc with bulge " + format_number(vs[i].bulge) +
                        " lies within the geometric tolerance of its chord; use bulge 0 for a "
                        "straight edge");
  const double radius = vs[i].bulge != 0.0 ? bulge_radius(chord, vs[i].bulge) : 0.0;
  if (radius > kMaxArcRadiusPerSize * tol.size)
    return error_at(part, li, i,
                    "arc with bulge " + format_number(vs[i].bulge) +
                        " is nearly straight: radius " + format_number(radius) + " exceeds " +
                        format_number(kMaxArcRadiusPerSize) + " times the pair's size " +
                        format_number(tol.size) + "; use bulge 0 for a straight edge");
  return std::nullopt;
}

std::optional<InputError> check_raw_loop(const RawPart& part, int li, const Tolerances& tol) {
  const RawLoop& loop = part.loops[li];
  if (loop.is_circle) return check_circle(part, li, tol);
  const int n = static_cast<int>(loop.vertices.size());
  if (n < 2)
    return error_at(part, li, -1,
                    "loop has " + std::to_string(n) +
                        " vertex; a loop needs at least two (write a circle as "
                        "{\"circle\": [cx, cy, r]})");
  for (int i = 0; i < n; ++i)
    if (auto e = check_raw_edge(part, li, i, tol)) return e;
  if (n == 2 && loop.vertices[0].bulge == 0.0 && loop.vertices[1].bulge == 0.0)
    return error_at(part, li, -1,
                    "two-vertex loop with two straight edges encloses no area (give one edge a "
                    "bulge)");
  return std::nullopt;
}

// ---- Curve stage ----------------------------------------------------------------------

struct EdgeRef {
  int loop = 0;
  int edge = 0;
  Box box;
};

// Where two edges of a part meet in a way a valid part forbids. Ordered so that the reported
// problem is the one with the smallest indices, whatever order the sweep finds them in.
struct Conflict {
  int loop_a = 0, edge_a = 0, loop_b = 0, edge_b = 0;
  std::string reason;
  bool operator<(const Conflict& o) const {
    return std::tie(loop_a, edge_a, loop_b, edge_b) <
           std::tie(o.loop_a, o.edge_a, o.loop_b, o.edge_b);
  }
};

std::optional<InputError> check_arc_magnitude(const Part& part, int li, int ei) {
  const Curve& c = part.loops[li].edges[ei];
  const bool finite = is_finite(c.center) && std::isfinite(c.radius) && is_finite(c.from);
  if (!finite || std::fabs(c.center.x) > kMaxMagnitude || std::fabs(c.center.y) > kMaxMagnitude ||
      c.radius > kMaxMagnitude) {
    const int vertex = part.loops[li].is_circle() ? -1 : ei;
    return InputError{"", part.name, li, vertex,
                      "arc too flat: its center " + format_point(c.center) + " or radius " +
                          format_number(c.radius) + " exceeds the magnitude limit " +
                          format_number(kMaxMagnitude)};
  }
  return std::nullopt;
}

// Shared vertices of two edges of one loop of n edges (a < b): the end of a is the start of
// b when they are consecutive, and the end of b is the start of a when b is the last edge and
// a the first. A two-edge loop has both.
int shared_vertices(const Loop& loop, int a, int b, std::array<Vec2, 2>& out) {
  const int n = static_cast<int>(loop.edges.size());
  int count = 0;
  if (b == a + 1) out[count++] = loop.edges[a].to;
  if (a == 0 && b == n - 1) out[count++] = loop.edges[a].from;
  return count;
}

// Whether every point of a hit is one of the shared vertices. A hit of intersect() may sit up
// to eps from each curve, so up to two eps from the vertex itself.
bool hit_at_shared_vertex(const IntersectionHit& hit, const std::array<Vec2, 2>& shared, int count,
                          double eps) {
  for (int k = 0; k < count; ++k) {
    const bool start_near = distance(hit.point, shared[k]) <= 2.0 * eps;
    const bool end_near = distance(hit.point_end, shared[k]) <= 2.0 * eps;
    if (start_near && (!hit.is_piece || end_near)) return true;
  }
  return false;
}

std::string describe_hit(const IntersectionHit& hit) {
  if (hit.is_piece)
    return "overlap from " + format_point(hit.point) + " to " + format_point(hit.point_end);
  return "meet at " + format_point(hit.point);
}

std::optional<Conflict> check_edge_pair(const Part& part, const EdgeRef& a, const EdgeRef& b,
                                        double eps) {
  const Curve& ca = part.loops[a.loop].edges[a.edge];
  const Curve& cb = part.loops[b.loop].edges[b.edge];
  const Intersection x = intersect(ca, cb, eps);
  if (x.kind == IntersectionKind::none || x.count == 0) return std::nullopt;
  const std::string ea = std::to_string(a.edge), eb = std::to_string(b.edge);
  if (a.loop != b.loop) {
    return Conflict{a.loop, a.edge, b.loop, b.edge,
                    "loops " + std::to_string(a.loop) + " and " + std::to_string(b.loop) +
                        " touch or cross: edge " + ea + " of loop " + std::to_string(a.loop) +
                        " and edge " + eb + " of loop " + std::to_string(b.loop) + " " +
                        describe_hit(x.hits[0])};
  }
  std::array<Vec2, 2> shared{};
  const int n_shared = shared_vertices(part.loops[a.loop], a.edge, b.edge, shared);
  for (int k = 0; k < x.count; ++k) {
    if (hit_at_shared_vertex(x.hits[k], shared, n_shared, eps)) continue;
    const std::string what = n_shared > 0 ? "adjacent edges " : "edges ";
    return Conflict{a.loop, a.edge, b.loop, b.edge,
                    "loop crosses or touches itself: " + what + ea + " and " + eb + " " +
                        describe_hit(x.hits[k])};
  }
  return std::nullopt;
}

std::vector<EdgeRef> sorted_edge_boxes(const Part& part, double eps) {
  std::vector<EdgeRef> refs;
  for (int li = 0; li < static_cast<int>(part.loops.size()); ++li)
    for (int ei = 0; ei < static_cast<int>(part.loops[li].edges.size()); ++ei)
      refs.push_back({li, ei, bounding_box(part.loops[li].edges[ei]).inflated(eps)});
  std::sort(refs.begin(), refs.end(), [](const EdgeRef& p, const EdgeRef& q) {
    return std::tie(p.box.lo.x, p.loop, p.edge) < std::tie(q.box.lo.x, q.loop, q.edge);
  });
  return refs;
}

// Sweep over x: only edges whose boxes overlap are intersected. Keeps the smallest conflict,
// looking on after the first only at pairs that could give a smaller one, and for at most a
// budget of box pairs: a part of many coincident copies (a drawing's block arrayed with no
// spacing) has a conflict in nearly every pair, and would otherwise take quadratic time to
// find the smallest. Such a part gets the smallest of those the budget saw.
std::optional<Conflict> find_conflict(const Part& part, double eps) {
  const std::vector<EdgeRef> refs = sorted_edge_boxes(part, eps);
  const size_t budget = 16 * refs.size() + 1000000;  // box pairs looked at after a conflict
  size_t after_conflict = 0;
  std::optional<Conflict> best;
  for (size_t i = 0; i < refs.size(); ++i) {
    for (size_t j = i + 1; j < refs.size() && refs[j].box.lo.x <= refs[i].box.hi.x; ++j) {
      if (best && ++after_conflict > budget) return best;
      if (!refs[i].box.overlaps(refs[j].box)) continue;
      const bool i_first =
          std::tie(refs[i].loop, refs[i].edge) < std::tie(refs[j].loop, refs[j].edge);
      const EdgeRef& a = i_first ? refs[i] : refs[j];
      const EdgeRef& b = i_first ? refs[j] : refs[i];
      if (best && std::tie(a.loop, a.edge, b.loop, b.edge) >=
                      std::tie(best->loop_a, best->edge_a, best->loop_b, best->edge_b))
        continue;  // no smaller conflict here
      auto c = check_edge_pair(part, a, b, eps);
      if (c && (!best || *c < *best)) best = std::move(c);
    }
  }
  return best;
}

}  // namespace

double raw_pair_size(const RawPart& moving, const RawPart& fixed) {
  Box box;
  double reach = 0.0, unused = 0.0;
  for (const RawLoop& loop : fixed.loops) add_raw_extent(loop, box, unused);
  Box moving_box;
  for (const RawLoop& loop : moving.loops) add_raw_extent(loop, moving_box, reach);
  if (!moving.loops.empty()) {
    box.add(Vec2{-reach, -reach});
    box.add(Vec2{reach, reach});
  }
  return box.diagonal();
}

std::optional<InputError> check_raw_part(const RawPart& part, const Tolerances& tol) {
  for (int li = 0; li < static_cast<int>(part.loops.size()); ++li)
    if (auto e = check_raw_loop(part, li, tol)) return e;
  return std::nullopt;
}

Part build_part(const RawPart& raw) {
  Part part;
  part.name = raw.name;
  part.enclosure = raw.enclosure;
  for (int li = 0; li < static_cast<int>(raw.loops.size()); ++li) {
    const RawLoop& rl = raw.loops[li];
    Loop loop;
    loop.source_index = li;
    if (rl.is_circle) {
      loop.edges.push_back(make_circle(rl.center, rl.radius));
    } else {
      const size_t n = rl.vertices.size();
      for (size_t i = 0; i < n; ++i) {
        const RawVertex& v = rl.vertices[i];
        loop.edges.push_back(make_bulge_arc(v.p, rl.vertices[(i + 1) % n].p, v.bulge));
      }
    }
    part.loops.push_back(std::move(loop));
  }
  return part;
}

std::optional<InputError> check_part_curves(const Part& part, const Tolerances& tol) {
  for (int li = 0; li < static_cast<int>(part.loops.size()); ++li)
    for (int ei = 0; ei < static_cast<int>(part.loops[li].edges.size()); ++ei)
      if (part.loops[li].edges[ei].is_arc())
        if (auto e = check_arc_magnitude(part, li, ei)) return e;
  const std::optional<Conflict> c = find_conflict(part, tol.geometric);
  if (!c) return std::nullopt;
  const int vertex = part.loops[c->loop_a].is_circle() ? -1 : c->edge_a;
  return InputError{"", part.name, c->loop_a, vertex, c->reason};
}

}  // namespace cslice::detail
