// The sliced configuration space of a pair (paper sections 4, 7 and 2.6): the critical
// orientations, a slice at each, a representative slice in every open interval between two
// consecutive ones, and intermediate slices close enough together that linear interpolation
// between neighbours stays within the pair's contact tolerance (docs/space-format.md).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cslice/critical.hpp"
#include "cslice/slice.hpp"

namespace cslice {

// Why a slice is in the space.
enum class SliceKind {
  critical,      // at a critical orientation
  interval,      // the representative of an open interval: its middle
  intermediate,  // added so that consecutive slices are at most the interpolation step apart
};
std::string_view to_string(SliceKind k);

struct SpaceSlice {
  double theta = 0.0;  // in [-pi, pi)
  SliceKind kind = SliceKind::interval;
  // Interval i runs from critical orientation i to critical orientation i + 1 (the last one
  // wraps past pi to the first). A critical slice records the interval it starts. With no
  // critical orientation there is one interval, the whole turn, starting at -pi.
  int interval = 0;
  Slice slice;
};

// A feature pair, the label of a contact segment (paper section 4).
struct SegmentLabel {
  int moving_feature = 0;
  int fixed_feature = 0;
  friend auto operator<=>(const SegmentLabel&, const SegmentLabel&) = default;
};

// How the realizable contact segments of slice `from` correspond to those of the next slice
// `to` (by theta, cyclically: the last slice's successor is the first), by label.
struct SliceCorrespondence {
  int from = 0, to = 0;                                  // indices into SlicedSpace::slices
  std::vector<SegmentLabel> kept, appearing, vanishing;  // each sorted
};

struct SpaceOptions {
  CriticalOptions critical;
  int threads = 0;  // slices computed at once; 0 lets oneTBB choose (every core)
};

struct SlicedSpace {
  CriticalSet criticals;
  // The largest angle between consecutive slices of an interval (radians), and the reach it
  // was derived from (space.cpp, interpolation_step).
  double max_step = 0.0;
  double reach = 0.0;
  std::vector<SpaceSlice> slices;                   // sorted by theta
  std::vector<SliceCorrespondence> correspondence;  // slice i to slice (i + 1) mod n
  // Wall-clock seconds: not part of the result, and the only thing that varies between runs.
  double seconds_criticals = 0.0;
  double seconds_slices = 0.0;
};

// The farthest any point P + R(theta) Q of a contact curve of the pair can lie from its
// centre of turning: max |Q| over every defining point (docs/space-format.md).
double contact_reach(const Pair& pair);

// The interpolation step for a reach and tolerance: sqrt(8 tol / reach), capped at pi / 2.
double interpolation_step(double reach, double tolerance);

SlicedSpace compute_space(const Pair& pair, const SpaceOptions& options = {});

// The labels of the realizable contact segments of a slice, sorted and without repeats.
std::vector<SegmentLabel> realizable_labels(const Slice& slice);

// The space as JSON text (format "cslice-space", version 1; docs/space-format.md), ending in
// a newline. Without timing the text depends only on the pair and the options' screening.
std::string space_to_json(const Pair& pair, const SlicedSpace& space, bool with_timing = true);

}  // namespace cslice
