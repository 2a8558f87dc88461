// Slice equivalence: label-preserving isomorphism of contact graphs.
#include <gtest/gtest.h>

#include "cslice/equivalence.hpp"
#include "support/cli_run.hpp"
#include "support/examples.hpp"

using namespace cslice;

namespace {

Pair example(const std::string& name) {
  return testkit::load_example(name);
}

// A slice holding only a contact graph: `n` nodes, all with the same label, and the edges.
Slice graph_only(int n, const std::vector<std::pair<int, int>>& edges) {
  Slice s;
  for (int i = 0; i < n; ++i) {
    ContactSegment c;
    c.id = i;
    s.contact_segments.push_back(c);
    s.contact_graph.nodes.push_back(i);
  }
  for (auto [a, b] : edges) s.contact_graph.edges.push_back({a, b, {}});
  return s;
}

}  // namespace

TEST(Equivalence, ASliceIsEquivalentToItself) {
  for (const char* name : {"knee", "cam", "fixture", "fastener"}) {
    const Pair pair = example(name);
    const Slice s = compute_slice(pair, 0.4);
    EXPECT_TRUE(slices_equivalent(s, s).equivalent) << name;
  }
}

TEST(Equivalence, NearbyRegularSlicesAreEquivalent) {
  // Orientations 1e-7 apart almost surely have no critical orientation between them.
  for (const char* name : {"knee", "cam", "fixture", "fastener"}) {
    const Pair pair = example(name);
    const EquivalenceResult r =
        slices_equivalent(compute_slice(pair, 0.4), compute_slice(pair, 0.4 + 1e-7));
    EXPECT_TRUE(r.equivalent) << name << ": " << r.difference;
  }
}

TEST(Equivalence, FastenerOpenAndLockedDiffer) {
  const Pair pair = example("fastener");
  const EquivalenceResult r =
      slices_equivalent(compute_slice(pair, 0.0), compute_slice(pair, 1.5707963));
  EXPECT_FALSE(r.equivalent);
  EXPECT_FALSE(r.difference.empty());
}

TEST(Equivalence, ParallelEdgesAtThetaZeroDifferFromATiltedPeg) {
  const Pair pair = example("square-peg-hole");
  EXPECT_FALSE(slices_equivalent(compute_slice(pair, 0.0), compute_slice(pair, 0.2)).equivalent);
  EXPECT_TRUE(slices_equivalent(compute_slice(pair, 0.2), compute_slice(pair, 0.3)).equivalent);
}

TEST(Equivalence, SixCycleIsNotTwoTriangles) {
  // Same labels, same degrees: colour refinement alone cannot tell them apart.
  const Slice hexagon = graph_only(6, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {0, 5}});
  const Slice triangles = graph_only(6, {{0, 1}, {1, 2}, {0, 2}, {3, 4}, {4, 5}, {3, 5}});
  EXPECT_FALSE(slices_equivalent(hexagon, triangles).equivalent);
  EXPECT_TRUE(slices_equivalent(hexagon, hexagon).equivalent);
  // Relabelled nodes: the same graph up to isomorphism.
  const Slice shuffled = graph_only(6, {{3, 1}, {1, 5}, {5, 0}, {0, 2}, {2, 4}, {4, 3}});
  EXPECT_TRUE(slices_equivalent(hexagon, shuffled).equivalent);
}

// Distinct labels force the only possible map; same label multiset, same number of meetings.
TEST(Equivalence, DistinctLabelsDecideByTheirMeetings) {
  const auto labelled = [](Slice s) {
    for (ContactSegment& c : s.contact_segments) c.fixed_feature = c.id;
    return s;
  };
  const Slice path = labelled(graph_only(4, {{0, 1}, {1, 2}, {2, 3}}));
  const Slice star = labelled(graph_only(4, {{0, 1}, {0, 2}, {0, 3}}));
  const Slice reversed = labelled(graph_only(4, {{3, 2}, {2, 1}, {1, 0}}));
  EXPECT_TRUE(slices_equivalent(path, reversed).equivalent);
  const EquivalenceResult r = slices_equivalent(path, star);
  EXPECT_FALSE(r.equivalent);
  EXPECT_NE(r.difference.find("meets different contact segments"), std::string::npos);
  // Isomorphic as unlabelled graphs, but not by the labels: 0-1-2-3 against 1-0-2-3.
  EXPECT_FALSE(
      slices_equivalent(path, labelled(graph_only(4, {{1, 0}, {0, 2}, {2, 3}}))).equivalent);
  const Slice doubled = labelled(graph_only(4, {{0, 1}, {1, 2}, {2, 3}, {0, 1}}));
  const Slice doubled_elsewhere = labelled(graph_only(4, {{0, 1}, {1, 2}, {2, 3}, {2, 3}}));
  EXPECT_FALSE(slices_equivalent(doubled, doubled_elsewhere).equivalent);
}

TEST(Equivalence, MultiplicityOfMeetingPointsCounts) {
  const Slice once = graph_only(3, {{0, 1}, {1, 2}, {0, 2}, {0, 1}});
  const Slice twice = graph_only(3, {{0, 1}, {1, 2}, {0, 2}, {1, 2}});
  EXPECT_TRUE(slices_equivalent(once, twice).equivalent);  // isomorphic by relabelling
  const Slice path = graph_only(3, {{0, 1}, {1, 2}, {0, 1}, {1, 2}});
  EXPECT_FALSE(slices_equivalent(once, path).equivalent);
}

class EquivalenceCli : public testkit::ScratchDirTest {
 protected:
  EquivalenceCli() : ScratchDirTest("equivalence_cli") {}
};

TEST_F(EquivalenceCli, AnswersAndExitStatus) {
  const std::string pair = testkit::quoted(testkit::example_path("fastener"));
  const auto same = testkit::run_cli("equivalent " + pair + " 0.4 0.4000001", dir_);
  EXPECT_EQ(same.status, 0);
  EXPECT_EQ(same.out, "equivalent\n");
  const auto differ = testkit::run_cli("equivalent " + pair + " 0 1.5707963", dir_);
  EXPECT_EQ(differ.status, 1);
  EXPECT_NE(differ.out.find("not equivalent: "), std::string::npos);
  EXPECT_TRUE(differ.err.empty());
  const auto bad = testkit::run_cli("equivalent " + pair + " 0 nan", dir_);
  EXPECT_EQ(bad.status, 2);
  EXPECT_TRUE(bad.out.empty());
}
