// Construction and evaluation of segments and circular arcs.
#include <algorithm>

#include "cslice/geometry.hpp"

namespace cslice {

double wrap_angle(double a) {
  constexpr double kFarAngle = 1000.0 * kTwoPi;
  if (std::fabs(a) > kFarAngle) {
    const double r = std::atan2(std::sin(a), std::cos(a));  // in [-pi, pi]
    return r >= kPi ? -kPi : r;
  }
  a = fmod_two_pi(a + kPi);
  if (a < 0.0) a += kTwoPi;
  return a - kPi;
}

// The bulge gives the centre without trigonometry: with b = tan(sweep/4), the centre lies
// at distance d(1 - b^2)/(4b) to the left of the chord's midpoint (negative: to the right)
// and the radius is d(1 + b^2)/(4|b|), d the chord length.
double bulge_radius(double chord, double bulge) {
  return chord * (1.0 + bulge * bulge) / (4.0 * std::fabs(bulge));
}

Curve make_bulge_arc(Vec2 from, Vec2 to, double bulge) {
  if (bulge == 0.0) return make_segment(from, to);
  Curve c;
  c.from = from;
  c.to = to;
  c.bulge = bulge;
  const Vec2 chord = to - from;
  const double d = length(chord);
  const double b2 = bulge * bulge;
  const double offset = d * (1.0 - b2) / (4.0 * bulge);
  c.center = lerp(from, to, 0.5) + offset * perp_left(normalized(chord));
  c.radius = bulge_radius(d, bulge);
  c.sweep = 4.0 * std::atan(bulge);
  c.start_angle = std::atan2(from.y - c.center.y, from.x - c.center.x);
  return c;
}

Curve make_arc(Vec2 center, double radius, double start_angle, double sweep) {
  PlainTrig trig;
  return make_arc_using(trig, center, radius, start_angle, sweep);
}

Curve make_circle(Vec2 center, double radius, bool counterclockwise) {
  return make_arc(center, radius, 0.0, counterclockwise ? kTwoPi : -kTwoPi);
}

Curve reversed(const Curve& c) {
  if (c.is_segment()) return make_segment(c.to, c.from);
  Curve r = c;
  std::swap(r.from, r.to);
  r.start_angle = c.start_angle + c.sweep;
  r.sweep = -c.sweep;
  r.bulge = -c.bulge;
  return r;
}

Curve transformed(const Curve& c, const Transform& t) {
  Curve r = c;
  r.from = t.apply(c.from);
  r.to = t.apply(c.to);
  if (c.is_arc()) {
    r.center = t.apply(c.center);
    r.start_angle = c.start_angle + t.angle;
  }
  return r;
}

Vec2 tangent_at(const Curve& c, double t) {
  if (c.is_segment()) return normalized(c.to - c.from);
  const Vec2 radial = unit_vector(c.start_angle + t * c.sweep);
  return c.sweep > 0.0 ? perp_left(radial) : perp_right(radial);
}

double curve_length(const Curve& c) {
  return c.is_segment() ? distance(c.from, c.to) : c.radius * std::fabs(c.sweep);
}

namespace {

// The angles of the four axis directions and their unit vectors, computed once.
struct AxisDirection {
  double angle;
  Vec2 unit;
};
const std::array<AxisDirection, 4>& axis_directions() {
  static const std::array<AxisDirection, 4> axes = [] {
    std::array<AxisDirection, 4> a;
    for (int k = 0; k < 4; ++k) a[k] = {k * (kPi / 2.0), unit_vector(k * (kPi / 2.0))};
    return a;
  }();
  return axes;
}

}  // namespace

// Whether an arc passes an axis is whether arc_parameter_of_angle(c, a) lies in [0, 1],
// decided from its angle delta before the division: delta / span is in [0, 1] exactly when
// delta <= span (a quotient of positive doubles rounds above 1 whenever the numerator is the
// larger), and delta = 2pi becomes 0 / span when moved back a turn. Any other delta beyond
// span ends outside [0, 1].
Box arc_bounding_box(const Curve& c) {
  Box b;
  b.add(c.from);
  b.add(c.to);
  const double span = std::fabs(c.sweep);
  const std::array<AxisDirection, 4>& axes = axis_directions();
  if (!(span > 0.0 && span <= kTwoPi)) {  // the division's own rules decide
    for (const AxisDirection& axis : axes) {
      const double t = arc_parameter_of_angle(c, axis.angle);
      if (t >= 0.0 && t <= 1.0) b.add(c.center + c.radius * axis.unit);
    }
    return b;
  }
  for (const AxisDirection& axis : axes) {
    const double delta = arc_turn(c, axis.angle);
    if (delta <= span || delta == kTwoPi) b.add(c.center + c.radius * axis.unit);
  }
  return b;
}

// Chord term plus the circular segment between chord and arc: r^2 (sweep - sin sweep) / 2,
// signed by the sweep, so a loop's sum is its enclosed area without polygonising arcs.
double signed_area_contribution(const Curve& c) {
  PlainTrig trig;
  return signed_area_contribution_using(trig, c);
}

double closest_parameter(const Curve& c, Vec2 p) {
  if (c.is_segment()) {
    const Vec2 d = c.to - c.from;
    const double len2 = length_squared(d);
    if (len2 == 0.0) return 0.0;
    return std::clamp(dot(p - c.from, d) / len2, 0.0, 1.0);
  }
  const Vec2 r = p - c.center;
  if (r.x == 0.0 && r.y == 0.0) return 0.0;  // every point of the arc is nearest
  const double t = arc_parameter_of_angle(c, std::atan2(r.y, r.x));
  if (t >= 0.0 && t <= 1.0) return t;
  return distance(p, c.from) <= distance(p, c.to) ? 0.0 : 1.0;
}

}  // namespace cslice
