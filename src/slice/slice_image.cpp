// A slice mapped across a symmetry of the pair (include/cslice/symmetry.hpp).
#include <algorithm>

#include "cslice/slice.hpp"
#include "cslice/symmetry.hpp"

namespace cslice {

namespace {

class SliceMapper {
 public:
  explicit SliceMapper(const PairSymmetry& s) : s_(s), mirror_(s.plane.map.mirror) {}

  Vec2 point(Vec2 p) const { return s_.plane.apply(p); }

  // The image of c, reversed under a mirror: a mirror swaps left and right, and every curve of
  // a slice has a side that matters on its left (blocked space along a contact segment, the
  // component along a boundary piece).
  Curve curve(const Curve& c) const {
    if (c.is_segment()) {
      const Vec2 from = point(c.from), to = point(c.to);
      return mirror_ ? make_segment(to, from) : make_segment(from, to);
    }
    Curve r = c;
    r.from = point(c.from);
    r.to = point(c.to);
    r.center = point(c.center);
    r.start_angle = s_.plane.map.apply_angle(c.start_angle);
    if (!mirror_) return r;
    r.sweep = -c.sweep;
    r.bulge = -c.bulge;
    return reversed(r);
  }

  void pieces(std::vector<ContactPiece>& pieces, bool cycle) const {
    for (ContactPiece& p : pieces) p.curve = curve(p.curve);
    // A cycle runs the other way round under a mirror: its pieces in reverse order.
    if (cycle && mirror_) std::reverse(pieces.begin(), pieces.end());
  }

  void segments(std::vector<ContactSegment>& segments) const {
    for (ContactSegment& c : segments) {
      c.moving_feature = s_.moving_map[c.moving_feature];
      c.fixed_feature = s_.plane.feature_map[c.fixed_feature];
      c.curve = curve(c.curve);
    }
  }

 private:
  const PairSymmetry& s_;
  bool mirror_;
};

}  // namespace

Slice mapped_slice(const Slice& slice, const PairSymmetry& symmetry, double theta) {
  const SliceMapper map(symmetry);
  Slice out = slice;
  out.theta = theta;
  map.segments(out.contact_segments);
  for (FreeComponent& c : out.free_components) {
    c.sample = map.point(c.sample);
    for (std::vector<ContactPiece>& cycle : c.boundary) map.pieces(cycle, true);
  }
  map.pieces(out.realizable, false);
  for (DegenerateContact& d : out.degenerate) d.curve = map.curve(d.curve);
  for (ContactGraphEdge& e : out.contact_graph.edges) e.at = map.point(e.at);
  return out;
}

}  // namespace cslice
