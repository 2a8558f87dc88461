#include "support/slice_oracle.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cslice/classify.hpp"
#include "cslice/slice.hpp"
#include "cslice/space.hpp"
#include "support/failures.hpp"

namespace cslice::testkit {

int check_slice_against_classify(const Pair& pair, double theta, int points, std::mt19937& rng,
                                 const std::string& what, bool sample_clearance) {
  return check_slice_against_classify(pair, compute_slice(pair, theta), points, rng, what,
                                      sample_clearance);
}

int check_slice_against_classify(const Pair& pair, const Slice& slice, int points,
                                 std::mt19937& rng, const std::string& what,
                                 bool sample_clearance) {
  const int before = failures_so_far();
  const double theta = slice.theta;
  PlacementTester tester(pair);
  // Every sample is strictly free: not blocked and clear of contact. (A pocket narrower than
  // the tolerance is still a free component; classify's band may call its centre contact.)
  for (const FreeComponent& c : slice.free_components) {
    const Pose at{c.sample.x, c.sample.y, theta};
    EXPECT_NE(tester.classify(at), Placement::blocked)
        << what << " theta " << theta << ": sample of component " << c.id;
    if (sample_clearance) {
      EXPECT_GT(tester.boundary_distance(at), pair.tol.geometric)
          << what << " theta " << theta << ": sample of component " << c.id;
    }
  }
  const double reach = std::max(std::fabs(pair.moving.box.lo.x), std::fabs(pair.moving.box.hi.x)) +
                       std::max(std::fabs(pair.moving.box.lo.y), std::fabs(pair.moving.box.hi.y));
  const Box box = pair.fixed.box.inflated(reach);
  std::uniform_real_distribution<double> ux(box.lo.x, box.hi.x), uy(box.lo.y, box.hi.y);
  int decisive = 0;
  for (int i = 0; i < points; ++i) {
    const Vec2 p{ux(rng), uy(rng)};
    const Placement truth = tester.classify({p.x, p.y, theta});
    if (truth == Placement::contact) continue;
    ++decisive;
    const int comp = slice.locate(p);
    EXPECT_EQ(comp >= 0, truth == Placement::free)
        << what << " theta " << theta << " point (" << p.x << ", " << p.y << "): classify says "
        << to_string(truth) << ", slice component " << comp;
    if (failures_so_far() != before) return decisive;
  }
  return decisive;
}

namespace {

SegmentLabel label_of(const Slice& s, int id) {
  const ContactSegment& c = s.contact_segments.at(id);
  return {c.moving_feature, c.fixed_feature};
}

// The contact graph's edges as label pairs, sorted: ids differ between slices, labels not.
std::vector<std::pair<SegmentLabel, SegmentLabel>> graph_labels(const Slice& s) {
  std::vector<std::pair<SegmentLabel, SegmentLabel>> out;
  for (const ContactGraphEdge& e : s.contact_graph.edges) {
    const SegmentLabel a = label_of(s, e.a), b = label_of(s, e.b);
    out.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The labels of the contact segments longer than the geometric epsilon, and of perfect fits,
// sorted: contact segments of no length, where a feature's normal range only touches the
// other's, come and go with round-off (a slice mapped across a symmetry of the pair has its
// source's).
std::vector<SegmentLabel> lengthy_labels(const Slice& s) {
  std::vector<SegmentLabel> out;
  for (const ContactSegment& c : s.contact_segments)
    if (c.is_point || curve_length(c.curve) > s.epsilon)
      out.push_back({c.moving_feature, c.fixed_feature});
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

void expect_same_slice(const Pair& pair, const Slice& evaluated, const Slice& computed,
                       const std::string& what) {
  ASSERT_EQ(evaluated.theta, computed.theta) << what;
  EXPECT_EQ(lengthy_labels(evaluated), lengthy_labels(computed)) << what;
  ASSERT_EQ(evaluated.free_components.size(), computed.free_components.size()) << what;
  const double area_slack = pair.tol.geometric * pair.tol.size;
  for (const FreeComponent& c : evaluated.free_components) {
    const int match = computed.locate(c.sample);
    ASSERT_GE(match, 0) << what << ": sample of component " << c.id << " not free";
    const FreeComponent& m = computed.free_components[match];
    EXPECT_EQ(evaluated.locate(m.sample), c.id) << what << ": component " << c.id;
    EXPECT_EQ(c.bounded, m.bounded) << what << ": component " << c.id;
    EXPECT_EQ(c.boundary.size(), m.boundary.size()) << what << ": component " << c.id;
    if (c.bounded) {
      EXPECT_NEAR(c.area, m.area, area_slack) << what << ": component " << c.id;
    }
  }
  EXPECT_EQ(realizable_labels(evaluated), realizable_labels(computed)) << what;
  EXPECT_EQ(evaluated.realizable.size(), computed.realizable.size()) << what;
  EXPECT_EQ(graph_labels(evaluated), graph_labels(computed)) << what;
  EXPECT_EQ(evaluated.degenerate.size(), computed.degenerate.size()) << what;
  if (std::isinf(computed.blocked_area)) {
    EXPECT_TRUE(std::isinf(evaluated.blocked_area)) << what;
  } else {
    EXPECT_NEAR(evaluated.blocked_area, computed.blocked_area, area_slack) << what;
  }
}

int expect_boundary_sides_agree_with_classify(const Pair& pair, const Slice& slice,
                                              const std::string& what) {
  PlacementTester tester(pair);
  const double offset = 4 * pair.tol.contact;
  int tested = 0;
  for (const FreeComponent& c : slice.free_components)
    for (const auto& cycle : c.boundary)
      for (const ContactPiece& piece : cycle) {
        const Vec2 mid = point_at(piece.curve, 0.5);
        const Vec2 left = perp_left(normalized(tangent_at(piece.curve, 0.5)));
        // Only where no other piece passes within twice the offset of the middle: in a
        // component thinner than that, the point beside a piece may lie beyond the opposite
        // one.
        bool clear = true;
        for (const ContactPiece& other : slice.realizable) {
          const double d = distance_to_curve(other.curve, mid);
          clear = clear && (d > 2 * offset || d <= pair.tol.geometric);
        }
        if (!clear) continue;
        for (const double side : {1.0, -1.0}) {
          const Vec2 p = mid + side * offset * left;
          ++tested;
          const Placement truth = tester.classify({p.x, p.y, slice.theta});
          EXPECT_EQ(truth, side > 0 ? Placement::free : Placement::blocked)
              << what << ": beside a piece of component " << c.id << " at (" << mid.x << ", "
              << mid.y << ")";
        }
      }
  return tested;
}

}  // namespace cslice::testkit
