// Point queries from a computed space (SpaceQuery) on the paper's examples, reported as
// queries per second (items_per_second):
//   BM_Query/<example>             random configurations over the contact curves' bounding
//                                  box, random theta each (the measure)
//   BM_QueryNearContact/<example>  the hard case: each configuration within five contact
//                                  tolerances of a realizable piece of a stored slice, its
//                                  theta up to a quarter of the interpolation step away, so
//                                  the boundary must be evaluated at theta
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "cslice/query.hpp"
#include "cslice/space.hpp"
#include "support/examples.hpp"

namespace {

using namespace cslice;

std::vector<Pose> uniform_poses(const SlicedSpace& space) {
  Box box;
  for (const SpaceSlice& s : space.slices)
    for (const ContactSegment& c : s.slice.contact_segments) box.add(bounding_box(c.curve));
  box = box.inflated(0.1 * box.diagonal());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(box.lo.x, box.hi.x), uy(box.lo.y, box.hi.y),
      ut(-kPi, kPi);
  std::vector<Pose> poses(4096);
  for (Pose& p : poses) p = {ux(rng), uy(rng), ut(rng)};
  return poses;
}

std::vector<Pose> near_contact_poses(const Pair& pair, const SlicedSpace& space) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0), off(-1.0, 1.0);
  std::vector<const SpaceSlice*> stored;
  for (const SpaceSlice& s : space.slices)
    if (s.kind != SliceKind::critical && !s.slice.realizable.empty()) stored.push_back(&s);
  std::vector<Pose> poses;
  while (poses.size() < 4096) {
    const SpaceSlice& s = *stored[size_t(u(rng) * double(stored.size())) % stored.size()];
    const std::vector<ContactPiece>& pieces = s.slice.realizable;
    const Vec2 p =
        point_at(pieces[size_t(u(rng) * double(pieces.size())) % pieces.size()].curve, u(rng));
    const double r = 5.0 * pair.tol.contact;
    poses.push_back(
        {p.x + r * off(rng), p.y + r * off(rng), s.theta + 0.25 * space.max_step * off(rng)});
  }
  return poses;
}

void run_queries(benchmark::State& state, const Pair& pair, const SlicedSpace& space,
                 const std::vector<Pose>& poses) {
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
  state.counters["far_share"] =
      st.queries ? static_cast<double>(st.far_from_contact) / static_cast<double>(st.queries) : 0.0;
}

void BM_Query(benchmark::State& state, const char* name) {
  const Pair pair = testkit::load_example(name);
  const SlicedSpace space = compute_space(pair);
  run_queries(state, pair, space, uniform_poses(space));
}

void BM_QueryNearContact(benchmark::State& state, const char* name) {
  const Pair pair = testkit::load_example(name);
  const SlicedSpace space = compute_space(pair);
  run_queries(state, pair, space, near_contact_poses(pair, space));
}

BENCHMARK_CAPTURE(BM_Query, cam, "cam");
BENCHMARK_CAPTURE(BM_Query, fastener, "fastener");
BENCHMARK_CAPTURE(BM_Query, fixture, "fixture");
BENCHMARK_CAPTURE(BM_Query, knee, "knee");
BENCHMARK_CAPTURE(BM_QueryNearContact, cam, "cam");
BENCHMARK_CAPTURE(BM_QueryNearContact, fastener, "fastener");
BENCHMARK_CAPTURE(BM_QueryNearContact, fixture, "fixture");
BENCHMARK_CAPTURE(BM_QueryNearContact, knee, "knee");

}  // namespace

BENCHMARK_MAIN();
