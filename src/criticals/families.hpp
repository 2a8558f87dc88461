// Contact families: the contact segments of one feature pair followed through every
// orientation. Each is a line segment or circular arc whose defining points move as
// P + R(theta) Q (docs/criticals.md, "Contact families"), alive on one interval of theta.
#pragma once

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

// A box holding every contact segment of the family for theta in [lo, hi] (hi - lo small,
// at most pi/2), or an empty box when it is nowhere alive there.
Box family_box(const ContactFamily& family, double lo, double hi);

// The family's curve as an implicit equation g(X, theta) = w |X|^2 + a(theta) . X + b(theta)
// (w = 0 for lines, whose normal `a` is a unit vector; w = 1 for circles).
struct FamilyEquation {
  bool circle = false;
  TrigVec a;
  Trig b;
  // For lines: a point on it and its unit normal; for circles: the centre and radius.
  TrigVec point, normal;
  double radius = 0.0;
};
FamilyEquation family_equation(const ContactFamily& family);
// g(X) for the family's curve at the moving point X.
Trig evaluate_equation(const FamilyEquation& e, const TrigVec& x);

}  // namespace cslice
