// Throughput of the direct placement test on the paper's examples, at random poses that put
// the moving part near the fixed part (the poses a configuration-space sweep asks about).
// Target: at least 100,000 queries per second per core. Results live in docs/performance.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "cslice/classify.hpp"
#include "cslice/pair.hpp"
#include "support/examples.hpp"

namespace {

using cslice::testkit::load_example;

// Bounding box of the moving part turned by theta about its body origin.
cslice::Box turned_box(const cslice::Part& part, double theta) {
  const cslice::Transform t(cslice::Pose{0.0, 0.0, theta});
  cslice::Box box;
  for (const cslice::Loop& loop : part.loops)
    for (const cslice::Curve& c : loop.edges)
      box.add(cslice::bounding_box(cslice::transformed(c, t)));
  return box;
}

// A reference point range for orientation theta. Against a solid part: its box grown by the
// moving part's reach, so the moving part overlaps or nearly touches it. In an enclosure,
// where that box would be almost all blocked: the positions that keep the turned moving
// part's box inside the opening's box, widened by 1% of the size, where the moving part
// rattles around (for the cam, its narrow channel).
cslice::Box reference_range(const cslice::Pair& pair, double theta) {
  const cslice::Box& f = pair.fixed.box;
  const cslice::Box m = turned_box(pair.moving, theta);
  if (!pair.fixed.enclosure) {
    double reach = 0.0;
    for (cslice::Vec2 c : {m.lo, m.hi, cslice::Vec2{m.lo.x, m.hi.y}, cslice::Vec2{m.hi.x, m.lo.y}})
      reach = std::max(reach, cslice::length(c));
    return f.inflated(reach);
  }
  // Spanning both offsets also covers a part too wide to fit: then the range is its overflow.
  cslice::Box r;
  r.add(f.lo - m.lo);
  r.add(f.hi - m.hi);
  return r.inflated(0.01 * pair.tol.size);
}

std::vector<cslice::Pose> poses_near_fixed(const cslice::Pair& pair, int count) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<cslice::Pose> poses(count);
  for (cslice::Pose& p : poses) {
    const double theta = -cslice::kPi + cslice::kTwoPi * u(rng);
    const cslice::Box b = reference_range(pair, theta);
    p = {b.lo.x + (b.hi.x - b.lo.x) * u(rng), b.lo.y + (b.hi.y - b.lo.y) * u(rng), theta};
  }
  return poses;
}

void BM_PlacementTester(benchmark::State& state, const std::string& name) {
  const cslice::Pair pair = load_example(name);
  constexpr int kPoses = 4096;  // a power of two, cycled through with a mask
  const std::vector<cslice::Pose> poses = poses_near_fixed(pair, kPoses);
  cslice::PlacementTester tester(pair);
  std::array<long, 3> answers{};
  size_t i = 0;
  for (auto _ : state) {
    const cslice::Placement p = tester.classify(poses[i++ & (kPoses - 1)]);
    ++answers[static_cast<int>(p)];
    benchmark::DoNotOptimize(p);
  }
  state.SetItemsProcessed(state.iterations());
  // The mix of answers, so a change in speed can be told from a change in workload.
  const double n = static_cast<double>(std::max<long>(1, state.iterations()));
  state.counters["free"] = answers[0] / n;
  state.counters["contact"] = answers[1] / n;
  state.counters["blocked"] = answers[2] / n;
  state.counters["features"] = pair.moving.feature_count() + pair.fixed.feature_count();
}

// The free function builds a tester per call: the price of not reusing one.
void BM_ClassifyFunction(benchmark::State& state, const std::string& name) {
  const cslice::Pair pair = load_example(name);
  constexpr int kPoses = 4096;
  const std::vector<cslice::Pose> poses = poses_near_fixed(pair, kPoses);
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(cslice::classify(pair, poses[i++ & (kPoses - 1)]));
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK_CAPTURE(BM_PlacementTester, knee, std::string("knee"));
BENCHMARK_CAPTURE(BM_PlacementTester, cam, std::string("cam"));
BENCHMARK_CAPTURE(BM_PlacementTester, fixture, std::string("fixture"));
BENCHMARK_CAPTURE(BM_PlacementTester, fastener, std::string("fastener"));
BENCHMARK_CAPTURE(BM_ClassifyFunction, knee, std::string("knee"));

}  // namespace

BENCHMARK_MAIN();
