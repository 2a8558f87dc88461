#include "criticals/events.hpp"

#include <algorithm>

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

EventEquation endpoint_equation(const MovingPoint& end, const FamilyEquation& b) {
  const TrigVec x = rotating_point(end.p, end.q);
  if (b.circle) {
    const TrigVec d = x - b.point;
    const Trig dd = dot(d, d), rr = Trig::constant(b.radius * b.radius);
    return {dd - rr, norm_sum({&dd, &rr})};
  }
  // n . (x - p) as n . x - n . p, where -n . p is the line's own b (family_equation), the
  // same bits as recomputing it: negation is exact, and x - y is x + (-y).
  const Trig along = dot(b.normal, x);
  return {along + b.b, norm_sum({&along, &b.b})};
}

int tangent_equations(const FamilyEquation& a, const FamilyEquation& b,
                      std::array<EventEquation, 2>& out) {
  if (!a.circle && !b.circle) return 0;
  if (a.circle && b.circle) {
    if (a.radius == 0.0 || b.radius == 0.0) return 0;  // a point on a curve: an endpoint event
    const TrigVec d = a.point - b.point;
    const Trig dd = dot(d, d);
    int n = 0;
    for (double r : {a.radius + b.radius, std::fabs(a.radius - b.radius)}) {
      const Trig rr = Trig::constant(r * r);
      out[n++] = {dd - rr, norm_sum({&dd, &rr})};
    }
    return n;
  }
  const FamilyEquation& line = a.circle ? b : a;
  const FamilyEquation& circle = a.circle ? a : b;
  if (circle.radius == 0.0) return 0;
  const Trig reach = dot(line.normal, circle.point - line.point);
  int n = 0;
  for (double r : {circle.radius, -circle.radius}) {
    const Trig rr = Trig::constant(r);
    out[n++] = {reach - rr, norm_sum({&reach, &rr})};
  }
  return n;
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

Vec2 tangent_point(const FamilyEquation& a, const FamilyEquation& b, double angle) {
  const TrigAngle theta(angle);  // one sin/cos pair for every evaluation
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

std::optional<Vec2> triple_point(const FamilyEquation& a, const FamilyEquation& b,
                                 const FamilyEquation& c, double angle) {
  const TrigAngle theta(angle);  // one sin/cos pair for every evaluation
  const FamilyEquation* e[3] = {&a, &b, &c};
  const FamilyEquation* g = nullptr;
  for (auto* x : e)
    if (x->circle && !g) g = x;
  // Solve two of the linear equations; with no circle pick the best-conditioned pair.
  struct Row {
    double ax, ay, b;
  };
  std::array<Row, 3> rows;  // 2 with a circle, else 3: no allocation per root
  int count = 0;
  for (auto* x : e) {
    if (x == g) continue;
    const Linear l = g ? minus_circle(*x, *g) : Linear{x->a.x, x->a.y, x->b};
    rows[count++] = {l.ax(theta), l.ay(theta), l.b(theta)};
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

}  // namespace cslice
