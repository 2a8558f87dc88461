// A slice against the direct placement test: the check the slice tests make on a few pairs
// and the stress driver on many.
#pragma once

#include <random>
#include <string>

#include "cslice/slice.hpp"

namespace cslice::testkit {

// Computes the slice of `pair` at theta and expects each free component's sample not blocked
// by `classify` (and, with sample_clearance, farther than the geometric epsilon from contact),
// and membership in a free component to agree with `classify` at `points` random points
// around the pair, except where `classify` says contact. Returns how many points were
// decisive (not contact); stops at the first failure. Measuring each sample's clearance takes
// time quadratic in the parts' sizes: large pairs may skip it.
int check_slice_against_classify(const Pair& pair, double theta, int points, std::mt19937& rng,
                                 const std::string& what, bool sample_clearance = true);

// The same checks on a slice already made (a stored slice of a sliced space).
int check_slice_against_classify(const Pair& pair, const Slice& slice, int points,
                                 std::mt19937& rng, const std::string& what,
                                 bool sample_clearance = true);

// A slice made another way (evaluated from a boundary model) against the slice computed from
// scratch at its theta: the same contact segments (those of no length aside), the free components matched through
// their samples both ways with the same boundedness and area, the same realizable labels,
// contact graph (by label), degenerate contacts (by count) and blocked area. Pieces and
// components may come in another order.
void expect_same_slice(const Pair& pair, const Slice& other, const Slice& computed,
                       const std::string& what);

// Just beside the middle of every boundary piece, classify sees free space on the
// component's side (the piece's left) and blocked space on the other, where no other piece
// comes near: the boundary lies where contact really is. Returns the sides tested.
int expect_boundary_sides_agree_with_classify(const Pair& pair, const Slice& slice,
                                              const std::string& what);

}  // namespace cslice::testkit
