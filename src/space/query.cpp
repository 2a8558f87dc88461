// Point queries on a computed sliced space (include/cslice/query.hpp).
//
// Between two consecutive critical orientations the contact structure is fixed: the same
// realizable contact segments (by feature-pair label) bound the same free components, meeting
// in the same order. So each interval keeps a model taken from its representative slice: per
// free component, per boundary cycle, the label of each piece and, for each corner between two
// pieces, which intersection of the two contact curves it is (its rank along the first curve).
// At a query theta the labelled contact segments are rebuilt in closed form (add_pair_contacts,
// the same construction the slices use), the corners re-intersected, and the pieces rebuilt
// between them: the exact boundary of the slice at theta. A point within the pair's contact
// tolerance of a piece is in contact (the nearest piece names the features); otherwise the
// component whose cycles enclose it (even-odd) makes it free; otherwise it is blocked.
//
// Most queries need none of that. Each label's contact segments stay within a known bound of
// their family's cover at the interval's nearest stored slice (its drift times the turn), so
// when no label can come within the contact tolerance of the point between that slice and the
// query's theta, no free-space boundary crossed the point in between: the stored slice's own
// answer there is the answer (QueryStats::far_from_contact; 94% of random queries on the
// fixture).
//
// The model is validated when built: evaluated at every stored slice of the interval, its
// corners must be corners of that slice's boundary and the samples of that slice's components
// must land in the components the topology says. Where the model cannot be built or does not
// validate (an interval with degenerate contacts, a cycle that runs along one segment across
// a corner, overlapping curves), or where at a query theta the re-intersection does not give
// the corners the model expects, the answer FALLS BACK to the slice computed at theta
// (compute_slice, cached for recent orientations) and located in it: correct, but far slower.
// QueryStats counts how often each path answered. At a critical orientation (within the
// critical angle) the stored critical slice answers directly.
#include "cslice/query.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "contacts/contact_features.hpp"
#include "criticals/families.hpp"
#include "parts/loop_queries.hpp"
#include "slice/boundary_model.hpp"

namespace cslice {

namespace {

// What the queries add to a component of the boundary model.
struct ComponentBounds {
  int component = -1;  // 3D component
  // Bounded components: the box of its labels' covers at each stored slice, and their
  // largest drift; p outside it (inflated) cannot be inside the component.
  std::vector<Box> boxes;
  double drift = 0.0;
};

struct IntervalModel {
  bool exact = false;
  int representative = -1;
  std::vector<int> stored;  // non-critical stored slices of the interval, by theta
  BoundaryModel boundary;
  std::vector<ComponentBounds> bounds;  // per component of the boundary model
  // Bounds for skipping labels a query cannot need: per label, the box of its family's cover
  // at each stored slice's theta, and how fast the cover can move (per radian).
  std::vector<double> thetas;    // of the stored slices
  std::vector<Box> cover_boxes;  // [stored slice i * labels + label]
  std::vector<double> drift;
};

// The boundary evaluated at one theta.
struct Evaluated {
  int interval = -1;
  double theta = std::numeric_limits<double>::quiet_NaN();
  bool ok = false;
  EvaluatedBoundary boundary;
};

double angle_gap(double a, double b) {
  return std::fabs(wrap_angle(a - b));
}

}  // namespace

struct SpaceQuery::Impl {
  const Pair& pair;
  const SlicedSpace& space;
  std::vector<ContactFeature> moving, fixed;
  std::vector<double> criticals;
  std::vector<IntervalModel> intervals;
  QueryStats stats;
  const IntervalModel* current = nullptr;
  Evaluated eval;
  std::vector<ContactSegment> scratch_segments;
  std::vector<Curve> scratch_curves;
  SortedHits scratch_hits;
  std::deque<std::pair<double, Slice>> fallback_slices;  // most recent first
  std::vector<ContactFamily> families;
  // Per query: which labels may matter, their curves and the corners, evaluated on demand.
  size_t max_labels = 0, max_corners = 0;
  unsigned stamp = 0;
  std::vector<unsigned> curve_stamp, corner_stamp, box_stamp;
  std::vector<char> label_near, label_ray;
  Transform turn;  // the rotation by the query's theta
  std::vector<Curve> lazy_curves;
  std::vector<Box> lazy_boxes;
  std::vector<Vec2> lazy_corners;

  Impl(const Pair& p, const SlicedSpace& s)
      : pair(p),
        space(s),
        moving(contact_features(p.moving)),
        fixed(contact_features(p.fixed)),
        families(contact_families(p)) {
    for (const CriticalOrientation& o : space.criticals.orientations) criticals.push_back(o.theta);
    intervals.resize(std::max<size_t>(1, criticals.size()));
    for (int i = 0; i < static_cast<int>(space.slices.size()); ++i) {
      const SpaceSlice& ss = space.slices[i];
      if (ss.kind == SliceKind::critical && !criticals.empty()) continue;
      IntervalModel& m = intervals.at(ss.interval);
      m.stored.push_back(i);
      if (ss.kind == SliceKind::interval) m.representative = i;
    }
    for (IntervalModel& m : intervals) {
      if (m.representative < 0 && !m.stored.empty()) m.representative = m.stored.front();
      build_model(m);
    }
    curve_stamp.assign(max_labels, 0);
    box_stamp.assign(max_labels, 0);
    lazy_boxes.resize(max_labels);
    corner_stamp.assign(max_corners, 0);
    label_near.assign(max_labels, 0);
    label_ray.assign(max_labels, 0);
    lazy_curves.resize(max_labels);
    lazy_corners.resize(max_corners);
    stats.intervals = static_cast<int>(intervals.size());
    for (const IntervalModel& m : intervals) stats.exact_intervals += m.exact ? 1 : 0;
  }

  // The contact curve of label l at the orientation `at` rotates by; false unless the label
  // gives exactly one contact segment there, not a point.
  bool label_curve(const SegmentLabel& l, const Transform& at, Curve& out) {
    scratch_segments.clear();
    add_pair_contacts(pair, moving[l.moving_feature], fixed[l.fixed_feature], at, scratch_segments);
    if (scratch_segments.size() != 1 || scratch_segments[0].is_point) return false;
    out = scratch_segments[0].curve;
    return true;
  }

  // The contact curve of each label of the model at theta.
  bool evaluate_curves(const IntervalModel& m, double theta) {
    const Transform at(Pose{0.0, 0.0, theta});
    scratch_curves.resize(m.boundary.labels.size());
    for (size_t l = 0; l < scratch_curves.size(); ++l)
      if (!label_curve(m.boundary.labels[l], at, scratch_curves[l])) return false;
    return true;
  }

  void build_model(IntervalModel& m) {
    m.exact = false;
    if (m.representative < 0) return;
    std::optional<BoundaryModel> model =
        model_boundary(space.slices[m.representative].slice, pair.tol);
    if (!model) return;
    m.boundary = std::move(*model);
    const auto& comp3d = space.topology.slice_components.at(m.representative);
    m.bounds.resize(m.boundary.components.size());
    for (size_t c = 0; c < m.bounds.size(); ++c) m.bounds[c].component = comp3d.at(c);
    m.exact = true;
    m.exact = validate(m) && build_bounds(m);
  }

  bool build_bounds(IntervalModel& m) {
    for (int s : m.stored) m.thetas.push_back(space.slices[s].theta);
    const std::vector<SegmentLabel>& labels_of = m.boundary.labels;
    const size_t labels = labels_of.size();
    m.cover_boxes.resize(m.thetas.size() * labels);
    for (size_t l = 0; l < labels; ++l) {
      const ContactFamily* family = nullptr;
      for (const ContactFamily& f : families)
        if (f.moving == labels_of[l].moving_feature && f.fixed == labels_of[l].fixed_feature)
          family = &f;
      if (family == nullptr) return false;
      for (size_t i = 0; i < m.thetas.size(); ++i)
        m.cover_boxes[i * labels + l] = bounding_box(family_cover(*family, m.thetas[i]));
      m.drift.push_back(family_drift(*family));
    }
    for (size_t c = 0; c < m.bounds.size(); ++c) {
      ComponentBounds& cb = m.bounds[c];
      cb.boxes.assign(m.thetas.size(), Box{});
      for (const CycleModel& cyc : m.boundary.components[c].cycles)
        for (const PieceModel& pm : cyc.pieces) {
          cb.drift = std::max(cb.drift, m.drift[pm.label]);
          for (size_t i = 0; i < m.thetas.size(); ++i)
            cb.boxes[i].add(m.cover_boxes[i * labels + pm.label]);
        }
    }
    max_labels = std::max(max_labels, labels);
    max_corners = std::max(max_corners, static_cast<size_t>(m.boundary.corners));
    return true;
  }

  // The model evaluated at every stored slice of its interval reproduces that slice: its
  // corners are corners there, and that slice's component samples land in the components
  // the topology gives them.
  bool validate(const IntervalModel& m) {
    const int index = static_cast<int>(&m - intervals.data());
    for (int s : m.stored) {
      const Slice& slice = space.slices[s].slice;
      if (!slice.degenerate.empty()) return false;
      if (!evaluate(index, space.slices[s].theta)) return false;
      std::vector<Vec2> corners;
      size_t pieces = 0;
      for (const FreeComponent& fc : slice.free_components)
        for (const auto& cycle : fc.boundary) {
          pieces += cycle.size();
          for (const ContactPiece& p : cycle) corners.push_back(p.curve.to);
        }
      if (pieces != eval.boundary.pieces.size()) return false;
      for (const Curve& piece : eval.boundary.pieces) {
        bool found = false;
        for (Vec2 q : corners) found = found || distance(q, piece.to) <= pair.tol.criticality;
        if (!found) return false;
      }
      for (const FreeComponent& fc : slice.free_components) {
        const int want = space.topology.slice_components.at(s).at(fc.id);
        const int got = locate_evaluated(m, fc.sample);
        if (got != want) return false;
      }
    }
    return true;
  }

  // Evaluates interval `index`'s boundary at theta into `eval` (cached for a repeated theta).
  bool evaluate(int index, double theta) {
    if (eval.interval == index && eval.theta == theta) return eval.ok;
    eval.interval = index;
    eval.theta = theta;
    eval.ok = false;
    const IntervalModel& m = intervals[index];
    eval.ok = evaluate_curves(m, theta) &&
              evaluate_boundary(m.boundary, scratch_curves, pair.tol.geometric, eval.boundary);
    return eval.ok;
  }

  // The contact curve of label l at the query theta, evaluated once per query.
  const Curve* lazy_curve(int l) {
    if (curve_stamp[l] != stamp) {
      if (!label_curve(current->boundary.labels[l], turn, lazy_curves[l])) return nullptr;
      curve_stamp[l] = stamp;
    }
    return &lazy_curves[l];
  }

  // The bounding box of label l's curve at the query theta (lazy_curve(l) first).
  const Box& curve_box(int l) {
    if (box_stamp[l] != stamp) {
      lazy_boxes[l] = bounding_box(lazy_curves[l]);
      box_stamp[l] = stamp;
    }
    return lazy_boxes[l];
  }

  const Vec2* lazy_corner(const CornerModel& k) {
    if (corner_stamp[k.id] != stamp) {
      const Curve* a = lazy_curve(k.a);
      const Curve* b = a ? lazy_curve(k.b) : nullptr;
      if (!b || !corner_point(k, *a, *b, pair.tol.geometric, scratch_hits, lazy_corners[k.id]))
        return nullptr;
      corner_stamp[k.id] = stamp;
    }
    return &lazy_corners[k.id];
  }

  // The turn from theta to stored_theta, both in interval `index`, inside the interval: the
  // bounds below hold only where no critical orientation lies between, and the short way
  // round would cross them where an interval spans most of the turn.
  double turn_within(int index, double theta, double stored_theta) const {
    if (criticals.empty()) return angle_gap(theta, stored_theta);
    const double start = criticals[index];
    return std::fabs(ccw_turn(start, theta) - ccw_turn(start, stored_theta));
  }

  // The query in an exact interval, evaluating only the labels whose curves can lie within
  // the contact tolerance of p or cross the rightward ray from p (the only pieces that can
  // change the even-odd parity): a label's cover at theta lies within |theta - theta_s|
  // times its drift of its cover at the nearest stored slice theta_s. Gives the answer the
  // whole evaluated boundary gives; false when the boundary cannot be evaluated at theta.
  bool query_lazy(int index, double theta, Vec2 p, QueryAnswer& a) {
    const IntervalModel& m = intervals[index];
    size_t nearest = 0;
    double gap = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < m.thetas.size(); ++i) {
      const double g = turn_within(index, theta, m.thetas[i]);
      if (g < gap) {
        gap = g;
        nearest = i;
      }
    }
    const double slack = pair.tol.contact + pair.tol.criticality;
    bool any_near = false;
    const size_t labels = m.boundary.labels.size();
    for (size_t l = 0; l < labels; ++l) {
      const Box& b = m.cover_boxes[nearest * labels + l];
      const double r = gap * m.drift[l] + slack;
      label_ray[l] = p.y >= b.lo.y - r && p.y <= b.hi.y + r && p.x <= b.hi.x + r;
      label_near[l] = label_ray[l] && p.x >= b.lo.x - r;
      any_near = any_near || label_near[l];
    }
    if (!any_near) return answer_far_from_contact(m.stored[nearest], p, a);
    current = &m;
    turn = Transform(Pose{0.0, 0.0, theta});
    if (++stamp == 0) {
      std::fill(curve_stamp.begin(), curve_stamp.end(), 0);
      std::fill(box_stamp.begin(), box_stamp.end(), 0);
      std::fill(corner_stamp.begin(), corner_stamp.end(), 0);
      stamp = 1;
    }
    double best = std::numeric_limits<double>::infinity();
    int best_label = -1, inside_component = -1;
    Curve piece;
    for (size_t ci = 0; ci < m.bounds.size(); ++ci) {
      const ComponentModel& cm = m.boundary.components[ci];
      const ComponentBounds& cb = m.bounds[ci];
      bool inside = !cm.bounded;
      bool may_hold = true;
      if (cm.bounded) {
        const Box& b = cb.boxes[nearest];
        const double r = gap * cb.drift + slack;
        may_hold = p.x >= b.lo.x - r && p.x <= b.hi.x + r && p.y >= b.lo.y - r && p.y <= b.hi.y + r;
      }
      for (const CycleModel& cyc : cm.cycles) {
        const size_t n = cyc.pieces.size();
        for (size_t i = 0; i < n; ++i) {
          const PieceModel& pm = cyc.pieces[i];
          // label_near implies label_ray; outside the component only contact matters.
          if (!(may_hold ? label_ray[pm.label] : label_near[pm.label])) continue;
          const Curve* c = lazy_curve(pm.label);
          if (!c) return false;
          // The piece lies on its curve, to within a corner's round-off: a curve passing
          // neither near p nor across the ray spares the corners, two intersections.
          const Box& box = curve_box(pm.label);
          const double e = pair.tol.criticality;
          const bool near = label_near[pm.label] && p.x >= box.lo.x - slack &&
                            p.x <= box.hi.x + slack && p.y >= box.lo.y - slack &&
                            p.y <= box.hi.y + slack;
          const bool ray =
              may_hold && p.y >= box.lo.y - e && p.y <= box.hi.y + e && p.x <= box.hi.x + e;
          if (!near && !ray) continue;
          if (cyc.full_circle) {
            if (!c->is_arc()) return false;
            piece = make_circle(c->center, c->radius, pm.sweep_sign > 0);
          } else {
            const Vec2* from = lazy_corner(cyc.corners[(i + n - 1) % n]);
            const Vec2* to = from ? lazy_corner(cyc.corners[i]) : nullptr;
            if (!to || !piece_between(pm, *c, *from, *to, piece)) return false;
          }
          if (near) {
            const double d = distance_to_curve(piece, p);
            if (d < best) {
              best = d;
              best_label = pm.label;
            }
          }
          if (ray && toggles_parity(piece, p)) inside = !inside;
        }
      }
      if (may_hold && inside && inside_component < 0) inside_component = cb.component;
    }
    if (best_label >= 0 && best <= pair.tol.contact) {
      a.placement = Placement::contact;
      a.contact = m.boundary.labels[best_label];
    } else {
      a.component = inside_component;
      a.placement = inside_component >= 0 ? Placement::free : Placement::blocked;
    }
    return true;
  }

  // The query when no label is near p: the boundary of the free space between stored slice s
  // and theta is made of those labels' contact segments, none of which came within the
  // contact tolerance of p in that turn (their covers' bounds), so p stayed on one side of all
  // of them: its answer at theta is its answer in slice s.
  bool answer_far_from_contact(int s, Vec2 p, QueryAnswer& a) {
    ++stats.far_from_contact;
    const int c = space.slices[s].slice.locate_off_boundary(p);
    a.placement = c >= 0 ? Placement::free : Placement::blocked;
    a.component = c >= 0 ? space.topology.slice_components[s][c] : -1;
    return true;
  }

  // The 3D component of the evaluated component whose cycles enclose p, or -1.
  int locate_evaluated(const IntervalModel& m, Vec2 p) const {
    int begin = 0;
    const EvaluatedBoundary& e = eval.boundary;
    for (size_t c = 0; c < m.bounds.size(); ++c) {
      const int end = e.component_end[c];
      bool inside = !m.boundary.components[c].bounded;
      for (int i = begin; i < end; ++i)
        if (toggles_parity(e.pieces[i], p)) inside = !inside;
      if (inside) return m.bounds[c].component;
      begin = end;
    }
    return -1;
  }

  int interval_of(double theta) const {
    if (criticals.empty()) return 0;
    const auto it = std::upper_bound(criticals.begin(), criticals.end(), theta);
    const int k = static_cast<int>(it - criticals.begin()) - 1;
    return k < 0 ? static_cast<int>(criticals.size()) - 1 : k;
  }

  // Answers from a slice at the query's theta. `components` maps its free components to 3D
  // components when it is a stored slice; otherwise (nullptr) each is matched through its
  // sample located in the stored slices of `interval`.
  QueryAnswer answer_from_slice(const Slice& slice, Vec2 p, const std::vector<int>* components,
                                int interval) const {
    QueryAnswer a;
    double best = std::numeric_limits<double>::infinity();
    auto consider = [&](const Curve& curve, int segment) {
      const double d = distance_to_curve(curve, p);
      if (d <= pair.tol.contact && d < best) {
        best = d;
        const ContactSegment& s = slice.contact_segments.at(segment);
        a.placement = Placement::contact;
        a.contact = {s.moving_feature, s.fixed_feature};
      }
    };
    for (const ContactPiece& piece : slice.realizable) consider(piece.curve, piece.segment);
    for (const DegenerateContact& d : slice.degenerate)
      if (!d.segments.empty()) consider(d.curve, d.segments.front());
    if (a.placement == Placement::contact) return a;
    const int c = slice.locate(p);
    if (c < 0) return a;  // blocked
    a.placement = Placement::free;
    if (components) {
      a.component = components->at(c);
      return a;
    }
    a.component = stored_component_of(slice, c, interval);
    return a;
  }

  // The 3D component of free component c of a slice inside `interval`: where its sample lies
  // in a stored slice of the interval or, for a component that moved further than its own
  // width since the nearest of them (a small region turning about a far origin, with stored
  // slices a large step apart), the one component there with its boundary labels: the
  // slices of one interval are equivalent (the topology matches them the same way).
  int stored_component_of(const Slice& slice, int c, int interval) const {
    const Vec2 sample = slice.free_components[c].sample;
    for (int s : intervals[interval].stored) {
      const int sc = space.slices[s].slice.locate(sample);
      if (sc >= 0) return space.topology.slice_components[s][sc];
    }
    const std::vector<SegmentLabel> labels = boundary_labels(slice, slice.free_components[c]);
    for (int s : intervals[interval].stored) {
      const Slice& stored = space.slices[s].slice;
      int match = -1, matches = 0;
      for (const FreeComponent& fc : stored.free_components)
        if (boundary_labels(stored, fc) == labels) match = fc.id, ++matches;
      if (matches == 1) return space.topology.slice_components[s][match];
    }
    return -1;
  }

  // FALLBACK: the slice computed at theta (not from the stored structure), kept for reuse.
  const Slice& fallback_slice(double theta) {
    for (const auto& [t, s] : fallback_slices)
      if (t == theta) return s;
    if (fallback_slices.size() >= 8) fallback_slices.pop_back();
    fallback_slices.emplace_front(theta, compute_slice(pair, theta));
    return fallback_slices.front().second;
  }

  QueryAnswer query(const Pose& pose) {
    ++stats.queries;
    const double theta = wrap_angle(pose.theta);
    const Vec2 p{pose.x, pose.y};
    const int n = static_cast<int>(criticals.size());
    const int k = interval_of(theta);
    // At a critical orientation: the stored critical slice.
    for (int c : {k, (k + 1) % std::max(n, 1)}) {
      if (n == 0 || angle_gap(theta, criticals[c]) > pair.tol.critical_angle) continue;
      for (int s = 0; s < static_cast<int>(space.slices.size()); ++s)
        if (space.slices[s].kind == SliceKind::critical && space.slices[s].interval == c) {
          ++stats.at_stored_slice;
          return answer_from_slice(space.slices[s].slice, p, &space.topology.slice_components[s],
                                   k);
        }
    }
    const IntervalModel& m = intervals[k];
    QueryAnswer lazy;
    if (m.exact && query_lazy(k, theta, p, lazy)) {
      ++stats.evaluated;
      return lazy;
    }
    if (m.exact && evaluate(k, theta)) {
      ++stats.evaluated;
      QueryAnswer a;
      double best = std::numeric_limits<double>::infinity();
      int best_piece = -1;
      for (size_t i = 0; i < eval.boundary.pieces.size(); ++i) {
        const double d = distance_to_curve(eval.boundary.pieces[i], p);
        if (d < best) {
          best = d;
          best_piece = static_cast<int>(i);
        }
      }
      if (best_piece >= 0 && best <= pair.tol.contact) {
        a.placement = Placement::contact;
        a.contact = m.boundary.labels[eval.boundary.piece_label[best_piece]];
        return a;
      }
      a.component = locate_evaluated(m, p);
      a.placement = a.component >= 0 ? Placement::free : Placement::blocked;
      // A component with no 3D id cannot happen in an interval; keep free with -1 if it does.
      return a;
    }
    ++stats.fallback;
    return answer_from_slice(fallback_slice(theta), p, nullptr, k);
  }
};

SpaceQuery::SpaceQuery(const Pair& pair, const SlicedSpace& space)
    : impl_(std::make_unique<Impl>(pair, space)) {}
SpaceQuery::~SpaceQuery() = default;

QueryAnswer SpaceQuery::query(const Pose& pose) {
  return impl_->query(pose);
}

const QueryStats& SpaceQuery::stats() const {
  return impl_->stats;
}

}  // namespace cslice
