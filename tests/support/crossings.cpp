#include "support/crossings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>

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

int carry_finely(const Pair& pair, Vec2 p, double from, double to, Vec2* landed) {
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
    if (c >= 0 && landed) *landed = slice.free_components[c].sample;
    if (c < 0 || next == to) return c;
    p = slice.free_components[c].sample;
    theta = next;
  }
  return -1;
}

namespace {

// Where each free component of the stored slice next to critical slice `at` (after it when
// from_after, else before it) lands when carried across to the stored slice on the other
// side: (component, component landed in), for those that get there.
struct Crossing {
  int from, to;  // stored slice indices
  std::vector<std::pair<int, int>> landed;
};

Crossing carry_across(const Pair& pair, const SlicedSpace& space, int at, bool from_after) {
  const int n = static_cast<int>(space.slices.size());
  Crossing x{(at + (from_after ? 1 : n - 1)) % n, (at + (from_after ? n - 1 : 1)) % n, {}};
  const SpaceSlice &a = space.slices[x.from], &b = space.slices[x.to];
  const double target = a.theta + wrap_angle(b.theta - a.theta);
  for (const FreeComponent& c : a.slice.free_components) {
    Vec2 at;
    if (carry_finely(pair, c.sample, a.theta, target, &at) < 0) continue;  // vanishes there
    // The stored slice's own component there: one mapped across a symmetry of the pair lists
    // its components in its source's order, not the computed slice's.
    const int land = b.slice.locate(at);
    EXPECT_GE(land, 0) << "the sample where component " << c.id << " of the slice at " << a.theta
                       << " lands is not free in the stored slice at " << b.theta;
    if (land >= 0) x.landed.emplace_back(c.id, land);
  }
  return x;
}

void expect_landed_joined(const SlicedSpace& space, int at, const Crossing& x,
                          const std::string& what) {
  for (auto [c, land] : x.landed)
    EXPECT_EQ(space.topology.slice_components[x.from][c],
              space.topology.slice_components[x.to][land])
        << what << ": component " << c << " of the slice at " << space.slices[x.from].theta
        << " carried across the critical orientation " << space.slices[at].theta;
}

const CriticalTransition* transition_at(const SlicedSpace& space, int at) {
  for (const CriticalTransition& t : space.topology.transitions)
    if (t.theta == space.slices[at].theta) return &t;
  return nullptr;
}

}  // namespace

int expect_crossings_joined(const Pair& pair, const SlicedSpace& space, int at, bool from_after,
                            const std::string& what) {
  const Crossing x = carry_across(pair, space, at, from_after);
  expect_landed_joined(space, at, x, what);
  return static_cast<int>(x.landed.size());
}

int expect_joins_witnessed(const Pair& pair, const SlicedSpace& space, int at,
                           const std::string& what) {
  const CriticalTransition* t = transition_at(space, at);
  if (t == nullptr) {
    ADD_FAILURE() << what << ": no transition at the critical slice " << space.slices[at].theta;
    return 0;
  }
  const std::vector<std::vector<int>>& cells = space.topology.slice_cells;
  // Classes of cells the carries join (kept apart from the library's own union-find).
  std::vector<int> parent(space.topology.cells.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int c) {
    while (parent[c] != c) c = parent[c];
    return c;
  };
  // Cells whose component next to the critical slice is thinner than that slice's epsilon
  // band (its own sample does not locate in it): no carry can start there, so no carry can
  // witness their joins (designed pairs 822 and 4314: slivers of area 4e-13 in intervals of
  // 2e-4 rad).
  std::vector<char> too_thin(parent.size(), 0);
  for (bool from_after : {false, true}) {
    const Crossing x = carry_across(pair, space, at, from_after);
    expect_landed_joined(space, at, x, what);
    for (auto [c, land] : x.landed) parent[root(cells[x.from][c])] = root(cells[x.to][land]);
    const Slice& side = space.slices[x.from].slice;
    for (const FreeComponent& c : side.free_components)
      if (side.locate(c.sample) != c.id) too_thin[cells[x.from][c.id]] = 1;
  }
  int unwitnessed = 0;
  for (const TransitionEvent& e : t->events) {
    std::vector<int> joined;
    for (const std::vector<int>* side : {&e.before, &e.after})
      for (int cell : *side)
        if (!too_thin[cell]) joined.push_back(cell);
    for (int cell : joined) {
      if (root(cell) == root(joined.front())) continue;
      ++unwitnessed;
      ADD_FAILURE() << what << ": cells " << joined.front() << " and " << cell
                    << " joined across the critical orientation " << t->theta
                    << ", but no component carried across joins them";
    }
  }
  return unwitnessed;
}

}  // namespace cslice::testkit
