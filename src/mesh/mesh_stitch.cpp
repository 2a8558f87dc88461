// Stitching the strip between two consecutive slices: which boundary pieces of one slice
// become which of the other, as bands to tile (paper section 2.5: from the known
// correspondence, never by guessing).
//
// Within an interval (neither slice critical) the boundary cycles of linked components have
// the same labels in the same cyclic order: cycles are paired and aligned by their labels
// (longest cyclic common subsequence), each matched pair of pieces is one band, and the pieces
// between two matched ones on either side another. Next to a critical slice the cycles walk
// through the critical slice's pieces instead (mesh_walk.cpp).
#include <algorithm>
#include <cmath>
#include <map>

#include "mesh/mesh_internal.hpp"

namespace cslice::mesh_detail {

std::vector<int> cycle_polyline(const SampledSlice& s, const Cycle& cycle, int first, int count) {
  const int n = static_cast<int>(cycle.size());
  std::vector<int> out{s.pieces[cycle[((first % n) + n) % n]].first()};
  for (int k = 0; k < count; ++k) {
    const Piece& p = s.pieces[cycle[(first + k) % n]];
    out.insert(out.end(), p.verts.begin() + 1, p.verts.end());
  }
  return out;
}

double shift_into(const Piece& frame, const Piece& part) {
  double d = part.start - frame.start;
  if (frame.period > 0.0) d -= frame.period * std::round(d / frame.period);
  return d;
}

int cyclic_gap(int from, int to, int n) {
  return ((to - from - 1) % n + n) % n;
}

void add_cone(const SampledSlice& s, const Cycle& c, double other_theta, bool lower,
              VertexStore& store, StripResult& out) {
  ++out.stats.coned_cycles;
  const std::vector<int> loop = cycle_polyline(s, c, 0, static_cast<int>(c.size()));
  Vec2 centroid;
  for (size_t k = 0; k + 1 < loop.size(); ++k) centroid = centroid + store.xy(loop[k]);
  centroid = (1.0 / static_cast<double>(std::max<size_t>(1, loop.size() - 1))) * centroid;
  const int apex = store.add(centroid, other_theta, {-1, -1});
  out.bands.push_back(lower ? Band{loop, {apex}, {}, {}} : Band{{apex}, loop, {}, {}});
}

namespace {

// Longest common subsequence of a and b rotated by r, as matched index pairs.
std::vector<std::pair<int, int>> lcs(const std::vector<SegmentLabel>& a,
                                     const std::vector<SegmentLabel>& b, int r) {
  const int n = static_cast<int>(a.size()), m = static_cast<int>(b.size());
  const auto bl = [&](int k) { return b[(k + r) % m]; };
  std::vector<int> dp((n + 1) * (m + 1), 0);
  const auto at = [&](int i, int j) -> int& { return dp[i * (m + 1) + j]; };
  for (int i = 1; i <= n; ++i)
    for (int j = 1; j <= m; ++j)
      at(i, j) =
          a[i - 1] == bl(j - 1) ? at(i - 1, j - 1) + 1 : std::max(at(i - 1, j), at(i, j - 1));
  std::vector<std::pair<int, int>> out;
  for (int i = n, j = m; i > 0 && j > 0;) {
    if (a[i - 1] == bl(j - 1) && at(i, j) == at(i - 1, j - 1) + 1) {
      out.push_back({i - 1, (j - 1 + r) % m});
      --i;
      --j;
    } else if (at(i - 1, j) >= at(i, j - 1)) {
      --i;
    } else {
      --j;
    }
  }
  std::reverse(out.begin(), out.end());
  return out;
}

// The strip between two slices of one interval.
class Aligner {
 public:
  Aligner(const SampledSlice& a, const SampledSlice& b, VertexStore& store)
      : a_(a), b_(b), store_(store) {}

  StripResult run(const ComponentLinks& links) {
    for (const auto& [lower, upper] : links.groups) align_group(lower, upper);
    return std::move(out_);
  }

 private:
  const SampledSlice &a_, &b_;
  VertexStore& store_;
  StripResult out_;

  std::vector<SegmentLabel> labels(const SampledSlice& s, const Cycle& c) const {
    std::vector<SegmentLabel> out;
    for (int p : c) out.push_back(s.pieces[p].label);
    return out;
  }

  // The band between piece pa of a and piece pb of b, by material coordinate.
  void piece_band(const Piece& pa, const Piece& pb) {
    Band band{pa.verts, pb.verts, pa.offset, pb.offset};
    const double shift = shift_into(pa, pb);
    for (double& c : band.upper_coord) c += shift;
    out_.bands.push_back(std::move(band));
  }

  void align_group(const std::vector<int>& lower, const std::vector<int>& upper) {
    struct Candidate {
      const Cycle *ca, *cb;
      std::vector<std::pair<int, int>> pairs;
    };
    std::vector<Candidate> candidates;
    for (int p : lower)
      for (int q : upper)
        for (const Cycle& x : a_.cycles[p])
          for (const Cycle& y : b_.cycles[q]) candidates.push_back({&x, &y, align(x, y)});
    std::stable_sort(
        candidates.begin(), candidates.end(),
        [](const Candidate& x, const Candidate& y) { return x.pairs.size() > y.pairs.size(); });
    std::map<const Cycle*, bool> used;
    for (const Candidate& c : candidates) {
      if (c.pairs.empty()) break;
      if (used[c.ca] || used[c.cb]) continue;
      used[c.ca] = used[c.cb] = true;
      stitch_aligned(*c.ca, *c.cb, c.pairs);
    }
    // A cycle left alone on each side sharing no label with the other: the same patch (only
    // when the slices disagree numerically), aligned by the nearest start points.
    std::vector<const Cycle*> left_a, left_b;
    for (int p : lower)
      for (const Cycle& x : a_.cycles[p])
        if (!used[&x]) left_a.push_back(&x);
    for (int q : upper)
      for (const Cycle& y : b_.cycles[q])
        if (!used[&y]) left_b.push_back(&y);
    if (left_a.size() == 1 && left_b.size() == 1) {
      stitch_unanchored(*left_a.front(), *left_b.front());
      return;
    }
    for (const Cycle* x : left_a) add_cone(a_, *x, b_.theta, true, store_, out_);
    for (const Cycle* y : left_b) add_cone(b_, *y, a_.theta, false, store_, out_);
  }

  // The best cyclic alignment of two cycles' labels: the longest common subsequence over every
  // rotation of y; among equally long ones, the smallest distance between matched starts
  // (only a periodic label sequence has several).
  std::vector<std::pair<int, int>> align(const Cycle& x, const Cycle& y) const {
    const std::vector<SegmentLabel> lx = labels(a_, x), ly = labels(b_, y);
    std::vector<std::pair<int, int>> best;
    double best_cost = 0.0;
    for (int r = 0; r < static_cast<int>(y.size()); ++r) {
      std::vector<std::pair<int, int>> pairs = lcs(lx, ly, r);
      if (pairs.size() < best.size() || pairs.empty()) continue;
      double cost = 0.0;
      for (auto [i, j] : pairs)
        cost += distance(store_.xy(a_.pieces[x[i]].first()), store_.xy(b_.pieces[y[j]].first()));
      if (pairs.size() > best.size() || cost < best_cost) {
        best = std::move(pairs);
        best_cost = cost;
      }
    }
    return best;
  }

  void stitch_aligned(const Cycle& x, const Cycle& y, const std::vector<std::pair<int, int>>& m) {
    ++out_.stats.matched_cycles;
    const int k = static_cast<int>(m.size());
    const int nx = static_cast<int>(x.size()), ny = static_cast<int>(y.size());
    for (int t = 0; t < k; ++t) {
      const auto [pa, pb] = m[t];
      const auto [qa, qb] = m[(t + 1) % k];
      piece_band(a_.pieces[x[pa]], b_.pieces[y[pb]]);
      ++out_.stats.matched_pieces;
      const int ga = cyclic_gap(pa, qa, nx), gb = cyclic_gap(pb, qb, ny);
      out_.stats.unmatched_pieces += ga + gb;
      out_.bands.push_back(
          {cycle_polyline(a_, x, pa + 1, ga), cycle_polyline(b_, y, pb + 1, gb), {}, {}});
    }
  }

  void stitch_unanchored(const Cycle& x, const Cycle& y) {
    ++out_.stats.matched_cycles;
    ++out_.stats.unanchored_cycles;
    const Vec2 start = store_.xy(a_.pieces[x.front()].first());
    int best = 0;
    for (int r = 1; r < static_cast<int>(y.size()); ++r)
      if (distance(start, store_.xy(b_.pieces[y[r]].first())) <
          distance(start, store_.xy(b_.pieces[y[best]].first())))
        best = r;
    out_.bands.push_back({cycle_polyline(a_, x, 0, static_cast<int>(x.size())),
                          cycle_polyline(b_, y, best, static_cast<int>(y.size())),
                          {},
                          {}});
  }
};

}  // namespace

StripResult stitch_strip(const SampledSlice& a, const SampledSlice& b, const ComponentLinks& links,
                         VertexStore& store) {
  if (b.critical() && !a.critical()) return walk_critical(a, b, true, links, store);
  if (a.critical() && !b.critical()) return walk_critical(b, a, false, links, store);
  return Aligner(a, b, store).run(links);
}

}  // namespace cslice::mesh_detail
