// The promise of the critical orientations (paper section 5): between two consecutive ones
// every slice is equivalent to the interval's representative, and every change that dense
// sampling finds across the circle has a reported critical orientation in its bracket. On
// the bundled examples and on 100 random pairs of curved parts. Extraneous orientations
// (reported, no change) are allowed and counted.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "support/completeness.hpp"
#include "support/designed_pairs.hpp"
#include "support/examples.hpp"
#include "support/random_parts.hpp"

using namespace cslice;

namespace {

void expect_complete(const Pair& pair, const std::string& name,
                     testkit::CompletenessReport* total = nullptr) {
  const CriticalSet set = critical_orientations(pair);
  const testkit::CompletenessReport r = testkit::check_completeness(pair, set);
  for (const std::string& f : r.interval_failures) ADD_FAILURE() << name << ": " << f;
  for (const std::string& m : r.missed) ADD_FAILURE() << name << ": " << m;
  if (!total) {
    std::printf("%-16s %4d orientations, %4d extraneous, %3d near-critical, %6lld slices\n",
                name.c_str(), r.orientations, r.extraneous, r.near_critical, r.slices);
    return;
  }
  total->orientations += r.orientations;
  total->extraneous += r.extraneous;
  total->near_critical += r.near_critical;
  total->slices += r.slices;
  total->interval_failures.insert(total->interval_failures.end(), r.interval_failures.begin(),
                                  r.interval_failures.end());
  total->missed.insert(total->missed.end(), r.missed.begin(), r.missed.end());
}

}  // namespace

TEST(CriticalCompleteness, BundledExamples) {
  for (const char* name : {"knee", "cam", "fixture", "fastener", "square-peg-hole", "disc-in-box",
                           "disc-half-plane", "pin-exact-fit"})
    expect_complete(testkit::load_example(name), name);
}

TEST(CriticalCompleteness, HundredRandomCurvedPairs) {
  testkit::CompletenessReport total;
  for (int i = 0; i < 100; ++i) {
    std::mt19937 rng(4000u + i);
    const int moving = 3 + i % 3, fixed = 4 + i % 4;
    const testkit::RandomPair p = testkit::random_pair(rng, moving, fixed, i % 3 == 0);
    expect_complete(p.pair, "random pair " + std::to_string(i), &total);
  }
  std::printf("100 random pairs: %d orientations, %d extraneous, %d near-critical, %lld slices\n",
              total.orientations, total.extraneous, total.near_critical, total.slices);
}

// Larger pairs (8 and 10 vertices per loop, holes in every third): denser arrangements with
// more near-coincident criticalities.
TEST(CriticalCompleteness, TenLargerRandomCurvedPairs) {
  testkit::CompletenessReport total;
  for (unsigned seed = 5010; seed < 5020; ++seed) {
    std::mt19937 rng(seed);
    const testkit::RandomPair p = testkit::random_pair(rng, 8, 10, (seed - 5000) % 3 == 0);
    expect_complete(p.pair, "larger pair " + std::to_string(seed), &total);
  }
  std::printf("10 larger pairs: %d orientations, %d extraneous, %d near-critical, %lld slices\n",
              total.orientations, total.extraneous, total.near_critical, total.slices);
}

// A stress run's pair where one group's criticalities spread over 2.6e-8 rad: a sample just
// before the group's middle but after its first criticality (a segment appearing) differed
// from its interval's representative. The interval runs between the groups' spans.
// Stress seed 141335: three contact curves (a line, a flat arc of radius 12 and an arc of
// radius 0.5) meet at one point at theta = -1.1845926, where a piece of the line comes onto
// the free boundary. The triple point taken from the line and the two circles' radical line,
// which cross at a shallow angle, lay 1e-5 off the small arc, and the triple was rejected:
// a change with no critical orientation. The crossings of each two curves themselves are
// candidates for the point now (src/criticals/events.cpp).
TEST(CriticalCompleteness, TriplePointWhereTheRadicalLineCrossesAtAShallowAngle) {
  expect_complete(testkit::stress_pair(141335).pair, "stress pair 141335");
}

TEST(CriticalCompleteness, SamplesInsideAGroupsSpanBelongToItsOrientation) {
  expect_complete(testkit::stress_pair(100223).pair, "stress pair 100223");
}

namespace {

// A regular k-gon of circumradius r about the origin, first vertex at angle `phase`, as a
// pair-file loop.
std::string regular_loop(int k, double r, double phase = 0.0, double dx = 0.0, double dy = 0.0) {
  std::ostringstream out;
  out.precision(17);
  out << "[";
  for (int i = 0; i < k; ++i) {
    const double a = phase + kTwoPi * i / k;
    out << (i ? "," : "") << "[" << dx + r * std::cos(a) << "," << dy + r * std::sin(a) << "]";
  }
  out << "]";
  return out.str();
}

Pair designed_pair(const std::string& name, const std::string& moving, const std::string& hole) {
  const std::string json = R"({"name":")" + name + R"(","moving":{"loops":[)" + moving +
                           R"(]},"fixed":{"loops":[[[-6,-6],[6,-6],[6,6],[-6,6]],)" + hole + "]}}";
  LoadResult r = parse_pair(json, name);
  if (!r.ok()) throw std::runtime_error(name + ": " + r.error->message());
  return std::move(*r.pair);
}

}  // namespace

// Designed, degenerate fits (from a stress run over 82 such pairs, all complete): contact at
// every orientation, tangency to every side at once, clearances of 1e-3 and 1e-4, identical
// polygons, a peg in a slot of its own width.
TEST(CriticalCompleteness, DesignedFits) {
  const double hexagon_inradius_one = 1.0 / std::cos(kPi / 6);
  const std::string rounded_peg =
      "[[-0.2,-1.5,0],[0.2,-1.5,0.41421356237309503],[0.5,-1.2,0],[0.5,1.2,0.41421356237309503],"
      "[0.2,1.5,0],[-0.2,1.5,0.41421356237309503],[-0.5,1.2,0],[-0.5,-1.2,0.41421356237309503]]";
  const Pair pairs[] = {
      designed_pair("triangle in a disc through its vertices", regular_loop(3, 1.0),
                    R"({"circle":[0,0,1]})"),
      designed_pair("disc touching every side of a hexagon", R"({"circle":[0,0,1]})",
                    regular_loop(6, hexagon_inradius_one)),
      designed_pair("square, clearance 1e-3", regular_loop(4, 1.0), regular_loop(4, 1.001)),
      designed_pair("octagon in an octagon turned half a tooth, 1e-4", regular_loop(8, 1.0),
                    regular_loop(8, 1.0001, kPi / 8)),
      designed_pair("pentagon in its own shape, origin off centre",
                    regular_loop(5, 1.0, 0.0, 0.1, 0.05), regular_loop(5, 1.0)),
      designed_pair("rounded peg in a slot of its width", rounded_peg,
                    "[[-0.5,-4],[0.5,-4],[0.5,4],[-0.5,4]]"),
  };
  for (const Pair& pair : pairs) expect_complete(pair, pair.name);
}

// The stress driver's designed pairs (tests/support/designed_pairs.cpp), six rounds of its six
// kinds, two of them turned by an arbitrary angle: parts on a unit grid in openings they fit
// exactly, polygons spinning in discs and in copies of themselves, pins in slots of their
// width (pair 33 lost its sliding fit to the containment test), combs interlocking.
// Designed pairs 9912 and 10740: an L-tromino in an opening of cells, turned, aligns exactly
// at a critical orientation; after it a free sliver grows like the cube of the turn and the
// slices show it as a perfect fit until it is wider than the epsilon, 1.8e-3 rad later. With
// finer epsilons that change moves towards the critical orientation (to 0.29e-3 rad at a
// hundredth), but the sliver's own tip is then a perfect fit on and off, and the bisection
// used to stop at one of those changes instead, at 54% of the way: reported missed. A change
// of the realizable labels is now followed as such.
TEST(CriticalCompleteness, SliverNarrowerThanTheEpsilonAfterAnExactAlignment) {
  for (unsigned seed : {9912u, 10740u}) {
    const Pair pair = testkit::designed_pair(seed).pair;
    const testkit::CompletenessReport r =
        testkit::check_completeness(pair, critical_orientations(pair));
    EXPECT_TRUE(r.missed.empty()) << seed << ": " << (r.missed.empty() ? "" : r.missed[0]);
    EXPECT_TRUE(r.interval_failures.empty()) << seed;
    EXPECT_GT(r.near_critical, 0) << seed;  // the sliver's change, seen and explained
  }
}

TEST(CriticalCompleteness, DesignedPairsOfEveryKind) {
  testkit::CompletenessReport total;
  for (unsigned seed = 0; seed < 36; ++seed)
    expect_complete(testkit::designed_pair(seed).pair, "designed pair " + std::to_string(seed),
                    &total);
  std::printf("36 designed pairs: %d orientations, %d extraneous, %d near-critical, %lld slices\n",
              total.orientations, total.extraneous, total.near_critical, total.slices);
}
