// Cost of one slice (compute_slice at one theta), against CGAL's Minkowski sum on the same
// polygonal pairs. Targets (see docs/performance.md, section "Slice"): a slice of a pair with
// about 10,000 features in 20 ms on one core; at least 50 times faster than CGAL's reduced
// convolution; cost growing no faster than k log k in the number k of contact segments.
//
//   BM_SliceExample/<name>/<i>  the paper's examples at theta[i]
//   BM_SlicerExample/<name>     one more slice of an example by a Slicer already slicing it
//                               (as the sliced space does), cycling through 64 orientations
//   BM_SliceStar/<n>            smooth random star polygons, n vertices per part
//   BM_SlicerStar/<n>           the same by a Slicer made once (the pair's contact data built
//                               outside the timed loop)
//   BM_CgalStar/<n>             CGAL::minkowski_sum_by_reduced_convolution_2 (exact
//                               kernel) of the same pairs: fixed + moving turned and reflected
//   BM_SliceRoughStar/<n>       rough stars (independent radius noise): k grows like n^2
//   BM_SlicerRoughStar/<n>      the same by a Slicer made once, as BM_SlicerStar
//   BM_SliceRoughStarUnproven/<n>  the same with no contact segment proven blocked
//                               (slice/blocked_proof.hpp): what the proof saves
//   BM_CgalRoughStar/<n>        CGAL on those
//   BM_SliceCurved/<e>          smooth stars with half their edges arcs, e edges per part
//                               (2e features per part)
//   BM_SlicerGear/<n>           a gear of n teeth in a ring of 2n, as BM_SlicerExample
//   BM_SlicerGearUnproven/<n>   the same with no contact segment proven blocked
// Counters: k = contact segments, free = free components, bounded = bounded ones, features =
// both parts' features, ns_per_klogk = time / (k log2 k). Pairs are built and parsed once,
// outside the timed loops; CGAL's input polygons too.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/minkowski_sum_2.h>
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "cslice/slice.hpp"
#include "slice/blocked_proof.hpp"
#include "support/examples.hpp"
#include "support/random_polygons.hpp"

namespace {

using cslice::testkit::LoopVertices;
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;

constexpr double kStarTheta = 0.7;
constexpr double kExampleThetas[] = {0.0, 0.5, 1.9};

using cslice::testkit::load_example;

struct BenchPair {
  LoopVertices moving, fixed;
  cslice::Pair pair;
};

enum class Shape { smooth, rough, curved };

// A fixed star of radius 3 and a moving one of radius 1 (origin slightly off its centre),
// both with three random lobes. Smooth: vertices sampled from the lobed contour at jittered
// angles, so each part is a fine polygon of a smooth curve (what a machined contour looks
// like). Rough: each radius also jittered by 30% of the angular spacing, which turns
// neighbouring edges by up to about 30 degrees. Curved: smooth, with half the edges arcs
// following the contour (the flattest, near inflections, stay straight). Retries with the
// next seed if the reader rejects the pair.
const BenchPair& star_pair(Shape shape, int n) {
  static std::map<std::pair<int, int>, BenchPair> cache;
  const auto key = std::make_pair(static_cast<int>(shape), n);
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  const double radial_jitter = shape == Shape::rough ? 0.3 * cslice::kTwoPi / n : 0.0;
  const double arc_fraction = shape == Shape::curved ? 0.5 : 0.0;
  cslice::testkit::AcceptedStarPair a = cslice::testkit::accepted_star_pair(
      n, radial_jitter, arc_fraction, 2026 + static_cast<unsigned>(n), 1, 76, "star");
  BenchPair p{std::move(a.loops.moving), std::move(a.loops.fixed), std::move(a.pair)};
  return cache.emplace(key, std::move(p)).first->second;
}

int features(const cslice::Pair& pair) {
  return pair.moving.feature_count() + pair.fixed.feature_count();
}

// Runs compute_slice in the timed loop and reports the counters.
void run_slice(benchmark::State& state, const cslice::Pair& pair, double theta) {
  cslice::Slice slice;
  double seconds = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    slice = cslice::compute_slice(pair, theta);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    benchmark::DoNotOptimize(slice.blocked_area);
  }
  const double k = static_cast<double>(slice.contact_segments.size());
  int bounded = 0;
  for (const cslice::FreeComponent& c : slice.free_components) bounded += c.bounded ? 1 : 0;
  state.SetComplexityN(static_cast<int64_t>(k));
  state.counters["k"] = k;
  state.counters["free"] = static_cast<double>(slice.free_components.size());
  state.counters["bounded"] = bounded;
  state.counters["features"] = features(pair);
  state.counters["arcs"] = pair.moving.arc_count() + pair.fixed.arc_count();
  const double per_iteration = seconds / std::max<double>(1.0, double(state.iterations()));
  state.counters["ns_per_klogk"] = k > 1.0 ? per_iteration * 1e9 / (k * std::log2(k)) : 0.0;
}

void BM_SliceExample(benchmark::State& state, const std::string& name) {
  const cslice::Pair pair = load_example(name);
  const double theta = kExampleThetas[state.range(0)];
  state.SetLabel("theta=" + std::to_string(theta));
  run_slice(state, pair, theta);
}

// One Slicer for all iterations, as the sliced space uses one per thread: the features'
// contact data, the placement tester and the slices' working buffers are kept, so this is
// the cost of one more slice, averaged over orientations all around.
void run_slicer_around(benchmark::State& state, const cslice::Pair& pair) {
  cslice::Slicer slicer(pair);
  constexpr int kThetas = 64;
  int k = 0;
  for (auto _ : state) {
    const double theta = -cslice::kPi + (k++ % kThetas + 0.5) * cslice::kTwoPi / kThetas;
    const cslice::Slice slice = slicer.slice(theta);
    benchmark::DoNotOptimize(slice.blocked_area);
  }
  state.counters["features"] = features(pair);
}

void BM_SlicerExample(benchmark::State& state, const std::string& name) {
  run_slicer_around(state, load_example(name));
}

// The same for gears in ring gears (testkit::gear_pair; 24n features, most contact segments
// arcs at the teeth's tips and roots), with the contact segments proven blocked left out as
// the slice does, and with none left out: what the proof saves on arcs.
const cslice::Pair& gear_pair(int teeth) {
  return cslice::testkit::made_once(cslice::testkit::gear_pair, teeth);
}
void BM_SlicerGear(benchmark::State& state) {
  run_slicer_around(state, gear_pair(int(state.range(0))));
}
void BM_SlicerGearUnproven(benchmark::State& state) {
  cslice::set_blocked_proof_mode(cslice::BlockedProofMode::never);
  run_slicer_around(state, gear_pair(int(state.range(0))));
  cslice::set_blocked_proof_mode(cslice::BlockedProofMode::automatic);
}

void BM_SliceStar(benchmark::State& state) {
  run_slice(state, star_pair(Shape::smooth, int(state.range(0))).pair, kStarTheta);
}
// The same star slice by a Slicer made outside the timed loop: the pair's contact data
// (contact features, the index of fixed normals) are then built once, as for every slice of
// a sliced space; compute_slice builds them per call.
void run_slicer_star(benchmark::State& state, const cslice::Pair& pair) {
  cslice::Slicer slicer(pair);
  for (auto _ : state) {
    const cslice::Slice slice = slicer.slice(kStarTheta);
    benchmark::DoNotOptimize(slice.blocked_area);
  }
  state.counters["features"] = features(pair);
}
void BM_SlicerStar(benchmark::State& state) {
  run_slicer_star(state, star_pair(Shape::smooth, int(state.range(0))).pair);
}
void BM_SlicerRoughStar(benchmark::State& state) {
  run_slicer_star(state, star_pair(Shape::rough, int(state.range(0))).pair);
}
void BM_SliceRoughStar(benchmark::State& state) {
  run_slice(state, star_pair(Shape::rough, int(state.range(0))).pair, kStarTheta);
}
void BM_SliceRoughStarUnproven(benchmark::State& state) {
  cslice::set_blocked_proof_mode(cslice::BlockedProofMode::never);
  run_slice(state, star_pair(Shape::rough, int(state.range(0))).pair, kStarTheta);
  cslice::set_blocked_proof_mode(cslice::BlockedProofMode::automatic);
}
void BM_SliceCurved(benchmark::State& state) {
  run_slice(state, star_pair(Shape::curved, int(state.range(0))).pair, kStarTheta);
}

// CGAL's reduced convolution of the fixed polygon and the moving one turned by theta (in
// double, as cslice does) and reflected through its origin (exact), exact kernel.
void run_cgal(benchmark::State& state, const BenchPair& p, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  Polygon fixed, moving;
  for (const auto& v : p.fixed) fixed.push_back(Kernel::Point_2(v.x, v.y));
  for (const auto& v : p.moving)
    moving.push_back(Kernel::Point_2(-(c * v.x - s * v.y), -(s * v.x + c * v.y)));
  size_t outer = 0, holes = 0;
  for (auto _ : state) {
    const CGAL::Polygon_with_holes_2<Kernel> sum =
        CGAL::minkowski_sum_by_reduced_convolution_2(fixed, moving);
    outer = sum.outer_boundary().size();
    holes = sum.number_of_holes();
    benchmark::DoNotOptimize(outer);
  }
  state.counters["outer_vertices"] = static_cast<double>(outer);
  state.counters["holes"] = static_cast<double>(holes);
  state.counters["features"] = features(p.pair);
}

void BM_CgalStar(benchmark::State& state) {
  run_cgal(state, star_pair(Shape::smooth, int(state.range(0))), kStarTheta);
}
void BM_CgalRoughStar(benchmark::State& state) {
  run_cgal(state, star_pair(Shape::rough, int(state.range(0))), kStarTheta);
}

#define CSLICE_EXAMPLE(name)                                   \
  BENCHMARK_CAPTURE(BM_SliceExample, name, std::string(#name)) \
      ->DenseRange(0, 2)                                       \
      ->Unit(benchmark::kMillisecond)
CSLICE_EXAMPLE(knee);
CSLICE_EXAMPLE(cam);
CSLICE_EXAMPLE(fixture);
CSLICE_EXAMPLE(fastener);

#define CSLICE_SLICER_EXAMPLE(name) \
  BENCHMARK_CAPTURE(BM_SlicerExample, name, std::string(#name))->Unit(benchmark::kMicrosecond)
CSLICE_SLICER_EXAMPLE(knee);
CSLICE_SLICER_EXAMPLE(cam);
CSLICE_SLICER_EXAMPLE(fixture);
CSLICE_SLICER_EXAMPLE(fastener);

BENCHMARK(BM_SliceStar)
    ->Arg(100)
    ->Arg(300)
    ->Arg(1000)
    ->Arg(3000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oNLogN);
BENCHMARK(BM_SlicerStar)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CgalStar)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);
// Tens of seconds each with the exact kernel: one iteration.
BENCHMARK(BM_CgalStar)->Arg(3000)->Arg(10000)->Iterations(1)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_SliceRoughStar)
    ->Arg(100)
    ->Arg(300)
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(3000)
    ->Unit(benchmark::kMillisecond);
// 5.8 million contact segments, 4 GB, seconds: one iteration.
BENCHMARK(BM_SliceRoughStar)->Arg(10000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SliceRoughStarUnproven)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SlicerRoughStar)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CgalRoughStar)->Arg(100)->Arg(300)->Unit(benchmark::kMillisecond);
// 1.5, 8 and 23 s, 2 GB at 3,000; at 10,000 it would need about 19 GB (not run).
BENCHMARK(BM_CgalRoughStar)
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(3000)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

BENCHMARK(BM_SlicerGear)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SlicerGearUnproven)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SliceCurved)
    ->Arg(250)
    ->Arg(800)
    ->Arg(2500)
    ->Arg(5000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oNLogN);

}  // namespace

BENCHMARK_MAIN();
