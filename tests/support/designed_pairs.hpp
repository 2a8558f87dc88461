// Designed pairs: the coincidences of machined parts, which random parts never have. Edges on
// a unit grid (parallel edges sliding along each other, perfect fits in openings of the same
// width, three contacts through one point), regular polygons spinning in discs and polygons
// of their own size, discs and stadiums in slots of exactly their width, rounded rectangles
// in openings with equal corner radii, interlocking combs. Every sixth to third pair is
// turned by an arbitrary angle, which leaves the coincidences off by round-off only.
#pragma once

#include "support/random_parts.hpp"

namespace cslice::testkit {

// The designed pair number `seed` (its kind is seed % 6; the JSON names it), drawn again
// until the reader accepts it.
RandomPair designed_pair(unsigned seed);

}  // namespace cslice::testkit
