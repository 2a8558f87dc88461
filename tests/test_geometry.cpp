// Curves, intersections and distances: each intersection kind on each curve pair, the
// degenerate cases (parallel overlap, co-circular arcs, tangency, endpoint touches), and
// cross-checks of distances against dense sampling.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "cslice/geometry.hpp"
#include "geometry/box_pairs.hpp"
#include "parts/loop_queries.hpp"

using namespace cslice;

namespace {

constexpr double kEps = 1e-9;

Curve arc_deg(Vec2 c, double r, double start_deg, double sweep_deg) {
  return make_arc(c, r, start_deg * kPi / 180.0, sweep_deg * kPi / 180.0);
}

// Smallest distance between two curves by sampling both densely (an independent estimate).
double sampled_distance(const Curve& a, const Curve& b, int n = 2000) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i)
    best = std::min(best, distance_to_curve(b, point_at(a, double(i) / n)));
  for (int i = 0; i <= n; ++i)
    best = std::min(best, distance_to_curve(a, point_at(b, double(i) / n)));
  return best;
}

}  // namespace

TEST(Curve, BulgeArcHalfCircle) {
  const Curve c = make_bulge_arc({1, 0}, {-1, 0}, 1.0);
  EXPECT_NEAR(c.radius, 1.0, 1e-15);
  EXPECT_NEAR(c.center.x, 0.0, 1e-15);
  EXPECT_NEAR(c.center.y, 0.0, 1e-15);
  EXPECT_NEAR(c.sweep, kPi, 1e-15);
  const Vec2 mid = point_at(c, 0.5);
  EXPECT_NEAR(mid.x, 0.0, 1e-12);
  EXPECT_NEAR(mid.y, 1.0, 1e-12);  // counterclockwise from (1,0) passes through the top
  EXPECT_NEAR(curve_length(c), kPi, 1e-12);
}

TEST(Curve, BulgeArcClockwiseQuarter) {
  const double b = std::tan(-kPi / 8.0);  // quarter circle, clockwise
  const Curve c = make_bulge_arc({0, 1}, {1, 0}, b);
  EXPECT_NEAR(c.center.x, 0.0, 1e-12);
  EXPECT_NEAR(c.center.y, 0.0, 1e-12);
  EXPECT_NEAR(c.radius, 1.0, 1e-12);
  EXPECT_LT(c.sweep, 0.0);
  const Vec2 mid = point_at(c, 0.5);
  EXPECT_NEAR(mid.x, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(mid.y, std::sqrt(0.5), 1e-12);
}

TEST(Curve, BoundingBoxIncludesAxisExtremes) {
  const Box b = bounding_box(make_bulge_arc({1, 0}, {-1, 0}, 1.0));
  EXPECT_NEAR(b.hi.y, 1.0, 1e-12);
  EXPECT_NEAR(b.lo.y, 0.0, 1e-12);
  EXPECT_NEAR(b.lo.x, -1.0, 1e-12);
  EXPECT_NEAR(b.hi.x, 1.0, 1e-12);
}

TEST(Curve, ReversedAndTransformedKeepTheSamePoints) {
  const Curve c = arc_deg({1, 2}, 3, 10, 250);
  const Curve r = reversed(c);
  for (double t : {0.0, 0.3, 0.8, 1.0}) {
    EXPECT_NEAR(distance(point_at(c, t), point_at(r, 1.0 - t)), 0.0, 1e-12);
  }
  const Transform tf(Pose{5, -1, 0.7});
  const Curve m = transformed(c, tf);
  for (double t : {0.0, 0.4, 1.0})
    EXPECT_NEAR(distance(tf.apply(point_at(c, t)), point_at(m, t)), 0.0, 1e-12);
}

TEST(Area, LoopsWithArcs) {
  // Unit disc from two half circles; square with a half-disc bump on its top edge.
  const Curve disc[] = {make_bulge_arc({1, 0}, {-1, 0}, 1), make_bulge_arc({-1, 0}, {1, 0}, 1)};
  EXPECT_NEAR(loop_signed_area(disc), kPi, 1e-12);
  const Curve bump[] = {make_segment({0, 0}, {2, 0}), make_segment({2, 0}, {2, 2}),
                        make_bulge_arc({2, 2}, {0, 2}, 1), make_segment({0, 2}, {0, 0})};
  EXPECT_NEAR(loop_signed_area(bump), 4.0 + kPi / 2.0, 1e-12);
  const Curve circle[] = {make_circle({3, 3}, 2, false)};
  EXPECT_NEAR(loop_signed_area(circle), -4.0 * kPi, 1e-12);
}

TEST(Containment, ArcLoopsWithoutPolygonising) {
  const Curve bump[] = {make_segment({0, 0}, {2, 0}), make_segment({2, 0}, {2, 2}),
                        make_bulge_arc({2, 2}, {0, 2}, 1), make_segment({0, 2}, {0, 0})};
  EXPECT_TRUE(loop_encloses(bump, {1, 2.9}));   // inside the bump
  EXPECT_FALSE(loop_encloses(bump, {1, 3.1}));  // above it
  EXPECT_TRUE(loop_encloses(bump, {1, 1}));
  EXPECT_FALSE(loop_encloses(bump, {1.9, 2.9}));  // beside the bump, above the square
  // A notch: concave arc cut into the top edge.
  const Curve notch[] = {make_segment({0, 0}, {2, 0}), make_segment({2, 0}, {2, 2}),
                         make_bulge_arc({2, 2}, {0, 2}, -1), make_segment({0, 2}, {0, 0})};
  EXPECT_FALSE(loop_encloses(notch, {1, 1.5}));
  EXPECT_TRUE(loop_encloses(notch, {0.1, 1.5}));
  EXPECT_NEAR(loop_signed_area(notch), 4.0 - kPi / 2.0, 1e-12);
}

TEST(SegmentSegment, Crossing) {
  const Intersection x =
      intersect(make_segment({0, 0}, {2, 2}), make_segment({0, 2}, {2, 0}), kEps);
  ASSERT_EQ(x.kind, IntersectionKind::one);
  EXPECT_NEAR(x.hits[0].point.x, 1.0, 1e-12);
  EXPECT_NEAR(x.hits[0].ta0, 0.5, 1e-12);
  EXPECT_NEAR(x.hits[0].tb0, 0.5, 1e-12);
}

TEST(SegmentSegment, ParallelApartIsNone) {
  EXPECT_EQ(intersect(make_segment({0, 0}, {2, 0}), make_segment({0, 1}, {2, 1}), kEps).kind,
            IntersectionKind::none);
}

TEST(SegmentSegment, CollinearOverlapOppositeDirections) {
  const Intersection x =
      intersect(make_segment({0, 0}, {4, 0}), make_segment({3, 0}, {1, 0}), kEps);
  ASSERT_EQ(x.kind, IntersectionKind::overlapping);
  EXPECT_FALSE(x.same_direction);
  ASSERT_EQ(x.count, 1);
  EXPECT_NEAR(x.hits[0].ta0, 0.25, 1e-12);
  EXPECT_NEAR(x.hits[0].ta1, 0.75, 1e-12);
  EXPECT_NEAR(x.hits[0].tb0, 1.0, 1e-12);
  EXPECT_NEAR(x.hits[0].tb1, 0.0, 1e-12);
}

TEST(SegmentSegment, CollinearEndToEndIsATouch) {
  const Intersection x =
      intersect(make_segment({0, 0}, {1, 0}), make_segment({1, 0}, {2, 0}), kEps);
  ASSERT_EQ(x.kind, IntersectionKind::tangent);
  EXPECT_NEAR(x.hits[0].ta0, 1.0, 1e-12);
  EXPECT_NEAR(x.hits[0].tb0, 0.0, 1e-12);
}

// Contact segments meeting end to end in a chain share that end bit for bit: the one hit is
// exactly there, at parameters exactly 0 or 1 (no round-off from solving for the crossing),
// in whichever order the pair comes; a shallow meeting still goes by the collinear rule.
TEST(SegmentSegment, ASharedEndIsTheExactHit) {
  const Vec2 p{0.1, 0.7};  // 0.1 and 0.7 are not representable: a solved crossing rounds
  const Curve a = make_segment({-2.3, 0.3}, p), b = make_segment(p, {1.9, 4.1});
  for (bool swapped : {false, true}) {
    const Intersection x = swapped ? intersect(b, a, kEps) : intersect(a, b, kEps);
    ASSERT_EQ(x.kind, IntersectionKind::one);
    ASSERT_EQ(x.count, 1);
    EXPECT_EQ(x.hits[0].point, p);
    EXPECT_EQ(x.hits[0].ta0, swapped ? 0.0 : 1.0);
    EXPECT_EQ(x.hits[0].tb0, swapped ? 1.0 : 0.0);
    EXPECT_FALSE(x.hits[0].is_tangent);
  }
  // Both starting at p, and both ending there.
  const Curve c = make_segment(p, {0.4, -3.0});
  const Intersection from_from = intersect(b, c, kEps);
  ASSERT_EQ(from_from.count, 1);
  EXPECT_EQ(from_from.hits[0].ta0, 0.0);
  EXPECT_EQ(from_from.hits[0].tb0, 0.0);
  const Intersection to_to = intersect(a, reversed(c), kEps);
  ASSERT_EQ(to_to.count, 1);
  EXPECT_EQ(to_to.hits[0].ta0, 1.0);
  EXPECT_EQ(to_to.hits[0].tb0, 1.0);
  // Folded back within eps of itself: a shared piece, not a point.
  const Curve bar = make_segment({0, 0}, {1, 0}), back = make_segment({1, 0}, {0.5, 1e-12});
  EXPECT_EQ(intersect(bar, back, kEps).kind, IntersectionKind::overlapping);
  // The same answer without building the intersection, as the slice's split points ask it.
  auto segments_meet_end_to_end = [](const Curve& x, const Curve& y, double eps) {
    return segment_pair_shortcut(x, y, eps) == SegmentPairShortcut::end_to_end;
  };
  EXPECT_TRUE(segments_meet_end_to_end(a, b, kEps));
  EXPECT_TRUE(segments_meet_end_to_end(b, c, kEps));
  EXPECT_FALSE(segments_meet_end_to_end(bar, back, kEps));
  EXPECT_FALSE(segments_meet_end_to_end(make_segment({0, 0}, {2, 2}), make_segment({0, 2}, {2, 0}),
                                        kEps));  // a crossing, no shared end
  EXPECT_FALSE(segments_meet_end_to_end(a, make_segment(p + Vec2{1e-15, 0}, {1.9, 4.1}), kEps));
  EXPECT_FALSE(segments_meet_end_to_end(make_arc(p, 1.0, 0.0, 1.0), b, kEps));
  // A bar continued with its far end 0.5 to 3 eps off the bar's line: collinear within
  // eps at first (a shared piece), then meeting end to end, decided by the offsets and then
  // on squares (beyond twice eps).
  for (const double off : {0.5, 0.9, 1.1, 1.5, 3.0})
    EXPECT_EQ(segments_meet_end_to_end(bar, make_segment({1, 0}, {2, off * kEps}), kEps), off > 1.0)
        << off << " eps off";
}

TEST(SegmentSegment, EndpointWithinEpsilonOfTheOtherCounts) {
  // A T-junction whose stem stops 1e-12 short of the bar, at a shallow angle.
  const Intersection x =
      intersect(make_segment({0, 0}, {10, 0}), make_segment({5, 1e-12}, {15, 1e-3}), kEps);
  EXPECT_NE(x.kind, IntersectionKind::none);
}

// The shortcut the slice's split points take before intersecting a pair of segments: a
// segment lying wholly on one side of the other's carrier, more than 2 eps off it, is apart.
TEST(SegmentSegment, PairsApartAreToldBeforeIntersecting) {
  const Curve bar = make_segment({0, 0}, {1, 0});
  // A stem above the bar, its foot 0.5 to 3 eps off the bar's line: touching within eps,
  // then a case for the full routine (none), then apart (beyond twice eps).
  for (const double off : {0.5, 0.9, 1.5, 1.9, 2.1, 3.0}) {
    const Curve stem = make_segment({0.5, off * kEps}, {0.7, 1.0});
    const SegmentPairShortcut expected =
        off > 2.0 ? SegmentPairShortcut::apart : SegmentPairShortcut::needs_intersection;
    EXPECT_EQ(segment_pair_shortcut(bar, stem, kEps), expected) << off << " eps off";
    EXPECT_EQ(segment_pair_shortcut(stem, bar, kEps), expected) << off << " eps off";
    EXPECT_EQ(intersect(bar, stem, kEps).kind == IntersectionKind::none, off > 1.0) << off;
  }
  // Straddling the bar's line but wholly to its right: apart by the bar's own carrier.
  EXPECT_EQ(segment_pair_shortcut(bar, make_segment({2, -1}, {2, 1}), kEps),
            SegmentPairShortcut::apart);
  // Parallel and far: apart. Crossing, or collinear within eps: not told, nor arcs.
  EXPECT_EQ(segment_pair_shortcut(bar, make_segment({0, 1}, {1, 1}), kEps),
            SegmentPairShortcut::apart);
  EXPECT_EQ(segment_pair_shortcut(bar, make_segment({0.5, -1}, {0.5, 1}), kEps),
            SegmentPairShortcut::needs_intersection);
  EXPECT_EQ(segment_pair_shortcut(bar, make_segment({2, 0.5 * kEps}, {3, 0.5 * kEps}), kEps),
            SegmentPairShortcut::needs_intersection);
  EXPECT_EQ(segment_pair_shortcut(bar, make_arc({0.5, 2}, 1.0, 0.0, 1.0), kEps),
            SegmentPairShortcut::needs_intersection);
}

// On random pairs placed eps-close in every way (ends near the other's carrier, shared ends,
// near-parallel), the shortcut never contradicts the full routine.
TEST(SegmentSegment, TheShortcutAgreesWithIntersectOnNearPairs) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(-1, 1), t(-0.3, 1.3), off(-4, 4);
  int apart = 0, end_to_end = 0;
  for (int i = 0; i < 20000; ++i) {
    const Curve a = make_segment({u(rng), u(rng)}, {u(rng), u(rng)});
    const Vec2 normal = perp_left(normalized(a.to - a.from));
    auto near_a = [&] { return point_at(a, t(rng)) + (off(rng) * kEps) * normal; };
    const Vec2 from = i % 3 == 0 ? a.to : near_a();
    const Vec2 to = i % 2 == 0 ? near_a() : Vec2{u(rng), u(rng)};
    const Curve b = make_segment(from, to);
    const Intersection x = intersect(a, b, kEps);
    switch (segment_pair_shortcut(a, b, kEps)) {
      case SegmentPairShortcut::apart:
        ++apart;
        EXPECT_EQ(x.kind, IntersectionKind::none) << i;
        break;
      case SegmentPairShortcut::end_to_end:
        ++end_to_end;
        ASSERT_EQ(x.count, 1) << i;
        EXPECT_FALSE(x.hits[0].is_piece) << i;
        EXPECT_EQ(x.hits[0].point, a.to) << i;
        break;
      case SegmentPairShortcut::needs_intersection:
        break;
    }
  }
  EXPECT_GT(apart, 2000);
  EXPECT_GT(end_to_end, 2000);
}

TEST(SegmentArc, TwoCrossings) {
  const Intersection x = intersect(make_segment({-2, 0.5}, {2, 0.5}), make_circle({0, 0}, 1), kEps);
  ASSERT_EQ(x.kind, IntersectionKind::two);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(length(x.hits[i].point), 1.0, 1e-12);
}

TEST(SegmentArc, TangentLine) {
  const Intersection x = intersect(make_segment({-2, 1}, {2, 1}), make_circle({0, 0}, 1), kEps);
  ASSERT_EQ(x.kind, IntersectionKind::tangent);
  EXPECT_NEAR(x.hits[0].point.x, 0.0, 1e-9);
  EXPECT_NEAR(x.hits[0].point.y, 1.0, 1e-12);
}

TEST(SegmentArc, CrossingOffTheArcIsIgnored) {
  const Curve upper = arc_deg({0, 0}, 1, 0, 180);
  EXPECT_EQ(intersect(make_segment({-2, -0.5}, {2, -0.5}), upper, kEps).kind,
            IntersectionKind::none);
  const Intersection x = intersect(make_segment({0, -2}, {0, 2}), upper, kEps);
  ASSERT_EQ(x.kind, IntersectionKind::one);
  EXPECT_NEAR(x.hits[0].tb0, 0.5, 1e-12);  // parameters come back in (segment, arc) order
  EXPECT_NEAR(x.hits[0].ta0, 0.75, 1e-12);
  const Intersection swapped = intersect(upper, make_segment({0, -2}, {0, 2}), kEps);
  EXPECT_NEAR(swapped.hits[0].ta0, 0.5, 1e-12);
  EXPECT_NEAR(swapped.hits[0].tb0, 0.75, 1e-12);
}

TEST(ArcArc, TwoCrossings) {
  const Intersection x = intersect(make_circle({0, 0}, 1), make_circle({1, 0}, 1), kEps);
  ASSERT_EQ(x.kind, IntersectionKind::two);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(x.hits[i].point.x, 0.5, 1e-12);
}

// A unit circle and a nearly straight one (centre 10^4 away) through two of its points, in
// both argument orders: the crossings land within 10^-11 of those points. Computed from the
// far centre (r^2 - s^2 with r^2 = 10^8) they strayed by about 10^-9.
TEST(ArcArc, NearlyStraightArcCrossesWhereItShould) {
  const Vec2 p{std::cos(0.3), std::sin(0.3)}, q{std::cos(1.1), std::sin(1.1)};
  const Vec2 mid = 0.5 * (p + q), away = perp_left((1.0 / distance(p, q)) * (q - p));
  const Vec2 far = mid + 1e4 * away;
  const Curve big = make_circle(far, distance(far, p));
  const Curve unit = make_circle({0, 0}, 1);
  for (const Intersection& x : {intersect(unit, big, kEps), intersect(big, unit, kEps)}) {
    ASSERT_EQ(x.kind, IntersectionKind::two);
    for (int i = 0; i < 2; ++i)
      EXPECT_LT(std::min(distance(x.hits[i].point, p), distance(x.hits[i].point, q)), 1e-11);
  }
}

TEST(ArcArc, ExternalAndInternalTangency) {
  const Intersection ext = intersect(make_circle({0, 0}, 1), make_circle({3, 0}, 2), kEps);
  ASSERT_EQ(ext.kind, IntersectionKind::tangent);
  EXPECT_NEAR(ext.hits[0].point.x, 1.0, 1e-12);
  const Intersection in = intersect(make_circle({0, 0}, 3), make_circle({1, 0}, 2), kEps);
  ASSERT_EQ(in.kind, IntersectionKind::tangent);
  EXPECT_NEAR(in.hits[0].point.x, 3.0, 1e-12);
}

TEST(ArcArc, ConcentricDifferentRadiiNeverMeet) {
  EXPECT_EQ(intersect(make_circle({0, 0}, 1), make_circle({0, 0}, 2), kEps).kind,
            IntersectionKind::none);
}

TEST(ArcArc, CocircularPieces) {
  // Same circle: [0, 200] degrees against [180, 370]: two shared pieces.
  const Intersection x = intersect(arc_deg({0, 0}, 2, 0, 200), arc_deg({0, 0}, 2, 180, 190), kEps);
  ASSERT_EQ(x.kind, IntersectionKind::overlapping);
  EXPECT_TRUE(x.same_direction);
  ASSERT_EQ(x.count, 2);
  double total = 0;
  for (int i = 0; i < 2; ++i) total += std::fabs(x.hits[i].ta1 - x.hits[i].ta0) * 200.0;
  EXPECT_NEAR(total, 30.0, 1e-9);  // degrees shared: [180, 200] and [0, 10]
}

TEST(ArcArc, CocircularOppositeDirectionsAndEndTouch) {
  const Intersection x = intersect(arc_deg({0, 0}, 1, 0, 90), arc_deg({0, 0}, 1, 90, -45), kEps);
  ASSERT_EQ(x.kind, IntersectionKind::overlapping);
  EXPECT_FALSE(x.same_direction);
  const Intersection touch = intersect(arc_deg({0, 0}, 1, 0, 90), arc_deg({0, 0}, 1, 90, 90), kEps);
  EXPECT_EQ(touch.kind, IntersectionKind::tangent);
}

TEST(ArcArc, PerfectFitCircles) {
  // A pin in a hole of the same radius: the whole circle is shared, travelled oppositely.
  const Intersection x =
      intersect(make_circle({0, 0}, 1, true), make_circle({0, 0}, 1, false), kEps);
  ASSERT_EQ(x.kind, IntersectionKind::overlapping);
  EXPECT_FALSE(x.same_direction);
}

TEST(Distance, PointToArcUsesTheNearerEnd) {
  const Curve upper = arc_deg({0, 0}, 1, 0, 180);
  EXPECT_NEAR(distance_to_curve(upper, {0, 3}), 2.0, 1e-12);
  EXPECT_NEAR(distance_to_curve(upper, {0, -3}), std::hypot(1.0, 3.0), 1e-12);
  EXPECT_NEAR(distance_to_curve(upper, {0, 0}), 1.0, 1e-12);
}

TEST(Distance, AgreesWithSamplingOnRandomCurves) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-3, 3), ang(-kPi, kPi), sw(-1.9 * kPi, 1.9 * kPi),
      rad(0.2, 2.0);
  auto random_curve = [&](bool arc) {
    return arc ? make_arc({u(rng), u(rng)}, rad(rng), ang(rng), sw(rng))
               : make_segment({u(rng), u(rng)}, {u(rng), u(rng)});
  };
  for (int i = 0; i < 600; ++i) {
    const Curve a = random_curve(i % 2 == 0), b = random_curve(i % 3 == 0);
    const double exact = distance_between(a, b);
    const double sampled = sampled_distance(a, b);
    // Sampling overestimates by at most the sample spacing's sagitta-level error.
    EXPECT_LE(exact, sampled + 1e-12) << i;
    EXPECT_GE(exact, sampled - 5e-3) << i;
    // A positive distance means no intersection, and an intersection means distance 0.
    const Intersection x = intersect(a, b, 0.0);
    if (x.count > 0) {
      EXPECT_NEAR(exact, 0.0, 1e-9) << i;
    }
  }
}

TEST(Intersection, HitsLieOnBothCurvesForRandomPairs) {
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(-3, 3), ang(-kPi, kPi), sw(-1.9 * kPi, 1.9 * kPi),
      rad(0.2, 2.0);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Curve a = (i % 2) ? make_arc({u(rng), u(rng)}, rad(rng), ang(rng), sw(rng))
                            : make_segment({u(rng), u(rng)}, {u(rng), u(rng)});
    const Curve b = (i % 3) ? make_arc({u(rng), u(rng)}, rad(rng), ang(rng), sw(rng))
                            : make_segment({u(rng), u(rng)}, {u(rng), u(rng)});
    const Intersection x = intersect(a, b, kEps);
    for (int h = 0; h < x.count; ++h) {
      ++hits;
      EXPECT_NEAR(distance(point_at(a, x.hits[h].ta0), x.hits[h].point), 0.0, 1e-8) << i;
      EXPECT_NEAR(distance(point_at(b, x.hits[h].tb0), x.hits[h].point), 0.0, 1e-8) << i;
    }
    if (x.count == 0) {
      EXPECT_GT(distance_between(a, b), 0.0) << i;
    }
  }
  EXPECT_GT(hits, 300);
}

TEST(Containment, PointOnAChordLineOfAnAntennaPairStaysInside) {
  // A square with an arc traversed there and back (a dangling curve inside a face, as
  // arrangement cycles have). Query points lie on the arc's chord line (up to round-off)
  // and inside its disc: the two traversals must cancel whatever round-off says of sides.
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> u(0.5, 3.5), t(0.05, 0.95), b(-0.9, 0.9);
  for (int i = 0; i < 20000; ++i) {
    const Vec2 a{u(rng), u(rng)}, c{u(rng), u(rng)};
    const Curve arc = make_bulge_arc(a, c, b(rng));
    const Curve walk[] = {make_segment({0, 0}, {4, 0}),
                          make_segment({4, 0}, {4, 4}),
                          make_segment({4, 4}, {0, 4}),
                          make_segment({0, 4}, {0, 0}),
                          make_segment({0, 0}, a),
                          arc,
                          reversed(arc),
                          make_segment(a, {0, 0})};
    const Vec2 p = lerp(a, c, t(rng));
    ASSERT_TRUE(loop_encloses(walk, p)) << i;
  }
}

TEST(Containment, FullCircleInsideALongerCycleCountsItsDisc) {
  // A square whose boundary walk also goes once around a circle centred on a corner.
  const Curve walk[] = {make_segment({0, 0}, {4, 0}), make_circle({4, 0}, 1, true),
                        make_segment({4, 0}, {4, 4}), make_segment({4, 4}, {0, 4}),
                        make_segment({0, 4}, {0, 0})};
  EXPECT_FALSE(loop_encloses(walk, {3.5, 0.2}));  // in the square and the disc: cancels
  EXPECT_TRUE(loop_encloses(walk, {4.5, 0.2}));   // the disc only
  EXPECT_TRUE(loop_encloses(walk, {2, 2}));       // the square only
}

// A stadium (a 1 x 1 bar with half-circle ends) turned by many angles: the centre of each
// rounded end lies on that half circle's chord, where a pin of the stadium's width reaches
// when it touches both sides. The sector check, computed otherwise than the chord's side,
// put such points outside the half circle's segment for about half of the angles, and so
// outside the part (designed stress pair 33: classify called a sliding fit blocked).
TEST(Containment, PointsOnTheChordOfAHalfCircleAreInside) {
  int checked = 0;
  for (int k = 0; k < 360; ++k) {
    const double a = 0.0174 * k + 0.003, c = std::cos(a), s = std::sin(a);
    const auto at = [&](double u, double v) { return Vec2{c * u - s * v, s * u + c * v}; };
    const Vec2 p0 = at(0.5, -0.5), p1 = at(0.5, 0.5), p2 = at(-0.5, 0.5), p3 = at(-0.5, -0.5);
    const Curve loop[] = {make_bulge_arc(p0, p1, 1.0), make_segment(p1, p2),
                          make_bulge_arc(p2, p3, 1.0), make_segment(p3, p0)};
    for (const double t : {0.5, 0.25, 0.75, 0.5 + 1e-9, 0.5 - 1e-9}) {
      ASSERT_TRUE(loop_encloses(loop, lerp(p0, p1, t))) << k << " " << t;
      ASSERT_TRUE(loop_encloses(loop, lerp(p2, p3, t))) << k << " " << t;
      checked += 2;
    }
    EXPECT_FALSE(loop_encloses(loop, at(1.2, 0.0))) << k;
    EXPECT_TRUE(loop_encloses(loop, at(0.9, 0.0))) << k;
  }
  EXPECT_EQ(checked, 3600);
}

TEST(Containment, ATinyArcWithSnappedEndsTogglesOnlyNearItself) {
  // A 1.4e-8 piece of an arc of radius 17 (sweep 8e-10) whose ends an arrangement snapped to
  // vertices about 1e-8 away: its chord now points nearly along the radius, and
  // the chord's half-plane alone cut the disc in two (seed 4242 pair 9 of the slice tests).
  const Curve arc = make_arc({0, 0}, 17.0, 0.0, 8e-10);
  Curve snapped = arc;
  snapped.from = arc.from + Vec2{-1e-8, 5e-9};
  snapped.to = arc.to + Vec2{1e-8, -5e-9};
  for (const Vec2 p : {Vec2{16.0, 0.5}, Vec2{16.0, -0.5}, Vec2{5.0, 3.0}, Vec2{-3.0, 1.0}})
    EXPECT_FALSE(toggles_parity(snapped, p)) << p.x << ", " << p.y;
  // Exact ends: the segment is the same whatever the sector test adds.
  const Curve half = make_arc({0, 0}, 1.0, 0.0, kPi / 2);
  EXPECT_TRUE(toggles_parity(half, {0.65, 0.65}));  // between the chord and the arc
  EXPECT_FALSE(toggles_parity(half, {0.8, 0.8}));   // beyond the arc
}

// Far angles wrap by the true turn, as std::sin and std::cos take them (the double nearest
// 2pi is 2.4e-16 short of it: by it, 1e15 rad wrapped 0.04 rad away from the orientation a
// Transform turns by); near ones as before, by fmod's exact remainder.
TEST(Angles, FarAnglesWrapToTheOrientationSinAndCosGive) {
  for (double a : {1e9, -1e9, 7.5e10, -1e12, 1e15, 3e17, 1e300}) {
    const double w = wrap_angle(a);
    SCOPED_TRACE(a);
    EXPECT_GE(w, -kPi);
    EXPECT_LT(w, kPi);
    EXPECT_NEAR(std::cos(w), std::cos(a), 1e-15);
    EXPECT_NEAR(std::sin(w), std::sin(a), 1e-15);
  }
  for (double a : {-1000.5, -7.0, -kPi, 3.5, 6.0, kPi, 100.0, 6283.0}) {
    SCOPED_TRACE(a);
    double expected = std::fmod(a + kPi, kTwoPi);
    if (expected < 0.0) expected += kTwoPi;
    EXPECT_EQ(wrap_angle(a), expected - kPi);
  }
  // In [-pi, pi) an angle is its own principal angle, bit for bit (wrap_angle(0.1) is not).
  for (double a : {-kPi, -1.0, 0.1, 3.14159}) EXPECT_EQ(principal_angle(a), a);
  EXPECT_EQ(principal_angle(kPi), -kPi);
  EXPECT_EQ(principal_angle(1e15), wrap_angle(1e15));
}

// A Transform's angle is its principal angle, consistent with its sine and cosine: an arc
// placed at a far orientation keeps its start angle on its start point. At 1e15 rad the sum of
// the two angles was rounded to an eighth of a radian: this arc's start angle pointed 0.075
// away from its start.
TEST(Angles, AnArcTurnedFarKeepsItsStartAngleOnItsStart) {
  const Curve arc = make_arc({1.0, 2.0}, 3.0, 0.4, 1.2);
  for (double far : {1e9, -3e13, 1e15}) {
    const Transform t(Pose{0.5, -0.25, far});
    EXPECT_GE(t.angle, -kPi) << far;
    EXPECT_LT(t.angle, kPi) << far;
    const Curve placed = transformed(arc, t);
    const Vec2 start = placed.center + placed.radius * unit_vector(placed.start_angle);
    EXPECT_LT(distance(start, placed.from), 1e-12) << far;
  }
}

namespace {

// The grid's pairs against every pair tried: each overlapping pair once, i < j, nothing else.
// Boxes that touch at an edge or a corner overlap (Box::overlaps is closed); empty boxes
// overlap nothing.
void expect_grid_pairs_exact(const std::vector<Box>& boxes, const std::string& name) {
  std::vector<std::pair<size_t, size_t>> expected, found;
  for (size_t i = 0; i < boxes.size(); ++i)
    for (size_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) expected.emplace_back(i, j);
  BoxGridScratch scratch;
  const bool gridded = for_each_overlapping_pair_on_grid(
      boxes.size(), [&](size_t i) -> const Box& { return boxes[i]; }, scratch,
      [&](size_t i, size_t j) { found.emplace_back(i, j); });
  ASSERT_TRUE(gridded) << name;
  for (auto [i, j] : found) EXPECT_LT(i, j) << name;
  std::sort(found.begin(), found.end());
  EXPECT_EQ(std::adjacent_find(found.begin(), found.end()), found.end()) << name << ": twice";
  EXPECT_EQ(found, expected) << name;
}

Box box_around(Vec2 c, double w, double h) {
  Box b;
  b.add(Vec2{c.x - w / 2, c.y - h / 2});
  b.add(Vec2{c.x + w / 2, c.y + h / 2});
  return b;
}

}  // namespace

TEST(BoxPairs, TheGridFindsExactlyTheOverlappingPairs) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int round = 0; round < 20; ++round) {
    // Around a ring, as the contact families of a gear in a ring gear lie.
    std::vector<Box> ring, mixed;
    for (int i = 0; i < 400; ++i) {
      const double a = kTwoPi * u(rng), r = 3.0 + 0.3 * u(rng);
      ring.push_back(box_around({r * std::cos(a), r * std::sin(a)}, 0.2 * u(rng), 0.2 * u(rng)));
      mixed.push_back(
          box_around({4.0 * u(rng), 2.0 * u(rng)}, 1.5 * u(rng) * u(rng) * u(rng), 0.05 * u(rng)));
    }
    expect_grid_pairs_exact(ring, "ring " + std::to_string(round));
    expect_grid_pairs_exact(mixed, "mixed " + std::to_string(round));
  }
}

TEST(BoxPairs, TheGridOnDegenerateBoxes) {
  // A unit grid of unit squares: every neighbour, diagonal ones too, touches exactly.
  std::vector<Box> tiles;
  for (int x = 0; x < 12; ++x)
    for (int y = 0; y < 12; ++y) tiles.push_back(box_around({x + 0.5, y + 0.5}, 1.0, 1.0));
  expect_grid_pairs_exact(tiles, "tiles");
  // Points, some of them equal, and empty boxes among them.
  std::vector<Box> points;
  for (int i = 0; i < 300; ++i) {
    if (i % 7 == 0) points.push_back(Box{});
    points.push_back(box_around({double(i % 17), double(i % 5)}, 0.0, 0.0));
  }
  expect_grid_pairs_exact(points, "points");
  // All on one horizontal line (no height at all), and all the same box.
  std::vector<Box> flat, same;
  for (int i = 0; i < 200; ++i) {
    flat.push_back(box_around({0.37 * i, 1.0}, 0.5, 0.0));
    same.push_back(box_around({1.0, 2.0}, 0.3, 0.1));
  }
  expect_grid_pairs_exact(flat, "flat");
  expect_grid_pairs_exact(same, "same");
  expect_grid_pairs_exact({}, "none");
  expect_grid_pairs_exact({box_around({0, 0}, 1, 1)}, "one");
}

// A few boxes as large as the spread of many small ones would meet in every cell: the caller
// sweeps instead.
TEST(BoxPairs, TheGridDeclinesBoxesAsLargeAsTheirSpread) {
  std::vector<Box> boxes;
  for (int i = 0; i < 30; ++i) boxes.push_back(box_around({5.0 + 0.01 * i, 5.0}, 10.0, 10.0));
  for (int i = 0; i < 370; ++i)
    boxes.push_back(box_around({0.027 * i, 10.0 - 0.027 * i}, 0.01, 0.01));
  BoxGridScratch scratch;
  int visits = 0;
  const bool gridded = for_each_overlapping_pair_on_grid(
      boxes.size(), [&](size_t i) -> const Box& { return boxes[i]; }, scratch,
      [&](size_t, size_t) { ++visits; });
  EXPECT_FALSE(gridded);
  EXPECT_EQ(visits, 0);
}

// The chords' bounds hold the exact distance (and the sampled one) between them, for segments
// and arcs up to a half turn, crossing or apart; past a half turn they bound nothing.
TEST(Distance, ChordBoundsHoldTheDistance) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto random_curve = [&](double max_sweep) {
    const Vec2 c{3.0 * u(rng), 3.0 * u(rng)};
    const double r = 0.05 + 2.0 * std::fabs(u(rng));
    if (u(rng) < -0.6) return make_segment(c, c + Vec2{r * u(rng), r * u(rng)});
    return make_arc(c, r, kPi * u(rng), max_sweep * u(rng));
  };
  int arcs = 0, tight = 0;
  for (int i = 0; i < 3000; ++i) {
    const Curve a = random_curve(kPi), b = random_curve(i % 10 == 0 ? kTwoPi : kPi);
    if (a.is_segment() || b.is_segment()) continue;
    const DistanceBounds bounds = chord_distance_bounds(a, b);
    if (std::fabs(b.sweep) > kPi) {
      EXPECT_EQ(bounds.lo, 0.0);
      EXPECT_EQ(bounds.hi, std::numeric_limits<double>::infinity());
      continue;
    }
    ++arcs;
    const double exact = distance_between(a, b);
    EXPECT_LE(bounds.lo, exact + 1e-12) << i;
    EXPECT_GE(bounds.hi, exact - 1e-12) << i;
    EXPECT_LE(bounds.lo, sampled_distance(a, b, 400) + 1e-12) << i;
    tight += bounds.hi - bounds.lo < 0.1 ? 1 : 0;
  }
  EXPECT_GT(arcs, 1000);
  EXPECT_GT(tight, arcs / 50);  // the bounds are not vacuous
  // A half turn exactly, against its own chord: the distance is 0, the sagitta the radius.
  const Curve half = make_arc({0.0, 0.0}, 1.0, 0.0, kPi);
  const DistanceBounds own = chord_distance_bounds(half, make_segment(half.from, half.to));
  EXPECT_EQ(own.lo, 0.0);
  EXPECT_NEAR(own.hi, 1.0, 1e-12);
  // Segments: both bounds are their distance.
  const Curve s1 = make_segment({0, 0}, {1, 0}), s2 = make_segment({0, 2}, {1, 3});
  EXPECT_EQ(chord_distance_bounds(s1, s2).lo, distance_between(s1, s2));
  EXPECT_EQ(chord_distance_bounds(s1, s2).hi, distance_between(s1, s2));
}
