#include "support/slice_oracle.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cslice/classify.hpp"
#include "cslice/slice.hpp"
#include "support/failures.hpp"

namespace cslice::testkit {

int check_slice_against_classify(const Pair& pair, double theta, int points, std::mt19937& rng,
                                 const std::string& what, bool sample_clearance) {
  const int before = failures_so_far();
  const Slice slice = compute_slice(pair, theta);
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

}  // namespace cslice::testkit
