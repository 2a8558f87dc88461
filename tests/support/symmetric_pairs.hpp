// Random pairs with symmetries (include/cslice/symmetry.hpp, docs/symmetry.md): star-shaped
// loops whose edges are straight or gently curved arcs, drawn symmetric under a mirror or
// under quarter turns, for the tests of symmetric pairs and cslice_stress --symmetric.
#pragma once

#include <array>
#include <random>
#include <vector>

#include "cslice/geometry.hpp"
#include "support/random_parts.hpp"

namespace cslice::testkit {

// A loop's vertices [x, y, bulge of the edge that starts there].
using SymmetricLoop = std::vector<std::array<double, 3>>;

// A star around the origin symmetric under y -> -y: k vertices at angles in (0, pi) with
// radii in [r0, r1], their mirror images, and bulges of -0.1, 0 or 0.1 (a mirrored edge keeps
// its bulge, as the mirror and the reversal of the loop both negate it).
SymmetricLoop mirror_star(std::mt19937& rng, int k, double r0, double r1);

// A star around the origin symmetric under quarter turns: k vertices per quarter.
SymmetricLoop quarter_star(std::mt19937& rng, int k, double r0, double r1);

// The loop turned by `turns` quarter turns and moved to `centre` (by one rounded addition, so
// that the symmetry about the centre holds to round-off only), as JSON [[x, y, b], ...].
std::string placed_loop_json(const SymmetricLoop& loop, int turns, Vec2 centre);

// The pair of one moving and one fixed loop (JSON, as placed_loop_json gives them), the
// fixed part an enclosure when asked.
RandomPair symmetric_pair_of(const std::string& moving, const std::string& fixed, bool enclosure,
                             const std::string& name);

// The pair cslice_stress --symmetric draws for `seed`, by seed % 4: a mirror-symmetric moving
// star around an obstacle symmetric under quarter turns (theta -> theta + k pi / 2) or under
// a mirror (theta -> pi - theta), or inside such an opening of an enclosure; the fixed part's
// centre off the origin. Drawn again until the reader accepts it.
RandomPair symmetric_pair(unsigned seed);

}  // namespace cslice::testkit
