// Contact families in closed form (the same contact equations as src/contacts/contacts.cpp,
// with theta left free). With c the centre and rho the signed radius of a disc feature
// (vertex: rho = 0), n the fixed outward normal at the touching point, and R = R(theta):
//   disc m on segment f:   O = f(v) + rho_m n_f - R c_m          (n_f constant)
//   segment m on disc f:   O = c_f + rho_f R u_m - R m(u)        (u_m: m's inward normal)
//   disc m on disc f:      O = c_f + (rho_f + rho_m) n - R c_m,  n in N_f and in -R N_m.
// Every defining point is P + R Q. The normal intervals decide where a family is alive: a
// moving normal interval [lo, lo + span] faces the fixed normals [lo + theta + pi, ...].
#include "criticals/families.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace cslice {

Vec2 MovingPoint::at(double theta) const {
  return p + Transform(Pose{0.0, 0.0, theta}).rotate(q);
}

namespace {

bool is_full(const AngleInterval& a) {
  return a.span >= kTwoPi;
}

ContactFamily disc_on_segment(const ContactFeature& m, const ContactFeature& f) {
  ContactFamily fam;
  fam.shape = FamilyShape::fixed_line;
  const double n_f = f.normals.lo;
  const Vec2 shift = m.rho * unit_vector(n_f);
  fam.ends = {{f.from + shift, -m.center}, {f.to + shift, -m.center}};
  fam.alive = {n_f - kPi - m.normals.lo - m.normals.span, m.normals.span};
  return fam;
}

ContactFamily segment_on_disc(const ContactFeature& m, const ContactFeature& f) {
  ContactFamily fam;
  fam.shape = FamilyShape::turning_line;
  const Vec2 u = f.rho * unit_vector(m.normals.lo + kPi);
  fam.ends = {{f.center, u - m.from}, {f.center, u - m.to}};
  fam.alive = {f.normals.lo - m.normals.lo - kPi, f.normals.span};
  return fam;
}

// The largest |c_m + rho u(mu)| over the moving normals mu: how fast a contact point followed
// at a fixed moving normal moves (its derivative in theta is that vector turned by R).
double moving_point_speed(const ContactFamily& f) {
  const double rho = f.inward ? -f.radius : f.radius;
  const Vec2 c = -f.center.q;
  const AngleInterval& n = f.moving_normals;
  double v =
      std::max(length(c + rho * unit_vector(n.lo)), length(c + rho * unit_vector(n.lo + n.span)));
  // The farthest point of the whole circle from the origin, if the normals reach it.
  double far = std::atan2(c.y, c.x) + (rho < 0.0 ? kPi : 0.0);
  const double d = ccw_turn(n.lo, far);
  if (is_full(n) || d <= n.span) v = std::max(v, length(c) + std::fabs(rho));
  return v;
}

ContactFamily disc_on_disc(const ContactFeature& m, const ContactFeature& f, double eps) {
  ContactFamily fam;
  fam.shape = FamilyShape::circle;
  const double rho = f.rho + m.rho;
  fam.radius = std::fabs(rho) <= eps ? 0.0 : std::fabs(rho);
  fam.center = {f.center, -m.center};
  fam.inward = rho < 0.0;
  fam.fixed_normals = f.normals;
  fam.moving_normals = m.normals;
  fam.alive = {f.normals.lo - m.normals.span - m.normals.lo - kPi, f.normals.span + m.normals.span};
  if (fam.radius == 0.0) {
    fam.ends = {fam.center};
    return fam;
  }
  fam.point_speed = moving_point_speed(fam);
  std::vector<double> fixed_ends, moving_ends;
  if (!is_full(f.normals)) fixed_ends = {f.normals.lo, f.normals.lo + f.normals.span};
  if (!is_full(m.normals)) moving_ends = {m.normals.lo, m.normals.lo + m.normals.span};
  for (double e : fixed_ends) fam.ends.push_back({f.center + rho * unit_vector(e), -m.center});
  for (double e : moving_ends)
    fam.ends.push_back({f.center, rho * unit_vector(e + kPi) - m.center});
  for (double ef : fixed_ends)
    for (double em : moving_ends) fam.switches.push_back(wrap_angle(ef - em - kPi));
  return fam;
}

// Sorts the switches and keeps one of each run closer than the angular tolerance (across
// theta = +-pi too): an alive range's end and a switch of ends computed by different sums
// agree only to round-off, and whether they came out equal must not decide whether the family
// lists one segment end or two (the knee listed one more drawn 1,000 times smaller).
void merge_close_switches(std::vector<double>& switches, double angular) {
  std::sort(switches.begin(), switches.end());
  switches.erase(std::unique(switches.begin(), switches.end(),
                             [&](double a, double b) { return b - a <= angular; }),
                 switches.end());
  if (switches.size() >= 2 && switches.front() + kTwoPi - switches.back() <= angular)
    switches.pop_back();
}

}  // namespace

std::vector<ContactFamily> contact_families(const Pair& pair) {
  const std::vector<ContactFeature> moving = contact_features(pair.moving);
  const std::vector<ContactFeature> fixed = contact_features(pair.fixed);
  const double eps = pair.tol.geometric;
  std::vector<ContactFamily> out;
  for (const ContactFeature& m : moving) {
    for (const ContactFeature& f : fixed) {
      if (!pair_can_touch(m, f, eps)) continue;
      ContactFamily fam = f.kind == FeatureKind::segment   ? disc_on_segment(m, f)
                          : m.kind == FeatureKind::segment ? segment_on_disc(m, f)
                                                           : disc_on_disc(m, f, eps);
      fam.moving = m.feature;
      fam.fixed = f.feature;
      fam.kind = contact_kind(m, f);
      if (!fam.always_alive()) {
        fam.alive.lo = wrap_angle(fam.alive.lo);
        fam.switches.push_back(fam.alive.lo);
        fam.switches.push_back(wrap_angle(fam.alive.lo + fam.alive.span));
      }
      merge_close_switches(fam.switches, pair.tol.angular);
      out.push_back(std::move(fam));
    }
  }
  return out;
}

bool alive_at(const ContactFamily& family, double theta, double slack) {
  if (family.always_alive()) return true;
  const double d = ccw_turn(family.alive.lo, theta);
  return d <= family.alive.span + slack || d >= kTwoPi - slack;
}

// Whether [lo, hi] meets the family's alive interval (both taken around the circle).
bool alive_within(const ContactFamily& family, double lo, double hi) {
  if (family.always_alive()) return true;
  const double d = ccw_turn(lo, family.alive.lo);
  // The alive interval starts d after lo: inside [lo, hi], or began before lo and lasts.
  return d <= hi - lo || d + family.alive.span >= kTwoPi;
}

Curve family_cover(const ContactFamily& family, double theta) {
  return family_cover(family, Transform(Pose{0.0, 0.0, theta}));
}

Curve family_cover(const ContactFamily& family, const Transform& rotation) {
  const double theta = rotation.angle;
  if (family.shape != FamilyShape::circle)
    return make_segment(family.ends[0].at(rotation), family.ends[1].at(rotation));
  const Vec2 c = family.center.at(rotation);
  if (family.radius == 0.0) return make_segment(c, c);
  AngleInterval normals = family.fixed_normals;
  if (normals.span >= kTwoPi)
    normals = {family.moving_normals.lo + theta + kPi, family.moving_normals.span};
  if (normals.span >= kTwoPi) return make_circle(c, family.radius);
  const double start = normals.lo + (family.inward ? kPi : 0.0);
  return make_arc(c, family.radius, start, normals.span);
}

double family_drift(const ContactFamily& family) {
  if (family.shape != FamilyShape::circle)
    return std::max(length(family.ends[0].q), length(family.ends[1].q));
  // A full fixed circle's cover turns with the moving normals.
  const bool turns = family.fixed_normals.span >= kTwoPi;
  return length(family.center.q) + (turns ? family.radius : 0.0);
}

namespace {

AngleInterval widened(const AngleInterval& a, double by) {
  return is_full(a) ? a : AngleInterval{a.lo - by, std::min(a.span + 2.0 * by, kTwoPi)};
}

// The meeting of two angle intervals when it is one piece (possibly empty: span < 0).
std::optional<AngleInterval> meeting(const AngleInterval& a, const AngleInterval& b) {
  if (is_full(a)) return b;
  if (is_full(b)) return a;
  const double d = ccw_turn(a.lo, b.lo);  // where b starts, seen from a.lo
  if (d <= a.span) {
    if (d + b.span > kTwoPi) return std::nullopt;  // b wraps back into a: two pieces
    return AngleInterval{a.lo + d, std::min(a.span - d, b.span)};
  }
  const double into = b.span - (kTwoPi - d);  // how far b reaches past a.lo
  return AngleInterval{a.lo, into < 0.0 ? -1.0 : std::min(a.span, into)};
}

}  // namespace

FamilyCover family_cover_within(const ContactFamily& family, double theta, double half_width) {
  return family_cover_within(family, Transform(Pose{0.0, 0.0, theta}), half_width);
}

FamilyCover family_cover_within(const ContactFamily& family, const Transform& rotation,
                                double half_width) {
  const double theta = rotation.angle;
  const auto loose = [&] {
    return FamilyCover{family_cover(family, rotation), family_drift(family)};
  };
  if (family.shape != FamilyShape::circle || family.radius == 0.0) return loose();
  // Followed at a fixed normal n, a contact point moves with the centre, and n stays in N_f;
  // followed at a fixed moving normal mu, it moves as the moving feature's point, and
  // theta + pi + mu stays in the facing normals at theta. The other interval is widened by
  // the half-width: the contact at theta + d has n in both N_f and the normals facing then.
  const AngleInterval facing{family.moving_normals.lo + theta + kPi, family.moving_normals.span};
  const double by_centre = length(family.center.q), by_point = family.point_speed;
  const bool centre = by_centre <= by_point;
  const std::optional<AngleInterval> normals =
      centre ? meeting(family.fixed_normals, widened(facing, half_width))
             : meeting(widened(family.fixed_normals, half_width), facing);
  if (!normals || normals->span < 0.0) return loose();
  const Vec2 c = family.center.at(rotation);
  const double drift = centre ? by_centre : by_point;
  if (is_full(*normals)) return {make_circle(c, family.radius), drift};
  const double start = normals->lo + (family.inward ? kPi : 0.0);
  return {make_arc(c, family.radius, start, normals->span), drift};
}

FamilyEquation family_equation(const ContactFamily& family) {
  FamilyEquation e;
  if (family.shape == FamilyShape::circle) {
    e.circle = true;
    e.anchor = family.center;
    e.point = rotating_point(family.center.p, family.center.q);
    e.radius = family.radius;
    e.a = Trig::constant(-2.0) * e.point;
    e.b = dot(e.point, e.point) - Trig::constant(family.radius * family.radius);
    return e;
  }
  const MovingPoint& from = family.ends[0];
  const MovingPoint& to = family.ends[1];
  e.anchor = from;
  e.point = rotating_point(from.p, from.q);
  e.turning = family.shape == FamilyShape::turning_line;
  if (e.turning) {
    e.unit_normal = normalized(perp_left(to.q - from.q));
    e.normal = rotating_point({0.0, 0.0}, e.unit_normal);
  } else {
    e.unit_normal = normalized(perp_left(to.p - from.p));
    e.normal = constant_vec(e.unit_normal);
  }
  e.a = e.normal;
  e.b = -dot(e.normal, e.point);
  const auto [p0, p1, p2] = e.line_terms(e.anchor.p, e.anchor.q);
  e.anchor_size = std::max({std::fabs(p0), std::fabs(p1), std::fabs(p2)});
  return e;
}

}  // namespace cslice
