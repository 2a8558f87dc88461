// Slices of a sliced space arranged from their neighbour's realizable labels and those the
// critical orientation between names (SpaceOptions::narrow_arrangements) against the same
// slices arranging every contact segment, and against the direct placement test.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "cslice/slice.hpp"
#include "cslice/space.hpp"
#include "support/examples.hpp"
#include "support/random_parts.hpp"
#include "support/slice_oracle.hpp"

using namespace cslice;

namespace {

SlicedSpace space_of(const Pair& pair, bool narrow) {
  SpaceOptions options;
  options.threads = 2;
  options.narrow_arrangements = narrow;
  return compute_space(pair, options);
}

// Every slice of the narrowed space against its twin arranged whole, and the topology built
// on them; returns the slices compared.
int compare_spaces(const Pair& pair, const std::string& name) {
  const SlicedSpace narrow = space_of(pair, true), whole = space_of(pair, false);
  EXPECT_EQ(narrow.slices.size(), whole.slices.size()) << name;
  EXPECT_EQ(narrow.topology.components.size(), whole.topology.components.size()) << name;
  EXPECT_EQ(narrow.topology.cells.size(), whole.topology.cells.size()) << name;
  EXPECT_EQ(narrow.topology.slice_components, whole.topology.slice_components) << name;
  int compared = 0;
  for (size_t i = 0; i < narrow.slices.size() && i < whole.slices.size(); ++i) {
    EXPECT_EQ(narrow.slices[i].evaluated, whole.slices[i].evaluated) << name << " slice " << i;
    testkit::expect_same_slice(pair, narrow.slices[i].slice, whole.slices[i].slice,
                               name + " slice " + std::to_string(i));
    ++compared;
  }
  return compared;
}

// How many contact segments of the slice's list a narrowed arrangement would leave out, had
// it been given `labels`: the measure of what narrowing saves.
int left_out(const Slice& slice, const std::vector<SegmentLabel>& labels) {
  int n = 0;
  for (const ContactSegment& s : slice.contact_segments)
    n += std::binary_search(labels.begin(), labels.end(),
                            SegmentLabel{s.moving_feature, s.fixed_feature})
             ? 0
             : 1;
  return n;
}

}  // namespace

// The paper's examples and the small designed ones (exact fits, a peg turning in its hole,
// symmetric parts): every slice the same either way.
TEST(NarrowedSlices, ExamplesMatchSlicesArrangedWhole) {
  for (const char* name : {"knee", "cam", "fixture", "fastener", "disc-in-box", "square-peg-hole",
                           "pin-exact-fit", "disc-half-plane"}) {
    const Pair pair = testkit::load_example(name);
    EXPECT_GT(compare_spaces(pair, name), 0) << name;
  }
}

// A free component born at a criticality where one contact segment's end meets another:
// a third segment, sharing that end with the first (their features are neighbours), bounds
// the new component too, though the criticality names only the first two (stress seed
// 128232; narrowing from the names alone lost the component for twelve slices). The
// segments through the criticality's configuration are arranged as well.
TEST(NarrowedSlices, ComponentBornWhereContactSegmentsShareAnEndIsKept) {
  const testkit::RandomPair p = testkit::stress_pair(128232);
  EXPECT_GT(compare_spaces(p.pair, "stress pair 128232"), 0);
}

// Random curved pairs of the stress set, and tight fits (pinched free space, intervals with
// none at all): every slice the same either way.
TEST(NarrowedSlices, RandomAndTightPairsMatchSlicesArrangedWhole) {
  for (unsigned seed = 100240; seed < 100280; ++seed) {
    const testkit::RandomPair p = testkit::stress_pair(seed);
    compare_spaces(p.pair, "random pair " + std::to_string(seed));
  }
  std::mt19937 rng(5);
  for (int k = 0; k < 10; ++k)
    compare_spaces(testkit::tight_pair(rng, k), "tight pair " + std::to_string(k));
}

// The labels of `slice`'s contact segments passing within `reach` of a configuration of one
// of the orientation's criticalities.
void add_labels_through(const Slice& slice, const CriticalOrientation& o, double reach,
                        std::vector<SegmentLabel>& labels) {
  for (const ContactSegment& s : slice.contact_segments)
    for (const Criticality& c : o.criticalities)
      if (distance_to_curve(s.curve, c.at) <= reach)
        labels.push_back({s.moving_feature, s.fixed_feature});
}

// The narrowing is not empty: on the fixture, a slice's neighbour and the criticalities
// between leave out a good share of its contact segments, and still every realizable one is
// among the labels they give, on slices arranged whole.
TEST(NarrowedSlices, FixtureSlicesLeaveOutContactSegmentsNeverRealizable) {
  const Pair pair = testkit::load_example("fixture");
  const SlicedSpace space = space_of(pair, false);
  const double reach = kEventReachPerCriticality * pair.tol.criticality;
  int listed = 0, out = 0;
  for (size_t i = 1; i < space.slices.size(); ++i) {
    const SpaceSlice& s = space.slices[i];
    if (s.evaluated) continue;
    size_t before = i - 1;  // the last slice from scratch
    while (before > 0 && space.slices[before].evaluated) --before;
    std::vector<SegmentLabel> labels = realizable_labels(space.slices[before].slice);
    const CriticalOrientation& o = space.criticals.orientations[size_t(s.interval)];
    for (const Criticality& c : o.criticalities)
      for (const FeaturePairRef& p : c.pairs) labels.push_back({p.moving_feature, p.fixed_feature});
    if (s.kind == SliceKind::critical) add_labels_through(s.slice, o, reach, labels);
    if (space.slices[before].kind == SliceKind::critical)
      add_labels_through(space.slices[before].slice, o, reach, labels);
    std::sort(labels.begin(), labels.end());
    for (const SegmentLabel& l : realizable_labels(s.slice))
      EXPECT_TRUE(std::binary_search(labels.begin(), labels.end(), l))
          << "slice " << i << ": " << l.moving_feature << "/" << l.fixed_feature;
    listed += int(s.slice.contact_segments.size());
    out += left_out(s.slice, labels);
  }
  EXPECT_GT(out, listed / 5) << out << " of " << listed;
}

// Narrowed slices pass the slice tests' own oracle: samples free, membership as classify says
// at random points, boundary pieces where contact is.
TEST(NarrowedSlices, AgreeWithClassify) {
  std::mt19937 rng(2027);
  for (const char* name : {"knee", "fixture", "fastener"}) {
    const Pair pair = testkit::load_example(name);
    const SlicedSpace space = space_of(pair, true);
    int checked = 0;
    for (size_t i = 0; i < space.slices.size(); i += 5) {
      const std::string what = std::string(name) + " slice " + std::to_string(i);
      checked += testkit::check_slice_against_classify(pair, space.slices[i].slice, 200, rng, what);
      testkit::expect_boundary_sides_agree_with_classify(pair, space.slices[i].slice, what);
    }
    EXPECT_GT(checked, 0) << name;
  }
}
