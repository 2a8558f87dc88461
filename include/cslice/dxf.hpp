// CAD drawings in and out (docs/dxf-import.md). In: drawing.hpp reads DXF (and SVG) drawings
// as pair files. Out: a slice's free-space boundary as exact lines and arcs.
#pragma once

#include <string>

#include "cslice/drawing.hpp"
#include "cslice/pair.hpp"
#include "cslice/slice.hpp"

namespace cslice {

// The slice as a DXF drawing (R12, ASCII): each free component's boundary cycles as closed
// POLYLINEs with bulges (a whole circle as a CIRCLE) on layer FREE_<id>, perfect fits as POINTs
// on PERFECT_FIT, sliding fits as LINEs and ARCs on SLIDING_FIT. Coordinates are the moving
// part's body origin's, in the pair's units.
std::string slice_to_dxf(const Pair& pair, const Slice& slice);

}  // namespace cslice
