// Pieces of compute_space shared with the space reader (space_reader.cpp), which rebuilds a
// space from a file by recomputing its slices at the stored orientations.
#pragma once

#include <functional>
#include <vector>

#include "cslice/space.hpp"

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

// The slices at the planned orientations, in parallel (`threads` as in SpaceOptions), each
// stored at its own index: the same whatever the thread count.
std::vector<SpaceSlice> compute_slices(const Pair& pair, const std::vector<PlannedSlice>& plan,
                                       int threads, const ProgressReport& progress = {});

// Calls slice_at(i, slicer) for every i in [0, count), in parallel (`threads` as in
// SpaceOptions), with one Slicer per thread; slice_at must store by index to keep results
// independent of the thread count.
void for_each_index_parallel(const Pair& pair, size_t count, int threads,
                             const std::function<void(size_t, Slicer&)>& slice_at);

// Slice i to slice i + 1, and the last back to the first.
std::vector<SliceCorrespondence> slice_correspondences(const std::vector<SpaceSlice>& slices);

}  // namespace cslice::detail
