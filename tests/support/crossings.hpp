// The 3D topology's joins across critical orientations, checked by carrying configurations
// across in steps their clearance proves free (independently of src/space/topology.cpp; the
// test of the topology and the stress driver use it). Slivers thinner than the contact
// tolerance are where the joins went wrong, and classify's band cannot see them.
#pragma once

#include <string>

#include "cslice/space.hpp"

namespace cslice::testkit {

// Carries the free configuration (p, from) to orientation `to` (unwrapped: within pi of
// `from`) by free vertical segments, each short enough that blocked space, which creeps by at
// most the moving part's reach per radian, cannot cover p's clearance in its slice less the
// slice's epsilon; within each slice p moves to its component's sample (a free path there).
// Returns the component of the slice at `to` where it lands, -1 where it leaves free space or
// a step gets shorter than the angular tolerance (a component shrinking to nothing); with
// `landed`, that component's sample (to find it in a slice made another way, whose
// components may come in another order).
int carry_finely(const Pair& pair, Vec2 p, double from, double to, Vec2* landed = nullptr);

// Carries every free component of the stored slice next to critical slice `at` (after it when
// from_after, else before it, cyclically) across to the stored slice on the other side, and
// expects each that gets there to land in a component of its own 3D component. Returns how
// many got there.
int expect_crossings_joined(const Pair& pair, const SlicedSpace& space, int at, bool from_after,
                            const std::string& what);

// The converse, for false joins: carries every free component of both stored slices next to
// critical slice `at` across (as above, expecting each joined where it lands), and expects the
// cells of every event of the topology's transition there to be joined by those carries.
// Returns how many cells of the events no carry joins to the rest (each a failure: a join the
// sample rules made that nothing carried confirms, or a component too thin to carry through).
// A cell whose component next to the critical slice is thinner than that slice's epsilon band
// (its sample does not locate) cannot start a carry and is left out of the check.
int expect_joins_witnessed(const Pair& pair, const SlicedSpace& space, int at,
                           const std::string& what);

}  // namespace cslice::testkit
