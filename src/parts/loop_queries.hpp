// Loop-level queries shared by part construction, validation and the placement test.
#pragma once

#include <span>

#include "cslice/part.hpp"

namespace cslice {

// Signed area enclosed by a closed sequence of curves (positive when counterclockwise).
double loop_signed_area(std::span<const Curve> edges);

// True when p lies inside the region a closed sequence of curves encloses, whatever its
// orientation. Even-odd rule on the chord polygon, corrected by each arc's circular segment
// (the region between the chord and the arc), so arcs need no polygonisation. Points on the
// boundary give either answer.
bool loop_encloses(std::span<const Curve> edges, Vec2 p);

// Whether one curve of a closed walk toggles the even-odd parity of p (its chord crossed by
// the rightward ray from p, or p inside its circular segment; a full circle: inside its
// disc). loop_encloses is the parity of these over the walk.
bool toggles_parity(const Curve& c, Vec2 p);

// Distance from p to the nearest curve of the sequence.
double distance_to_curves(std::span<const Curve> edges, Vec2 p);

}  // namespace cslice
