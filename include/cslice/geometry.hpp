// Plane geometry of cslice: points, boxes and curves (line segments and circular arcs), with
// one intersection and one distance routine per pair of curve kinds. Plain double
// arithmetic; every comparison against zero goes through an epsilon the caller passes in
// (from Tolerances), never a literal.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace cslice {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

inline Vec2 operator+(Vec2 a, Vec2 b) {
  return {a.x + b.x, a.y + b.y};
}
inline Vec2 operator-(Vec2 a, Vec2 b) {
  return {a.x - b.x, a.y - b.y};
}
inline Vec2 operator-(Vec2 a) {
  return {-a.x, -a.y};
}
inline Vec2 operator*(double s, Vec2 a) {
  return {s * a.x, s * a.y};
}
inline Vec2 operator*(Vec2 a, double s) {
  return {s * a.x, s * a.y};
}
inline bool operator==(Vec2 a, Vec2 b) {
  return a.x == b.x && a.y == b.y;
}
inline double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
inline double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
inline double length_squared(Vec2 a) {
  return dot(a, a);
}
inline double length(Vec2 a) {
  // Not hypot: the reader caps coordinates at 1e9, so the squares cannot overflow, and
  // sqrt is several times faster on this hot path.
  return std::sqrt(a.x * a.x + a.y * a.y);
}
inline double distance(Vec2 a, Vec2 b) {
  return length(a - b);
}
inline Vec2 perp_left(Vec2 a) {
  return {-a.y, a.x};
}
inline Vec2 perp_right(Vec2 a) {
  return {a.y, -a.x};
}
inline Vec2 unit_vector(double angle) {
  return {std::cos(angle), std::sin(angle)};
}
inline Vec2 normalized(Vec2 a) {
  const double n = length(a);
  return n > 0.0 ? Vec2{a.x / n, a.y / n} : Vec2{0.0, 0.0};
}
inline Vec2 lerp(Vec2 a, Vec2 b, double t) {
  return a + t * (b - a);
}
inline bool is_finite(Vec2 a) {
  return std::isfinite(a.x) && std::isfinite(a.y);
}

// A rotation by `angle` (radians, counterclockwise) followed by a translation: the placement
// of a moving part at configuration (x, y, theta).
struct Pose {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
};

// Wraps an angle into [-pi, pi). Up to a thousand turns by the double nearest 2pi (exactly, as
// fmod does: off the true turn by at most 3e-13 rad there); beyond, by the true turn, as
// std::sin and std::cos reduce their argument, so that a far orientation (1e9 rad) wraps to
// the one Transform turns by: the double nearest 2pi is 2.4e-16 short of it, which 1e9 rad,
// 160 million turns, multiply to 4e-8 rad, and 1e15 rad to 0.04.
double wrap_angle(double a);

// theta itself when already in [-pi, pi), else wrap_angle(theta): the same orientation, small
// enough to add to other angles without losing their digits. Contact segments add theta to
// the features' normal angles, and at theta = 1e9 rad the sums were rounded to 1.2e-7 rad,
// a hundred times the angular tolerance: the slice lost its free space.
inline double principal_angle(double theta) {
  return theta >= -kPi && theta < kPi ? theta : wrap_angle(theta);
}

// Precomputed rotation, so a placed part costs one sin/cos pair, not one per point. `angle`
// is the turn's principal angle: the one arcs add to their start angles and contact segments
// to normal angles, consistent with c and s (taken from p.theta itself, exactly) however far
// p.theta is. At 1e15 rad a placed arc's start angle was rounded to an eighth of a radian.
struct Transform {
  double c = 1.0, s = 0.0;
  Vec2 offset;
  double angle = 0.0;
  explicit Transform(Pose p)
      : c(std::cos(p.theta)),
        s(std::sin(p.theta)),
        offset{p.x, p.y},
        angle(principal_angle(p.theta)) {}
  Transform() = default;
  Vec2 rotate(Vec2 v) const { return {c * v.x - s * v.y, s * v.x + c * v.y}; }
  Vec2 apply(Vec2 p) const { return rotate(p) + offset; }
};

// Axis-aligned box; empty when lo > hi.
struct Box {
  Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  bool empty() const { return lo.x > hi.x || lo.y > hi.y; }
  void add(Vec2 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  // Adding b.lo and then b.hi, with half the comparisons: in a box that is not empty (and
  // has no NaN corner) lo <= hi, so b.hi never lowers the lo that b.lo left, nor b.lo raises
  // the hi.
  void add(const Box& b) {
    if (b.empty()) return;
    lo = {std::min(lo.x, b.lo.x), std::min(lo.y, b.lo.y)};
    hi = {std::max(hi.x, b.hi.x), std::max(hi.y, b.hi.y)};
  }
  // Inline: both run in the innermost loops of the sweeps and the placement test.
  Box inflated(double margin) const {
    if (empty()) return *this;
    Box b;
    b.lo = {lo.x - margin, lo.y - margin};
    b.hi = {hi.x + margin, hi.y + margin};
    return b;
  }
  // All four sides compared, with no branch between them: callers filter many boxes, and
  // which of them overlap follows no pattern a branch predictor finds.
  bool overlaps(const Box& b) const {
    return !((b.lo.x > hi.x) | (b.hi.x < lo.x) | (b.lo.y > hi.y) | (b.hi.y < lo.y));
  }
  double diagonal() const { return empty() ? 0.0 : distance(lo, hi); }
};

// std::fmod(a, kTwoPi), bit for bit, without the library call for the angles met in
// practice: below one turn in magnitude it is a itself, and between one and two turns
// a -+ kTwoPi is exact (Sterbenz), which is the remainder fmod computes exactly.
inline double fmod_two_pi(double a) {
  const double m = std::fabs(a);
  if (m < kTwoPi) return a;
  if (m > kTwoPi && m < 2.0 * kTwoPi) return a > 0.0 ? a - kTwoPi : a + kTwoPi;
  return std::fmod(a, kTwoPi);  // exactly one or two turns (a signed zero), more, or NaN
}

// How far angle `to` lies counterclockwise from angle `from`, in [0, 2pi] (a remainder just
// below zero rounds up to 2pi itself): where angle intervals and arcs place an angle.
inline double ccw_turn(double from, double to) {
  double d = fmod_two_pi(to - from);
  if (d < 0.0) d += kTwoPi;
  return d;
}

// A boundary edge, directed from `from` to `to`: a line segment (bulge 0) or a circular arc
// (bulge = tan(sweep / 4), positive counterclockwise). A full circle has from == to and
// sweep = +-2pi. Parameter t in [0, 1] runs uniformly in arc length from `from` to `to`.
struct Curve {
  Vec2 from, to;
  double bulge = 0.0;
  // Arc data, meaningful only when is_arc().
  Vec2 center;
  double radius = 0.0;
  double start_angle = 0.0;  // angle of `from` seen from the center
  double sweep = 0.0;        // signed, in (-2pi, 2pi] (0 for segments)

  bool is_arc() const { return sweep != 0.0; }
  bool is_segment() const { return sweep == 0.0; }
  bool is_full_circle() const { return std::fabs(sweep) >= kTwoPi; }
  bool is_counterclockwise() const { return sweep > 0.0; }
};

// Inline: every segment piece of an arrangement and many contact segments are made here.
inline Curve make_segment(Vec2 from, Vec2 to) {
  Curve c;
  c.from = from;
  c.to = to;
  return c;
}
// Arc from `from` to `to` with the given bulge; a zero bulge gives a segment.
Curve make_bulge_arc(Vec2 from, Vec2 to, double bulge);
// The radius of the arc of that bulge (nonzero) over a chord of length `chord`.
double bulge_radius(double chord, double bulge);
// Arc of the circle (center, radius) from start_angle, turning by sweep (signed, |sweep| <= 2pi).
Curve make_arc(Vec2 center, double radius, double start_angle, double sweep);
// The sines, cosines and tangents the curve functions take, as the standard functions give
// them. A cache returning the very same values (the slice's TrigMemo) can stand in for it in
// make_arc_using and signed_area_contribution_using.
struct PlainTrig {
  Vec2 unit_vector(double angle) const { return cslice::unit_vector(angle); }
  double tan(double x) const { return std::tan(x); }
  double sin(double x) const { return std::sin(x); }
};
// make_arc with its trigonometry from `trig` (make_arc is make_arc_using(PlainTrig{}, ...)).
template <class TrigSource>
Curve make_arc_using(TrigSource& trig, Vec2 center, double radius, double start_angle,
                     double sweep) {
  Curve c;
  c.center = center;
  c.radius = radius;
  c.start_angle = start_angle;
  c.sweep = std::clamp(sweep, -kTwoPi, kTwoPi);
  c.from = center + radius * trig.unit_vector(start_angle);
  c.to = c.is_full_circle() ? c.from : center + radius * trig.unit_vector(start_angle + c.sweep);
  c.bulge = c.is_full_circle() ? std::numeric_limits<double>::infinity() : trig.tan(c.sweep / 4.0);
  return c;
}
// make_arc for an arc whose ends are known already (the vertices or corners a piece is snapped
// to): `from` and `to` as given instead of computed from the angles, so no sine or cosine.
template <class TrigSource>
Curve make_arc_between_using(TrigSource& trig, Vec2 center, double radius, double start_angle,
                             double sweep, Vec2 from, Vec2 to) {
  Curve c;
  c.center = center;
  c.radius = radius;
  c.start_angle = start_angle;
  c.sweep = std::clamp(sweep, -kTwoPi, kTwoPi);
  c.from = from;
  c.to = to;
  c.bulge = c.is_full_circle() ? std::numeric_limits<double>::infinity() : trig.tan(c.sweep / 4.0);
  return c;
}
inline Curve make_arc_between(Vec2 center, double radius, double start_angle, double sweep,
                              Vec2 from, Vec2 to) {
  PlainTrig trig;
  return make_arc_between_using(trig, center, radius, start_angle, sweep, from, to);
}
// Full circle traversed counterclockwise (sweep = 2pi) or clockwise, starting at angle 0.
Curve make_circle(Vec2 center, double radius, bool counterclockwise = true);

Curve reversed(const Curve& c);
Curve transformed(const Curve& c, const Transform& t);

// Inline: called for nearly every split point of a slice, most of them a curve's end.
inline Vec2 point_at(const Curve& c, double t) {
  if (t == 0.0) return c.from;
  if (t == 1.0) return c.to;
  if (c.is_segment()) return lerp(c.from, c.to, t);
  return c.center + c.radius * unit_vector(c.start_angle + t * c.sweep);
}
// Unit tangent in the direction of travel at parameter t.
Vec2 tangent_at(const Curve& c, double t);
// Signed curvature: +1/r for counterclockwise arcs, -1/r for clockwise arcs, 0 for segments.
// Inline: read for every half-edge ordered around a vertex.
inline double signed_curvature(const Curve& c) {
  if (c.is_segment()) return 0.0;
  return c.sweep > 0.0 ? 1.0 / c.radius : -1.0 / c.radius;
}
double curve_length(const Curve& c);
// The box of an arc: its ends and the extreme points of its circle that it passes.
Box arc_bounding_box(const Curve& c);
// Inline for segments: a slice takes the box of every contact curve and every edge.
inline Box bounding_box(const Curve& c) {
  if (!c.is_segment()) return arc_bounding_box(c);
  Box b;
  b.add(c.from);
  b.add(c.to);
  return b;
}
// Signed area between the curve and the origin: summing over a closed loop gives the area
// it encloses (positive for counterclockwise loops).
double signed_area_contribution(const Curve& c);
// The same, with the sine of an arc's sweep from `trig` (see PlainTrig).
template <class TrigSource>
double signed_area_contribution_using(TrigSource& trig, const Curve& c) {
  double a = 0.5 * cross(c.from, c.to);
  if (c.is_arc()) a += 0.5 * c.radius * c.radius * (c.sweep - trig.sin(c.sweep));
  return a;
}

// How far angle `a` lies from the arc's start_angle in its sweep direction, in [0, 2pi].
inline double arc_turn(const Curve& arc, double a) {
  return arc.sweep > 0.0 ? ccw_turn(arc.start_angle, a) : ccw_turn(a, arc.start_angle);
}
// Parameter t of angle `a` on an arc, measured from start_angle in the sweep direction and
// divided by |sweep|; values outside [0, 1] mean the angle is off the arc. Inline: every
// meeting point on an arc and every arc box come here.
inline double arc_parameter_of_angle(const Curve& arc, double a) {
  const double span = std::fabs(arc.sweep);
  double delta = arc_turn(arc, a);
  // Off the arc, report the angle beyond whichever end is nearer, so that callers can
  // accept points a tolerance outside either end.
  if (delta > span && delta - span > kTwoPi - delta) delta -= kTwoPi;
  return delta / span;
}
// Parameter of the point of the curve nearest to p (clamped to [0, 1]).
double closest_parameter(const Curve& c, Vec2 p);

// closest_parameter(c, p) and distance_to_curve(c, p) together, the same values, from one
// angle instead of two for an arc.
struct NearestPoint {
  double t = 0.0;
  double distance = 0.0;
};
NearestPoint nearest_point(const Curve& c, Vec2 p);

// ---- Intersections --------------------------------------------------------------------
// One routine per pair of curve kinds; `intersect` picks the right one. All take eps (a
// length): points closer than eps are the same, curves closer than eps touch.

enum class IntersectionKind {
  none,         // no common point
  one,          // a single transversal crossing
  two,          // two transversal crossings
  tangent,      // touching without crossing (at least one hit is a tangency)
  overlapping,  // the curves share a piece of positive length
};

// One common point, or one common piece (when is_piece) from (ta0, tb0) to (ta1, tb1).
struct IntersectionHit {
  Vec2 point;      // the point, or the piece's first end (at ta0)
  Vec2 point_end;  // the piece's other end (at ta1); equals point when !is_piece
  double ta0 = 0.0, ta1 = 0.0;
  double tb0 = 0.0, tb1 = 0.0;
  bool is_piece = false;
  bool is_tangent = false;
};

struct Intersection {
  IntersectionKind kind = IntersectionKind::none;
  int count = 0;  // hits used in `hits`
  std::array<IntersectionHit, 2> hits{};
  // For overlapping curves: whether both travel the shared piece in the same direction.
  bool same_direction = false;
};

Intersection intersect_segment_segment(const Curve& a, const Curve& b, double eps);
// What intersect_segment_segment would find for segments a and b, when the offsets of their
// ends from each other's carriers tell it without building the intersection:
// - end_to_end: they share an end exactly (bit for bit) and are not collinear within eps;
//   that end is their only meeting, intersect's one hit, at parameters 0 or 1;
// - apart: one lies on one side of the other's carrier, more than 2 eps off it all along,
//   and they are not collinear: no hit;
// - needs_intersection: anything else, arcs included.
enum class SegmentPairShortcut { end_to_end, apart, needs_intersection };
SegmentPairShortcut segment_pair_shortcut(const Curve& a, const Curve& b, double eps);
Intersection intersect_segment_arc(const Curve& segment, const Curve& arc, double eps);
Intersection intersect_arc_arc(const Curve& a, const Curve& b, double eps);
// The two crossing points of circles (c1, r1) and (c2, r2) at centre distance d > 0, computed
// from the smaller circle with the differences factored (well conditioned for a far, flat
// circle's centre); circles that miss each other, or nearly, give their nearest point twice.
std::array<Vec2, 2> circle_crossings(Vec2 c1, double r1, Vec2 c2, double r2, double d);
Intersection intersect(const Curve& a, const Curve& b, double eps);

// ---- Distances -------------------------------------------------------------------------
double distance_to_curve(const Curve& c, Vec2 p);
// Smallest distance between two curves (0 when they meet).
double distance_segment_segment(const Curve& a, const Curve& b);
double distance_segment_arc(const Curve& segment, const Curve& arc);
double distance_arc_arc(const Curve& a, const Curve& b);
double distance_between(const Curve& a, const Curve& b);
// Bounds on distance_between(a, b) from the curves' chords alone (no arc parameter, no
// atan2): the chords' distance less and plus the sum of the sagittas. An arc of at most a
// half turn lies over its chord, every point of one within its sagitta of the other's point
// straight across. For an arc of more than a half turn, none: {0, infinity}.
struct DistanceBounds {
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
};
DistanceBounds chord_distance_bounds(const Curve& a, const Curve& b);
// Largest distance from p to a point of the curve: an endpoint, or for an arc the point of
// its circle opposite p, when the arc passes through it.
double farthest_distance(const Curve& c, Vec2 p);

}  // namespace cslice
