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
#include "support/cli_run.hpp"
#include "support/examples.hpp"
#include "support/random_parts.hpp"
#include "support/spaces.hpp"

using namespace cslice;
using testkit::space_of;

namespace {

// Where configurations are drawn: every contact curve of the stored slices, with a margin.
Box query_box(const SlicedSpace& space) {
  Box box;
  for (const SpaceSlice& s : space.slices)
    for (const ContactSegment& c : s.slice.contact_segments) box.add(bounding_box(c.curve));
  const double margin = 0.1 * box.diagonal();
  return box.inflated(margin);
}

bool deep_blocked(PlacementTester& tester, const Pose& pose, double d) {
  for (int k = 0; k < 8; ++k) {
    const Vec2 u = unit_vector(k * kPi / 4);
    if (!tester.blocked({pose.x + d * u.x, pose.y + d * u.y, pose.theta})) return false;
  }
  return true;
}

// Whether a realizable piece of the slice at the pose's theta passes within `d` of it: the
// eight probes of deep_blocked miss the tip of a free wedge narrower than their spacing
// (stress seeds 100050, 100158, 100206: blocked in all eight directions, yet 0.0078 from the
// tip of a thin pocket, with a contact tolerance of 0.0086).
bool near_realizable(const Pair& pair, const Pose& pose, double d) {
  const Slice slice = compute_slice(pair, pose.theta);
  return std::any_of(slice.realizable.begin(), slice.realizable.end(), [&](const ContactPiece& p) {
    return distance_to_curve(p.curve, {pose.x, pose.y}) <= d;
  });
}

void expect_agrees_with_classify(const Pair& pair, const SlicedSpace& space, int queries,
                                 unsigned seed, const std::string& name) {
  SpaceQuery q(pair, space);
  PlacementTester tester(pair);
  std::mt19937 rng(seed);
  const Box box = query_box(space);
  std::uniform_real_distribution<double> ux(box.lo.x, box.hi.x), uy(box.lo.y, box.hi.y),
      ut(-kPi, kPi);
  int checked = 0, free_count = 0, blocked_count = 0, mismatches = 0;
  // Half the queries anywhere in the box, half near realizable contact of a stored slice (a
  // random point of a random piece, moved by up to 0.05% to 5% of the pair's size, theta moved by
  // up to a slice step), where free and blocked space meet.
  std::vector<std::pair<double, const Curve*>> pieces;
  for (const SpaceSlice& s : space.slices)
    for (const ContactPiece& p : s.slice.realizable) pieces.push_back({s.theta, &p.curve});
  std::uniform_real_distribution<double> unit(-1.0, 1.0), ut01(0.0, 1.0);
  std::uniform_int_distribution<size_t> upiece(0, pieces.empty() ? 0 : pieces.size() - 1);
  for (int i = 0; i < queries; ++i) {
    Pose pose{ux(rng), uy(rng), ut(rng)};
    if (i % 2 == 1 && !pieces.empty()) {
      const auto& [theta, curve] = pieces[upiece(rng)];
      const Vec2 p = point_at(*curve, ut01(rng));
      const double r = pair.tol.size * std::pow(10.0, -1.3 - 2.0 * ut01(rng));
      pose = {p.x + r * unit(rng), p.y + r * unit(rng), theta + space.max_step * unit(rng)};
    }
    const QueryAnswer a = q.query(pose);
    // Outside the band by boundary distance: free. Overlapping boundaries are at distance 0,
    // so blocked configurations are checked when they stay blocked translated 2 tol.contact
    // in eight directions (deep enough in blocked space).
    const Placement truth = tester.classify(pose);
    if (truth == Placement::contact) continue;
    if (truth == Placement::free && tester.boundary_distance(pose) <= 2.0 * pair.tol.contact)
      continue;
    if (truth == Placement::blocked && !deep_blocked(tester, pose, 2.0 * pair.tol.contact))
      continue;
    // A contact answer within the band of such a wedge is right.
    if (truth == Placement::blocked && a.placement == Placement::contact &&
        near_realizable(pair, pose, 1.5 * pair.tol.contact))
      continue;
    ++checked;
    (truth == Placement::free ? free_count : blocked_count) += 1;
    if (a.placement != truth && ++mismatches <= 10)
      ADD_FAILURE() << name << ": at (" << pose.x << ", " << pose.y << ", " << pose.theta
                    << ") query says " << to_string(a.placement) << ", classify "
                    << to_string(truth);
    if (a.placement == Placement::free) {
      EXPECT_GE(a.component, 0) << name;
      EXPECT_LT(a.component, static_cast<int>(space.topology.components.size())) << name;
    }
  }
  EXPECT_EQ(mismatches, 0) << name;
  EXPECT_GT(checked, queries / 8) << name;
  const QueryStats& st = q.stats();
  std::cout << name << ": " << checked << " checked (" << free_count << " free, " << blocked_count
            << " blocked); " << st.evaluated << " evaluated, " << st.fallback << " fallback, "
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

// The tip of a thin free pocket (stress seed 100050): a configuration 0.0078 from the
// pocket's corner, within the contact tolerance 0.0086, is blocked by classify and stays
// blocked 2 tolerances away in all eight probe directions; the query's contact answer is
// right, as a realizable piece of the slice there passes within the tolerance.
TEST(SpaceQuery, ContactAtTheTipOfAThinPocketIsWithinTheBand) {
  std::mt19937 rng(100050);
  const testkit::RandomPair rp = testkit::random_pair(rng, 3, 8, true);
  const SlicedSpace space = space_of(rp.pair);
  SpaceQuery q(rp.pair, space);
  PlacementTester tester(rp.pair);
  const Pose pose{-0.045802104942899005, -0.1342124899868315, -1.4667158734858445};
  EXPECT_EQ(q.query(pose).placement, Placement::contact);
  EXPECT_EQ(tester.classify(pose), Placement::blocked);
  EXPECT_TRUE(deep_blocked(tester, pose, 2.0 * rp.pair.tol.contact));
  EXPECT_TRUE(near_realizable(rp.pair, pose, rp.pair.tol.contact));
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
