// Cost of the whole sliced space (compute_space: critical orientations, every slice, the
// correspondence and the 3D topology) of each paper example, the job `cslice compute` and
// `cslice stats` time. Target (issue 5, docs/performance.md "Sliced space"): 10 ms or less per
// example on one core, and the two-core speed-up.
//
//   BM_Space/<name>/threads:<t>  the example on t threads (oneTBB; the result is the same)
//   BM_SpaceArrangedWhole/<name>/threads:1  every slice from scratch arranging all its contact
//                                segments (SpaceOptions::narrow_arrangements = false)
//   BM_SpaceFromScratch/<name>/threads:1  that, and none evaluated from its interval's
//                                structure (SpaceOptions::evaluate_slices = false)
// Counters: critical orientations, slices stored, and the milliseconds spent on the
// critical orientations (the rest is slices and topology).
#include <benchmark/benchmark.h>

#include <string>
#include <utility>

#include "cslice/space.hpp"
#include "support/examples.hpp"

namespace {

// How the slices are made: as compute_space does by default, or without one or both of its
// shortcuts (the same space either way).
enum class Mode { normal, arranged_whole, from_scratch };

void run_space(benchmark::State& state, const std::string& name, Mode mode) {
  const cslice::Pair pair = cslice::testkit::load_example(name);
  cslice::SpaceOptions options;
  options.threads = static_cast<int>(state.range(0));
  options.narrow_arrangements = mode == Mode::normal;
  options.evaluate_slices = mode != Mode::from_scratch;
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

// Every example as compute_space makes it on one and two threads, then arranged whole and
// from scratch on one, in that order.
void register_benchmarks() {
  const char* const examples[] = {"knee", "cam", "fixture", "fastener"};
  const std::pair<Mode, const char*> modes[] = {{Mode::normal, "BM_Space/"},
                                                {Mode::arranged_whole, "BM_SpaceArrangedWhole/"},
                                                {Mode::from_scratch, "BM_SpaceFromScratch/"}};
  for (const auto& [mode, prefix] : modes)
    for (const char* name : examples) {
      const std::string title = std::string(prefix) + name;
      benchmark::internal::Benchmark* b = benchmark::RegisterBenchmark(
          title.c_str(), [=](benchmark::State& state) { run_space(state, name, mode); });
      b->ArgName("threads")->Arg(1)->Unit(benchmark::kMillisecond);
      if (mode == Mode::normal) b->Arg(2);
    }
}

}  // namespace

int main(int argc, char** argv) {
  register_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
