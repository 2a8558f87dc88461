// Random test pairs: star-shaped loops whose edges are straight or gently curved arcs,
// optionally with a hole, serialised to the pair format so they go through the reader.
#pragma once

#include <optional>
#include <random>
#include <string>

#include "cslice/pair.hpp"

namespace cslice::testkit {

struct RandomLoopOptions {
  int vertices = 8;
  double radius = 1.0;        // mean distance of vertices from the centre
  double roughness = 0.4;     // radial jitter, as a fraction of the radius
  double arc_fraction = 0.5;  // share of edges that are arcs
  double max_bulge = 0.35;    // |bulge| of arcs (tan of a quarter of their sweep)
  Vec2 center;
};

// JSON of one loop, e.g. "[[x,y,b],...]": a star-shaped polygon with arc edges.
std::string random_loop_json(std::mt19937& rng, const RandomLoopOptions& options);

// A random valid pair (retries until the reader accepts it); `holes` adds a hole to the
// fixed part. Returns the JSON text too, for failure messages.
struct RandomPair {
  Pair pair;
  std::string json;
};
RandomPair random_pair(std::mt19937& rng, int moving_vertices, int fixed_vertices, bool holes);

// The pair cslice_stress (tests/stress) draws for `seed`: random_pair from std::mt19937(seed)
// with 3 to 8 moving and 4 to 11 fixed vertices, a hole in every third. Tests name the seeds
// of stress runs' failures by it.
RandomPair stress_pair(unsigned seed);

// A tight fit, number k of a series drawn from rng: a random star-shaped moving part (4 to 7
// vertices) in a star-shaped opening of an enclosure (even k) or a hole in a square (odd k)
// 1.15 to 1.55 times its size, drawn again until some slice has free space.
Pair tight_pair(std::mt19937& rng, int k);

}  // namespace cslice::testkit
