// Split points of the arrangement's curves (see arrangement.cpp for the rules).
#include "slice/split_points.hpp"

#include <algorithm>
#include <bit>
#include <numeric>

#include "geometry/near_curve.hpp"
#include "slice/small_sort.hpp"

namespace cslice {

void SplitsByCurve::build(const std::vector<SplitPoint>& splits, size_t first, size_t curves) {
  // Sizes read once: the stores below could alias them, so a loop bound on size() is
  // reloaded every iteration.
  const size_t n = splits.size();
  start.assign(curves + 1, 0);
  index.resize(n - first);
  for (size_t k = first; k < n; ++k) ++start[splits[k].curve + 1];
  for (size_t c = 0; c < curves; ++c) start[c + 1] += start[c];
  fill.assign(start.begin(), start.end() - 1);
  for (size_t k = first; k < n; ++k) index[fill[splits[k].curve]++] = int(k);
}

bool ClosestPoints::insert(int curve, Vec2 p) {
  const uint64_t x = std::bit_cast<uint64_t>(p.x), y = std::bit_cast<uint64_t>(p.y);
  if (2 * (keys_.size() + 1) > slot_.size()) {  // grow, and place the keys again
    slot_.assign(std::max<size_t>(64, 4 * slot_.size()), 0);
    used_.clear();
    std::vector<Key> keys;
    keys.swap(keys_);
    for (const Key& k : keys)
      insert(k.curve, {std::bit_cast<double>(k.x), std::bit_cast<double>(k.y)});
  }
  uint64_t h = (x * 0x9E3779B97F4A7C15ull) ^ (y * 0xC2B2AE3D27D4EB4Full) ^ uint64_t(curve);
  h ^= h >> 29;
  const size_t mask = slot_.size() - 1;
  size_t k = size_t(h) & mask;
  for (; slot_[k] != 0; k = (k + 1) & mask) {
    const Key& o = keys_[slot_[k] - 1];
    if (o.x == x && o.y == y && o.curve == curve) return true;
  }
  keys_.push_back({x, y, curve});
  slot_[k] = int(keys_.size());
  used_.push_back(k);
  return false;
}

void ClosestPoints::clear() {
  for (size_t k : used_) slot_[k] = 0;
  used_.clear();
  keys_.clear();
}

namespace {

// Whether p at parameter t is exactly (bit for bit) an end of c.
bool is_end(const Curve& c, double t, Vec2 p) {
  return (t == 0.0 && p == c.from) || (t == 1.0 && p == c.to);
}

// Every pair of curves whose boxes overlap, found by sweeping boxes sorted by their left x.
void candidate_pairs(SplitScratch& s) {
  const std::vector<Box>& boxes = s.boxes;
  s.order.resize(boxes.size());
  std::iota(s.order.begin(), s.order.end(), 0);
  sort_by_coordinate(
      s.order, [&](int a) { return boxes[a].lo.x; }, s.by_x);
  s.sorted.resize(boxes.size());  // contiguous for the sweep
  const size_t n = boxes.size();
  const Box* sorted = s.sorted.data();
  const int* order = s.order.data();
  for (size_t i = 0; i < n; ++i) s.sorted[i] = boxes[order[i]];
  // The pairs are written without a branch on whether the boxes overlap: on rough contours
  // a tenth to a half of the pairs tried do, which no branch predictor foresees. Each pair
  // goes in at `count`, which moves on only when they overlap.
  size_t count = 0, room = s.pairs.size();
  std::pair<int, int>* out = s.pairs.data();
  for (size_t i = 0; i < n; ++i) {
    const Box& a = sorted[i];
    for (size_t j = i + 1; j < n && sorted[j].lo.x <= a.hi.x; ++j) {
      if (count == room) {
        s.pairs.resize(room = 2 * count + 64);
        out = s.pairs.data();
      }
      const Box& b = sorted[j];  // Box::overlaps, knowing b.lo.x <= a.hi.x
      out[count] = {order[i], order[j]};
      count += size_t(!(b.hi.x < a.lo.x) & !(b.lo.y > a.hi.y) & !(b.hi.y < a.lo.y));
    }
  }
  s.pairs.resize(count);
}

// Curves within eps of each other along a stretch must be cut at the same vertices there, or
// their pieces would not coincide and a third curve would cross them in an order that
// round-off decides: two lines closer than eps crossed by a third at a shallow angle get
// their crossings at points farther apart than eps. The same holds for curves that only meet
// at points, next to those points: arcs the intersection step calls tangent (a lens thinner
// than eps) and curves crossing at a shallow angle stay within eps of each other for up to
// sqrt(eps / curvature) or eps / angle. So every split point of one curve inside a shared
// piece, or within eps of a curve it meets, is copied to the other, at the same point; the
// pieces between them then merge into one edge. Two passes carry points along chains.
//
// A copy that repeats a split point exactly (curve, t and p: a point copied onto a curve
// along two paths, as where several collinear curves share pieces at a perfect fit) is not
// made: it would join that point's vertex and lie next to it along the curve, and carry
// nothing further that the point does not.
class Sharer {
 public:
  Sharer(const std::vector<Curve>& curves, SplitScratch& s, std::vector<SplitPoint>& splits,
         double eps)
      : curves_(curves), s_(s), splits_(splits), eps_(eps) {}

  void run() {
    if (s_.shared.empty() && s_.end_to_end.empty()) return;
    s_.copied.clear();
    for (int i : s_.closest_hits) s_.copied.insert(splits_[i].curve, splits_[i].p);
    size_t first_new = 0;
    for (int pass = 0; pass < 2; ++pass) {
      SplitsByCurve& fresh = s_.fresh;
      fresh.build(splits_, first_new, curves_.size());
      if (first_new != 0) s_.all.build(splits_, 0, curves_.size());
      all_ = first_new == 0 ? &fresh : &s_.all;
      s_.grouped = first_new == 0 ? SplitScratch::Grouped::fresh : SplitScratch::Grouped::all;
      // The fresh points in curve order, compact; where each is on its own curve (a sine and
      // cosine on an arc) is found when asked.
      std::vector<FreshSplit>& points = s_.points;
      const size_t n = fresh.index.size();
      points.resize(n);
      for (size_t i = 0; i < n; ++i) {
        const SplitPoint& sp = splits_[fresh.index[i]];
        FreshSplit& p = points[i];
        p.t = sp.t;
        p.met = sp.met;
        p.curve = sp.curve;
        p.p = sp.p;
        p.located = false;
      }
      s_.added.clear();
      for (const auto& [a, b] : s_.end_to_end) {
        if (!(pass == 0 && only_ends(a))) copy_near(a, b);
        if (!(pass == 0 && only_ends(b))) copy_near(b, a);
      }
      for (const SharedPiece& sp : s_.shared) {
        if (sp.near) {
          copy_near(sp.a, sp.b);
          copy_near(sp.b, sp.a);
        } else {
          copy_inside(sp.a, sp.b, sp.a_lo, sp.a_hi);
          copy_inside(sp.b, sp.a, sp.b_lo, sp.b_hi);
        }
      }
      if (s_.added.empty()) return;
      first_new = splits_.size();
      splits_.insert(splits_.end(), s_.added.begin(), s_.added.end());
      s_.grouped = SplitScratch::Grouped::none;  // the points just added are in neither
    }
  }

 private:
  // Whether curve c's fresh points are its two ends only (on the first pass every split
  // point is fresh, and every curve has its ends). Then copy_near from c onto a segment it
  // meets end to end copies nothing: their shared end is one of the other's ends, and
  // since the two are not collinear within eps, c's other end lies farther than eps from
  // the other's carrier. Most pairs of a slice are such neighbours, most of them without
  // any other point.
  bool only_ends(int c) const { return s_.fresh.start[c + 1] - s_.fresh.start[c] == 2; }

  std::span<FreshSplit> fresh_of(int c) {
    return {s_.points.data() + s_.fresh.start[c], s_.points.data() + s_.fresh.start[c + 1]};
  }

  void add(int to, Vec2 p) {
    if (s_.copied.insert(to, p)) return;  // repeats a split point exactly
    s_.added.push_back({to, closest_parameter(curves_[to], p), p});
  }

  // The fresh points of `from` with t in [lo, hi], onto `to`.
  void copy_inside(int from, int to, double lo, double hi) {
    for (const FreshSplit& p : fresh_of(from))
      if (!(p.t < lo || p.t > hi)) add(to, p.p);
  }

  // The fresh points of `from` within eps of `to`, except where the two meet (already on
  // both), and those within eps of a point `to` has (they would join its vertex anyway).
  // Measured from the curve's own point, so that a vertex carried onto a curve passes on to
  // the curves that one runs beside. Outside the other's box grown by eps is farther than
  // eps from it, as is a point clearly off its line or circle (carrier_rejects: most of the
  // points of curves crossing at an angle). (Their t lies in [0, 1], the whole range a near
  // piece spans.)
  void copy_near(int from, int to) {
    const Box& box = s_.boxes[to];
    const Curve& other = curves_[to];
    for (FreshSplit& p : fresh_of(from)) {
      // At an end of `to`, which is one of its points: has_point_near's answer, at once
      // (the shared end of two contact segments meeting end to end).
      if (p.met == to || p.p == other.from || p.p == other.to) continue;
      if (!p.located) {
        p.on_curve = point_at(curves_[p.curve], p.t);
        p.located = true;
      }
      const Vec2 q = p.on_curve;
      if (q.x < box.lo.x || q.x > box.hi.x || q.y < box.lo.y || q.y > box.hi.y) continue;
      if (carrier_rejects(other, q, eps_) || has_point_near(to, p.p) ||
          distance_to_curve(other, q) > eps_)
        continue;
      add(to, p.p);
    }
  }

  bool has_point_near(int c, Vec2 p) const {
    for (int k : all_->of(c))
      if (length_squared(splits_[k].p - p) <= eps_ * eps_) return true;
    return false;
  }

  const std::vector<Curve>& curves_;
  SplitScratch& s_;
  std::vector<SplitPoint>& splits_;
  double eps_;
  const SplitsByCurve* all_ = nullptr;
};

}  // namespace

void split_points(const std::vector<Curve>& curves, double eps, SplitScratch& s,
                  std::vector<SplitPoint>& splits) {
  splits.clear();
  s.shared.clear();
  s.end_to_end.clear();
  s.closest_hits.clear();
  s.boxes.clear();
  s.grouped = SplitScratch::Grouped::none;
  for (size_t i = 0; i < curves.size(); ++i) {
    splits.push_back({int(i), 0.0, curves[i].from});
    splits.push_back({int(i), 1.0, curves[i].to});
    s.boxes.push_back(bounding_box(curves[i]).inflated(eps));
  }
  candidate_pairs(s);
  for (auto [i, j] : s.pairs) {
    // Contact segments meeting end to end (most pairs): the touch at their shared end adds
    // no point (below) but they are near there, without building an Intersection. Segments
    // apart add nothing.
    const SegmentPairShortcut shortcut = segment_pair_shortcut(curves[i], curves[j], eps);
    if (shortcut == SegmentPairShortcut::end_to_end) {
      s.end_to_end.push_back({i, j});
      continue;
    }
    if (shortcut == SegmentPairShortcut::apart) continue;
    const Intersection x = intersect(curves[i], curves[j], eps);
    bool piece = false;
    for (int k = 0; k < x.count; ++k) {
      const IntersectionHit& h = x.hits[k];
      // A point hit inside both curves, not a tangency, is a crossing; at an end of either
      // curve it is a touch (that curve ends there).
      const Meeting how = h.is_piece     ? Meeting::other
                          : h.is_tangent ? Meeting::tangent
                          : (h.ta0 > 0.0 && h.ta0 < 1.0 && h.tb0 > 0.0 && h.tb0 < 1.0)
                              ? Meeting::crossing
                              : Meeting::other;
      // A touch exactly at an end of both curves (contact segments meeting end to end)
      // repeats their end points, which come first, and records no meeting: adding it would
      // only make two more points for every later step to merge back.
      if (how == Meeting::other && !h.is_piece && is_end(curves[i], h.ta0, h.point) &&
          is_end(curves[j], h.tb0, h.point))
        continue;
      splits.push_back({i, h.ta0, h.point, j, how});
      splits.push_back({j, h.tb0, h.point, i, how});
      if (h.is_piece) {
        piece = true;
        splits.push_back({i, h.ta1, h.point_end});
        splits.push_back({j, h.tb1, h.point_end});
        // The intersection step takes a piece's parameters on b as closest_parameter.
        s.closest_hits.push_back(int(splits.size()) - 3);
        s.closest_hits.push_back(int(splits.size()) - 1);
        s.shared.push_back({i, j, std::min(h.ta0, h.ta1), std::max(h.ta0, h.ta1),
                            std::min(h.tb0, h.tb1), std::max(h.tb0, h.tb1)});
      }
    }
    if (x.count > 0 && !piece) s.shared.push_back({i, j, 0.0, 1.0, 0.0, 1.0, true});
  }
  Sharer(curves, s, splits, eps).run();
}

}  // namespace cslice
