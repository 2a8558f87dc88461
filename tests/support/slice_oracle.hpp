// A slice against the direct placement test: the check the slice tests make on a few pairs
// and the stress driver on many.
#pragma once

#include <random>
#include <string>

#include "cslice/pair.hpp"

namespace cslice::testkit {

// Computes the slice of `pair` at theta and expects each free component's sample not blocked
// by `classify` (and, with sample_clearance, farther than the geometric epsilon from contact),
// and membership in a free component to agree with `classify` at `points` random points
// around the pair, except where `classify` says contact. Returns how many points were
// decisive (not contact); stops at the first failure. Measuring each sample's clearance takes
// time quadratic in the parts' sizes: large pairs may skip it.
int check_slice_against_classify(const Pair& pair, double theta, int points, std::mt19937& rng,
                                 const std::string& what, bool sample_clearance = true);

}  // namespace cslice::testkit
