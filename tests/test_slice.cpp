// The slice against the direct placement test and against closed-form answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <sstream>
#include <thread>

#include "cslice/classify.hpp"
#include "cslice/critical.hpp"
#include "cslice/equivalence.hpp"
#include "cslice/slice.hpp"
#include "cslice/slice_io.hpp"
#include "slice/close_points.hpp"
#include "support/designed_pairs.hpp"
#include "support/examples.hpp"
#include "support/moved_examples.hpp"
#include "support/random_parts.hpp"
#include "support/random_polygons.hpp"
#include "support/slice_oracle.hpp"

using namespace cslice;

namespace {

using testkit::check_slice_against_classify;
using testkit::load_example;

struct SliceSummary {
  int bounded = 0, unbounded = 0, realizable = 0, degenerate = 0;
  double bounded_area = 0.0;
};

SliceSummary summary_of(const Slice& s) {
  SliceSummary out;
  for (const FreeComponent& c : s.free_components) {
    (c.bounded ? out.bounded : out.unbounded)++;
    if (c.bounded) out.bounded_area += c.area;
  }
  out.realizable = int(s.contact_graph.nodes.size());
  out.degenerate = int(s.degenerate.size());
  return out;
}

void expect_same_summary(const Slice& a, const Slice& b, const std::string& what) {
  const SliceSummary x = summary_of(a), y = summary_of(b);
  EXPECT_EQ(x.bounded, y.bounded) << what;
  EXPECT_EQ(x.unbounded, y.unbounded) << what;
  EXPECT_EQ(x.realizable, y.realizable) << what;
  EXPECT_EQ(x.degenerate, y.degenerate) << what;
  EXPECT_NEAR(x.bounded_area, y.bounded_area, 1e-9 * (1.0 + x.bounded_area)) << what;
}

double peg_side(double theta) {
  return 2.0 * (std::fabs(std::cos(theta)) + std::fabs(std::sin(theta)));
}

}  // namespace

TEST(SliceAnalytic, DiscInSquareBoxIsASquareOfSideTwiceSMinusR) {
  const Pair pair = load_example("disc-in-box");  // s = 3, r = 1
  for (double theta : {-3.0, -1.0, 0.0, 0.4, 2.2}) {
    const Slice s = compute_slice(pair, theta);
    ASSERT_EQ(s.free_components.size(), 1u);
    EXPECT_TRUE(s.free_components[0].bounded);
    EXPECT_NEAR(s.free_components[0].area, 16.0, 1e-9);
    EXPECT_EQ(s.contact_graph.nodes.size(), 4u);
  }
}

TEST(SliceAnalytic, SquarePegInSquareHole) {
  const Pair pair = load_example("square-peg-hole");  // peg side 2, hole side 3
  for (double theta : {0.0, 0.2, 0.5, 0.785, 1.3, 2.0, -2.9}) {
    const Slice s = compute_slice(pair, theta);
    const double side = 3.0 - peg_side(theta);
    int bounded = 0;
    for (const FreeComponent& c : s.free_components) {
      if (!c.bounded) continue;
      ++bounded;
      EXPECT_NEAR(c.area, side * side, 1e-9) << theta;
    }
    EXPECT_EQ(bounded, 1) << theta;
  }
}

TEST(SliceAnalytic, CamBacklashIsTheClearanceSquared) {
  const Pair pair = load_example("cam");  // breadth 10 in a 10.2 opening
  for (double theta = -3.1; theta < 3.14; theta += 0.37) {
    const Slice s = compute_slice(pair, theta);
    ASSERT_EQ(s.free_components.size(), 1u) << theta;
    EXPECT_NEAR(s.free_components[0].area, 0.04, 1e-9) << theta;
  }
}

TEST(SliceAnalytic, DiscAgainstABlockBlocksTheRoundedRectangle) {
  const Pair pair = load_example("disc-half-plane");  // r = 1, block 10 x 4
  for (double theta : {0.0, 1.0, -2.5}) {
    const Slice s = compute_slice(pair, theta);
    EXPECT_NEAR(s.blocked_area, 12.0 * 6.0 - (4.0 - kPi), 1e-9) << theta;
  }
  EXPECT_TRUE(std::isinf(compute_slice(load_example("disc-in-box"), 0.3).blocked_area));
}

TEST(SliceDegenerate, PinInHoleOfItsOwnRadiusLeavesAContactPoint) {
  const Pair pair = load_example("pin-exact-fit");
  const Slice s = compute_slice(pair, 0.7);
  ASSERT_EQ(s.degenerate.size(), 1u);
  EXPECT_TRUE(s.degenerate[0].is_point);
  EXPECT_EQ(classify(pair, {s.degenerate[0].curve.from.x, s.degenerate[0].curve.from.y, 0.7}),
            Placement::contact);
  for (const FreeComponent& c : s.free_components) EXPECT_FALSE(c.bounded);
}

TEST(SliceDegenerate, SquarePegInHoleOfItsOwnSizeLeavesAContactPoint) {
  const std::string json = R"({"name":"snug","moving":{"loops":[[[-1,-1],[1,-1],[1,1],[-1,1]]]},
    "fixed":{"loops":[[[-5,-5],[5,-5],[5,5],[-5,5]],[[-1,-1],[1,-1],[1,1],[-1,1]]]}})";
  const Pair pair = *parse_pair(json, "snug").pair;
  const Slice s = compute_slice(pair, 0.0);
  ASSERT_EQ(s.degenerate.size(), 1u);
  EXPECT_TRUE(s.degenerate[0].is_point);
  EXPECT_NEAR(length(s.degenerate[0].curve.from), 0.0, 1e-9);
}

TEST(SliceDegenerate, PegInSlotOfItsOwnWidthLeavesAContactCurve) {
  // A 2 x 2 peg in a slot 2 wide and 6 long: it slides along a line of length 4.
  const std::string json = R"({"name":"slot","moving":{"loops":[[[-1,-1],[1,-1],[1,1],[-1,1]]]},
    "fixed":{"loops":[[[-5,-5],[5,-5],[5,5],[-5,5]],[[-3,-1],[3,-1],[3,1],[-3,1]]]}})";
  const Pair pair = *parse_pair(json, "slot").pair;
  const Slice s = compute_slice(pair, 0.0);
  double length_total = 0.0;
  for (const DegenerateContact& d : s.degenerate)
    if (!d.is_point) length_total += curve_length(d.curve);
  EXPECT_NEAR(length_total, 4.0, 1e-9);
}

// A pin in a slot of exactly its width (designed stress pair 33: the slot turned by an
// arbitrary angle). At every orientation the pin slides along the slot's axis, touching both
// sides: a sliding fit one unit long, its two ends where the pin also meets the rounded ends,
// and every slice equivalent to every other. The placement test put the middle of the fit
// in blocked space at about half of the orientations (containment at the chord of a half
// circle), and those slices lost the fit.
TEST(SliceDegenerate, PinInATurnedSlotOfItsWidthSlidesAtEveryOrientation) {
  const std::string json =
      R"({"name":"designed-round-in-slot","moving":{"loops":[{"circle":[-0.25,0,0.5]}]},)"
      R"("fixed":{"enclosure":true,"loops":[[[0.68915349959494865,0.15832704758200727],)"
      R"([-0.15832704758200727,0.68915349959494865,1],[-0.68915349959494865,)"
      R"(-0.15832704758200727],[0.15832704758200727,-0.68915349959494865,1]]]}})";
  const Pair pair = *parse_pair(json, "pin-in-slot").pair;
  const Slice first = compute_slice(pair, 0.0);
  for (int k = 0; k < 48; ++k) {
    const double theta = -kPi + kTwoPi * k / 48 + 0.001 * k;
    const Slice s = compute_slice(pair, theta);
    double fit = 0.0;
    for (const DegenerateContact& d : s.degenerate)
      if (!d.is_point) fit += curve_length(d.curve);
    EXPECT_NEAR(fit, 1.0, 1e-9) << theta;
    EXPECT_TRUE(s.free_components.empty()) << theta;
    const EquivalenceResult e = slices_equivalent(first, s);
    EXPECT_TRUE(e.equivalent) << theta << ": " << e.difference;
  }
}

TEST(SliceDegenerate, TriangleInTriangularHoleOfItsOwnSize) {
  // Three contact lines through one point, each alone blocking a half plane.
  const std::string json = R"({"name":"tri","moving":{"loops":[[[0,0],[2,0],[1,1.5]]]},
    "fixed":{"loops":[[[-5,-5],[6,-5],[6,6],[-5,6]],[[0,0],[2,0],[1,1.5]]]}})";
  const Pair pair = *parse_pair(json, "tri").pair;
  const Slice s = compute_slice(pair, 0.0);
  ASSERT_EQ(s.degenerate.size(), 1u);
  EXPECT_TRUE(s.degenerate[0].is_point);
  EXPECT_NEAR(length(s.degenerate[0].curve.from), 0.0, 1e-9);
}

TEST(SliceDegenerate, ParallelEdgesSlidingGiveOverlappingContactSegments) {
  // A square resting in a wider square hole at theta 0: the peg's edges are parallel to the
  // hole's, so vertex/segment and segment/vertex contacts coincide along each wall.
  const Pair pair = load_example("square-peg-hole");
  const Slice s = compute_slice(pair, 0.0);
  int bounded = 0;
  for (const FreeComponent& c : s.free_components) {
    if (!c.bounded) continue;
    ++bounded;
    EXPECT_NEAR(c.area, 1.0, 1e-9);
    ASSERT_EQ(c.boundary.size(), 1u);
    EXPECT_EQ(c.boundary[0].size(), 4u);  // four walls, each one merged edge
  }
  EXPECT_EQ(bounded, 1);
}

TEST(SliceOracle, PaperExamplesAgreeWithClassify) {
  std::mt19937 rng(2026);
  for (const char* name :
       {"knee", "cam", "fixture", "fastener", "disc-half-plane", "square-peg-hole"}) {
    const Pair pair = load_example(name);
    int decisive = 0;
    for (double theta = -3.0; theta < 3.15; theta += 0.5)
      decisive += check_slice_against_classify(pair, theta, 400, rng, name);
    EXPECT_GT(decisive, 3000) << name;
  }
}

TEST(SliceOracle, RandomCurvedPairsAgreeWithClassify) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (int i = 0; i < 60; ++i) {
    const testkit::RandomPair rp = testkit::random_pair(rng, 5 + i % 6, 6 + i % 9, i % 3 == 0);
    for (int k = 0; k < 3; ++k)
      check_slice_against_classify(rp.pair, angle(rng), 300, rng, rp.json);
    if (HasFailure()) break;
  }
}

TEST(SliceOracle, JaggedStarsWithTinyFacesKeepTheirFreeSpace) {
  // 250-vertex jagged stars give thousands of contact segments and faces of area ~1e-13;
  // every cycle but a component's outer one must bound a face, however small.
  std::mt19937 rng(5);
  const testkit::RandomLoopOptions m{250, 1.0, 0.05, 0.5, 0.02, {0, 0}};
  const testkit::RandomLoopOptions f{250, 3.0, 0.05, 0.5, 0.02, {0, 0}};
  const std::string json = R"({"name":"jagged","moving":{"loops":[)" +
                           testkit::random_loop_json(rng, m) + R"(]},"fixed":{"loops":[)" +
                           testkit::random_loop_json(rng, f) + "]}}";
  const Pair pair = *parse_pair(json, "jagged").pair;
  const Slice s = compute_slice(pair, 0.3);
  ASSERT_EQ(s.free_components.size(), 1u);
  EXPECT_FALSE(s.free_components[0].bounded);
  std::mt19937 points(8);
  check_slice_against_classify(pair, 0.3, 300, points, "jagged");
}

TEST(SliceOracle, NearlyTangentArcsCrossingTwiceStayConsistent) {
  // 10,000 features in all, ~300,000 contact segments: arcs of equal-feature families
  // meet nearly tangentially and cross again 1e-4 away. The order of curves at each vertex
  // must follow the intersection step's verdict (tangent or crossing), or a lens between two
  // such crossings breaks and the unbounded free face leaks into blocked space.
  std::mt19937 rng(5);
  const testkit::RandomLoopOptions m{2500, 1.0, 0.0005, 0.5, 0.02, {0, 0}};
  const testkit::RandomLoopOptions f{2500, 3.0, 0.0005, 0.5, 0.02, {0, 0}};
  std::string json = R"({"name":"dense","moving":{"loops":[)";
  json += testkit::random_loop_json(rng, m);
  json += R"(]},"fixed":{"loops":[)";
  json += testkit::random_loop_json(rng, f);
  json += "]}}";
  const Pair pair = *parse_pair(json, "dense").pair;
  const Slice s = compute_slice(pair, 0.3);
  ASSERT_EQ(s.free_components.size(), 1u);
  EXPECT_FALSE(s.free_components[0].bounded);
}

// Random curved pairs at exact critical orientations, where the slices just either side have
// one unbounded free component and the critical slice used to have none:
// - a contact arc of a large radius (a nearly straight arc, or a concave and a convex arc of
//   nearly equal radii) shrinks to a sliver of normals narrower than the angular epsilon but
//   longer than eps; dropping it as a single touching direction opened the contact chain;
// - two contact segments leave a vertex-vertex contact at a shallow angle and one ends
//   within eps of the other, so snapping collapses the blocked sliver between them onto one
//   edge blocked from both sides by its own labels, which then marked the unbounded face
//   blocked.
TEST(SliceOracle, CriticalOrientationsKeepTheirFreeSpace) {
  struct Case {
    unsigned seed;
    int index;  // the pair drawn index-th from the seed, as below
    double theta;
  };
  // The critical orientations as critical_orientations finds them.
  for (const Case& c : {Case{1001u, 10, 2.3141730021220477}, Case{4242u, 20, 2.1720311310772127},
                        Case{5005u, 1, -0.75512693816575016}, Case{5005u, 3, 1.6208977385923342},
                        Case{4242u, 9, 1.6419650360976465}, Case{7u, 7, -0.72959428383543568}}) {
    std::mt19937 rng(c.seed);
    testkit::RandomPair rp;
    for (int i = 0; i <= c.index; ++i)
      rp = testkit::random_pair(rng, 4 + i % 4, 5 + i % 5, i % 2 == 0);
    const std::string what = "seed " + std::to_string(c.seed) + " pair " + std::to_string(c.index);
    const Slice s = compute_slice(rp.pair, c.theta);
    int unbounded = 0;
    for (const FreeComponent& comp : s.free_components) unbounded += comp.bounded ? 0 : 1;
    EXPECT_EQ(unbounded, 1) << what;
    std::mt19937 points(c.seed);
    EXPECT_GT(check_slice_against_classify(rp.pair, c.theta, 2000, points, what), 1000) << what;
    if (HasFailure()) return;
  }
}

// Designed pair 859: a 2 x 1 rectangle about a polyomino turned by an arbitrary angle. At the
// orientation where their edges turn parallel, 130 criticalities agree to 1e-15 rad and two
// grazing endpoint roots lie 1.5e-8 rad off. The slice at the group's middle, 7.5e-9 rad from
// the coincidence, had contact segments meant to end at one point ending 1.5e-8 apart (twice
// the geometric epsilon) and lost the unbounded free component, which an ordinary fixed
// part always has. The slice is taken at the group's median member now.
TEST(SliceOracle, ACriticalSliceAtACoincidenceKeepsItsUnboundedComponent) {
  const Pair pair = testkit::designed_pair(859).pair;
  const CriticalSet set = critical_orientations(pair);
  bool coincidence = false;
  for (const CriticalOrientation& o : set.orientations) {
    coincidence = coincidence || std::fabs(o.theta + 2.0705309552) < 1e-6;
    const Slice s = compute_slice(pair, o.theta);
    int unbounded = 0;
    for (const FreeComponent& c : s.free_components) unbounded += c.bounded ? 0 : 1;
    EXPECT_EQ(unbounded, 1) << o.theta;
  }
  EXPECT_TRUE(coincidence);
}

TEST(SliceInvariance, SymmetricFixturePartGivesTheSameSliceAHalfTurnLater) {
  // The fixture's part is symmetric under a half turn about its origin (paper 2.3: it also
  // engages upside down), so the slices at theta and theta + pi coincide.
  const Pair pair = load_example("fixture");
  for (double theta : {0.0, 0.3, 1.2, 2.0}) {
    const Slice a = compute_slice(pair, theta), b = compute_slice(pair, theta + kPi);
    expect_same_summary(a, b, "theta " + std::to_string(theta));
    EXPECT_NEAR(a.blocked_area, b.blocked_area, 1e-9 * a.blocked_area);
  }
}

// An orientation outside [-pi, pi) is the same placement as its wrapped angle, however far:
// the contact segments add theta to the features' normal angles, and at 1e9 rad those sums
// kept 1.2e-7 rad of them, a hundred times the angular tolerance; the fixture's slice there
// had no free space at all. Each far slice matches the one at the angle std::sin and
// std::cos reduce it to, and its samples are free by the direct test at the far angle.
TEST(SliceInvariance, AFarOrientationGivesTheSliceOfItsWrappedAngle) {
  for (const char* name : {"knee", "fixture", "fastener"}) {
    const Pair pair = load_example(name);
    PlacementTester tester(pair);
    for (double far : {4.0, -7.5, 1e9, -1e12, 1e15}) {
      const std::string what = std::string(name) + " at " + std::to_string(far);
      const double wrapped = std::atan2(std::sin(far), std::cos(far));
      const Slice s = compute_slice(pair, far);
      EXPECT_GE(s.theta, -kPi) << what;
      EXPECT_LT(s.theta, kPi) << what;
      EXPECT_NEAR(s.theta, wrapped, 1e-12) << what;
      expect_same_summary(s, compute_slice(pair, wrapped), what);
      EXPECT_FALSE(s.free_components.empty()) << what;
      for (const FreeComponent& c : s.free_components)
        EXPECT_EQ(tester.classify({c.sample.x, c.sample.y, far}), Placement::free) << what;
    }
  }
}

TEST(SliceInvariance, MovingTheWholeSceneKeepsEverySlice) {
  // Rotating both parts about the origin by phi rotates every slice by phi; translating both
  // (the moving part within its body frame) shifts it. Counts and areas are unchanged.
  for (const char* name : {"knee", "cam", "fixture", "fastener", "square-peg-hole"}) {
    const Pair pair = load_example(name);
    for (const auto& [phi, shift] :
         {std::pair<double, Vec2>{kPi, {0.0, 0.0}}, std::pair<double, Vec2>{0.7, {2.5, -1.25}}}) {
      const Pair moved = testkit::moved_example(name, 1.0, phi, shift);
      for (double theta : {0.0, 0.9}) {
        // The moving part's body frame turned by phi too: theta means the same placement.
        expect_same_summary(compute_slice(pair, theta), compute_slice(moved, theta),
                            std::string(name) + " rotated " + std::to_string(phi));
      }
    }
  }
}

// Smooth stars with half their edges arcs following the contour, 2,000 edges per part (the
// benchmark's curved pair). Neighbouring moving arcs joined by tiny reflex turns give contact
// curves that run within eps of each other for a long stretch: arcs whose lens is thinner
// than eps (called tangent), curves crossing at 1e-5 rad, curves ending within eps of
// another they have just crossed, parallel lines closer than 2 eps joined by a vertex. The
// order of pieces leaving such vertices must follow the intersection step's verdicts, or a
// blocked chain opens and the unbounded free face leaks into blocked space (it used to: the
// slice lost its only free component).
TEST(SliceOracle, CurvedStarsWithTinyReflexTurnsKeepTheirFreeSpace) {
  // Seeds whose slice leaked before, each through a different one of those cases.
  for (unsigned seed : {2026u, 2054u, 2116u, 2124u, 2129u}) {
    std::mt19937 rng(seed + 2000u);
    const testkit::StarPairLoops loops = testkit::lobed_star_pair(rng, 2000, 0.0, 0.5);
    LoadResult r =
        parse_pair(testkit::pair_json("curved", {loops.moving}, {loops.fixed}), "curved");
    ASSERT_TRUE(r.ok()) << seed;
    const std::string what = "curved stars, seed " + std::to_string(seed);
    const Slice s = compute_slice(*r.pair, 0.7);
    ASSERT_EQ(s.free_components.size(), 1u) << what;
    EXPECT_FALSE(s.free_components[0].bounded) << what;
    std::mt19937 points(seed);
    EXPECT_GT(check_slice_against_classify(*r.pair, 0.7, 100, points, what, seed == 2026u), 30)
        << what;
    if (HasFailure()) return;
  }
}

// Two contact arcs shorter than eps in a row, both shrinking away at a critical orientation:
// dropped, they left their neighbours' ends 1.4e-8 apart (eps 9.7e-9) and the slice there had
// no free component at all. Stress seeds (tests/stress) 100283 and 100289, at the critical
// orientations critical_orientations finds near these angles.
TEST(SliceOracle, ShortArcsInARowKeepTheBoundaryClosed) {
  for (auto [seed, near] : {std::pair{100283u, -2.3438159928}, std::pair{100289u, 0.2873553446}}) {
    const testkit::RandomPair rp = testkit::stress_pair(seed);
    const CriticalSet set = critical_orientations(rp.pair);
    double theta = near + 1.0;
    for (const CriticalOrientation& o : set.orientations)
      if (std::fabs(o.theta - near) < std::fabs(theta - near)) theta = o.theta;
    ASSERT_LT(std::fabs(theta - near), 1e-7) << seed;
    const Slice s = compute_slice(rp.pair, theta);
    int unbounded = 0;
    for (const FreeComponent& c : s.free_components) unbounded += c.bounded ? 0 : 1;
    EXPECT_EQ(unbounded, 1) << seed;
    std::mt19937 points(seed);
    EXPECT_GT(
        check_slice_against_classify(rp.pair, theta, 500, points, "seed " + std::to_string(seed)),
        200);
  }
}

// A Slicer keeps its working buffers from one slice to the next, and compute_slice keeps its
// thread's from one call to the next, whatever the pair; no slice may depend on the ones
// before it. Slices of different sizes in turn (every pair at one orientation, then the next
// orientation) must each match the slice of a Slicer made for it alone, field for field.
TEST(SliceReuse, ReusedBuffersGiveTheSlicesOfFreshOnes) {
  std::vector<Pair> pairs;
  for (const char* name : {"knee", "fixture", "cam"}) pairs.push_back(load_example(name));
  std::mt19937 rng(7);
  for (int i = 0; i < 4; ++i)
    pairs.push_back(testkit::random_pair(rng, 5 + i, 8 + 2 * i, i % 2 == 0).pair);
  std::vector<Slicer> slicers;
  for (const Pair& pair : pairs) slicers.emplace_back(pair);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (int k = 0; k < 12; ++k) {
    const double theta = k == 0 ? 0.0 : angle(rng);
    for (size_t p = 0; p < pairs.size(); ++p) {
      const Pair& pair = pairs[p];
      const std::string fresh = slice_to_json(pair, Slicer(pair).slice(theta));
      EXPECT_EQ(slice_to_json(pair, slicers[p].slice(theta)), fresh)
          << "pair " << p << ", theta " << theta << ": the pair's own Slicer";
      EXPECT_EQ(slice_to_json(pair, compute_slice(pair, theta)), fresh)
          << "pair " << p << ", theta " << theta << ": compute_slice";
    }
  }
}

// compute_slice's buffers are per thread: threads slicing different pairs at once, each in
// its own order, get the slices one thread gets alone.
TEST(SliceReuse, ThreadsSlicingAtOnceGetTheSameSlices) {
  std::vector<Pair> pairs;
  for (const char* name : {"knee", "fixture", "cam", "fastener"})
    pairs.push_back(load_example(name));
  const std::vector<double> thetas = {0.0, 0.7, -2.1, 1.9, 3.0};
  std::vector<std::string> alone;
  for (const Pair& pair : pairs)
    for (double theta : thetas) alone.push_back(slice_to_json(pair, compute_slice(pair, theta)));
  const size_t jobs = alone.size();
  constexpr int kThreads = 4;
  std::vector<std::vector<std::string>> got(kThreads, std::vector<std::string>(jobs));
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int round = 0; round < 3; ++round)
        for (size_t k = 0; k < jobs; ++k) {
          // A different order in each thread: shifted, and backwards in every other one.
          const size_t shifted = (k + size_t(7 * t)) % jobs;
          const size_t job = t % 2 ? jobs - 1 - shifted : shifted;
          const Pair& pair = pairs[job / thetas.size()];
          got[t][job] = slice_to_json(pair, compute_slice(pair, thetas[job % thetas.size()]));
        }
    });
  for (std::thread& th : threads) th.join();
  for (int t = 0; t < kThreads; ++t)
    for (size_t job = 0; job < jobs; ++job)
      EXPECT_TRUE(got[t][job] == alone[job])
          << "thread " << t << ": " << pairs[job / thetas.size()].name << " at theta "
          << thetas[job % thetas.size()] << " differs from the slice computed alone";
}

// ---- Clustering close points (the arrangement's vertices) --------------------------------

// The cell method against every pair, on dense random clusters (hundreds of points within eps,
// as at a perfect fit), points exactly eps apart, and scattered points: the same clusters.
TEST(ClosePoints, CellsUniteExactlyThePairsWithinEps) {
  std::mt19937 rng(99);
  const double eps = 1e-3;
  for (int round = 0; round < 40; ++round) {
    std::uniform_real_distribution<double> centre(-5.0, 5.0), jitter(-eps, eps);
    std::vector<Vec2> points;
    const int clusters = 1 + round % 7;
    for (int c = 0; c < clusters; ++c) {
      const Vec2 at{centre(rng), round % 2 ? 0.25 : centre(rng)};  // odd rounds: one row
      const int size = 1 + static_cast<int>(rng() % 300);
      for (int i = 0; i < size; ++i)
        points.push_back({at.x + jitter(rng) * (round % 3), at.y + jitter(rng) * (round % 3)});
      points.push_back({at.x + eps, at.y});  // exactly eps from the centre
      points.push_back({at.x, at.y - eps});
      points.push_back(at);
    }
    std::shuffle(points.begin(), points.end(), rng);
    const int n = static_cast<int>(points.size());
    std::vector<int> id(n);
    std::iota(id.begin(), id.end(), 0);
    UnionFind by_cells(n), by_pairs(n);
    CellScratch scratch;
    unite_close_by_cells(points, id, eps, by_cells, scratch);
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (distance(points[i], points[j]) <= eps) by_pairs.unite(i, j);
    int differ = 0;
    for (int i = 0; i < n; ++i) differ += by_cells.find(i) != by_pairs.find(i);
    EXPECT_EQ(differ, 0) << "round " << round << ", " << n << " points";
  }
}
