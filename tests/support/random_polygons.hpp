// Random simple polygons (and polygon-like loops with arc edges) as pair-format loops, for
// oracles and benchmarks that need parts whose shape is known independently of cslice:
//   - star-shaped loops: vertices at increasing angles around a centre, each at a random
//     radius; rough (independent radii: spiky, non-convex) or smooth (a few random lobes
//     sampled densely: locally convex or concave, like a machined contour), optionally with
//     arc edges that follow the smooth contour;
//   - combs: a base bar with teeth whose tips carry caps, so the pockets between teeth have
//     narrow mouths and a small part placed in a pocket cannot get out (the Minkowski sum of
//     the comb and that part has holes).
// Every generator draws from the std::mt19937 it is given and nothing else (through
// std::uniform_real_distribution only), so a seed fixes the output for a given standard
// library.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "cslice/pair.hpp"

namespace cslice::testkit {

// One vertex of a loop: the edge starting here is straight (bulge 0) or an arc with
// bulge = tan(sweep / 4).
struct LoopVertex {
  double x = 0.0;
  double y = 0.0;
  double bulge = 0.0;
};
using LoopVertices = std::vector<LoopVertex>;

struct StarOptions {
  int vertices = 8;
  double radius = 1.0;         // mean distance of the vertices from the centre
  double radial_jitter = 0.3;  // independent radius noise per vertex, fraction of the radius
  double angle_jitter = 0.8;   // vertex angle noise, fraction of the angular spacing (< 1)
  int lobes = 0;               // harmonics of the smooth contour (0: a circle)
  double lobe_depth = 0.0;     // total relative amplitude of the harmonics (< 1 - jitter)
  // Arc edges: each edge becomes an arc with this probability. Its sweep follows the
  // smooth contour (the mean of the turns at its two ends), scaled by a random factor in
  // [1 - bulge_noise, 1 + bulge_noise], so curved loops stay nearly tangent-continuous.
  double arc_fraction = 0.0;
  double bulge_noise = 0.5;
  // Arcs that would lie closer than this to their chord (a length) stay straight: the reader
  // rejects arcs within its geometric tolerance of the chord (near the contour's inflections,
  // or on very fine loops).
  double min_sagitta = 0.0;
  Vec2 center;
};

// A counterclockwise star-shaped loop. With arc_fraction 0 it is a simple polygon; with
// arcs, simple whenever the turns between neighbouring edges are small (smooth contours):
// pass it through parse_pair, which validates, when in doubt.
LoopVertices random_star(std::mt19937& rng, const StarOptions& options);

// The lobed star pairs of the benchmarks, and of tests that reproduce them: a fixed star of
// radius 3 about the origin and a moving one of radius 1 centred at (0.1, -0.2) off its body
// origin, both with three lobes of depth 0.3 and `vertices` vertices, radii jittered by
// `radial_jitter` (a fraction of the radius), a share `arc_fraction` of the edges arcs.
// The fixed star is drawn first.
struct StarPairLoops {
  LoopVertices moving, fixed;
};
StarPairLoops lobed_star_pair(std::mt19937& rng, int vertices, double radial_jitter,
                              double arc_fraction);

// The first lobed star pair the reader accepts among those drawn by std::mt19937(first_seed +
// k * seed_step) for k = 0 .. tries - 1 (the benchmarks', curved_star_pair's and the stress
// driver's draws), with its loops and JSON (named `name`); throws when none is accepted.
struct AcceptedStarPair {
  StarPairLoops loops;
  std::string json;
  Pair pair;
};
AcceptedStarPair accepted_star_pair(int vertices, double radial_jitter, double arc_fraction,
                                    unsigned first_seed, unsigned seed_step, int tries,
                                    const std::string& name);

struct CombOptions {
  int teeth = 3;
  // The width of the part meant to get caught: pocket mouths are drawn around it (some
  // narrower, some wider), pocket interiors wider than it, teeth taller than it.
  double part_size = 1.0;
  double cap_probability = 0.85;  // chance that a tooth carries a cap (else a plain stem)
  double turn = 0.0;              // rotation of the whole comb about the origin (radians)
  Vec2 offset;                    // then a translation
};

// A counterclockwise comb: 4 + 8 * teeth vertices, all edges straight.
LoopVertices random_comb(std::mt19937& rng, const CombOptions& options);

// A counterclockwise rectangle of sides w x h centred at `center`, turned by `turn`.
LoopVertices rectangle(double w, double h, Vec2 center = {}, double turn = 0.0);

// A counterclockwise gear of `teeth` straight-flanked teeth about the origin, tooth 0 centred
// on the angle `phase`: tips are arcs of radius `tip` spanning `tip_half` radians either side
// of a tooth's centre, roots arcs of radius `root` between flanks that leave it `root_half`
// radians either side. With tip < root the teeth point inwards: the opening of a ring gear
// (make the fixed part an enclosure).
struct GearShape {
  int teeth = 8;
  double tip = 1.0, root = 0.8;
  double tip_half = 0.1, root_half = 0.15;
  double phase = 0.0;
};
LoopVertices gear(const GearShape& shape);
// The pair file's text of a gear of `teeth` about the origin (tips at `tip`, roots at `root`)
// inside the opening of a ring gear of `ring_teeth` (tips at `ring_tip`, roots at
// `ring_root`), both straight-flanked with the proportions of examples/drawings/gear-in-ring.dxf
// (scripts/make-gear-drawing.py); `tolerance` 0 leaves the default.
std::string gear_in_ring_json(int teeth, double tip, double root, int ring_teeth, double ring_tip,
                              double ring_root, double tolerance = 0.0);

// Signed area enclosed by a loop (positive counterclockwise), arcs included.
double loop_area(const LoopVertices& loop);

// JSON of one loop, "[[x,y,b],...]", with round-trip precision (17 digits): parse_pair
// reads back exactly these doubles.
std::string loop_json(const LoopVertices& loop);

// A whole pair file as JSON text.
std::string pair_json(const std::string& name, const std::vector<LoopVertices>& moving,
                      const std::vector<LoopVertices>& fixed);

// Parses pair_json(...) output; throws std::runtime_error with the reader's message when
// the reader rejects it.
Pair parse_or_throw(const std::string& json, const std::string& source);

// The random curved pair of bench_critical's BM_CriticalCurved/<vertices>: lobed_star_pair
// with radii jittered 10% and half the edges arcs, drawn by std::mt19937(seed + vertices) for
// the first seed from 2026 whose pair the reader accepts (4 * vertices features).
Pair curved_star_pair(int vertices);

// bench_critical's gear pair: a gear of `teeth` teeth in a ring gear of twice as many, with the
// proportions of examples/drawings/gear-in-ring.dxf scaled with the teeth (24 * teeth features,
// symmetric under turns by 2 pi / teeth and mirrors; tolerance 0.001).
Pair gear_pair(int teeth);

// make(n), made at the first call for that maker and n and kept for the process: benchmarks
// ask for the same pair in every run, outside their timed loops. Not thread-safe.
const Pair& made_once(Pair (*make)(int), int n);

}  // namespace cslice::testkit
