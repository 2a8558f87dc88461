// Critical orientations: every solution of the criticality equations of the contact
// families, kept when its configuration lies on the contact segments it involves (their
// parameter limits) and, optionally, outside blocked space.
//
// Pairs and triples of families are only solved when they can meet: theta is cut into
// bins, each family gets a box per bin it is alive in (holding all its contact segments
// there), and only families whose boxes overlap in some bin are paired (a sweep along x).
// Each pair or triple is solved once over the whole circle.
#include <algorithm>
#include <map>
#include <unordered_set>

#include "criticals/events.hpp"
#include "cslice/classify.hpp"
#include "cslice/critical.hpp"

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

// A family alive in a bin: its cover at the bin's middle orientation, how far its contact
// segments can stray from that cover within the bin, and the box holding them all.
struct BinEntry {
  int family = 0;
  Curve cover;
  double margin = 0.0;
  Box box;
};

class CriticalFinder {
 public:
  CriticalFinder(const Pair& pair, const CriticalOptions& options)
      : pair_(pair),
        options_(options),
        screen_pair_(screening_pair(pair)),
        tester_(screen_pair_),
        moving_(contact_features(pair.moving)),
        fixed_(contact_features(pair.fixed)),
        families_(contact_families(pair)) {
    for (const ContactFamily& f : families_) equations_.push_back(family_equation(f));
    set_.stats.families = int(families_.size());
  }

  CriticalSet run() {
    // Finer bins cull more pairs but cost a cover per alive family each; on the random
    // curved pairs of bench_critical one bin per eight families measured best.
    const int count = std::clamp(int(families_.size()) / 8, 32, 1 << 12);
    bin_width_ = kTwoPi / count;
    switches_.assign(count, {});
    for (size_t i = 0; i < families_.size(); ++i)
      for (double theta : families_[i].switches)
        switches_[bin_of(theta)].push_back({int(i), theta});
    pending_.assign(count, {});
    for (int b = 0; b < count; ++b) solve_bin(b);
    // Pairs are solved once, in the first bin where they may meet, so a root may fall in
    // another bin; probing its contact segments needs that bin's neighbours.
    for (int b = 0; b < count; ++b) {
      if (pending_[b].empty()) continue;
      current_bin_ = b;
      fill_bin(b);
      for (const Pending& p : pending_[b]) keep_point(p.condition, {p.a, p.b}, p.theta, p.at);
    }
    group();
    return std::move(set_);
  }

 private:
  // The pair with its geometric epsilon widened to the criticality tolerance: the placement
  // test then calls blocked only overlaps deeper than a criticality's own round-off.
  static Pair screening_pair(const Pair& pair) {
    Pair p = pair;
    p.tol.geometric = pair.tol.criticality;
    return p;
  }

  // ---- Candidate pairs and triples ----------------------------------------------------

  int bin_of(double theta) const {
    const int b = int(std::floor((wrap_angle(theta) + kPi) / bin_width_));
    return std::clamp(b, 0, int(switches_.size()) - 1);
  }

  // Families alive in bin b, each with its cover at the bin's middle.
  void fill_bin(int b) {
    const double lo = -kPi + b * bin_width_, mid = lo + 0.5 * bin_width_;
    bin_.clear();
    for (size_t i = 0; i < families_.size(); ++i) {
      const ContactFamily& f = families_[i];
      if (!alive_within(f, lo, lo + bin_width_)) continue;
      BinEntry e;
      e.family = int(i);
      e.cover = family_cover(f, mid);
      e.margin = family_drift(f) * 0.5 * bin_width_ + pair_.tol.criticality;
      e.box = bounding_box(e.cover).inflated(e.margin);
      bin_.push_back(e);
    }
  }

  // Two families can meet within the bin only if their covers come within their margins.
  bool may_meet(const BinEntry& x, const BinEntry& y) const {
    return x.box.overlaps(y.box) && distance_between(x.cover, y.cover) <= x.margin + y.margin;
  }

  // Whether the third family can pass through a point where the first two meet within the
  // bin. Where covers x and y cross at an angle phi, their crossing stays within the meeting
  // of two bands as wide as their margins: (margin_x + margin_y) / sin(phi) from where it is
  // at the bin's middle (doubled for the curvature of arcs). Covers that only come close,
  // or cross nearly tangentially, give no bound.
  bool may_meet_at(const BinEntry& x, const BinEntry& y, const Intersection& meet,
                   const BinEntry& z) const {
    if (meet.kind == IntersectionKind::none || meet.kind == IntersectionKind::overlapping)
      return true;
    for (int h = 0; h < meet.count; ++h) {
      const IntersectionHit& hit = meet.hits[h];
      const double sine =
          std::fabs(cross(tangent_at(x.cover, hit.ta0), tangent_at(y.cover, hit.tb0)));
      const double drift = 2.0 * (x.margin + y.margin);
      if (drift >= sine * pair_.tol.size) return true;  // could drift across the whole pair
      if (distance_to_curve(z.cover, hit.point) <= z.margin + drift / sine) return true;
    }
    return false;
  }

  void solve_bin(int b) {
    current_bin_ = b;
    fill_bin(b);
    std::vector<BinEntry>& bin = bin_;
    std::sort(bin.begin(), bin.end(),
              [](const BinEntry& x, const BinEntry& y) { return x.box.lo.x < y.box.lo.x; });
    std::vector<std::vector<int>> neighbours(bin.size());
    for (size_t i = 0; i < bin.size(); ++i)
      for (size_t j = i + 1; j < bin.size() && bin[j].box.lo.x <= bin[i].box.hi.x; ++j)
        if (may_meet(bin[i], bin[j])) {
          neighbours[i].push_back(int(j));
          neighbours[j].push_back(int(i));
          solve_pair(bin[i].family, bin[j].family);
        }
    for (auto& n : neighbours) std::sort(n.begin(), n.end());
    for (size_t i = 0; i < bin.size(); ++i)
      for (int j : neighbours[i]) {
        if (j <= int(i)) continue;
        std::optional<Intersection> meet;  // computed when a third family needs it
        for (int k : neighbours[j]) {
          if (k <= j || !std::binary_search(neighbours[i].begin(), neighbours[i].end(), k))
            continue;
          if (!meet) meet = intersect(bin[i].cover, bin[j].cover, pair_.tol.geometric);
          if (may_meet_at(bin[i], bin[j], *meet, bin[k]))
            solve_triple(bin[i].family, bin[j].family, bin[k].family);
        }
      }
    for (const auto& [family, theta] : switches_[b]) add_segment_end(family, theta);
  }

  // Exact keys (no hashing collisions can drop a pair): family indices in base N.
  uint64_t key(uint64_t a, uint64_t b, uint64_t c = 0) const {
    const uint64_t n = families_.size() + 1;
    return (a * n + b) * n + c;
  }

  void solve_pair(int i, int j) {
    if (i > j) std::swap(i, j);
    if (!solved_pairs_.insert(key(i, j)).second) return;
    for (auto [a, b] : {std::pair{i, j}, std::pair{j, i}})
      for (size_t e = 0; e < families_[a].ends.size(); ++e)
        for (double theta : roots(endpoint_equation(families_[a].ends[e], equations_[b])))
          add_endpoint(a, int(e), b, theta);
    std::array<EventEquation, 2> tangents;
    const int n = tangent_equations(equations_[i], equations_[j], tangents);
    for (int k = 0; k < n; ++k)
      for (double theta : roots(tangents[k])) add_tangent(i, j, theta);
  }

  void solve_triple(int i, int j, int k) {
    int f[3] = {i, j, k};
    std::sort(f, f + 3);
    if (!solved_triples_.insert(key(f[0], f[1], f[2])).second) return;
    const EventEquation eq = triple_equation(equations_[f[0]], equations_[f[1]], equations_[f[2]]);
    for (double theta : roots(eq)) add_triple(f[0], f[1], f[2], theta);
  }

  std::vector<double> roots(const EventEquation& eq) {
    ++set_.stats.equations;
    const TrigRoots r = trig_roots(eq.f, kRelativeGeometricEpsilon * eq.magnitude,
                                   kRelativeGeometricEpsilon, pair_.tol.angular);
    set_.stats.roots += long(r.roots.size());
    return r.roots;
  }

  // ---- Validation: the configuration lies on the contact segments --------------------

  const std::vector<ContactSegment>& segments_of(int family, double theta,
                                                 std::vector<ContactSegment>& out) const {
    out.clear();
    const ContactFamily& f = families_[family];
    add_pair_contacts(pair_, moving_[f.moving], fixed_[f.fixed], theta, out);
    return out;
  }

  // How near x lies to the family's contact segments at theta, and to their ends: one
  // rebuild of the segments answers both.
  struct Nearness {
    bool on_segment = false;
    bool at_end = false;
  };
  Nearness nearness(int family, double theta, Vec2 x) {
    Nearness n;
    const double tol = pair_.tol.criticality;
    for (const ContactSegment& s : segments_of(family, theta, scratch_)) {
      n.on_segment |= distance_to_curve(s.curve, x) <= tol;
      n.at_end |= std::min(distance(s.curve.from, x), distance(s.curve.to, x)) <= tol;
    }
    return n;
  }

  // A cheap first test: every family involved exists at theta.
  bool all_alive(std::initializer_list<int> fams, double theta) const {
    for (int f : fams)
      if (!alive_at(families_[f], theta, pair_.tol.critical_angle)) return false;
    return true;
  }

  void add_endpoint(int a, int end, int b, double theta) {
    if (!all_alive({a, b}, theta)) return reject();
    const Vec2 x = families_[a].ends[end].at(theta);
    if (!nearness(a, theta, x).at_end || !nearness(b, theta, x).on_segment) return reject();
    keep_point(CriticalCondition::endpoint, {a, b}, theta, x);
  }

  void add_tangent(int a, int b, double theta) {
    if (!all_alive({a, b}, theta)) return reject();
    const Vec2 x = tangent_point(equations_[a], equations_[b], theta);
    if (!nearness(a, theta, x).on_segment || !nearness(b, theta, x).on_segment) return reject();
    keep_point(CriticalCondition::tangent, {a, b}, theta, x);
  }

  void add_triple(int a, int b, int c, double theta) {
    if (!all_alive({a, b, c}, theta)) return reject();
    const std::optional<Vec2> x = triple_point(equations_[a], equations_[b], equations_[c], theta);
    if (!x) return reject();
    // Three curves through the end of one of them is an endpoint event, which its own
    // (better conditioned) equation finds; the triple equation there is near-degenerate
    // when two of the curves always share that end.
    bool at_an_end = false;
    for (int f : {a, b, c}) {
      const Nearness n = nearness(f, theta, *x);
      if (!n.on_segment) return reject();
      at_an_end |= n.at_end;
    }
    if (at_an_end) return reject();
    keep_point(CriticalCondition::triple, {a, b, c}, theta, *x);
  }

  void reject() { ++set_.stats.off_segment; }

  // ---- Screening: criticalities inside blocked space change nothing --------------------

  bool blocked_at(Vec2 x, double theta) {
    // Several equations find one event (an end of a on b and of b on a, a vertex with both
    // its edges): test each configuration once.
    const double cell = pair_.tol.criticality;
    const std::array<long long, 3> key{std::llround(theta / pair_.tol.critical_angle),
                                       std::llround(x.x / cell), std::llround(x.y / cell)};
    if (auto it = screened_.find(key); it != screened_.end()) return it->second;
    const bool b = tester_.blocked({x.x, x.y, theta});
    screened_.emplace(key, b);
    return b;
  }

  void keep_point(CriticalCondition c, std::initializer_list<int> fams, double theta, Vec2 x) {
    if (!options_.screen_blocked || !blocked_at(x, theta)) return keep(c, fams, theta, x);
    if (fams.size() == 2 && bin_of(theta) != current_bin_) {
      pending_[bin_of(theta)].push_back({c, *fams.begin(), *(fams.begin() + 1), theta, x});
      return;
    }
    if (overlap_reaches_free(fams, theta)) return keep(c, fams, theta, x);
    ++set_.stats.blocked;
  }

  // Two contact segments that overlap at theta (parallel edges brought into line, equal
  // circles) change along the whole shared piece, not only at the point found: probe it.
  bool overlap_reaches_free(std::initializer_list<int> fams, double theta) {
    if (fams.size() != 2) return false;
    std::vector<ContactSegment> a, b;
    segments_of(*fams.begin(), theta, a);
    segments_of(*(fams.begin() + 1), theta, b);
    std::vector<Vec2> probes;
    for (const ContactSegment& sa : a)
      for (const ContactSegment& sb : b)
        if (intersect(sa.curve, sb.curve, pair_.tol.geometric).kind ==
            IntersectionKind::overlapping)
          add_piece_probes(*fams.begin(), sa.curve, theta, probes);
    return std::any_of(probes.begin(), probes.end(), [&](Vec2 p) { return !blocked_at(p, theta); });
  }

  // A contact segment appearing, vanishing or switching ends matters only if some of it is
  // outside blocked space. Other contact segments cut it into pieces each wholly blocked or
  // not, so its ends and the pieces' midpoints decide (a piece free at a single crossing
  // point only would be a degenerate contact, which the crossing's own criticalities see).
  void add_segment_end(int family, double theta) {
    std::vector<ContactSegment> own;
    segments_of(family, theta, own);
    // Cheap probes first (the ends and each segment's middle); cutting into pieces only when
    // those are all blocked.
    std::vector<Vec2> probes;
    for (const MovingPoint& e : families_[family].ends) probes.push_back(e.at(theta));
    for (const ContactSegment& s : own) probes.push_back(point_at(s.curve, 0.5));
    const Vec2 at = probes.front();
    auto all_blocked = [&] {
      return std::all_of(probes.begin(), probes.end(),
                         [&](Vec2 p) { return blocked_at(p, theta); });
    };
    if (options_.screen_blocked && all_blocked()) {
      probes.clear();
      for (const ContactSegment& s : own) add_piece_probes(family, s.curve, theta, probes);
      if (all_blocked()) {
        ++set_.stats.blocked;
        return;
      }
    }
    keep(CriticalCondition::segment_end, {family}, theta, at);
  }

  void add_piece_probes(int family, const Curve& curve, double theta, std::vector<Vec2>& probes) {
    std::vector<double> cuts = {0.0, 1.0};
    const Box box = bounding_box(curve).inflated(pair_.tol.criticality);
    std::vector<ContactSegment> others;
    for (const BinEntry& n : bin_) {
      if (n.family == family || !n.box.overlaps(box)) continue;
      for (const ContactSegment& s : segments_of(n.family, theta, others)) {
        const Intersection hit = intersect(curve, s.curve, pair_.tol.geometric);
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

  void keep(CriticalCondition c, std::initializer_list<int> fams, double theta, Vec2 x) {
    Criticality k;
    k.theta = wrap_angle(theta);
    k.condition = c;
    k.at = x;
    for (int f : fams) {
      const ContactFamily& fam = families_[f];
      k.pairs.push_back({fam.moving, fam.fixed, fam.kind});
    }
    kept_.push_back(std::move(k));
  }

  // ---- Grouping (paper section 9) -------------------------------------------------------

  void group() {
    std::sort(kept_.begin(), kept_.end(),
              [](const Criticality& a, const Criticality& b) { return a.theta < b.theta; });
    set_.stats.criticalities = long(kept_.size());
    for (const Criticality& k : kept_) ++set_.counts[int(k.condition)];
    const double gap = pair_.tol.critical_angle;
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
      double lo = kept_[starts[g]].theta, hi = kept_[end - 1].theta;
      if (g == 0 && wrapped < kept_.size()) {
        lo = kept_[wrapped].theta - kTwoPi;
        for (size_t i = wrapped; i < kept_.size(); ++i) o.criticalities.push_back(kept_[i]);
      }
      for (size_t i = starts[g]; i < end; ++i) o.criticalities.push_back(kept_[i]);
      o.theta = wrap_angle(0.5 * (lo + hi));
      set_.orientations.push_back(std::move(o));
    }
    std::sort(set_.orientations.begin(), set_.orientations.end(),
              [](const auto& a, const auto& b) { return a.theta < b.theta; });
  }

  const Pair& pair_;
  CriticalOptions options_;
  Pair screen_pair_;
  PlacementTester tester_;
  std::vector<ContactFeature> moving_, fixed_;
  std::vector<ContactFamily> families_;
  std::vector<FamilyEquation> equations_;
  std::vector<BinEntry> bin_;  // the bin being solved
  int current_bin_ = 0;
  // Blocked point criticalities of two families whose overlap must still be probed, by bin.
  struct Pending {
    CriticalCondition condition;
    int a, b;
    double theta;
    Vec2 at;
  };
  std::vector<std::vector<Pending>> pending_;
  std::vector<std::vector<std::pair<int, double>>> switches_;  // (family, theta) per bin
  double bin_width_ = kTwoPi;
  std::unordered_set<uint64_t> solved_pairs_, solved_triples_;
  std::vector<ContactSegment> scratch_;
  std::vector<Criticality> kept_;
  std::map<std::array<long long, 3>, bool> screened_;  // blocked_at, by configuration cell
  CriticalSet set_;
};

}  // namespace

CriticalSet critical_orientations(const Pair& pair, const CriticalOptions& options) {
  return CriticalFinder(pair, options).run();
}

}  // namespace cslice
