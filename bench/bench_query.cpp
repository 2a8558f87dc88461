// Point queries from a computed space (SpaceQuery) on the paper's examples: random
// configurations over the contact curves' bounding box, random theta each. Reports
// queries per second (items_per_second).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "cslice/query.hpp"
#include "cslice/space.hpp"
#include "support/examples.hpp"

namespace {

using namespace cslice;

void BM_Query(benchmark::State& state, const char* name) {
  const Pair pair = testkit::load_example(name);
  const SlicedSpace space = compute_space(pair);
  Box box;
  for (const SpaceSlice& s : space.slices)
    for (const ContactSegment& c : s.slice.contact_segments) box.add(bounding_box(c.curve));
  box = box.inflated(0.1 * box.diagonal());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(box.lo.x, box.hi.x), uy(box.lo.y, box.hi.y),
      ut(-kPi, kPi);
  std::vector<Pose> poses(4096);
  for (Pose& p : poses) p = {ux(rng), uy(rng), ut(rng)};
  SpaceQuery query(pair, space);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(query.query(poses[i]));
    i = (i + 1) % poses.size();
  }
  state.SetItemsProcessed(state.iterations());
  const QueryStats& st = query.stats();
  state.counters["fallback_share"] =
      st.queries ? static_cast<double>(st.fallback) / static_cast<double>(st.queries) : 0.0;
  state.counters["exact_intervals"] = st.exact_intervals;
  state.counters["intervals"] = st.intervals;
}

BENCHMARK_CAPTURE(BM_Query, cam, "cam");
BENCHMARK_CAPTURE(BM_Query, fastener, "fastener");
BENCHMARK_CAPTURE(BM_Query, fixture, "fixture");
BENCHMARK_CAPTURE(BM_Query, knee, "knee");

}  // namespace

BENCHMARK_MAIN();
