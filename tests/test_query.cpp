// Point queries from the computed space (SpaceQuery, `cslice query`) against the direct
// placement test: on the paper's examples and random curved pairs, random configurations
// outside the contact tolerance band get the answer `classify` gives, points on realizable
// contact are contact, and free answers carry the topology's 3D component ids.
#include "cslice/query.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "cslice/classify.hpp"
#include "cslice/space.hpp"
#include "support/band.hpp"
#include "support/cli_run.hpp"
#include "support/designed_pairs.hpp"
#include "support/examples.hpp"
#include "support/moved_examples.hpp"
#include "support/random_parts.hpp"
#include "support/spaces.hpp"

using namespace cslice;
using testkit::deep_blocked;
using testkit::near_realizable;
using testkit::query_box;
using testkit::space_of;

namespace {

void expect_agrees_with_classify(const Pair& pair, const SlicedSpace& space, int queries,
                                 unsigned seed, const std::string& name) {
  SpaceQuery q(pair, space);
  const testkit::QueryAgreement r =
      testkit::compare_queries_with_classify(pair, space, q, queries, seed, name);
  EXPECT_EQ(r.mismatches, 0) << name;
  EXPECT_GT(r.checked, queries / 8) << name;
  const QueryStats& st = q.stats();
  if (st.exact_intervals > 0) {  // both ways of answering from the model were checked
    EXPECT_GT(st.far_from_contact, 0u) << name;
    EXPECT_GT(st.evaluated, st.far_from_contact) << name;
  }
  std::cout << name << ": " << r.checked << " checked (" << r.free_count << " free, "
            << r.blocked_count << " blocked); " << st.evaluated << " evaluated ("
            << st.far_from_contact << " far from contact), " << st.fallback << " fallback, "
            << st.at_stored_slice << " at critical slices; " << st.exact_intervals << "/"
            << st.intervals << " intervals exact\n";
}

// Points on realizable pieces of the stored non-critical slices are contact, by both.
void expect_contact_on_pieces(const Pair& pair, const SlicedSpace& space, const std::string& name) {
  SpaceQuery q(pair, space);
  PlacementTester tester(pair);
  int checked = 0;
  for (const SpaceSlice& s : space.slices) {
    if (s.kind == SliceKind::critical) continue;
    for (const ContactPiece& piece : s.slice.realizable) {
      const Vec2 p = point_at(piece.curve, 0.5);
      const Pose pose{p.x, p.y, s.theta};
      if (tester.classify(pose) != Placement::contact) continue;
      const QueryAnswer a = q.query(pose);
      EXPECT_EQ(a.placement, Placement::contact) << name << " at theta " << s.theta;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0) << name;
}

// Component ids: each stored slice's component samples get the topology's ids, and random
// points of one slice component at a fresh theta share one id.
void expect_component_ids(const Pair& pair, const SlicedSpace& space, unsigned seed,
                          const std::string& name) {
  SpaceQuery q(pair, space);
  for (size_t s = 0; s < space.slices.size(); ++s) {
    if (space.slices[s].kind == SliceKind::critical) continue;
    for (const FreeComponent& c : space.slices[s].slice.free_components) {
      const QueryAnswer a = q.query({c.sample.x, c.sample.y, space.slices[s].theta});
      if (a.placement != Placement::free) continue;  // a sliver's sample within the band
      EXPECT_EQ(a.component, space.topology.slice_components[s][c.id])
          << name << " slice " << s << " component " << c.id;
    }
  }
  std::mt19937 rng(seed);
  const Box box = query_box(space);
  std::uniform_real_distribution<double> ux(box.lo.x, box.hi.x), uy(box.lo.y, box.hi.y),
      ut(-kPi, kPi);
  for (int t = 0; t < 6; ++t) {
    const double theta = ut(rng);
    const Slice slice = compute_slice(pair, theta);
    std::vector<int> id_of(slice.free_components.size(), -2);
    for (int i = 0; i < 300; ++i) {
      const Vec2 p{ux(rng), uy(rng)};
      const int c = slice.locate(p);
      if (c < 0) continue;
      const QueryAnswer a = q.query({p.x, p.y, theta});
      if (a.placement != Placement::free) continue;
      if (id_of[c] == -2) id_of[c] = a.component;
      EXPECT_EQ(a.component, id_of[c]) << name << " theta " << theta << " component " << c;
    }
  }
}

}  // namespace

TEST(SpaceQuery, PaperExamplesAgreeWithClassify) {
  for (const char* name : {"cam", "fastener", "fixture", "knee"}) {
    const Pair pair = testkit::load_example(name);
    const SlicedSpace space = space_of(pair);
    expect_agrees_with_classify(pair, space, 4000, 17, name);
    expect_contact_on_pieces(pair, space, name);
    expect_component_ids(pair, space, 5, name);
  }
}

TEST(SpaceQuery, RandomCurvedPairsAgreeWithClassify) {
  std::mt19937 rng(2024);
  for (int i = 0; i < 4; ++i) {
    const testkit::RandomPair rp = testkit::random_pair(rng, 4 + i % 3, 5 + i % 4, i % 2 == 0);
    const SlicedSpace space = space_of(rp.pair);
    const std::string name = "random pair " + std::to_string(i);
    expect_agrees_with_classify(rp.pair, space, 2000, 100 + i, name);
    expect_component_ids(rp.pair, space, 200 + i, name);
  }
}

// A far orientation is answered at the orientation classify places it at: the query wraps
// theta by the true turn (at 1e15 rad, the double nearest 2pi put it 0.04 rad away).
TEST(SpaceQuery, AFarOrientationIsAnsweredAtItsTrueWrappedAngle) {
  const Pair pair = testkit::load_example("knee");
  const SlicedSpace space = space_of(pair);
  SpaceQuery q(pair, space);
  std::mt19937 rng(31);
  const Box box = query_box(space);
  std::uniform_real_distribution<double> ux(box.lo.x, box.hi.x), uy(box.lo.y, box.hi.y);
  int differing = 0;
  for (double far : {1e15, -3e13}) {
    const double wrapped = std::atan2(std::sin(far), std::cos(far));
    for (int i = 0; i < 2000; ++i) {
      const double x = ux(rng), y = uy(rng);
      const QueryAnswer a = q.query({x, y, far}), b = q.query({x, y, wrapped});
      if (a.placement != b.placement || a.component != b.component) ++differing;
    }
  }
  EXPECT_EQ(differing, 0);
}

// The tip of a thin free pocket (stress seed 100050): a configuration 0.0078 from the
// pocket's corner, within the contact tolerance 0.0086, is blocked by classify and stays
// blocked 2 tolerances away in all eight probe directions; the query's contact answer is
// right, as a realizable piece of the slice there passes within the tolerance.
TEST(SpaceQuery, ContactAtTheTipOfAThinPocketIsWithinTheBand) {
  const testkit::RandomPair rp = testkit::stress_pair(100050);
  const SlicedSpace space = space_of(rp.pair);
  SpaceQuery q(rp.pair, space);
  PlacementTester tester(rp.pair);
  const Pose pose{-0.045802104942899005, -0.1342124899868315, -1.4667158734858445};
  EXPECT_EQ(q.query(pose).placement, Placement::contact);
  EXPECT_EQ(tester.classify(pose), Placement::blocked);
  EXPECT_TRUE(deep_blocked(tester, pose, 2.0 * rp.pair.tol.contact));
  EXPECT_TRUE(near_realizable(rp.pair, pose, rp.pair.tol.contact));
}

// Designed pair 1068 fits exactly at theta = pi only. A configuration 9.2e-7 rad from it
// (within the critical angle) is answered from the critical slice: contact. Classify finds an
// overlap of 1e-6 that no translation undoes and no piece of the slice at its own theta is
// near; turned by 9.2e-7 rad it touches, a distance far inside the contact tolerance. The
// oracle now accepts contact from the critical slice there.
TEST(SpaceQuery, ContactWithinTheCriticalAngleOfAnExactFitIsWithinTheBand) {
  const Pair pair = testkit::designed_pair(1068).pair;
  const SlicedSpace space = space_of(pair);
  SpaceQuery q(pair, space);
  PlacementTester tester(pair);
  const Pose pose{0.99634524115430234, 2.1363582928913596, -3.1415935742800474};
  const double band = 2.0 * pair.tol.contact;
  EXPECT_EQ(q.query(pose).placement, Placement::contact);
  EXPECT_EQ(tester.classify(pose), Placement::blocked);
  EXPECT_TRUE(deep_blocked(tester, pose, band));
  EXPECT_FALSE(near_realizable(pair, pose, 0.75 * band));
  EXPECT_TRUE(testkit::near_realizable_at_critical(pair, space, pose, 0.75 * band));
  // The stress run's 600 queries (no free space here but the fit: all of them blocked).
  SpaceQuery fresh(pair, space);
  EXPECT_EQ(testkit::compare_queries_with_classify(pair, space, fresh, 600, 1068, "designed-1068")
                .mismatches,
            0);
}

// Designed pair 6008: a regular octagon turning in the circle through its corners fits it at
// every orientation, and nowhere else: no free space, no critical orientation, a perfect fit
// (a degenerate point) in every slice. A configuration 0.0043 from it, within the contact
// tolerance 0.0057, is blocked by classify whichever way it moves; the query's contact is
// right, and the oracle counts perfect fits as contact now.
TEST(SpaceQuery, ContactNearAPerfectFitIsWithinTheBand) {
  const Pair pair = testkit::designed_pair(6008).pair;
  const SlicedSpace space = space_of(pair);
  EXPECT_TRUE(space.criticals.orientations.empty());
  SpaceQuery q(pair, space);
  PlacementTester tester(pair);
  const Pose pose{0.60390912798529151, -0.79625933250252223, -0.92625322032939472};
  const double band = 2.0 * pair.tol.contact;
  EXPECT_EQ(q.query(pose).placement, Placement::contact);
  EXPECT_EQ(tester.classify(pose), Placement::blocked);
  EXPECT_TRUE(deep_blocked(tester, pose, band));
  EXPECT_TRUE(near_realizable(pair, pose, 0.75 * band));
  SpaceQuery fresh(pair, space);
  EXPECT_EQ(testkit::compare_queries_with_classify(pair, space, fresh, 600, 6008, "designed-6008")
                .mismatches,
            0);
}

// Designed pair 255, a disc of diameter 1 turning about a point off its centre in an L-shaped
// slot 1 wide, with the slot drawn 30 mm out: the tolerances grow with that distance, so do the
// steps between stored slices (pi / 3 here, no critical orientation). The small free region
// moves further than its own width from one stored slice to the next, so a query between them
// (answered from a slice computed at its theta) finds its component's sample in none of them;
// the region's boundary labels name it there. It used to be answered free with no 3D
// component (-1).
TEST(SpaceQuery, AComponentThatMovedFurtherThanItsWidthIsNamedByItsLabels) {
  const testkit::RandomPair designed = testkit::designed_pair(255);
  const Pair pair = testkit::moved_pair(designed.json, "designed-255", 1, 0, {}, {30, -15});
  const SlicedSpace space = space_of(pair);
  ASSERT_TRUE(space.criticals.orientations.empty());
  ASSERT_EQ(space.topology.components.size(), 1u);
  SpaceQuery q(pair, space);
  PlacementTester tester(pair);
  for (const Pose& pose : {Pose{30.591938386, -13.378634277, 1.430701513},
                           Pose{30.588483501, -13.435712441, 1.429461348},
                           Pose{30.318293096, -13.742740562, -2.719079958}}) {
    EXPECT_EQ(tester.classify(pose), Placement::free);
    const QueryAnswer a = q.query(pose);
    EXPECT_EQ(a.placement, Placement::free);
    EXPECT_EQ(a.component, 0);
  }
}

class QueryCli : public testkit::ScratchDirTest {
 protected:
  QueryCli() : testkit::ScratchDirTest("cslice_query") {}
  std::string compute_cam() {
    const std::string space = (dir_ / "cam-space.json").string();
    const testkit::RunResult r =
        testkit::run_cli("compute " + testkit::quoted(testkit::example_path("cam")) + " -o " +
                             testkit::quoted(space),
                         dir_);
    EXPECT_EQ(r.status, 0) << r.err;
    return space;
  }
};

TEST_F(QueryCli, AnswersEachLine) {
  const std::string space = compute_cam();
  const testkit::RunResult r = testkit::run_cli("query " + testkit::quoted(space), dir_,
                                                "# comment\n0.885 -1.25 0.3\n\n100,100,0\n0 0 0\n");
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream lines(r.out);
  std::vector<std::string> words;
  std::string line;
  while (std::getline(lines, line)) words.push_back(line.substr(0, line.find(' ')));
  ASSERT_EQ(words.size(), 3u) << r.out;
  for (const std::string& w : words)
    EXPECT_TRUE(w == "free" || w == "contact" || w == "blocked") << r.out;

  // The same answers as the library.
  const Pair pair = testkit::load_example("cam");
  const SlicedSpace sp = space_of(pair);
  SpaceQuery q(pair, sp);
  EXPECT_EQ(words[0], std::string(to_string(q.query({0.885, -1.25, 0.3}).placement)));
  EXPECT_EQ(words[2], std::string(to_string(q.query({0, 0, 0}).placement)));
}

TEST_F(QueryCli, BadLineIsExit2NamingItAndPrintsNothing) {
  const std::string space = compute_cam();
  const testkit::RunResult r =
      testkit::run_cli("query " + testkit::quoted(space), dir_, "0 0 0\n1 2\n3 4 5\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("line 2"), std::string::npos) << r.err;
  const testkit::RunResult nan =
      testkit::run_cli("query " + testkit::quoted(space), dir_, "0 0 0\n\n0 0 nan\n");
  EXPECT_EQ(nan.status, 2);
  EXPECT_TRUE(nan.out.empty());
  EXPECT_NE(nan.err.find("line 3"), std::string::npos) << nan.err;
}

TEST_F(QueryCli, BadSpaceFileIsExit2) {
  testkit::write_file(dir_ / "bad.json", "{\"format\": \"cslice-space\"");
  const testkit::RunResult r =
      testkit::run_cli("query " + testkit::quoted((dir_ / "bad.json").string()), dir_, "0 0 0\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
  const testkit::RunResult missing =
      testkit::run_cli("query " + testkit::quoted((dir_ / "none.json").string()), dir_, "");
  EXPECT_EQ(missing.status, 2);
}
