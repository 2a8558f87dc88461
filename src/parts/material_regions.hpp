// Regions of a part's material standing on its straight edges: where a point of the other
// part is sure to overlap this one. The slice uses them to prove contact segments blocked
// (slice/blocked_proof.hpp).
#pragma once

#include <vector>

#include "cslice/part.hpp"

namespace cslice {

// The region standing on one straight edge: above the edge (on its material side) by less
// than `depth`, between the bisectors of the corners at its ends. In the edge's own frame (x
// along it from its start, y across into the material), start_side and end_side are the
// unit bisector directions at its start and end, and the region is
//   0 < y < depth,  cross(start_side, (x, y)) < 0,  cross(end_side, (x - length, y)) > 0.
// The regions of neighbouring edges meet along their common bisector, so together they line
// the boundary; at a reflex corner they reach past the edge's end, over the corner.
struct MaterialRegion {
  double depth = 0.0;  // 0: no region (arcs, vertices, edges at a cusp or hemmed in by arcs)
  Vec2 start_side, end_side;
  // Where the corner sides reach `height`, in the edge's frame (edge of length `length`).
  Vec2 start_at(double height) const { return start_side * (height / start_side.y); }
  Vec2 end_at(double height, double length) const {
    return Vec2{length, 0.0} + end_side * (height / end_side.y);
  }
};

// Per feature of the part, in feature order. Each straight edge's region is as deep as no
// other edge of the part comes within `margin` of it (so every point of the region higher
// than margin and lower than depth - margin lies farther than margin, less a thousandth of
// it, inside the material), and at most twice the edge's length: deeper regions prove few more
// contact segments blocked and cost more to search (docs/performance.md, sixteenth session).
std::vector<MaterialRegion> material_regions(const Part& part, double margin);

}  // namespace cslice
