#include "support/band.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace cslice::testkit {

bool deep_blocked(PlacementTester& tester, const Pose& pose, double d) {
  for (int k = 0; k < 8; ++k) {
    const Vec2 u = unit_vector(k * kPi / 4);
    if (!tester.blocked({pose.x + d * u.x, pose.y + d * u.y, pose.theta})) return false;
  }
  return true;
}

// Perfect fits count: a polygon turning in the circle through its corners (designed pair
// 6008) has no other contact space, only a degenerate point at every theta.
bool near_realizable(const Pair& pair, const Pose& pose, double d) {
  const Slice slice = compute_slice(pair, pose.theta);
  const Vec2 p{pose.x, pose.y};
  return std::any_of(
             slice.realizable.begin(), slice.realizable.end(),
             [&](const ContactPiece& piece) { return distance_to_curve(piece.curve, p) <= d; }) ||
         std::any_of(
             slice.degenerate.begin(), slice.degenerate.end(),
             [&](const DegenerateContact& c) { return distance_to_curve(c.curve, p) <= d; });
}

// A query within the critical angle of a critical orientation is answered from that slice
// (src/space/query.cpp). Turning by that angle moves no point further than the criticality
// tolerance, far inside the contact tolerance: contact in that slice is contact within the
// band, though at the query's own theta a fit that exists at the critical one only may
// overlap (designed pair 1068: 9.2e-7 rad from an exact fit, an overlap of 1e-6 that no
// translation undoes).
bool near_realizable_at_critical(const Pair& pair, const SlicedSpace& space, const Pose& pose,
                                 double d) {
  for (const CriticalOrientation& o : space.criticals.orientations)
    if (std::fabs(wrap_angle(pose.theta - o.theta)) <= pair.tol.critical_angle &&
        near_realizable(pair, {pose.x, pose.y, o.theta}, d))
      return true;
  return false;
}

Box query_box(const SlicedSpace& space) {
  Box box;
  for (const SpaceSlice& s : space.slices)
    for (const ContactSegment& c : s.slice.contact_segments) box.add(bounding_box(c.curve));
  const double margin = 0.1 * box.diagonal();
  return box.inflated(margin);
}

QueryAgreement compare_queries_with_classify(const Pair& pair, const SlicedSpace& space,
                                             SpaceQuery& q, int queries, unsigned seed,
                                             const std::string& name) {
  PlacementTester tester(pair);
  std::mt19937 rng(seed);
  const Box box = query_box(space);
  std::uniform_real_distribution<double> ux(box.lo.x, box.hi.x), uy(box.lo.y, box.hi.y),
      ut(-kPi, kPi);
  std::vector<std::pair<double, const Curve*>> pieces;
  for (const SpaceSlice& s : space.slices)
    for (const ContactPiece& p : s.slice.realizable) pieces.push_back({s.theta, &p.curve});
  std::uniform_real_distribution<double> unit(-1.0, 1.0), ut01(0.0, 1.0);
  std::uniform_int_distribution<size_t> upiece(0, pieces.empty() ? 0 : pieces.size() - 1);
  const double band = 2.0 * pair.tol.contact;
  QueryAgreement out;
  for (int i = 0; i < queries; ++i) {
    Pose pose{ux(rng), uy(rng), ut(rng)};
    if (i % 2 == 1 && !pieces.empty()) {
      const auto& [theta, curve] = pieces[upiece(rng)];
      const Vec2 p = point_at(*curve, ut01(rng));
      const double r = pair.tol.size * std::pow(10.0, -1.3 - 2.0 * ut01(rng));
      pose = {p.x + r * unit(rng), p.y + r * unit(rng), theta + space.max_step * unit(rng)};
    }
    const QueryAnswer a = q.query(pose);
    // Outside the band by boundary distance: free. Overlapping boundaries are at distance 0,
    // so blocked configurations are checked when they stay blocked translated by the band in
    // eight directions, unless a contact answer has a realizable piece that near.
    const Placement truth = tester.classify(pose);
    if (truth == Placement::contact) continue;
    if (truth == Placement::free && tester.boundary_distance(pose) <= band) continue;
    if (truth == Placement::blocked && !deep_blocked(tester, pose, band)) continue;
    if (truth == Placement::blocked && a.placement == Placement::contact &&
        (near_realizable(pair, pose, 0.75 * band) ||
         near_realizable_at_critical(pair, space, pose, 0.75 * band)))
      continue;
    ++out.checked;
    (truth == Placement::free ? out.free_count : out.blocked_count) += 1;
    if (a.placement != truth && ++out.mismatches <= 10)
      ADD_FAILURE() << name << ": at (" << pose.x << ", " << pose.y << ", " << pose.theta
                    << ") query says " << to_string(a.placement) << ", classify "
                    << to_string(truth);
    if (a.placement == Placement::free) {
      EXPECT_GE(a.component, 0) << name;
      EXPECT_LT(a.component, static_cast<int>(space.topology.components.size())) << name;
    }
  }
  return out;
}

}  // namespace cslice::testkit
