// Critical orientations: the trigonometric root finder, analytic cases with known critical
// sets, invariance under rotating either part, and the `cslice critical` command.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>

#include "criticals/families.hpp"
#include "criticals/trig.hpp"
#include "cslice/critical.hpp"
#include "cslice/space.hpp"
#include "support/cli_run.hpp"
#include "support/examples.hpp"
#include "support/moved_examples.hpp"
#include "support/random_parts.hpp"
#include "support/random_polygons.hpp"

using namespace cslice;

namespace {

constexpr double kRootAccuracy = 1e-10;

Trig random_trig(std::mt19937& rng, int degree) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Trig t;
  for (int j = 0; j <= degree; ++j) {
    t.a[j] = u(rng);
    if (j > 0) t.b[j] = u(rng);
  }
  return t;
}

std::vector<double> thetas(const CriticalSet& set) {
  std::vector<double> out;
  for (const CriticalOrientation& o : set.orientations) out.push_back(o.theta);
  return out;
}

// Angular distance on the circle.
double circle_gap(double a, double b) {
  return std::fabs(wrap_angle(a - b));
}

// Every value of `expected` matches one of `got` and back, each within `accuracy`.
void expect_same_angles(const std::vector<double>& got, const std::vector<double>& expected,
                        double accuracy) {
  ASSERT_EQ(got.size(), expected.size());
  for (double e : expected) {
    double best = kPi;
    for (double g : got) best = std::min(best, circle_gap(g, e));
    EXPECT_LE(best, accuracy) << "expected a critical orientation at " << e;
  }
}

Pair polygon_pair(const testkit::LoopVertices& moving, const testkit::LoopVertices& fixed) {
  return testkit::parse_or_throw(testkit::pair_json("analytic", {moving}, {fixed}), "analytic");
}

testkit::LoopVertices regular_polygon(int n, double r, Vec2 c, double phase) {
  testkit::LoopVertices v;
  for (int i = 0; i < n; ++i) {
    const Vec2 p = c + r * unit_vector(phase + kTwoPi * i / n);
    v.push_back({p.x, p.y, 0.0});
  }
  return v;
}

}  // namespace

// ---- Trigonometric polynomials ----------------------------------------------------------

TEST(Trig, ProductsAndDerivativesAgreeWithPointwiseValues) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const Trig f = random_trig(rng, 3), g = random_trig(rng, 4);
    const Trig fg = f * g, df = f.derivative(), h = f.half_turned();
    for (double theta : {-3.0, -1.1, 0.0, 0.4, 2.9}) {
      EXPECT_NEAR(fg(theta), f(theta) * g(theta), 1e-12);
      EXPECT_NEAR(h(theta), f(theta + kPi), 1e-12);
      const double step = 1e-6;
      EXPECT_NEAR(df(theta), (f(theta + step) - f(theta - step)) / (2 * step), 1e-7);
    }
  }
}

// The arithmetic runs only up to each operand's `top`; with the default top (kMaxDegree) it
// runs over every harmonic. Both must give the same bits up to the degree, where any root
// finding reads them.
TEST(Trig, ArithmeticUpToTopKeepsEveryBit) {
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> pick(0, 4);
  auto bits_equal = [](const Trig& x, const Trig& y) {
    if (x.degree() != y.degree()) return false;
    for (int j = 0; j <= x.degree(); ++j)
      if (std::memcmp(&x.a[j], &y.a[j], sizeof(double)) != 0 ||
          std::memcmp(&x.b[j], &y.b[j], sizeof(double)) != 0)
        return false;
    return true;
  };
  for (int trial = 0; trial < 2000; ++trial) {
    Trig f = random_trig(rng, pick(rng)), g = random_trig(rng, pick(rng));
    if (trial % 3 == 0) f.a[0] = -0.0;  // signed zeros must survive too
    if (trial % 5 == 0) g.b[1] = 0.0;
    Trig tf = f, tg = g;  // the same values, with tight tops
    tf.top = f.degree();
    tg.top = g.degree();
    EXPECT_TRUE(bits_equal(tf * tg, f * g)) << "trial " << trial;
    EXPECT_TRUE(bits_equal(tf + tg, f + g)) << "trial " << trial;
    EXPECT_TRUE(bits_equal(tf - tg, f - g)) << "trial " << trial;
    EXPECT_TRUE(bits_equal(0.3 * tf, 0.3 * f)) << "trial " << trial;
    EXPECT_TRUE(bits_equal(tf.derivative(), f.derivative())) << "trial " << trial;
    EXPECT_TRUE(bits_equal(tf.half_turned(), f.half_turned())) << "trial " << trial;
    EXPECT_LE((tf * tg).top, tf.top + tg.top);
  }
}

TEST(Trig, RotatingPointsTraceCircles) {
  const TrigVec p = rotating_point({1.0, 2.0}, {3.0, -1.0});
  for (double theta : {-2.0, 0.3, 1.7}) {
    const Vec2 expected = Vec2{1.0, 2.0} + Transform(Pose{0, 0, theta}).rotate({3.0, -1.0});
    const Vec2 got = evaluate(p, theta);
    EXPECT_NEAR(got.x, expected.x, 1e-14);
    EXPECT_NEAR(got.y, expected.y, 1e-14);
  }
}

// Roots against a brute-force scan: every sign change of a fine sampling holds a reported
// root, and every reported root is a zero.
TEST(Trig, RootsMatchABruteForceScan) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 300; ++trial) {
    const int degree = 1 + trial % 6;
    const Trig f = random_trig(rng, degree);
    const TrigRoots r = trig_roots(f, 1e-14, 1e-12, 1e-12);
    ASSERT_FALSE(r.identically_zero);
    for (double t : r.roots) {
      EXPECT_LE(std::fabs(f(t)), 1e-9) << "trial " << trial;
      EXPECT_GE(t, -kPi);
      EXPECT_LT(t, kPi);
    }
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const double a = -kPi + kTwoPi * i / n, b = -kPi + kTwoPi * (i + 1) / n;
      if ((f(a) < 0) == (f(b) < 0)) continue;
      bool found = false;
      for (double t : r.roots) found |= t >= a - 1e-9 && t <= b + 1e-9;
      for (double t : r.roots) found |= b >= kPi && t <= -kPi + 1e-9;
      EXPECT_TRUE(found) << "trial " << trial << ": sign change in [" << a << ", " << b << "]";
    }
  }
}

TEST(Trig, DoubleRootsAreFoundAndPolished) {
  // (cos theta - cos 0.7)^2 touches zero at +-0.7 without changing sign.
  const Trig c = Trig::harmonic(1.0, 0.0) - Trig::constant(std::cos(0.7));
  const TrigRoots r = trig_roots(c * c, 1e-14, 1e-9, 1e-12);
  ASSERT_EQ(r.roots.size(), 2u);
  EXPECT_NEAR(r.roots[0], -0.7, kRootAccuracy);
  EXPECT_NEAR(r.roots[1], 0.7, kRootAccuracy);
}

// A double root computed with round-off either way: the equation's extremum just short of
// zero (no root in exact terms), on it, or just across (two roots a few 1e-8 rad apart). The
// rounding must not decide between one root and two: designed parts put such roots exactly at
// the orientation where a contact segment starts, and only the extremum itself is there.
TEST(Trig, ADoubleRootIsOneRootWhicheverWayRoundOffFalls) {
  const double ulp = std::numeric_limits<double>::epsilon();
  for (double depth : {-4 * ulp, -ulp, 0.0, ulp, 4 * ulp}) {
    // First harmonic, closed form: cos(theta - 0.3) = 1 + depth.
    const Trig c = Trig::harmonic(std::cos(0.3), std::sin(0.3)) - Trig::constant(1.0 + depth);
    const TrigRoots r1 = trig_roots(c, 1e-14, 1e-9, 1e-9);
    ASSERT_EQ(r1.roots.size(), 1u) << depth;
    EXPECT_NEAR(r1.roots[0], 0.3, kRootAccuracy) << depth;
    // Second harmonic, searched in tan(theta / 2): cos(2 theta - 0.5) = 1 + depth, at 0.25
    // and 0.25 - pi.
    Trig c2 = Trig::constant(-(1.0 + depth));
    c2.top = 2;
    c2.a[2] = std::cos(0.5);
    c2.b[2] = std::sin(0.5);
    const TrigRoots r2 = trig_roots(c2, 1e-14, 1e-9, 1e-9);
    ASSERT_EQ(r2.roots.size(), 2u) << depth;
    EXPECT_NEAR(r2.roots[0], 0.25 - kPi, kRootAccuracy) << depth;
    EXPECT_NEAR(r2.roots[1], 0.25, kRootAccuracy) << depth;
    // The same at theta = 0 and pi, the middles of the two charts (t = 0, where a bound
    // taken at the extremum is the constant term alone) and where the sorted roots wrap.
    Trig c0 = Trig::constant(-(1.0 + depth));
    c0.top = 2;
    c0.a[2] = 1.0;
    const TrigRoots r0 = trig_roots(c0, 1e-14, 1e-9, 1e-9);
    ASSERT_EQ(r0.roots.size(), 2u) << depth;
    EXPECT_NEAR(std::fabs(r0.roots[0]), kPi, kRootAccuracy) << depth;
    EXPECT_NEAR(r0.roots[1], 0.0, kRootAccuracy) << depth;
  }
}

TEST(Trig, RootsAtTheChartBordersAndAtMinusPiAreReportedOnce) {
  // sin(theta) vanishes at -pi and 0; cos(theta) at +-pi/2, where the two charts meet.
  const TrigRoots s = trig_roots(Trig::harmonic(0.0, 1.0), 1e-14, 1e-12, 1e-12);
  ASSERT_EQ(s.roots.size(), 2u);
  EXPECT_NEAR(s.roots[0], -kPi, kRootAccuracy);
  EXPECT_NEAR(s.roots[1], 0.0, kRootAccuracy);
  const TrigRoots c = trig_roots(Trig::harmonic(1.0, 0.0), 1e-14, 1e-12, 1e-12);
  ASSERT_EQ(c.roots.size(), 2u);
  EXPECT_NEAR(c.roots[0], -kPi / 2, kRootAccuracy);
  EXPECT_NEAR(c.roots[1], kPi / 2, kRootAccuracy);
}

TEST(Trig, AnIdenticallyZeroConditionHasNoRoots) {
  // cos^2 + sin^2 - 1 cancels to round-off.
  const Trig c = Trig::harmonic(1.0, 0.0), s = Trig::harmonic(0.0, 1.0);
  const TrigRoots r = trig_roots(c * c + s * s - Trig::constant(1.0), 1e-12, 1e-12, 1e-12);
  EXPECT_TRUE(r.identically_zero);
  EXPECT_TRUE(r.roots.empty());
}

// ---- Analytic cases -----------------------------------------------------------------

// Two convex polygons: the free space is the outside of their Minkowski sum, whose edges
// follow the edge normals in angular order; it changes only where a rotated moving normal
// opposes a fixed one: theta = n_f - n_m - pi for every pair of edges.
TEST(CriticalAnalytic, ConvexPolygonsChangeOnlyWhereEdgeNormalsOppose) {
  const testkit::LoopVertices moving = regular_polygon(3, 1.0, {0.2, -0.1}, 0.3);
  const testkit::LoopVertices fixed = regular_polygon(5, 2.0, {0.0, 0.0}, 0.05);
  const Pair pair = polygon_pair(moving, fixed);
  std::vector<double> expected;
  auto normals = [](const testkit::LoopVertices& v) {
    std::vector<double> out;
    for (size_t i = 0; i < v.size(); ++i) {
      const auto& a = v[i];
      const auto& b = v[(i + 1) % v.size()];
      out.push_back(std::atan2(-(b.x - a.x), b.y - a.y));  // right of a counterclockwise edge
    }
    return out;
  };
  for (double nm : normals(moving))
    for (double nf : normals(fixed)) expected.push_back(wrap_angle(nf - nm - kPi));
  const CriticalSet set = critical_orientations(pair);
  expect_same_angles(thetas(set), expected, 1e-9);
  EXPECT_EQ(set.counts[int(CriticalCondition::tangent)], 0);
}

TEST(CriticalAnalytic, ASquarePegInASquareHoleChangesAtQuarterTurns) {
  const CriticalSet set = critical_orientations(testkit::load_example("square-peg-hole"));
  expect_same_angles(thetas(set), {-kPi, -kPi / 2, 0.0, kPi / 2}, 1e-12);
}

// A disc turning about any point of itself only translates its contact segments.
TEST(CriticalAnalytic, DiscsHaveNoCriticalOrientations) {
  for (const char* name : {"disc-in-box", "disc-half-plane", "pin-exact-fit"})
    EXPECT_TRUE(critical_orientations(testkit::load_example(name)).orientations.empty()) << name;
  const std::string eccentric = R"({"name": "eccentric",
    "moving": {"loops": [{"circle": [0.8, 0.3, 0.5]}]},
    "fixed": {"loops": [[[-3, -2], [4, -2], [2, 1], [-1, 3, 0.4]]]}})";
  const LoadResult r = parse_pair(eccentric, "eccentric");
  ASSERT_TRUE(r.ok()) << r.error->message();
  EXPECT_TRUE(critical_orientations(*r.pair).orientations.empty());
}

// Screening drops only criticalities in blocked space: everything it keeps, the unscreened
// run finds too.
TEST(CriticalAnalytic, ScreeningOnlyRemoves) {
  for (const char* name : {"knee", "cam", "fixture", "fastener"}) {
    const Pair pair = testkit::load_example(name);
    CriticalOptions all;
    all.screen_blocked = false;
    const CriticalSet screened = critical_orientations(pair),
                      unscreened = critical_orientations(pair, all);
    EXPECT_LE(screened.stats.criticalities, unscreened.stats.criticalities) << name;
    EXPECT_EQ(unscreened.stats.blocked, 0) << name;
    for (double t : thetas(screened)) {
      double best = kPi;
      for (double u : thetas(unscreened)) best = std::min(best, circle_gap(t, u));
      EXPECT_LE(best, pair.tol.critical_angle) << name << " at " << t;
    }
  }
}

// Turning the fixed part by alpha turns every slice, so the critical orientations shift by
// alpha; turning the moving part's body frame by beta shifts them by -beta.
TEST(CriticalInvariance, TurningEitherPartShiftsTheCriticalOrientations) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 6; ++trial) {
    const Pair pair = testkit::random_pair(rng, 5, 6, trial % 2 == 0).pair;
    const double alpha = 0.37 + trial, beta = -1.1 + 0.5 * trial;
    Pair turned_fixed = pair, turned_moving = pair;
    turned_fixed.fixed = placed(pair.fixed, {0.0, 0.0, alpha});
    turned_moving.moving = placed(pair.moving, {0.0, 0.0, beta});
    const std::vector<double> base = thetas(critical_orientations(pair));
    std::vector<double> shifted_fixed, shifted_moving;
    for (double t : base) {
      shifted_fixed.push_back(wrap_angle(t + alpha));
      shifted_moving.push_back(wrap_angle(t - beta));
    }
    // Round-off moves a group's middle by up to the grouping angle.
    const double accuracy = pair.tol.critical_angle;
    expect_same_angles(thetas(critical_orientations(turned_fixed)), shifted_fixed, accuracy);
    expect_same_angles(thetas(critical_orientations(turned_moving)), shifted_moving, accuracy);
  }
}

// The same pair drawn in micrometres or in metres: every tolerance scales with the pair's size,
// so the critical orientations are the same angles. Round-off differs with the scale, so this
// also checks that no decision rests on which way it falls where designed parts are exactly
// degenerate: the cam's double roots (parallel edges brought into line) gave 96
// criticalities in the file's units and 192 at every other scale before they were merged,
// and the knee's families listed a switch twice or once. (The fixture's and fastener's
// counts still differ by a few ill-conditioned triple points, at orientations they have
// anyway: docs/criticals.md, Stress runs.)
TEST(CriticalInvariance, ScalingThePairKeepsTheCriticalOrientations) {
  for (const char* name : {"knee", "cam", "fixture", "fastener"}) {
    const Pair pair = testkit::load_example(name);
    const CriticalSet base = critical_orientations(pair);
    for (double scale : {1e-3, 1e3}) {
      const CriticalSet scaled = critical_orientations(testkit::moved_example(name, scale, 0, {}));
      SCOPED_TRACE(std::string(name) + " scaled by " + std::to_string(scale));
      expect_same_angles(thetas(scaled), thetas(base), pair.tol.critical_angle);
      // The knee listed one segment end more drawn 1,000 times smaller (two switches of one
      // family that round-off made equal or not).
      if (std::string(name) == "cam" || std::string(name) == "knee") {
        for (int c = 0; c < kCriticalConditionCount; ++c)
          EXPECT_EQ(scaled.counts[c], base.counts[c]) << to_string(CriticalCondition(c));
      }
    }
  }
}

// A mirror turns every rotation the other way: the critical orientations of the mirrored pair
// are those of the pair, negated.
TEST(CriticalInvariance, MirroringThePairNegatesTheCriticalOrientations) {
  for (const char* name : {"knee", "cam", "fixture", "fastener"}) {
    const Pair pair = testkit::load_example(name);
    std::vector<double> negated;
    for (double t : thetas(critical_orientations(pair))) negated.push_back(wrap_angle(-t));
    SCOPED_TRACE(name);
    expect_same_angles(thetas(critical_orientations(testkit::mirrored_example(name))), negated,
                       pair.tol.critical_angle);
  }
}

TEST(CriticalExamples, CountsAreInThePapersRange) {
  // The paper's Figure 8: 125, 64, 155 and 118 criticalities. Ours count critical
  // orientations after grouping and screening; they must stay the same order of magnitude
  // (docs/performance.md lists both).
  for (const char* name : {"knee", "cam", "fixture", "fastener"}) {
    const CriticalSet set = critical_orientations(testkit::load_example(name));
    EXPECT_GE(set.orientations.size(), 4u) << name;
    EXPECT_LE(set.orientations.size(), 400u) << name;
    int total = 0;
    for (int c : set.counts) total += c;
    EXPECT_EQ(total, set.stats.criticalities) << name;
    for (size_t i = 1; i < set.orientations.size(); ++i)
      EXPECT_GT(set.orientations[i].theta - set.orientations[i - 1].theta,
                testkit::load_example(name).tol.critical_angle);
  }
}

// A triple point near the end of one of its three curves, and of that one only, is a
// critical orientation of its own. On this random curved pair (BM_CriticalCurved/50's) three
// contact arcs cross at a shallow angle 1.2e-5 rad after an endpoint event; their triple
// point lies within the criticality tolerance of one arc's end, 8.7e-6 away, and was taken
// for that endpoint event, though the realizable contact changes there.
TEST(CriticalCompleteness, ATriplePointNearOneCurvesEndIsItsOwnEvent) {
  const Pair pair = testkit::curved_star_pair(50);
  const double before = -1.2459946, after = -1.2459942;
  ASSERT_NE(realizable_labels(compute_slice(pair, before)),
            realizable_labels(compute_slice(pair, after)));
  const CriticalSet set = critical_orientations(pair);
  const bool reported = std::any_of(
      set.orientations.begin(), set.orientations.end(),
      [&](const CriticalOrientation& o) { return o.theta > before && o.theta < after; });
  EXPECT_TRUE(reported) << "no critical orientation where the realizable contact changes";
}

// The candidate culling rests on this (docs/criticals.md, "Candidates"): every contact segment
// of a family at theta within half_width of theta_b lies within drift * |theta - theta_b| of
// the family's cover at theta_b. Sampled on random curved pairs and on a lobed star with flat
// arcs of large radius, whose circle families use the moving-point drift.
TEST(CriticalCovers, HoldEveryContactSegmentWithinTheirDrift) {
  std::vector<Pair> pairs;
  for (unsigned seed = 7100; seed < 7106; ++seed) {
    std::mt19937 rng(seed);
    pairs.push_back(testkit::random_pair(rng, 4, 6, seed % 2 == 0).pair);
  }
  std::mt19937 rng(2026 + 12);
  const testkit::StarPairLoops star = testkit::lobed_star_pair(rng, 12, 0.1, 0.5);
  pairs.push_back(
      testkit::parse_or_throw(testkit::pair_json("star", {star.moving}, {star.fixed}), "star"));
  const double half_width = 0.05;
  int checked = 0;
  for (const Pair& pair : pairs) {
    const auto moving = contact_features(pair.moving), fixed = contact_features(pair.fixed);
    auto feature = [](const std::vector<ContactFeature>& fs, int index) {
      return *std::find_if(fs.begin(), fs.end(), [&](auto& f) { return f.feature == index; });
    };
    for (const ContactFamily& family : contact_families(pair)) {
      const ContactFeature m = feature(moving, family.moving), f = feature(fixed, family.fixed);
      for (int b = 0; b < 16; ++b) {
        const double mid = -kPi + (b + 0.5) * kTwoPi / 16;
        const FamilyCover cover = family_cover_within(family, mid, half_width);
        for (int k = -4; k <= 4; ++k) {
          const double theta = mid + half_width * k / 4;
          std::vector<ContactSegment> segments;
          add_pair_contacts(pair, m, f, theta, segments);
          for (const ContactSegment& s : segments)
            for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
              const Vec2 p = point_at(s.curve, t);
              EXPECT_LE(distance_to_curve(cover.curve, p),
                        cover.drift * std::fabs(theta - mid) + pair.tol.geometric)
                  << "family " << family.moving << "/" << family.fixed << " at " << theta;
              ++checked;
            }
        }
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(CriticalParallel, OneAndTwoThreadsGiveTheSameSet) {
  std::vector<Pair> pairs;
  for (const char* name : {"knee", "fixture", "fastener"})
    pairs.push_back(testkit::load_example(name));
  std::mt19937 rng(77);
  const testkit::StarPairLoops star = testkit::lobed_star_pair(rng, 12, 0.1, 0.5);
  pairs.push_back(
      testkit::parse_or_throw(testkit::pair_json("star", {star.moving}, {star.fixed}), "star"));
  for (const Pair& pair : pairs) {
    CriticalOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const CriticalSet a = critical_orientations(pair, one), b = critical_orientations(pair, two);
    EXPECT_EQ(critical_set_to_json(pair, a), critical_set_to_json(pair, b)) << pair.name;
    EXPECT_EQ(a.stats.equations, b.stats.equations) << pair.name;
    EXPECT_EQ(a.stats.culled, b.stats.culled) << pair.name;
    EXPECT_EQ(a.stats.blocked, b.stats.blocked) << pair.name;
  }
}

// ---- The command ----------------------------------------------------------------------

class CriticalCli : public testkit::ScratchDirTest {
 protected:
  CriticalCli() : ScratchDirTest("cslice_critical") {}
};

TEST_F(CriticalCli, WritesSortedJsonWithCounts) {
  const std::string out = (dir_ / "cam.json").string();
  const testkit::RunResult r =
      testkit::run_cli("critical " + testkit::quoted(testkit::example_path("cam")) + " --json " +
                           testkit::quoted(out),
                       dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(testkit::read_file(out));
  ASSERT_TRUE(j.contains("critical"));
  ASSERT_TRUE(j.contains("counts"));
  double last = -kPi - 1.0;
  int total = 0;
  for (const auto& c : j["critical"]) {
    EXPECT_GT(c["theta"].get<double>(), last);
    last = c["theta"].get<double>();
    EXPECT_TRUE(c.contains("condition"));
    EXPECT_FALSE(c["features"].empty());
    total += int(c["criticalities"].size());
  }
  EXPECT_EQ(j["counts"]["criticalities"].get<int>(), total);
  EXPECT_EQ(j["counts"]["orientations"].get<size_t>(), j["critical"].size());
}

TEST_F(CriticalCli, PrintsATableWithASummary) {
  const testkit::RunResult r = testkit::run_cli(
      "critical " + testkit::quoted(testkit::example_path("square-peg-hole")), dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("critical orientations 4"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("segment_end"), std::string::npos);
}

TEST_F(CriticalCli, BadInputExitsTwoWithNoOutput) {
  testkit::write_file(dir_ / "bad.json", "{\"name\": 3");
  const std::string out = (dir_ / "out.json").string();
  const testkit::RunResult r =
      testkit::run_cli("critical " + testkit::quoted((dir_ / "bad.json").string()) + " --json " +
                           testkit::quoted(out),
                       dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}
