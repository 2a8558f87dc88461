#include "support/free_poses.hpp"

namespace cslice::testkit {

std::optional<Pose> random_free_pose(const Pair& pair, std::mt19937& rng) {
  std::uniform_real_distribution<double> ut(-kPi, kPi), unit(0.0, 1.0);
  PlacementTester tester(pair);
  for (int slices = 0; slices < kMaxSlicesTried; ++slices) {
    const Slice s = compute_slice(pair, ut(rng));
    if (s.free_components.empty()) continue;
    const size_t n = s.free_components.size();
    const FreeComponent& fc =
        s.free_components[static_cast<size_t>(unit(rng) * static_cast<double>(n)) % n];
    Box box;
    for (const auto& cycle : fc.boundary)
      for (const ContactPiece& p : cycle) box.add(bounding_box(p.curve));
    if (!fc.bounded) box = box.inflated(0.3 * box.diagonal());
    for (int tries = 0; tries < 200; ++tries) {
      const Pose pose{box.lo.x + unit(rng) * (box.hi.x - box.lo.x),
                      box.lo.y + unit(rng) * (box.hi.y - box.lo.y), s.theta};
      if (s.locate({pose.x, pose.y}) == fc.id && tester.classify(pose) == Placement::free &&
          tester.boundary_distance(pose) > 2.0 * pair.tol.contact)
        return pose;
    }
  }
  return std::nullopt;
}

}  // namespace cslice::testkit
