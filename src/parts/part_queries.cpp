// Point queries on loops and parts, and placing a part at a pose.
#include <algorithm>
#include <cmath>

#include "cslice/part.hpp"
#include "parts/loop_queries.hpp"

namespace cslice {
namespace {

// Which side of the line through a and b the point p lies on: +1 left, -1 right, never 0.
// Computed on the endpoints in a canonical order, so reversing a chord negates the answer
// exactly, and an exact zero is resolved as if p were moved by (d, d^2) for an infinitesimal
// d. Both containment tests below use this one sign, so they can never disagree about a
// point on a chord: moving it across flips both, leaving the parity unchanged.
int side_of_chord(Vec2 a, Vec2 b, Vec2 p) {
  const bool swap = b.x < a.x || (b.x == a.x && b.y < a.y);
  if (swap) std::swap(a, b);
  int sign;
  const double s = cross(b - a, p - a);
  if (s != 0.0)
    sign = s > 0.0 ? 1 : -1;
  else if (b.y != a.y)
    sign = b.y > a.y ? -1 : 1;
  else
    sign = b.x > a.x ? 1 : -1;
  return swap ? -sign : sign;
}

// Even-odd crossing of a rightward ray from p with the chord from a to b. Half-open in y (as
// if p were raised by d^2), so a ray through a vertex counts it once.
bool ray_crosses_chord(Vec2 a, Vec2 b, Vec2 p, int side) {
  if ((a.y > p.y) == (b.y > p.y)) return false;
  return b.y > a.y ? side > 0 : side < 0;
}

// The region between an arc and its chord: the arc's disc cut by the chord's line, on the
// side where the arc runs (right of the chord for counterclockwise arcs). A minor arc's
// segment also lies within the arc's sector, which is checked too: an arrangement snaps a
// piece's ends to vertices up to eps away, so the chord of a piece not much longer than eps
// can point anywhere, and its half-plane would then cut the disc far from the arc (a 1e-8
// piece of a contact arc of radius 17 toggled points 0.8 away). The sector, bounded by the
// rays through the ends, stays a sliver along such an arc. For an arc whose ends lie on its
// circle the segment is inside the sector, so the test changes nothing there.
// Only arcs of at most a quarter turn are checked. The sector's rays leave the chord at its
// ends at an angle of (pi - sweep) / 2, and computed by other operations than the chord's
// side they may disagree with it near them: for a half circle both rays lie along the chord,
// and a point on the chord (the centre of a slot's rounded end, where a pin of the slot's
// width reaches) came out on the arc's side but outside the sector, outside the part. Past a
// quarter turn the piece is long beside its snapping (or its circle within eps of it), so its
// chord cannot point away from the arc.
constexpr double kSectorCheckedSweep = 0.5 * kPi;
bool in_circular_segment(const Curve& arc, Vec2 p, int side) {
  const Vec2 q = p - arc.center;
  if (length_squared(q) >= arc.radius * arc.radius) return false;
  if (!(arc.sweep > 0.0 ? side < 0 : side > 0)) return false;
  if (std::fabs(arc.sweep) > kSectorCheckedSweep) return true;
  const Vec2 a = arc.from - arc.center, b = arc.to - arc.center;
  return arc.sweep > 0.0 ? cross(a, q) >= 0.0 && cross(q, b) >= 0.0
                         : cross(a, q) <= 0.0 && cross(q, b) <= 0.0;
}

}  // namespace

double loop_signed_area(std::span<const Curve> edges) {
  double area = 0.0;
  for (const Curve& c : edges) area += signed_area_contribution(c);
  return area;
}

// The region bounded by chords and arcs is the chord polygon with every arc's circular
// segment toggled in or out, so parity of (chord crossings + segments containing p) decides.
bool toggles_parity(const Curve& c, Vec2 p) {
  if (c.from == c.to) {
    // A full circle: its chord is a point and its segment the whole disc.
    return c.is_full_circle() && length_squared(p - c.center) < c.radius * c.radius;
  }
  const int side = side_of_chord(c.from, c.to, p);
  return ray_crosses_chord(c.from, c.to, p, side) !=
         (c.is_arc() && in_circular_segment(c, p, side));
}

bool loop_encloses(std::span<const Curve> edges, Vec2 p) {
  bool inside = false;
  for (const Curve& c : edges)
    if (toggles_parity(c, p)) inside = !inside;
  return inside;
}

double distance_to_curves(std::span<const Curve> edges, Vec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Curve& c : edges) best = std::min(best, distance_to_curve(c, p));
  return best;
}

Part placed(const Part& part, const Pose& pose) {
  const Transform t(pose);
  Part out = part;
  out.box = Box{};
  for (Loop& loop : out.loops) {
    for (Curve& c : loop.edges) {
      c = transformed(c, t);
      out.box.add(bounding_box(c));
    }
  }
  for (Feature& f : out.features) {
    f.normal_in = t.rotate(f.normal_in);
    f.normal_out = t.rotate(f.normal_out);
    f.point = t.apply(f.point);
    set_normal_angle(out, f);  // (turn does not change with the pose)
  }
  return out;
}

const Curve& edge_of(const Part& part, const Feature& f) {
  // A feature's index is an edge's (a vertex's: the edge it starts), below the loop's count.
  return part.loops[f.loop].edges[size_t(f.index)];
}

}  // namespace cslice
