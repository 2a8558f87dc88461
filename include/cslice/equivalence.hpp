// Slice equivalence (paper section 4): two slices are equivalent when their contact graphs
// are isomorphic by an isomorphism that maps each node to one with the same label, the
// feature pair (moving feature, fixed feature) of its contact segment.
#pragma once

#include <string>

#include "cslice/slice.hpp"

namespace cslice {

struct EquivalenceResult {
  bool equivalent = false;
  // When not equivalent: the first difference found, in words (empty otherwise).
  std::string difference;
};

// Exact test: label multisets, then colour refinement of nodes by their labelled
// neighbourhoods, then a search for an isomorphism within the colour classes.
EquivalenceResult slices_equivalent(const Slice& a, const Slice& b);

}  // namespace cslice
