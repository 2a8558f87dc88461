// Path queries (PathPlanner, include/cslice/path.hpp) on the paper's examples: random pairs
// of free configurations (a random theta, a random free component of the slice there, a
// random point of it), and one telling query per example. Reports queries per second and
// the average number of configurations, critical crossings and clearance evaluations.
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "cslice/classify.hpp"
#include "cslice/path.hpp"
#include "cslice/space.hpp"
#include "support/examples.hpp"
#include "support/free_poses.hpp"

namespace {

using namespace cslice;

// `cold`: a new planner for every query (no slices cached from earlier queries; its
// construction, which builds a SpaceQuery, is timed too), as for one `cslice path` run.
void run(benchmark::State& state, const Pair& pair, const SlicedSpace& space,
         const std::vector<std::pair<Pose, Pose>>& queries, bool cold) {
  auto planner = std::make_unique<PathPlanner>(pair, space);
  size_t i = 0;
  double poses = 0, crossings = 0, evaluations = 0, found = 0;
  for (auto _ : state) {
    if (cold) planner = std::make_unique<PathPlanner>(pair, space);
    const PathResult r = planner->plan(queries[i].first, queries[i].second);
    benchmark::DoNotOptimize(r.poses.data());
    poses += static_cast<double>(r.poses.size());
    crossings += r.stats.critical_crossings;
    evaluations += static_cast<double>(r.stats.clearance_evaluations);
    found += r.status == PathStatus::found ? 1 : 0;
    i = (i + 1) % queries.size();
  }
  const double n = static_cast<double>(state.iterations());
  state.SetItemsProcessed(state.iterations());
  state.counters["configurations"] = poses / n;
  state.counters["crossings"] = crossings / n;
  state.counters["evaluations"] = evaluations / n;
  state.counters["found_share"] = found / n;
}

void BM_PathRandom(benchmark::State& state, const char* name) {
  const Pair pair = testkit::load_example(name);
  const SlicedSpace space = compute_space(pair);
  std::mt19937 rng(7);
  std::vector<std::pair<Pose, Pose>> queries;
  for (int k = 0; k < 64; ++k)
    queries.push_back({testkit::random_free_pose(pair, rng).value(),
                       testkit::random_free_pose(pair, rng).value()});
  run(state, pair, space, queries, false);
}

// One long query each: the cam round its spiral channel (to the channel's centre at theta
// 3), the fastener's pin from outside into the cavity, the fixture's part turned upside down
// in its seat (out between the fingers, half a turn, back in), the femur flexed from -0.3 to
// 1.3 rad close over the tibia.
void BM_PathNotable(benchmark::State& state, const char* name, bool cold, Pose from, Pose to) {
  const Pair pair = testkit::load_example(name);
  const SlicedSpace space = compute_space(pair);
  if (name == std::string("cam")) {
    const Slice s = compute_slice(pair, to.theta);
    to.x = s.free_components.at(0).sample.x;
    to.y = s.free_components.at(0).sample.y;
  }
  run(state, pair, space, {{from, to}}, cold);
}

BENCHMARK_CAPTURE(BM_PathRandom, cam, "cam")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PathRandom, fastener, "fastener")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PathRandom, fixture, "fixture")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PathRandom, knee, "knee")->Unit(benchmark::kMillisecond);
// Warm: one planner for all iterations (its cached slices help); cold: a new one each time.
#define NOTABLE(name, mode, ...)                                                        \
  BENCHMARK_CAPTURE(BM_PathNotable, name##_##mode, #name, std::string(#mode) == "cold", \
                    __VA_ARGS__)                                                        \
      ->Unit(benchmark::kMillisecond)
NOTABLE(cam, warm, Pose{0.0, -1.25, 0.0}, Pose{0.0, 0.0, 3.0});
NOTABLE(fastener, warm, Pose{0.0, 6.0, 0.0}, Pose{0.0, -3.0, 0.0});
NOTABLE(fixture, warm, Pose{2.1, -0.75, 0.0}, Pose{2.1, -0.75, 3.14159265});
NOTABLE(knee, warm, Pose{5.0, -7.91, -0.3}, Pose{5.0, -0.45, 1.3});
NOTABLE(cam, cold, Pose{0.0, -1.25, 0.0}, Pose{0.0, 0.0, 3.0});
NOTABLE(fastener, cold, Pose{0.0, 6.0, 0.0}, Pose{0.0, -3.0, 0.0});
NOTABLE(fixture, cold, Pose{2.1, -0.75, 0.0}, Pose{2.1, -0.75, 3.14159265});
NOTABLE(knee, cold, Pose{5.0, -7.91, -0.3}, Pose{5.0, -0.45, 1.3});

}  // namespace

BENCHMARK_MAIN();
