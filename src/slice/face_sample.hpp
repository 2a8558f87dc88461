// A point strictly inside a face of an arrangement, far from its boundary.
#pragma once

#include <span>
#include <vector>

#include "cslice/tolerance.hpp"
#include "slice/arrangement.hpp"

namespace cslice {

// Buffers of face_sample, kept between calls.
struct FaceSampleScratch {
  std::vector<Curve> curves;
  std::vector<double> xs;
};

// A point inside the region the closed curves bound (`box` their bounding box): the midpoint
// of the widest inside interval on each of a few scan lines, keeping the one farthest from
// the curves. `xs` is scratch.
Vec2 sample_inside(std::span<const Curve> curves, const Box& box, std::vector<double>& xs);

// A point beyond every curve inside `box`: the sample of an unbounded region.
Vec2 sample_beyond(const Box& box, const Tolerances& tol);

// For a bounded face: the midpoint of the widest inside interval on each of a few scan
// lines, keeping the one farthest from the boundary. For the unbounded face: a point beyond
// every cycle. `box` is the union of the face's cycles' boxes, in face_cycles order.
Vec2 face_sample(const Arrangement& arr, int face, const Box& box, const Tolerances& tol,
                 FaceSampleScratch& scratch);

}  // namespace cslice
