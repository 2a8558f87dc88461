// Critical orientations: every solution of the criticality equations of the contact
// families, kept when its configuration lies on the contact segments it involves (their
// parameter limits) and, optionally, outside blocked space.
//
// Four passes, each parallel (oneTBB) and each giving the same result whatever the thread
// count, because every decision depends only on its own candidate and results are sorted
// before they are combined:
//  1. Meeting: per theta-bin, the pairs and triples of families that may meet there
//     (src/criticals/candidates.cpp). Each distinct pair or triple keeps its bins.
//  2. Solving: each pair or triple is solved once over the whole circle; a root outside the
//     bins where its families may meet is dropped unvalidated (culled), the others are
//     validated on the real contact segments.
//  3. Screening: each distinct configuration is tested once for blocked space; blocked ones
//     that could still reach free space along a contact segment (overlapping segments,
//     segment ends) are probed piece by piece, bin by bin.
//  4. Grouping into critical orientations (paper section 9).
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>
#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>

#include "criticals/candidates.hpp"
#include "criticals/events.hpp"
#include "criticals/symmetric.hpp"
#include "cslice/classify.hpp"
#include "cslice/critical.hpp"
#include "parallel/arena.hpp"
#include "slice/small_sort.hpp"

namespace cslice {

std::string_view to_string(CriticalCondition c) {
  switch (c) {
    case CriticalCondition::segment_end:
      return "segment_end";
    case CriticalCondition::endpoint:
      return "endpoint";
    case CriticalCondition::tangent:
      return "tangent";
    case CriticalCondition::triple:
      return "triple";
  }
  return "?";
}

namespace {

// A solution that passed validation, before screening. Families ascending within a
// condition's own order (an endpoint's first family owns the end).
struct Candidate {
  CriticalCondition condition = CriticalCondition::segment_end;
  std::array<int, 3> families{-1, -1, -1};
  int count = 0;
  double theta = 0.0;
  Vec2 at;
};

bool before(const Candidate& x, const Candidate& y) {
  if (x.theta != y.theta) return x.theta < y.theta;
  if (x.condition != y.condition) return x.condition < y.condition;
  // Element by element: std::array's comparisons call memcmp.
  for (int i = 0; i < 3; ++i)
    if (x.families[i] != y.families[i]) return x.families[i] < y.families[i];
  if (x.at.x != y.at.x) return x.at.x < y.at.x;
  return x.at.y < y.at.y;
}

// Everything the passes read and none of them writes.
struct Context {
  Context(const Pair& p, const CriticalOptions& o)
      : pair(p),
        options(o),
        screen_pair(screening_pair(p)),
        moving(contact_features(p.moving)),
        fixed(contact_features(p.fixed)) {
    // Two at a time, where independent: this is a tenth of the fixture's time, before any
    // parallel pass.
    tbb::parallel_invoke([&] { families = contact_families(p); },
                         [&] {
                           if (o.map_symmetric) symmetries = pair_symmetries(p);
                           domain = fundamental_domain(symmetries);
                         });
    binning = binning_for(int(families.size()), domain, p.tol.critical_angle);
    tbb::parallel_invoke(
        [&] {
          equations.reserve(families.size());
          for (const ContactFamily& f : families) equations.push_back(family_equation(f));
        },
        [&] { alive = alive_families_by_bin(families, binning); });
    if (!domain) symmetries.clear();
    for (size_t i = 0; domain && i < families.size(); ++i)
      family_by_features.push_back({features_of(families[i]), int(i)});
    std::sort(family_by_features.begin(), family_by_features.end());
    size_t total = 0;
    for (const std::vector<int>& bin : alive) total += bin.size();
    if (total <= kKeptEntries) kept_entries.resize(size_t(binning.count));
  }

  // The meeting pass builds every bin's entries, and screening needs them again for the bins
  // it probes: kept from one to the other unless there are more than this many (a memory
  // bound; a large pair rebuilds the few bins it probes instead).
  static constexpr size_t kKeptEntries = size_t(1) << 16;

  // The pair with its geometric epsilon widened to the criticality tolerance: the placement
  // test then calls blocked only overlaps deeper than a criticality's own round-off.
  static Pair screening_pair(const Pair& pair) {
    Pair p = pair;
    p.tol.geometric = pair.tol.criticality;
    return p;
  }

  std::vector<BinEntry> entries(int bin) const {
    return bin_entries(families, alive[bin], binning, bin, pair.tol.criticality);
  }

  // Finer bins cull more pairs but cost a cover per alive family each. Over the turn: one
  // bin per eight families, at least 32, measured best on the random pairs of bench_critical,
  // but no more than 4 sqrt(families), where the two meet (1,024 families): covering the turn
  // costs the bins times the families, the pairs met the families squared over the bins, and
  // their sum is least for bins growing as the square root. (A random curved pair of 13,799
  // families: 3.8 s with one bin per eight, 1,724; 2.2 s with 469.)
  // A symmetric pair's bins cover only its fundamental domain, grown by the critical angle:
  // as wide as the turn's, or finer, one per eight families up to 32 bins over the domain.
  // Against the turn's width alone, that takes 8% of the instructions off the fixture (18
  // bins in its quarter turn) and 2% off 40 random symmetric pairs, and changes nothing on
  // the smaller fastener, cam and designed symmetric pairs; twice the turn's width everywhere
  // cost the designed pairs 7% more. (Without the 32, a 16-tooth gear in a ring gear, 12,288
  // families, had 1,536 bins in its eighth of a turn: 3.2 s, against 0.5 s with 55.)
  static constexpr int kMaxBins = 1 << 12;
  static Binning binning_for(int families, const std::optional<AngleInterval>& domain,
                             double critical_angle) {
    const int per_eight = families / 8;
    const int turn =
        std::clamp(std::min(per_eight, int(4.0 * std::sqrt(double(families)))), 32, kMaxBins);
    if (!domain) return Binning(turn);
    const double span = domain->span + 2.0 * critical_angle;
    const int as_turn = int(std::lround(turn * span / kTwoPi));
    const int bins = std::clamp(std::max(as_turn, std::min(per_eight, 32)), 1, kMaxBins);
    return Binning(bins, domain->lo - critical_angle, span);
  }

  // With symmetries, only orientations of their fundamental domain (grown by the critical
  // angle) are searched: the images of what is found there are the rest.
  bool in_domain(double theta) const {
    return !domain || interval_contains(*domain, theta, pair.tol.critical_angle);
  }

  BinScope scope(int bin) const {
    return {&families, binning, bin, pair.tol.criticality, pair.tol.geometric, pair.tol.size};
  }

  const Pair& pair;
  CriticalOptions options;
  Pair screen_pair;
  std::vector<ContactFeature> moving, fixed;
  std::vector<ContactFamily> families;
  std::vector<FamilyEquation> equations;
  std::vector<PairSymmetry> symmetries;  // empty unless options.map_symmetric and a domain
  std::optional<AngleInterval> domain;
  Binning binning{1};
  std::vector<std::vector<int>> alive;  // per bin
  // With a domain, the families by their features and kind: an image's family.
  using Features = std::array<int, 3>;
  static Features features_of(const ContactFamily& f) { return {f.moving, f.fixed, int(f.kind)}; }
  std::vector<std::pair<Features, int>> family_by_features;
  // Per bin, its entries as the meeting pass built them (empty when not kept: see
  // kKeptEntries). Each bin's slot is written by the one task meeting it, then only read.
  std::vector<std::vector<BinEntry>> kept_entries;
};

// A configuration cell of screening: configurations in one cell get one placement test.
// Compared field by field (an array's comparisons call memcmp), in the order of the fields.
struct ProbeKey {
  long long theta = 0, x = 0, y = 0;
  friend bool operator==(const ProbeKey& p, const ProbeKey& q) {
    return p.theta == q.theta && p.x == q.x && p.y == q.y;
  }
  friend bool operator<(const ProbeKey& p, const ProbeKey& q) {
    if (p.theta != q.theta) return p.theta < q.theta;
    if (p.x != q.x) return p.x < q.x;
    return p.y < q.y;
  }
};
using ProbeAnswers = std::vector<std::pair<ProbeKey, bool>>;  // sorted by key, blocked or not

// std::llround, without the library call for the values met here: a truncation is exact
// below 2^52 in magnitude, and so is the fraction it leaves, which rounds half away from zero.
long long round_to_integer(double v) {
  if (!(std::fabs(v) < 0x1p52)) return std::llround(v);  // integers already, or out of range
  const long long t = static_cast<long long>(v);
  const double fraction = v - static_cast<double>(t);
  if (fraction >= 0.5) return t + 1;
  if (fraction <= -0.5) return t - 1;
  return t;
}

ProbeKey probe_key(const Pair& pair, Vec2 x, double theta) {
  const double cell = pair.tol.criticality;
  return {round_to_integer(theta / pair.tol.critical_angle), round_to_integer(x.x / cell),
          round_to_integer(x.y / cell)};
}

bool key_before(const std::pair<ProbeKey, bool>& entry, const ProbeKey& key) {
  return entry.first < key;
}

// The answer for key among [first, last), sorted.
std::optional<bool> find_answer(ProbeAnswers::const_iterator first,
                                ProbeAnswers::const_iterator last, const ProbeKey& key) {
  auto it = std::lower_bound(first, last, key, key_before);
  if (it != last && it->first == key) return it->second;
  return std::nullopt;
}

// Solves and validates (pass 2) and probes blocked space (pass 3); one per thread.
class Worker {
 public:
  explicit Worker(const Context& ctx) : ctx_(ctx), tester_(ctx.screen_pair) {}

  CriticalStats stats;
  std::vector<Candidate> found;  // validated solutions

  void solve_pair(const MeetingTask& t) {
    for (auto [a, b] : {std::pair{t.a, t.b}, std::pair{t.b, t.a}})
      for (size_t e = 0; e < ctx_.families[a].ends.size(); ++e)
        for (double theta :
             roots(endpoint_equation(ctx_.families[a].ends[e], ctx_.equations[b]), t))
          add_endpoint(a, int(e), b, theta);
    std::array<EventEquation, 2> tangents;
    const int n = tangent_equations(ctx_.equations[t.a], ctx_.equations[t.b], tangents);
    for (int k = 0; k < n; ++k)
      for (double theta : roots(tangents[k], t)) add_tangent(t.a, t.b, theta);
  }

  void solve_triple(const MeetingTask& t) {
    const auto& eq = ctx_.equations;
    for (double theta : roots(triple_equation(eq[t.a], eq[t.b], eq[t.c]), t, true))
      add_triple(t.a, t.b, t.c, theta);
  }

  // ---- Screening --------------------------------------------------------------------

  bool blocked(Vec2 x, double theta) { return tester_.blocked({x.x, x.y, theta}); }

  // Whether a candidate of two overlapping families (parallel edges brought into line, equal
  // circles), or a segment appearing, vanishing or switching ends, reaches free space: it
  // changes the slice along a whole piece of contact segment, not only at its point.
  // The probes' cache lasts for one bin's candidates, which one worker takes in a fixed
  // order, so that the answers do not depend on the thread count.
  // The bin's entries are built only when a piece needs cutting: most candidates are
  // settled by their cheap probes, or have no overlapping segments.
  void start_bin(int bin, const ProbeAnswers& tested) {
    tested_ = &tested;
    range_known_ = false;
    cache_.clear();
    bin_ = bin;
    entries_.reset();
  }
  bool reaches_free(const Candidate& c) {
    if (c.condition == CriticalCondition::segment_end) return segment_end_reaches_free(c);
    return overlap_reaches_free(c);
  }

 private:
  // The roots near the task's bins, in a buffer reused by the next call (validating a root
  // solves nothing, so a caller's loop over them is never disturbed).
  // A triple's equation (degree 2 or 3) is searched only near the task's bins; a pair's
  // (degree 1) is solved in closed form over the whole turn.
  const std::vector<double>& roots(const EventEquation& eq, const MeetingTask& task,
                                   bool triple = false) {
    ++stats.equations;
    const double slack = ctx_.pair.tol.critical_angle;
    std::array<AngleWindow, 2> windows;
    const int count = triple ? task.windows(ctx_.binning, slack, windows) : 0;
    const TrigRoots r =
        trig_roots_within(eq.f, kRelativeGeometricEpsilon * eq.magnitude, kRelativeGeometricEpsilon,
                          ctx_.pair.tol.angular, triple ? windows.data() : nullptr, count);
    stats.roots += long(r.roots.size());
    near_.clear();
    for (double theta : r.roots) {
      // With symmetries, a bin may reach past their domain: its roots there are images.
      if (task.near(ctx_.binning, theta, slack) && ctx_.in_domain(theta))
        near_.push_back(theta);
      else
        ++stats.culled;
    }
    return near_;
  }

  // ---- Validation: the configuration lies on the contact segments --------------------

  // The family's contact segments at the orientation `turn` rotates by (one rotation serves
  // every family a candidate involves).
  const std::vector<ContactSegment>& segments_of(int family, const Transform& turn,
                                                 std::vector<ContactSegment>& out) const {
    out.clear();
    const ContactFamily& f = ctx_.families[family];
    add_pair_contacts(ctx_.pair, ctx_.moving[f.moving], ctx_.fixed[f.fixed], turn, out);
    return out;
  }

  // segments_of, remembered for the last orientation asked: a bin's probes cut each contact
  // segment by its neighbours', and several candidates there share an orientation (a switch
  // seen by several families). The segments at one theta are rebuilt the same every time, so
  // this changes no answer. A reference stays valid until the orientation changes.
  const std::vector<ContactSegment>& segments_at(int family, double theta) {
    if (memo_.empty()) {
      memo_.resize(ctx_.families.size());
      memo_stamp_.assign(ctx_.families.size(), 0u);
    }
    // Bitwise: the segments at theta = -0 and +0 need not agree.
    if (!memo_used_ || std::bit_cast<std::uint64_t>(theta) != memo_theta_) {
      memo_used_ = true;
      memo_theta_ = std::bit_cast<std::uint64_t>(theta);
      memo_turn_ = Transform(Pose{0.0, 0.0, theta});
      if (++memo_now_ == 0) {  // wrapped: no stale stamp may match
        std::fill(memo_stamp_.begin(), memo_stamp_.end(), 0u);
        memo_now_ = 1;
      }
    }
    if (memo_stamp_[family] != memo_now_) {
      segments_of(family, memo_turn_, memo_[family]);
      memo_stamp_[family] = memo_now_;
    }
    return memo_[family];
  }

  // The two tests of nearness, per contact segment: x lies on it, or at one of its ends.
  static bool passes_near(const ContactSegment& s, Vec2 x, double tol) {
    return distance_to_curve(s.curve, x) <= tol;
  }
  static bool ends_near(const ContactSegment& s, Vec2 x, double tol) {
    return std::min(distance(s.curve.from, x), distance(s.curve.to, x)) <= tol;
  }

  // How near x lies to the family's contact segments at theta, and to their ends: one
  // rebuild of the segments answers both (a triple needs both; a pair one of each family).
  struct Nearness {
    bool on_segment = false;
    bool at_end = false;
  };
  Nearness nearness(int family, const Transform& turn, Vec2 x) {
    Nearness n;
    const double tol = ctx_.pair.tol.criticality;
    for (const ContactSegment& s : segments_of(family, turn, scratch_)) {
      n.on_segment |= passes_near(s, x, tol);
      n.at_end |= ends_near(s, x, tol);
    }
    return n;
  }
  // Each half of nearness() alone, stopping at the first segment that settles it (the
  // distance to an arc is the costly half, and an end needs none).
  bool on_segment(int family, const Transform& turn, Vec2 x) {
    const double tol = ctx_.pair.tol.criticality;
    const auto& segments = segments_of(family, turn, scratch_);
    return std::any_of(segments.begin(), segments.end(),
                       [&](const ContactSegment& s) { return passes_near(s, x, tol); });
  }
  bool at_end(int family, const Transform& turn, Vec2 x) {
    const double tol = ctx_.pair.tol.criticality;
    const auto& segments = segments_of(family, turn, scratch_);
    return std::any_of(segments.begin(), segments.end(),
                       [&](const ContactSegment& s) { return ends_near(s, x, tol); });
  }

  // A cheap first test: every family involved exists at theta.
  bool all_alive(std::initializer_list<int> fams, double theta) const {
    for (int f : fams)
      if (!alive_at(ctx_.families[f], theta, ctx_.pair.tol.critical_angle)) return false;
    return true;
  }

  void add_endpoint(int a, int end, int b, double theta) {
    if (!all_alive({a, b}, theta)) return reject();
    // One rotation (one sin/cos pair) for the end and both families' segments.
    const Transform turn(Pose{0.0, 0.0, theta});
    const Vec2 x = ctx_.families[a].ends[end].at(turn);
    // Both must hold; the end lying off b's segment is the common failure, so it goes first.
    if (!on_segment(b, turn, x) || !at_end(a, turn, x)) return reject();
    found.push_back({CriticalCondition::endpoint, {a, b, -1}, 2, theta, x});
  }

  void add_tangent(int a, int b, double theta) {
    if (!all_alive({a, b}, theta)) return reject();
    const Transform turn(Pose{0.0, 0.0, theta});
    const Vec2 x = tangent_point(ctx_.equations[a], ctx_.equations[b], TrigAngle(turn));
    if (!on_segment(a, turn, x) || !on_segment(b, turn, x)) return reject();
    found.push_back({CriticalCondition::tangent, {a, b, -1}, 2, theta, x});
  }

  void add_triple(int a, int b, int c, double theta) {
    if (!all_alive({a, b, c}, theta)) return reject();
    const auto& eq = ctx_.equations;
    const Transform turn(Pose{0.0, 0.0, theta});
    const std::optional<Vec2> x = triple_point(eq[a], eq[b], eq[c], TrigAngle(turn));
    if (!x) return reject();
    // Three curves through an end that two of them share is an endpoint event, which its
    // own (better conditioned) equation finds; the triple equation there is near-degenerate
    // when the two always share that end. Near the end of one curve only, it is a triple
    // point of its own: the three curves can cross at a shallow angle, the point sliding
    // along that curve from its end while theta turns by more than the critical angle (a
    // random curved pair lost a change of its realizable contact so, its triple point within
    // the criticality tolerance of one end, 1.2e-5 rad after the endpoint event there).
    int at_ends = 0;
    for (int f : {a, b, c}) {
      const Nearness n = nearness(f, turn, *x);
      if (!n.on_segment) return reject();
      at_ends += n.at_end ? 1 : 0;
    }
    if (at_ends >= 2) return reject();
    found.push_back({CriticalCondition::triple, {a, b, c}, 3, theta, *x});
  }

  void reject() { ++stats.off_segment; }

  // ---- Probing pieces of contact segments --------------------------------------------

  // blocked(), remembered per configuration cell within a bin (several probes coincide:
  // the ends of adjoining segments, one switch seen by several families).
  // The point criticalities' own tests (screen's first step) answer too: a switch's probe
  // often lands on the endpoint criticality of its family and a neighbour. They are
  // complete before any probe runs, so the answers do not depend on the order either.
  bool blocked_cached(Vec2 x, double theta) {
    const ProbeKey key = probe_key(ctx_.pair, x, theta);
    // A candidate's probes share its orientation: the point answers of that orientation cell
    // are found once, and each probe looks among those few.
    if (!range_known_ || range_theta_ != key.theta) {
      range_known_ = true;
      range_theta_ = key.theta;
      range_first_ = std::lower_bound(tested_->begin(), tested_->end(),
                                      ProbeKey{key.theta, LLONG_MIN, LLONG_MIN}, key_before);
      for (range_last_ = range_first_;
           range_last_ != tested_->end() && range_last_->first.theta == key.theta;)
        ++range_last_;
    }
    if (const std::optional<bool> known = find_answer(range_first_, range_last_, key))
      return *known;
    // A sorted vector: a bin's probes are few, and a map would allocate per entry.
    auto it = std::lower_bound(cache_.begin(), cache_.end(), key, key_before);
    if (it != cache_.end() && it->first == key) return it->second;
    const bool b = blocked(x, theta);
    cache_.insert(it, {key, b});
    return b;
  }

  bool any_free(const std::vector<Vec2>& probes, double theta) {
    return std::any_of(probes.begin(), probes.end(),
                       [&](Vec2 p) { return !blocked_cached(p, theta); });
  }

  const std::vector<BinEntry>& bin_entries() {
    if (!ctx_.kept_entries.empty()) return ctx_.kept_entries[size_t(bin_)];
    if (!entries_) entries_ = ctx_.entries(bin_);
    return *entries_;
  }

  bool overlap_reaches_free(const Candidate& c) {
    if (c.count != 2) return false;
    const std::vector<ContactSegment>& a = segments_at(c.families[0], c.theta);
    const std::vector<ContactSegment>& b = segments_at(c.families[1], c.theta);
    // Piece by piece, stopping at the first free probe: the probes tested, and so the cache,
    // are those of testing them all in this order up to that one.
    std::vector<Vec2>& probes = probes_;  // scratch, kept with its capacity
    probes.clear();
    for (const ContactSegment& sa : a)
      for (const ContactSegment& sb : b)
        if (intersect(sa.curve, sb.curve, ctx_.pair.tol.geometric).kind ==
            IntersectionKind::overlapping) {
          probes.clear();
          add_piece_probes(c.families[0], sa.curve, c.theta, probes);
          if (any_free(probes, c.theta)) return true;
        }
    return false;
  }

  // A contact segment appearing, vanishing or switching ends matters only if some of it is
  // outside blocked space. Other contact segments cut it into pieces each wholly blocked or
  // not, so its ends and the pieces' midpoints decide (a piece free at a single crossing
  // point only would be a degenerate contact, which the crossing's own criticalities see).
  bool segment_end_reaches_free(const Candidate& c) {
    const int family = c.families[0];
    const std::vector<ContactSegment>& own = segments_at(family, c.theta);
    // Cheap probes first (the ends and each segment's middle); cutting into pieces only when
    // those are all blocked.
    std::vector<Vec2>& probes = probes_;  // scratch, kept with its capacity
    probes.clear();
    const Transform& rotation = memo_turn_;  // segments_at() just turned to c.theta
    for (const MovingPoint& e : ctx_.families[family].ends) probes.push_back(e.at(rotation));
    for (const ContactSegment& s : own) probes.push_back(point_at(s.curve, 0.5));
    if (any_free(probes, c.theta)) return true;
    for (const ContactSegment& s : own) {
      probes.clear();
      add_piece_probes(family, s.curve, c.theta, probes);
      if (any_free(probes, c.theta)) return true;
    }
    return false;
  }

  void add_piece_probes(int family, const Curve& curve, double theta, std::vector<Vec2>& probes) {
    std::vector<double>& cuts = cuts_;  // scratch, kept with its capacity
    cuts.assign({0.0, 1.0});
    const Box box = bounding_box(curve).inflated(ctx_.pair.tol.criticality);
    for (const BinEntry& n : bin_entries()) {
      if (n.family == family || !n.box.overlaps(box)) continue;
      for (const ContactSegment& s : segments_at(n.family, theta)) {
        const Intersection hit = intersect(curve, s.curve, ctx_.pair.tol.geometric);
        for (int h = 0; h < hit.count; ++h) {
          cuts.push_back(hit.hits[h].ta0);
          cuts.push_back(hit.hits[h].ta1);
        }
      }
    }
    std::sort(cuts.begin(), cuts.end());
    for (size_t k = 0; k + 1 < cuts.size(); ++k)
      if (cuts[k + 1] > cuts[k]) probes.push_back(point_at(curve, 0.5 * (cuts[k] + cuts[k + 1])));
  }

  const Context& ctx_;
  PlacementTester tester_;
  std::vector<ContactSegment> scratch_;
  std::vector<std::vector<ContactSegment>> memo_;  // segments_at(), by family
  std::vector<unsigned> memo_stamp_;               // memo_now_ when memo_[f] was built
  unsigned memo_now_ = 0;
  std::uint64_t memo_theta_ = 0;
  Transform memo_turn_;  // the rotation by memo_theta_
  bool memo_used_ = false;
  std::vector<double> near_;              // roots()
  std::vector<Vec2> probes_;              // the probes of one candidate (reaches_free)
  std::vector<double> cuts_;              // add_piece_probes()
  ProbeAnswers cache_;                    // sorted by key
  const ProbeAnswers* tested_ = nullptr;  // the point criticalities' answers
  // Those of one orientation cell, range_theta_ (blocked_cached()), once found.
  bool range_known_ = false;
  long long range_theta_ = 0;
  ProbeAnswers::const_iterator range_first_, range_last_;
  int bin_ = 0;
  std::optional<std::vector<BinEntry>> entries_;  // of bin_, when built
};

class CriticalFinder {
 public:
  CriticalFinder(const Pair& pair, const CriticalOptions& options)
      : ctx_(pair, options), workers_([this] { return std::make_unique<Worker>(ctx_); }) {
    set_.stats.families = int(ctx_.families.size());
  }

  CriticalSet run() {
    auto [pairs, triples] = meet();
    solve(pairs, triples);
    std::vector<Candidate> found;
    for (auto& w : workers_) {
      found.insert(found.end(), w->found.begin(), w->found.end());
      w->found.clear();
    }
    add_switches(found);
    sort_candidates(found);
    const std::vector<char> keep = screen(found);
    for (auto& w : workers_) add_stats(w->stats);
    kept_.reserve(size_t(std::count_if(keep.begin(), keep.end(), [](char k) { return k != 0; })));
    for (size_t i = 0; i < found.size(); ++i)
      if (keep[i]) kept_.push_back(criticality(found[i]));
    set_.stats.blocked = long(found.size() - kept_.size());
    if (ctx_.domain)
      set_.stats.mapped = add_symmetric_images(
          kept_, ctx_.symmetries, ctx_.pair.tol,
          [this](const FeaturePairRef& p, double theta) { return segment_end_at(p, theta); });
    group();
    if (ctx_.domain) align_symmetric_orientations(set_, ctx_.symmetries, ctx_.pair.tol);
    return std::move(set_);
  }

 private:
  using Workers = tbb::enumerable_thread_specific<std::unique_ptr<Worker>>;

  // Pass 1: the pairs and triples that may meet, with their bins. Bins go in blocks, each
  // block's candidates grouped and merged in before the next: a pair or triple meets in
  // many bins, and the candidates of all bins at once would take gigabytes on large pairs.
  std::pair<std::vector<MeetingTask>, std::vector<MeetingTask>> meet() {
    struct Found {
      std::vector<MeetingCandidate> pairs, triples;
    };
    std::vector<MeetingTask> pairs, triples;
    constexpr int kBlock = 64;
    for (int first = 0; first < ctx_.binning.count; first += kBlock) {
      tbb::enumerable_thread_specific<Found> per_thread;
      tbb::parallel_for(first, std::min(first + kBlock, ctx_.binning.count), [&](int b) {
        Found& f = per_thread.local();
        std::vector<BinEntry> entries = ctx_.entries(b);
        meeting_candidates(entries, ctx_.scope(b), f.pairs, f.triples);
        if (!ctx_.kept_entries.empty()) ctx_.kept_entries[size_t(b)] = std::move(entries);
      });
      std::vector<MeetingCandidate> block_pairs, block_triples;
      for (Found& f : per_thread) {
        block_pairs.insert(block_pairs.end(), f.pairs.begin(), f.pairs.end());
        block_triples.insert(block_triples.end(), f.triples.begin(), f.triples.end());
      }
      merge_tasks(pairs, group_candidates(block_pairs));
      merge_tasks(triples, group_candidates(block_triples));
    }
    return {std::move(pairs), std::move(triples)};
  }

  // Pass 2: every pair and triple solved and its roots validated.
  void solve(const std::vector<MeetingTask>& pairs, const std::vector<MeetingTask>& triples) {
    const size_t n = pairs.size() + triples.size();
    tbb::parallel_for(size_t(0), n, [&](size_t i) {
      Worker& w = *workers_.local();
      if (i < pairs.size())
        w.solve_pair(pairs[i]);
      else
        w.solve_triple(triples[i - pairs.size()]);
    });
  }

  // Sorted by `before`. Candidates it does not order are alike in every field (count follows
  // from the condition), and their angles are spread over the turn: bucketed by angle (a
  // monotone map), each bucket sorted by `before`. A NaN angle has no bucket.
  static void sort_candidates(std::vector<Candidate>& found) {
    const auto nan = [](const Candidate& c) { return std::isnan(c.theta); };
    if (std::any_of(found.begin(), found.end(), nan))
      return std::sort(found.begin(), found.end(), before);
    const size_t buckets = std::max<size_t>(1, found.size() / 4);
    const double per_radian = double(buckets) / kTwoPi;
    const auto bucket_of = [&](const Candidate& c) {
      const double b = std::floor((c.theta + kPi) * per_radian);  // monotone in theta
      return size_t(std::clamp(b, 0.0, double(buckets - 1)));
    };
    bucket_sort(found, buckets, bucket_of, before);
  }

  // Condition 2 needs no equation: the switches are known per family.
  void add_switches(std::vector<Candidate>& found) const {
    for (size_t i = 0; i < ctx_.families.size(); ++i)
      for (double theta : ctx_.families[i].switches)
        if (ctx_.in_domain(theta))
          found.push_back({CriticalCondition::segment_end,
                           {int(i), -1, -1},
                           1,
                           theta,
                           ctx_.families[i].ends.front().at(theta)});
  }

  // Pass 3: which candidates (sorted) to keep.
  std::vector<char> screen(const std::vector<Candidate>& found) {
    std::vector<char> keep(found.size(), 1);
    if (!ctx_.options.screen_blocked) return keep;
    // Point criticalities: each distinct configuration cell tested once, by the first
    // candidate in it (several equations find one event: an end of a on b and of b on a, a
    // vertex with both its edges).
    std::vector<std::pair<ProbeKey, size_t>> keys;
    for (size_t i = 0; i < found.size(); ++i)
      if (found[i].condition != CriticalCondition::segment_end)
        keys.push_back({probe_key(ctx_.pair, found[i].at, found[i].theta), i});
    std::sort(keys.begin(), keys.end());
    std::vector<size_t> firsts;  // indices into keys where a new key starts
    for (size_t k = 0; k < keys.size(); ++k)
      if (k == 0 || keys[k].first != keys[k - 1].first) firsts.push_back(k);
    std::vector<char> blocked(firsts.size());
    tbb::parallel_for(size_t(0), firsts.size(), [&](size_t g) {
      const Candidate& c = found[keys[firsts[g]].second];
      blocked[g] = workers_.local()->blocked(c.at, c.theta);
    });
    ProbeAnswers tested(firsts.size());  // sorted, as the keys are
    for (size_t g = 0; g < firsts.size(); ++g) tested[g] = {keys[firsts[g]].first, blocked[g] != 0};
    // Blocked candidates that may still reach free space, and every segment end, are
    // probed along their contact segments, grouped by bin (the probes cut by the bin's
    // families).
    std::vector<std::vector<size_t>> probe(ctx_.binning.count);
    for (size_t g = 0, k = 0; k < keys.size(); ++k) {
      if (g + 1 < firsts.size() && k == firsts[g + 1]) ++g;
      if (!blocked[g]) continue;
      const size_t i = keys[k].second;
      keep[i] = 0;
      if (found[i].count == 2) probe[ctx_.binning.bin_of(found[i].theta)].push_back(i);
    }
    for (size_t i = 0; i < found.size(); ++i)
      if (found[i].condition == CriticalCondition::segment_end) {
        keep[i] = 0;
        probe[ctx_.binning.bin_of(found[i].theta)].push_back(i);
      }
    tbb::parallel_for(0, ctx_.binning.count, [&](int b) {
      if (probe[b].empty()) return;
      Worker& w = *workers_.local();
      w.start_bin(b, tested);
      for (size_t i : probe[b]) keep[i] = w.reaches_free(found[i]);
    });
    return keep;
  }

  void add_stats(const CriticalStats& s) {
    set_.stats.equations += s.equations;
    set_.stats.roots += s.roots;
    set_.stats.culled += s.culled;
    set_.stats.off_segment += s.off_segment;
  }

  // Where a segment_end criticality of these features happens (add_switches).
  Vec2 segment_end_at(const FeaturePairRef& p, double theta) const {
    const Context::Features key{p.moving_feature, p.fixed_feature, int(p.kind)};
    const auto& index = ctx_.family_by_features;
    const auto it = std::lower_bound(index.begin(), index.end(), std::pair{key, -1});
    if (it == index.end() || it->first != key) return {};
    return ctx_.families[size_t(it->second)].ends.front().at(theta);
  }

  Criticality criticality(const Candidate& c) const {
    Criticality k;
    k.theta = wrap_angle(c.theta);
    k.condition = c.condition;
    k.at = c.at;
    for (int i = 0; i < c.count; ++i) {
      const ContactFamily& fam = ctx_.families[c.families[i]];
      k.pairs.push_back({fam.moving, fam.fixed, fam.kind});
    }
    return k;
  }

  // ---- Grouping (paper section 9) -------------------------------------------------------

  // The angle of a group: its median member's (the lower of the two middle ones), unwrapped
  // into [lo, hi]. A designed coincidence puts most members at one angle, exact to round-off,
  // while a grazing root among them is exact to about 1e-8 rad only. The group's middle could
  // then lie 7.5e-9 rad off the coincidence, where contact segments meant to end at one point
  // ended 1.5e-8 apart (twice the geometric epsilon) and a slice lost its unbounded free
  // component (designed stress pair 859). The median is a member's own angle.
  static double group_angle(const CriticalOrientation& o, double lo, double hi) {
    std::vector<double> angles;
    angles.reserve(o.criticalities.size());
    for (const Criticality& c : o.criticalities)
      angles.push_back(c.theta < lo ? c.theta + kTwoPi : c.theta > hi ? c.theta - kTwoPi : c.theta);
    const auto mid = angles.begin() + (angles.size() - 1) / 2;
    std::nth_element(angles.begin(), mid, angles.end());
    return wrap_angle(*mid);
  }

  void group() {
    // Stable: candidates were sorted by everything, so equal wrapped angles keep that order.
    // They were sorted by angle too, so only an angle that wrapping moved calls for a sort.
    const auto by_angle = [](const Criticality& a, const Criticality& b) {
      return a.theta < b.theta;
    };
    if (!std::is_sorted(kept_.begin(), kept_.end(), by_angle))
      std::stable_sort(kept_.begin(), kept_.end(), by_angle);
    set_.stats.criticalities = long(kept_.size());
    for (const Criticality& k : kept_) ++set_.counts[int(k.condition)];
    const double gap = ctx_.pair.tol.critical_angle;
    // Groups as index ranges; a group straddling theta = -pi joins the last to the first.
    std::vector<size_t> starts;
    for (size_t i = 0; i < kept_.size(); ++i)
      if (i == 0 || kept_[i].theta - kept_[i - 1].theta > gap) starts.push_back(i);
    size_t wrapped = kept_.size();  // start of a last group that wraps onto the first
    if (starts.size() > 1 && kept_.front().theta + kTwoPi - kept_.back().theta <= gap) {
      wrapped = starts.back();
      starts.pop_back();
    }
    for (size_t g = 0; g < starts.size(); ++g) {
      const size_t end = g + 1 < starts.size() ? starts[g + 1] : wrapped;
      CriticalOrientation o;
      o.criticalities.reserve(end - starts[g] + (g == 0 ? kept_.size() - wrapped : 0));
      double lo = kept_[starts[g]].theta, hi = kept_[end - 1].theta;
      if (g == 0 && wrapped < kept_.size()) {
        lo = kept_[wrapped].theta - kTwoPi;
        for (size_t i = wrapped; i < kept_.size(); ++i)
          o.criticalities.push_back(std::move(kept_[i]));
      }
      // Each criticality goes to one group, and its angle was read above: moved, not copied.
      for (size_t i = starts[g]; i < end; ++i) o.criticalities.push_back(std::move(kept_[i]));
      o.theta = group_angle(o, lo, hi);
      set_.orientations.push_back(std::move(o));
    }
    std::stable_sort(set_.orientations.begin(), set_.orientations.end(),
                     [](const auto& a, const auto& b) { return a.theta < b.theta; });
  }

  Context ctx_;
  Workers workers_;
  std::vector<Criticality> kept_;
  CriticalSet set_;
};

}  // namespace

CriticalSet critical_orientations(const Pair& pair, const CriticalOptions& options) {
  if (options.threads <= 0) return CriticalFinder(pair, options).run();
  tbb::task_arena arena(arena_threads(options.threads));
  return arena.execute([&] {
    // A new arena's other threads join it only once it has work, some 40 microseconds later:
    // an empty task, spawned first, calls them in while the context starts.
    tbb::task_group summon;
    summon.run([] {});
    CriticalSet set = CriticalFinder(pair, options).run();
    summon.wait();
    return set;
  });
}

}  // namespace cslice
