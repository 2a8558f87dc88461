// Slice::locate: the free component around a point. Topology and queries ask it for many
// points per slice (component samples in neighbouring slices), and nearly every boundary
// piece lies far from the point, so each piece is first tried by bounds that settle its two
// questions (within epsilon? toggles parity?) exactly as the full tests would.
#include "cslice/slice.hpp"
#include "geometry/near_curve.hpp"
#include "parts/loop_queries.hpp"

namespace cslice {
namespace {

// Whether toggles_parity(c, p) can be true. It is false when the rightward ray's chord test
// fails at its first step (both ends on one side of p's height: ray_crosses_chord's own
// comparison) and the circular segment's at its first (p not strictly inside the arc's
// circle: in_circular_segment's own comparison, also the full circle's), so this repeats
// those comparisons and leaves the rest to toggles_parity.
bool may_toggle_parity(const Curve& c, Vec2 p) {
  if ((c.from.y > p.y) != (c.to.y > p.y)) return true;
  return c.is_arc() && !(length_squared(p - c.center) >= c.radius * c.radius);
}

// Even-odd over all boundary cycles of a component: the parity of their union. With
// kNearTest, -1 as soon as p is within eps of a piece.
template <bool kNearTest>
int locate_in(const Slice& s, Vec2 p) {
  for (const FreeComponent& c : s.free_components) {
    bool inside = !c.bounded;
    for (const auto& cycle : c.boundary) {
      for (const ContactPiece& piece : cycle) {
        if (kNearTest && within_distance(piece.curve, p, s.epsilon)) return -1;
        if (may_toggle_parity(piece.curve, p) && toggles_parity(piece.curve, p)) inside = !inside;
      }
    }
    if (inside) return c.id;
  }
  return -1;
}

}  // namespace

int Slice::locate(Vec2 p) const {
  return locate_in<true>(*this, p);
}

int Slice::locate_off_boundary(Vec2 p) const {
  return locate_in<false>(*this, p);
}

}  // namespace cslice
