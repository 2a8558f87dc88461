// Cost of the whole sliced space (compute_space: critical orientations, every slice, the
// correspondence and the 3D topology) of each paper example, the job `cslice compute` and
// `cslice stats` time. Target (issue 5, docs/performance.md "Sliced space"): 10 ms or less per
// example on one core, and the two-core speed-up.
//
//   BM_Space/<name>/threads:<t>  the example on t threads (oneTBB; the result is the same)
//   BM_SpaceFromScratch/<name>/threads:1  every slice computed from scratch, none evaluated
//                                from its interval's structure (SpaceOptions::evaluate_slices)
// Counters: critical orientations, slices stored, and the milliseconds spent on the
// critical orientations (the rest is slices and topology).
#include <benchmark/benchmark.h>

#include <string>

#include "cslice/space.hpp"
#include "support/examples.hpp"

namespace {

void run_space(benchmark::State& state, const std::string& name, bool evaluate) {
  const cslice::Pair pair = cslice::testkit::load_example(name);
  cslice::SpaceOptions options;
  options.threads = static_cast<int>(state.range(0));
  options.evaluate_slices = evaluate;
  cslice::SlicedSpace space;
  double criticals_seconds = 0.0;
  for (auto _ : state) {
    space = cslice::compute_space(pair, options);
    criticals_seconds += space.seconds_criticals;
    benchmark::DoNotOptimize(space.slices.data());
  }
  state.counters["orientations"] = static_cast<double>(space.criticals.orientations.size());
  state.counters["slices"] = static_cast<double>(space.slices.size());
  state.counters["criticals_ms"] =
      benchmark::Counter(1e3 * criticals_seconds, benchmark::Counter::kAvgIterations);
}

void BM_Space(benchmark::State& state, const std::string& name) {
  run_space(state, name, true);
}

void BM_SpaceFromScratch(benchmark::State& state, const std::string& name) {
  run_space(state, name, false);
}

}  // namespace

BENCHMARK_CAPTURE(BM_Space, knee, std::string("knee"))
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Space, cam, std::string("cam"))
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Space, fixture, std::string("fixture"))
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Space, fastener, std::string("fastener"))
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SpaceFromScratch, knee, std::string("knee"))
    ->ArgName("threads")
    ->Arg(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SpaceFromScratch, cam, std::string("cam"))
    ->ArgName("threads")
    ->Arg(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SpaceFromScratch, fixture, std::string("fixture"))
    ->ArgName("threads")
    ->Arg(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SpaceFromScratch, fastener, std::string("fastener"))
    ->ArgName("threads")
    ->Arg(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
