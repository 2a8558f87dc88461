// A slice mapped across a symmetry of the pair (include/cslice/symmetry.hpp).
#include "slice/slice_image.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

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
    Curve r = c;
    r.from = point(c.from);
    r.to = point(c.to);
    if (c.is_arc()) {
      r.center = point(c.center);
      r.start_angle = s_.plane.map.apply_angle(c.start_angle);
      if (mirror_) {  // the image turns the other way
        r.sweep = -c.sweep;
        r.bulge = -c.bulge;
      }
    }
    return mirror_ ? reversed(r) : r;
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

// The contact segment at theta that each mapped one is: the same label (a feature pair rarely
// makes two; then the nearest by its ends), or -1.
std::vector<int> counterparts(const std::vector<ContactSegment>& mapped,
                              const std::vector<ContactSegment>& fresh) {
  const auto label = [](const ContactSegment& c) {
    return std::pair{c.moving_feature, c.fixed_feature};
  };
  std::vector<int> by_label(fresh.size());
  std::iota(by_label.begin(), by_label.end(), 0);
  std::sort(by_label.begin(), by_label.end(),
            [&](int a, int b) { return label(fresh[size_t(a)]) < label(fresh[size_t(b)]); });
  std::vector<int> out(mapped.size(), -1);
  std::vector<char> taken(fresh.size(), false);
  for (size_t i = 0; i < mapped.size(); ++i) {
    const ContactSegment& m = mapped[i];
    auto it = std::lower_bound(by_label.begin(), by_label.end(), label(m),
                               [&](int f, auto l) { return label(fresh[size_t(f)]) < l; });
    double best = std::numeric_limits<double>::infinity();
    for (; it != by_label.end() && label(fresh[size_t(*it)]) == label(m); ++it) {
      const ContactSegment& f = fresh[size_t(*it)];
      const double d = distance(f.curve.from, m.curve.from) + distance(f.curve.to, m.curve.to);
      if (!taken[size_t(*it)] && f.is_point == m.is_point && d < best) {
        best = d;
        out[i] = *it;
      }
    }
    if (out[i] >= 0) taken[size_t(out[i])] = true;
  }
  return out;
}

// Calls f on every piece of the slice: the realizable ones and those of the boundary cycles.
template <class F>
void for_each_piece(Slice& slice, F f) {
  for (ContactPiece& p : slice.realizable) f(p);
  for (FreeComponent& c : slice.free_components)
    for (std::vector<ContactPiece>& cycle : c.boundary)
      for (ContactPiece& p : cycle) f(p);
}

// Whether curve c runs along the whole of piece p: within eps of its ends and its middle.
bool runs_along(const Curve& c, const Curve& p, double eps) {
  return distance_to_curve(c, point_at(p, 0.5)) <= eps && distance_to_curve(c, p.from) <= eps &&
         distance_to_curve(c, p.to) <= eps;
}

// Each piece named by the lowest id of the realizable contact segments it runs along.
void name_coincident_pieces(Slice& slice) {
  const auto rename = [&](ContactPiece& piece) {
    for (int id : slice.contact_graph.nodes) {  // ascending: the first found is the lowest
      if (id >= piece.segment) return;
      if (runs_along(slice.contact_segments[size_t(id)].curve, piece.curve, slice.epsilon)) {
        piece.segment = id;
        return;
      }
    }
  };
  for_each_piece(slice, rename);
}

}  // namespace

std::optional<Slice> mapped_slice_as_computed(const Slice& source, const PairSymmetry& symmetry,
                                              double theta, ContactMaker& contacts) {
  Slice out = mapped_slice(source, symmetry, theta);
  std::vector<ContactSegment> fresh;
  contacts.segments(theta, fresh);
  const std::vector<int> to = counterparts(out.contact_segments, fresh);
  // What the source's structure uses must be there; what the arrangement would cut must match.
  std::vector<char> used(out.contact_segments.size(), false), matched(fresh.size(), false);
  for (int id : realizable_segments(out)) used[size_t(id)] = true;
  for (size_t i = 0; i < to.size(); ++i) {
    const bool lengthy = curve_length(out.contact_segments[i].curve) > out.epsilon;
    if (to[i] < 0 && (used[i] || lengthy)) return std::nullopt;
    if (to[i] >= 0) matched[size_t(to[i])] = true;
  }
  for (size_t j = 0; j < fresh.size(); ++j)
    if (!matched[j] && (fresh[j].is_point || curve_length(fresh[j].curve) > out.epsilon))
      return std::nullopt;
  out.contact_segments = std::move(fresh);
  const auto id = [&](int old) { return to[size_t(old)]; };
  for_each_piece(out, [&](ContactPiece& p) { p.segment = id(p.segment); });
  for (DegenerateContact& d : out.degenerate) {
    for (int& s : d.segments) s = id(s);
    std::sort(d.segments.begin(), d.segments.end());
  }
  for (int& n : out.contact_graph.nodes) n = id(n);
  std::sort(out.contact_graph.nodes.begin(), out.contact_graph.nodes.end());
  for (ContactGraphEdge& e : out.contact_graph.edges) {
    e.a = id(e.a);
    e.b = id(e.b);
    if (e.a > e.b) std::swap(e.a, e.b);
  }
  if (out.coincident_pieces) name_coincident_pieces(out);
  return out;
}

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
