// Pieces of compute_space shared with the space reader (space_reader.cpp), which rebuilds a
// space from a file by recomputing its slices at the stored orientations.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <functional>
#include <optional>
#include <vector>

#include "contacts/contact_features.hpp"
#include "cslice/space.hpp"
#include "parallel/arena.hpp"
#include "slice/boundary_model.hpp"

namespace cslice::detail {

// An orientation to slice at, before the slice is computed.
struct PlannedSlice {
  double theta = 0.0;
  SliceKind kind = SliceKind::interval;
  int interval = 0;
};

// Every orientation compute_space slices at, sorted by theta (docs/space-format.md, "Which
// orientations are sliced").
std::vector<PlannedSlice> plan_slices(const CriticalSet& criticals, double step);

// Boundary models already checked, by the index of the slice they model: empty where none
// was tried; holding an empty optional where one was tried and cannot stand in
// (checked_model). The topology's side slices reuse those of the intermediate slices.
using KnownModels = std::vector<std::optional<std::optional<BoundaryModel>>>;

// The slices at the planned orientations, in parallel (`threads` as in SpaceOptions), each
// stored at its own index: the same whatever the thread count. Intermediate slices are
// evaluated from their interval's representative (SpaceOptions::evaluate_slices) when
// `evaluate`; slices at the image of another's orientation under a symmetry of the pair are
// mapped from it when `map_symmetric`; the representatives' models go into `models` when
// given.
struct SliceRules {
  int threads = 0;            // as in SpaceOptions
  bool evaluate = true;       // SpaceOptions::evaluate_slices
  bool map_symmetric = true;  // SpaceOptions::map_symmetric
};
std::vector<SpaceSlice> compute_slices(const Pair& pair, const std::vector<PlannedSlice>& plan,
                                       const SliceRules& rules, const ProgressReport& progress = {},
                                       KnownModels* models = nullptr);

// compute_topology, taking the side slices' models from `known` where they were built.
SpaceTopology compute_topology(const Pair& pair, const SlicedSpace& space,
                               const TopologyOptions& options, const KnownModels* known);

// Calls run(i, worker) for every i in [0, count), in parallel (`threads` as in SpaceOptions),
// with one Worker per thread, made as Worker(&pair); run must store by index to keep results
// independent of the thread count.
template <class Worker>
void for_each_index_parallel(const Pair& pair, size_t count, int threads,
                             const std::function<void(size_t, Worker&)>& run) {
  tbb::enumerable_thread_specific<Worker> workers(&pair);
  tbb::task_arena arena(arena_threads(threads));
  // Grain 1: slices differ widely in cost, so let the scheduler balance single ones.
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 1), [&](const auto& range) {
      Worker& worker = workers.local();
      for (size_t i = range.begin(); i != range.end(); ++i) run(i, worker);
    });
  });
}

// The same with a Slicer per thread.
void for_each_index_parallel(const Pair& pair, size_t count, int threads,
                             const std::function<void(size_t, Slicer&)>& slice_at);

// A thread's means of slicing: from scratch, or from a boundary model.
struct SliceWorker {
  explicit SliceWorker(const Pair* pair);
  // The slice at theta from `model` where it can be evaluated there (`evaluated`), else from
  // scratch; from scratch when model is null.
  Slice slice(const BoundaryModel* model, double theta, bool& evaluated);

  const Pair& pair;
  Slicer slicer;
  ContactMaker contacts;
  SliceFromModelScratch scratch;
};

// The boundary model of an interval's representative slice, when it reproduces that slice's
// structure (model_reproduces); only then may it stand in for the interval's other slices.
std::optional<BoundaryModel> checked_model(const Pair& pair, const Slice& representative);

// Slice i to slice i + 1, and the last back to the first.
std::vector<SliceCorrespondence> slice_correspondences(const std::vector<SpaceSlice>& slices);

}  // namespace cslice::detail
