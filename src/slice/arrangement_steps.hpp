// Steps of ArrangementBuilder::build that need only the arrangement itself (kept apart from
// arrangement.cpp for its length).
#pragma once

#include <vector>

#include "slice/arrangement.hpp"

namespace cslice {

// Groups the half-edges by origin into arr.outgoing_start and arr.outgoing_edges, each
// vertex's in increasing half-edge order; `fill` is a buffer.
void group_by_origin(Arrangement& arr, std::vector<int>& fill);

}  // namespace cslice
