// A slice written out for other programs: the JSON format documented in
// docs/slice-format.md. Lives apart from the core: nothing in the geometry depends on it.
#pragma once

#include <set>
#include <string>

#include "cslice/pair.hpp"
#include "cslice/slice.hpp"

namespace cslice {

// "vertex 3 of loop 0", "segment 2 of loop 1", "arc 0 of loop 2": a feature of `part` named
// as the pair file lists it (loop and vertex numbers from the file, 0-based, even when the
// reader reversed the loop to put the material on its left). Out-of-range indices give
// "feature N".
std::string describe_feature(const Part& part, int feature);

// realizable_segments (slice.hpp) as a set, for look-ups by id.
std::set<int> realizable_segment_ids(const Slice& slice);

// The slice as JSON text (format "cslice-slice", version 1), ending in a newline.
std::string slice_to_json(const Pair& pair, const Slice& slice);

}  // namespace cslice
