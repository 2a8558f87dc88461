// The contact surface of a sliced space as triangles (paper section 2.5).
//
// Construction. The free-space boundary of a slice is a set of cycles of realizable pieces
// (FreeComponent::boundary), each labelled by the feature pair of its contact segment. Each
// piece of each stored slice is sampled once into a polyline: a line segment by its ends, an
// arc by equal parameter steps, enough that the sagitta of every chord stays within the chord
// tolerance. Consecutive pieces of a cycle share their corner vertex, and the strips below and
// above a slice use the same vertices, so the mesh has no T-junctions.
//
// Between consecutive slices i and j (by theta; the last slice wraps to the first across
// theta = pi = -pi):
//  1. Components are linked by the space's topology, never by position: within an interval,
//     by their cell (SpaceTopology::slice_cells); to or from a critical slice, by the events of
//     its CriticalTransition (a cell before or after and a component of the critical slice in
//     one event).
//  2. The cycles of linked components are paired by their labels: each candidate pair is
//     scored by the longest cyclic common subsequence of the two label sequences, and pairs
//     are taken greedily by score. Within an interval the two sequences are one rotation of
//     each other, so the match is exact; only when a sequence is periodic (the same labels
//     repeat around a cycle) does position choose among the label-equal rotations (smallest
//     total distance between matched pieces).
//  3. Matched pieces (same label, in cyclic order) are stitched by a strip of triangles. The
//     pieces between two consecutive matched pieces (a piece vanishing at, or appearing from,
//     a critical slice, whose partner has degenerated to the corner where its neighbours
//     meet) are stitched as one strip between their polylines; when one side has no piece the
//     strip is a fan to that corner. A strip between polylines of n and m chords has n + m
//     triangles, chosen greedily by arc-length fraction (the classic contour tiling), so two
//     sides sampled differently (an arc flattening towards a critical slice) still tile.
//  4. A cycle with no partner (a component or hole appearing or vanishing at a critical slice,
//     or the extra cycle of a branching) is closed by a cone from its polyline to the centroid
//     of its vertices at the other slice's theta: the patch ends at that slice. A cycle paired
//     with a cycle of no common label (possible only across a critical slice) is aligned by
//     the nearest start points (stats.unanchored_cycles).
//
// The strip from the last slice to the first is cut at theta = pi: vertices of the first slice
// are seen at theta + 2 pi, triangles crossing pi are split at the plane, and the cut vertices
// appear twice, at pi and at -pi (ContactMesh::seam). When the first slice is at -pi itself its
// vertices are duplicated at pi instead.
//
// Limits. Branching (a merge or split of components or holes at a critical slice) is closed
// by cones rather than tiled through the critical slice, so the surface is closed but not
// exact there; a cone over a non-convex cycle can intersect the surface nearby. Degenerate
// contacts (perfect and sliding fits) carry no free volume and are not meshed. Partial
// reconstruction stitches only the strips whose theta span meets the range and keeps the
// triangles whose three vertices lie inside; it does not clip triangles at the range or box.
#include "cslice/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>

namespace cslice {

namespace {

// Largest turn of one chord of a sampled arc (radians), whatever the tolerance: a quarter
// turn, so that even a coarse tolerance keeps a full circle a square, not a segment.
constexpr double kMaxChordTurn = kPi / 2;
// Cap on the chords of one piece, against absurd tolerances.
constexpr int kMaxChords = 100000;

// One boundary cycle of a slice, sampled.
struct Cycle {
  std::vector<int> verts;            // closed: the last vertex is followed by the first
  std::vector<int> piece_start;      // per piece: offset into verts of its first vertex
  std::vector<int> piece_chords;     // per piece: its chords (0 for a piece shorter than eps)
  std::vector<SegmentLabel> labels;  // per piece
  int piece_count() const { return static_cast<int>(labels.size()); }
};

struct SampledSlice {
  std::vector<std::vector<Cycle>> components;  // per free component, per boundary cycle
};

int chords_for(const Curve& c, double tol, double eps) {
  if (curve_length(c) <= eps) return 0;
  if (c.is_segment()) return 1;
  double turn = kMaxChordTurn;  // sagitta r (1 - cos(turn / 2)) <= tol
  if (tol < c.radius) turn = std::min(turn, 2.0 * std::acos(1.0 - tol / c.radius));
  const double n = std::ceil(std::fabs(c.sweep) / turn);
  return static_cast<int>(std::clamp(n, 1.0, static_cast<double>(kMaxChords)));
}

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

bool in_range(double theta, double from, double to) {
  return from <= to ? theta >= from && theta <= to : theta >= from || theta <= to;
}

class MeshBuilder {
 public:
  MeshBuilder(const SlicedSpace& space, const MeshOptions& options, double tol)
      : space_(space), options_(options), sampled_(space.slices.size()) {
    mesh_.chord_tolerance = tol;
    for (size_t k = 0; k < space.topology.transitions.size(); ++k)
      transition_of_critical_[space.topology.transitions[k].critical] = static_cast<int>(k);
  }

  ContactMesh build() {
    const int n = static_cast<int>(space_.slices.size());
    if (n < 2) return std::move(mesh_);
    cut_mode_ = space_.slices[0].theta > -kPi + kSeamSlack;
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      wrap_ = j == 0;
      if (!strip_wanted(i, j)) continue;
      stitch(i, j);
      ++mesh_.stats.strips;
    }
    filter();
    return std::move(mesh_);
  }

 private:
  // Two slices closer than this to -pi are at -pi (radians): far below any slice spacing.
  static constexpr double kSeamSlack = 1e-12;

  const SlicedSpace& space_;
  const MeshOptions& options_;
  ContactMesh mesh_;
  std::vector<int> vertex_slice_;  // per vertex: its slice (-1 for seam vertices)
  std::vector<std::optional<SampledSlice>> sampled_;
  std::map<int, int> transition_of_critical_;
  bool wrap_ = false, cut_mode_ = true;
  std::map<std::pair<int, int>, std::pair<int, int>> cuts_;  // edge -> (at pi, at -pi)
  std::map<int, int> dups_;                                  // vertex -> its copy at pi

  int add_vertex(Vec2 p, double theta, SegmentLabel label, int slice) {
    mesh_.vertices.push_back({p.x, p.y, theta, label});
    vertex_slice_.push_back(slice);
    return static_cast<int>(mesh_.vertices.size()) - 1;
  }
  Vec2 xy(int v) const { return {mesh_.vertices[v].x, mesh_.vertices[v].y}; }

  bool strip_wanted(int i, int j) const {
    const double a = space_.slices[i].theta, b = space_.slices[j].theta;
    const double from = options_.theta_from, to = options_.theta_to;
    const auto meets = [&](double lo, double hi) {
      if (from <= to) return hi >= from && lo <= to;
      return hi >= from || lo <= to;
    };
    return wrap_ ? meets(a, kPi) || meets(-kPi, b) : meets(a, b);
  }

  const SampledSlice& sampled(int s) {
    if (!sampled_[s]) sampled_[s] = sample(s);
    return *sampled_[s];
  }

  SampledSlice sample(int s) {
    const Slice& slice = space_.slices[s].slice;
    const double theta = space_.slices[s].theta;
    SampledSlice out;
    for (const FreeComponent& comp : slice.free_components) {
      out.components.emplace_back();
      for (const auto& pieces : comp.boundary) {
        Cycle c;
        for (const ContactPiece& piece : pieces) {
          const ContactSegment& seg = slice.contact_segments.at(piece.segment);
          const SegmentLabel label{seg.moving_feature, seg.fixed_feature};
          const int chords = chords_for(piece.curve, mesh_.chord_tolerance, slice.epsilon);
          c.piece_start.push_back(static_cast<int>(c.verts.size()));
          c.piece_chords.push_back(chords);
          c.labels.push_back(label);
          for (int k = 0; k < chords; ++k)
            c.verts.push_back(
                add_vertex(point_at(piece.curve, double(k) / chords), theta, label, s));
        }
        if (c.verts.size() >= 2) out.components.back().push_back(std::move(c));
      }
    }
    return out;
  }

  // Vertices of `count` pieces of c from piece `first` (cyclically), both ends included.
  static std::vector<int> polyline(const Cycle& c, int first, int count) {
    const int total = static_cast<int>(c.verts.size());
    const int np = c.piece_count();
    int chords = 0;
    for (int k = 0; k < count; ++k) chords += c.piece_chords[(first + k) % np];
    std::vector<int> out;
    const int start = c.piece_start[first % np];
    for (int k = 0; k <= chords; ++k) out.push_back(c.verts[(start + k) % total]);
    return out;
  }

  // ---- Linking components through the topology ------------------------------------------

  const CriticalTransition* transition_at(int s) const {
    if (space_.slices[s].kind != SliceKind::critical) return nullptr;
    const auto it = transition_of_critical_.find(space_.slices[s].interval);
    return it == transition_of_critical_.end() ? nullptr : &space_.topology.transitions[it->second];
  }

  int cell(int s, int p) const {
    const auto& cells = space_.topology.slice_cells;
    return s < static_cast<int>(cells.size()) && p < static_cast<int>(cells[s].size()) ? cells[s][p]
                                                                                       : -1;
  }

  bool linked(int i, int p, int j, int q) const {
    const CriticalTransition* ti = transition_at(i);
    const CriticalTransition* tj = transition_at(j);
    const auto has = [](const std::vector<int>& v, int x) {
      return std::find(v.begin(), v.end(), x) != v.end();
    };
    if (tj != nullptr && ti == nullptr) {
      for (const TransitionEvent& e : tj->events)
        if (has(e.before, cell(i, p)) && has(e.critical_components, q)) return true;
      return false;
    }
    if (ti != nullptr && tj == nullptr) {
      for (const TransitionEvent& e : ti->events)
        if (has(e.critical_components, p) && has(e.after, cell(j, q))) return true;
      return false;
    }
    if (ti == nullptr && cell(i, p) >= 0 && cell(j, q) >= 0) return cell(i, p) == cell(j, q);
    // Two critical slices in a row, or cells missing: the 3D components decide.
    const auto& comps = space_.topology.slice_components;
    if (i >= static_cast<int>(comps.size()) || j >= static_cast<int>(comps.size())) return false;
    return p < static_cast<int>(comps[i].size()) && q < static_cast<int>(comps[j].size()) &&
           comps[i][p] >= 0 && comps[i][p] == comps[j][q];
  }

  // ---- Stitching -------------------------------------------------------------------------

  struct CycleRef {
    int component = 0, cycle = 0;
  };

  void stitch(int i, int j) {
    const SampledSlice& a = sampled(i);
    const SampledSlice& b = sampled(j);
    struct Candidate {
      int score = 0;
      CycleRef ca, cb;
      std::vector<std::pair<int, int>> pairs;
    };
    std::vector<Candidate> candidates;
    for (int p = 0; p < static_cast<int>(a.components.size()); ++p)
      for (int q = 0; q < static_cast<int>(b.components.size()); ++q) {
        if (!linked(i, p, j, q)) continue;
        for (int x = 0; x < static_cast<int>(a.components[p].size()); ++x)
          for (int y = 0; y < static_cast<int>(b.components[q].size()); ++y) {
            Candidate c{0, {p, x}, {q, y}, align(a.components[p][x], b.components[q][y])};
            c.score = static_cast<int>(c.pairs.size());
            candidates.push_back(std::move(c));
          }
      }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& x, const Candidate& y) { return x.score > y.score; });
    std::map<std::pair<int, int>, bool> used_a, used_b;
    for (const Candidate& c : candidates) {
      if (c.score == 0) break;
      if (used_a[{c.ca.component, c.ca.cycle}] || used_b[{c.cb.component, c.cb.cycle}]) continue;
      used_a[{c.ca.component, c.ca.cycle}] = used_b[{c.cb.component, c.cb.cycle}] = true;
      stitch_cycles(a.components[c.ca.component][c.ca.cycle],
                    b.components[c.cb.component][c.cb.cycle], c.pairs);
    }
    // A cycle left alone in each of two components linked only to each other: same patch,
    // no common label (only across a critical slice).
    for (const Candidate& c : candidates) {
      if (used_a[{c.ca.component, c.ca.cycle}] || used_b[{c.cb.component, c.cb.cycle}]) continue;
      if (free_cycles(a, c.ca.component, used_a) != 1 ||
          free_cycles(b, c.cb.component, used_b) != 1)
        continue;
      used_a[{c.ca.component, c.ca.cycle}] = used_b[{c.cb.component, c.cb.cycle}] = true;
      stitch_unanchored(a.components[c.ca.component][c.ca.cycle],
                        b.components[c.cb.component][c.cb.cycle]);
    }
    for (int p = 0; p < static_cast<int>(a.components.size()); ++p)
      for (int x = 0; x < static_cast<int>(a.components[p].size()); ++x)
        if (!used_a[{p, x}]) cone(a.components[p][x], j, true);
    for (int q = 0; q < static_cast<int>(b.components.size()); ++q)
      for (int y = 0; y < static_cast<int>(b.components[q].size()); ++y)
        if (!used_b[{q, y}]) cone(b.components[q][y], i, false);
  }

  static int free_cycles(const SampledSlice& s, int comp,
                         std::map<std::pair<int, int>, bool>& used) {
    int n = 0;
    for (int x = 0; x < static_cast<int>(s.components[comp].size()); ++x)
      n += used[{comp, x}] ? 0 : 1;
    return n;
  }

  // The best cyclic alignment of two cycles' labels: the longest common subsequence over every
  // rotation of b; among equally long ones, the smallest distance between matched starts.
  std::vector<std::pair<int, int>> align(const Cycle& a, const Cycle& b) const {
    std::vector<std::pair<int, int>> best;
    double best_cost = 0.0;
    for (int r = 0; r < b.piece_count(); ++r) {
      std::vector<std::pair<int, int>> pairs = lcs(a.labels, b.labels, r);
      if (pairs.size() < best.size() || pairs.empty()) continue;
      double cost = 0.0;
      for (auto [x, y] : pairs) cost += distance(xy(c_start(a, x)), xy(c_start(b, y)));
      if (pairs.size() > best.size() || cost < best_cost) {
        best = std::move(pairs);
        best_cost = cost;
      }
    }
    return best;
  }
  static int c_start(const Cycle& c, int piece) {
    return c.verts[c.piece_start[piece] % c.verts.size()];
  }

  void stitch_cycles(const Cycle& a, const Cycle& b, const std::vector<std::pair<int, int>>& m) {
    ++mesh_.stats.matched_cycles;
    const int k = static_cast<int>(m.size());
    const int na = a.piece_count(), nb = b.piece_count();
    for (int t = 0; t < k; ++t) {
      const auto [pa, pb] = m[t];
      const auto [qa, qb] = m[(t + 1) % k];
      strip(polyline(a, pa, 1), polyline(b, pb, 1));
      ++mesh_.stats.matched_pieces;
      const int ga = ((qa - pa - 1) % na + na) % na, gb = ((qb - pb - 1) % nb + nb) % nb;
      mesh_.stats.unmatched_pieces += ga + gb;
      strip(polyline(a, pa + 1, ga), polyline(b, pb + 1, gb));
    }
  }

  void stitch_unanchored(const Cycle& a, const Cycle& b) {
    ++mesh_.stats.matched_cycles;
    ++mesh_.stats.unanchored_cycles;
    int best = 0;
    for (int r = 1; r < b.piece_count(); ++r)
      if (distance(xy(c_start(a, 0)), xy(c_start(b, r))) <
          distance(xy(c_start(a, 0)), xy(c_start(b, best))))
        best = r;
    strip(polyline(a, 0, a.piece_count()), polyline(b, best, b.piece_count()));
  }

  // Closes a cycle of slice-side `lower` (true: the lower slice of the strip) by a cone to
  // the centroid of its vertices at slice `other`.
  void cone(const Cycle& c, int other, bool lower) {
    ++mesh_.stats.coned_cycles;
    Vec2 centroid;
    for (int v : c.verts) centroid = centroid + xy(v);
    centroid = (1.0 / static_cast<double>(c.verts.size())) * centroid;
    const int apex = add_vertex(centroid, space_.slices[other].theta, {-1, -1}, other);
    const std::vector<int> loop = polyline(c, 0, c.piece_count());
    if (lower)
      strip(loop, {apex});
    else
      strip({apex}, loop);
  }

  // Tiles the band between polyline p (lower slice) and q (upper slice), both running with
  // free space on their left: n + m triangles, advancing along whichever side is behind in
  // arc-length fraction. Normals point out of free space.
  void strip(const std::vector<int>& p, const std::vector<int>& q) {
    const std::vector<double> fp = fractions(p), fq = fractions(q);
    size_t a = 0, b = 0;
    while (a + 1 < p.size() || b + 1 < q.size()) {
      const bool advance_p = b + 1 >= q.size() || (a + 1 < p.size() && fp[a + 1] <= fq[b + 1]);
      if (advance_p) {
        emit({p[a], p[a + 1], q[b]});
        ++a;
      } else {
        emit({p[a], q[b + 1], q[b]});
        ++b;
      }
    }
  }

  std::vector<double> fractions(const std::vector<int>& line) const {
    std::vector<double> f(line.size(), 0.0);
    for (size_t k = 1; k < line.size(); ++k)
      f[k] = f[k - 1] + distance(xy(line[k - 1]), xy(line[k]));
    const double total = f.empty() ? 0.0 : f.back();
    for (size_t k = 0; k < f.size(); ++k)
      f[k] = total > 0.0 ? f[k] / total : double(k) / double(std::max<size_t>(1, f.size() - 1));
    return f;
  }

  // ---- The seam at theta = pi ------------------------------------------------------------

  bool lifted(int v) const { return wrap_ && vertex_slice_[v] == 0; }

  void emit(std::array<int, 3> t) {
    if (!wrap_) {
      mesh_.triangles.push_back(t);
      return;
    }
    if (!cut_mode_) {
      for (int& v : t)
        if (lifted(v)) v = duplicate(v);
      mesh_.triangles.push_back(t);
      return;
    }
    const int up = lifted(t[0]) + lifted(t[1]) + lifted(t[2]);
    if (up == 0 || up == 3) {
      mesh_.triangles.push_back(t);
      return;
    }
    // Rotate (keeping orientation) so the vertex alone on its side comes first.
    const bool lone_up = up == 1;
    while (lifted(t[0]) != lone_up) std::rotate(t.begin(), t.begin() + 1, t.end());
    const auto [c1_pi, c1_mpi] = cut(t[0], t[1]);
    const auto [c2_pi, c2_mpi] = cut(t[0], t[2]);
    // The lone vertex's side keeps a triangle; the other side a quad.
    const int c1_lone = lone_up ? c1_mpi : c1_pi, c2_lone = lone_up ? c2_mpi : c2_pi;
    const int c1_pair = lone_up ? c1_pi : c1_mpi, c2_pair = lone_up ? c2_pi : c2_mpi;
    mesh_.triangles.push_back({t[0], c1_lone, c2_lone});
    mesh_.triangles.push_back({c1_pair, t[1], t[2]});
    mesh_.triangles.push_back({c1_pair, t[2], c2_pair});
  }

  double lifted_theta(int v) const { return mesh_.vertices[v].theta + (lifted(v) ? kTwoPi : 0.0); }

  std::pair<int, int> cut(int u, int w) {
    const auto key = std::minmax(u, w);
    const auto it = cuts_.find(key);
    if (it != cuts_.end()) return it->second;
    const int lo = lifted(u) ? w : u, hi = lifted(u) ? u : w;
    const double t = (kPi - lifted_theta(lo)) / (lifted_theta(hi) - lifted_theta(lo));
    const Vec2 p = lerp(xy(lo), xy(hi), t);
    const SegmentLabel label = mesh_.vertices[lo].label;
    const int at_pi = add_vertex(p, kPi, label, -1), at_mpi = add_vertex(p, -kPi, label, -1);
    mesh_.seam.push_back({at_pi, at_mpi});
    return cuts_[key] = {at_pi, at_mpi};
  }

  int duplicate(int v) {
    const auto it = dups_.find(v);
    if (it != dups_.end()) return it->second;
    const int d = add_vertex(xy(v), kPi, mesh_.vertices[v].label, -1);
    mesh_.seam.push_back({d, v});
    return dups_[v] = d;
  }

  // ---- Partial reconstruction ------------------------------------------------------------

  bool inside(const MeshVertex& v) const {
    if (!in_range(v.theta, options_.theta_from, options_.theta_to)) return false;
    const Box& box = options_.box;
    return box.empty() ||
           (v.x >= box.lo.x && v.x <= box.hi.x && v.y >= box.lo.y && v.y <= box.hi.y);
  }

  void filter() {
    const bool whole =
        options_.box.empty() && options_.theta_from <= -kPi && options_.theta_to >= kPi;
    std::vector<int> used(mesh_.vertices.size(), 0);
    std::vector<std::array<int, 3>> kept;
    for (const auto& t : mesh_.triangles) {
      if (!whole && !(inside(mesh_.vertices[t[0]]) && inside(mesh_.vertices[t[1]]) &&
                      inside(mesh_.vertices[t[2]]))) {
        ++mesh_.stats.triangles_outside;
        continue;
      }
      kept.push_back(t);
      for (int v : t) used[v] = 1;
    }
    std::vector<int> index(mesh_.vertices.size(), -1);
    std::vector<MeshVertex> vertices;
    for (size_t v = 0; v < used.size(); ++v)
      if (used[v]) {
        index[v] = static_cast<int>(vertices.size());
        vertices.push_back(mesh_.vertices[v]);
      }
    for (auto& t : kept)
      for (int& v : t) v = index[v];
    std::vector<std::pair<int, int>> seam;
    for (auto [a, b] : mesh_.seam)
      if (index[a] >= 0 && index[b] >= 0) seam.push_back({index[a], index[b]});
    mesh_.vertices = std::move(vertices);
    mesh_.triangles = std::move(kept);
    mesh_.seam = std::move(seam);
  }
};

// The contact tolerance the interpolation step was derived from (interpolation_step inverted),
// or, when the step is capped, the default relative tolerance at the size of the slices.
double default_tolerance(const SlicedSpace& space) {
  if (space.reach > 0.0 && space.max_step < kPi / 2 * (1.0 - 1e-12))
    return space.reach * space.max_step * space.max_step / 8.0;
  Box box;
  for (const SpaceSlice& s : space.slices)
    for (const ContactPiece& p : s.slice.realizable) box.add(bounding_box(p.curve));
  const double size = box.empty() ? 1.0 : box.diagonal();
  return kDefaultRelativeTolerance * (size > 0.0 ? size : 1.0);
}

}  // namespace

ContactMesh contact_mesh(const SlicedSpace& space, const MeshOptions& options) {
  const double tol =
      options.chord_tolerance > 0.0 ? options.chord_tolerance : default_tolerance(space);
  return MeshBuilder(space, options, tol).build();
}

ContactMesh contact_mesh(const Pair& pair, const SlicedSpace& space, MeshOptions options) {
  if (!(options.chord_tolerance > 0.0)) options.chord_tolerance = pair.tol.contact;
  return contact_mesh(space, options);
}

double enclosed_volume(const ContactMesh& mesh) {
  double v = 0.0;
  for (const auto& t : mesh.triangles) {
    const MeshVertex &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double ux = b.x - a.x, uy = b.y - a.y, ut = b.theta - a.theta;
    const double wx = c.x - a.x, wy = c.y - a.y, wt = c.theta - a.theta;
    const double nx = uy * wt - ut * wy, ny = ut * wx - ux * wt;  // twice the area times n
    v += (nx * (a.x + b.x + c.x) + ny * (a.y + b.y + c.y)) / 12.0;
  }
  return v;
}

}  // namespace cslice
