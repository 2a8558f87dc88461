// Stitching a strip next to a critical slice C, from the regular slice R on its other side
// (paper section 2.5: from the known correspondence, never by guessing; docs/mesh.md).
//
// Each piece of C (a "dart") belongs to the piece of R with its label: each cycle of C is
// aligned with each cycle of R linked to it through the transition, preserving their order
// (several darts may go to one piece: a piece split at C by a curve touching it), and a dart
// two cycles of R claim goes to the nearer piece. Each cycle of R then walks through the
// darts given to its pieces, in its own order. That is the whole story of a branching: at a
// merge the cycles of C that touch at a pinch vertex (shared, see mesh_sample.cpp) are walked
// in turn by the one merged cycle of R; at a split, by the several cycles of R, each taking its
// run. Where the walk jumps between darts that do not meet, a degenerate contact of C joins
// them (a sliding fit, along which free space opens on R's side: the fastener's slot); it is
// walked once in each direction. A dart no piece of R has (it appears or vanishes exactly at C)
// is tiled with the pieces between its neighbours. A cycle of R given no dart (a component or
// hole that vanishes at C) closes onto the degenerate contact it shrinks to: a point (a fan) or
// a curve (walked both ways), or, when C shows neither, the point where its contact curves
// meet in C. A cycle of C with nothing on R's side (a sliver vanishing at C itself, up to
// round-off) is closed flat in C. Only a cycle of R with nothing to close onto is closed by a
// cone, and counted.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "mesh/mesh_internal.hpp"

namespace cslice::mesh_detail {

namespace {

// Fills the NaN coordinates of a polyline by arc length between the known ones; the ends,
// when unknown, take the band's own ends (0 and `length`) or the nearest known value.
void fill_coordinates(const std::vector<int>& line, std::vector<double>& coord, double length,
                      const VertexStore& store) {
  const int n = static_cast<int>(line.size());
  int first = -1, last = -1;
  for (int k = 0; k < n; ++k)
    if (!std::isnan(coord[k])) {
      if (first < 0) first = k;
      last = k;
    }
  if (std::isnan(coord.front())) coord.front() = first < 0 ? 0.0 : std::min(0.0, coord[first]);
  if (std::isnan(coord.back())) coord.back() = last < 0 ? length : std::max(length, coord[last]);
  std::vector<double> along(n, 0.0);
  for (int k = 1; k < n; ++k)
    along[k] = along[k - 1] + distance(store.xy(line[k - 1]), store.xy(line[k]));
  for (int k = 1, known = 0; k < n; ++k) {
    if (std::isnan(coord[k])) continue;
    for (int g = known + 1; g < k; ++g) {
      const double span = along[k] - along[known];
      const double t = span > 0.0 ? (along[g] - along[known]) / span : 0.5;
      coord[g] = coord[known] + t * (coord[k] - coord[known]);
    }
    known = k;
  }
}

// Distance of a dart of the critical slice from a piece of the regular one: at its ends and
// middle, so a dart ending at a pinch still goes to the piece it runs along.
double dart_distance(const Piece& dart, const Piece& piece) {
  return distance_to_curve(piece.curve, dart.curve.from) +
         2.0 * distance_to_curve(piece.curve, point_at(dart.curve, 0.5)) +
         distance_to_curve(piece.curve, dart.curve.to);
}

// Where the nearest point of the line or circle carrying curve c lies along c, as a length from
// its start, not clamped to the curve (darts of a neighbouring slice may reach past its ends);
// a circle is cut opposite the arc's middle.
double along_carrier(const Curve& c, Vec2 p) {
  if (c.is_segment()) return dot(p - c.from, normalized(c.to - c.from));
  const double sign = c.sweep > 0.0 ? 1.0 : -1.0;
  const double middle = c.start_angle + 0.5 * c.sweep;
  const Vec2 d = p - c.center;
  const double off = wrap_angle(std::atan2(d.y, d.x) - middle);
  return c.radius * (0.5 * std::fabs(c.sweep) + sign * off);
}

using Score = std::pair<double, double>;  // (matches, -distance), compared in that order

// One linear alignment, darts from si and pieces from sj (cyclically), by dynamic
// programming: dart i either goes to piece j (scoring weight(i, j)), or is skipped; several
// consecutive darts may go to one piece. Returns the score and each dart's piece or -1.
template <class Weight>
Score align_from(int n, int m, int si, int sj, const Weight& weight, std::vector<int>& match) {
  std::vector<Score> dp((n + 1) * (m + 1), Score{0.0, 0.0});
  std::vector<char> took((n + 1) * (m + 1), 0);  // 0: skip piece, 1: skip dart, 2: match
  const auto at = [&](int i, int j) { return i * (m + 1) + j; };
  for (int i = 1; i <= n; ++i)
    for (int j = 1; j <= m; ++j) {
      Score v = dp[at(i, j - 1)];
      char t = 0;
      if (dp[at(i - 1, j)] > v) v = dp[at(i - 1, j)], t = 1;
      if (const std::optional<Score> w = weight((si + i - 1) % n, (sj + j - 1) % m)) {
        const Score with{dp[at(i - 1, j)].first + w->first, dp[at(i - 1, j)].second + w->second};
        if (with > v) v = with, t = 2;
      }
      dp[at(i, j)] = v;
      took[at(i, j)] = t;
    }
  match.assign(n, -1);
  for (int i = n, j = m; i > 0 && j > 0;) {
    const char t = took[at(i, j)];
    if (t == 0) {
      --j;
      continue;
    }
    if (t == 2) match[(si + i - 1) % n] = (sj + j - 1) % m;
    --i;
  }
  return dp[at(n, m)];
}

// How well dart d of critical slice c answers to a regular piece labelled l: 1 for its own
// label, 1/2 for the label of a segment coinciding with it (find_coinciding_labels), else 0.
double label_weight(const SampledSlice& c, int d, SegmentLabel l) {
  if (c.pieces[d].label == l) return 1.0;
  if (d >= static_cast<int>(c.coinciding.size())) return 0.0;
  const auto& alt = c.coinciding[d];
  return std::find(alt.begin(), alt.end(), l) == alt.end() ? 0.0 : 0.5;
}

// The order-preserving alignment of the darts of critical cycle y with the pieces of regular
// cycle x: for each dart, the position of its piece in x, or -1. A match scores 1 for the same
// label, 1/2 for the label of a coinciding segment; among alignments of equal score, the
// smaller total distance wins. Both cycles are cut at a label found once in each, or, when
// every label repeats, x is tried at every rotation.
std::vector<int> align_darts(const SampledSlice& c, const Cycle& y, const SampledSlice& r,
                             const Cycle& x) {
  const int n = static_cast<int>(y.size()), m = static_cast<int>(x.size());
  const auto weight = [&](int i, int j) -> std::optional<Score> {
    const Piece& p = r.pieces[x[j]];
    const double w = label_weight(c, y[i], p.label);
    if (w == 0.0) return std::nullopt;
    return Score{w, -dart_distance(c.pieces[y[i]], p)};
  };
  std::vector<SegmentLabel> ly, lx;
  for (int p : y) ly.push_back(c.pieces[p].label);
  for (int p : x) lx.push_back(r.pieces[p].label);
  const auto once = [](const std::vector<SegmentLabel>& v, SegmentLabel l) {
    return std::count(v.begin(), v.end(), l) == 1;
  };
  std::vector<std::pair<int, int>> starts;
  for (int i = 0; i < n && starts.empty(); ++i)
    if (once(ly, ly[i]) && once(lx, ly[i]))
      starts.push_back({i, static_cast<int>(std::find(lx.begin(), lx.end(), ly[i]) - lx.begin())});
  if (starts.empty())
    for (int j = 0; j < m; ++j) starts.push_back({0, j});
  std::vector<int> best(n, -1), match;
  Score best_score{-1.0, 0.0};
  for (const auto& [si, sj] : starts) {
    const Score score = align_from(n, m, si, sj, weight, match);
    if (score > best_score) {
      best_score = score;
      best = match;
    }
  }
  return best;
}

class Walker {
 public:
  // One step of a regular cycle's walk: dart `piece` of the critical slice, walked along the
  // regular cycle's piece at position `at`.
  // A loose step (a dart no regular piece has, or a join of another label) lies between
  // regular pieces, in the stretch after piece `at`.
  struct Step {
    int at = 0;
    int piece = 0;
    bool loose = false;
  };

  Walker(const SampledSlice& r, const SampledSlice& c, bool r_lower, VertexStore& store)
      : r_(r), c_(c), r_lower_(r_lower), store_(store) {}

  StripResult run(const ComponentLinks& links) {
    dart_used_.assign(c_.pieces.size(), 0);
    // Cycles left over by their transition events (components too small for the topology's
    // samples to link) are then walked among themselves, by their labels.
    Leftovers left;
    std::vector<char> c_linked(c_.cycles.size(), 0);
    for (const auto& [lower, upper] : links.groups) {
      const std::vector<int>& r_comps = r_lower_ ? lower : upper;
      const std::vector<int>& c_comps = r_lower_ ? upper : lower;
      for (int q : c_comps) c_linked[q] = 1;
      walk_group(cycles_of(r_, r_comps), cycles_of(c_, c_comps), &left);
    }
    for (int q = 0; q < static_cast<int>(c_.cycles.size()); ++q)
      if (!c_linked[q])
        for (const Cycle& y : c_.cycles[q]) left.c.push_back(&y);
    walk_group(left.r, left.c, nullptr);
    return std::move(out_);
  }

 private:
  struct Leftovers {
    std::vector<const Cycle*> r, c;
  };

  const SampledSlice &r_, &c_;
  bool r_lower_;
  VertexStore& store_;
  StripResult out_;
  std::vector<char> dart_used_;  // per piece of the critical slice: walked already

  static std::vector<const Cycle*> cycles_of(const SampledSlice& s, const std::vector<int>& comps) {
    std::vector<const Cycle*> out;
    for (int p : comps)
      for (const Cycle& x : s.cycles[p]) out.push_back(&x);
    return out;
  }

  // A branching: a regular cycle walking darts of several critical cycles (a merge, seen from
  // after it), or a critical cycle whose darts several regular cycles walk (seen from before).
  void count_branchings(const std::vector<const Cycle*>& c_cycles,
                        const std::map<int, int>& cycle_of_dart, int r_count) {
    std::vector<std::vector<int>> sources(r_count);
    for (int k = 0; k < static_cast<int>(c_cycles.size()); ++k) {
      std::vector<int> targets;
      for (int d : *c_cycles[k]) {
        const auto it = cycle_of_dart.find(d);
        if (it == cycle_of_dart.end()) continue;
        targets.push_back(it->second);
        sources[it->second].push_back(k);
      }
      std::sort(targets.begin(), targets.end());
      if (std::unique(targets.begin(), targets.end()) - targets.begin() > 1)
        ++out_.stats.branched_cycles;
    }
    for (auto& s : sources) {
      std::sort(s.begin(), s.end());
      if (std::unique(s.begin(), s.end()) - s.begin() > 1) ++out_.stats.branched_cycles;
    }
  }

  // Which piece of R (cycle, position) a dart of C goes to, and how well.
  struct Claim {
    int cycle = -1, at = -1;
    double weight = 0.0, distance = 0.0;
  };
  std::map<int, Claim> claim_darts(const std::vector<const Cycle*>& r_cycles,
                                   const std::vector<const Cycle*>& c_cycles) const;
  void drop_open_branches(const std::vector<const Cycle*>& c_cycles,
                          std::map<int, Claim>& owner) const;
  void drop_cycles_beyond_their_pieces(const std::vector<const Cycle*>& r_cycles,
                                       const std::vector<const Cycle*>& c_cycles,
                                       std::map<int, Claim>& owner) const;
  int degenerate_dart(int from, int to, bool unused_only) const;
  // Walks the cycles of R linked to the cycles of C through one event. In the first pass
  // (`left` given) what finds no partner is left over; in the second it is closed.
  void walk_group(const std::vector<const Cycle*>& r_cycles,
                  const std::vector<const Cycle*>& c_cycles, Leftovers* left);
  void chain_darts(std::vector<Step>& steps) const;
  void chain_group(std::vector<Step>::iterator first, std::vector<Step>::iterator last) const;
  std::vector<Step> join(const Cycle& cycle, const std::vector<Step>& steps);
  void emit_walk(const Cycle& cycle, std::vector<Step> steps);
  bool collapse(const Cycle& cycle);
  void own_copy_of_ridge(size_t first_band);
  int vanishing_point(const Cycle& cycle);
  void cap(const Cycle& cycle);
  void band(std::vector<int> r_line, std::vector<double> r_coord, std::vector<int> c_line,
            std::vector<double> c_coord);
};

// Each dart to a regular piece of its label (or, failing that, of a segment coinciding with
// it), by order-preserving alignment of each pair of cycles; a dart that two regular cycles
// claim (the pinched label at a split) goes to the nearer piece.
std::map<int, Walker::Claim> Walker::claim_darts(const std::vector<const Cycle*>& r_cycles,
                                                 const std::vector<const Cycle*>& c_cycles) const {
  std::map<int, Claim> owner;
  for (const Cycle* y : c_cycles)
    for (int i = 0; i < static_cast<int>(r_cycles.size()); ++i) {
      const std::vector<int> match = align_darts(c_, *y, r_, *r_cycles[i]);
      for (int k = 0; k < static_cast<int>(y->size()); ++k) {
        if (match[k] < 0) continue;
        const int d = (*y)[k];
        const Piece& rp = r_.pieces[(*r_cycles[i])[match[k]]];
        const Claim claim{i, match[k], rp.label == c_.pieces[d].label ? 1.0 : 0.5,
                          dart_distance(c_.pieces[d], rp)};
        const auto it = owner.find(d);
        if (it == owner.end() || claim.weight > it->second.weight ||
            (claim.weight == it->second.weight && claim.distance < it->second.distance))
          owner[d] = claim;
      }
    }
  return owner;
}

// The first degenerate dart of C from vertex `from` to vertex `to` (among those no walk has
// used yet, when asked), or -1.
int Walker::degenerate_dart(int from, int to, bool unused_only) const {
  for (int d = c_.boundary_pieces; d < static_cast<int>(c_.pieces.size()); ++d)
    if ((!unused_only || !dart_used_[d]) && c_.pieces[d].first() == from &&
        c_.pieces[d].last() == to)
      return d;
  return -1;
}

// The darts of one cycle of C owned by different regular cycles form branches: runs of
// consecutive owned darts of one owner, each with the loose darts after it. At a real
// branching (the pinch of a merge or a split at C) every branch closes on itself, at the
// pinch vertex or through a degenerate dart, and the regular cycles' walks meet there. A
// branch that does not close is a label matched across two components that meet only just
// beyond C, within its critical angle (stress seed 133605: a piece new at C given to the
// other component's piece of that label). Its darts are left loose, to follow their
// neighbours in the largest branch.
void Walker::drop_open_branches(const std::vector<const Cycle*>& c_cycles,
                                std::map<int, Claim>& owner) const {
  struct Branch {
    int first = 0, count = 0;  // into `owned`
    bool closed = false;
  };
  for (const Cycle* y : c_cycles) {
    const int n = static_cast<int>(y->size());
    std::vector<int> owned;  // positions in y
    for (int k = 0; k < n; ++k)
      if (owner.count((*y)[k])) owned.push_back(k);
    const int m = static_cast<int>(owned.size());
    const auto owner_at = [&](int i) { return owner.at((*y)[owned[i]]).cycle; };
    std::vector<int> starts;  // indices into `owned` where a branch starts
    for (int i = 0; i < m; ++i)
      if (owner_at(i) != owner_at((i + m - 1) % m)) starts.push_back(i);
    if (starts.size() < 2) continue;
    std::vector<Branch> branches;
    for (size_t b = 0; b < starts.size(); ++b) {
      const int i0 = starts[b], i1 = starts[(b + 1) % starts.size()];
      const int last = (owned[i1] + n - 1) % n;  // the dart before the next branch
      const int from = c_.pieces[(*y)[owned[i0]]].first(), to = c_.pieces[(*y)[last]].last();
      const bool closed = from == to || degenerate_dart(from, to, false) >= 0 ||
                          degenerate_dart(to, from, false) >= 0;
      branches.push_back({i0, (i1 - i0 + m) % m, closed});
    }
    if (std::all_of(branches.begin(), branches.end(), [](const Branch& b) { return b.closed; }))
      continue;
    const auto largest =
        std::max_element(branches.begin(), branches.end(),
                         [](const Branch& a, const Branch& b) { return a.count < b.count; });
    for (auto b = branches.begin(); b != branches.end(); ++b) {
      if (b == largest || b->closed) continue;
      for (int j = 0; j < b->count; ++j) owner.erase((*y)[owned[(b->first + j) % m]]);
    }
  }
}

// A sliver of free space that vanishes at C itself, up to round-off, can touch a component
// that goes on (stress seed 148668: two contact curves nearly tangent at C, the sliver between
// them and a third curve, 6e-8 wide, gone 1e-7 rad beyond C). The topology rightly links both
// to R's component, whose pieces of the sliver's labels end where the curves cross in R, far
// from the sliver: every dart of it lies beyond the end of the piece that claims it. Walked,
// its cycle would be fanned to that one regular vertex, a cone whose two edges to it run
// alongside the walk's own (edges used four times). Such a cycle, one of several in the
// group, is released to be capped in C.
void Walker::drop_cycles_beyond_their_pieces(const std::vector<const Cycle*>& r_cycles,
                                             const std::vector<const Cycle*>& c_cycles,
                                             std::map<int, Claim>& owner) const {
  if (c_cycles.size() < 2) return;
  const auto beyond = [&](int d) {
    const Claim& claim = owner.at(d);
    const Piece& rp = r_.pieces[(*r_cycles[claim.cycle])[claim.at]];
    const double along = along_carrier(rp.curve, point_at(c_.pieces[d].curve, 0.5));
    return along < 0.0 || along > curve_length(rp.curve);
  };
  std::vector<const Cycle*> released;
  for (const Cycle* y : c_cycles) {
    bool any = false, all_beyond = true;
    for (int d : *y)
      if (owner.count(d)) any = true, all_beyond = all_beyond && beyond(d);
    if (any && all_beyond) released.push_back(y);
  }
  if (released.empty() || released.size() == c_cycles.size()) return;
  for (const Cycle* y : released)
    for (int d : *y) owner.erase(d);
}

void Walker::walk_group(const std::vector<const Cycle*>& r_cycles,
                        const std::vector<const Cycle*>& c_cycles, Leftovers* left) {
  const SampledSlice &r = r_, &c = c_;
  std::map<int, Claim> owner = claim_darts(r_cycles, c_cycles);
  drop_open_branches(c_cycles, owner);
  drop_cycles_beyond_their_pieces(r_cycles, c_cycles, owner);
  // A dart with no such piece (it appears or vanishes exactly at the critical slice) is loose:
  // it follows the owned dart before it in its cycle. A cycle of C with no owned dart at all
  // has no partner on R's side: left over for the second pass, then capped.
  std::vector<std::vector<Step>> steps(r_cycles.size());
  std::map<int, std::vector<int>> followers;  // owned dart -> loose darts after it
  for (const Cycle* y : c_cycles) {
    const int n = static_cast<int>(y->size());
    int first_owned = -1;
    for (int k = 0; k < n && first_owned < 0; ++k)
      if (owner.count((*y)[k])) first_owned = k;
    if (first_owned < 0) {
      if (left)
        left->c.push_back(y);
      else
        cap(*y);
      continue;
    }
    for (int k = 1, last = (*y)[first_owned]; k < n; ++k) {
      const int d = (*y)[(first_owned + k) % n];
      if (owner.count(d)) {
        last = d;
      } else {
        followers[last].push_back(d);
        ++out_.stats.unmatched_pieces;
      }
    }
  }
  for (const auto& [d, claim] : owner) steps[claim.cycle].push_back({claim.at, d, false});
  std::map<int, int> cycle_of_dart;
  for (const auto& [d, claim] : owner) cycle_of_dart[d] = claim.cycle;
  count_branchings(c_cycles, cycle_of_dart, static_cast<int>(r_cycles.size()));
  for (size_t i = 0; i < r_cycles.size(); ++i) {
    // Along each regular piece, its darts in the order of their middles' nearest points (a
    // dart of a coinciding segment has no coordinate in the piece's frame).
    auto& s = steps[i];
    const auto along = [&](const Step& x) {
      return along_carrier(r.pieces[(*r_cycles[i])[x.at]].curve,
                           point_at(c.pieces[x.piece].curve, 0.5));
    };
    std::stable_sort(s.begin(), s.end(), [&](const Step& x, const Step& y) {
      return x.at != y.at ? x.at < y.at : along(x) < along(y);
    });
    chain_darts(s);
    std::vector<Step> walk;
    for (const Step& st : s) {
      walk.push_back(st);
      for (int f : followers[st.piece]) walk.push_back({st.at, f, true});
    }
    for (const Step& st : walk) dart_used_[st.piece] = 1;
    if (!walk.empty()) {
      ++out_.stats.matched_cycles;
      emit_walk(*r_cycles[i], std::move(walk));
    } else if (left) {
      left->r.push_back(r_cycles[i]);
    } else if (!collapse(*r_cycles[i])) {
      add_cone(r, *r_cycles[i], c.theta, r_lower_, store_, out_);
    }
  }
}

// Darts of one regular piece that meet end to start follow each other, whatever their middles'
// positions say: next to a critical slice a piece's curve can move many times its own length
// (a short contact arc whose circle turns with theta), and the middles of two consecutive
// darts then project onto the regular piece's carrier almost together, in either order (stress
// seed 100125). Chains are kept in the order of their first darts.
void Walker::chain_darts(std::vector<Step>& steps) const {
  for (size_t g0 = 0, g1 = 0; g0 < steps.size(); g0 = g1) {
    while (g1 < steps.size() && steps[g1].at == steps[g0].at) ++g1;
    if (g1 - g0 > 1) chain_group(steps.begin() + g0, steps.begin() + g1);
  }
}

// One piece's darts, [first, last).
void Walker::chain_group(std::vector<Step>::iterator first,
                         std::vector<Step>::iterator last) const {
  const std::vector<Step> steps(first, last);
  const size_t n = steps.size();
  const auto piece = [&](size_t k) -> const Piece& { return c_.pieces[steps[k].piece]; };
  const auto follows = [&](size_t k, size_t before) {
    return k != before && piece(before).last() == piece(k).first() &&
           piece(before).first() != piece(before).last();
  };
  std::vector<char> taken(n, 0), has_predecessor(n, 0);
  for (size_t k = 0; k < n; ++k)
    for (size_t j = 0; j < n; ++j) has_predecessor[k] |= follows(k, j);
  for (size_t head = 0; head < n; ++head) {
    if (taken[head] || has_predecessor[head]) continue;
    for (size_t k = head; k < n;) {
      taken[k] = 1;
      *first++ = steps[k];
      size_t next = 0;
      while (next < n && (taken[next] || !follows(next, k))) ++next;
      k = next;
    }
  }
  for (size_t k = 0; k < n; ++k)  // chains closed on themselves keep their order
    if (!taken[k]) *first++ = steps[k];
}

// Appends the vertices of dart d to a polyline, its start merged with the line's end.
void append(std::vector<int>& line, const Piece& d) {
  if (line.empty() || line.back() != d.first()) line.push_back(d.first());
  line.insert(line.end(), d.verts.begin() + 1, d.verts.end());
}

// Builds the bands of one regular cycle walking through the darts `steps`: one band per
// regular piece that has darts, and one for each stretch between two such pieces (pieces that
// shrink to a corner at the critical slice, loose darts, and joins between darts that do not
// meet).
// Joins darts that do not meet by a degenerate dart from one's end to the next one's start:
// it goes with the regular piece of its own label on either side, or is loose.
std::vector<Walker::Step> Walker::join(const Cycle& cycle, const std::vector<Step>& steps) {
  std::vector<Step> joined;
  const int n = static_cast<int>(steps.size());
  struct Jump {
    int from, to;
    SegmentLabel label;
  };
  std::vector<Jump> jumps;  // joins with no degenerate dart: straight edges
  for (int k = 0; k < n; ++k) {
    const Step &x = steps[k], &y = steps[(k + 1) % n];
    joined.push_back(x);
    const int from = c_.pieces[x.piece].last(), to = c_.pieces[y.piece].first();
    if (from == to) continue;
    const int bridge = degenerate_dart(from, to, true);
    if (bridge < 0) {
      jumps.push_back({from, to, c_.pieces[x.piece].label});
      continue;
    }
    dart_used_[bridge] = 1;
    ++out_.stats.degenerate_joins;
    const SegmentLabel label = c_.pieces[bridge].label;
    if (!y.loose && label == r_.pieces[cycle[y.at]].label) {
      if (k + 1 == n)
        joined.insert(joined.begin(), {y.at, bridge, false});
      else
        joined.push_back({y.at, bridge, false});
    } else {
      joined.push_back({x.at, bridge, x.loose || !(label == r_.pieces[cycle[x.at]].label)});
    }
  }
  // A jump paired with one back between the same two vertices along another label crosses a
  // lens (MeshStats::lens_joins); any other is a guess.
  for (const Jump& j : jumps) {
    const bool paired = std::any_of(jumps.begin(), jumps.end(), [&](const Jump& o) {
      return o.from == j.to && o.to == j.from && !(o.label == j.label);
    });
    ++(paired ? out_.stats.lens_joins : out_.stats.straight_joins);
  }
  // A loose step between two owned steps of one piece (a piece of C appearing inside one of
  // R, splitting it) belongs to that piece.
  for (int k = 0, prev = -1; k < static_cast<int>(joined.size()); ++k) {
    if (joined[k].loose) continue;
    for (int g = prev + 1; prev >= 0 && g < k; ++g)
      if (joined[prev].at == joined[k].at) joined[g].loose = false;
    prev = k;
  }
  return joined;
}

// Rotates the walk to start a run (owned steps on one piece of R) and returns the runs as
// (first step, end of its owned steps); loose steps follow their run.
std::vector<std::pair<int, int>> runs_of(std::vector<Walker::Step>& joined) {
  const int m = static_cast<int>(joined.size());
  const auto run_starts = [&](int k) {
    const Walker::Step &s = joined[k], &prev = joined[(k + m - 1) % m];
    return !s.loose && (prev.loose || prev.at != s.at);
  };
  int start = 0;
  while (start < m && !run_starts(start)) ++start;
  if (start == m) start = 0;  // a single run covering the whole walk
  std::rotate(joined.begin(), joined.begin() + start, joined.end());
  std::vector<std::pair<int, int>> runs;
  for (int k = 0; k < m;) {
    int e = k + 1;
    while (e < m && !joined[e].loose && joined[e].at == joined[k].at) ++e;
    runs.push_back({k, e});
    k = e;
    while (k < m && joined[k].loose) ++k;
  }
  return runs;
}

void Walker::emit_walk(const Cycle& cycle, std::vector<Step> steps) {
  const SampledSlice &r = r_, &c = c_;
  std::vector<Step> joined = join(cycle, steps);
  const int m = static_cast<int>(joined.size());
  const std::vector<std::pair<int, int>> runs = runs_of(joined);
  const int np = static_cast<int>(cycle.size());
  for (size_t g = 0; g < runs.size(); ++g) {
    const auto [s0, s1] = runs[g];
    const Piece& rp = r.pieces[cycle[joined[s0].at]];
    std::vector<int> line;
    std::vector<double> coord;
    for (int k = s0; k < s1; ++k) {
      const Piece& d = c.pieces[joined[k].piece];
      const bool same = d.label == rp.label;
      const double shift = same ? shift_into(rp, d) : 0.0;
      append(line, d);
      coord.resize(line.size(), std::numeric_limits<double>::quiet_NaN());
      for (size_t v = 0; same && v < d.verts.size(); ++v)
        coord[line.size() - d.verts.size() + v] = shift + d.offset[v];
    }
    fill_coordinates(line, coord, rp.length(), store_);
    band(rp.verts, rp.offset, line, coord);
    ++out_.stats.matched_pieces;
    // The stretch to the next run: the regular pieces in between, against the loose steps.
    const int next = runs[(g + 1) % runs.size()].first;
    const int at = joined[s0].at, next_at = joined[next].at;
    const int gap = runs.size() == 1 ? np - 1 : cyclic_gap(at, next_at, np);
    out_.stats.unmatched_pieces += gap;
    std::vector<int> c_line{line.back()};
    for (int k = s1 % m; k != next; k = (k + 1) % m) append(c_line, c.pieces[joined[k].piece]);
    if (c_line.back() != c.pieces[joined[next].piece].first())
      c_line.push_back(c.pieces[joined[next].piece].first());
    band(cycle_polyline(r, cycle, at + 1, gap), {}, c_line, {});
  }
}

// A regular cycle given no dart: it shrinks to a degenerate contact of the critical slice
// sharing one of its labels, the nearest: a fan to a point, or a walk along a curve both ways.
bool Walker::collapse(const Cycle& cycle) {
  const SampledSlice &r = r_, &c = c_;
  const auto has_label = [&](SegmentLabel l) {
    for (int p : cycle)
      if (r.pieces[p].label == l) return true;
    return false;
  };
  const auto dist = [&](Vec2 q) {
    double best = std::numeric_limits<double>::infinity();
    for (int p : cycle) best = std::min(best, distance_to_curve(r.pieces[p].curve, q));
    return best;
  };
  double best = std::numeric_limits<double>::infinity();
  int best_point = -1, best_dart = -1;
  for (int k = 0; k < static_cast<int>(c.points.size()); ++k) {
    const DegeneratePoint& p = c.points[k];
    if (std::none_of(p.labels.begin(), p.labels.end(), has_label)) continue;
    const double d = dist(store_.xy(p.vertex));
    if (d < best) best = d, best_point = k, best_dart = -1;
  }
  // A dart answers to a piece of the cycle by its label or a coinciding one.
  const auto answers = [&](int d) {
    for (int p : cycle)
      if (label_weight(c, d, r.pieces[p].label) > 0.0) return true;
    return false;
  };
  for (int d = c.boundary_pieces; d + 1 < static_cast<int>(c.pieces.size()); d += 2) {
    if (dart_used_[d] || dart_used_[d + 1]) continue;
    if (!answers(d) && !answers(d + 1)) continue;
    const double e = dist(point_at(c.pieces[d].curve, 0.5));
    if (e < best) best = e, best_point = -1, best_dart = d;
  }
  int apex = best_point >= 0 ? c.points[best_point].vertex : -1;
  if (apex < 0 && best_dart < 0) apex = vanishing_point(cycle);
  if (apex >= 0) {
    ++out_.stats.collapsed_to_point;
    band(cycle_polyline(r, cycle, 0, static_cast<int>(cycle.size())), {}, {apex}, {});
    return true;
  }
  if (best_dart < 0) return false;
  ++out_.stats.collapsed_to_curve;
  // The two darts go to the regular pieces of their labels (the best weight, then the
  // nearest), or follow each other.
  std::vector<Step> steps;
  for (int d : {best_dart, best_dart + 1}) {
    dart_used_[d] = 1;
    int at = -1;
    double weight = 0.0, near = std::numeric_limits<double>::infinity();
    for (int k = 0; k < static_cast<int>(cycle.size()); ++k) {
      const double w = label_weight(c, d, r.pieces[cycle[k]].label);
      const double e = dart_distance(c.pieces[d], r.pieces[cycle[k]]);
      if (w > weight || (w == weight && w > 0.0 && e < near)) {
        weight = w;
        near = e;
        at = k;
      }
    }
    steps.push_back({at, d});
  }
  if (steps[0].at < 0 && steps[1].at < 0) steps[0].at = 0;
  for (int k = 0; k < 2; ++k)
    if (steps[k].at < 0) steps[k].at = steps[1 - k].at;
  if (steps[1].at < steps[0].at) std::swap(steps[0], steps[1]);
  const size_t first_band = out_.bands.size();
  emit_walk(cycle, std::move(steps));
  own_copy_of_ridge(first_band);
  return true;
}

// Free space pinched to a curve at C (a part fitting its opening exactly at one orientation
// only) is closed from each side by a walk along the curve both ways. Sharing the curve's
// vertices, the two sides put four triangles on each of its edges (designed pair 81: a
// stadium in a square of its length); each side's ridge gets its own copy of the vertices
// instead, so that each side closes on itself and the surface touches itself along the curve,
// as the free space does. The bands from first_band on are this collapse's.
void Walker::own_copy_of_ridge(size_t first_band) {
  std::map<int, int> copy;
  for (size_t b = first_band; b < out_.bands.size(); ++b) {
    std::vector<int>& line = r_lower_ ? out_.bands[b].upper : out_.bands[b].lower;
    for (int& v : line) {
      const auto [it, fresh] = copy.try_emplace(v, -1);
      if (fresh) {
        const MeshVertex original = store_.vertices[static_cast<size_t>(v)];
        it->second = store_.add(store_.xy(v), original.theta, original.label);
        store_.end_label.back() = store_.end_label[static_cast<size_t>(v)];
      }
      v = it->second;
    }
  }
}

// Where a regular cycle with nothing in the critical slice to close onto vanishes: a point
// where the contact curves of its labels meet in the critical slice, all of them within the
// criticality tolerance (the slice shows no degenerate point there when round-off leaves the
// curves a hair apart). A new vertex of the critical slice, or -1.
int Walker::vanishing_point(const Cycle& cycle) {
  const SampledSlice &r = r_, &c = c_;
  std::vector<SegmentLabel> labels;
  for (int p : cycle) labels.push_back(r.pieces[p].label);
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  std::map<SegmentLabel, std::vector<const Curve*>> curves;
  for (const ContactSegment& seg : c.slice->contact_segments) {
    const SegmentLabel l{seg.moving_feature, seg.fixed_feature};
    if (!seg.is_point && std::binary_search(labels.begin(), labels.end(), l))
      curves[l].push_back(&seg.curve);
  }
  if (curves.size() < 2) return -1;
  const double eps = c.slice->epsilon, reach = kCriticalityPerGeometric * eps;
  const auto score = [&](Vec2 q) {
    double worst = 0.0;
    for (const auto& [l, list] : curves) {
      double d = std::numeric_limits<double>::infinity();
      for (const Curve* k : list) d = std::min(d, distance_to_curve(*k, q));
      worst = std::max(worst, d);
    }
    return worst;
  };
  double best = reach;
  std::optional<Vec2> found;
  std::vector<const Curve*> all;
  for (const auto& [l, list] : curves) all.insert(all.end(), list.begin(), list.end());
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size(); ++j) {
      const Intersection x = intersect(*all[i], *all[j], reach);
      for (int h = 0; h < x.count; ++h)
        if (const double e = score(x.hits[h].point); e <= best) {
          best = e;
          found = x.hits[h].point;
        }
    }
  if (!found) return -1;
  return store_.add(*found, c.theta, labels.front());
}

// A cycle of the critical slice with nothing on R's side: its component (or hole) vanishes at
// C itself, up to round-off, and is left there as a sliver. Closed flat in C, by a fan from its
// centroid; a cycle that encloses no area closes itself (its edges run both ways).
void Walker::cap(const Cycle& cycle) {
  const std::vector<int> loop = cycle_polyline(c_, cycle, 0, static_cast<int>(cycle.size()));
  Vec2 centroid;
  double area = 0.0;
  for (size_t k = 0; k + 1 < loop.size(); ++k) {
    centroid = centroid + store_.xy(loop[k]);
    area += 0.5 * cross(store_.xy(loop[k]), store_.xy(loop[k + 1]));
  }
  const double eps = c_.slice->epsilon;
  if (std::fabs(area) <= eps * eps) return;
  centroid = (1.0 / static_cast<double>(loop.size() - 1)) * centroid;
  ++out_.stats.capped_cycles;
  const int apex = store_.add(centroid, c_.theta, c_.pieces[cycle.front()].label);
  // Oriented like the strip on R's side would have closed it: the cap faces away from C's
  // free side, towards R.
  if (r_lower_)
    out_.bands.push_back({{apex}, loop, {}, {}});
  else
    out_.bands.push_back({loop, {apex}, {}, {}});
}

void Walker::band(std::vector<int> r_line, std::vector<double> r_coord, std::vector<int> c_line,
                  std::vector<double> c_coord) {
  if (r_lower_)
    out_.bands.push_back(
        {std::move(r_line), std::move(c_line), std::move(r_coord), std::move(c_coord)});
  else
    out_.bands.push_back(
        {std::move(c_line), std::move(r_line), std::move(c_coord), std::move(r_coord)});
}

}  // namespace

StripResult walk_critical(const SampledSlice& r, const SampledSlice& c, bool r_lower,
                          const ComponentLinks& links, VertexStore& store) {
  return Walker(r, c, r_lower, store).run(links);
}

}  // namespace cslice::mesh_detail
