// Intersections of segments and circular arcs, one routine per pair of curve kinds.
//
// Every routine takes eps, a length: points within eps are one point, a curve within eps of a
// point passes through it. Hits carry parameters on both curves (t in [0, 1] along each) and
// are snapped into [0, 1]. Near-degenerate configurations are decided in a fixed order:
// overlap first (collinear or co-circular within eps), then tangency (distance between the
// carriers within eps of touching), then transversal crossings; finally an endpoint of
// either curve within eps of the other becomes a hit if no hit is already there, so that a
// crossing lost to round-off near an endpoint is never dropped.
#include <algorithm>

#include "cslice/geometry.hpp"

namespace cslice {
namespace {

void add_hit(Intersection& r, const IntersectionHit& h, double eps) {
  for (int i = 0; i < r.count; ++i) {
    const IntersectionHit& o = r.hits[i];
    if (o.is_piece) {
      // A point on a shared piece adds nothing.
      const double ta_lo = std::min(o.ta0, o.ta1), ta_hi = std::max(o.ta0, o.ta1);
      if (h.ta0 >= ta_lo && h.ta0 <= ta_hi) return;
      if (distance(o.point, h.point) <= eps || distance(o.point_end, h.point) <= eps) return;
    } else if (distance(o.point, h.point) <= eps) {
      return;
    }
  }
  if (r.count < 2) r.hits[r.count++] = h;
}

IntersectionHit point_hit(Vec2 p, double ta, double tb, bool tangent) {
  IntersectionHit h;
  h.point = h.point_end = p;
  h.ta0 = h.ta1 = std::clamp(ta, 0.0, 1.0);
  h.tb0 = h.tb1 = std::clamp(tb, 0.0, 1.0);
  h.is_tangent = tangent;
  return h;
}

void finish_kind(Intersection& r) {
  if (r.count == 0) {
    r.kind = IntersectionKind::none;
    return;
  }
  bool piece = false, tangent = false;
  for (int i = 0; i < r.count; ++i) {
    piece = piece || r.hits[i].is_piece;
    tangent = tangent || r.hits[i].is_tangent;
  }
  if (piece)
    r.kind = IntersectionKind::overlapping;
  else if (tangent)
    r.kind = IntersectionKind::tangent;
  else
    r.kind = r.count == 1 ? IntersectionKind::one : IntersectionKind::two;
}

// Whether p is within eps of the curve's carrier (its line or circle): a cheap necessary
// condition for being within eps of the curve itself. `slack` is eps times the length of a
// segment (unused for arcs), computed once per curve.
bool near_carrier(const Curve& c, Vec2 p, double eps, double slack) {
  if (c.is_arc()) return std::fabs(distance(p, c.center) - c.radius) <= eps;
  return std::fabs(cross(c.to - c.from, p - c.from)) <= slack;
}
double carrier_slack(const Curve& c, double eps) {
  return c.is_arc() ? 0.0 : eps * length(c.to - c.from);
}

// Whether add_hit would drop a point hit at p whatever its parameters: both hits are taken,
// or one lies within eps of p. Checked first, as the shared end of two contact segments
// meeting end to end is nearly always found already, and its parameter on the other curve
// costs an angle.
bool drops_hit_at(const Intersection& r, Vec2 p, double eps) {
  if (r.count >= 2) return true;
  for (int i = 0; i < r.count; ++i) {
    const IntersectionHit& o = r.hits[i];
    if (distance(o.point, p) <= eps || (o.is_piece && distance(o.point_end, p) <= eps)) return true;
  }
  return false;
}

// Adds endpoint touches that the closed-form solution may have lost to round-off. When the
// carriers were found tangent (within eps of touching), every common point is a tangency:
// the two curves run within eps of each other there and never cross, even where the exact
// circles do (a lens thinner than eps), so an end within eps of the other curve touches it
// from the side the tangency implies.
// `near` says which ends pass near_carrier: a.from and a.to against b, then b.from and b.to
// against a.
void add_endpoint_touches(Intersection& r, const Curve& a, const Curve& b, bool tangent, double eps,
                          const std::array<bool, 4>& near) {
  for (int k = 0; k < 2; ++k) {
    const double ta = k;
    const Vec2 p = k == 0 ? a.from : a.to;  // point_at(a, ta)
    if (!near[k] || drops_hit_at(r, p, eps)) continue;
    const NearestPoint n = nearest_point(b, p);
    if (n.distance <= eps) add_hit(r, point_hit(p, ta, n.t, tangent), eps);
  }
  for (int k = 0; k < 2; ++k) {
    const double tb = k;
    const Vec2 p = k == 0 ? b.from : b.to;  // point_at(b, tb)
    if (!near[2 + k] || drops_hit_at(r, p, eps)) continue;
    const NearestPoint n = nearest_point(a, p);
    if (n.distance <= eps) add_hit(r, point_hit(p, n.t, tb, tangent), eps);
  }
}
void add_endpoint_touches(Intersection& r, const Curve& a, const Curve& b, bool tangent, double eps,
                          double slack_a, double slack_b) {
  add_endpoint_touches(
      r, a, b, tangent, eps,
      {near_carrier(b, a.from, eps, slack_b), near_carrier(b, a.to, eps, slack_b),
       near_carrier(a, b.from, eps, slack_a), near_carrier(a, b.to, eps, slack_a)});
}

// Parameter on an arc for a point known to lie on its circle, or NaN when it is more than
// eps (in length) beyond either end.
double arc_parameter_within(const Curve& arc, Vec2 p, double eps) {
  const double t = arc_parameter_of_angle(arc, std::atan2(p.y - arc.center.y, p.x - arc.center.x));
  const double length = arc.radius * std::fabs(arc.sweep);  // curve_length(arc)
  const double slack = length > 0.0 ? eps / length : 0.0;
  if (t < -slack || t > 1.0 + slack) return std::numeric_limits<double>::quiet_NaN();
  return std::clamp(t, 0.0, 1.0);
}

double segment_parameter_within(const Curve& s, Vec2 p, double eps) {
  const Vec2 d = s.to - s.from;
  const double len2 = length_squared(d);
  const double t = dot(p - s.from, d) / len2;
  const double slack = eps / std::sqrt(len2);
  if (t < -slack || t > 1.0 + slack) return std::numeric_limits<double>::quiet_NaN();
  return std::clamp(t, 0.0, 1.0);
}

// Adds p, a point on both curves' carriers, as a hit when it lies within eps of both curves'
// extents.
void add_if_on_both(Intersection& r, const Curve& a, const Curve& b, Vec2 p, bool tangent,
                    double eps) {
  auto parameter = [&](const Curve& c) {
    return c.is_arc() ? arc_parameter_within(c, p, eps) : segment_parameter_within(c, p, eps);
  };
  const double ta = parameter(a);
  if (std::isnan(ta)) return;  // off a: b's parameter (an angle on an arc) is not needed
  const double tb = parameter(b);
  if (!std::isnan(tb)) add_hit(r, point_hit(p, ta, tb, tangent), eps);
}

// Collinear segments (both within eps of one carrier line): the shared piece, or a single
// touching point when the shared part is shorter than eps.
void collinear_overlap(Intersection& r, const Curve& a, const Curve& b, double eps) {
  const Vec2 d = a.to - a.from;
  const double len2 = length_squared(d);
  const double s0 = dot(b.from - a.from, d) / len2, s1 = dot(b.to - a.from, d) / len2;
  const double lo = std::max(0.0, std::min(s0, s1)), hi = std::min(1.0, std::max(s0, s1));
  const double len = std::sqrt(len2);
  r.same_direction = s1 > s0;
  if ((hi - lo) * len < -eps) return;
  if ((hi - lo) * len <= eps) {
    const Vec2 p = lerp(a.from, a.to, 0.5 * (lo + hi));
    add_hit(r, point_hit(p, 0.5 * (lo + hi), closest_parameter(b, p), true), eps);
    return;
  }
  IntersectionHit h;
  h.is_piece = true;
  h.ta0 = lo;
  h.ta1 = hi;
  h.point = lerp(a.from, a.to, lo);
  h.point_end = lerp(a.from, a.to, hi);
  h.tb0 = closest_parameter(b, h.point);
  h.tb1 = closest_parameter(b, h.point_end);
  r.hits[r.count++] = h;
}

// Shared pieces of two arcs of one circle, found on the counterclockwise angle axis.
void cocircular_overlap(Intersection& r, const Curve& a, const Curve& b, double eps) {
  r.same_direction = (a.sweep > 0.0) == (b.sweep > 0.0);
  const double ccw_start_a = a.sweep > 0.0 ? a.start_angle : a.start_angle + a.sweep;
  const double ccw_start_b = b.sweep > 0.0 ? b.start_angle : b.start_angle + b.sweep;
  const double span_a = std::fabs(a.sweep), span_b = std::fabs(b.sweep);
  const double angular_eps = eps / a.radius;
  double offset = fmod_two_pi(ccw_start_b - ccw_start_a);
  if (offset < 0.0) offset += kTwoPi;
  // b's interval, relative to a's start, may wrap: consider it and its copy one turn earlier.
  for (double shift : {offset - kTwoPi, offset}) {
    const double lo = std::max(0.0, shift), hi = std::min(span_a, shift + span_b);
    if (hi - lo < -angular_eps) continue;
    const double mid = 0.5 * (lo + hi);
    if (hi - lo <= angular_eps) {
      const Vec2 p = a.center + a.radius * unit_vector(ccw_start_a + mid);
      add_hit(r, point_hit(p, closest_parameter(a, p), closest_parameter(b, p), true), eps);
      continue;
    }
    IntersectionHit h;
    h.is_piece = true;
    const Vec2 p_lo = a.center + a.radius * unit_vector(ccw_start_a + lo);
    const Vec2 p_hi = a.center + a.radius * unit_vector(ccw_start_a + hi);
    const bool a_ccw = a.sweep > 0.0;
    h.point = a_ccw ? p_lo : p_hi;
    h.point_end = a_ccw ? p_hi : p_lo;
    h.ta0 = a_ccw ? lo / span_a : 1.0 - hi / span_a;
    h.ta1 = a_ccw ? hi / span_a : 1.0 - lo / span_a;
    h.tb0 = closest_parameter(b, h.point);
    h.tb1 = closest_parameter(b, h.point_end);
    if (r.count < 2) r.hits[r.count++] = h;
  }
}

// An end of a that is exactly (bit for bit) an end of b, with its parameters on both.
struct SharedEnd {
  bool shared = false;
  Vec2 at;
  double ta = 0.0, tb = 0.0;
};
SharedEnd shared_end(const Curve& a, const Curve& b) {
  if (a.to == b.from) return {true, a.to, 1.0, 0.0};
  if (a.from == b.to) return {true, a.from, 0.0, 1.0};
  if (a.to == b.to) return {true, a.to, 1.0, 1.0};
  if (a.from == b.from) return {true, a.from, 0.0, 0.0};
  return {};
}

// How two segments lie to each other's carriers: their directions and lengths, and how far
// each end is off the other's carrier times the other's length (near_carrier's very
// products). Within eps of one carrier, both are collinear: one rule for
// intersect_segment_segment and segment_pair_shortcut.
struct SegmentOffsets {
  Vec2 da, db;
  double la, lb;
  double a0, a1, b0, b1;        // a.from, a.to off b's carrier; b.from, b.to off a's
  bool a_one_side, b_one_side;  // both ends of a strictly on one side of b's carrier; of b, a's
  bool collinear;
};

// The directions and the ends' offsets, without the lengths and the verdict
// (measure_collinear).
SegmentOffsets end_offsets(const Curve& a, const Curve& b) {
  SegmentOffsets o;
  o.da = a.to - a.from;
  o.db = b.to - b.from;
  const double b0 = cross(o.da, b.from - a.from), b1 = cross(o.da, b.to - a.from);
  const double a0 = cross(o.db, a.from - b.from), a1 = cross(o.db, a.to - b.from);
  o.b0 = std::fabs(b0);
  o.b1 = std::fabs(b1);
  o.a0 = std::fabs(a0);
  o.a1 = std::fabs(a1);
  o.b_one_side = b0 * b1 > 0.0;
  o.a_one_side = a0 * a1 > 0.0;
  return o;
}

// The lengths, and whether the ends lie within eps of the other's carrier.
void measure_collinear(SegmentOffsets& o, double eps) {
  o.la = length(o.da);
  o.lb = length(o.db);
  const double b_off_a = std::max(o.b0, o.b1) / o.la;
  const double a_off_b = std::max(o.a0, o.a1) / o.lb;
  o.collinear = b_off_a <= eps || a_off_b <= eps;
}

SegmentOffsets segment_offsets(const Curve& a, const Curve& b, double eps) {
  SegmentOffsets o = end_offsets(a, b);
  measure_collinear(o, eps);
  return o;
}

// Whether measure_collinear would find them not collinear, decided on squares, without a
// root or a division, when both are clearly so: some end of each lies more than 2 eps off
// the other's carrier. The margin of 2 covers the rounding of either form many times over;
// in between, measure_collinear decides.
bool clearly_not_collinear(const SegmentOffsets& o, double eps) {
  const double margin = 4.0 * eps * eps;
  return std::max(o.b0 * o.b0, o.b1 * o.b1) > margin * dot(o.da, o.da) &&
         std::max(o.a0 * o.a0, o.a1 * o.a1) > margin * dot(o.db, o.db);
}

// Whether both ends of a segment lie on one side of the other's carrier, more than 2 eps off
// it (on squares, as clearly_not_collinear), given their offsets times the carrier's length.
bool clear_of_carrier(bool one_side, double off0, double off1, Vec2 carrier, double eps) {
  return one_side && std::min(off0 * off0, off1 * off1) > 4.0 * eps * eps * dot(carrier, carrier);
}

}  // namespace

// End to end: not collinear, so their carriers meet only at the shared end, and the other
// two ends lie farther than eps from the other's carrier; intersect_segment_segment finds
// that one point. Contact segments meeting end to end at an angle (most candidate pairs of a
// slice) are told on squares (clearly_not_collinear).
// Apart: one lies wholly on one side of the other's carrier, more than 2 eps off it, so no
// point of it (nor the carriers' crossing, beyond its end) is within eps of the other, and
// they are not collinear: intersect_segment_segment finds no point. Most candidate pairs of
// rough contours that do not meet end to end.
SegmentPairShortcut segment_pair_shortcut(const Curve& a, const Curve& b, double eps) {
  if (!a.is_segment() || !b.is_segment()) return SegmentPairShortcut::needs_intersection;
  SegmentOffsets o = end_offsets(a, b);
  const bool not_collinear = clearly_not_collinear(o, eps);
  if (shared_end(a, b).shared) {
    if (not_collinear) return SegmentPairShortcut::end_to_end;
    measure_collinear(o, eps);
    return o.collinear ? SegmentPairShortcut::needs_intersection : SegmentPairShortcut::end_to_end;
  }
  const bool apart = clear_of_carrier(o.b_one_side, o.b0, o.b1, o.da, eps) ||
                     clear_of_carrier(o.a_one_side, o.a0, o.a1, o.db, eps);
  return not_collinear && apart ? SegmentPairShortcut::apart
                                : SegmentPairShortcut::needs_intersection;
}

// Segment a(t) = a.from + t (a.to - a.from) against b(u) likewise. Parallel carriers within
// eps overlap (a piece, or a tangent point when they only touch end to end); otherwise the
// unique crossing of the carriers counts when it lies within eps of both segments.
Intersection intersect_segment_segment(const Curve& a, const Curve& b, double eps) {
  Intersection r;
  const SegmentOffsets o = segment_offsets(a, b, eps);
  if (o.collinear) {
    collinear_overlap(r, a, b, eps);
  } else if (const SharedEnd end = shared_end(a, b); end.shared) {
    // The general steps below would find this one point (up to round-off) and nothing else
    // (segment_pair_shortcut's end_to_end). Contact segments meeting end to end in a chain share
    // their ends bit for bit, and most candidate pairs of a slice are such neighbours.
    r.hits[r.count++] = point_hit(end.at, end.ta, end.tb, false);
  } else {
    const double denom = cross(o.da, o.db);
    if (denom != 0.0) {
      const Vec2 w = b.from - a.from;
      const double t = cross(w, o.db) / denom, u = cross(w, o.da) / denom;
      if (t >= -eps / o.la && t <= 1.0 + eps / o.la && u >= -eps / o.lb && u <= 1.0 + eps / o.lb) {
        const double tc = std::clamp(t, 0.0, 1.0);
        add_hit(r, point_hit(lerp(a.from, a.to, tc), tc, std::clamp(u, 0.0, 1.0), false), eps);
      }
    }
    // near_carrier of each end, with carrier_slack from the lengths already at hand.
    const double slack_a = eps * o.la, slack_b = eps * o.lb;
    add_endpoint_touches(r, a, b, false, eps,
                         {o.a0 <= slack_b, o.a1 <= slack_b, o.b0 <= slack_a, o.b1 <= slack_a});
  }
  finish_kind(r);
  return r;
}

// Segment s(t) against the circle of the arc: the foot q of the centre on the carrier line
// at distance h; |h| within eps of the radius is a tangency at q, |h| < r gives the two
// points q +- sqrt(r^2 - h^2) along the line. Each point counts when within eps of both.
Intersection intersect_segment_arc(const Curve& s, const Curve& arc, double eps) {
  Intersection r;
  const Vec2 d = s.to - s.from;
  const double len = length(d);
  const Vec2 dir = (1.0 / len) * d;
  const double t0 = dot(arc.center - s.from, dir);
  const Vec2 q = s.from + t0 * dir;
  const double h = distance(q, arc.center);
  if (h <= arc.radius + eps) {
    const bool tangent = h >= arc.radius - eps;
    if (tangent) {
      const Vec2 p = h > 0.0 ? arc.center + (arc.radius / h) * (q - arc.center) : q;
      add_if_on_both(r, s, arc, p, true, eps);
    } else {
      const double k = std::sqrt(arc.radius * arc.radius - h * h);
      for (double sign : {-1.0, 1.0}) {
        add_if_on_both(r, s, arc, q + (sign * k) * dir, false, eps);
      }
    }
    add_endpoint_touches(r, s, arc, tangent, eps, eps * len, carrier_slack(arc, eps));
  }
  finish_kind(r);
  return r;
}

// The two crossing points of circles (c1, r1) and (c2, r2) at centre distance d, strictly
// between tangencies: c1 + s u +- h perp(u), u the unit vector from c1 to c2, with
// s = (d^2 + r1^2 - r2^2) / 2d and h = sqrt(r1^2 - s^2). Measured from the smaller circle and
// with the differences factored, (d - r2)(d + r2) and (r1 - s)(r1 + s). A nearly straight arc
// has a far centre: at a radius 4,000 times the part's size, r1^2 - s^2 taken from it in the
// plain form lost 2e-8 on a part of size 8, three times the geometric epsilon, and the shared
// end of two contact arcs came back as two points (stress seed 101242 lost its free space so).
// From the smaller circle the error is that of d alone, about 1e-16 of the far centre's
// distance.
std::array<Vec2, 2> circle_crossings(Vec2 c1, double r1, Vec2 c2, double r2, double d) {
  if (r1 > r2) {
    std::swap(c1, c2);
    std::swap(r1, r2);
  }
  const Vec2 u = (1.0 / d) * (c2 - c1);
  const double s = ((d - r2) * (d + r2) + r1 * r1) / (2.0 * d);
  const double h = std::sqrt(std::max(0.0, (r1 - s) * (r1 + s)));
  return {c1 + s * u + h * perp_left(u), c1 + s * u - h * perp_left(u)};
}

// Arcs on circles (c1, r1) and (c2, r2) at centre distance d. Concentric within eps: equal
// radii overlap (pieces or touching ends), others never meet. Otherwise d within eps of
// r1 + r2 or |r1 - r2| is a tangency on the centre line; in between, the two crossings of
// the circles (circle_crossings).
Intersection intersect_arc_arc(const Curve& a, const Curve& b, double eps) {
  Intersection r;
  const Vec2 cc = b.center - a.center;
  const double d = length(cc);
  const double r1 = a.radius, r2 = b.radius;
  if (d <= eps) {
    if (std::fabs(r1 - r2) <= eps) cocircular_overlap(r, a, b, eps);
  } else if (d <= r1 + r2 + eps && d >= std::fabs(r1 - r2) - eps) {
    const Vec2 u = (1.0 / d) * cc;
    std::array<Vec2, 2> points;
    int n = 0;
    bool tangent = false;
    if (d >= r1 + r2 - eps) {
      points[n++] = a.center + (r1 + 0.5 * (d - r1 - r2)) * u;
      tangent = true;
    } else if (d <= std::fabs(r1 - r2) + eps) {
      const double side = r1 >= r2 ? 1.0 : -1.0;
      points[n++] = a.center + (side * r1) * u;
      tangent = true;
    } else {
      points = circle_crossings(a.center, r1, b.center, r2, d);
      n = 2;
    }
    for (int i = 0; i < n; ++i) add_if_on_both(r, a, b, points[i], tangent, eps);
    add_endpoint_touches(r, a, b, tangent, eps, carrier_slack(a, eps), carrier_slack(b, eps));
  }
  finish_kind(r);
  return r;
}

Intersection intersect(const Curve& a, const Curve& b, double eps) {
  if (a.is_segment() && b.is_segment()) return intersect_segment_segment(a, b, eps);
  if (a.is_arc() && b.is_arc()) return intersect_arc_arc(a, b, eps);
  if (a.is_segment()) return intersect_segment_arc(a, b, eps);
  // Arc first: solve with the roles swapped, then swap the parameters back.
  Intersection r = intersect_segment_arc(b, a, eps);
  for (int i = 0; i < r.count; ++i) {
    std::swap(r.hits[i].ta0, r.hits[i].tb0);
    std::swap(r.hits[i].ta1, r.hits[i].tb1);
  }
  return r;
}

}  // namespace cslice
