#include "criticals/events.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace cslice {
namespace {

double norm_sum(std::initializer_list<const Trig*> terms) {
  double n = 0.0;
  for (const Trig* t : terms) n += t->norm();
  return n;
}

// The linear equation a . X + b = 0 a curve leaves after subtracting circle g (w = 1) from
// it: a radical line for a circle, the line itself for a line.
struct Linear {
  Trig ax, ay, b;
};
Linear minus_circle(const FamilyEquation& e, const FamilyEquation& g) {
  if (!e.circle) return {e.a.x, e.a.y, e.b};
  return {e.a.x - g.a.x, e.a.y - g.a.y, e.b - g.b};
}

}  // namespace

// The pair equations are all of degree 1 and are written in closed form from the moving
// points: with X - Y = A + R(theta) B for two moving points X, Y, and R v . B expanded,
//   |A + R B|^2 = |A|^2 + |B|^2 + 2 (A . B) cos - 2 (A x B) sin,
//   m . (A + R B) = m . A + (m . B) cos - (m x B) sin           (m a fixed unit normal),
//   R v . (A + R B) = v . B + (A . v) cos - (A x v) sin          (a turning one).
// The same equations built by multiplying trigonometric polynomials leave degree-2 terms
// that cancel only to round-off, and cost ten times as much. Each magnitude is the largest
// term it sums, as trig_roots' identically-zero test expects.
namespace {

EventEquation first_harmonic(double constant, double cosine, double sine, double magnitude) {
  Trig f;
  f.a[0] = constant;
  f.a[1] = cosine;
  f.b[1] = sine;
  f.top = 1;
  return {f, magnitude};
}

double largest(double a, double b, double c) {
  return std::max({std::fabs(a), std::fabs(b), std::fabs(c)});
}

// |X - C|^2 - r^2 for the moving point X and circle centre C.
EventEquation distance_equation(const MovingPoint& x, const MovingPoint& centre, double r) {
  const Vec2 a = x.p - centre.p, b = x.q - centre.q;
  const double square = dot(a, a) + dot(b, b), along = 2.0 * dot(a, b), across = -2.0 * cross(a, b);
  return first_harmonic(square - r * r, along, across, largest(square, along, across) + r * r);
}

// n . (X - p) - offset, from the coefficients of n . (X - p) for a line of normal n through
// p, the moving point X standing for A + R B (see above; FamilyEquation::line_terms). Its
// magnitude is that of the difference, or (`parts`) of n . X and n . p apart: an end on a
// line compares two points each given in its own frame, and a permanent coincidence there
// cancels only to the round-off of their own sizes.
EventEquation line_equation(const MovingPoint& x, const FamilyEquation& line, double offset,
                            bool parts) {
  const auto [fixed, along, across] = line.line_terms(x.p - line.anchor.p, x.q - line.anchor.q);
  double magnitude = largest(fixed, along, across);
  if (parts) {
    const auto [x0, x1, x2] = line.line_terms(x.p, x.q);
    magnitude = largest(x0, x1, x2) + line.anchor_size;
  }
  return first_harmonic(fixed - offset, along, across, magnitude + std::fabs(offset));
}

}  // namespace

EventEquation endpoint_equation(const MovingPoint& end, const FamilyEquation& b) {
  return b.circle ? distance_equation(end, b.anchor, b.radius) : line_equation(end, b, 0.0, true);
}

int tangent_equations(const FamilyEquation& a, const FamilyEquation& b,
                      std::array<EventEquation, 2>& out) {
  if (!a.circle && !b.circle) return 0;
  if (a.circle && b.circle) {
    if (a.radius == 0.0 || b.radius == 0.0) return 0;  // a point on a curve: an endpoint event
    out[0] = distance_equation(a.anchor, b.anchor, a.radius + b.radius);
    out[1] = distance_equation(a.anchor, b.anchor, std::fabs(a.radius - b.radius));
    return 2;
  }
  const FamilyEquation& line = a.circle ? b : a;
  const FamilyEquation& circle = a.circle ? a : b;
  if (circle.radius == 0.0) return 0;
  out[0] = line_equation(circle.anchor, line, circle.radius, false);
  out[1] = line_equation(circle.anchor, line, -circle.radius, false);
  return 2;
}

EventEquation triple_equation(const FamilyEquation& a, const FamilyEquation& b,
                              const FamilyEquation& c) {
  const FamilyEquation* e[3] = {&a, &b, &c};
  const FamilyEquation* const* g = std::find_if(e, e + 3, [](auto* x) { return x->circle; });
  if (g == e + 3) {
    // det [a1x a1y b1; a2x a2y b2; a3x a3y b3], expanded along the last column.
    const Trig m1 = a.b * cross(b.a, c.a), m2 = b.b * cross(c.a, a.a), m3 = c.b * cross(a.a, b.a);
    return {m1 + m2 + m3, norm_sum({&m1, &m2, &m3})};
  }
  const FamilyEquation* others[2];
  int k = 0;
  for (auto* x : e)
    if (x != *g) others[k++] = x;
  const Linear l1 = minus_circle(*others[0], **g), l2 = minus_circle(*others[1], **g);
  const Trig d = l1.ax * l2.ay - l1.ay * l2.ax;
  const Trig nx = l2.b * l1.ay - l1.b * l2.ay;
  const Trig ny = l1.b * l2.ax - l2.b * l1.ax;
  const Trig t1 = nx * nx + ny * ny;
  const Trig t2 = d * ((*g)->a.x * nx + (*g)->a.y * ny);
  const Trig t3 = (*g)->b * (d * d);
  return {t1 + t2 + t3, norm_sum({&t1, &t2, &t3})};
}

Vec2 tangent_point(const FamilyEquation& a, const FamilyEquation& b, const TrigAngle& theta) {
  if (a.circle != b.circle) {
    const FamilyEquation& line = a.circle ? b : a;
    const FamilyEquation& circle = a.circle ? a : b;
    const Vec2 c = evaluate(circle.point, theta), n = evaluate(line.normal, theta);
    return c - dot(n, c - evaluate(line.point, theta)) * n;
  }
  const Vec2 ca = evaluate(a.point, theta), cb = evaluate(b.point, theta);
  const Vec2 u = normalized(cb - ca);
  const Vec2 candidates[2] = {ca + a.radius * u, ca - a.radius * u};
  auto miss = [&](Vec2 p) { return std::fabs(distance(p, cb) - b.radius); };
  return miss(candidates[0]) <= miss(candidates[1]) ? candidates[0] : candidates[1];
}

namespace {

// How far x lies from the family's whole curve at theta (a line or a circle).
double curve_miss(const FamilyEquation& f, Vec2 x, const TrigAngle& theta) {
  if (f.circle) return std::fabs(distance(x, evaluate(f.point, theta)) - f.radius);
  return std::fabs(dot(evaluate(f.normal, theta), x - evaluate(f.point, theta)));
}

// The common point of two of the three curves' linear equations (with circle g subtracted
// from the others when given), from the best-conditioned pair of rows.
std::optional<Vec2> solve_rows(const FamilyEquation* const (&e)[3], const FamilyEquation* g,
                               const TrigAngle& theta) {
  struct Row {
    double ax, ay, b;
  };
  std::array<Row, 3> rows;  // 2 with a circle, else 3: no allocation per root
  int count = 0;
  for (auto* x : e) {
    if (x == g) continue;
    // minus_circle() evaluated, without building it.
    if (g && x->circle)
      rows[count++] = {evaluate_difference(x->a.x, g->a.x, theta),
                       evaluate_difference(x->a.y, g->a.y, theta),
                       evaluate_difference(x->b, g->b, theta)};
    else
      rows[count++] = {x->a.x(theta), x->a.y(theta), x->b(theta)};
  }
  std::optional<Vec2> best;
  double best_det = 0.0;
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j) {
      const Row& r = rows[i];
      const Row& s = rows[j];
      const double det = r.ax * s.ay - r.ay * s.ax;
      if (std::fabs(det) <= best_det) continue;
      best_det = std::fabs(det);
      best = Vec2{(-r.b * s.ay + s.b * r.ay) / det, (-r.ax * s.b + s.ax * r.b) / det};
    }
  if (best && !is_finite(*best)) return std::nullopt;
  return best;
}

// Where two whole curves cross at theta, by their own geometry (a line's foot and chord, or
// the circles' common chord), added to `out`; where they miss each other, their nearest
// point (a grazing crossing that round-off pulled apart). whole_curves_cross
// (candidates.cpp) has the same geometry but no answer for grazing curves, which bound no
// meeting there; a triple point needs that nearest point too.
void add_crossings(const FamilyEquation& f, const FamilyEquation& g, const TrigAngle& theta,
                   std::vector<Vec2>& out) {
  if (!f.circle && !g.circle) return;  // two lines: solve_rows already has their point
  if (f.circle != g.circle) {
    const FamilyEquation& line = f.circle ? g : f;
    const FamilyEquation& circle = f.circle ? f : g;
    const Vec2 c = evaluate(circle.point, theta), n = evaluate(line.normal, theta);
    const double d = dot(n, c - evaluate(line.point, theta));
    const Vec2 foot = c - d * n, along{-n.y, n.x};
    const double h = std::sqrt(std::max(0.0, circle.radius * circle.radius - d * d));
    out.push_back(foot + h * along);
    out.push_back(foot - h * along);
    return;
  }
  const Vec2 c1 = evaluate(f.point, theta), c2 = evaluate(g.point, theta);
  const double d = distance(c1, c2);
  if (!(d > 0.0)) return;
  for (Vec2 p : circle_crossings(c1, f.radius, c2, g.radius, d)) out.push_back(p);
}

}  // namespace

// The linear equations (a circle subtracted from the others) can cross at a shallow angle
// where two of the curves themselves cross steeply: a line and the radical line of a flat
// circle of radius 12 and one of radius 0.5 put the point 2.3e-5 along the line from where
// the three meet, 1e-5 off the third curve, and the triple was rejected (stress seed 141335,
// a change the critical orientations missed). So the crossings of each two of the curves
// themselves are candidates too, and the one nearest all three curves is kept; the linear
// equations' point comes first, so a tie keeps what it gave before.
std::optional<Vec2> triple_point(const FamilyEquation& a, const FamilyEquation& b,
                                 const FamilyEquation& c, const TrigAngle& theta) {
  const FamilyEquation* const e[3] = {&a, &b, &c};
  const FamilyEquation* g = nullptr;
  for (auto* x : e)
    if (x->circle && !g) g = x;
  std::optional<Vec2> best = solve_rows(e, g, theta);
  if (!g) return best;
  const auto miss = [&](Vec2 x) {
    double m = 0.0;
    for (auto* f : e) m = std::max(m, curve_miss(*f, x, theta));
    return m;
  };
  double best_miss = best ? miss(*best) : std::numeric_limits<double>::infinity();
  // Nearly always the linear point is on all three to round-off: no need to look further.
  if (best && best_miss <= kWellPlacedTriplePoint * std::max(1.0, length(*best))) return best;
  std::vector<Vec2> candidates;
  add_crossings(a, b, theta, candidates);
  add_crossings(a, c, theta, candidates);
  add_crossings(b, c, theta, candidates);
  for (Vec2 x : candidates) {
    if (!is_finite(x)) continue;
    if (const double m = miss(x); m < best_miss) {
      best_miss = m;
      best = x;
    }
  }
  return best;
}

}  // namespace cslice
