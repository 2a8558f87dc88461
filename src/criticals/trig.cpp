#include "criticals/trig.hpp"

#include <algorithm>
#include <cassert>
#include <optional>
#include <utility>

#include "cslice/tolerance.hpp"

namespace cslice {

Trig Trig::constant(double v) {
  Trig t;
  t.a[0] = v;
  t.top = 0;
  return t;
}

Trig Trig::harmonic(double c, double s) {
  Trig t;
  t.a[1] = c;
  t.b[1] = s;
  t.top = 1;
  return t;
}

int Trig::degree() const {
  for (int j = top; j > 0; --j)
    if (a[j] != 0.0 || b[j] != 0.0) return j;
  return 0;
}

// Coefficients above `top` are zero and leave the largest magnitude as it is.
double Trig::norm() const {
  double n = 0.0;
  for (int j = 0; j <= top; ++j) n = std::max(n, std::max(std::fabs(a[j]), std::fabs(b[j])));
  return n;
}

namespace {
// f at the angle whose cosine and sine are c1, s1: harmonics by the rotation recurrence.
// n = f.degree(), for a caller evaluating f many times.
double evaluate_at(const Trig& f, int n, double c1, double s1) {
  double c = 1.0, s = 0.0, v = f.a[0];
  for (int j = 1; j <= n; ++j) {
    const double cn = c * c1 - s * s1;
    s = s * c1 + c * s1;
    c = cn;
    v += f.a[j] * c + f.b[j] * s;
  }
  return v;
}
double evaluate_at(const Trig& f, double c1, double s1) {
  return evaluate_at(f, f.degree(), c1, s1);
}
}  // namespace

double Trig::operator()(double theta) const {
  // One sin/cos pair per evaluation.
  return evaluate_at(*this, std::cos(theta), std::sin(theta));
}

double Trig::operator()(const TrigAngle& theta) const {
  return evaluate_at(*this, theta.c, theta.s);
}

Trig Trig::derivative() const {
  Trig d;
  d.top = top;
  for (int j = 1; j <= top; ++j) {
    d.a[j] = j * b[j];
    d.b[j] = -j * a[j];
  }
  return d;
}

Trig Trig::half_turned() const {
  Trig t = *this;
  for (int j = 1; j <= top; j += 2) {
    t.a[j] = -t.a[j];
    t.b[j] = -t.b[j];
  }
  return t;
}

// Harmonics above both tops are zero in the result too; only their sign could differ from a
// full pass (-0 + -0), and nothing reads a zero above the degree but for its magnitude.
Trig operator+(const Trig& f, const Trig& g) {
  Trig r;
  r.top = std::max(f.top, g.top);
  for (int j = 0; j <= r.top; ++j) {
    r.a[j] = f.a[j] + g.a[j];
    r.b[j] = f.b[j] + g.b[j];
  }
  return r;
}

Trig operator-(const Trig& f) {
  return -1.0 * f;
}

// f + (-g), in one pass: x - y and x + (-y) are the same IEEE operation.
Trig operator-(const Trig& f, const Trig& g) {
  Trig r;
  r.top = std::max(f.top, g.top);
  for (int j = 0; j <= r.top; ++j) {
    r.a[j] = f.a[j] - g.a[j];
    r.b[j] = f.b[j] - g.b[j];
  }
  return r;
}

Trig operator*(double s, const Trig& f) {
  Trig r;
  r.top = f.top;
  for (int j = 0; j <= r.top; ++j) {
    r.a[j] = s * f.a[j];
    r.b[j] = s * f.b[j];
  }
  return r;
}

// Product to sum, with complex harmonics: f = sum_j Re(F_j e^{ij.theta}) where
// F_0 = a0 and F_j = a_j - i b_j, and Re(u) Re(v) = (Re(u v) + Re(u conj(v))) / 2.
// Written out in real arithmetic, operation for operation as std::complex computes it
// (x y = (x.re y.re - x.im y.im, x.re y.im + x.im y.re)) so the coefficients keep every bit,
// without its overflow checks and with the accumulators only as long as the result.
namespace {
struct Complex {
  double re = 0.0, im = 0.0;
};
Complex times(Complex x, Complex y) {
  return {x.re * y.re - x.im * y.im, x.re * y.im + x.im * y.re};
}
Complex half(Complex x) {
  return {0.5 * x.re, 0.5 * x.im};
}
Complex conjugate(Complex x) {
  return {x.re, -x.im};
}
void accumulate(Complex& acc, Complex x) {
  acc.re += x.re;
  acc.im += x.im;
}

// The product of f (degree nf) and g (degree ng). Templated on the degrees for the small
// ones, so that the loops unroll: the operations and their order are those of the general
// case, so the bits are too.
template <int NF, int NG>
Trig multiply(const Trig& f, const Trig& g, int nf, int ng) {
  if constexpr (NF >= 0) nf = NF;
  if constexpr (NG >= 0) ng = NG;
  // Accumulators for the frequencies the product reaches (all of them when not templated).
  constexpr int kAcc = NF >= 0 && NG >= 0 ? NF + NG + 1 : Trig::kMaxDegree + 1;
  std::array<Complex, kAcc> acc{};
  for (int j = 0; j <= nf; ++j) {
    const Complex u{f.a[j], -f.b[j]}, half_u = half(u);
    for (int k = 0; k <= ng; ++k) {
      const Complex v{g.a[k], -g.b[k]};
      accumulate(acc[j + k], times(half_u, v));
      const int d = j - k;
      // Re(u e^{ij} conj(v e^{ik})) = Re(u conj(v) e^{i(j-k)}); a negative frequency is the
      // conjugate at the positive one.
      if (d >= 0)
        accumulate(acc[d], times(half_u, conjugate(v)));
      else
        accumulate(acc[-d], half(conjugate(times(u, conjugate(v)))));
    }
  }
  Trig r;
  r.top = nf + ng;
  r.a[0] = acc[0].re;  // a zero frequency has no sine part
  for (int j = 1; j <= r.top; ++j) {
    r.a[j] = acc[j].re;
    r.b[j] = -acc[j].im;
  }
  return r;
}

using Multiply = Trig (*)(const Trig&, const Trig&, int, int);
constexpr int kUnrolledDegree = 3;  // triple equations multiply factors of degree <= 3

template <int NF, int... NG>
constexpr std::array<Multiply, sizeof...(NG)> multiply_row(std::integer_sequence<int, NG...>) {
  return {&multiply<NF, NG>...};
}
template <int... NF>
constexpr auto multiply_table(std::integer_sequence<int, NF...>) {
  using Seq = std::make_integer_sequence<int, kUnrolledDegree + 1>;
  return std::array<std::array<Multiply, kUnrolledDegree + 1>, sizeof...(NF)>{
      multiply_row<NF>(Seq{})...};
}
constexpr auto kMultiply = multiply_table(std::make_integer_sequence<int, kUnrolledDegree + 1>{});

}  // namespace

Trig operator*(const Trig& f, const Trig& g) {
  const int nf = f.degree(), ng = g.degree();
  assert(nf + ng <= Trig::kMaxDegree);
  if (nf <= kUnrolledDegree && ng <= kUnrolledDegree) return kMultiply[nf][ng](f, g, nf, ng);
  return multiply<-1, -1>(f, g, nf, ng);
}

namespace {
// constant(c) + harmonic(cos_part, sin_part), written out: the same additions (each with the
// other term's zero, which turns a -0 into +0), without the two temporaries.
Trig constant_plus_harmonic(double c, double cos_part, double sin_part) {
  Trig t;
  t.top = 1;
  t.a[0] = c + 0.0;
  t.b[0] = 0.0 + 0.0;
  t.a[1] = 0.0 + cos_part;
  t.b[1] = 0.0 + sin_part;
  return t;
}
}  // namespace

TrigVec rotating_point(Vec2 p, Vec2 q) {
  return {constant_plus_harmonic(p.x, q.x, -q.y), constant_plus_harmonic(p.y, q.y, q.x)};
}

TrigVec constant_vec(Vec2 v) {
  return {Trig::constant(v.x), Trig::constant(v.y)};
}

TrigVec operator+(const TrigVec& u, const TrigVec& v) {
  return {u.x + v.x, u.y + v.y};
}
TrigVec operator-(const TrigVec& u, const TrigVec& v) {
  return {u.x - v.x, u.y - v.y};
}
TrigVec operator*(const Trig& s, const TrigVec& v) {
  return {s * v.x, s * v.y};
}
Trig dot(const TrigVec& u, const TrigVec& v) {
  return u.x * v.x + u.y * v.y;
}
Trig cross(const TrigVec& u, const TrigVec& v) {
  return u.x * v.y - u.y * v.x;
}
// operator- then evaluate_at: the same differences, up to the difference's degree, without
// operator-'s bookkeeping.
double evaluate_difference(const Trig& f, const Trig& g, const TrigAngle& theta) {
  Trig d;
  d.top = std::max(f.top, g.top);
  d.a[0] = f.a[0] - g.a[0];
  int n = 0;
  for (int j = 1; j <= d.top; ++j) {
    d.a[j] = f.a[j] - g.a[j];
    d.b[j] = f.b[j] - g.b[j];
    if (d.a[j] != 0.0 || d.b[j] != 0.0) n = j;
  }
  return evaluate_at(d, n, theta.c, theta.s);
}

Vec2 evaluate(const TrigVec& v, double theta) {
  return {v.x(theta), v.y(theta)};
}
Vec2 evaluate(const TrigVec& v, const TrigAngle& theta) {
  return {v.x(theta), v.y(theta)};
}

namespace {

// ---- Real polynomials in t = tan(theta / 2) ---------------------------------------------
//
// Fixed capacity, no allocation: an equation of degree n in theta is one of degree 2n in t,
// and every root search here runs thousands of times per pair of parts.

constexpr int kMaxPolyDegree = 2 * Trig::kMaxDegree;

struct Poly {
  std::array<double, kMaxPolyDegree + 1> c{};  // coefficients, lowest degree first
  int size = 0;                                // degree + 1; 0 for the zero polynomial
};

// Roots found in one interval: a polynomial of degree d has at most d. Only the first
// `count` are ever read (lists are filled in place, never copied): the rest stay unset.
struct RootList {
  std::array<double, kMaxPolyDegree + 1> t;
  int count = 0;
  void push(double v) {
    if (count < int(t.size())) t[count++] = v;
  }
};

// Horner's rule. The size is a template argument for the sizes met, so that the loop
// unrolls; the operations and their order stay those of the plain loop.
template <int N>
double horner(const double* c, double t, int n) {
  if constexpr (N >= 0) n = N;
  double v = 0.0;
  for (int i = n; i-- > 0;) v = v * t + c[i];
  return v;
}

// p(t), and p'(t) from dp = derivative(p): the same two sums as two separate calls.
template <int N>
std::pair<double, double> horner2(const double* c, const double* dc, double t, int n) {
  if constexpr (N >= 0) n = N;
  double v = 0.0, w = 0.0;
  for (int i = n; i-- > 0;) {
    v = v * t + c[i];
    if (i > 0) w = w * t + dc[i - 1];
  }
  return {v, w};
}

constexpr int kUnrolledSize = 2 * 3 + 1;  // triple equations have degree <= 3 in theta

template <int... N>
constexpr auto horner_table(std::integer_sequence<int, N...>) {
  return std::array<double (*)(const double*, double, int), sizeof...(N)>{&horner<N>...};
}
constexpr auto kHorner = horner_table(std::make_integer_sequence<int, kUnrolledSize + 1>{});

double eval(const Poly& p, double t) {
  if (p.size <= kUnrolledSize) return kHorner[p.size](p.c.data(), t, p.size);
  return horner<-1>(p.c.data(), t, p.size);
}

Poly derivative(const Poly& p) {
  Poly d;
  for (int i = 1; i < p.size; ++i) d.c[i - 1] = double(i) * p.c[i];
  d.size = std::max(p.size - 1, 0);
  return d;
}

void trim(Poly& p) {
  while (p.size > 0 && p.c[p.size - 1] == 0.0) --p.size;
}

// (1 + t^2)^n F(2 atan t): with e^{i.theta} = (1 + it)^2 / (1 + t^2), each harmonic
// Re(F_j e^{ij.theta}) becomes Re(F_j (1 + it)^{2j}) (1 + t^2)^{n - j}.
// The coefficients of (1 + t^2)^k, lowest degree first (exact small integers).
using Binomials = std::array<std::array<double, kMaxPolyDegree + 1>, Trig::kMaxDegree + 1>;
constexpr Binomials binomials() {
  Binomials s{};
  s[0][0] = 1.0;
  for (int k = 1; k <= Trig::kMaxDegree; ++k)
    for (int i = 0; i <= 2 * k; ++i)
      s[k][i] = (i <= 2 * k - 2 ? s[k - 1][i] : 0.0) + (i >= 2 ? s[k - 1][i - 2] : 0.0);
  return s;
}
constexpr Binomials kBinomials = binomials();

// The coefficients of w_j = (1 + it)^{2j}, lowest degree first (exact small integers): built up
// two factors of (1 + it) at a time.
struct HalfAnglePowers {
  std::array<std::array<double, kMaxPolyDegree + 1>, Trig::kMaxDegree + 1> re{}, im{};
};
constexpr HalfAnglePowers half_angle_powers() {
  HalfAnglePowers w;
  std::array<double, kMaxPolyDegree + 1> re{}, im{};
  re[0] = 1.0;
  for (int j = 0; j <= Trig::kMaxDegree; ++j) {
    if (j > 0)
      for (int twice = 0; twice < 2; ++twice)
        for (int i = 2 * j; i > 0; --i) {  // w[i] += i w[i - 1]
          re[i] += 0.0 * re[i - 1] - 1.0 * im[i - 1];
          im[i] += 0.0 * im[i - 1] + 1.0 * re[i - 1];
        }
    w.re[j] = re;
    w.im[j] = im;
  }
  return w;
}
constexpr HalfAnglePowers kHalfAnglePowers = half_angle_powers();

Poly to_half_angle(const Trig& f) {
  const int n = f.degree();
  // s = (1 + t^2)^{n - j}. Each coefficient Re(F_j w_j[i]) is the real part of a complex
  // product, written out as the compiler does; w's zeros (whatever their sign) add nothing to
  // a nonzero one, and a zero one is skipped.
  const Binomials& s = kBinomials;
  const HalfAnglePowers& w = kHalfAnglePowers;
  Poly p;
  p.size = 2 * n + 1;
  for (int j = 0; j <= n; ++j) {
    const double fj_re = f.a[j], fj_im = -f.b[j];
    const auto& sj = s[n - j];
    for (int i = 0; i <= 2 * j; ++i) {
      const double c = fj_re * w.re[j][i] - fj_im * w.im[j][i];
      if (c == 0.0) continue;
      for (int k = 0; k <= 2 * (n - j); ++k) p.c[i + k] += c * sj[k];
    }
  }
  trim(p);
  return p;
}

// A root of p in [lo, hi] where p(lo) = flo and p(hi) have opposite signs: Newton steps kept
// inside the shrinking bracket, bisection when a step leaves it. Templated on p's size
// (horner2).
template <int N>
double refine_sized(const Poly& p, const Poly& dp, double lo, double hi, double flo) {
  double t = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const auto [ft, d] = horner2<N>(p.c.data(), dp.c.data(), t, p.size);
    if (ft == 0.0) return t;
    if ((ft < 0.0) == (flo < 0.0)) {
      lo = t;
      flo = ft;
    } else {
      hi = t;
    }
    double next = d != 0.0 ? t - ft / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == t || hi - lo <= 4.0 * std::numeric_limits<double>::epsilon()) return next;
    t = next;
  }
  return t;
}

template <int... N>
constexpr auto refine_table(std::integer_sequence<int, N...>) {
  return std::array<double (*)(const Poly&, const Poly&, double, double, double), sizeof...(N)>{
      &refine_sized<N>...};
}
constexpr auto kRefine = refine_table(std::make_integer_sequence<int, kUnrolledSize + 1>{});

double refine_bracketed(const Poly& p, const Poly& dp, double lo, double hi, double flo) {
  if (p.size <= kUnrolledSize) return kRefine[p.size](p, dp, lo, hi, flo);
  return refine_sized<-1>(p, dp, lo, hi, flo);
}

double evaluation_bound(const Poly& p, double t) {
  double v = 0.0;
  for (int i = p.size; i-- > 0;) v = v * std::fabs(t) + std::fabs(p.c[i]);
  return v;
}

// Real roots of p in [lo, hi]: the roots of p' split the interval into pieces where p is
// monotone, each holding at most one root; an extremum where p nearly vanishes is a double
// root that no sign change reveals. `touch` is relative to the evaluation bound over the
// chart (|t| <= 1), not at the extremum: at t = 0 that would be the constant term alone,
// which then never counts as nearly zero, and a double root at theta = 0 or pi (a designed
// alignment) that round-off leaves just short of zero was missed. The caller checks |f|
// against its own norm again after polishing.
void real_roots(const Poly& p, double lo, double hi, double touch, RootList& out,
                RootList* double_roots) {
  if (p.size <= 1) return;
  if (p.size == 2) {
    const double t = -p.c[0] / p.c[1];
    if (t >= lo && t <= hi) out.push(t);
    return;
  }
  const Poly dp = derivative(p);
  RootList turns;
  real_roots(dp, lo, hi, touch, turns, nullptr);
  std::sort(turns.t.begin(), turns.t.begin() + turns.count);
  turns.push(hi);
  double x0 = lo, f0 = eval(p, lo);
  if (f0 == 0.0) out.push(lo);
  for (int i = 0; i < turns.count; ++i) {
    const double x1 = turns.t[i], f1 = eval(p, x1);
    if (f1 == 0.0) {
      out.push(x1);
    } else if (f0 != 0.0 && (f0 < 0.0) != (f1 < 0.0)) {
      out.push(refine_bracketed(p, dp, x0, x1, f0));
    } else if (double_roots && i + 1 < turns.count &&
               std::fabs(f1) <= touch * evaluation_bound(p, 1.0)) {
      double_roots->push(x1);
    }
    x0 = x1;
    f0 = f1;
  }
}

// A harmonic this small relative to the largest coefficient is round-off left by a
// cancellation (a few units in the last place of the terms that cancelled).
constexpr double kCancelledHarmonic = 64.0 * std::numeric_limits<double>::epsilon();
// A harmonic this small relative to the identically-zero threshold moves no root that
// matters: products of rotating points make degree-6 triple equations whose top harmonics
// cancel (rotation invariance) down to round-off of the summed terms, far below it.
constexpr double kNegligibleOfZero = 1e-4;

// A polishing step longer than this (radians) means Newton has left the root it started at
// (the root found in t is far more accurate than that); the unpolished value is kept.
constexpr double kMaxPolishStep = 1e-3;

// Newton on f' from a near-double root: the extremum itself, which f' crosses simply.
double polish_extremum(const Trig& f, double theta) {
  const Trig d1 = f.derivative(), d2 = d1.derivative();
  const int n1 = d1.degree(), n2 = d2.degree();
  for (int it = 0; it < 8; ++it) {
    const double c1 = std::cos(theta), s1 = std::sin(theta);  // one pair for both
    const double s = evaluate_at(d2, n2, c1, s1);
    if (s == 0.0) break;
    const double step = evaluate_at(d1, n1, c1, s1) / s;
    if (!std::isfinite(step) || std::fabs(step) > kMaxPolishStep) break;
    theta -= step;
    if (std::fabs(step) <= std::numeric_limits<double>::epsilon()) break;
  }
  return theta;
}

// Newton on f from a simple root found in t; stops when a step stops shrinking.
double polish_root(const Trig& f, double theta) {
  const Trig d1 = f.derivative();
  const int n = f.degree(), n1 = d1.degree();
  double last = std::numeric_limits<double>::infinity();
  for (int it = 0; it < 6; ++it) {
    const double c1 = std::cos(theta), s1 = std::sin(theta);  // one pair for both
    const double s = evaluate_at(d1, n1, c1, s1);
    if (s == 0.0) break;
    const double step = evaluate_at(f, n, c1, s1) / s;
    if (!std::isfinite(step) || std::fabs(step) >= last || std::fabs(step) > kMaxPolishStep) break;
    theta -= step;
    last = std::fabs(step);
  }
  return theta;
}

// Amplitude of harmonic j (coefficients are far from overflow: no need for hypot).
double harmonic_size(const Trig& f, int j) {
  return std::sqrt(f.a[j] * f.a[j] + f.b[j] * f.b[j]);
}

// a0 + a1 cos + b1 sin = a0 + A cos(theta - phi): theta = phi +- acos(-a0 / A); a double
// root where |a0| = A to within `touch` above, or to within round-off below: f then dips
// across zero by no more than the round-off of its coefficients (kDoubleRootDepth of its
// norm), and which side the rounding fell must not decide between one root and two roots a
// few 1e-8 rad apart, each placed where a family designed to switch exactly at the double
// root may not exist yet (the cam's parallel edges gave two such roots in its file's units
// and one at other scales).
// Adds them to `r` (the caller's result, returned in place).
void first_harmonic_roots(const Trig& f, double touch, double merge_angle, TrigRoots& r) {
  const double amplitude = harmonic_size(f, 1), phase = std::atan2(f.b[1], f.a[1]);
  const double c = -f.a[0] / amplitude;
  if (std::fabs(c) > 1.0 + touch) return;
  const bool twofold = amplitude - std::fabs(f.a[0]) <= kDoubleRootDepth * f.norm();
  const double spread = twofold ? (c < 0.0 ? kPi : 0.0) : std::acos(std::clamp(c, -1.0, 1.0));
  double lo = wrap_angle(phase - spread), hi = wrap_angle(phase + spread);
  if (hi < lo) std::swap(lo, hi);
  r.roots.push_back(lo);
  if (!(hi - lo <= merge_angle || lo + kTwoPi - hi <= merge_angle)) r.roots.push_back(hi);
}

// The extremum of f between two neighbouring roots lo < hi, if it lies within
// kDoubleRootDepth of zero (n is f's norm): the two are then one double root that round-off
// pushed across (first_harmonic_roots gives the reason). The extremum itself may be one of
// the two (found as a double root), give or take the angle roots are told apart by.
std::optional<double> shallow_extremum(const Trig& f, double n, double lo, double hi,
                                       double merge_angle) {
  const double x = polish_extremum(f, 0.5 * (lo + hi));
  if (x < lo - merge_angle || x > hi + merge_angle || std::fabs(f(x)) > kDoubleRootDepth * n)
    return std::nullopt;
  return x;
}

// Neighbouring roots around a shallow extremum become that extremum. Only roots within
// kDoubleRootSpan of each other, which one critical orientation takes in anyway: an equation
// flat to round-off over a wider stretch (three curves nearly concurrent for a while) has
// roots that round-off places, but merging them would move a critical orientation, not just
// where it is validated.
void merge_shallow_crossings(const Trig& f, double n, double merge_angle, TrigRoots& r) {
  size_t kept = 0;
  for (size_t i = 0; i < r.roots.size(); ++i) {
    double theta = r.roots[i];
    if (i + 1 < r.roots.size() && r.roots[i + 1] - theta <= kDoubleRootSpan) {
      if (const auto x = shallow_extremum(f, n, theta, r.roots[i + 1], merge_angle)) {
        theta = *x;
        ++i;
      }
    }
    r.roots.begin()[kept++] = theta;
  }
  r.roots.resize(kept);
  // The same across theta = +-pi, where the sorted list wraps.
  if (kept < 2) return;
  const double lo = r.roots[kept - 1], hi = r.roots[0] + kTwoPi;
  if (hi - lo > kDoubleRootSpan) return;
  const auto x = shallow_extremum(f, n, lo, hi, merge_angle);
  if (!x) return;
  r.roots.begin()[0] = wrap_angle(*x);
  r.roots.resize(kept - 1);
  std::sort(r.roots.begin(), r.roots.end());
}

// The stretches of t = tan(phi / 2), |t| <= 1, that a chart searches: phi = theta for the
// first chart and theta - pi for the second.
struct ChartStretches {
  std::array<std::array<double, 2>, 2> t{};
  int count = 0;
};
constexpr ChartStretches kWholeChart{{{{-1.0, 1.0}}}, 1};

// The part of each window in the chart whose middle is at `centre` (0 or pi), as stretches
// of t, overlapping ones joined.
ChartStretches chart_stretches(double centre, const AngleWindow* windows, int count) {
  ChartStretches c;
  for (int w = 0; w < count; ++w) {
    if (windows[w].half >= 0.5 * kPi) return kWholeChart;
    // Within half a turn of the chart's middle; a window narrower than a quarter turn meets
    // the chart's half turn only there.
    const double mid = wrap_angle(windows[w].mid - centre);
    const double lo = mid - windows[w].half, hi = mid + windows[w].half;
    if (lo > 0.5 * kPi || hi < -0.5 * kPi) continue;
    // A window reaching the chart's border searches up to t = +-1 exactly (tan(pi / 4) rounds
    // below 1): a root on the border may be found on this chart only.
    c.t[c.count++] = {lo <= -0.5 * kPi ? -1.0 : std::tan(0.5 * lo),
                      hi >= 0.5 * kPi ? 1.0 : std::tan(0.5 * hi)};
  }
  if (c.count == 2 && c.t[1][0] < c.t[0][0]) std::swap(c.t[0], c.t[1]);
  if (c.count == 2 && c.t[1][0] <= c.t[0][1]) {
    c.t[0][1] = std::max(c.t[0][1], c.t[1][1]);
    c.count = 1;
  }
  return c;
}

// What solvable() reads of f before changing it: its norm, whether that is zero to the
// equation's accuracy, and the size below which a harmonic is cancellation residue (cos^2 +
// sin^2 in |P + R Q|^2 cancels down to round-off, and would raise the degree for nothing).
struct HarmonicScreen {
  double norm = 0.0, cancelled = 0.0;
  bool identically_zero = false;
};

HarmonicScreen screen_harmonics(const Trig& f, double zero_norm) {
  HarmonicScreen s;
  s.norm = f.norm();
  s.identically_zero = s.norm <= zero_norm;
  s.cancelled = std::max(kCancelledHarmonic * s.norm, kNegligibleOfZero * zero_norm);
  return s;
}

// No root when the constant term outweighs every kept harmonic together.
bool constant_outweighs(const Trig& f, double amplitude, double touch, double norm) {
  return std::fabs(f.a[0]) > amplitude * (1.0 + touch) + touch * norm;
}

// Drops f's cancellation residue in place; false when no root can exist.
bool solvable(Trig& f, double zero_norm, double touch, TrigRoots& r) {
  const HarmonicScreen s = screen_harmonics(f, zero_norm);
  if (s.identically_zero) {
    r.identically_zero = true;
    return false;
  }
  // Above f.top every harmonic is zero already.
  double amplitude = 0.0;
  for (int j = 1; j <= f.top; ++j) {
    const double size = harmonic_size(f, j);
    if (size <= s.cancelled)
      f.a[j] = f.b[j] = 0.0;
    else
      amplitude += size;
  }
  return !constant_outweighs(f, amplitude, touch, s.norm);
}

// Roots above degree 1: on two charts, each |t| <= 1, theta in [-pi/2, pi/2] directly and
// the rest half a turn away, each searched over its stretches.
void chart_roots(const Trig& f, double touch, double merge_angle,
                 const ChartStretches (&stretches)[2], TrigRoots& r) {
  const double n = f.norm();
  for (int chart = 0; chart < 2; ++chart) {
    if (stretches[chart].count == 0) continue;
    const Trig g = chart == 0 ? f : f.half_turned();
    const Poly p = to_half_angle(g);
    const double shift = chart == 0 ? 0.0 : kPi;
    for (int k = 0; k < stretches[chart].count; ++k) {
      RootList simple, twofold;
      real_roots(p, stretches[chart].t[k][0], stretches[chart].t[k][1], touch, simple, &twofold);
      for (int i = 0; i < simple.count; ++i)
        r.roots.push_back(wrap_angle(polish_root(f, 2.0 * std::atan(simple.t[i]) + shift)));
      for (int i = 0; i < twofold.count; ++i) {
        const double t = twofold.t[i];
        const double theta = wrap_angle(polish_extremum(f, 2.0 * std::atan(t) + shift));
        if (std::fabs(f(theta)) <= touch * n) r.roots.push_back(theta);
      }
    }
  }
  std::sort(r.roots.begin(), r.roots.end());
  // Chart borders (theta = +-pi/2) are found twice.
  const double* last = std::unique(r.roots.begin(), r.roots.end(),
                                   [&](double x, double y) { return y - x <= merge_angle; });
  r.roots.resize(size_t(last - r.roots.begin()));
  merge_shallow_crossings(f, n, merge_angle, r);
}

}  // namespace

TrigRoots trig_roots(const Trig& raw, double zero_norm, double touch, double merge_angle) {
  return trig_roots_within(raw, zero_norm, touch, merge_angle, nullptr, 0);
}

namespace {

// trig_roots_within for an equation of degree 1 or less (top <= 1: every pair equation), the
// same steps without copying it: solvable()'s tests on harmonics 0 and 1, then the closed form,
// or no root when the harmonic is dropped (the general path's polynomial is then a constant).
TrigRoots first_harmonic_only(const Trig& f, double zero_norm, double touch, double merge_angle) {
  TrigRoots r;
  const HarmonicScreen s = screen_harmonics(f, zero_norm);
  if (s.identically_zero) {
    r.identically_zero = true;
    return r;
  }
  const double size = f.top == 1 ? harmonic_size(f, 1) : 0.0;
  const bool kept = f.top == 1 && !(size <= s.cancelled);
  if (!kept || constant_outweighs(f, size, touch, s.norm)) return r;
  first_harmonic_roots(f, touch, merge_angle, r);
  return r;
}

}  // namespace

TrigRoots trig_roots_within(const Trig& raw, double zero_norm, double touch, double merge_angle,
                            const AngleWindow* windows, int window_count) {
  if (raw.top <= 1) return first_harmonic_only(raw, zero_norm, touch, merge_angle);
  TrigRoots r;
  Trig f = raw;
  if (!solvable(f, zero_norm, touch, r)) return r;
  if (f.degree() == 1) {
    first_harmonic_roots(f, touch, merge_angle, r);
    return r;  // every return names r, which is then built in place
  }
  const ChartStretches stretches[2] = {
      windows ? chart_stretches(0.0, windows, window_count) : kWholeChart,
      windows ? chart_stretches(kPi, windows, window_count) : kWholeChart};
  chart_roots(f, touch, merge_angle, stretches, r);
  return r;
}

}  // namespace cslice
