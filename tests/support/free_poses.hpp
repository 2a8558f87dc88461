// Random free configurations for path tests and benchmarks (a plain source file, no
// GoogleTest, so the benchmarks can share it).
#pragma once

#include <optional>
#include <random>

#include "cslice/classify.hpp"
#include "cslice/slice.hpp"

namespace cslice::testkit {

// A random theta, a random free component of the slice there, a random point of it
// (rejection in the box of its boundary, grown for an unbounded one), free by classify with
// clearance above twice the contact tolerance. Nothing when kMaxSlicesTried orientations give
// none (a tight fit whose free space is everywhere thinner than that), rather than a hang.
inline constexpr int kMaxSlicesTried = 200;
std::optional<Pose> random_free_pose(const Pair& pair, std::mt19937& rng);

}  // namespace cslice::testkit
