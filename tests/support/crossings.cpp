#include "support/crossings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "cslice/part.hpp"
#include "cslice/slice.hpp"

namespace cslice::testkit {

namespace {

// How far p lies from the boundary of the slice's free space.
double clearance_in(const Slice& slice, Vec2 p) {
  double d = std::numeric_limits<double>::infinity();
  for (const FreeComponent& c : slice.free_components)
    for (const auto& cycle : c.boundary)
      for (const ContactPiece& piece : cycle) d = std::min(d, distance_to_curve(piece.curve, p));
  return d;
}

constexpr int kMaxSteps = 5000;

}  // namespace

int carry_finely(const Pair& pair, Vec2 p, double from, double to) {
  Slicer slicer(pair);
  const double reach = moving_reach(pair.moving);
  Slice slice = slicer.slice(wrap_angle(from));
  double theta = from;
  for (int k = 0; k < kMaxSteps; ++k) {
    if (slice.locate(p) < 0) return -1;
    const double step = 0.5 * (clearance_in(slice, p) - slice.epsilon) / reach;
    if (!(step > pair.tol.angular)) return -1;
    const double next = to < theta ? std::max(to, theta - step) : std::min(to, theta + step);
    slice = slicer.slice(wrap_angle(next));
    const int c = slice.locate(p);
    if (c < 0 || next == to) return c;
    p = slice.free_components[c].sample;
    theta = next;
  }
  return -1;
}

int expect_crossings_joined(const Pair& pair, const SlicedSpace& space, int at, bool from_after,
                            const std::string& what) {
  const int n = static_cast<int>(space.slices.size());
  const int from = (at + (from_after ? 1 : n - 1)) % n, to = (at + (from_after ? n - 1 : 1)) % n;
  const SpaceSlice &a = space.slices[from], &b = space.slices[to];
  const double target = a.theta + wrap_angle(b.theta - a.theta);
  int crossed = 0;
  for (const FreeComponent& c : a.slice.free_components) {
    const int land = carry_finely(pair, c.sample, a.theta, target);
    if (land < 0) continue;  // it vanishes at the critical orientation
    ++crossed;
    EXPECT_EQ(space.topology.slice_components[from][c.id],
              space.topology.slice_components[to][land])
        << what << ": component " << c.id << " of the slice at " << a.theta
        << " carried across the critical orientation " << space.slices[at].theta;
  }
  return crossed;
}

}  // namespace cslice::testkit
