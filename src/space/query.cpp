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

namespace cslice {

namespace {

struct CornerModel {
  int id = 0;        // index among the interval's corners
  int a = 0, b = 0;  // label indices of the pieces before and after the corner
  int rank = 0;      // which hit of intersect(a, b), in order along a
  int count = 0;     // how many hits there are in the interval
};

struct PieceModel {
  int label = 0;
  int sweep_sign = 0;  // arcs: direction of travel (+1 counterclockwise); segments: 0
};

struct CycleModel {
  std::vector<PieceModel> pieces;
  std::vector<CornerModel> corners;  // corner k ends piece k and starts piece k + 1
  bool full_circle = false;          // one piece, a whole circle
};

struct ComponentModel {
  bool bounded = true;
  int component = -1;  // 3D component
  std::vector<CycleModel> cycles;
  // Bounded components: the box of its labels' covers at each stored slice, and their
  // largest drift; p outside it (inflated) cannot be inside the component.
  std::vector<Box> boxes;
  double drift = 0.0;
};

struct IntervalModel {
  bool exact = false;
  int representative = -1;
  std::vector<int> stored;  // non-critical stored slices of the interval, by theta
  std::vector<SegmentLabel> labels;
  std::vector<ComponentModel> components;
  int corners = 0;
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
  std::vector<Curve> pieces;
  std::vector<int> piece_label;
  std::vector<int> component_end;  // pieces of component c: [end[c-1], end[c])
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
  std::vector<std::pair<double, Vec2>> scratch_hits;
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

  int label_index(IntervalModel& m, SegmentLabel l) {
    const auto it = std::find(m.labels.begin(), m.labels.end(), l);
    if (it != m.labels.end()) return static_cast<int>(it - m.labels.begin());
    m.labels.push_back(l);
    return static_cast<int>(m.labels.size()) - 1;
  }

  // The contact curve of each label of the model at theta; false unless each label gives
  // exactly one contact segment.
  bool evaluate_curves(const IntervalModel& m, double theta) {
    scratch_curves.clear();
    const Transform turn(Pose{0.0, 0.0, theta});
    for (const SegmentLabel& l : m.labels) {
      scratch_segments.clear();
      add_pair_contacts(pair, moving[l.moving_feature], fixed[l.fixed_feature], turn,
                        scratch_segments);
      if (scratch_segments.size() != 1 || scratch_segments[0].is_point) return false;
      scratch_curves.push_back(scratch_segments[0].curve);
    }
    return true;
  }

  // Transversal hits of two curves, sorted along the first; false if they overlap.
  bool hits_of(const Curve& a, const Curve& b) {
    scratch_hits.clear();
    const Intersection x = intersect(a, b, pair.tol.geometric);
    if (x.kind == IntersectionKind::overlapping) return false;
    for (int i = 0; i < x.count; ++i) {
      if (x.hits[i].is_piece) return false;
      scratch_hits.push_back({x.hits[i].ta0, x.hits[i].point});
    }
    std::sort(scratch_hits.begin(), scratch_hits.end(),
              [](const auto& p, const auto& q) { return p.first < q.first; });
    return true;
  }

  void build_model(IntervalModel& m) {
    m.exact = false;
    if (m.representative < 0) return;
    const Slice& rep = space.slices[m.representative].slice;
    if (!rep.degenerate.empty()) return;
    const auto& comp3d = space.topology.slice_components.at(m.representative);
    for (const FreeComponent& fc : rep.free_components) {
      ComponentModel cm;
      cm.bounded = fc.bounded;
      cm.component = comp3d.at(fc.id);
      for (const auto& cycle : fc.boundary) {
        CycleModel cyc;
        for (const ContactPiece& piece : cycle) {
          const ContactSegment& seg = rep.contact_segments.at(piece.segment);
          const int li = label_index(m, {seg.moving_feature, seg.fixed_feature});
          cyc.pieces.push_back({li, piece.curve.is_arc() ? (piece.curve.sweep > 0 ? 1 : -1) : 0});
          if (piece.curve.is_full_circle()) cyc.full_circle = true;
        }
        if (cyc.pieces.empty()) return;
        if (cyc.full_circle && cyc.pieces.size() != 1) return;
        cm.cycles.push_back(std::move(cyc));
      }
      m.components.push_back(std::move(cm));
    }
    // Corners: which hit of the two curves each one is at the representative orientation.
    if (!evaluate_curves(m, space.slices[m.representative].theta)) return;
    size_t c = 0;
    for (const FreeComponent& fc : rep.free_components) {
      for (size_t k = 0; k < fc.boundary.size(); ++k) {
        CycleModel& cyc = m.components[c].cycles[k];
        if (cyc.full_circle) continue;
        const size_t n = cyc.pieces.size();
        for (size_t i = 0; i < n; ++i) {
          const int a = cyc.pieces[i].label, b = cyc.pieces[(i + 1) % n].label;
          if (a == b) return;
          if (!hits_of(scratch_curves[a], scratch_curves[b]) || scratch_hits.empty()) return;
          const Vec2 corner = fc.boundary[k][i].curve.to;
          int best = 0;
          for (int h = 1; h < static_cast<int>(scratch_hits.size()); ++h)
            if (distance(scratch_hits[h].second, corner) <
                distance(scratch_hits[best].second, corner))
              best = h;
          if (distance(scratch_hits[best].second, corner) > pair.tol.criticality) return;
          cyc.corners.push_back({m.corners++, a, b, best, static_cast<int>(scratch_hits.size())});
        }
      }
      ++c;
    }
    m.exact = true;
    m.exact = validate(m) && build_bounds(m);
  }

  bool build_bounds(IntervalModel& m) {
    for (int s : m.stored) m.thetas.push_back(space.slices[s].theta);
    const size_t labels = m.labels.size();
    m.cover_boxes.resize(m.thetas.size() * labels);
    for (size_t l = 0; l < labels; ++l) {
      const ContactFamily* family = nullptr;
      for (const ContactFamily& f : families)
        if (f.moving == m.labels[l].moving_feature && f.fixed == m.labels[l].fixed_feature)
          family = &f;
      if (family == nullptr) return false;
      for (size_t i = 0; i < m.thetas.size(); ++i)
        m.cover_boxes[i * labels + l] = bounding_box(family_cover(*family, m.thetas[i]));
      m.drift.push_back(family_drift(*family));
    }
    for (ComponentModel& cm : m.components) {
      cm.boxes.assign(m.thetas.size(), Box{});
      for (const CycleModel& cyc : cm.cycles)
        for (const PieceModel& pm : cyc.pieces) {
          cm.drift = std::max(cm.drift, m.drift[pm.label]);
          for (size_t i = 0; i < m.thetas.size(); ++i)
            cm.boxes[i].add(m.cover_boxes[i * m.labels.size() + pm.label]);
        }
    }
    max_labels = std::max(max_labels, m.labels.size());
    max_corners = std::max(max_corners, static_cast<size_t>(m.corners));
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
      if (pieces != eval.pieces.size()) return false;
      for (const Curve& piece : eval.pieces) {
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
    eval.pieces.clear();
    eval.piece_label.clear();
    eval.component_end.clear();
    const IntervalModel& m = intervals[index];
    if (!evaluate_curves(m, theta)) return false;
    std::vector<Vec2> corner_points;
    for (const ComponentModel& cm : m.components) {
      for (const CycleModel& cyc : cm.cycles) {
        if (cyc.full_circle) {
          const Curve& c = scratch_curves[cyc.pieces[0].label];
          if (!c.is_arc()) return false;
          eval.pieces.push_back(make_circle(c.center, c.radius, cyc.pieces[0].sweep_sign > 0));
          eval.piece_label.push_back(cyc.pieces[0].label);
          continue;
        }
        const size_t n = cyc.pieces.size();
        corner_points.clear();
        for (const CornerModel& k : cyc.corners) {
          if (!hits_of(scratch_curves[k.a], scratch_curves[k.b])) return false;
          if (static_cast<int>(scratch_hits.size()) != k.count) return false;
          corner_points.push_back(scratch_hits[k.rank].second);
        }
        for (size_t i = 0; i < n; ++i) {
          const Vec2 from = corner_points[(i + n - 1) % n], to = corner_points[i];
          const PieceModel& pm = cyc.pieces[i];
          Curve piece;
          if (!make_piece(pm, scratch_curves[pm.label], from, to, piece)) return false;
          eval.pieces.push_back(piece);
          eval.piece_label.push_back(pm.label);
        }
      }
      eval.component_end.push_back(static_cast<int>(eval.pieces.size()));
    }
    eval.ok = true;
    return true;
  }

  // The piece of a contact curve between two corners, in the model's direction.
  static bool make_piece(const PieceModel& pm, const Curve& c, Vec2 from, Vec2 to, Curve& out) {
    if (pm.sweep_sign == 0) {
      out = make_segment(from, to);
      return true;
    }
    if (!c.is_arc()) return false;
    const double a0 = std::atan2(from.y - c.center.y, from.x - c.center.x);
    const double a1 = std::atan2(to.y - c.center.y, to.x - c.center.x);
    double sweep = std::fmod(pm.sweep_sign * (a1 - a0), kTwoPi);
    if (sweep < 0) sweep += kTwoPi;
    // Exactly the corners, not their round trip through angles.
    out = make_arc_between(c.center, c.radius, a0, pm.sweep_sign * sweep, from, to);
    return true;
  }

  // The contact curve of label l at the query theta, evaluated once per query.
  const Curve* lazy_curve(int l) {
    if (curve_stamp[l] != stamp) {
      const SegmentLabel& label = current->labels[l];
      scratch_segments.clear();
      add_pair_contacts(pair, moving[label.moving_feature], fixed[label.fixed_feature], turn,
                        scratch_segments);
      if (scratch_segments.size() != 1 || scratch_segments[0].is_point) return nullptr;
      lazy_curves[l] = scratch_segments[0].curve;
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
      if (!b || !hits_of(*a, *b) || static_cast<int>(scratch_hits.size()) != k.count)
        return nullptr;
      lazy_corners[k.id] = scratch_hits[k.rank].second;
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
    for (size_t l = 0; l < m.labels.size(); ++l) {
      const Box& b = m.cover_boxes[nearest * m.labels.size() + l];
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
    for (const ComponentModel& cm : m.components) {
      bool inside = !cm.bounded;
      bool may_hold = true;
      if (cm.bounded) {
        const Box& b = cm.boxes[nearest];
        const double r = gap * cm.drift + slack;
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
            if (!to || !make_piece(pm, *c, *from, *to, piece)) return false;
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
      if (may_hold && inside && inside_component < 0) inside_component = cm.component;
    }
    if (best_label >= 0 && best <= pair.tol.contact) {
      a.placement = Placement::contact;
      a.contact = m.labels[best_label];
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
    for (size_t c = 0; c < m.components.size(); ++c) {
      const int end = eval.component_end[c];
      bool inside = !m.components[c].bounded;
      for (int i = begin; i < end; ++i)
        if (toggles_parity(eval.pieces[i], p)) inside = !inside;
      if (inside) return m.components[c].component;
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
    const Vec2 sample = slice.free_components[c].sample;
    for (int s : intervals[interval].stored) {
      const int sc = space.slices[s].slice.locate(sample);
      if (sc >= 0) {
        a.component = space.topology.slice_components[s][sc];
        break;
      }
    }
    return a;
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
      for (size_t i = 0; i < eval.pieces.size(); ++i) {
        const double d = distance_to_curve(eval.pieces[i], p);
        if (d < best) {
          best = d;
          best_piece = static_cast<int>(i);
        }
      }
      if (best_piece >= 0 && best <= pair.tol.contact) {
        a.placement = Placement::contact;
        a.contact = m.labels[eval.piece_label[best_piece]];
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
