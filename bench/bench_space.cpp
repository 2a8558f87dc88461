// Cost of the whole sliced space (compute_space: critical orientations, every slice, the
// correspondence and the 3D topology) of each paper example, the job `cslice compute` and
// `cslice stats` time. Target (issue 5, docs/performance.md "Sliced space"): 10 ms or less per
// example on one core, and the two-core speed-up.
//
//   BM_Space/<name>/threads:<t>  the example on t threads (oneTBB; the result is the same)
//   BM_SpaceFromScratch/<name>/threads:1  every slice computed from scratch, none evaluated
//                                from its interval's structure (SpaceOptions::evaluate_slices)
//                                or mapped across a symmetry (SpaceOptions::map_symmetric), as
//                                `cslice compute --from-scratch`
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
  options.map_symmetric = evaluate;
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

// Every example evaluated on one and two threads, then from scratch on one, in that order.
void register_benchmarks() {
  const char* const examples[] = {"knee", "cam", "fixture", "fastener"};
  for (const bool evaluate : {true, false})
    for (const char* name : examples) {
      const std::string title = std::string(evaluate ? "BM_Space/" : "BM_SpaceFromScratch/") + name;
      benchmark::internal::Benchmark* b = benchmark::RegisterBenchmark(
          title.c_str(), [=](benchmark::State& state) { run_space(state, name, evaluate); });
      b->ArgName("threads")->Arg(1)->Unit(benchmark::kMillisecond);
      if (evaluate) b->Arg(2);
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
