// Features of finished parts: convexity and outward normals after orientation, areas and the
// paper's feature counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cslice/pair.hpp"

namespace cslice {
namespace {

// Reads a pair whose moving part has the given loops (the fixed part is a plain square).
Part moving_part(const std::string& loops) {
  const std::string text = R"({"moving": {"loops": [)" + loops +
                           R"(]}, "fixed": {"loops": [[[-9,-9],[9,-9],[9,9],[-9,9]]]}})";
  const LoadResult r = parse_pair(text, "features.json");
  EXPECT_TRUE(r.ok()) << r.error->message();
  return r.ok() ? r.pair->moving : Part{};
}

const Feature* find_feature(const Part& part, FeatureKind kind, int loop, int index) {
  for (const Feature& f : part.features)
    if (f.kind == kind && f.loop == loop && f.index == index) return &f;
  return nullptr;
}

void expect_vec(Vec2 got, Vec2 want) {
  EXPECT_NEAR(got.x, want.x, 1e-12) << "x";
  EXPECT_NEAR(got.y, want.y, 1e-12) << "y";
}

// Counterclockwise: corners at (0,0), (4,0) convex; a concave arc (bulge -0.5) from (4,0) up
// to (4,2) dipping to x = 3.5; convex corner (4,2); reflex corner (2,2); a convex half-circle
// arc from (2,4) to (0,4) that starts straight up and ends straight down, so the vertices at
// (2,4) and (0,4) are smooth.
const char* const kMixedShape = R"([[0,0],[4,0,-0.5],[4,2],[2,2],[2,4,1],[0,4]])";

TEST(PartFeatures, ConvexityOnMixedShape) {
  const Part p = moving_part(kMixedShape);
  ASSERT_EQ(p.loops.size(), 1u);
  EXPECT_FALSE(p.loops[0].reversed);
  const Convexity want_vertex[] = {Convexity::convex,  Convexity::convex, Convexity::convex,
                                   Convexity::concave, Convexity::smooth, Convexity::smooth};
  for (int i = 0; i < 6; ++i) {
    const Feature* v = find_feature(p, FeatureKind::vertex, 0, i);
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(v->convexity, want_vertex[i]) << "vertex " << i;
  }
  const Feature* concave_arc = find_feature(p, FeatureKind::arc, 0, 1);
  const Feature* convex_arc = find_feature(p, FeatureKind::arc, 0, 4);
  ASSERT_NE(concave_arc, nullptr);
  ASSERT_NE(convex_arc, nullptr);
  EXPECT_EQ(concave_arc->convexity, Convexity::concave);
  EXPECT_EQ(convex_arc->convexity, Convexity::convex);
  for (int i : {0, 2, 3, 5}) {
    const Feature* s = find_feature(p, FeatureKind::segment, 0, i);
    ASSERT_NE(s, nullptr) << "segment " << i;
    EXPECT_EQ(s->convexity, Convexity::flat);
  }
}

TEST(PartFeatures, NormalsOnMixedShape) {
  const Part p = moving_part(kMixedShape);
  const Feature* bottom = find_feature(p, FeatureKind::segment, 0, 0);
  expect_vec(bottom->normal_in, {0, -1});
  expect_vec(bottom->normal_out, {0, -1});
  const Feature* left = find_feature(p, FeatureKind::segment, 0, 5);
  expect_vec(left->normal_in, {-1, 0});
  // Concave arc: circle center (4.75, 1), radius 1.25; outward normals point to the center.
  const Feature* dent = find_feature(p, FeatureKind::arc, 0, 1);
  expect_vec(dent->normal_in, {0.6, 0.8});
  expect_vec(dent->normal_out, {0.6, -0.8});
  // Convex half circle centered (1, 4): outward normals point away from the center.
  const Feature* bump = find_feature(p, FeatureKind::arc, 0, 4);
  expect_vec(bump->normal_in, {1, 0});
  expect_vec(bump->normal_out, {-1, 0});
  // Reflex corner at (2,2): incoming edge runs left (normal up), outgoing runs up (normal right).
  const Feature* reflex = find_feature(p, FeatureKind::vertex, 0, 3);
  expect_vec(reflex->point, {2, 2});
  expect_vec(reflex->normal_in, {0, 1});
  expect_vec(reflex->normal_out, {1, 0});
  // Convex corner at (0,0): from the left side (normal -x) to the bottom (normal -y); the
  // normal cone runs counterclockwise from normal_in to normal_out.
  const Feature* corner = find_feature(p, FeatureKind::vertex, 0, 0);
  expect_vec(corner->normal_in, {-1, 0});
  expect_vec(corner->normal_out, {0, -1});
  EXPECT_GT(cross(corner->normal_in, corner->normal_out), 0.0);
  // Smooth vertex: both normals agree.
  const Feature* smooth = find_feature(p, FeatureKind::vertex, 0, 4);
  expect_vec(smooth->normal_in, smooth->normal_out);
}

// The normal cones as angles, which the contact step buckets by: a segment's normal, a convex
// corner's quarter turn, a reflex corner's negative turn; the same after the part is placed.
TEST(PartFeatures, NormalAnglesOnMixedShape) {
  const Part p = moving_part(kMixedShape);
  const Feature* bottom = find_feature(p, FeatureKind::segment, 0, 0);
  EXPECT_NEAR(bottom->normal_angle, -kPi / 2, 1e-15);
  EXPECT_EQ(bottom->turn, 0.0);
  const Feature* corner = find_feature(p, FeatureKind::vertex, 0, 0);
  EXPECT_NEAR(std::remainder(corner->normal_angle - kPi, kTwoPi), 0.0, 1e-15);  // -pi or pi
  EXPECT_NEAR(corner->turn, kPi / 2, 1e-15);
  const Feature* reflex = find_feature(p, FeatureKind::vertex, 0, 3);
  EXPECT_NEAR(reflex->normal_angle, kPi / 2, 1e-15);
  EXPECT_NEAR(reflex->turn, -kPi / 2, 1e-15);
  const Part turned = placed(p, Pose{3.0, -1.0, 0.5});
  for (size_t i = 0; i < p.features.size(); ++i) {
    const Feature &f = p.features[i], &g = turned.features[i];
    if (f.kind == FeatureKind::arc) continue;
    EXPECT_NEAR(std::remainder(g.normal_angle - f.normal_angle - 0.5, kTwoPi), 0.0, 1e-12);
    EXPECT_NEAR(g.turn, f.turn, 1e-12);
  }
}

TEST(PartFeatures, ClockwiseInputGivesSameFeatures) {
  // The mixed shape listed clockwise: vertices reversed, bulges moved and negated.
  const Part p = moving_part(R"([[0,0],[0,4,-1],[2,4],[2,2],[4,2,0.5],[4,0]])");
  ASSERT_TRUE(p.loops[0].reversed);
  const auto count = [&](FeatureKind k, Convexity c) {
    return std::count_if(p.features.begin(), p.features.end(),
                         [&](const Feature& f) { return f.kind == k && f.convexity == c; });
  };
  EXPECT_EQ(count(FeatureKind::vertex, Convexity::convex), 3);
  EXPECT_EQ(count(FeatureKind::vertex, Convexity::concave), 1);
  EXPECT_EQ(count(FeatureKind::vertex, Convexity::smooth), 2);
  EXPECT_EQ(count(FeatureKind::arc, Convexity::convex), 1);
  EXPECT_EQ(count(FeatureKind::arc, Convexity::concave), 1);
  EXPECT_EQ(count(FeatureKind::segment, Convexity::flat), 4);
  // Vertex 0 stays put; oriented vertex k is input vertex (n - k) % n.
  const Feature* v3 = find_feature(p, FeatureKind::vertex, 0, 3);
  expect_vec(v3->point, {2, 2});
  EXPECT_EQ(v3->convexity, Convexity::concave);
}

TEST(PartFeatures, HoleFeaturesPointIntoTheHole) {
  const Part p =
      moving_part(R"([[0,0],[6,0],[6,6],[0,6]], [[2,2],[4,2],[4,4],[2,4]], {"circle": [1,1,0.5]})");
  // Hole corners are reflex seen from the material; the hole's bottom edge faces up.
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(find_feature(p, FeatureKind::vertex, 1, i)->convexity, Convexity::concave);
  const Curve& hole_edge = p.loops[1].edges[0];
  const Feature* f = find_feature(p, FeatureKind::segment, 1, 0);
  // Whichever side of the hole edge 0 is, its normal points toward the hole's center.
  const Vec2 mid = point_at(hole_edge, 0.5);
  EXPECT_GT(dot(f->normal_in, Vec2{3, 3} - mid), 0.0);
  // The circle (a hole too) is a concave arc with no vertex.
  EXPECT_EQ(find_feature(p, FeatureKind::arc, 2, 0)->convexity, Convexity::concave);
  EXPECT_EQ(find_feature(p, FeatureKind::vertex, 2, 0), nullptr);
}

TEST(PartFeatures, EnclosureCornersAreConcave) {
  const LoadResult r = parse_pair(
      R"({"moving": {"loops": [{"circle": [0,0,1]}]},
          "fixed": {"loops": [[[-5,-5],[5,-5],[5,5],[-5,5]]], "enclosure": true}})",
      "enclosure.json");
  ASSERT_TRUE(r.ok()) << r.error->message();
  const Part& f = r.pair->fixed;
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(find_feature(f, FeatureKind::vertex, 0, i)->convexity, Convexity::concave);
  // The bottom wall's outward normal (out of the material) points up, into the opening.
  for (const Feature& feat : f.features)
    if (feat.kind == FeatureKind::segment && edge_of(f, feat).from.y == -5.0 &&
        edge_of(f, feat).to.y == -5.0)
      expect_vec(feat.normal_in, {0, 1});
  EXPECT_NEAR(f.area, 100.0, 1e-9);
}

TEST(PartFeatures, AreaUnitSquare) {
  EXPECT_NEAR(moving_part(R"([[0,0],[1,0],[1,1],[0,1]])").area, 1.0, 1e-12);
}

TEST(PartFeatures, AreaDisc) {
  EXPECT_NEAR(moving_part(R"({"circle": [1, 2, 3]})").area, kPi * 9.0, 1e-9);
}

TEST(PartFeatures, AreaSquareWithHalfDiscBump) {
  // The top edge from (2,2) to (0,2) is a counterclockwise half circle bulging up.
  const Part p = moving_part(R"([[0,0],[2,0],[2,2,1],[0,2]])");
  EXPECT_NEAR(p.area, 4.0 + kPi / 2.0, 1e-9);
  EXPECT_EQ(p.segment_count(), 3);
  EXPECT_EQ(p.arc_count(), 1);
  EXPECT_EQ(p.vertex_count(), 4);
  EXPECT_EQ(p.feature_count(), 8);
  EXPECT_EQ(p.features.size(), 8u);
}

TEST(PartFeatures, AreaSquareWithHalfDiscDent) {
  const Part p = moving_part(R"([[0,0],[2,0],[2,2,-1],[0,2]])");
  EXPECT_NEAR(p.area, 4.0 - kPi / 2.0, 1e-9);
}

TEST(PartFeatures, FeatureCounts) {
  const Part p =
      moving_part(R"([[0,0],[6,0],[6,6],[0,6]], [[2,2],[4,2,1],[4,4]], {"circle": [1,1,0.5]})");
  EXPECT_EQ(p.segment_count(), 4 + 2);
  EXPECT_EQ(p.arc_count(), 1 + 1);
  EXPECT_EQ(p.vertex_count(), 4 + 3);
  EXPECT_EQ(p.feature_count(), 15);
  EXPECT_EQ(static_cast<int>(p.features.size()), p.feature_count());
}

TEST(PartFeatures, BoxCoversArcs) {
  const Part p = moving_part(R"([[0,0],[2,0],[2,2,1],[0,2]])");
  expect_vec(p.box.lo, {0, 0});
  expect_vec(p.box.hi, {2, 3});
}

TEST(PartFeatures, FinishPartOnHandBuiltLoops) {
  // Clockwise unit square built directly: finish_part orients it and fills everything.
  Part part;
  part.name = "moving";
  Loop loop;
  const Vec2 v[] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  for (int i = 0; i < 4; ++i) loop.edges.push_back(make_segment(v[i], v[(i + 1) % 4]));
  part.loops.push_back(loop);
  finish_part(part);
  EXPECT_TRUE(part.loops[0].reversed);
  EXPECT_NEAR(part.area, 1.0, 1e-12);
  EXPECT_EQ(part.feature_count(), 8);
  for (const Feature& f : part.features)
    if (f.kind == FeatureKind::vertex) {
      EXPECT_EQ(f.convexity, Convexity::convex);
    }
  // Calling it again changes nothing.
  finish_part(part);
  EXPECT_TRUE(part.loops[0].reversed);
  EXPECT_NEAR(part.area, 1.0, 1e-12);
}

}  // namespace
}  // namespace cslice
