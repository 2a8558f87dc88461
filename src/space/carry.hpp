// Samples carried across a critical orientation (src/space/topology.cpp, docs/space-format.md,
// Joins by carrying): from a component of the critical slice to the side slice, along free
// vertical segments, through slices inside the side's interval.
#pragma once

#include <functional>
#include <vector>

#include "cslice/slice.hpp"

namespace cslice::detail {

// How far a component's sample lies from its boundary; infinite with no boundary.
double sample_clearance(const Slice& s, int component);

// Steps a sample may take before it is given up: each turns by half the sample's clearance
// over the reach, and a thin component growing away from the critical orientation at a small
// fraction of the reach per radian multiplies its clearance by little per step (stress seed
// 107007: 620 steps across 1e-3 rad from a triangle of area 3e-13).
inline constexpr int kMaxCarrySteps = 1000;

// A sample being carried: its component in the slice it starts from, where it is and its
// clearance there, the turn that clearance allows, the steps taken (in such turns: a sample
// carried along at a thinner one's pace counts the steps it would have taken alone), and the
// component of the target slice where it landed (-1 while on its way, or when lost).
struct CarriedSample {
  int component = 0;
  Vec2 p;
  double clearance = 0.0;
  double own_turn = 0.0;
  double steps = 0.0;
  int landed = -1;
  bool active = true;
};

// Carries the samples (of components of slice `from`) to the orientation of slice `to`:
// each step turns by at most half a sample's clearance less eps over `reach` (the moving
// part's), so blocked space, which creeps by at most the reach per radian, cannot get there;
// within each slice the point moves to its component's sample, a free path there. Once a
// sample's clearance exceeds the reach times the turn left, its sample rule holds for the rest
// of the way and it is located in `to`. The samples step together, by the least of their
// turns, so that one slice serves them all (a turn smaller than a sample's own is as safe):
// thin pockets side by side, as a gear's meshing positions, would otherwise each step through
// slices of their own. A sample is lost when it leaves free space, when its turn falls to the
// angular tolerance or its steps run out (a component shrinking to nothing at the critical
// orientation). `slice_at(theta)` gives the slices between; returns how many it gave.
int carry_samples(const Slice& from, std::vector<CarriedSample>& carried, const Slice& to,
                  double reach, double angular_tolerance,
                  const std::function<Slice(double theta)>& slice_at);

}  // namespace cslice::detail
