// The contact surface of a sliced space as triangles (paper section 2.5): the driver.
//
// Each stored slice is sampled once (mesh_sample.cpp); the strip between consecutive slices
// (the last wraps to the first, across theta = pi) is stitched from the space's topology and
// the pieces' labels (mesh_stitch.cpp) and tiled (mesh_tile.cpp). With the pair at hand, each
// strip is checked halfway between its slices against the true slice computed there, and
// split by that slice while it strays further than the tolerances (docs/mesh.md derives the
// bound this gives on the enclosed volume). The wrap strip is built up to the first slice
// + 2 pi and cut at pi (mesh_cut.cpp), and a partial reconstruction clips the result exactly.
#include "cslice/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <unordered_set>

#include "mesh/mesh_internal.hpp"

namespace cslice {

using namespace mesh_detail;

namespace {

// A first slice closer than this to -pi is at -pi (radians): far below any slice spacing.
constexpr double kSeamSlack = 1e-12;
// Halvings of one strip at most; the side-slice angle stops them long before in practice.
constexpr int kMaxRefinement = 16;

void add(MeshStats& a, const MeshStats& b) {
  a.strips += b.strips;
  a.matched_cycles += b.matched_cycles;
  a.matched_pieces += b.matched_pieces;
  a.unmatched_pieces += b.unmatched_pieces;
  a.coned_cycles += b.coned_cycles;
  a.unanchored_cycles += b.unanchored_cycles;
  a.collapsed_to_point += b.collapsed_to_point;
  a.collapsed_to_curve += b.collapsed_to_curve;
  a.branched_cycles += b.branched_cycles;
  a.capped_cycles += b.capped_cycles;
  a.cancelled_sheets += b.cancelled_sheets;
  a.degenerate_joins += b.degenerate_joins;
  a.straight_joins += b.straight_joins;
  a.lens_joins += b.lens_joins;
  a.refined_slices += b.refined_slices;
  a.unconverged_strips += b.unconverged_strips;
  a.max_deviation = std::max(a.max_deviation, b.max_deviation);
  a.triangles_cut += b.triangles_cut;
  a.triangles_outside += b.triangles_outside;
}

// Stitching that fell back on a guess: a refinement must not add any.
int guesses(const MeshStats& s) {
  return s.coned_cycles + s.unanchored_cycles + s.straight_joins;
}

// The true contact curves of a slice by label, to measure a strip against.
class CurveIndex {
 public:
  explicit CurveIndex(const Slice& s) {
    const auto put = [&](int segment, const Curve& c) {
      const ContactSegment& seg = s.contact_segments.at(segment);
      by_label_[{seg.moving_feature, seg.fixed_feature}].push_back(c);
      all_.push_back(c);
    };
    for (const FreeComponent& comp : s.free_components)
      for (const auto& cycle : comp.boundary)
        for (const ContactPiece& p : cycle) put(p.segment, p.curve);
    for (const DegenerateContact& d : s.degenerate)
      for (int segment : d.segments) put(segment, d.curve);
  }

  // Distance from p to the curves of the given labels, or to every curve when that is more
  // than `enough` (a corner's labels may miss the piece it lies nearest at a pinch).
  double distance(Vec2 p, std::initializer_list<SegmentLabel> labels, double enough) const {
    double best = std::numeric_limits<double>::infinity();
    for (const SegmentLabel& l : labels) {
      const auto it = by_label_.find(l);
      if (it == by_label_.end()) continue;
      for (const Curve& c : it->second) best = std::min(best, distance_to_curve(c, p));
    }
    if (best <= enough) return best;
    for (const Curve& c : all_) best = std::min(best, distance_to_curve(c, p));
    return best;
  }

 private:
  std::map<SegmentLabel, std::vector<Curve>> by_label_;
  std::vector<Curve> all_;
};

class MeshBuilder {
 public:
  MeshBuilder(const SlicedSpace& space, const MeshOptions& options, const Pair* pair)
      : space_(space),
        options_(options),
        pair_(pair),
        store_(mesh_.vertices),
        sampled_(space.slices.size()) {
    mesh_.chord_tolerance = options.chord_tolerance;
    mesh_.interpolation_tolerance = options.interpolation_tolerance;
    for (size_t k = 0; k < space.topology.transitions.size(); ++k)
      transition_of_critical_[space.topology.transitions[k].critical] = static_cast<int>(k);
    const double critical_angle =
        pair ? pair->tol.critical_angle : kCriticalityPerGeometric * kRelativeGeometricEpsilon;
    theta_snap_ = kMeshPlaneSnapPerTolerance * critical_angle;
    if (pair) {
      min_step_ = side_slice_angle(pair->tol);
      slicer_.emplace(*pair);
    }
  }

  ContactMesh build() {
    const int n = static_cast<int>(space_.slices.size());
    if (n < 2) return std::move(mesh_);
    xy_snap_ = kMeshPlaneSnapPerTolerance * space_.slices[0].slice.epsilon;
    std::vector<Triangle> triangles;
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      if (!strip_wanted(i, j)) continue;
      const SampledSlice& a = stored(i);
      const SampledSlice& b = j == 0 ? first_copy() : stored(j);
      StripMesh strip = stitch(a, b, 0);
      triangles.insert(triangles.end(), strip.triangles.begin(), strip.triangles.end());
      add(mesh_.stats, strip.stats);
      ++mesh_.stats.strips;
    }
    mesh_.triangles = std::move(triangles);
    original_.resize(mesh_.vertices.size(), -1);
    cut_seam(mesh_, original_, theta_snap_);
    const bool whole =
        options_.box.empty() && options_.theta_from <= -kPi && options_.theta_to >= kPi;
    if (!whole) clip(mesh_, options_, theta_snap_, xy_snap_);
    compact(mesh_);
    return std::move(mesh_);
  }

 private:
  struct StripMesh {
    std::vector<Triangle> triangles;
    MeshStats stats;
  };

  const SlicedSpace& space_;
  const MeshOptions& options_;
  const Pair* pair_;
  std::optional<Slicer> slicer_;  // with the pair: the true slices that check the strips
  ContactMesh mesh_;
  VertexStore store_;
  std::vector<std::optional<SampledSlice>> sampled_;
  std::pair<int, int> first_range_;  // the first slice's sampled vertices: first, count
  std::optional<SampledSlice> first_copy_;
  std::vector<int> original_;  // per vertex: the first slice's vertex it copies, or -1
  std::map<int, int> transition_of_critical_;
  std::deque<Slice> refined_;  // slices computed in between (stable addresses)
  double theta_snap_ = 0.0, xy_snap_ = 0.0, min_step_ = 0.0;

  bool strip_wanted(int i, int j) const {
    const double a = space_.slices[i].theta, b = space_.slices[j].theta;
    const double from = options_.theta_from, to = options_.theta_to;
    const auto meets = [&](double lo, double hi) {
      if (from <= to) return hi >= from && lo <= to;
      return hi >= from || lo <= to;
    };
    return j == 0 ? meets(a, kPi) || meets(-kPi, b) : meets(a, b);
  }

  // ---- Slices ----------------------------------------------------------------------------

  double gap_after(int s) const {
    const int n = static_cast<int>(space_.slices.size());
    const double d = space_.slices[(s + 1) % n].theta - space_.slices[s].theta;
    return s + 1 == n ? d + kTwoPi : d;
  }

  SamplingOptions sampling(double widest_gap) const {
    // A chord of a turning line twists by its length times the step, and a triangle on it
    // strays from the ruled surface by a quarter of that: chords of 4 tol / step keep it
    // within the interpolation tolerance (docs/mesh.md).
    return {mesh_.chord_tolerance, 4.0 * mesh_.interpolation_tolerance / widest_gap};
  }

  SampledSlice sample_stored(int s, double theta) {
    const int n = static_cast<int>(space_.slices.size());
    SamplingOptions o = sampling(std::max(gap_after(s), gap_after((s + n - 1) % n)));
    o.weld_across_cycles = space_.slices[s].kind == SliceKind::critical;
    SampledSlice out = sample_slice(space_.slices[s].slice, theta, o, store_);
    out.transition = transition_at(s);
    if (out.transition) find_coinciding_labels(out);
    const auto& topo = space_.topology;
    const size_t comps = out.cycles.size();
    out.cells =
        s < static_cast<int>(topo.slice_cells.size()) ? topo.slice_cells[s] : std::vector<int>{};
    out.components = s < static_cast<int>(topo.slice_components.size()) ? topo.slice_components[s]
                                                                        : std::vector<int>{};
    out.cells.resize(comps, -1);
    out.components.resize(comps, -1);
    return out;
  }

  const SampledSlice& stored(int s) {
    if (!sampled_[s]) {
      const int first = static_cast<int>(mesh_.vertices.size());
      // A first slice within the slack of -pi lies on the seam: exactly there.
      const double theta = space_.slices[s].theta;
      sampled_[s] = sample_stored(s, s == 0 && theta <= -kPi + kSeamSlack ? -kPi : theta);
      if (s == 0) first_range_ = {first, static_cast<int>(mesh_.vertices.size()) - first};
    }
    return *sampled_[s];
  }

  // The first slice again, at theta + 2 pi (exactly pi when it lies at -pi), sampled alike so
  // its k-th vertex copies the first slice's k-th.
  const SampledSlice& first_copy() {
    if (first_copy_) return *first_copy_;
    stored(0);
    const double theta = space_.slices[0].theta;
    const int first = static_cast<int>(mesh_.vertices.size());
    first_copy_ = sample_stored(0, theta <= -kPi + kSeamSlack ? kPi : theta + kTwoPi);
    original_.resize(mesh_.vertices.size(), -1);
    const auto [start, count] = first_range_;
    for (int k = 0; k < count && first + k < static_cast<int>(original_.size()); ++k)
      original_[first + k] = start + k;
    return *first_copy_;
  }

  const CriticalTransition* transition_at(int s) const {
    if (space_.slices[s].kind != SliceKind::critical) return nullptr;
    const auto it = transition_of_critical_.find(space_.slices[s].interval);
    return it == transition_of_critical_.end() ? nullptr : &space_.topology.transitions[it->second];
  }

  // The slice `truth` computed halfway between a and b, sampled, its components given the
  // cells of the regular one of them (by their samples, or by their boundary labels).
  SampledSlice refined(const SampledSlice& a, const SampledSlice& b, const Slice& truth) {
    const double theta = 0.5 * (a.theta + b.theta);
    SamplingOptions o = sampling(b.theta - theta);
    o.weld_across_cycles = false;  // halfway between two slices: regular
    SampledSlice out = sample_slice(truth, theta, o, store_);
    const SampledSlice& r = a.critical() ? b : a;
    for (const FreeComponent& comp : truth.free_components) {
      int k = r.slice->locate(comp.sample);
      if (k < 0) {
        const std::vector<SegmentLabel> mine = boundary_labels(truth, comp);
        for (int q = 0; q < static_cast<int>(r.cycles.size()) && k < 0; ++q)
          if (boundary_labels(*r.slice, r.slice->free_components[q]) == mine) k = q;
      }
      out.cells.push_back(k >= 0 ? r.cells[k] : -1);
      out.components.push_back(k >= 0 ? r.components[k] : -1);
    }
    return out;
  }

  // ---- Links through the topology --------------------------------------------------------

  ComponentLinks links(const SampledSlice& a, const SampledSlice& b) const {
    if (b.critical() && !a.critical()) return through(*b.transition, a, true);
    if (a.critical() && !b.critical()) return through(*a.transition, b, false);
    // Within an interval: one group per cell (or per 3D component where cells are unknown).
    ComponentLinks out;
    std::map<long, int> group;
    const auto key = [](const SampledSlice& s, int p) -> long {
      if (s.cells[p] >= 0) return s.cells[p];
      return s.components[p] >= 0 ? (1L << 40) + s.components[p] : -1;
    };
    const auto place = [&](const SampledSlice& s, int p, bool lower) {
      const long k = key(s, p);
      if (k < 0 || !group.count(k)) {
        if (k >= 0) group[k] = static_cast<int>(out.groups.size());
        out.groups.emplace_back();
      }
      auto& g = out.groups[k < 0 ? out.groups.size() - 1 : group[k]];
      (lower ? g.first : g.second).push_back(p);
    };
    for (int p = 0; p < static_cast<int>(a.cycles.size()); ++p) place(a, p, true);
    for (int q = 0; q < static_cast<int>(b.cycles.size()); ++q) place(b, q, false);
    return out;
  }

  // Across critical slice C from regular slice r: one group per event of its transition.
  static ComponentLinks through(const CriticalTransition& t, const SampledSlice& r, bool r_lower) {
    ComponentLinks out;
    std::vector<char> r_done(r.cycles.size(), 0);
    for (const TransitionEvent& e : t.events) {
      const std::vector<int>& cells = r_lower ? e.before : e.after;
      std::vector<int> mine;
      for (int p = 0; p < static_cast<int>(r.cycles.size()); ++p)
        if (std::find(cells.begin(), cells.end(), r.cells[p]) != cells.end()) {
          mine.push_back(p);
          r_done[p] = 1;
        }
      if (mine.empty() && e.critical_components.empty()) continue;
      if (r_lower)
        out.groups.push_back({mine, e.critical_components});
      else
        out.groups.push_back({e.critical_components, mine});
    }
    for (int p = 0; p < static_cast<int>(r.cycles.size()); ++p)
      if (!r_done[p])
        out.groups.push_back(r_lower ? std::make_pair(std::vector<int>{p}, std::vector<int>{})
                                     : std::make_pair(std::vector<int>{}, std::vector<int>{p}));
    return out;
  }

  // ---- Strips ----------------------------------------------------------------------------

  StripMesh stitch(const SampledSlice& a, const SampledSlice& b, int depth) {
    StripResult r = stitch_strip(a, b, links(a, b), store_);
    StripMesh out{std::move(r.triangles), r.stats};
    for (const Band& band : r.bands) tile_band(band, store_, out.triangles);
    // Sheets come from a fit's two darts, which only a critical slice has.
    for (const SampledSlice* s : {&a, &b})
      if (s->critical() && s->pieces.size() > static_cast<size_t>(s->boundary_pieces))
        out.stats.cancelled_sheets += cancel_opposite_triangles(
            out.triangles, triangles_on_two_way_edges(out.triangles, store_, s->theta));
    if (!pair_) return out;
    // The true slice halfway: kept, as a refined slice may be made of it.
    refined_.push_back(slicer_->slice(wrap_angle(0.5 * (a.theta + b.theta))));
    const Slice& truth = refined_.back();
    const double allowed = mesh_.chord_tolerance + mesh_.interpolation_tolerance;
    const double deviation = measure(out.triangles, 0.5 * (a.theta + b.theta), truth, allowed);
    out.stats.max_deviation = deviation;
    if (deviation <= allowed) return out;
    // Halves narrower than twice the side-slice angle would put a slice nearer a critical one
    // than the topology trusts slices to show their interval.
    if (depth >= kMaxRefinement || b.theta - a.theta < 2.0 * min_step_) {
      ++out.stats.unconverged_strips;
      return out;
    }
    const SampledSlice mid = refined(a, b, truth);
    StripMesh lower = stitch(a, mid, depth + 1);
    StripMesh upper = stitch(mid, b, depth + 1);
    add(lower.stats, upper.stats);
    if (guesses(lower.stats) > guesses(out.stats)) {
      ++out.stats.unconverged_strips;
      return out;
    }
    lower.triangles.insert(lower.triangles.end(), upper.triangles.begin(), upper.triangles.end());
    ++lower.stats.refined_slices;
    return lower;
  }

  // The largest distance at theta = mid (halfway between the strip's slices) of the
  // triangles' edges from the contact curves of the true slice there.
  double measure(const std::vector<Triangle>& triangles, double mid, const Slice& truth,
                 double allowed) const {
    const CurveIndex curves(truth);
    std::unordered_set<long long> seen;
    const long long n = static_cast<long long>(mesh_.vertices.size());
    double worst = 0.0;
    for (const Triangle& t : triangles)
      for (int k = 0; k < 3; ++k) {
        const int u = std::min(t[k], t[(k + 1) % 3]), w = std::max(t[k], t[(k + 1) % 3]);
        const MeshVertex &vu = mesh_.vertices[u], &vw = mesh_.vertices[w];
        if (vu.theta == vw.theta || !seen.insert(u * n + w).second) continue;
        const double f = (mid - vu.theta) / (vw.theta - vu.theta);
        const Vec2 p{vu.x + f * (vw.x - vu.x), vu.y + f * (vw.y - vu.y)};
        worst = std::max(
            worst, curves.distance(
                       p, {vu.label, store_.end_label[u], vw.label, store_.end_label[w]}, allowed));
      }
    return worst;
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

ContactMesh build_mesh(const SlicedSpace& space, MeshOptions options, const Pair* pair) {
  if (!(options.chord_tolerance > 0.0))
    options.chord_tolerance = pair ? pair->tol.contact : default_tolerance(space);
  if (!(options.interpolation_tolerance > 0.0))
    options.interpolation_tolerance = options.chord_tolerance;
  return MeshBuilder(space, options, pair).build();
}

}  // namespace

ContactMesh contact_mesh(const SlicedSpace& space, const MeshOptions& options) {
  return build_mesh(space, options, nullptr);
}

ContactMesh contact_mesh(const Pair& pair, const SlicedSpace& space, MeshOptions options) {
  return build_mesh(space, std::move(options), &pair);
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
