// The sliced configuration space: which orientations get a slice, the slices themselves
// (in parallel with oneTBB), and the correspondence of contact segments between neighbours.
#include "cslice/space.hpp"

#include <atomic>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iterator>
#include <span>

#include "criticals/families.hpp"
#include "cslice/slice_io.hpp"
#include "cslice/symmetry.hpp"
#include "geometry/angle_search.hpp"
#include "slice/slice_image.hpp"
#include "space/space_build.hpp"

namespace cslice {

namespace {

using Planned = detail::PlannedSlice;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Slices in the open interval from critical orientation `a` to `b` (b > a), `step` apart at
// most: the fewest equal parts that keep that promise, and at least two so the interval has a
// slice. The representative is the inner point nearest the middle (exactly the middle for an
// even count): any inner slice represents the interval, and one slice per interval saved is
// worth more than perfect centring.
void plan_interval(double a, double b, double step, int interval, std::vector<Planned>& out) {
  const double length = b - a;
  const int m = std::max(2, static_cast<int>(std::ceil(length / step)));
  for (int k = 1; k < m; ++k) {
    const SliceKind kind = k == m / 2 ? SliceKind::interval : SliceKind::intermediate;
    out.push_back({wrap_angle(a + length * k / m), kind, interval});
  }
}

SliceCorrespondence correspond(int from, int to, std::span<const SegmentLabel> a,
                               std::span<const SegmentLabel> b) {
  SliceCorrespondence c;
  c.from = from;
  c.to = to;
  c.kept.reserve(std::min(a.size(), b.size()));  // most labels carry on: one allocation
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(c.kept));
  std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(c.appearing));
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(c.vanishing));
  return c;
}

}  // namespace

namespace detail {

// Every orientation to slice at, sorted by theta. Interval i runs from critical orientation
// i to i + 1; the last wraps to the first plus 2 pi. With no critical orientation the whole
// turn is one interval, anchored by an intermediate slice at -pi.
std::vector<Planned> plan_slices(const CriticalSet& criticals, double step) {
  std::vector<double> starts;
  for (const CriticalOrientation& o : criticals.orientations) starts.push_back(o.theta);
  const bool none = starts.empty();
  if (none) starts.push_back(-kPi);
  std::vector<Planned> out;
  const int n = static_cast<int>(starts.size());
  for (int i = 0; i < n; ++i) {
    out.push_back({starts[i], none ? SliceKind::intermediate : SliceKind::critical, i});
    const double end = i + 1 < n ? starts[i + 1] : starts.front() + kTwoPi;
    plan_interval(starts[i], end, step, i, out);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Planned& x, const Planned& y) { return x.theta < y.theta; });
  return out;
}

namespace {

struct SlicerWorker {
  explicit SlicerWorker(const Pair* pair) : slicer(*pair) {}
  Slicer slicer;
};

}  // namespace

SliceWorker::SliceWorker(const Pair* pair) : pair(*pair), slicer(*pair), contacts(*pair) {}

Slice SliceWorker::slice(const BoundaryModel* model, double theta, bool& evaluated) {
  std::optional<Slice> from_model;
  if (model) from_model = slice_from_model(pair, *model, theta, contacts, scratch);
  evaluated = from_model.has_value();
  return evaluated ? std::move(*from_model) : slicer.slice(theta);
}

std::optional<BoundaryModel> checked_model(const Pair& pair, const Slice& representative) {
  std::optional<BoundaryModel> model = model_boundary(representative, pair.tol);
  if (model && !model_reproduces(*model, representative)) model.reset();
  return model;
}

// Each slice depends only on the pair and its theta (an intermediate slice on its interval's
// representative, itself computed from the pair and its theta) and is stored at its own
// index, so the result is the same whatever the number of threads or the order they run in.
void for_each_index_parallel(const Pair& pair, size_t count, int threads,
                             const std::function<void(size_t, Slicer&)>& slice_at) {
  for_each_index_parallel<SlicerWorker>(pair, count, threads,
                                        [&](size_t i, SlicerWorker& w) { slice_at(i, w.slicer); });
}

namespace {

// Which planned slices are mapped across a symmetry of the pair (docs/symmetry.md) rather
// than computed: source[i] is the slice that slice i is the image of (-1: none), under
// symmetries[symmetry[i]]. Decided before any slice is computed, in plan order, so that the
// result does not depend on the thread count.
struct ImagePlan {
  std::vector<int> source, symmetry;
  std::vector<char> is_source;
};

// The planned slice within `angular` of theta, or -1 (the plan is sorted by theta).
int planned_near(const std::vector<Planned>& plan, double theta, double angular) {
  return index_near_angle(plan, theta, angular, [](const Planned& p) { return p.theta; });
}

// Each slice that `may_source` accepts and that is no image yet becomes a source, and every
// unassigned slice that `may_image` accepts at one of its symmetric orientations its image.
template <class Source, class Image>
void assign_images(const std::vector<Planned>& plan, const std::vector<PairSymmetry>& symmetries,
                   double angular, Source may_source, Image may_image, ImagePlan& out) {
  for (size_t k = 0; k < plan.size(); ++k) {
    if (out.source[k] >= 0 || out.is_source[k] || !may_source(plan[k])) continue;
    out.is_source[k] = true;
    for (size_t s = 0; s < symmetries.size(); ++s) {
      const int j = planned_near(plan, symmetries[s].image_theta(plan[k].theta), angular);
      if (j < 0 || out.is_source[j] || out.source[j] >= 0 || !may_image(plan[j])) continue;
      out.source[j] = static_cast<int>(k);
      out.symmetry[j] = static_cast<int>(s);
    }
  }
}

// Slices computed from scratch (critical and interval ones, and intermediate ones when not
// evaluated) are mapped to any slice; evaluated intermediate ones only to other intermediate
// ones, as they need their interval's representative first.
ImagePlan plan_images(const std::vector<Planned>& plan, const std::vector<PairSymmetry>& symmetries,
                      double angular, bool evaluate) {
  ImagePlan out{std::vector<int>(plan.size(), -1), std::vector<int>(plan.size(), -1),
                std::vector<char>(plan.size(), false)};
  if (symmetries.empty() || plan.empty()) return out;
  const auto evaluated = [&](const Planned& p) {
    return evaluate && p.kind == SliceKind::intermediate;
  };
  const auto any = [](const Planned&) { return true; };
  assign_images(plan, symmetries, angular, std::not_fn(evaluated), any, out);
  assign_images(plan, symmetries, angular, evaluated, evaluated, out);
  return out;
}

// A stored slice keeps its vectors for the space's lifetime, and they grew by doubling (the
// contact segments into a buffer sized by the previous slice): giving back their spare
// capacity took the 600-feature smooth star pair's peak from 3.89 to 3.76 GB.
void release_spare_capacity(Slice& slice) {
  slice.contact_segments.shrink_to_fit();
  slice.realizable.shrink_to_fit();
  slice.degenerate.shrink_to_fit();
  slice.contact_graph.nodes.shrink_to_fit();
  slice.contact_graph.edges.shrink_to_fit();
  for (FreeComponent& c : slice.free_components)
    for (std::vector<ContactPiece>& cycle : c.boundary) cycle.shrink_to_fit();
}

// The image at theta of a stored slice under `symmetry`, or nothing where it must be
// computed. A slice whose pieces lie along coincident contact segments names them by the
// lowest id, in the order the contact segments are made at its theta: its image takes the
// contact segments made at its own theta and its names from them (mapped_slice_as_computed).
// An evaluated slice has its representative's pieces (null with no critical orientation,
// where no slice is evaluated).
std::optional<Slice> image_of(const SpaceSlice& source, const Slice* representative,
                              const PairSymmetry& symmetry, double theta, ContactMaker& contacts) {
  const bool inherits = source.evaluated && representative && representative->coincident_pieces;
  if (source.slice.coincident_pieces || inherits)
    return mapped_slice_as_computed(source.slice, symmetry, theta, contacts);
  return mapped_slice(source.slice, symmetry, theta);
}

}  // namespace

std::vector<SpaceSlice> compute_slices(const Pair& pair, const std::vector<Planned>& plan,
                                       const SliceRules& rules, const ProgressReport& progress,
                                       KnownModels* models) {
  std::vector<SpaceSlice> out(plan.size());
  if (models) models->assign(plan.size(), std::nullopt);
  std::atomic<size_t> done = 0;
  const auto store = [&](size_t i, Slice slice, bool evaluated) {
    release_spare_capacity(slice);
    out[i] = {plan[i].theta, plan[i].kind, plan[i].interval, std::move(slice), evaluated};
    if (progress) progress("slices", ++done, plan.size());
  };
  const std::vector<PairSymmetry> symmetries =
      rules.map_symmetric ? pair_symmetries(pair) : std::vector<PairSymmetry>{};
  const ImagePlan images = plan_images(plan, symmetries, pair.tol.angular, rules.evaluate);
  // Critical and representative slices first, from scratch, and their images; then per
  // interval its intermediate ones, and theirs.
  std::vector<size_t> first, first_images, later_images;
  std::vector<std::vector<size_t>> later;
  std::vector<int> representative;
  for (size_t i = 0; i < plan.size(); ++i) {
    const size_t interval = static_cast<size_t>(plan[i].interval);
    if (interval >= later.size()) {
      later.resize(interval + 1);
      representative.resize(interval + 1, -1);
    }
    if (plan[i].kind == SliceKind::interval) representative[interval] = static_cast<int>(i);
    const bool evaluated = plan[i].kind == SliceKind::intermediate && rules.evaluate;
    if (images.source[i] >= 0)
      (plan[images.source[i]].kind == SliceKind::intermediate && rules.evaluate ? later_images
                                                                                : first_images)
          .push_back(i);
    else if (evaluated)
      later[interval].push_back(i);
    else
      first.push_back(i);
  }
  // On this thread: a mapped slice costs a copy, a few percent of one computed; the images
  // that cannot be mapped are computed after, in parallel.
  ContactMaker contacts(pair);
  const auto map_images = [&](const std::vector<size_t>& which) {
    std::vector<size_t> computed;
    for (size_t i : which) {
      const SpaceSlice& source = out[images.source[i]];
      const int r = representative[size_t(source.interval)];  // -1 with no critical orientation
      std::optional<Slice> image =
          image_of(source, r >= 0 ? &out[size_t(r)].slice : nullptr, symmetries[images.symmetry[i]],
                   plan[i].theta, contacts);
      if (!image) {
        computed.push_back(i);
        continue;
      }
      store(i, std::move(*image), false);
      out[i].mapped = true;
    }
    for_each_index_parallel(pair, computed.size(), rules.threads, [&](size_t k, Slicer& s) {
      store(computed[k], s.slice(plan[computed[k]].theta), false);
    });
  };
  for_each_index_parallel(pair, first.size(), rules.threads, [&](size_t k, Slicer& s) {
    store(first[k], s.slice(plan[first[k]].theta), false);
  });
  map_images(first_images);
  for_each_index_parallel<SliceWorker>(
      pair, later.size(), rules.threads, [&](size_t k, SliceWorker& w) {
        if (later[k].empty()) return;
        std::optional<BoundaryModel> model;
        if (representative[k] >= 0) model = checked_model(pair, out[representative[k]].slice);
        for (size_t i : later[k]) {
          bool evaluated = false;
          Slice slice = w.slice(model ? &*model : nullptr, plan[i].theta, evaluated);
          store(i, std::move(slice), evaluated);
        }
        // Each interval writes its own representative's slot.
        if (models && representative[k] >= 0) (*models)[representative[k]] = std::move(model);
      });
  map_images(later_images);
  return out;
}

namespace {
// Appends the slice's realizable labels, sorted, each once (realizable_labels).
void append_realizable_labels(const Slice& slice, std::vector<char>& marked,
                              std::vector<SegmentLabel>& out) {
  const size_t first = out.size();
  mark_realizable_segments(slice, marked);
  for (size_t id = 0; id < marked.size(); ++id)
    if (marked[id]) {
      const ContactSegment& s = slice.contact_segments[id];  // ids number the segments
      out.push_back({s.moving_feature, s.fixed_feature});
    }
  std::sort(out.begin() + first, out.end());
  out.erase(std::unique(out.begin() + first, out.end()), out.end());
}
}  // namespace

// Slice i to slice i + 1, and the last back to the first: theta = -pi and pi are one slice.
// Every slice's labels go into one buffer (slice i's from start[i] to start[i + 1]): slices
// are many and their labels few, and a vector per slice, with the marks behind it, cost more
// than comparing them.
std::vector<SliceCorrespondence> slice_correspondences(const std::vector<SpaceSlice>& slices) {
  std::vector<SegmentLabel> labels;
  std::vector<size_t> start = {0};
  std::vector<char> marked;
  for (const SpaceSlice& s : slices) {
    append_realizable_labels(s.slice, marked, labels);
    start.push_back(labels.size());
  }
  const auto of = [&](int i) {
    return std::span<const SegmentLabel>(labels.data() + start[i], start[i + 1] - start[i]);
  };
  std::vector<SliceCorrespondence> out;
  const int n = static_cast<int>(slices.size());
  out.reserve(size_t(n));
  for (int i = 0; i < n && n > 1; ++i) {
    const int j = (i + 1) % n;
    out.push_back(correspond(i, j, of(i), of(j)));
  }
  return out;
}

}  // namespace detail

std::string_view to_string(SliceKind k) {
  switch (k) {
    case SliceKind::critical:
      return "critical";
    case SliceKind::interval:
      return "interval";
    case SliceKind::intermediate:
      return "intermediate";
  }
  return "unknown";
}

// Every contact curve is built from points O = P + R(theta) Q (docs/criticals.md, contact
// families): a line's ends, an arc's centre and candidate ends. A line's inner points have Q
// between its ends' (Q is affine along it), and an arc's point of world normal n has the
// centre's Q, so the largest |Q| over the families' defining points bounds them all. It is
// not the moving part's reach: a moving segment on a fixed arc of radius r slides along it,
// Q = r u - a_m, and a disc turning about its own centre has Q = 0.
double contact_reach(const Pair& pair) {
  double reach = 0.0;
  for (const ContactFamily& f : contact_families(pair)) {
    if (f.shape == FamilyShape::circle) reach = std::max(reach, length(f.center.q));
    for (const MovingPoint& e : f.ends) reach = std::max(reach, length(e.q));
  }
  return reach;
}

// Between two slices dtheta apart, a point P + R(theta) Q moves along a circle of radius |Q|
// and leaves the chord joining its two ends by at most the sagitta
// |Q| (1 - cos(dtheta / 2)) <= |Q| dtheta^2 / 8. Linear interpolation of the defining points
// therefore stays within `tolerance` of the true contact curves when
// dtheta <= sqrt(8 tolerance / |Q|max). The cap keeps slices at least a quarter turn apart
// for tiny or point-like moving parts, where the bound says nothing useful.
double interpolation_step(double reach, double tolerance) {
  const double cap = kPi / 2;
  if (!(reach > 0.0)) return cap;
  return std::min(cap, std::sqrt(8.0 * tolerance / reach));
}

std::vector<SegmentLabel> realizable_labels(const Slice& slice) {
  std::vector<SegmentLabel> out;
  std::vector<char> marked;
  detail::append_realizable_labels(slice, marked, out);
  return out;
}

SlicedSpace compute_space(const Pair& pair, const SpaceOptions& options) {
  SlicedSpace space;
  auto start = std::chrono::steady_clock::now();
  const auto report = [&](std::string_view stage, size_t done, size_t total) {
    if (options.progress) options.progress(stage, done, total);
  };
  CriticalOptions critical = options.critical;
  if (critical.threads == 0) critical.threads = options.threads;
  report("critical orientations", 0, 1);
  space.criticals = critical_orientations(pair, critical);
  space.seconds_criticals = seconds_since(start);
  report("critical orientations", 1, 1);

  start = std::chrono::steady_clock::now();
  space.reach = contact_reach(pair);
  space.max_step = interpolation_step(space.reach, pair.tol.contact);
  detail::KnownModels models;
  space.slices = detail::compute_slices(
      pair, detail::plan_slices(space.criticals, space.max_step),
      {options.threads, options.evaluate_slices, options.map_symmetric}, options.progress, &models);
  space.correspondence = detail::slice_correspondences(space.slices);
  report("topology", 0, 1);
  space.topology = detail::compute_topology(
      pair, space, {options.threads, options.verify_joins, options.evaluate_slices}, &models);
  report("topology", 1, 1);
  space.seconds_slices = seconds_since(start);
  return space;
}

}  // namespace cslice
