// Samples carried across critical orientations together (src/space/carry.cpp): the same
// landings as each carried alone, through fewer slices; and the topology that uses them the
// same whatever the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cslice/space.hpp"
#include "space/carry.hpp"
#include "support/random_polygons.hpp"

using namespace cslice;

namespace {

// A gear of 8 teeth in a ring gear of 16 (examples/drawings/gear-in-ring.dxf): its free space
// is mostly thin pockets where the teeth mesh, many beside each other in one slice.
Pair gear_in_ring() {
  const std::string json = testkit::gear_in_ring_json(8, 5.0, 2.75, 16, 7.0, 9.25, 0.001);
  const LoadResult loaded = parse_pair(json, "gear in ring");
  if (!loaded.ok()) throw std::runtime_error(loaded.error->message());
  return *loaded.pair;
}

}  // namespace

// At the first two critical orientations of the gear pair where three or more of the critical
// slice's thin components must be carried to the side slice (eight each: the meshing
// positions), carrying them together lands each where it lands carried alone (some nowhere:
// pockets closing there), and asks for far fewer slices than the carries alone together.
TEST(Carry, SamplesOfOneSliceStepTogether) {
  const Pair pair = gear_in_ring();
  SpaceOptions options;
  options.threads = 1;
  const SlicedSpace space = compute_space(pair, options);
  const double reach = moving_reach(pair.moving), delta = side_slice_angle(pair.tol);
  int transitions = 0, together_total = 0, alone_total = 0, landed = 0;
  for (const SpaceSlice& stored : space.slices) {
    if (stored.kind != SliceKind::critical || transitions == 2) continue;
    const Slice& from = stored.slice;
    const Slice to = compute_slice(pair, from.theta + delta);
    std::vector<detail::CarriedSample> together;
    for (int c = 0; c < static_cast<int>(from.free_components.size()); ++c) {
      const double clearance = detail::sample_clearance(from, c);
      if (clearance - from.epsilon <= reach * delta)
        together.push_back({c, from.free_components[c].sample, clearance});
    }
    if (together.size() < 3) continue;
    ++transitions;
    const auto slice_at = [&](double theta) { return compute_slice(pair, theta); };
    const int together_slices =
        detail::carry_samples(from, together, to, reach, pair.tol.angular, slice_at);
    int alone_slices = 0;
    for (const detail::CarriedSample& k : together) {
      std::vector<detail::CarriedSample> alone = {{k.component,
                                                   from.free_components[k.component].sample,
                                                   detail::sample_clearance(from, k.component)}};
      alone_slices += detail::carry_samples(from, alone, to, reach, pair.tol.angular, slice_at);
      EXPECT_EQ(alone[0].landed, k.landed)
          << "theta " << from.theta << ", component " << k.component;
      landed += k.landed >= 0 ? 1 : 0;
    }
    EXPECT_LT(together_slices, alone_slices) << "theta " << from.theta;
    together_total += together_slices;
    alone_total += alone_slices;
  }
  EXPECT_EQ(transitions, 2);
  EXPECT_GT(landed, 0);
  EXPECT_LT(3 * together_total, alone_total);  // measured: 153 slices against 1,033
}

// The carries run in parallel before the transitions use them: the topology is the same on
// one thread and on several.
TEST(Carry, TopologyIsTheSameOnAnyNumberOfThreads) {
  const Pair pair = gear_in_ring();
  SpaceOptions one, many;
  one.threads = 1;
  many.threads = 4;
  const SpaceTopology a = compute_space(pair, one).topology, b = compute_space(pair, many).topology;
  EXPECT_GT(a.checks.joins_by_carrying, 0);
  EXPECT_EQ(a.checks.joins_by_carrying, b.checks.joins_by_carrying);
  EXPECT_EQ(a.checks.carry_slices, b.checks.carry_slices);
  ASSERT_EQ(a.components.size(), b.components.size());
  for (size_t c = 0; c < a.components.size(); ++c)
    EXPECT_EQ(a.components[c].cells, b.components[c].cells) << "component " << c;
  ASSERT_EQ(a.transitions.size(), b.transitions.size());
  for (size_t t = 0; t < a.transitions.size(); ++t)
    EXPECT_EQ(a.transitions[t].joins, b.transitions[t].joins) << "transition " << t;
}
