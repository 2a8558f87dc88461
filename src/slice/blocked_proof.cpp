// Contact segments proven blocked (see blocked_proof.hpp).
#include "slice/blocked_proof.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <utility>

#include "geometry/clip.hpp"
#include "slice/group_by.hpp"

namespace cslice {
namespace {

std::atomic<BlockedProofMode> g_mode{BlockedProofMode::automatic};

// Below this many contact segments per feature the proof costs more than it saves. Measured
// on one-shot slices of the stars in the sixteenth session: at 0.5 per feature (smooth) 70%
// slower, at 1.8 10 to 28% slower, at 2.0 even, at 2.6 15 to 20% faster, at 14.5 3.4 times
// faster. Since the arrangement leaves out the pieces inside crossings (twenty-fourth
// session) it costs polygon pairs, whose contact segments are all lines, less: rough stars
// at 4.05 per feature are 8% slower with the proof, at 4.26 even, at 6.3 17% faster, at 14.5
// 1.9 times faster; a gear of 8 teeth (3.3 per feature, mostly arcs) is 5% faster with it
// (docs/performance.md).
constexpr double kSegmentsPerFeatureWorthProving = 2.0;
constexpr double kLineSegmentsPerFeatureWorthProving = 4.5;

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

// Above this many contact segments the arrays a slab or a target adds to are sized for
// all of them at once. Their buffers are then fresh at every one-shot slice (a thread keeps
// at most 64 MB of them, src/slice/slice.cpp), and grown by doubling each size faults in a
// new block past the allocator's mmap threshold: rough n = 3,000 one-shot 430 -> 355 ms.
// Below it, reserving made the allocator stop reusing freed blocks (rough n = 300 one-shot
// 2.03 -> 2.44 ms, 18% of it page faults).
constexpr size_t kReserveAbove = size_t(1) << 17;

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
  const bool lines_only = pair.moving.arc_count() + pair.fixed.arc_count() == 0;
  const double per_feature =
      lines_only ? kLineSegmentsPerFeatureWorthProving : kSegmentsPerFeatureWorthProving;
  return double(contact_segments) >
         per_feature * double(pair.moving.feature_count() + pair.fixed.feature_count());
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
  collect(segments, regions, margin);
  if (slabs_.empty()) return;
  index_slabs();
  order_targets();
  stamp_.assign(slabs_.size(), -1);
  query_ = -1;
  hint_ = -1;
  recent_.clear();
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
//
// The targets (every contact segment but a point) and the box of them all are taken in the
// same pass: at a thousand vertices a side the contact segments outgrow the cache, and each
// pass over them cost as much as a tenth of the proof.
void BlockedProof::collect(const std::vector<ContactSegment>& segments, const PairRegions& regions,
                           double margin) {
  slabs_.clear();
  slab_boxes_.clear();
  unordered_.clear();
  target_points_.clear();
  all_ = Box{};
  if (segments.size() > kReserveAbove) {
    slabs_.reserve(segments.size());
    slab_boxes_.reserve(segments.size());
    unordered_.reserve(segments.size());
    target_points_.reserve(segments.size());
  }
  for (const ContactSegment& s : segments) {
    if (s.is_point) continue;
    const bool line = s.curve.is_segment();
    const Box target_box = bounding_box(s.curve);
    all_.add(target_box);
    unordered_.push_back({s.curve.from, s.curve.to, s.id, line});
    target_points_.push_back(0.5 * (target_box.lo + target_box.hi));
    if (!line) continue;
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
    all_.add(box);
  }
}

// The slabs, deepest first, in kDepthClasses classes of equal width: each cell lists its
// slabs in this order. A deep slab holds more of a target crossing it, so the spans that
// cover a target come sooner: a third fewer slabs tested on rough stars of 1,000 vertices
// a side, a sixth fewer at 300, at the cost of a counting sort.
void BlockedProof::order_by_depth() {
  constexpr int kDepthClasses = 256;
  double deepest = 0.0;
  for (const Slab& s : slabs_) deepest = std::max(deepest, s.high);
  const double per_class = deepest > 0.0 ? (kDepthClasses - 1) / deepest : 0.0;
  group_by(
      slabs_.size(), kDepthClasses,
      [&](size_t k) { return size_t(kDepthClasses - 1 - int(slabs_[k].high * per_class)); },
      group_start_, by_depth_, group_fill_);
}

// A uniform grid of cells about as wide as the average slab, each listing the slabs whose
// boxes overlap it.
void BlockedProof::index_slabs() {
  const Box& all = all_;
  double extent = 0.0;
  for (const Box& b : slab_boxes_) extent += 0.5 * (b.hi.x - b.lo.x + b.hi.y - b.lo.y);
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
  order_by_depth();
  for (const int k : by_depth_) {
    const CellRange r = slab_cells_[size_t(k)];
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x) {
        const size_t at = size_t(fill_[size_t(y) * size_t(columns_) + size_t(x)]++);
        cell_slabs_[at] = k;
        cell_boxes_[at] = slab_boxes_[size_t(k)];
      }
  }
}

// The row-by-row walk of the grid's cells, rows back and forth: cells next to each other in
// the walk are neighbours.
size_t BlockedProof::walk_index(Vec2 p) const {
  Box at;
  at.add(p);
  const CellRange r = cells(at);
  return size_t(r.y0) * size_t(columns_) + size_t(r.y0 % 2 == 0 ? r.x0 : columns_ - 1 - r.x0);
}

// The targets by the cell of their box's centre in the walk: neighbours follow each other,
// and the slabs that covered one are tried first on the next.
void BlockedProof::order_targets() {
  const size_t n = unordered_.size();
  target_cells_.resize(n);
  for (size_t k = 0; k < n; ++k) target_cells_[k] = walk_index(target_points_[k]);
  group_by(
      n, size_t(columns_) * size_t(rows_), [&](size_t k) { return target_cells_[k]; }, group_start_,
      target_order_, group_fill_);
  targets_.resize(n);
  for (size_t i = 0; i < n; ++i) targets_[i] = unordered_[size_t(target_order_[i])];
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

// Slabs whose boxes are checked before the first of them is tested: 8 to 32 take 12% off
// the proof on rough stars of 1,000 vertices a side, against a whole cell at once, and are
// even at 300.
constexpr int kSlabsPerBatch = 16;

// Calls stop(j) once for each slab j whose box overlaps b and whose stamp is not the
// current query's, until it returns true; whether it did.
template <class Stop>
bool BlockedProof::any_slab_near(const Box& b, Stop stop) {
  const CellRange r = cells(b);
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) {
      const size_t cell = size_t(y) * size_t(columns_) + size_t(x);
      // The slabs whose boxes overlap first, without a branch on each box: half of them
      // overlap, and which ones follows no pattern a branch predictor finds. A few at a
      // time: the deep slabs come first, and often cover the target before the rest.
      const int begin = cell_start_[cell], end = cell_start_[cell + 1];
      int* near = near_.data();
      for (int chunk = begin; chunk < end; chunk += kSlabsPerBatch) {
        size_t count = 0;
        for (int k = chunk, stop_at = std::min(end, chunk + kSlabsPerBatch); k < stop_at; ++k) {
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
    }
  return false;
}

// Whether one slab holds the whole arc, or else each of its halves, and so on down to
// pieces of 1 / 2^kArcHalvings of it: pieces that share their ends, each held whole by a
// slab, cover it with the margin all along.
bool BlockedProof::covered_arc(const ArcTarget& arc, int halvings) {
  if (hint_ >= 0 && holds_arc(slabs_[size_t(hint_)], arc)) return true;
  ++query_;
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
// until they cover it (so a target left unproven is the only one that reads them all). The
// slabs that gave spans to the last target proven are tried first: the targets come in
// walk order, and neighbours are mostly covered by the same few slabs.
bool BlockedProof::covered(Vec2 p0, Vec2 p1, int id) {
  Span span;
  bool whole = false;
  spans_.clear();
  giving_.clear();
  ++query_;
  auto try_slab = [&](int j) {
    const Slab& s = slabs_[size_t(j)];
    if (s.segment == id || !inside(s, p0, p1, span, whole)) return false;
    if (whole) {
      giving_.assign(1, j);
      return true;
    }
    giving_.push_back(j);
    return add_covers_unit(spans_, span);
  };
  bool held = false;
  for (int j : recent_) {
    stamp_[size_t(j)] = query_;
    if ((held = try_slab(j))) break;
  }
  if (!held) {
    Box b;
    b.add(p0);
    b.add(p1);
    held = any_slab_near(b, try_slab);
  }
  if (held) recent_.swap(giving_);
  return held;
}

}  // namespace cslice
