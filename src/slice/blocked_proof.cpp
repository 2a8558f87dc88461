// Contact segments proven blocked (see blocked_proof.hpp).
#include "slice/blocked_proof.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <utility>

#include "geometry/clip.hpp"

namespace cslice {
namespace {

std::atomic<BlockedProofMode> g_mode{BlockedProofMode::automatic};

// Below this many contact segments per feature the proof costs more than it saves (measured on
// one-shot slices of the stars: at 0.5 per feature (smooth) 70% slower, at 1.8 10 to 28%
// slower, at 2.0 even, at 2.6 15 to 20% faster, at 4 16% faster, at 14.5 3.4 times faster;
// docs/performance.md, sixteenth session).
constexpr size_t kSegmentsPerFeatureWorthProving = 2;

// Adds an open span to `merged` (disjoint open spans sorted by lo, merged where they overlap;
// spans that only touch leave their common point uncovered) and returns whether they now
// cover [0, 1].
bool add_covers_unit(std::vector<BlockedProof::Span>& merged, BlockedProof::Span s) {
  size_t i = 0;
  while (i < merged.size() && !(merged[i].hi > s.lo)) ++i;
  size_t j = i;
  for (; j < merged.size() && merged[j].lo < s.hi; ++j) {
    s.lo = std::min(s.lo, merged[j].lo);
    s.hi = std::max(s.hi, merged[j].hi);
  }
  if (i == j) {
    merged.insert(merged.begin() + std::ptrdiff_t(i), s);
  } else {
    merged[i] = s;
    merged.erase(merged.begin() + std::ptrdiff_t(i + 1), merged.begin() + std::ptrdiff_t(j));
  }
  return s.lo < 0.0 && s.hi > 1.0;
}

// An arc not held whole by one slab is tried as two halves, those as halves again, and so
// on, this many times (pieces of an eighth). On gears two to four halvings cost the same and
// prove nearly every arc that 17 sample points find inside slabs (docs/performance.md,
// eighteenth session).
constexpr int kArcHalvings = 3;

bool is_line_target(const ContactSegment& s) {
  return !s.is_point && s.curve.is_segment();
}

// Where a target's cell is found: a line's midpoint, an arc's box's centre.
Vec2 target_point(const Curve& c) {
  if (c.is_segment()) return 0.5 * (c.from + c.to);
  const Box b = bounding_box(c);
  return 0.5 * (b.lo + b.hi);
}

}  // namespace

// An arc target, or a piece of one, as its support computations want it: the arc, and the
// unit vectors from its centre to its ends in counterclockwise order (lo to hi).
struct BlockedProof::ArcTarget {
  Curve arc;
  Vec2 lo, hi;
  bool full, over_half;  // the whole circle; more than half of it

  explicit ArcTarget(const Curve& c)
      : arc(c), full(c.is_full_circle()), over_half(std::fabs(c.sweep) > kPi) {
    const Vec2 a = (c.from - c.center) * (1.0 / c.radius), b = (c.to - c.center) * (1.0 / c.radius);
    lo = c.sweep > 0.0 ? a : b;
    hi = c.sweep > 0.0 ? b : a;
  }

  // Its two halves, which share the middle point.
  std::pair<ArcTarget, ArcTarget> halves() const {
    const double half = 0.5 * arc.sweep, middle_angle = arc.start_angle + half;
    const Vec2 middle = arc.center + arc.radius * unit_vector(middle_angle);
    return {
        ArcTarget(
            make_arc_between(arc.center, arc.radius, arc.start_angle, half, arc.from, middle)),
        ArcTarget(make_arc_between(arc.center, arc.radius, middle_angle, half, middle, arc.to))};
  }

  // Whether the arc holds the point of its circle in direction d (unit). Where round-off
  // decides (d along an end's direction), either answer moves an extreme by a negligible
  // amount: the end lies there too.
  bool holds(Vec2 d) const {
    if (full) return true;
    if (!over_half) return cross(lo, d) >= 0.0 && cross(d, hi) >= 0.0;
    return !(cross(hi, d) > 0.0 && cross(d, lo) > 0.0);  // not in the gap, under half a turn
  }

  // The least and greatest of dot(p - origin, n) + k over the arc's points p (n unit): at an
  // end, or where the circle's normal is n or -n if the arc holds that point.
  std::pair<double, double> extremes(Vec2 origin, Vec2 n, double k) const {
    const double at_from = dot(arc.from - origin, n) + k, at_to = dot(arc.to - origin, n) + k;
    const double at_center = dot(arc.center - origin, n) + k;
    double least = std::min(at_from, at_to), greatest = std::max(at_from, at_to);
    if (holds(n)) greatest = std::max(greatest, at_center + arc.radius);
    if (holds(-n)) least = std::min(least, at_center - arc.radius);
    return {least, greatest};
  }
};

namespace {

using ArcTarget = BlockedProof::ArcTarget;

}  // namespace

bool worth_proving(const Pair& pair, size_t contact_segments) {
  switch (g_mode.load(std::memory_order_relaxed)) {
    case BlockedProofMode::always:
      return true;
    case BlockedProofMode::never:
      return false;
    case BlockedProofMode::automatic:
      break;
  }
  return contact_segments > kSegmentsPerFeatureWorthProving *
                                size_t(pair.moving.feature_count() + pair.fixed.feature_count());
}

void set_blocked_proof_mode(BlockedProofMode mode) {
  g_mode.store(mode);
}

double proof_margin(const Pair& pair) {
  return kProvenBlockedMarginPerGeometric * pair.tol.geometric;
}

PairRegions pair_regions(const Pair& pair) {
  const double margin = proof_margin(pair);
  return {material_regions(pair.moving, margin), material_regions(pair.fixed, margin)};
}

BlockedProof::CellRange BlockedProof::cells(const Box& b) const {
  return {std::clamp(int((b.lo.x - origin_.x) * per_cell_), 0, columns_ - 1),
          std::clamp(int((b.hi.x - origin_.x) * per_cell_), 0, columns_ - 1),
          std::clamp(int((b.lo.y - origin_.y) * per_cell_), 0, rows_ - 1),
          std::clamp(int((b.hi.y - origin_.y) * per_cell_), 0, rows_ - 1)};
}

void BlockedProof::find(const std::vector<ContactSegment>& segments, const PairRegions& regions,
                        double margin, std::vector<char>& proven) {
  proven.assign(segments.size(), 0);
  add_slabs(segments, regions, margin);
  if (slabs_.empty()) return;
  index_slabs(segments);
  order_targets(segments);
  stamp_.assign(slabs_.size(), -1);
  query_ = -1;
  hint_ = -1;
  for (const Target& t : targets_) {
    const bool held = t.line ? covered(t.from, t.to, t.id)
                             : covered_arc(ArcTarget(segments[size_t(t.id)].curve), 0);
    if (held) proven[size_t(t.id)] = 1;
  }
}

// One slab per contact segment of a disc feature (vertex or arc) on a straight one, either
// way round, whose segment has a region deeper than twice the margin. The disc touches the
// segment at one point of its boundary, the same all along the contact segment (src/contacts:
// the segment shifted, or turned through theta + pi, whole). So a slab's frame is its contact
// segment's: start, direction, and material on the left (the blocked side).
void BlockedProof::add_slabs(const std::vector<ContactSegment>& segments,
                             const PairRegions& regions, double margin) {
  slabs_.clear();
  slab_boxes_.clear();
  for (const ContactSegment& s : segments) {
    if (!is_line_target(s)) continue;
    const MaterialRegion* region =
        s.kind == ContactKind::vertex_segment || s.kind == ContactKind::arc_segment
            ? &regions.fixed[size_t(s.fixed_feature)]
        : s.kind == ContactKind::segment_vertex || s.kind == ContactKind::segment_arc
            ? &regions.moving[size_t(s.moving_feature)]
            : nullptr;
    if (!region || region->depth <= 2.0 * margin) continue;
    const Vec2 d = s.curve.to - s.curve.from;
    const double length = cslice::length(d);
    if (!(length > 0.0)) continue;
    const Vec2 along = d * (1.0 / length), across = perp_left(along), from = s.curve.from;
    const Slab slab{from,
                    along,
                    across,
                    length,
                    margin,
                    region->depth - margin,
                    region->start_side,
                    region->end_side,
                    s.id};
    // Its corners: its ends, and where the corner bisectors reach its depth (past the apex
    // when the bisectors meet first: the box still holds the slab).
    auto world = [&](Vec2 v) { return from + v.x * along + v.y * across; };
    Box box;
    box.add(from);
    box.add(s.curve.to);
    box.add(world(region->start_at(region->depth)));
    box.add(world(region->end_at(region->depth, length)));
    slabs_.push_back(slab);
    slab_boxes_.push_back(box);
  }
}

// A uniform grid of cells about as wide as the average slab, each listing the slabs whose
// boxes overlap it.
void BlockedProof::index_slabs(const std::vector<ContactSegment>& segments) {
  Box all;
  double extent = 0.0;
  for (const Box& b : slab_boxes_) {
    all.add(b);
    extent += 0.5 * (b.hi.x - b.lo.x + b.hi.y - b.lo.y);
  }
  for (const ContactSegment& s : segments)
    if (!s.is_point) all.add(bounding_box(s.curve));
  const double n = double(slabs_.size());
  const double w = all.hi.x - all.lo.x, h = all.hi.y - all.lo.y;
  // At least as wide as a quarter of the slabs' number of cells would fill the whole box.
  cell_ = std::max({extent / n, std::sqrt(w * h / (4.0 * n)), 1e-300});
  columns_ = int(std::min(w / cell_, 4.0 * n)) + 1;
  rows_ = int(std::min(h / cell_, 4.0 * n)) + 1;
  per_cell_ = 1.0 / cell_;
  origin_ = all.lo;
  cell_start_.assign(size_t(columns_) * size_t(rows_) + 1, 0);
  slab_cells_.clear();
  for (const Box& b : slab_boxes_) {
    const CellRange r = slab_cells_.emplace_back(cells(b));
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x)
        ++cell_start_[size_t(y) * size_t(columns_) + size_t(x) + 1];
  }
  int fullest = 0;  // slabs in the fullest cell
  for (size_t c = 1; c < cell_start_.size(); ++c) {
    fullest = std::max(fullest, cell_start_[c]);
    cell_start_[c] += cell_start_[c - 1];
  }
  near_.resize(size_t(fullest));
  cell_slabs_.resize(size_t(cell_start_.back()));
  cell_boxes_.resize(size_t(cell_start_.back()));
  fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (size_t k = 0; k < slabs_.size(); ++k) {
    const CellRange r = slab_cells_[k];
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x) {
        const size_t at = size_t(fill_[size_t(y) * size_t(columns_) + size_t(x)]++);
        cell_slabs_[at] = int(k);
        cell_boxes_[at] = slab_boxes_[k];
      }
  }
}

// The targets (every contact segment but a point) by the cell of target_point, rows walked
// back and forth: neighbours follow each other, and the slab that covered one is tried first
// on the next.
void BlockedProof::order_targets(const std::vector<ContactSegment>& segments) {
  auto cell_of = [&](const Curve& c) {
    Box mid;
    mid.add(target_point(c));
    const CellRange r = cells(mid);
    return size_t(r.y0) * size_t(columns_) + size_t(r.y0 % 2 == 0 ? r.x0 : columns_ - 1 - r.x0);
  };
  target_start_.assign(size_t(columns_) * size_t(rows_) + 1, 0);
  target_cells_.clear();
  for (const ContactSegment& s : segments)
    if (!s.is_point) ++target_start_[target_cells_.emplace_back(cell_of(s.curve)) + 1];
  for (size_t c = 1; c < target_start_.size(); ++c) target_start_[c] += target_start_[c - 1];
  targets_.resize(size_t(target_start_.back()));
  size_t k = 0;
  for (const ContactSegment& s : segments)
    if (!s.is_point)
      targets_[size_t(target_start_[target_cells_[k++]]++)] = {s.curve.from, s.curve.to, s.id,
                                                               s.curve.is_segment()};
}

namespace {

// Where the target (ends p0, p1) lies inside the slab: false when nowhere, else its open
// span, `whole` when end to end. The corner sides need no margin (material_regions.hpp).
template <class Slab>
inline bool inside(const Slab& s, Vec2 p0, Vec2 p1, BlockedProof::Span& span, bool& whole) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const Vec2 r0 = p0 - s.from, r1 = p1 - s.from;
  const Vec2 q0{dot(r0, s.along), dot(r0, s.across)}, q1{dot(r1, s.along), dot(r1, s.across)};
  const Vec2 end{s.length, 0.0};
  span = {-inf, inf};
  whole = true;
  return narrow_to_band(q0.y, q1.y, s.low, s.high, span.lo, span.hi, whole) &&
         narrow_to_band(cross(s.start_side, q0), cross(s.start_side, q1), -inf, 0.0, span.lo,
                        span.hi, whole) &&
         narrow_to_band(cross(s.end_side, q0 - end), cross(s.end_side, q1 - end), 0.0, inf, span.lo,
                        span.hi, whole);
}

// Whether the slab holds the whole arc: the least and greatest of each of its three strips'
// functions over the arc within the strip's bounds (the functions of `inside`, in world
// terms: a corner side v bounds the slab along the normal v.x across - v.y along).
template <class Slab>
bool holds_arc(const Slab& s, const ArcTarget& arc) {
  const auto [low, high] = arc.extremes(s.from, s.across, 0.0);
  if (!(low > s.low && high < s.high)) return false;
  const Vec2 start_normal = s.start_side.x * s.across - s.start_side.y * s.along;
  if (!(arc.extremes(s.from, start_normal, 0.0).second < 0.0)) return false;
  const Vec2 end_normal = s.end_side.x * s.across - s.end_side.y * s.along;
  return arc.extremes(s.from, end_normal, s.end_side.y * s.length).first > 0.0;
}

}  // namespace

// Calls stop(j) once for each slab j whose box overlaps b, until it returns true; whether
// it did.
template <class Stop>
bool BlockedProof::any_slab_near(const Box& b, Stop stop) {
  const CellRange r = cells(b);
  ++query_;
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) {
      const size_t cell = size_t(y) * size_t(columns_) + size_t(x);
      // The slabs whose boxes overlap first, without a branch on each box: half of them
      // overlap, and which ones follows no pattern a branch predictor finds.
      const int begin = cell_start_[cell], end = cell_start_[cell + 1];
      int* near = near_.data();
      size_t count = 0;
      for (int k = begin; k < end; ++k) {
        near[count] = cell_slabs_[size_t(k)];
        count += size_t(cell_boxes_[size_t(k)].overlaps(b));
      }
      for (size_t i = 0; i < count; ++i) {
        const int j = near[i];
        if (stamp_[size_t(j)] == query_) continue;  // met in an earlier cell
        stamp_[size_t(j)] = query_;
        if (stop(j)) return true;
      }
    }
  return false;
}

// Whether one slab holds the whole arc, or else each of its halves, and so on down to
// pieces of 1 / 2^kArcHalvings of it: pieces that share their ends, each held whole by a
// slab, cover it with the margin all along.
bool BlockedProof::covered_arc(const ArcTarget& arc, int halvings) {
  if (hint_ >= 0 && holds_arc(slabs_[size_t(hint_)], arc)) return true;
  const bool held = any_slab_near(arc_bounding_box(arc.arc), [&](int j) {
    if (!holds_arc(slabs_[size_t(j)], arc)) return false;
    hint_ = j;
    return true;
  });
  if (held) return true;
  if (halvings == kArcHalvings) return false;
  const auto [first, second] = arc.halves();
  return covered_arc(first, halvings + 1) && covered_arc(second, halvings + 1);
}

// Whether the target is covered end to end by the slabs of other contact segments. One slab
// often covers it whole; else the spans of the slabs near it are merged as they are found,
// until they cover it (so a target left unproven is the only one that reads them all).
bool BlockedProof::covered(Vec2 p0, Vec2 p1, int id) {
  Span span;
  bool whole = false;
  if (hint_ >= 0 && slabs_[size_t(hint_)].segment != id &&
      inside(slabs_[size_t(hint_)], p0, p1, span, whole) && whole)
    return true;
  Box b;
  b.add(p0);
  b.add(p1);
  spans_.clear();
  return any_slab_near(b, [&](int j) {
    const Slab& s = slabs_[size_t(j)];
    if (s.segment == id || !inside(s, p0, p1, span, whole)) return false;
    if (whole) {
      hint_ = j;
      return true;
    }
    return add_covers_unit(spans_, span);
  });
}

}  // namespace cslice
