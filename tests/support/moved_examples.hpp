// The bundled examples moved as a whole, for invariance tests: what a user gets by drawing
// the same pair in other units, turned, or elsewhere on the sheet.
#pragma once

#include <string>

#include "cslice/geometry.hpp"
#include "cslice/pair.hpp"

namespace cslice::testkit {

// The pair file's text with every point of both parts scaled by `scale` about the origin, then
// turned by `angle` about it and shifted by `shift` (the moving part within its body frame).
// Bulges are unchanged by similarities; circles' radii and a tolerance given as a number scale
// with the points. The fixed part alone is then shifted by `fixed_offset`: every slice shifts
// with it, and the pair's size (measured from the body origin) grows, so do its tolerances: a
// drawing placed far from its origin. Throws if the result does not load.
Pair moved_pair(const std::string& json_text, const std::string& name, double scale, double angle,
                Vec2 shift, Vec2 fixed_offset = {});
// The same for a bundled example.
Pair moved_example(const std::string& name, double scale, double angle, Vec2 shift);

// The example seen in a mirror: x -> -x for both parts, so every arc turns the other way
// (bulges negated) and every loop runs the other way round (the reader orients loops).
Pair mirrored_example(const std::string& name);

// A pair read back from a drawing of `original` (tests of the DXF and SVG import): the same
// features, areas and contact tolerance, and the same placement by classify at 2,000 random
// configurations within the pair's size. Failures name `name`.
void expect_same_pair(const Pair& read, const Pair& original, const std::string& name,
                      unsigned seed);

}  // namespace cslice::testkit
