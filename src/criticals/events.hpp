// The criticality equations of condition 3 for pairs and triples of contact families, one
// function per condition, and the configuration where each solution happens. Every
// equation is a trigonometric polynomial in theta; docs/criticals.md derives them.
#pragma once

#include <array>
#include <optional>

#include "criticals/families.hpp"

namespace cslice {

// An equation and the size of the terms it sums: F is identically zero (the condition holds
// at every orientation, a designed coincidence) when its coefficients cancel down to
// round-off of that size, whatever the units and scale of F.
struct EventEquation {
  Trig f;
  double magnitude = 0.0;
};

// End `end` of family a lies on the curve of family b: g_b(P + R Q) = 0.
EventEquation endpoint_equation(const MovingPoint& end, const FamilyEquation& b);

// The two curves touch tangentially: line and circle, n . (C - p) = +-r; two circles,
// |C1 - C2|^2 = (r1 +- r2)^2. Lines never do (two lines meet tangentially only by
// overlapping, which starts and ends at endpoint events). Returns how many equations.
int tangent_equations(const FamilyEquation& a, const FamilyEquation& b,
                      std::array<EventEquation, 2>& out);

// Three curves through one point: with every curve written w |X|^2 + a . X + b = 0, the
// determinant of three lines; otherwise two radical lines L1, L2 (each curve minus one
// circle G), whose meeting point N / D lies on G: |N|^2 + D a_G . N + b_G D^2 = 0.
EventEquation triple_equation(const FamilyEquation& a, const FamilyEquation& b,
                              const FamilyEquation& c);

// Where two curves touch at theta (the foot of the centre on the line, or the point on the
// line of centres), or three meet (their common point), if it is well defined.
// Both take theta as its cosine and sine (one pair for every evaluation).
Vec2 tangent_point(const FamilyEquation& a, const FamilyEquation& b, const TrigAngle& theta);
std::optional<Vec2> triple_point(const FamilyEquation& a, const FamilyEquation& b,
                                 const FamilyEquation& c, const TrigAngle& theta);

}  // namespace cslice
