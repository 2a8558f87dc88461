// Distances between points, segments and circular arcs.
//
// Between two curves that do not meet, the smallest distance is attained either at an
// endpoint of one of them or at a pair of interior points joined by a common normal. Each
// routine evaluates exactly those candidates, so it is exact up to round-off; curves that
// meet (found by the intersection routine with no tolerance) are at distance 0.
#include <algorithm>
#include <limits>

#include "cslice/geometry.hpp"
#include "geometry/near_curve.hpp"

namespace cslice {
namespace {

bool on_arc(const Curve& arc, Vec2 p) {
  const double t = arc_parameter_of_angle(arc, std::atan2(p.y - arc.center.y, p.x - arc.center.x));
  return t >= 0.0 && t <= 1.0;
}

double endpoint_candidates(const Curve& a, const Curve& b) {
  return std::min({distance_to_curve(b, a.from), distance_to_curve(b, a.to),
                   distance_to_curve(a, b.from), distance_to_curve(a, b.to)});
}

}  // namespace

double distance_to_curve(const Curve& c, Vec2 p) {
  if (c.is_segment()) return distance(p, point_at(c, closest_parameter(c, p)));
  const Vec2 r = p - c.center;
  const double rho = length(r);
  if (rho == 0.0) return c.radius;
  if (on_arc(c, p)) return std::fabs(rho - c.radius);
  return std::min(distance(p, c.from), distance(p, c.to));
}

namespace {

// The margin of the segment tests below over eps, per unit of eps plus the coordinates'
// size: 16u (u = DBL_EPSILON / 2), and the least eps they take (no underflow in squares).
constexpr double kRoundingMargin = 8.0 * std::numeric_limits<double>::epsilon();
constexpr double kSmallestEps = 0x1p-500;

// On an arc, the values distance_to_curve chooses from, by its very expressions: p's
// distance from the centre, from the circle, and from the nearer end. When both of the last
// two exceed eps (and rho is not 0), so does the one it returns.
struct ArcReach {
  double rho, radial, ends;
  bool beyond(double eps) const { return rho != 0.0 && radial > eps && ends > eps; }
};
ArcReach arc_reach(const Curve& c, Vec2 p) {
  const double rho = length(p - c.center);
  return {rho, std::fabs(rho - c.radius), std::min(distance(p, c.from), distance(p, c.to))};
}

}  // namespace

// A segment's computed distance is |p - q| for q = lerp(from, to, t) (or an end), and q lies
// outside the ends' box by at most 4u(|a| + |b|) per axis (u = DBL_EPSILON / 2; a, b the
// ends' coordinates on that axis): two roundings in t (b - a), one in the sum. The computed
// |p - q| is at least (1 - u)^3 times the exact difference along one axis (one rounding in
// that difference, one in its square, one in the square root, squares and sums rounded
// monotonically). So a gap g to the box, itself computed with one rounding, proves a
// computed distance above eps when g > eps + 16u (eps + S), S the sum of the ends' absolute
// coordinates: the 16u covers the 4u of q, the (1 - u)^-3 and (1 + u) factors on eps, and
// the three roundings of the threshold itself, with room to spare. This needs squares of
// differences above eps not to underflow, and the rounding of t (b - a) in the subnormal
// range (below 2^-1074) to stay under u eps: true for eps >= 2^-500 (the pair's geometric
// epsilon is 1e-9 of its size); a smaller eps takes the exact path.
bool segment_box_rejects(const Curve& c, Vec2 p, double eps) {
  if (!(eps >= kSmallestEps)) return false;
  const Vec2 a = c.from, b = c.to;
  const double scale = std::fabs(a.x) + std::fabs(b.x) + std::fabs(a.y) + std::fabs(b.y);
  const double limit = eps + kRoundingMargin * (eps + scale);
  // NaN anywhere fails every comparison: not rejected, the exact path decides.
  return std::min(a.x, b.x) - p.x > limit || p.x - std::max(a.x, b.x) > limit ||
         std::min(a.y, b.y) - p.y > limit || p.y - std::max(a.y, b.y) > limit;
}

// A segment's line distance as computed here, |cross(d, r)| / |d|, is off the exact one by
// a few u times the coordinates' size S (u = DBL_EPSILON / 2: the differences d and r are
// rounded on the coordinates' scale, the products relatively), and distance_to_curve's by as
// little: a margin of 16u (eps + S) over eps covers both, as in segment_box_rejects, whose
// bound on eps holds here too. An arc needs no margin: its test is within_distance's, on the
// very values distance_to_curve chooses from (arc_reach).
bool carrier_rejects(const Curve& c, Vec2 p, double eps) {
  if (!(eps >= kSmallestEps)) return false;
  if (c.is_segment()) {
    const Vec2 d = c.to - c.from, r = p - c.from;
    const double scale = std::fabs(p.x) + std::fabs(p.y) + std::fabs(c.from.x) +
                         std::fabs(c.from.y) + std::fabs(c.to.x) + std::fabs(c.to.y);
    const double limit = eps + kRoundingMargin * (eps + scale);
    const double across = cross(d, r);  // |d| times the distance from the line
    return across * across > limit * limit * length_squared(d);  // NaN: not rejected
  }
  // An arc's ends may lie off its circle (snapped to vertices), and near them the nearest
  // end decides.
  return arc_reach(c, p).beyond(eps);
}

// distance_to_curve returns one of the values computed here (on an arc: |rho - r| when p's
// angle is on the arc, else the nearer end's distance, or r when rho is 0, which is |rho - r|
// too), by the same expressions: when all of them exceed eps, so does the one it returns,
// and its angle (atan2, most of its cost) is not needed. A segment is first tried against
// its box (segment_box_rejects), then measured.
bool within_distance(const Curve& c, Vec2 p, double eps) {
  if (c.is_segment()) return !segment_box_rejects(c, p, eps) && distance_to_curve(c, p) <= eps;
  const ArcReach a = arc_reach(c, p);
  if (a.rho == 0.0) return c.radius <= eps;
  if (a.beyond(eps)) return false;
  return (on_arc(c, p) ? a.radial : a.ends) <= eps;
}

// The same steps as closest_parameter and distance_to_curve, sharing the arc's angle.
NearestPoint nearest_point(const Curve& c, Vec2 p) {
  if (c.is_segment()) {
    const double t = closest_parameter(c, p);
    return {t, distance(p, point_at(c, t))};
  }
  const Vec2 r = p - c.center;
  const double rho = length(r);
  if (r.x == 0.0 && r.y == 0.0) return {0.0, c.radius};  // every point of the arc is nearest
  const double t = arc_parameter_of_angle(c, std::atan2(r.y, r.x));
  if (t >= 0.0 && t <= 1.0) return {t, rho == 0.0 ? c.radius : std::fabs(rho - c.radius)};
  const double to_from = distance(p, c.from), to_to = distance(p, c.to);
  return {to_from <= to_to ? 0.0 : 1.0, rho == 0.0 ? c.radius : std::min(to_from, to_to)};
}

// Segments meet when each one's endpoints are not strictly on one side of the other.
double distance_segment_segment(const Curve& a, const Curve& b) {
  const Vec2 da = a.to - a.from, db = b.to - b.from;
  const double s1 = cross(da, b.from - a.from), s2 = cross(da, b.to - a.from);
  const double s3 = cross(db, a.from - b.from), s4 = cross(db, a.to - b.from);
  const bool straddle_a = (s1 <= 0.0 && s2 >= 0.0) || (s1 >= 0.0 && s2 <= 0.0);
  const bool straddle_b = (s3 <= 0.0 && s4 >= 0.0) || (s3 >= 0.0 && s4 <= 0.0);
  const bool collinear = s1 == 0.0 && s2 == 0.0;
  if (straddle_a && straddle_b && !collinear) return 0.0;
  return endpoint_candidates(a, b);
}

// Common normals of a segment and a circle pass through the centre perpendicular to the
// segment, meeting the circle at c +- r n.
double distance_segment_arc(const Curve& segment, const Curve& arc) {
  if (intersect_segment_arc(segment, arc, 0.0).count > 0) return 0.0;
  double best = endpoint_candidates(segment, arc);
  const Vec2 n = perp_left(normalized(segment.to - segment.from));
  for (double sign : {-1.0, 1.0}) {
    const Vec2 p = arc.center + (sign * arc.radius) * n;
    if (on_arc(arc, p)) best = std::min(best, distance_to_curve(segment, p));
  }
  return best;
}

// Common normals of two circles lie on the line of centres. Concentric arcs have common
// normals everywhere; their nearest points then include an endpoint of one of them.
double distance_arc_arc(const Curve& a, const Curve& b) {
  if (intersect_arc_arc(a, b, 0.0).count > 0) return 0.0;
  double best = endpoint_candidates(a, b);
  const Vec2 cc = b.center - a.center;
  if (cc.x == 0.0 && cc.y == 0.0) return best;
  const Vec2 u = normalized(cc);
  for (double sa : {-1.0, 1.0}) {
    const Vec2 pa = a.center + (sa * a.radius) * u;
    if (!on_arc(a, pa)) continue;
    for (double sb : {-1.0, 1.0}) {
      const Vec2 pb = b.center + (sb * b.radius) * u;
      if (on_arc(b, pb)) best = std::min(best, distance(pa, pb));
    }
  }
  return best;
}

double distance_between(const Curve& a, const Curve& b) {
  if (a.is_segment() && b.is_segment()) return distance_segment_segment(a, b);
  if (a.is_arc() && b.is_arc()) return distance_arc_arc(a, b);
  return a.is_segment() ? distance_segment_arc(a, b) : distance_segment_arc(b, a);
}

namespace {
// |bulge| = tan(sweep / 4) and sagitta = |bulge| chord / 2; -1 past a half turn (|bulge| > 1).
double sagitta(const Curve& c) {
  if (c.is_segment()) return 0.0;
  const double b = std::fabs(c.bulge);
  return b <= 1.0 ? 0.5 * b * distance(c.from, c.to) : -1.0;
}
}  // namespace

DistanceBounds chord_distance_bounds(const Curve& a, const Curve& b) {
  const double sa = sagitta(a), sb = sagitta(b);
  if (sa < 0.0 || sb < 0.0) return {};
  const double chords =
      distance_segment_segment(make_segment(a.from, a.to), make_segment(b.from, b.to));
  return {std::max(0.0, chords - sa - sb), chords + sa + sb};
}

// The distance from p to a point of the circle is largest at the point opposite p (through
// the centre); elsewhere on an arc it grows towards that point, so it is largest at an end.
double farthest_distance(const Curve& c, Vec2 p) {
  const double ends = std::max(distance(p, c.from), distance(p, c.to));
  if (!c.is_arc()) return ends;
  const Vec2 away = c.center - p;
  const double d = length(away);
  if (d == 0.0) return c.radius;
  const Vec2 far = c.center + (c.radius / d) * away;
  if (c.is_full_circle() || on_arc(c, far)) return std::max(ends, d + c.radius);
  return ends;
}

}  // namespace cslice
