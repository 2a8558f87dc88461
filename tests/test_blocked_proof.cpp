// Contact segments proven blocked and left out of the arrangement (slice/blocked_proof.hpp):
// the material regions they rest on lie inside the material with the margin to spare, every
// segment proven blocked is blocked by the direct placement test, and slices with the proof
// give the same free space, realizable segments and contact graph as slices without.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "cslice/classify.hpp"
#include "cslice/slice.hpp"
#include "parts/loop_queries.hpp"
#include "parts/material_regions.hpp"
#include "slice/blocked_proof.hpp"
#include "support/designed_pairs.hpp"
#include "support/random_parts.hpp"
#include "support/random_polygons.hpp"

using namespace cslice;

namespace {

Pair parse(const std::string& json) {
  LoadResult r = parse_pair(json, "test");
  if (!r.ok()) throw std::runtime_error(r.error->message());
  return std::move(*r.pair);
}

// A rough lobed star pair (the benchmarks' rough stars), n vertices per part; with
// arc_fraction, that share of the edges arcs.
Pair rough_star_pair(int n, unsigned seed, double arc_fraction = 0.0) {
  for (;; ++seed) {
    std::mt19937 rng(seed);
    const testkit::StarPairLoops loops =
        testkit::lobed_star_pair(rng, n, 0.3 * kTwoPi / n, arc_fraction);
    LoadResult r =
        parse_pair(testkit::pair_json("star", {loops.moving}, {loops.fixed}), "rough star");
    if (r.ok()) return std::move(*r.pair);
  }
}

// Restores the automatic mode when a test ends, however it ends.
struct ModeGuard {
  ~ModeGuard() { set_blocked_proof_mode(BlockedProofMode::automatic); }
};

Slice slice_with(const Pair& pair, double theta, BlockedProofMode mode) {
  set_blocked_proof_mode(mode);
  Slice s = compute_slice(pair, theta);
  set_blocked_proof_mode(BlockedProofMode::automatic);
  return s;
}

// The contact segments proven blocked at theta, found as the slice finds them.
std::vector<char> proven_at(const Pair& pair, double theta) {
  BlockedProof proof;
  std::vector<char> proven;
  proof.find(contact_segments(pair, theta), pair_regions(pair), proof_margin(pair), proven);
  return proven;
}

const MaterialRegion& region_of_edge(const Part& part, const std::vector<MaterialRegion>& r,
                                     int loop, int edge) {
  for (size_t f = 0; f < part.features.size(); ++f)
    if (part.features[f].kind == FeatureKind::segment && part.features[f].loop == loop &&
        part.features[f].index == edge)
      return r[f];
  throw std::runtime_error("no such edge");
}

}  // namespace

// A square's regions are the triangles under its centre, as deep as twice the side (no other
// edge enters them); a long thin rectangle's long edges reach only as deep as the other long
// edge, its short ones to the cap.
TEST(MaterialRegions, SquareAndThinRectangle) {
  const Pair pair = parse(
      R"({"moving": {"loops": [[[0,0],[2,0],[2,2],[0,2]]]},
          "fixed": {"loops": [[[0,0],[10,0],[10,1],[0,1]]]}})");
  const double margin = 1e-9;
  const std::vector<MaterialRegion> square = material_regions(pair.moving, margin);
  const double h = std::sqrt(0.5);
  for (int e = 0; e < 4; ++e) {
    const MaterialRegion& r = region_of_edge(pair.moving, square, 0, e);
    EXPECT_NEAR(r.depth, 4.0, 1e-12) << "edge " << e;
    EXPECT_NEAR(r.start_side.x, h, 1e-12);
    EXPECT_NEAR(r.start_side.y, h, 1e-12);
    EXPECT_NEAR(r.end_side.x, -h, 1e-12);
    EXPECT_NEAR(r.end_side.y, h, 1e-12);
  }
  const std::vector<MaterialRegion> thin = material_regions(pair.fixed, margin);
  EXPECT_NEAR(region_of_edge(pair.fixed, thin, 0, 0).depth, 1.0, 1e-12);
  EXPECT_NEAR(region_of_edge(pair.fixed, thin, 0, 2).depth, 1.0, 1e-12);
  EXPECT_NEAR(region_of_edge(pair.fixed, thin, 0, 1).depth, 2.0, 1e-12);
  // Vertices have none.
  for (size_t f = 0; f < pair.fixed.features.size(); ++f)
    if (pair.fixed.features[f].kind == FeatureKind::vertex) {
      EXPECT_EQ(thin[f].depth, 0.0);
    }
}

// Points of a region lower than its depth less the margin lie inside the material, farther
// than the margin from its boundary: random rough stars (reflex and convex corners), some
// with arcs, the random curved pairs (holes), and gears whose straight flanks run between
// arcs, the ring an enclosure.
TEST(MaterialRegions, RegionsLieInsideTheMaterialWithTheMargin) {
  std::mt19937 rng(7);
  std::vector<Pair> pairs;
  for (int n : {12, 40, 100}) pairs.push_back(rough_star_pair(n, 100 + unsigned(n)));
  for (int n : {30, 80}) pairs.push_back(rough_star_pair(n, 150 + unsigned(n), 0.5));
  for (int i = 0; i < 12; ++i)
    pairs.push_back(testkit::random_pair(rng, 5 + i, 6 + i, i % 2 == 0).pair);
  // Straight flanks between arcs (tips and roots), the ring gear an enclosure.
  pairs.push_back(parse(testkit::gear_in_ring_json(8, 5.0, 2.75, 16, 7.0, 9.25, 0.001)));
  int tested = 0, beside_arcs = 0;
  for (const Pair& pair : pairs)
    for (const Part* part : {&pair.moving, &pair.fixed}) {
      const double margin = 1e-3 * pair.tol.size;
      const std::vector<MaterialRegion> regions = material_regions(*part, margin);
      std::vector<Curve> boundary;
      for (const Loop& l : part->loops)
        boundary.insert(boundary.end(), l.edges.begin(), l.edges.end());
      for (size_t f = 0; f < part->features.size(); ++f) {
        const MaterialRegion& r = regions[f];
        if (r.depth <= 2.0 * margin) continue;
        const Feature& feature = part->features[f];
        const Loop& loop = part->loops[size_t(feature.loop)];
        const Curve& e = loop.edges[size_t(feature.index)];
        const size_t count = loop.edges.size();
        const bool arc_beside =
            !loop.edges[(size_t(feature.index) + 1) % count].is_segment() ||
            !loop.edges[(size_t(feature.index) + count - 1) % count].is_segment();
        const Vec2 along = normalized(e.to - e.from), across = perp_left(along);
        const double length = distance(e.from, e.to);
        std::uniform_real_distribution<double> y(margin, r.depth - margin);
        std::uniform_real_distribution<double> x(-r.depth * 4.0, length + r.depth * 4.0);
        for (int k = 0, found = 0; k < 400 && found < 20; ++k) {
          const Vec2 q{x(rng), y(rng)};
          if (!(cross(r.start_side, q) < 0.0 && cross(r.end_side, q - Vec2{length, 0.0}) > 0.0))
            continue;
          ++found;
          ++tested;
          beside_arcs += arc_beside ? 1 : 0;
          const Vec2 p = e.from + q.x * along + q.y * across;
          int inside = 0;
          for (const Loop& l : part->loops) inside += loop_encloses(l.edges, p) ? 1 : 0;
          const bool material = (inside % 2 == 1) != part->enclosure;
          ASSERT_TRUE(material) << "edge " << f << " at (" << q.x << ", " << q.y << ")";
          // The margin less a thousandth where arcs are near (material_regions.hpp).
          ASSERT_GT(distance_to_curves(boundary, p), 0.999 * margin) << "edge " << f;
        }
      }
    }
  EXPECT_GT(tested, 5000);
  EXPECT_GT(beside_arcs, 500);
}

// Every contact segment proven blocked is blocked all along by the direct placement test,
// and so are its points moved by the margin (less a hair) to either side: across a line,
// along the radius of an arc (33 points, so that every eighth of an arc has inner points).
TEST(BlockedProof, ProvenSegmentsAreBlocked) {
  std::vector<Pair> pairs;
  for (int n : {30, 60, 100}) pairs.push_back(rough_star_pair(n, 200 + unsigned(n)));
  for (int n : {60, 150}) pairs.push_back(rough_star_pair(n, 250 + unsigned(n), 0.25));
  for (int teeth : {8, 16}) pairs.push_back(testkit::gear_pair(teeth));
  int proven_count = 0, by_arcs = 0, arcs = 0;
  for (const Pair& pair : pairs) {
    PlacementTester tester(pair);
    const double margin = proof_margin(pair);
    for (double theta : {0.0, 0.7, 2.1, 4.0}) {
      const std::vector<ContactSegment> segments = contact_segments(pair, theta);
      const std::vector<char> proven = proven_at(pair, theta);
      for (const ContactSegment& s : segments) {
        if (!proven[size_t(s.id)]) continue;
        ++proven_count;
        by_arcs += s.kind == ContactKind::arc_segment || s.kind == ContactKind::segment_arc;
        arcs += s.curve.is_arc() ? 1 : 0;
        for (int k = 0; k <= 32; ++k) {
          const Vec2 p = point_at(s.curve, k / 32.0);
          const Vec2 across = s.curve.is_arc() ? normalized(p - s.curve.center)
                                               : perp_left(normalized(s.curve.to - s.curve.from));
          for (double side : {0.0, 0.99, -0.99}) {
            const Vec2 q = p + side * margin * across;
            ASSERT_TRUE(tester.blocked({q.x, q.y, theta}))
                << "segment " << s.id << " at theta " << theta << ", " << k << "/32";
          }
        }
      }
    }
  }
  EXPECT_GT(proven_count, 1000);  // the rough stars prove most of theirs
  EXPECT_GT(by_arcs, 50);         // arcs on segments too
  EXPECT_GT(arcs, 500);           // and arc contact segments, the gears' most of all
}

// Slices computed with the proof and without agree: free components (count, boundedness,
// area), realizable segments, contact graph, blocked area; on rough stars (many segments
// proven), random curved pairs (few) and designed ones (parallel edges sliding along each
// other, perfect fits, symmetric parts: contact segments lying on other segments' slabs'
// edges, which only the margin keeps), with the proof forced on.
TEST(BlockedProof, SlicesAreTheSameWithAndWithoutIt) {
  ModeGuard guard;
  std::mt19937 rng(11);
  std::vector<Pair> pairs;
  for (int n : {20, 50, 120}) pairs.push_back(rough_star_pair(n, 300 + unsigned(n)));
  for (int n : {40, 100}) pairs.push_back(rough_star_pair(n, 350 + unsigned(n), 0.25));
  for (int i = 0; i < 20; ++i)
    pairs.push_back(testkit::random_pair(rng, 4 + i % 6, 5 + i % 7, i % 3 == 0).pair);
  for (unsigned seed = 1; seed <= 60; ++seed) pairs.push_back(testkit::designed_pair(seed).pair);
  for (int teeth : {8, 16}) pairs.push_back(testkit::gear_pair(teeth));
  int left_out = 0;
  for (size_t p = 0; p < pairs.size(); ++p) {
    const Pair& pair = pairs[p];
    for (double theta : {0.3, 1.1, 2.6, 5.0}) {
      const Slice with = slice_with(pair, theta, BlockedProofMode::always);
      const Slice without = slice_with(pair, theta, BlockedProofMode::never);
      const std::vector<char> proven = proven_at(pair, theta);
      left_out += int(std::count(proven.begin(), proven.end(), 1));
      const std::string where = "pair " + std::to_string(p) + " theta " + std::to_string(theta);
      ASSERT_EQ(with.contact_segments.size(), without.contact_segments.size()) << where;
      ASSERT_EQ(with.free_components.size(), without.free_components.size()) << where;
      for (size_t c = 0; c < with.free_components.size(); ++c) {
        const FreeComponent& a = with.free_components[c];
        const FreeComponent& b = without.free_components[c];
        EXPECT_EQ(a.bounded, b.bounded) << where;
        if (a.bounded) {
          EXPECT_NEAR(a.area, b.area, 1e-9 * pair.tol.size * pair.tol.size) << where;
        }
      }
      if (std::isinf(without.blocked_area)) {
        EXPECT_EQ(with.blocked_area, without.blocked_area) << where;
      } else {
        EXPECT_NEAR(with.blocked_area, without.blocked_area,
                    1e-9 * std::max(1.0, std::fabs(without.blocked_area)))
            << where;
      }
      EXPECT_EQ(realizable_segments(with), realizable_segments(without)) << where;
      EXPECT_EQ(with.contact_graph.nodes, without.contact_graph.nodes) << where;
      EXPECT_EQ(with.contact_graph.edges.size(), without.contact_graph.edges.size()) << where;
      EXPECT_EQ(with.degenerate.size(), without.degenerate.size()) << where;
    }
  }
  EXPECT_GT(left_out, 2000);
}

// Arcs against slabs built by hand: two vertex/segment contacts along y = 0 whose fixed edges'
// regions (depth 1, corner sides vertical) make the slabs 0 < x < 6 and 4 < x < 10 (margin
// 0.01 taken off their heights). An arc held by one slab is proven; one whose ends lie in a
// slab but whose middle rises above it is not; one crossing from one slab into the other,
// held by neither whole, is proven through its halves.
TEST(BlockedProof, ArcsAreHeldWholeOrByPieces) {
  const double margin = 0.01;
  PairRegions regions;
  regions.fixed.assign(2, MaterialRegion{1.0, {0.0, 1.0}, {0.0, 1.0}});
  auto line = [](int id, int fixed, Vec2 from, Vec2 to) {
    ContactSegment s;
    s.id = id;
    s.fixed_feature = fixed;
    s.kind = ContactKind::vertex_segment;
    s.curve = make_segment(from, to);
    return s;
  };
  // The arc of the circle through (x0, y_ends) and (x1, y_ends) rising to y_top, counterclockwise
  // from its right end.
  auto arc = [](int id, double x0, double x1, double y_ends, double y_top) {
    const double half = 0.5 * (x1 - x0), rise = y_top - y_ends;
    const double radius = (half * half + rise * rise) / (2.0 * rise);
    const Vec2 center{0.5 * (x0 + x1), y_top - radius};
    const double start = std::atan2(y_ends - center.y, x1 - center.x);
    ContactSegment s;
    s.id = id;
    s.kind = ContactKind::arc_arc;
    s.curve = make_arc(center, radius, start, kPi - 2.0 * start);
    return s;
  };
  std::vector<ContactSegment> segments = {
      line(0, 0, {0.0, 0.0}, {6.0, 0.0}), line(1, 1, {4.0, 0.0}, {10.0, 0.0}),
      arc(2, 1.0, 5.0, 0.3, 0.6),    // inside the first slab
      arc(3, 6.5, 9.5, 0.5, 1.2),    // ends inside the second, middle above it
      arc(4, 2.0, 8.0, 0.3, 0.5),    // across both: each half inside one
      arc(5, 2.0, 8.0, 0.3, 0.995),  // across both, its top within the margin of y = 1
  };
  // Two thirds of circles, open on the left: one reaching past the slab's bottom and top
  // (not proven), one whose missing third would have crossed x = 0 (proven).
  segments.push_back(segments[2]);
  segments.back().id = 6;
  segments.back().curve = make_arc({3.0, 0.5}, 0.55, -2.0 * kPi / 3.0, 4.0 * kPi / 3.0);
  segments.push_back(segments[2]);
  segments.back().id = 7;
  segments.back().curve = make_arc({0.3, 0.5}, 0.4, -2.0 * kPi / 3.0, 4.0 * kPi / 3.0);
  BlockedProof proof;
  std::vector<char> proven;
  proof.find(segments, regions, margin, proven);
  EXPECT_TRUE(proven[2]);
  EXPECT_FALSE(proven[3]);
  EXPECT_TRUE(proven[4]);
  EXPECT_FALSE(proven[5]);
  EXPECT_FALSE(proven[6]);
  EXPECT_TRUE(proven[7]);
}

// The automatic mode looks only where contact segments outnumber features: more than 4.5 to 1
// on polygon pairs (the rough star of 500 vertices per part, 7.9 per feature, not that of
// 300, 4.05), more than 2 to 1 where the parts have arcs (a gear of 8 teeth, 3.3).
TEST(BlockedProof, LooksWhereSegmentsOutnumberFeatures) {
  auto features = [](const Pair& pair) {
    return size_t(pair.moving.feature_count() + pair.fixed.feature_count());
  };
  const Pair rough = rough_star_pair(300, 400);
  EXPECT_TRUE(worth_proving(rough, 9 * features(rough) / 2 + 1));
  EXPECT_FALSE(worth_proving(rough, 9 * features(rough) / 2));
  EXPECT_FALSE(worth_proving(rough, contact_segments(rough, 0.7).size()));
  const Pair rougher = rough_star_pair(500, 400);
  EXPECT_TRUE(worth_proving(rougher, contact_segments(rougher, 0.7).size()));
  const Pair gear = testkit::gear_pair(8);
  EXPECT_TRUE(worth_proving(gear, 2 * features(gear) + 1));
  EXPECT_FALSE(worth_proving(gear, 2 * features(gear)));
  EXPECT_TRUE(worth_proving(gear, contact_segments(gear, 0.7).size()));
}

// The contact segments proven do not depend on the order the search meets the slabs in
// (each cell's slabs deepest first, a few at a time, the last target's slabs tried first):
// the same segments, shuffled and numbered again, are proven the same, on rough stars and
// on gears (arcs held by pieces).
TEST(BlockedProof, WhatIsProvenDoesNotDependOnTheSegmentsOrder) {
  std::mt19937 rng(5);
  std::vector<Pair> pairs;
  for (int n : {60, 150}) pairs.push_back(rough_star_pair(n, 500 + unsigned(n)));
  pairs.push_back(rough_star_pair(80, 580, 0.25));
  pairs.push_back(testkit::gear_pair(16));
  int proven_count = 0;
  for (const Pair& pair : pairs)
    for (double theta : {0.4, 2.9}) {
      const std::vector<ContactSegment> segments = contact_segments(pair, theta);
      const std::vector<char> proven = proven_at(pair, theta);
      std::vector<int> order(segments.size());
      std::iota(order.begin(), order.end(), 0);
      std::shuffle(order.begin(), order.end(), rng);
      std::vector<ContactSegment> shuffled;
      for (int id : order) {
        shuffled.push_back(segments[size_t(id)]);
        shuffled.back().id = int(shuffled.size()) - 1;
      }
      BlockedProof proof;
      std::vector<char> again;
      proof.find(shuffled, pair_regions(pair), proof_margin(pair), again);
      for (size_t k = 0; k < order.size(); ++k) {
        ASSERT_EQ(again[k], proven[size_t(order[k])]) << "segment " << order[k] << " at " << theta;
        proven_count += again[k];
      }
    }
  EXPECT_GT(proven_count, 2000);
}
