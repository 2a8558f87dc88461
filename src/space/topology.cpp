// The 3D topology of the sliced space (paper sections 4 and 7): free-space cells (an open
// interval between consecutive critical orientations times one free component of its
// slices), how they join across each critical slice, and the connected components of the 3D
// free space (docs/space-format.md, "topology").
//
// Cells are followed slice to slice inside an interval by locating each component's sample
// in the neighbouring slice, both ways; the slices of an interval are equivalent, so any
// failure is reported in TopologyChecks, never papered over. Across a critical orientation
// theta_k the cells are joined through two side slices at theta_k -+ delta and the critical
// slice itself (join rules in `transition` below).
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>

#include "cslice/equivalence.hpp"
#include "cslice/space.hpp"
#include "geometry/union_find.hpp"
#include "space/carry.hpp"
#include "space/space_build.hpp"

namespace cslice {

namespace {

constexpr size_t kMaxProblems = 20;  // problems kept in words; the counts keep the rest
// Halvings of a gap between two slices of an interval whose components neither the samples
// nor distinct boundary labels match: 4 shrinks the gap 16 times (the paper examples need
// none, their labels decide).
constexpr int kMaxRefinement = 4;

// for_each_index_parallel's per-thread state, for tasks that need none.
struct NoScratch {
  explicit NoScratch(const Pair*) {}
};

int component_count(const Slice& s) {
  return static_cast<int>(s.free_components.size());
}

class TopologyBuilder {
 public:
  TopologyBuilder(const Pair& pair, const SlicedSpace& space, const TopologyOptions& options,
                  const detail::KnownModels* known)
      : pair_(pair), space_(space), options_(options), known_(known) {}

  SpaceTopology build() {
    plan_intervals();
    compute_side_slices();
    build_chains();
    build_cells();
    carry_all();
    UnionFind components(static_cast<int>(topo_.cells.size()));
    for (int k = 0; k < static_cast<int>(criticals_.size()); ++k) transition(k, components);
    build_components(components);
    return std::move(topo_);
  }

 private:
  // One slice of an interval's chain: a stored slice or a side slice.
  struct Link {
    const Slice* slice = nullptr;
    int stored = -1;         // index into space.slices, or -1 for a side or refinement slice
    int first_node = 0;      // node of its component 0
    bool evaluated = false;  // a side slice evaluated from the representative's structure
  };

  void problem(const std::string& text) {
    if (topo_.checks.problems.size() < kMaxProblems) topo_.checks.problems.push_back(text);
  }

  void plan_intervals() {
    for (const CriticalOrientation& o : space_.criticals.orientations)
      criticals_.push_back(o.theta);
    starts_ = criticals_;
    if (starts_.empty()) starts_.push_back(-kPi);
    const int n = static_cast<int>(starts_.size());
    for (int i = 0; i < n; ++i)
      ends_.push_back(i + 1 < n ? starts_[i + 1] : starts_.front() + kTwoPi);
    stored_.assign(n, {});
    critical_slice_.assign(criticals_.size(), -1);
    representative_.assign(n, -1);
    for (int s = 0; s < static_cast<int>(space_.slices.size()); ++s) {
      const SpaceSlice& slice = space_.slices[s];
      if (slice.kind == SliceKind::critical && !criticals_.empty()) {
        critical_slice_.at(slice.interval) = s;
        continue;
      }
      stored_.at(slice.interval).push_back(s);
      if (slice.kind == SliceKind::interval) representative_[slice.interval] = s;
    }
    for (int i = 0; i < n; ++i)
      std::stable_sort(stored_[i].begin(), stored_[i].end(), [&](int a, int b) {
        return ccw_turn(starts_[i], space_.slices[a].theta) <
               ccw_turn(starts_[i], space_.slices[b].theta);
      });
  }

  // The side slices of each critical orientation, before and after it: the interval's
  // nearest stored slice when it lies within the side angle delta (always so for an interval
  // narrower than 2 delta, whose middle slice is then used), otherwise an extra slice at
  // theta_k -+ delta. None is computed where the component counts decide the joins (below)
  // unless options_.verify_joins. Extra ones are computed in parallel and stored by index: the
  // same whatever the thread count.
  void compute_side_slices() {
    const int n = static_cast<int>(criticals_.size());
    const double delta = side_slice_angle(pair_.tol);
    std::vector<double> thetas(2 * n);
    side_angles_.assign(2 * n, 0.0);
    has_side_.assign(2 * n, 0);
    by_count_.assign(n, 0);
    far_.assign(2 * n, 0);
    for (int k = 0; k < n; ++k) {
      const int before = (k + n - 1) % n;
      const double gap_before =
          ccw_turn(space_.slices[stored_[before].back()].theta, criticals_[k]);
      const double gap_after = ccw_turn(criticals_[k], space_.slices[stored_[k].front()].theta);
      side_angles_[2 * k] = std::min(gap_before, delta);
      side_angles_[2 * k + 1] = std::min(gap_after, delta);
      by_count_[k] = !options_.verify_joins && joins_follow_from_counts(before, k);
      const bool certify = !by_count_[k] && !options_.verify_joins;
      far_[2 * k] = certify && gap_before > delta && clears(stored_[before].back(), k, gap_before);
      far_[2 * k + 1] = certify && gap_after > delta && clears(stored_[k].front(), k, gap_after);
      has_side_[2 * k] = gap_before > delta && !by_count_[k] && !far_[2 * k];
      has_side_[2 * k + 1] = gap_after > delta && !by_count_[k] && !far_[2 * k + 1];
      thetas[2 * k] = wrap_angle(criticals_[k] - delta);
      thetas[2 * k + 1] = wrap_angle(criticals_[k] + delta);
    }
    topo_.checks.joins_by_count =
        static_cast<int>(std::count(by_count_.begin(), by_count_.end(), char{1}));
    topo_.checks.joins_by_clearance =
        static_cast<int>(std::count(far_.begin(), far_.end(), char{1}));
    sides_.resize(thetas.size());
    side_evaluated_.assign(thetas.size(), 0);
    const std::vector<const BoundaryModel*> models = side_models();
    detail::for_each_index_parallel<detail::SliceWorker>(
        pair_, thetas.size(), options_.threads, [&](size_t i, detail::SliceWorker& w) {
          if (!has_side_[i]) return;
          bool evaluated = false;
          sides_[i] = w.slice(models[side_interval(static_cast<int>(i))], thetas[i], evaluated);
          side_evaluated_[i] = evaluated;
        });
    topo_.checks.side_slices_evaluated =
        static_cast<int>(std::count(side_evaluated_.begin(), side_evaluated_.end(), char{1}));
  }

  // The interval side slice 2k (before critical orientation k) or 2k + 1 (after it) lies in.
  int side_interval(int side) const {
    const int n = static_cast<int>(criticals_.size());
    const int k = side / 2;
    return side % 2 == 0 ? (k + n - 1) % n : k;
  }

  // A slice inside an interval (a side slice, a step carrying a sample) is given by the
  // interval's boundary model, where it holds, at a fraction of the cost of computing it. None
  // when verifying joins: then each such slice is computed from scratch and checked against
  // the representative, a check of the critical orientations.
  bool models_wanted() const { return !options_.verify_joins && options_.evaluate_slices; }

  // The model the slices' computation built for the interval's representative (it had
  // intermediate slices), or null.
  const std::optional<BoundaryModel>* known_model(int interval) const {
    if (!known_) return nullptr;
    const auto& slot = (*known_)[size_t(representative_[interval])];
    return slot ? &*slot : nullptr;
  }

  // The interval's model, built on first use; null where there is none.
  const BoundaryModel* model_of(int interval) {
    if (!models_wanted() || representative_[interval] < 0) return nullptr;
    const std::optional<BoundaryModel>* model = known_model(interval);
    if (!model) {
      if (!built_models_[interval]) build_model(interval);
      model = &*built_models_[interval];
    }
    return *model ? &**model : nullptr;
  }

  // The models of these intervals not known or built yet, built in parallel; model_of then
  // only reads them, from any thread.
  void build_models(std::vector<int> intervals) {
    if (!models_wanted()) return;
    std::sort(intervals.begin(), intervals.end());
    intervals.erase(std::unique(intervals.begin(), intervals.end()), intervals.end());
    std::erase_if(intervals, [&](int i) {
      return representative_[i] < 0 || known_model(i) || built_models_[i];
    });
    detail::for_each_index_parallel<NoScratch>(
        pair_, intervals.size(), options_.threads,
        [&](size_t k, NoScratch&) { build_model(intervals[k]); });
  }

  void build_model(int interval) {
    const Slice& representative = space_.slices[representative_[interval]].slice;
    built_models_[interval].emplace(detail::checked_model(pair_, representative));
  }

  // Per interval, the model for its side slices (up to two), those not known built in
  // parallel.
  std::vector<const BoundaryModel*> side_models() {
    std::vector<const BoundaryModel*> models(starts_.size(), nullptr);
    built_models_.assign(starts_.size(), std::nullopt);
    if (!models_wanted()) return models;
    std::vector<int> wanted;
    for (int i = 0; i < static_cast<int>(has_side_.size()); ++i)
      if (has_side_[i]) wanted.push_back(side_interval(i));
    build_models(wanted);
    for (int i = 0; i < static_cast<int>(has_side_.size()); ++i)
      if (has_side_[i]) models[side_interval(i)] = model_of(side_interval(i));
    return models;
  }

  // Whether stored slice `stored`, `gap` from critical orientation k, can stand in for a side
  // slice in the sample rules of `transition`: every sample of it and of the critical slice
  // must be proved to stand for a free vertical segment between the two. Turning the moving
  // part by dtheta moves none of its points further than reach * |dtheta| (moving_reach), so
  // a configuration whose distance from blocked space exceeds reach * |theta' - theta| stays
  // free up to theta'; a sample of a free component lies at least its distance to the
  // component's boundary from blocked space. So each sample's clearance less the geometric
  // epsilon must exceed reach * gap, and a sample so proved free must be found in a component
  // of the other slice (or the numbers disagree, and a side slice decides).
  bool clears(int stored, int k, double gap) const {
    const Slice& s = space_.slices[stored].slice;
    const Slice& sc = space_.slices[critical_slice_[k]].slice;
    const auto carried = [&](const Slice& from, const Slice& to) {
      for (int c = 0; c < component_count(from); ++c)
        if (detail::sample_clearance(from, c) - from.epsilon <= reach_ * gap ||
            to.locate(from.free_components[c].sample) < 0)
          return false;
      return true;
    };
    return carried(s, sc) && carried(sc, s);
  }

  // With at most one free component in the slices of the interval before critical
  // orientation k and at most one in those after (all slices of an interval are equivalent),
  // the sample rules of `transition` can only join every free component of the critical
  // slice to the one before and the one after: a sample C of the critical slice is free with
  // its clearance, so free at theta_k -+ delta too, in the only component there. With no free
  // component at theta_k, nothing joins across. So no side slice is needed there.
  bool joins_follow_from_counts(int before, int after) const {
    const auto count = [&](int interval) {
      return component_count(space_.slices[stored_[interval].front()].slice);
    };
    return count(before) <= 1 && count(after) <= 1;
  }

  // Each interval's slices in theta order: the side slice after its starting critical
  // orientation, its stored slices, the side slice before its ending one.
  void build_chains() {
    const int n = static_cast<int>(starts_.size());
    const int crit = static_cast<int>(criticals_.size());
    chains_.assign(n, {});
    int nodes = 0;
    const auto add = [&](int i, const Slice* s, int stored, bool evaluated) {
      chains_[i].push_back({s, stored, nodes, evaluated});
      nodes += component_count(*s);
    };
    for (int i = 0; i < n; ++i) {
      const int first = 2 * i + 1, last = 2 * ((i + 1) % std::max(crit, 1));
      if (crit > 0 && has_side_[first]) add(i, &sides_[first], -1, side_evaluated_[first]);
      for (int s : stored_[i]) add(i, &space_.slices[s].slice, s, false);
      if (crit > 0 && has_side_[last]) add(i, &sides_[last], -2, side_evaluated_[last]);
    }
    nodes_ = UnionFind(nodes);
    refined_links_.assign(n, {});
    for (int i = 0; i < n; ++i) {
      const std::vector<Link>& chain = chains_[i];
      for (size_t j = 0; j + 1 < chain.size(); ++j) match(i, chain[j], chain[j + 1]);
      // With no critical orientation the one interval is the whole turn: close it at pi.
      if (crit == 0 && chain.size() > 1) match(i, chain.back(), chain.front());
      if (crit > 0 && representative_[i] >= 0)
        for (const Link& side : {chain.front(), chain.back()}) {
          // An evaluated side slice has the representative's structure by construction.
          if (side.stored >= 0 || side.evaluated) continue;
          const EquivalenceResult e =
              slices_equivalent(*side.slice, space_.slices[representative_[i]].slice);
          if (!e.equivalent) {
            topo_.checks.side_slices_not_equivalent += 1;
            problem("interval " + std::to_string(i) + ": side slice at theta " +
                    std::to_string(side.slice->theta) +
                    " not equivalent to the representative: " + e.difference);
          }
        }
    }
  }

  // Matches the components of two consecutive slices of one interval: each one's sample
  // located in the other slice, both ways, must give one bijection, and matched components
  // must have the same boundary labels. A component may move further than its own width
  // between stored slices (the cam's 0.2-wide channel turns by ~0.1 per step); then distinct
  // boundary labels decide (the slices are equivalent), and only where they cannot is the gap
  // halved with an extra slice, up to kMaxRefinement times; a gap still unmatched after that
  // is a failure.
  void match(int interval, const Link& a, const Link& b, int depth = 0) {
    const Slice &sa = *a.slice, &sb = *b.slice;
    const int na = component_count(sa), nb = component_count(sb);
    std::vector<int> forward(na), backward(nb);
    for (int c = 0; c < na; ++c) forward[c] = sb.locate(sa.free_components[c].sample);
    for (int c = 0; c < nb; ++c) backward[c] = sa.locate(sb.free_components[c].sample);
    bool ok = na == nb;
    for (int c = 0; c < na && ok; ++c) ok = forward[c] >= 0 && backward[forward[c]] == c;
    for (int c = 0; c < nb && ok; ++c) ok = backward[c] >= 0 && forward[backward[c]] == c;
    if (!ok && match_by_labels(a, b, forward, backward)) return;
    if (!ok && depth < kMaxRefinement) {
      const Link mid = refine(interval, a, b);
      match(interval, a, mid, depth + 1);
      match(interval, mid, b, depth + 1);
      return;
    }
    // Unmatched after refinement: keep what the samples say, and report it.
    for (int c = 0; c < na; ++c)
      if (forward[c] >= 0) nodes_.unite(a.first_node + c, b.first_node + forward[c]);
    for (int c = 0; c < nb; ++c)
      if (backward[c] >= 0) nodes_.unite(b.first_node + c, a.first_node + backward[c]);
    if (!ok) {
      topo_.checks.interval_match_failures += 1;
      problem("interval " + std::to_string(interval) + ": components of the slices at theta " +
              std::to_string(sa.theta) + " (" + std::to_string(na) + ") and " +
              std::to_string(sb.theta) + " (" + std::to_string(nb) +
              ") do not match one to one by their samples");
    }
    for (int c = 0; c < na; ++c) {
      const int d = forward[c];
      if (d < 0 || backward[d] != c) continue;
      if (boundary_labels(sa, sa.free_components[c]) !=
          boundary_labels(sb, sb.free_components[d])) {
        topo_.checks.boundary_label_mismatches += 1;
        problem("interval " + std::to_string(interval) + ": component " + std::to_string(c) +
                " at theta " + std::to_string(sa.theta) + " and its match " + std::to_string(d) +
                " at theta " + std::to_string(sb.theta) + " have different boundary labels");
      }
    }
  }

  // For components whose samples are not found in the neighbouring slice (a narrow slot
  // that moves further than its width, a sliver shrinking towards a critical orientation):
  // the slices are equivalent, so when every component's boundary labels are distinct
  // within each slice, equal labels give the one bijection. It must agree with every pair
  // the samples did match both ways.
  bool match_by_labels(const Link& a, const Link& b, const std::vector<int>& forward,
                       const std::vector<int>& backward) {
    const Slice &sa = *a.slice, &sb = *b.slice;
    const int na = component_count(sa), nb = component_count(sb);
    if (na != nb) return false;
    std::vector<std::pair<std::vector<SegmentLabel>, int>> la, lb;
    for (int c = 0; c < na; ++c) la.emplace_back(boundary_labels(sa, sa.free_components[c]), c);
    for (int c = 0; c < nb; ++c) lb.emplace_back(boundary_labels(sb, sb.free_components[c]), c);
    std::sort(la.begin(), la.end());
    std::sort(lb.begin(), lb.end());
    std::vector<int> partner(na, -1);
    for (int i = 0; i < na; ++i) {
      if (la[i].first != lb[i].first) return false;
      if (i + 1 < na && la[i].first == la[i + 1].first) return false;
      partner[la[i].second] = lb[i].second;
    }
    for (int c = 0; c < na; ++c)
      if (forward[c] >= 0 && backward[forward[c]] == c && partner[c] != forward[c]) return false;
    for (int c = 0; c < na; ++c) nodes_.unite(a.first_node + c, b.first_node + partner[c]);
    topo_.checks.label_matches += 1;
    return true;
  }

  // An extra slice halfway from a to b (forward, across pi if need be), with its own nodes.
  Link refine(int interval, const Link& a, const Link& b) {
    const double theta = wrap_angle(a.slice->theta + ccw_turn(a.slice->theta, b.slice->theta) / 2);
    if (!refiner_) refiner_.emplace(pair_);
    refined_.push_back(refiner_->slice(theta));
    topo_.checks.refinement_slices += 1;
    const Link link{&refined_.back(), -1, static_cast<int>(nodes_.size())};
    for (int c = 0; c < component_count(refined_.back()); ++c) nodes_.add();
    refined_links_[interval].push_back(link);
    return link;
  }

  // Cells: the classes of matched components within each interval, numbered by interval,
  // then by component of the representative slice, then by first appearance along the chain.
  void build_cells() {
    const int n = static_cast<int>(starts_.size());
    node_cell_.assign(nodes_.size(), -1);
    topo_.slice_cells.assign(space_.slices.size(), {});
    for (int i = 0; i < n; ++i) {
      std::vector<int> order;  // chain positions: the representative first
      const double middle = (ends_[i] - starts_[i]) / 2;
      for (int j = 0; j < static_cast<int>(chains_[i].size()); ++j) order.push_back(j);
      // The representative first even where another slice is as near the middle (odd counts).
      const auto key = [&](int j) {
        return std::pair(chains_[i][j].stored != representative_[i],
                         std::abs(offset(i, j) - middle));
      };
      std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return key(x) < key(y); });
      std::vector<Link> links;  // the chain in that order, then refinements
      for (int j : order) links.push_back(chains_[i][j]);
      links.insert(links.end(), refined_links_[i].begin(), refined_links_[i].end());
      std::vector<int> root_cell(nodes_.size(), -1);
      for (const Link& link : links) {
        for (int c = 0; c < component_count(*link.slice); ++c) {
          const int root = nodes_.find(link.first_node + c);
          if (root_cell[root] < 0) root_cell[root] = new_cell(i, *link.slice, c);
          const int cell = root_cell[root];
          node_cell_[link.first_node + c] = cell;
          // Areas over the stored slices only: the side and refinement slices computed depend
          // on options_.verify_joins, the result must not.
          if (link.stored >= 0) add_area(topo_.cells[cell], link.slice->free_components[c]);
        }
      }
      for (const Link& link : chains_[i]) {
        if (link.stored < 0) continue;
        std::vector<int>& cells = topo_.slice_cells[link.stored];
        for (int c = 0; c < component_count(*link.slice); ++c)
          cells.push_back(node_cell_[link.first_node + c]);
      }
    }
  }

  double offset(int interval, int position) const {
    return ccw_turn(starts_[interval], chains_[interval][position].slice->theta);
  }

  int new_cell(int interval, const Slice& s, int component) {
    SpaceCell cell;
    cell.id = static_cast<int>(topo_.cells.size());
    cell.interval = interval;
    cell.theta_from = starts_[interval];
    cell.theta_to = ends_[interval];
    cell.sample_theta = s.theta;
    cell.sample = s.free_components[component].sample;
    cell.min_area = std::numeric_limits<double>::infinity();
    cell.max_area = -std::numeric_limits<double>::infinity();
    topo_.cells.push_back(cell);
    return cell.id;
  }

  static void add_area(SpaceCell& cell, const FreeComponent& c) {
    if (!c.bounded || !cell.bounded) {
      cell.bounded = false;
      cell.min_area = cell.max_area = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    cell.min_area = std::min(cell.min_area, c.area);
    cell.max_area = std::max(cell.max_area, c.area);
  }

  // Joins across critical orientation k, from the interval before (ending at the side slice
  // at theta_k - delta) to the interval after (starting at theta_k + delta). With A a
  // component of the slice before, B of the slice after and C of the critical slice, and a
  // sample "in" a component when Slice::locate puts it there:
  //   A ~ C when A's sample is in C, or C's sample is in A at theta_k - delta;
  //   B ~ C likewise at theta_k + delta;
  //   A ~ B when A's sample is in B and also free at theta_k (in some C), or B's sample is
  //   in A and free at theta_k.
  // A sample free at both sides and at theta_k itself marks a free vertical segment (up to a
  // motion of reach * delta, far below the samples' clearance); requiring theta_k as well
  // keeps a component pinched to a point at theta_k (a perfect fit) from being joined
  // across it. The classes of ~ are the events; their cells are one 3D component.
  void transition(int k, UnionFind& components) {
    const int n = static_cast<int>(criticals_.size());
    const int before = (k + n - 1) % n, after = k;
    const Link &lb = chains_[before].back(), &la = chains_[after].front();
    const Slice &sb = *lb.slice, &sa = *la.slice;
    const Slice& sc = space_.slices.at(critical_slice_[k]).slice;
    const int nb = component_count(sb), na = component_count(sa), nc = component_count(sc);
    // Elements: before components [0, nb), after [nb, nb + na), critical [nb + na, ...).
    UnionFind local(nb + na + nc);
    const int B0 = nb, C0 = nb + na;
    if (by_count_[k]) {
      // At most one component on each side (joins_follow_from_counts): with free space at
      // theta_k, all one event; without, nothing joins.
      if (nc > 0)
        for (int x = 1; x < nb + na + nc; ++x) local.unite(0, x);
    } else {
      join_by_samples(sb, sa, sc, far_[2 * k], far_[2 * k + 1], local);
      join_carried(carries_[2 * k], 0, C0, local);
      join_carried(carries_[2 * k + 1], B0, C0, local);
    }
    // Components of one cell are one (they differ only after a reported match failure).
    for (int x = 0; x < nb; ++x)
      for (int y = x + 1; y < nb; ++y)
        if (cell_of(lb, x) == cell_of(lb, y)) local.unite(x, y);
    for (int x = 0; x < na; ++x)
      for (int y = x + 1; y < na; ++y)
        if (cell_of(la, x) == cell_of(la, y)) local.unite(B0 + x, B0 + y);

    CriticalTransition t;
    t.critical = k;
    t.theta = criticals_[k];
    t.interval_before = before;
    t.interval_after = after;
    t.side_before = side_angles_[2 * k];
    t.side_after = side_angles_[2 * k + 1];
    std::vector<int> event_of(nb + na + nc, -1);
    for (int x = 0; x < nb + na + nc; ++x) {
      const int root = local.find(x);
      if (event_of[root] < 0) {
        event_of[root] = static_cast<int>(t.events.size());
        t.events.emplace_back();
      }
      TransitionEvent& e = t.events[event_of[root]];
      if (x < B0)
        e.before.push_back(cell_of(lb, x));
      else if (x < C0)
        e.after.push_back(cell_of(la, x - B0));
      else
        e.critical_components.push_back(x - C0);
    }
    critical_event_.emplace_back(nc, -1);
    std::vector<TransitionEvent> events;
    for (TransitionEvent& e : t.events) {
      for (auto* v : {&e.before, &e.after}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
      }
      if (e.before.empty() && e.after.empty()) {
        t.orphan_critical_components += static_cast<int>(e.critical_components.size());
        problem("critical orientation " + std::to_string(k) + " (theta " + std::to_string(t.theta) +
                "): a free component of its slice reaches no cell");
        continue;
      }
      e.kind = classify_event(e);
      for (int before_cell : e.before)
        for (int after_cell : e.after) t.joins.emplace_back(before_cell, after_cell);
      const std::vector<int>& any = e.before.empty() ? e.after : e.before;
      for (int cell : e.before) components.unite(cell, any.front());
      for (int cell : e.after) components.unite(cell, any.front());
      for (int c : e.critical_components) critical_event_.back()[c] = any.front();
      events.push_back(std::move(e));
    }
    const auto smallest = [](const TransitionEvent& e) {
      const int b = e.before.empty() ? std::numeric_limits<int>::max() : e.before.front();
      const int a = e.after.empty() ? std::numeric_limits<int>::max() : e.after.front();
      return std::min(a, b);
    };
    std::stable_sort(events.begin(), events.end(),
                     [&](const auto& x, const auto& y) { return smallest(x) < smallest(y); });
    t.events = std::move(events);
    std::sort(t.joins.begin(), t.joins.end());
    topo_.checks.orphan_critical_components += t.orphan_critical_components;
    topo_.transitions.push_back(std::move(t));
  }

  // The sample rules of `transition`, with components numbered as there. A far side is a
  // stored slice that `clears` proved for its own samples and the critical slice's: a sample
  // of the other side is not looked up in it (nothing proves its segment reaches that far).
  static void join_by_samples(const Slice& sb, const Slice& sa, const Slice& sc, bool far_before,
                              bool far_after, UnionFind& local) {
    const int nb = component_count(sb), na = component_count(sa);
    const int B0 = nb, C0 = nb + na;
    for (int a = 0; a < nb; ++a) {
      const Vec2 p = sb.free_components[a].sample;
      const int c = sc.locate(p), b = far_after ? -1 : sa.locate(p);
      if (c >= 0) local.unite(a, C0 + c);
      if (c >= 0 && b >= 0) local.unite(a, B0 + b);
    }
    for (int b = 0; b < na; ++b) {
      const Vec2 p = sa.free_components[b].sample;
      const int c = sc.locate(p), a = far_before ? -1 : sb.locate(p);
      if (c >= 0) local.unite(B0 + b, C0 + c);
      if (c >= 0 && a >= 0) local.unite(B0 + b, a);
    }
    for (int c = 0; c < component_count(sc); ++c) {
      const Vec2 p = sc.free_components[c].sample;
      const int a = sb.locate(p), b = sa.locate(p);
      if (a >= 0) local.unite(C0 + c, a);
      if (b >= 0) local.unite(C0 + c, B0 + b);
    }
  }

  // Joins the sample rules miss. A sample marks a free vertical segment only while its
  // clearance exceeds the reach times the gap, and a sliver of free space can be thinner than
  // that even at a side slice (cavity pairs: a triangle split off at a tangency, 0.06 long and
  // 5e-4 thick, shrank to a third within 7e-4 rad, off its own sample; stress seed 100167: a
  // lobe of 2e-7 merged through a pinch and left its sample behind). A component of the
  // critical slice has area, so it continues on both sides: each whose sample is not proved
  // to stand for a free segment to side slice s is carried across (carry.hpp) and joined where it
  // lands. Elements numbered as in `transition`: s's from `base`, the critical slice's from
  // `c0`.
  void join_carried(const std::vector<detail::CarriedSample>& carried, int base, int c0,
                    UnionFind& local) {
    for (const detail::CarriedSample& k : carried) {
      if (k.landed < 0 || local.find(c0 + k.component) == local.find(base + k.landed)) continue;
      local.unite(c0 + k.component, base + k.landed);
      ++topo_.checks.joins_by_carrying;
    }
  }

  // The carries of every transition the counts do not decide, before the transitions join
  // anything, in parallel: carries_[2k] from critical slice k to the side slice before it,
  // [2k + 1] to the one after.
  void carry_all() {
    const int n = static_cast<int>(criticals_.size());
    carries_.assign(2 * size_t(n), {});
    std::vector<int> intervals;  // whose models the carries need
    std::vector<double> clearances;
    for (int k = 0; k < n; ++k) {
      if (by_count_[k]) continue;
      const Slice& sc = space_.slices.at(critical_slice_[k]).slice;
      clearances.clear();
      for (int c = 0; c < component_count(sc); ++c)
        clearances.push_back(detail::sample_clearance(sc, c));
      for (const int i : {2 * k, 2 * k + 1}) {
        const double motion = reach_ * std::fabs(wrap_angle(side_of(i).theta - sc.theta));
        for (int c = 0; c < component_count(sc); ++c)
          if (clearances[c] - sc.epsilon <= motion)  // else its sample rule holds
            carries_[i].push_back({c, sc.free_components[c].sample, clearances[c]});
        if (!carries_[i].empty()) intervals.push_back(side_interval(i));
      }
    }
    build_models(intervals);
    std::vector<std::pair<int, int>> counts(carries_.size(), {0, 0});
    detail::for_each_index_parallel<detail::SliceWorker>(
        pair_, carries_.size(), options_.threads, [&](size_t i, detail::SliceWorker& w) {
          if (carries_[i].empty()) return;
          const int side = static_cast<int>(i);
          const BoundaryModel* model = model_of(side_interval(side));
          const auto slice_at = [&](double theta) {
            bool evaluated = false;
            Slice slice = w.slice(model, theta, evaluated);
            counts[i].second += evaluated ? 1 : 0;
            return slice;
          };
          counts[i].first =
              detail::carry_samples(space_.slices.at(critical_slice_[side / 2]).slice, carries_[i],
                                    side_of(side), reach_, pair_.tol.angular, slice_at);
        });
    for (const auto& [slices, evaluated] : counts) {
      topo_.checks.carry_slices += slices;
      topo_.checks.carry_slices_evaluated += evaluated;
    }
  }

  // The slice at side 2k (before critical orientation k) or 2k + 1 (after): the last of the
  // interval before, the first of the one after.
  const Slice& side_of(int side) const {
    const int n = static_cast<int>(criticals_.size()), k = side / 2;
    return side % 2 == 0 ? *chains_[(k + n - 1) % n].back().slice : *chains_[k].front().slice;
  }

  int cell_of(const Link& link, int component) const {
    return node_cell_[link.first_node + component];
  }

  static TransitionKind classify_event(const TransitionEvent& e) {
    const size_t b = e.before.size(), a = e.after.size();
    if (b == 0) return TransitionKind::appear;
    if (a == 0) return TransitionKind::vanish;
    if (b == 1 && a == 1) return TransitionKind::continues;
    if (a == 1) return TransitionKind::merge;
    if (b == 1) return TransitionKind::split;
    return TransitionKind::merge_split;
  }

  void build_components(UnionFind& uf) {
    const int cells = static_cast<int>(topo_.cells.size());
    std::vector<int> id_of_root(cells, -1);
    for (int c = 0; c < cells; ++c) {
      const int root = uf.find(c);
      if (id_of_root[root] < 0) {
        id_of_root[root] = static_cast<int>(topo_.components.size());
        topo_.components.emplace_back();
        topo_.components.back().id = id_of_root[root];
      }
      topo_.cells[c].component = id_of_root[root];
      topo_.components[id_of_root[root]].cells.push_back(c);
    }
    topo_.slice_components.assign(space_.slices.size(), {});
    for (size_t s = 0; s < space_.slices.size(); ++s)
      for (int cell : topo_.slice_cells[s])
        topo_.slice_components[s].push_back(cell < 0 ? -1 : topo_.cells[cell].component);
    for (size_t k = 0; k < criticals_.size(); ++k) {
      std::vector<int>& comps = topo_.slice_components.at(critical_slice_[k]);
      topo_.slice_cells.at(critical_slice_[k]).assign(critical_event_[k].size(), -1);
      for (int cell : critical_event_[k])
        comps.push_back(cell < 0 ? -1 : topo_.cells[cell].component);
    }
    for (SpaceComponent& comp : topo_.components) coverage(comp);
  }

  // Which intervals and critical orientations the component has free space in, as maximal
  // theta ranges.
  void coverage(SpaceComponent& comp) const {
    const int n = static_cast<int>(starts_.size());
    const int crit = static_cast<int>(criticals_.size());
    std::vector<char> interval(n, 0), critical(crit, 0);
    for (int cell : comp.cells) interval[topo_.cells[cell].interval] = 1;
    for (int k = 0; k < crit; ++k)
      for (int cell : critical_event_[k])
        if (cell >= 0 && topo_.cells[cell].component == comp.id) critical[k] = 1;
    comp.spans_all_theta =
        std::all_of(interval.begin(), interval.end(), [](char c) { return c; }) &&
        std::all_of(critical.begin(), critical.end(), [](char c) { return c; });
    if (comp.spans_all_theta) {
      comp.theta_ranges = {{-kPi, kPi}};
      return;
    }
    // Interval i continues into i + 1 when both are covered and so is critical i + 1.
    const auto joined = [&](int i) {
      const int next = (i + 1) % n;
      return crit > 0 && interval[i] && interval[next] && critical[next];
    };
    int first = -1;  // an interval that starts a run
    for (int i = 0; i < n && first < 0; ++i)
      if (interval[i] && !joined((i + n - 1) % n)) first = i;
    if (first < 0) return;  // cannot happen: not spanning, so some run has a start
    for (int step = 0; step < n; ++step) {
      const int i = (first + step) % n;
      if (!interval[i] || (step > 0 && joined((i + n - 1) % n))) continue;
      int j = i;
      while (joined(j)) j = (j + 1) % n;
      const double from = starts_[i];
      const double to = from + ccw_turn(starts_[i], starts_[j]) + (ends_[j] - starts_[j]);
      comp.theta_ranges.emplace_back(from, to);
    }
  }

  const Pair& pair_;
  const SlicedSpace& space_;
  TopologyOptions options_;
  const detail::KnownModels* known_;  // models built with the slices, or null
  detail::KnownModels built_models_;  // per interval: those built here (empty: not tried)
  std::vector<double> criticals_, starts_, ends_, side_angles_;
  std::vector<char> has_side_;  // 2k: an extra slice before critical k; 2k + 1: after it
  std::vector<char> by_count_;  // per critical: joined by joins_follow_from_counts
  std::vector<char> far_;       // 2k, 2k + 1: that side's stored slice stands in (clears)
  double reach_ = moving_reach(pair_.moving);
  std::vector<std::vector<detail::CarriedSample>>
      carries_;                           // per side of each critical orientation
  std::vector<std::vector<int>> stored_;  // per interval: its non-critical slices, by theta
  std::vector<int> critical_slice_, representative_;
  std::vector<Slice> sides_;          // 2k: before critical k, 2k + 1: after it
  std::vector<char> side_evaluated_;  // per side: evaluated from its interval's model
  std::vector<std::vector<Link>> chains_;
  std::deque<Slice> refined_;      // extra slices halving unmatched gaps (stable addresses)
  std::optional<Slicer> refiner_;  // computes them, built on first use
  std::vector<std::vector<Link>> refined_links_;  // per interval
  UnionFind nodes_;
  std::vector<int> node_cell_;
  std::vector<std::vector<int>> critical_event_;  // per critical slice component: a cell
  SpaceTopology topo_;
};

}  // namespace

std::string_view to_string(TransitionKind k) {
  switch (k) {
    case TransitionKind::continues:
      return "continue";
    case TransitionKind::merge:
      return "merge";
    case TransitionKind::split:
      return "split";
    case TransitionKind::merge_split:
      return "merge_split";
    case TransitionKind::appear:
      return "appear";
    case TransitionKind::vanish:
      return "vanish";
  }
  return "unknown";
}

// delta = sqrt(kSideSliceAngleSquaredPerAngular * angular) (tolerance.hpp: at a tangency
// the curves are then a criticality tolerance apart, so the side slice shows the interval's
// topology, not the critical one), about 1e-3 rad: small enough that no point of a contact
// curve moves more than reach * delta (about a thousandth of the pair's size) between a side
// slice and the critical one, far below the clearance of a component's sample. Far above the
// critical angle (1e3 angular tolerances), within which criticalities are one orientation.
double side_slice_angle(const Tolerances& tol) {
  return std::sqrt(kSideSliceAngleSquaredPerAngular * tol.angular);
}

SpaceTopology compute_topology(const Pair& pair, const SlicedSpace& space,
                               const TopologyOptions& options) {
  return TopologyBuilder(pair, space, options, nullptr).build();
}

SpaceTopology detail::compute_topology(const Pair& pair, const SlicedSpace& space,
                                       const TopologyOptions& options, const KnownModels* known) {
  return TopologyBuilder(pair, space, options, known).build();
}

std::vector<SegmentLabel> boundary_labels(const Slice& s, const FreeComponent& c) {
  size_t pieces = 0;
  for (const auto& cycle : c.boundary) pieces += cycle.size();
  std::vector<SegmentLabel> out;
  out.reserve(pieces);  // one allocation: the topology compares these for every matched pair
  for (const auto& cycle : c.boundary)
    for (const ContactPiece& piece : cycle) {
      const ContactSegment& seg = s.contact_segments.at(piece.segment);
      out.push_back({seg.moving_feature, seg.fixed_feature});
    }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace cslice
