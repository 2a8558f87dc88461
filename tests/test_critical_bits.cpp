// The speed-ups of the critical orientations keep every bit: the unrolled products and sums of
// trigonometric polynomials against the plain loops they replace, evaluation with a shared
// sin/cos pair, and the placement test, which places the moving part lazily and starts from
// the edge that settled the last blocked query, against a fresh tester per query.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>

#include "criticals/trig.hpp"
#include "cslice/classify.hpp"
#include "support/random_parts.hpp"

using namespace cslice;

namespace {

bool same_bits(double x, double y) {
  return std::memcmp(&x, &y, sizeof(double)) == 0;
}

// Every coefficient up to the degree, signed zeros included.
bool bits_equal(const Trig& x, const Trig& y) {
  if (x.degree() != y.degree()) return false;
  for (int j = 0; j <= x.degree(); ++j)
    if (!same_bits(x.a[j], y.a[j]) || !same_bits(x.b[j], y.b[j])) return false;
  return true;
}

// The product as the plain loop computed it (std::complex arithmetic written out), before it
// was templated on the degrees.
Trig reference_product(const Trig& f, const Trig& g) {
  struct C {
    double re = 0.0, im = 0.0;
  };
  const auto times = [](C x, C y) -> C {
    return {x.re * y.re - x.im * y.im, x.re * y.im + x.im * y.re};
  };
  const auto half = [](C x) -> C { return {0.5 * x.re, 0.5 * x.im}; };
  const auto conj = [](C x) -> C { return {x.re, -x.im}; };
  const auto add = [](C& acc, C x) {
    acc.re += x.re;
    acc.im += x.im;
  };
  const int nf = f.degree(), ng = g.degree();
  std::array<C, Trig::kMaxDegree + 1> acc{};
  for (int j = 0; j <= nf; ++j) {
    const C u{f.a[j], -f.b[j]}, half_u = half(u);
    for (int k = 0; k <= ng; ++k) {
      const C v{g.a[k], -g.b[k]};
      add(acc[j + k], times(half_u, v));
      if (j - k >= 0)
        add(acc[j - k], times(half_u, conj(v)));
      else
        add(acc[k - j], half(conj(times(u, conj(v)))));
    }
  }
  Trig r;
  r.top = nf + ng;
  r.a[0] = acc[0].re;
  for (int j = 1; j <= r.top; ++j) {
    r.a[j] = acc[j].re;
    r.b[j] = -acc[j].im;
  }
  return r;
}

// Random coefficients, some of them signed zeros, with a tight top.
Trig random_trig(std::mt19937& rng, int degree) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> zero(0, 5);
  Trig t;
  for (int j = 0; j <= degree; ++j) {
    t.a[j] = zero(rng) == 0 ? -0.0 : u(rng);
    if (j > 0) t.b[j] = zero(rng) == 0 ? (zero(rng) % 2 ? 0.0 : -0.0) : u(rng);
  }
  t.a[degree] = u(rng);  // the degree is met
  t.top = degree;
  return t;
}

}  // namespace

TEST(TrigBits, ProductsKeepTheBitsOfThePlainLoop) {
  std::mt19937 rng(2026);
  for (int nf = 0; nf <= 4; ++nf)
    for (int ng = 0; ng + nf <= Trig::kMaxDegree; ++ng)
      for (int trial = 0; trial < 200; ++trial) {
        const Trig f = random_trig(rng, nf), g = random_trig(rng, ng);
        EXPECT_TRUE(bits_equal(f * g, reference_product(f, g)))
            << "degrees " << nf << " x " << ng << ", trial " << trial;
      }
}

TEST(TrigBits, RotatingPointsKeepTheBitsOfTheirSum) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  const double special[] = {0.0, -0.0, 1.5, -2.25};
  for (int trial = 0; trial < 400; ++trial) {
    auto pick = [&](int k) { return trial % 5 == k ? special[trial % 4] : u(rng); };
    const Vec2 p{pick(0), pick(1)}, q{pick(2), pick(3)};
    const TrigVec got = rotating_point(p, q);
    EXPECT_TRUE(bits_equal(got.x, Trig::constant(p.x) + Trig::harmonic(q.x, -q.y))) << trial;
    EXPECT_TRUE(bits_equal(got.y, Trig::constant(p.y) + Trig::harmonic(q.y, q.x))) << trial;
  }
}

TEST(TrigBits, OneSinCosPairEvaluatesLikeTheAngle) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-4.0, 4.0);
  for (int trial = 0; trial < 300; ++trial) {
    const Trig f = random_trig(rng, trial % 7);
    const double theta = angle(rng);
    EXPECT_TRUE(same_bits(f(TrigAngle(theta)), f(theta))) << trial;
    const TrigVec v{f, f.derivative()};
    const Vec2 a = evaluate(v, TrigAngle(theta)), b = evaluate(v, theta);
    EXPECT_TRUE(same_bits(a.x, b.x) && same_bits(a.y, b.y)) << trial;
  }
}

// One tester asked many poses in a row (stale placements, the edge that settled the last
// blocked pose tried first, classify after a blocked test that stopped early) answers as a
// fresh tester does for each pose alone.
TEST(PlacementBits, AReusedTesterAnswersLikeAFreshOne) {
  std::mt19937 rng(99);
  for (int p = 0; p < 12; ++p) {
    const Pair pair = testkit::random_pair(rng, 4 + p % 4, 5 + p % 5, p % 3 == 0).pair;
    std::uniform_real_distribution<double> x(pair.fixed.box.lo.x - 1.0, pair.fixed.box.hi.x + 1.0);
    std::uniform_real_distribution<double> y(pair.fixed.box.lo.y - 1.0, pair.fixed.box.hi.y + 1.0);
    std::uniform_real_distribution<double> turn(-kPi, kPi);
    std::vector<Pose> poses;
    for (int i = 0; i < 150; ++i) {
      const Pose pose{x(rng), y(rng), turn(rng)};
      poses.push_back(pose);
      // Nearby poses, as screening asks them.
      poses.push_back({pose.x + 1e-3, pose.y - 2e-3, pose.theta + 1e-3});
    }
    std::shuffle(poses.begin(), poses.end(), rng);
    PlacementTester reused(pair);
    for (size_t i = 0; i < poses.size(); ++i) {
      const Pose& pose = poses[i];
      PlacementTester fresh(pair);
      const Placement expected = fresh.classify(pose);
      switch (i % 3) {
        case 0:
          EXPECT_EQ(reused.blocked(pose), expected == Placement::blocked) << "pair " << p;
          break;
        case 1:
          EXPECT_EQ(reused.classify(pose), expected) << "pair " << p;
          break;
        default:
          EXPECT_EQ(reused.blocked(pose), expected == Placement::blocked) << "pair " << p;
          EXPECT_EQ(reused.boundary_distance(pose), PlacementTester(pair).boundary_distance(pose))
              << "pair " << p;
      }
    }
  }
}
