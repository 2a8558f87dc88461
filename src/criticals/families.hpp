// Contact families: the contact segments of one feature pair followed through every
// orientation. Each is a line segment or circular arc whose defining points move as
// P + R(theta) Q (docs/criticals.md, "Contact families"), alive on one interval of theta.
#pragma once

#include <array>
#include <vector>

#include "contacts/contact_features.hpp"
#include "criticals/trig.hpp"

namespace cslice {

enum class FamilyShape {
  fixed_line,    // a moving disc feature on a fixed segment: direction fixed in the world
  turning_line,  // a moving segment on a fixed disc feature: direction turns with theta
  circle,        // disc feature on disc feature: a circle of fixed radius, moving centre
};

// A point P + R(theta) Q.
struct MovingPoint {
  Vec2 p, q;
  Vec2 at(double theta) const;
  // The same point for rotation = Transform(Pose{0, 0, theta}): one sin/cos pair for many.
  Vec2 at(const Transform& rotation) const { return p + rotation.rotate(q); }
};

struct ContactFamily {
  int moving = 0, fixed = 0;  // feature indices
  ContactKind kind = ContactKind::vertex_segment;
  FamilyShape shape = FamilyShape::fixed_line;
  // Lines: ends[0] -> ends[1]. Circles: the candidate ends, each the contact point at one end
  // of a normal interval (which of them bound the arc depends on theta).
  std::vector<MovingPoint> ends;
  MovingPoint center;   // circles only
  double radius = 0.0;  // circles only; 0 for a perfect fit (the family is a point)
  bool inward = false;  // circles only: contact points at C - radius n (rho_f + rho_m < 0)
  // Circles only: the normal intervals of the two features (the fixed one in the world, the
  // moving one in the body frame), which bound the contact arc.
  AngleInterval fixed_normals, moving_normals;
  // Circles only: the largest |c_m + rho u(mu)| over the moving normals mu, how fast a contact
  // point followed at a fixed moving normal moves (family_cover_within).
  double point_speed = 0.0;
  // Orientations where the pair touches: [alive.lo, alive.lo + alive.span]; span >= 2pi
  // means always.
  AngleInterval alive;
  // Orientations where the contact segment appears, vanishes, or one of its ends passes from
  // one feature's end to the other's (the normal intervals' ends meet).
  std::vector<double> switches;

  bool always_alive() const { return alive.span >= kTwoPi; }
  bool is_point() const { return shape == FamilyShape::circle && radius == 0.0; }
};

// Every feature pair that can touch at some orientation, after local overlap filtering.
std::vector<ContactFamily> contact_families(const Pair& pair);

// Whether theta lies in the family's alive interval, widened by `slack` radians.
bool alive_at(const ContactFamily& family, double theta, double slack);

// Whether [lo, hi] meets the family's alive interval.
bool alive_within(const ContactFamily& family, double lo, double hi);

// A curve holding the family's contact segments at theta, alive or not: a line family's
// whole segment; for circles the arc of the fixed feature's normals (or, for a full fixed
// circle, of the moving feature's), or the whole circle.
Curve family_cover(const ContactFamily& family, double theta);
// The same for rotation = Transform(Pose{0, 0, theta}): one sin/cos pair for many families.
Curve family_cover(const ContactFamily& family, const Transform& rotation);
// How far (per radian of theta) any point of the cover can move: no point of the family's
// contact segments at theta + d lies farther than |d| times this from the cover at theta.
double family_drift(const ContactFamily& family);

// A tighter cover for the orientations within half_width of theta, and its drift (per radian,
// as above). A circle family's contact arc at theta + d spans the fixed normals that face the
// moving ones, N_f and theta + d + pi + N_m, so its cover needs only their meeting, one of the
// two widened by half_width; and each contact point, followed at a fixed moving normal, moves with
// the moving feature's point there (|c_m + rho u(mu)| per radian), which is far slower than the
// circle's centre when the moving feature is a flat arc of large radius. Lines, and circles
// whose narrowed normals would be two pieces, keep family_cover and family_drift.
struct FamilyCover {
  Curve curve;
  double drift = 0.0;
};
FamilyCover family_cover_within(const ContactFamily& family, double theta, double half_width);
// The same for rotation = Transform(Pose{0, 0, theta}) (as family_cover).
FamilyCover family_cover_within(const ContactFamily& family, const Transform& rotation,
                                double half_width);

// The family's curve as an implicit equation g(X, theta) = w |X|^2 + a(theta) . X + b(theta)
// (w = 0 for lines, whose normal `a` is a unit vector; w = 1 for circles).
struct FamilyEquation {
  bool circle = false;
  TrigVec a;
  Trig b;
  // For lines: a point on it and its unit normal; for circles: the centre and radius.
  TrigVec point, normal;
  double radius = 0.0;
  // The same as moving points, for the pair equations' closed forms (events.cpp): the
  // centre or the line's point, and the unit normal, fixed or (turning) R(theta) `unit_normal`.
  MovingPoint anchor;
  Vec2 unit_normal;
  bool turning = false;
  // Lines: the coefficients (constant, cos, sin) of n . X for a moving point X = P + R Q given
  // as a = P, b = Q (or as differences of such), and the largest of those of the anchor (an end's
  // equation weighs its own terms against them: the same for every end, so found once).
  // R v . (A + R B) = v . B + (A . v) cos - (A x v) sin for a turning normal R v, and
  // m . (A + R B) = m . A + (m . B) cos - (m x B) sin for a fixed one (events.cpp).
  std::array<double, 3> line_terms(Vec2 a, Vec2 b) const {
    const Vec2 v = unit_normal;
    if (turning) return {dot(v, b), dot(a, v), -cross(a, v)};
    return {dot(v, a), dot(v, b), -cross(v, b)};
  }
  double anchor_size = 0.0;
};
FamilyEquation family_equation(const ContactFamily& family);

}  // namespace cslice
