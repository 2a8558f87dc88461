// Contact segments of a pair at one orientation (paper Figure 13, section 6.5).
//
// Every non-segment feature is a disc boundary: centre c and signed radius rho (+r for a
// convex arc, -r for a concave one, 0 for a vertex), with the set N of outward normals it
// can touch with (an angle interval). When a moving feature touches a fixed one at a point
// where the fixed outward normal is n, the moving outward normal is -n and
//   C_moving = c_fixed + (rho_fixed + rho_moving) n,   O = C_moving - R(theta) c_moving,
// so a disc pair traces a circular arc of radius |rho_f + rho_m| about c_f - R c_m, for n in
// N_f intersected with -R N_m. A segment contributes one normal and its extent instead,
// giving a line segment. Local overlap filtering is the normal-set test plus the sign rule:
// a concave feature touches only from inside its circle (rho_f + rho_m <= 0) and never
// another concave feature or a segment; a reflex vertex touches nothing. Segment/segment
// contacts are subsumed by the vertex contacts at their ends (paper 6.1).
#include <algorithm>
#include <bit>
#include <cstdint>
#include <iterator>
#include <optional>
#include <span>

#include "contacts/contact_features.hpp"
#include "cslice/slice.hpp"
#include "slice/trig_memo.hpp"

namespace cslice {

std::string_view to_string(ContactKind k) {
  switch (k) {
    case ContactKind::vertex_segment:
      return "vertex_segment";
    case ContactKind::segment_vertex:
      return "segment_vertex";
    case ContactKind::arc_segment:
      return "arc_segment";
    case ContactKind::segment_arc:
      return "segment_arc";
    case ContactKind::arc_arc:
      return "arc_arc";
    case ContactKind::vertex_arc:
      return "vertex_arc";
    case ContactKind::arc_vertex:
      return "arc_vertex";
  }
  return "?";
}

bool pair_can_touch(const ContactFeature& m, const ContactFeature& f, double eps) {
  if (!m.can_touch || !f.can_touch) return false;
  const bool m_seg = m.kind == FeatureKind::segment, f_seg = f.kind == FeatureKind::segment;
  if (m_seg && f_seg) return false;
  if (f_seg) return m.rho >= 0.0;  // a concave arc cannot rest on a straight edge
  if (m_seg) return f.rho >= 0.0;
  const bool m_concave = m.rho < 0.0, f_concave = f.rho < 0.0;
  if (m_concave && f_concave) return false;
  // Vertex/vertex contacts are endpoints of other segments.
  if (m.kind == FeatureKind::vertex && f.kind == FeatureKind::vertex) return false;
  return !((m_concave || f_concave) && f.rho + m.rho > eps);  // the convex one is too big
}

ContactKind contact_kind(const ContactFeature& m, const ContactFeature& f) {
  const bool m_vertex = m.kind == FeatureKind::vertex, f_vertex = f.kind == FeatureKind::vertex;
  if (f.kind == FeatureKind::segment)
    return m_vertex ? ContactKind::vertex_segment : ContactKind::arc_segment;
  if (m.kind == FeatureKind::segment)
    return f_vertex ? ContactKind::segment_vertex : ContactKind::segment_arc;
  if (m_vertex) return ContactKind::vertex_arc;
  if (f_vertex) return ContactKind::arc_vertex;
  return ContactKind::arc_arc;
}

namespace {

// Intersection of two circular intervals: up to two intervals (b may wrap around a's end).
int intersect_intervals(const AngleInterval& a, const AngleInterval& b, double angular_eps,
                        std::array<AngleInterval, 2>& out) {
  if (a.span >= kTwoPi) {
    out[0] = b;
    return 1;
  }
  if (b.span >= kTwoPi) {
    out[0] = a;
    return 1;
  }
  const double d = ccw_turn(a.lo, b.lo);
  int n = 0;
  for (double shift : {d, d - kTwoPi}) {
    const double lo = std::max(0.0, shift), hi = std::min(a.span, shift + b.span);
    if (hi >= lo - angular_eps) out[n++] = {a.lo + lo, std::max(0.0, hi - lo)};
  }
  return n;
}

class ContactBuilder {
 public:
  // `fixed_normals`, when given, holds unit_vector(f.normals.lo) of every fixed feature f
  // (indexed by f.feature): the normal of a fixed segment, the same at every orientation.
  // `trig`, when given, remembers the arcs' end directions and bulges between slices.
  // `turn` is Transform(Pose{0, 0, theta}): the rotation by theta, computed by the caller.
  ContactBuilder(const Pair& pair, const Transform& turn, std::vector<ContactSegment>& out,
                 const std::vector<Vec2>* fixed_normals = nullptr, TrigMemo* trig = nullptr)
      : pair_(pair),
        rot_(turn),
        theta_(turn.angle),
        out_(out),
        fixed_normals_(fixed_normals),
        trig_(trig) {}

  void add_pair(const ContactFeature& m, const ContactFeature& f) {
    if (pair_can_touch(m, f, pair_.tol.geometric)) add_touching_pair(m, f);
  }
  // A pair known to pass pair_can_touch.
  void add_touching_pair(const ContactFeature& m, const ContactFeature& f) {
    if (f.kind == FeatureKind::segment) return add_disc_on_segment(m, f);
    if (m.kind == FeatureKind::segment) return add_segment_on_disc(m, f);
    add_disc_on_disc(m, f);
  }

 private:
  // The moving feature's normal set, rotated and reversed: the fixed normals it can meet.
  AngleInterval opposed(const AngleInterval& n) const { return {n.lo + theta_ + kPi, n.span}; }

  // Written field by field in place: a local copied in was read back in 16-byte moves
  // across its 8-byte stores, which stalled (a fifth of the contacts' time on polygons).
  void emit(const ContactFeature& m, const ContactFeature& f, ContactKind kind, const Curve& curve,
            bool is_point = false) {
    const int id = static_cast<int>(out_.size());
    ContactSegment& s = out_.emplace_back();
    s.id = id;
    s.moving_feature = m.feature;
    s.fixed_feature = f.feature;
    s.kind = kind;
    s.curve = curve;
    s.is_point = is_point;
  }

  // make_arc, its sines, cosines and tangent taken from the memo when there is one.
  Curve arc(Vec2 center, double radius, double start_angle, double sweep) const {
    if (!trig_) return make_arc(center, radius, start_angle, sweep);
    return make_arc_using(*trig_, center, radius, start_angle, sweep);
  }

  // A moving disc feature on a fixed segment: the segment shifted by rho_m n_f - R c_m.
  void add_disc_on_segment(const ContactFeature& m, const ContactFeature& f) {
    if (!interval_contains(opposed(m.normals), f.normals.lo, pair_.tol.angular)) return;
    // A vertex (radius 0) touches at its centre: no normal needed.
    Vec2 shift = Vec2{} - moving(m).center;
    if (m.rho != 0.0) {
      const Vec2 normal = fixed_normals_ ? (*fixed_normals_)[f.feature] : unit_vector(f.normals.lo);
      shift = m.rho * normal - moving(m).center;
    }
    emit(m, f, contact_kind(m, f), make_segment(f.from + shift, f.to + shift));
  }

  // A moving segment on a fixed disc feature: the reversed rotated segment, placed so its
  // touching point meets the disc at the normal opposite to the segment's.
  void add_segment_on_disc(const ContactFeature& m, const ContactFeature& f) {
    const double n_angle = m.normals.lo + theta_ + kPi;
    if (!interval_contains(f.normals, n_angle, pair_.tol.angular)) return;
    Moving& mm = moving(m);
    // A vertex (radius 0) touches at its centre whatever the normal: no sine and cosine for
    // it, which were a twentieth of a polygon pair's slice.
    Vec2 touch = f.center;
    if (f.rho != 0.0) {
      if (!mm.has_normal) {
        mm.normal = unit_vector(n_angle);  // turns with theta: once per slice and feature
        mm.has_normal = true;
      }
      touch = f.center + f.rho * mm.normal;
    }
    emit(m, f, contact_kind(m, f), make_segment(touch - mm.from, touch - mm.to));
  }

  void add_disc_on_disc(const ContactFeature& m, const ContactFeature& f) {
    const double rho = f.rho + m.rho;
    const double eps = pair_.tol.geometric;
    std::array<AngleInterval, 2> parts;
    const int n = intersect_intervals(f.normals, opposed(m.normals), pair_.tol.angular, parts);
    const Vec2 c = f.center - moving(m).center;
    for (int i = 0; i < n; ++i) {
      if (std::fabs(rho) <= eps) {
        // A perfect fit, unless the features meet along a single touching direction only.
        if (parts[i].span > pair_.tol.angular)
          emit(m, f, contact_kind(m, f), make_segment(c, c), true);
        continue;
      }
      // An arc shorter than the geometric epsilon is kept: the arrangement merges its ends
      // into one vertex, but they also join the contact segments beside it. Two such arcs in
      // a row (a moving arc passing a fixed vertex onto a fixed arc, at the critical
      // orientation where both shrink away) can span more than eps together, and with them
      // dropped their neighbours' ends stayed 1.4e-8 apart, leaving a gap through which the
      // unbounded face leaked into blocked space (stress seeds 100283 and 100289). Likewise a
      // sliver of normals narrower than the angular epsilon makes an arc of a large radius
      // longer than eps. Only an empty set of normals makes no arc.
      if (!(parts[i].span > 0.0)) continue;
      if (rho > 0.0) {
        emit(m, f, contact_kind(m, f), arc(c, rho, parts[i].lo, parts[i].span));
      } else {
        // c + rho n = c + |rho| n(phi + pi); traverse clockwise to keep blocked on the left.
        emit(m, f, contact_kind(m, f),
             arc(c, -rho, parts[i].lo + parts[i].span + kPi, -parts[i].span));
      }
    }
  }

  // The moving feature turned by theta (its centre, its edge's ends, the direction opposite
  // its segment normal), kept for the feature met last (by address): each moving feature
  // meets many fixed ones in a row.
  struct Moving {
    Vec2 center, from, to;
    Vec2 normal;
    bool has_normal = false;
  };
  Moving& moving(const ContactFeature& m) {
    if (moving_of_ != &m) {
      moving_of_ = &m;
      moving_ = {rot_.rotate(m.center), rot_.rotate(m.from), rot_.rotate(m.to), {}};
    }
    return moving_;
  }

  const Pair& pair_;
  Transform rot_;
  double theta_;
  std::vector<ContactSegment>& out_;
  const std::vector<Vec2>* fixed_normals_;
  TrigMemo* trig_;
  const ContactFeature* moving_of_ = nullptr;
  Moving moving_;
};

}  // namespace

// Fixed features bucketed by the directions of their outward normals, so that each moving
// feature meets only the fixed ones whose normals can oppose its own: the pairs that can
// touch at all. Buckets split the circle evenly; an interval covers the run of buckets it
// overlaps (widened by the angular epsilon, as the interval tests are inclusive), and a
// fixed feature is a candidate when its run meets the query's. About one bucket per fixed
// feature: on random star pairs (100 and 300 vertices, smooth and rough) twice as many cost
// 1-3% more per one-shot slice, and half as many helped the rough ones but cost the smooth
// ones the false candidates.
//
// A feature whose run is short (an edge, a vertex of a smooth contour) is listed in each of
// its buckets, and a query reads the lists of its own buckets. A long run (a vertex where a
// rough contour turns) would be read once per bucket the two runs share, which cost most of
// the contacts on rough parts (docs/performance.md, eighteenth session). Long runs are found
// by where they start instead: the runs at most w buckets long that meet the query's run
// [first, first + count) start in [first - w + 1, first + count). So they are kept in classes
// of length (up to 16, 32, 64, ... buckets), each grouped by cells of starts as wide as its
// longest run, and a query reads each class's cells over that window: each run once.
class NormalIndex {
 public:
  // `with_normals`: whether normals() is wanted (a sine and cosine per feature).
  NormalIndex(const std::vector<ContactFeature>& fixed, double angular_eps, bool with_normals) {
    build(fixed, angular_eps, with_normals);
  }

  // Made anew for these features, in the storage of the last ones (ContactMaker::reset).
  void build(const std::vector<ContactFeature>& fixed, double angular_eps, bool with_normals) {
    bucket_count_ = std::clamp<size_t>(fixed.size(), 64, 65536);
    eps_ = angular_eps;
    per_radian_ = double(bucket_count_) / kTwoPi;
    ranges_.assign(fixed.size(), Range{});
    seen_.assign((fixed.size() + 63) / 64, 0);
    for (size_t i = 0; i < fixed.size(); ++i)
      if (fixed[i].can_touch) ranges_[i] = range_of(fixed[i].normals);
    // Only features that can touch are ever asked for theirs (and a vertex that cannot
    // touch has none: see ContactMaker).
    normals_.clear();
    if (with_normals) {
      normals_.resize(fixed.size());
      for (size_t i = 0; i < fixed.size(); ++i)
        if (fixed[i].can_touch) normals_[i] = unit_vector(fixed[i].normals.lo);
    }
    masks_.clear();
    bucket_start_.clear();
    bucket_items_.clear();
    runs_.clear();
    classes_.clear();
    cells_.clear();
    whole_circle_.clear();
    if (few_features()) {
      masks_.assign(bucket_count_, 0);
      for (size_t i = 0; i < fixed.size(); ++i)
        for_each_bucket(ranges_[i], [&](size_t b) { masks_[b] |= uint64_t{1} << i; });
    } else {
      list_short_runs();
      index_long_runs();
    }
  }

  // Every fixed feature whose bucket run meets the interval's, once each, in feature order:
  // the output (segment ids) then follows the features' order, whatever the bucketing.
  // With few features (few_features()), only those whose bit is set in `allowed`.
  void candidates(const AngleInterval& normals, std::vector<int>& out,
                  uint64_t allowed = ~uint64_t{0}) const {
    out.clear();
    const Range r = range_of(normals);
    if (few_features()) {
      // Few features: each bucket holds them as a bitmask; the features meeting r are
      // the union of its buckets' masks, read back in feature order.
      uint64_t bits = 0;
      for_each_bucket_range(r, [&](size_t from, size_t to) {
        for (size_t b = from; b < to; ++b) bits |= masks_[b];
      });
      for (bits &= allowed; bits != 0; bits &= bits - 1) out.push_back(std::countr_zero(bits));
      return;
    }
    // Only short runs and a query of one or two buckets (most of a smooth contour's): their
    // lists, each in feature order, merged.
    if (classes_.empty() && whole_circle_.empty() && r.count <= 2) {
      if (r.count == 0) return;
      const std::span<const int> a = bucket(r.first);
      if (r.count == 1) {
        out.assign(a.begin(), a.end());
        return;
      }
      const std::span<const int> b = bucket(r.first + 1 == bucket_count_ ? 0 : r.first + 1);
      std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
      return;
    }
    // Marked in a bitmap of the features, then read back in feature order, word by word over
    // the words marked (sorting the gathered lists cost more than the contacts themselves on
    // rough parts).
    touched_.clear();
    for_each_bucket_range(r, [&](size_t from, size_t to) {
      for (size_t b = from; b < to; ++b)
        for (int i : bucket(b)) mark(i);
    });
    for (const Run& run : whole_circle_) mark(run.feature);
    for (const Class& cls : classes_) find_in_class(cls, r);
    std::sort(touched_.begin(), touched_.end());
    for (size_t w : touched_) {
      for (uint64_t bits = seen_[w]; bits != 0; bits &= bits - 1)
        out.push_back(int(64 * w + size_t(std::countr_zero(bits))));
      seen_[w] = 0;
    }
  }

  // Whether candidates reads the features from bits (and can filter them by a mask).
  bool few_features() const { return ranges_.size() <= kScanLimit; }

  // unit_vector(f.normals.lo) of every fixed feature f that can touch, in feature order;
  // null when not asked for.
  const std::vector<Vec2>* normals() const { return normals_.empty() ? nullptr : &normals_; }

 private:
  static constexpr size_t kScanLimit = 64;
  // Runs of at most this many buckets are listed in each of their buckets.
  static constexpr size_t kShortRun = 8;

  // Buckets first, first + 1, ..., count of them, modulo the bucket count; none when empty.
  struct Range {
    size_t first = 0, count = 0;
  };
  struct Run {
    int first, count, feature;
  };
  // The long runs of up to 2^c buckets: those starting in cell k (buckets k 2^c to
  // (k + 1) 2^c - 1) are runs_[cells_[first_cell + k] .. cells_[first_cell + k + 1]).
  struct Class {
    size_t c, first_cell;
  };

  Range range_of(const AngleInterval& a) const {
    const size_t n = bucket_count_;
    if (a.span + 2.0 * eps_ >= kTwoPi) return {0, n};
    double lo = fmod_two_pi(a.lo - eps_);
    if (lo < 0.0) lo += kTwoPi;
    // Buckets by a product, not a quotient (two divisions per query): any increasing map
    // keeps runs of meeting intervals meeting, the index's only need.
    const size_t first = std::min(n - 1, size_t(lo * per_radian_));
    const size_t count = std::min(n, size_t((lo + a.span + 2.0 * eps_) * per_radian_) - first + 1);
    return {first, count};
  }

  template <class Fn>
  void for_each_bucket(const Range& r, Fn fn) const {
    // first < n and count <= n: one wrap at most, without a division per bucket.
    for (size_t k = 0, b = r.first; k < r.count; ++k, b = b + 1 == bucket_count_ ? 0 : b + 1) fn(b);
  }

  // The same buckets as for_each_bucket, as at most two runs [from, to) without the wrap.
  template <class Fn>
  void for_each_bucket_range(const Range& r, Fn fn) const {
    const size_t n = bucket_count_, end = r.first + r.count;
    fn(r.first, std::min(end, n));
    if (end > n) fn(size_t{0}, end - n);
  }

  // The class of a run of `count` buckets: the least c with count <= 2^c.
  static size_t class_of(size_t count) { return size_t(std::bit_width(count - 1)); }

  // The short runs, listed bucket by bucket in one array (a counting sort: one allocation,
  // not one per bucket), each bucket's in feature order.
  void list_short_runs() {
    auto is_short = [](const Range& r) { return r.count > 0 && r.count <= kShortRun; };
    bucket_start_.assign(bucket_count_ + 1, 0);
    for (const Range& r : ranges_)
      if (is_short(r)) for_each_bucket(r, [&](size_t b) { ++bucket_start_[b + 1]; });
    for (size_t b = 0; b < bucket_count_; ++b) bucket_start_[b + 1] += bucket_start_[b];
    bucket_items_.resize(size_t(bucket_start_.back()));
    fill_.assign(bucket_start_.begin(), bucket_start_.end() - 1);
    for (size_t i = 0; i < ranges_.size(); ++i)
      if (is_short(ranges_[i]))
        for_each_bucket(ranges_[i], [&](size_t b) { bucket_items_[size_t(fill_[b]++)] = int(i); });
  }

  // The long runs, grouped by class and within a class c by cells of 2^c buckets where they
  // start (one counting sort); runs round the whole circle apart.
  void index_long_runs() {
    const size_t n = bucket_count_, classes = class_of(n) + 1;
    std::vector<size_t> base(classes + 1, 0);  // class c's cells: base[c] .. base[c + 1]
    for (size_t c = 0; c < classes; ++c) base[c + 1] = base[c] + ((n - 1) >> c) + 1;
    auto cell_of = [&](const Range& r) {
      const size_t c = class_of(r.count);
      return base[c] + (r.first >> c);
    };
    auto is_long = [&](const Range& r) { return r.count > kShortRun && r.count < n; };
    if (std::none_of(ranges_.begin(), ranges_.end(),
                     [&](const Range& r) { return r.count > kShortRun; }))
      return;  // smooth contours: all short
    cells_.assign(base[classes] + 1, 0);
    for (const Range& r : ranges_)
      if (is_long(r)) ++cells_[cell_of(r) + 1];
    for (size_t k = 0; k + 1 < cells_.size(); ++k) cells_[k + 1] += cells_[k];
    runs_.resize(size_t(cells_.back()));
    std::vector<int> fill(cells_.begin(), cells_.end() - 1);
    for (size_t i = 0; i < ranges_.size(); ++i) {
      const Range& r = ranges_[i];
      const Run run{int(r.first), int(r.count), int(i)};
      if (r.count == n)
        whole_circle_.push_back(run);
      else if (is_long(r))
        runs_[size_t(fill[cell_of(r)]++)] = run;
    }
    for (size_t c = 0; c < classes; ++c)  // its runs: runs_[cells_[base[c]] .. cells_[base[c + 1]])
      if (cells_[base[c]] < cells_[base[c + 1]]) classes_.push_back({c, base[c]});
  }

  std::span<const int> bucket(size_t b) const {
    return {bucket_items_.data() + bucket_start_[b], bucket_items_.data() + bucket_start_[b + 1]};
  }

  // Marks the runs of a class that meet r: those starting in [r.first - w + 1, r.first +
  // r.count) modulo the bucket count, w = 2^c, read from the cells holding those starts.
  void find_in_class(const Class& cls, const Range& r) const {
    const size_t n = bucket_count_, w = std::min(n, size_t{1} << cls.c);
    const size_t length = r.count + w - 1;
    const int* cells = cells_.data() + cls.first_cell;
    auto read = [&](size_t lo, size_t hi) {  // runs starting in the cells of buckets [lo, hi]
      for (int i = cells[lo >> cls.c], end = cells[(hi >> cls.c) + 1]; i < end; ++i)
        if (meets(runs_[size_t(i)], r)) mark(runs_[size_t(i)].feature);
    };
    if (length >= n) return read(0, n - 1);
    const size_t from = (r.first + n - (w - 1)) % n, to = from + length - 1;
    if (to < n) return read(from, to);
    // The window wraps: its two parts, or all cells once when they share one.
    if (((to - n) >> cls.c) >= (from >> cls.c)) return read(0, n - 1);
    read(from, n - 1);
    read(0, to - n);
  }

  // Whether two runs of buckets meet, round the circle: one holds the other's first bucket.
  bool meets(const Run& run, const Range& r) const {
    const size_t n = bucket_count_, first = size_t(run.first);
    const size_t to_query = r.first >= first ? r.first - first : r.first + n - first;
    const size_t to_run = first >= r.first ? first - r.first : first + n - r.first;
    return to_query < size_t(run.count) || to_run < r.count;
  }

  void mark(int feature) const {
    uint64_t& word = seen_[size_t(feature) / 64];
    if (word == 0) touched_.push_back(size_t(feature) / 64);
    word |= uint64_t{1} << (size_t(feature) % 64);
  }

  size_t bucket_count_ = 64;
  // The short runs in bucket b: bucket_items_[bucket_start_[b] .. bucket_start_[b + 1]).
  std::vector<int> bucket_start_, bucket_items_;
  std::vector<int> fill_;          // list_short_runs' buffer
  std::vector<Range> ranges_;      // per fixed feature; empty when it cannot touch
  std::vector<Run> runs_;          // long: by class, then by cell of start
  std::vector<Class> classes_;     // the classes that have runs
  std::vector<int> cells_;         // per class, where its cells' runs start in runs_ (see Class)
  std::vector<Run> whole_circle_;  // runs round the whole circle: met by every query
  std::vector<Vec2> normals_;      // per fixed feature that can touch, unit_vector(normals.lo)
  std::vector<uint64_t> masks_;    // per bucket, its features as bits, when there are few
  mutable std::vector<uint64_t> seen_;   // candidates' bitmap of fixed features, left all zero
  mutable std::vector<size_t> touched_;  // the words of seen_ a query marked
  double per_radian_ = 1.0;              // buckets per radian
  double eps_ = 0.0;
};

ContactMaker::ContactMaker(const Pair& pair) : trig_(std::make_unique<TrigMemo>()) {
  reset(pair);
}

void ContactMaker::reset(const Pair& pair) {
  pair_ = &pair;
  // A feature that cannot touch is never paired (segments skips it, the index leaves it
  // out), so its normals are not needed.
  contact_features(pair.moving, false, moving_);
  contact_features(pair.fixed, false, fixed_);
  // Only a moving arc on a fixed segment needs the segment's normal as a vector.
  const bool with_normals =
      std::any_of(moving_.begin(), moving_.end(),
                  [](const ContactFeature& m) { return m.can_touch && m.rho != 0.0; });
  if (index_)
    index_->build(fixed_, pair.tol.angular, with_normals);
  else
    index_ = std::make_unique<NormalIndex>(fixed_, pair.tol.angular, with_normals);
  // Which pairs can touch at all does not depend on theta: with few fixed features, as a
  // mask per moving feature that filters the candidates before they are looked at.
  touching_.clear();
  if (!index_->few_features()) return;
  touching_.assign(moving_.size(), 0);
  for (size_t i = 0; i < moving_.size(); ++i)
    for (size_t j = 0; j < fixed_.size(); ++j)
      if (pair_can_touch(moving_[i], fixed_[j], pair.tol.geometric))
        touching_[i] |= uint64_t{1} << j;
}

ContactMaker::~ContactMaker() = default;

void ContactMaker::segments(double theta, std::vector<ContactSegment>& out) {
  out.clear();
  ContactBuilder builder(*pair_, Transform(Pose{0.0, 0.0, theta}), out, index_->normals(),
                         trig_.get());
  for (size_t k = 0; k < moving_.size(); ++k) {
    const ContactFeature& m = moving_[k];
    if (!m.can_touch) continue;
    const AngleInterval normals{m.normals.lo + theta + kPi, m.normals.span};
    if (touching_.empty()) {
      index_->candidates(normals, candidates_);
      for (int i : candidates_) builder.add_pair(m, fixed_[i]);
    } else {
      index_->candidates(normals, candidates_, touching_[k]);
      for (int i : candidates_) builder.add_touching_pair(m, fixed_[i]);
    }
  }
}

std::vector<ContactSegment> contact_segments(const Pair& pair, double theta) {
  std::vector<ContactSegment> out;
  ContactMaker(pair).segments(theta, out);
  return out;
}

void add_pair_contacts(const Pair& pair, const ContactFeature& m, const ContactFeature& f,
                       double theta, std::vector<ContactSegment>& out) {
  add_pair_contacts(pair, m, f, Transform(Pose{0.0, 0.0, theta}), out);
}

void add_pair_contacts(const Pair& pair, const ContactFeature& m, const ContactFeature& f,
                       const Transform& turn, std::vector<ContactSegment>& out) {
  ContactBuilder(pair, turn, out).add_pair(m, f);
}

}  // namespace cslice
