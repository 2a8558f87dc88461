// Trigonometric polynomials in the orientation theta, and their real roots.
//
// Every contact curve of a line/arc pair moves with theta through points of the form
// P + R(theta) Q, whose coordinates are degree-1 trigonometric polynomials. Each criticality
// condition is a polynomial expression in such coordinates, hence a trigonometric
// polynomial F(theta) = a0 + sum_j (a_j cos j.theta + b_j sin j.theta) of small degree:
// products make up to 6 nominally, but rotation invariance cancels the top harmonics, so
// pair conditions come out of degree 1 and triple points of degree at most 3. Its roots are the
// candidate critical orientations: docs/criticals.md derives each equation.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "cslice/geometry.hpp"

namespace cslice {

// cos(theta) and sin(theta), for evaluating several polynomials at one theta with one pair
// (the values, so the results, are those of evaluating each at theta).
struct TrigAngle {
  double c = 1.0, s = 0.0;
  explicit TrigAngle(double theta) : c(std::cos(theta)), s(std::sin(theta)) {}
  // The pair a rotation by theta already holds (Transform takes the same std::cos and
  // std::sin): a caller with both pays for one.
  explicit TrigAngle(const Transform& rotation) : c(rotation.c), s(rotation.s) {}
};

// A real Fourier polynomial of degree <= kMaxDegree, in Fourier form: products use the
// product-to-sum identities, so cos^2 + sin^2 cancels exactly up to round-off.
struct Trig {
  static constexpr int kMaxDegree = 8;
  std::array<double, kMaxDegree + 1> a{};  // cosine coefficients (a[0] is the constant)
  std::array<double, kMaxDegree + 1> b{};  // sine coefficients (b[0] unused, always 0)
  // Every coefficient above `top` is zero: the arithmetic below touches only harmonics up to
  // it (most equations are built from degree-1 terms, and a full pass over kMaxDegree
  // harmonics per operation was most of their cost). Setting coefficients by hand keeps the
  // default, which promises nothing.
  int top = kMaxDegree;

  static Trig constant(double v);
  // c cos(theta) + s sin(theta)
  static Trig harmonic(double c, double s);

  int degree() const;   // highest j with a nonzero coefficient (0 for constants and zero)
  double norm() const;  // largest coefficient magnitude
  double operator()(double theta) const;
  double operator()(const TrigAngle& theta) const;
  Trig derivative() const;
  // G(phi) = F(phi + shift) for shift = 0 or pi (a half turn negates the odd harmonics).
  Trig half_turned() const;
};

Trig operator+(const Trig& f, const Trig& g);
Trig operator-(const Trig& f, const Trig& g);
Trig operator-(const Trig& f);
Trig operator*(const Trig& f, const Trig& g);  // degrees must add up to <= kMaxDegree
Trig operator*(double s, const Trig& f);

// A point or vector whose coordinates are trigonometric polynomials.
struct TrigVec {
  Trig x, y;
};
// The moving point P + R(theta) Q.
TrigVec rotating_point(Vec2 p, Vec2 q);
TrigVec constant_vec(Vec2 v);
TrigVec operator+(const TrigVec& u, const TrigVec& v);
TrigVec operator-(const TrigVec& u, const TrigVec& v);
TrigVec operator*(const Trig& s, const TrigVec& v);
Trig dot(const TrigVec& u, const TrigVec& v);
Trig cross(const TrigVec& u, const TrigVec& v);
// (f - g)(theta), bit for bit, without building f - g.
double evaluate_difference(const Trig& f, const Trig& g, const TrigAngle& theta);
Vec2 evaluate(const TrigVec& v, double theta);
Vec2 evaluate(const TrigVec& v, const TrigAngle& theta);

// Real roots of f in [-pi, pi), sorted. A root is a sign change, polished to full
// precision, or a local extremum where |f| <= touch * f.norm(): a double root (a grazing
// contact) that a sign test would miss. Returns no roots when f is identically zero
// relative to `zero_norm` (f.norm() <= zero_norm): the condition then holds for every theta
// and marks a permanent coincidence, not a critical orientation.
// At most this many roots: two charts, each with its simple and its double roots. On a chart
// the polynomial in t has degree 2n <= 2 kMaxDegree: at most 2n distinct simple roots and
// 2n - 1 turning points (double roots), plus one repeat where the two stretches a chart may
// be searched over touch: two charts give at most 8n <= kMaxTrigRoots, and push_back's guard
// never drops a root.
inline constexpr int kMaxTrigRoots = 4 * (2 * Trig::kMaxDegree + 1);
static_assert(2 * (2 * (2 * Trig::kMaxDegree) - 1 + 1) <= kMaxTrigRoots);
// Fixed capacity, no allocation: thousands of equations are solved per pair of parts.
class TrigRootList {
 public:
  void push_back(double theta) {
    if (count_ < kMaxTrigRoots) roots_[count_++] = theta;
  }
  void resize(size_t n) { count_ = int(n); }
  size_t size() const { return size_t(count_); }
  bool empty() const { return count_ == 0; }
  double* begin() { return roots_.data(); }
  double* end() { return roots_.data() + count_; }
  const double* begin() const { return roots_.data(); }
  const double* end() const { return roots_.data() + count_; }
  double operator[](size_t i) const { return roots_[i]; }

 private:
  std::array<double, kMaxTrigRoots> roots_;
  int count_ = 0;
};
struct TrigRoots {
  TrigRootList roots;
  bool identically_zero = false;
};
// Roots closer than merge_angle are reported once.
TrigRoots trig_roots(const Trig& f, double zero_norm, double touch, double merge_angle);

// An arc of orientations, from mid - half to mid + half (radians).
struct AngleWindow {
  double mid = 0.0, half = kPi;
};
// trig_roots where only the roots within some of `windows` are needed: above degree 1 the
// roots are sought there only (the polynomial in tan(theta / 2) is searched over those
// stretches of its charts), and those outside may or may not be reported. Degrees 0 and 1
// are solved in closed form over the whole turn.
TrigRoots trig_roots_within(const Trig& f, double zero_norm, double touch, double merge_angle,
                            const AngleWindow* windows, int window_count);

}  // namespace cslice
