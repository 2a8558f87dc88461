// Slice::locate's shortcuts against the full tests they stand in for: within_distance
// against distance_to_curve(c, p) <= eps (the box margin of segments, the arc's cheap
// candidates), carrier_rejects never against it, and locate itself against the plain loop
// over every piece.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "cslice/slice.hpp"
#include "geometry/near_curve.hpp"
#include "parts/loop_queries.hpp"
#include "support/examples.hpp"

using namespace cslice;

namespace {

// Points around c: on it, and off it by multiples of eps near 1 (across the threshold).
std::vector<Vec2> probes(const Curve& c, double eps, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec2> out;
  for (int i = 0; i < 64; ++i) {
    const double t = i < 2 ? double(i) : unit(rng);
    const Vec2 at = point_at(c, t);
    const double angle = kTwoPi * unit(rng);
    for (double f : {0.0, 0.5, 1.0 - 1e-9, 1.0, 1.0 + 1e-9, 1.0 + 1e-6, 1.0 + 1e-3, 2.0}) {
      out.push_back(at + (f * eps) * perp_left(tangent_at(c, t)));
      out.push_back(at - (f * eps) * perp_left(tangent_at(c, t)));
      out.push_back(at + (f * eps) * unit_vector(angle));
    }
  }
  if (c.is_arc()) out.push_back(c.center);
  return out;
}

// Also: carrier_rejects never rejects a point within eps (`rejected` counts those it does).
void expect_same_decisions(const Curve& c, double eps, std::mt19937& rng, int& near,
                           int& rejected) {
  for (Vec2 p : probes(c, eps, rng)) {
    const bool exact = distance_to_curve(c, p) <= eps;
    near += exact;
    const bool carrier_far = carrier_rejects(c, p, eps);
    rejected += carrier_far;
    ASSERT_FALSE(exact && carrier_far)
        << "p " << p.x << ", " << p.y << " eps " << eps << " from " << c.from.x << ", " << c.from.y
        << " to " << c.to.x << ", " << c.to.y << " sweep " << c.sweep;
    ASSERT_EQ(within_distance(c, p, eps), exact)
        << "p " << p.x << ", " << p.y << " eps " << eps << " from " << c.from.x << ", " << c.from.y
        << " to " << c.to.x << ", " << c.to.y << " sweep " << c.sweep;
  }
}

// Far from the origin (coordinates 1e7 times the size of the curves, eps 1e-9 of that size),
// the rounding of the segment's nearest point is about eps: a box test without its
// margin rejects points whose computed distance is within eps.
TEST(SliceLocate, WithinDistanceMatchesDistanceFarFromOrigin) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int near = 0, rejected = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec2 offset{1e7 * unit(rng), 1e7 * unit(rng)};
    const Vec2 a = offset + Vec2{unit(rng), unit(rng)};
    // Nearly axis-parallel segments: points beside them lie beyond their box in one axis.
    const Vec2 d = k % 2 ? Vec2{1e-7 * unit(rng), unit(rng)} : Vec2{unit(rng), 1e-7 * unit(rng)};
    expect_same_decisions(make_segment(a, a + d), 1e-9, rng, near, rejected);
    expect_same_decisions(make_bulge_arc(a, a + d, 0.3 * unit(rng)), 1e-9, rng, near, rejected);
  }
  EXPECT_GT(near, 1000);  // the probes do straddle the threshold
}

// Near the origin, where round-off is far below eps: segments of every direction, the points
// twice eps off their line rejected, none within eps.
TEST(SliceLocate, CarrierRejectsNoPointWithinDistanceOfASegment) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int near = 0, rejected = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec2 a{unit(rng), unit(rng)}, d{unit(rng), unit(rng)};
    expect_same_decisions(make_segment(a, a + d), 1e-9, rng, near, rejected);
  }
  EXPECT_GT(near, 1000);
  EXPECT_GT(rejected, 10000);
}

TEST(SliceLocate, WithinDistanceMatchesDistanceOnArcs) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int near = 0, rejected = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec2 center{unit(rng), unit(rng)};
    const double radius = 0.01 + std::fabs(unit(rng));
    Curve arc = make_arc(center, radius, kPi * unit(rng), kTwoPi * unit(rng));
    // Snapped ends, as an arrangement leaves them: off the circle by up to eps.
    const double eps = 1e-9;
    arc.from = arc.from + Vec2{eps * unit(rng), eps * unit(rng)};
    arc.to = arc.to + Vec2{eps * unit(rng), eps * unit(rng)};
    expect_same_decisions(arc, eps, rng, near, rejected);
  }
  EXPECT_GT(rejected, 10000);  // twice eps off the circle, and beyond
  EXPECT_GT(near, 1000);
}

// The plain loop Slice::locate stood for before its shortcuts.
int locate_plainly(const Slice& s, Vec2 p) {
  for (const FreeComponent& c : s.free_components) {
    bool inside = !c.bounded;
    for (const auto& cycle : c.boundary)
      for (const ContactPiece& piece : cycle) {
        if (distance_to_curve(piece.curve, p) <= s.epsilon) return -1;
        if (toggles_parity(piece.curve, p)) inside = !inside;
      }
    if (inside) return c.id;
  }
  return -1;
}

TEST(SliceLocate, LocateMatchesPlainLoopOnExamples) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const char* name : {"fastener", "fixture", "knee", "cam"}) {
    const Pair pair = testkit::load_example(name);
    Slicer slicer(pair);
    for (double theta : {0.0, kPi, 0.5 * kPi, 1.234}) {
      const Slice s = slicer.slice(theta);
      std::vector<Vec2> points;
      for (const FreeComponent& c : s.free_components) {
        points.push_back(c.sample);
        for (const auto& cycle : c.boundary)
          for (const ContactPiece& piece : cycle)
            for (Vec2 p : probes(piece.curve, s.epsilon, rng)) points.push_back(p);
      }
      for (Vec2 p : points) ASSERT_EQ(s.locate(p), locate_plainly(s, p)) << name << " " << theta;
    }
  }
}

}  // namespace
