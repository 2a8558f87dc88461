// Cost of the critical orientations (critical_orientations on a whole pair). Target (see
// docs/performance.md, section "Critical orientations"): 1 ms or less for each paper
// example; random curved pairs of about 100 and 1,000 features, with the measured growth.
//
//   BM_CriticalExample/<name>/threads:<t>  the paper's examples on t threads (oneTBB)
//   BM_CriticalWholeTurn/<name>/threads:<t>  the same searching every orientation, not only a
//                              fundamental domain of the pair's symmetries (docs/symmetry.md)
//   BM_CriticalCurved/<n>      random lobed stars, n vertices per part (4n features): each
//                              vertex's radius jittered by 10%, half the edges arcs
//   BM_CriticalGear/<n>        a gear of n teeth in a ring gear of 2n (24n features)
// Counters: features, families (feature pairs that touch at some orientation), equations
// solved, criticalities kept, orientations after grouping, and the time per family^2 and per
// family^3 (the growth of candidate pairs and triples).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <random>
#include <stdexcept>

#include "cslice/critical.hpp"
#include "support/examples.hpp"
#include "support/random_polygons.hpp"

namespace {

// A fixed star of radius 3 and a moving one of radius 1 (origin off its centre), three lobes,
// half the edges arcs (testkit::curved_star_pair); built and parsed once per size, outside
// the timed loop.
const cslice::Pair& curved_pair(int n) {
  return cslice::testkit::made_once(cslice::testkit::curved_star_pair, n);
}

void run_critical(benchmark::State& state, const cslice::Pair& pair, int threads = 0,
                  bool map_symmetric = true) {
  cslice::CriticalSet set;
  cslice::CriticalOptions options;
  options.threads = threads;
  options.map_symmetric = map_symmetric;
  for (auto _ : state) {
    set = cslice::critical_orientations(pair, options);
    benchmark::DoNotOptimize(set.orientations.data());
  }
  const double families = set.stats.families;
  state.SetComplexityN(static_cast<int64_t>(families));
  state.counters["features"] = pair.moving.feature_count() + pair.fixed.feature_count();
  state.counters["families"] = families;
  state.counters["equations"] = static_cast<double>(set.stats.equations);
  state.counters["criticalities"] = static_cast<double>(set.stats.criticalities);
  state.counters["orientations"] = static_cast<double>(set.orientations.size());
}

// The paper's examples, on one and two threads; the symmetric ones (the knee has none) also
// searching the whole turn.
const bool kExamplesRegistered = [] {
  for (const bool whole_turn : {false, true})
    for (const std::string name : {"knee", "cam", "fixture", "fastener"}) {
      if (whole_turn && name == "knee") continue;
      const std::string title =
          std::string(whole_turn ? "BM_CriticalWholeTurn/" : "BM_CriticalExample/") + name;
      benchmark::RegisterBenchmark(title.c_str(),
                                   [=](benchmark::State& state) {
                                     run_critical(state, cslice::testkit::load_example(name),
                                                  static_cast<int>(state.range(0)), !whole_turn);
                                   })
          ->ArgName("threads")
          ->Arg(1)
          ->Arg(2)
          ->Unit(benchmark::kMillisecond);
    }
  return true;
}();

void BM_CriticalCurved(benchmark::State& state) {
  run_critical(state, curved_pair(static_cast<int>(state.range(0))));
}

// A gear of n teeth in a ring gear of 2n (testkit::gear_pair): 24n features, symmetric under
// turns by 2 pi / n and mirrors: the critical orientations of an eighth of a turn are searched.
const cslice::Pair& gear_pair(int teeth) {
  return cslice::testkit::made_once(cslice::testkit::gear_pair, teeth);
}

void BM_CriticalGear(benchmark::State& state) {
  run_critical(state, gear_pair(static_cast<int>(state.range(0))));
}

}  // namespace

BENCHMARK(BM_CriticalCurved)
    ->Arg(6)
    ->Arg(12)
    ->Arg(25)
    ->Arg(50)
    ->Unit(benchmark::kMillisecond)
    ->Complexity();
// Gears of 8 and 16 teeth in rings of 16 and 32: 192 and 384 features.
BENCHMARK(BM_CriticalGear)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);
// About 400 features: one timed run, reported on its own.
BENCHMARK(BM_CriticalCurved)
    ->Name("BM_CriticalCurved400")
    ->Arg(100)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
// About 1,000 features (Arg 250): minutes and gigabytes, so only when asked for with
// CSLICE_BENCH_LARGE=1 in the environment; docs/performance.md gives the run we made.
const bool kLargeRegistered = [] {
  if (std::getenv("CSLICE_BENCH_LARGE") == nullptr) return false;
  benchmark::RegisterBenchmark("BM_CriticalCurved1000", BM_CriticalCurved)
      ->Arg(250)
      ->Iterations(1)
      ->Unit(benchmark::kSecond);
  return true;
}();
BENCHMARK_MAIN();
