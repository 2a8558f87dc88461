#include "slice/boundary_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contacts/contact_features.hpp"
#include "slice/face_sample.hpp"

namespace cslice {

bool sorted_hits(const Curve& a, const Curve& b, double eps, SortedHits& hits) {
  hits.clear();
  const Intersection x = intersect(a, b, eps);
  if (x.kind == IntersectionKind::overlapping) return false;
  for (int i = 0; i < x.count; ++i) {
    if (x.hits[i].is_piece) return false;
    hits.push_back({x.hits[i].ta0, x.hits[i].point});
  }
  std::sort(hits.begin(), hits.end(),
            [](const auto& p, const auto& q) { return p.first < q.first; });
  return true;
}

int label_index(const BoundaryModel& model, SegmentLabel l) {
  const auto it = std::lower_bound(
      model.by_label.begin(), model.by_label.end(), l,
      [](const std::pair<SegmentLabel, int>& e, const SegmentLabel& k) { return e.first < k; });
  return it != model.by_label.end() && it->first == l ? it->second : -1;
}

bool label_segments(const BoundaryModel& model, std::span<const ContactSegment> segments,
                    std::vector<int>& ids, std::vector<Curve>& curves) {
  ids.assign(model.labels.size(), -1);
  curves.resize(model.labels.size());
  for (const ContactSegment& s : segments) {
    const int l = label_index(model, {s.moving_feature, s.fixed_feature});
    if (l < 0) continue;
    if (s.is_point || ids[l] >= 0) return false;
    ids[l] = s.id;
    curves[l] = s.curve;
  }
  return std::none_of(ids.begin(), ids.end(), [](int id) { return id < 0; });
}

namespace {

// Labels and pieces of every cycle, without corners; false on a full circle sharing its
// cycle, an empty cycle, or two contact segments of one label on the boundary.
bool model_cycles(const Slice& slice, BoundaryModel& m) {
  std::vector<int> label_of_segment(slice.contact_segments.size(), -1);
  for (const FreeComponent& fc : slice.free_components) {
    ComponentModel& cm = m.components.emplace_back();
    cm.bounded = fc.bounded;
    for (const auto& cycle : fc.boundary) {
      CycleModel& cyc = cm.cycles.emplace_back();
      for (const ContactPiece& piece : cycle) {
        int& label = label_of_segment.at(piece.segment);
        if (label < 0) {
          const ContactSegment& s = slice.contact_segments[piece.segment];
          label = static_cast<int>(m.labels.size());
          m.labels.push_back({s.moving_feature, s.fixed_feature});
        }
        const int sign = piece.curve.is_arc() ? (piece.curve.sweep > 0 ? 1 : -1) : 0;
        cyc.pieces.push_back({label, sign});
        cyc.full_circle = cyc.full_circle || piece.curve.is_full_circle();
      }
      if (cyc.pieces.empty() || (cyc.full_circle && cyc.pieces.size() != 1)) return false;
    }
  }
  for (int l = 0; l < static_cast<int>(m.labels.size()); ++l)
    m.by_label.push_back({m.labels[l], l});
  std::sort(m.by_label.begin(), m.by_label.end());
  const auto same = [](const auto& x, const auto& y) { return x.first == y.first; };
  return std::adjacent_find(m.by_label.begin(), m.by_label.end(), same) == m.by_label.end();
}

// Each corner's rank among the hits of its curves: the hit nearest the slice's corner, which
// must lie within the criticality tolerance of it.
bool model_corners(const Slice& slice, const std::vector<Curve>& curves, const Tolerances& tol,
                   BoundaryModel& m) {
  SortedHits hits;
  for (size_t c = 0; c < m.components.size(); ++c) {
    const FreeComponent& fc = slice.free_components[c];
    for (size_t k = 0; k < fc.boundary.size(); ++k) {
      CycleModel& cyc = m.components[c].cycles[k];
      if (cyc.full_circle) continue;
      const size_t n = cyc.pieces.size();
      for (size_t i = 0; i < n; ++i) {
        const int a = cyc.pieces[i].label, b = cyc.pieces[(i + 1) % n].label;
        if (a == b) return false;
        if (!sorted_hits(curves[a], curves[b], tol.geometric, hits) || hits.empty()) return false;
        const Vec2 corner = fc.boundary[k][i].curve.to;
        int best = 0;
        for (int h = 1; h < static_cast<int>(hits.size()); ++h)
          if (distance(hits[h].second, corner) < distance(hits[best].second, corner)) best = h;
        if (distance(hits[best].second, corner) > tol.criticality) return false;
        cyc.corners.push_back({m.corners++, a, b, best, static_cast<int>(hits.size())});
      }
    }
  }
  return true;
}

}  // namespace

std::optional<BoundaryModel> model_boundary(const Slice& slice, const Tolerances& tol) {
  if (!slice.degenerate.empty()) return std::nullopt;
  BoundaryModel m;
  std::vector<int> ids;
  std::vector<Curve> curves;
  if (!model_cycles(slice, m) || !label_segments(m, slice.contact_segments, ids, curves) ||
      !model_corners(slice, curves, tol, m))
    return std::nullopt;
  return m;
}

bool corner_point(const CornerModel& k, const Curve& a, const Curve& b, double eps,
                  SortedHits& hits, Vec2& out) {
  if (!sorted_hits(a, b, eps, hits) || static_cast<int>(hits.size()) != k.count) return false;
  out = hits[k.rank].second;
  return true;
}

bool piece_between(const PieceModel& piece, const Curve& c, Vec2 from, Vec2 to, Curve& out) {
  if (piece.sweep_sign == 0) {
    out = make_segment(from, to);
    return true;
  }
  if (!c.is_arc()) return false;
  const double a0 = std::atan2(from.y - c.center.y, from.x - c.center.x);
  const double a1 = std::atan2(to.y - c.center.y, to.x - c.center.x);
  double sweep = std::fmod(piece.sweep_sign * (a1 - a0), kTwoPi);
  if (sweep < 0) sweep += kTwoPi;
  // Exactly the corners, not their round trip through angles.
  out = make_arc_between(c.center, c.radius, a0, piece.sweep_sign * sweep, from, to);
  return true;
}

bool evaluate_boundary(const BoundaryModel& model, std::span<const Curve> curves, double eps,
                       EvaluatedBoundary& out) {
  out.pieces.clear();
  out.piece_label.clear();
  out.cycle_end.clear();
  out.component_end.clear();
  out.corners.resize(model.corners);
  for (const ComponentModel& cm : model.components) {
    for (const CycleModel& cyc : cm.cycles) {
      if (cyc.full_circle) {
        const Curve& c = curves[cyc.pieces[0].label];
        if (!c.is_arc()) return false;
        out.pieces.push_back(make_circle(c.center, c.radius, cyc.pieces[0].sweep_sign > 0));
        out.piece_label.push_back(cyc.pieces[0].label);
        out.cycle_end.push_back(static_cast<int>(out.pieces.size()));
        continue;
      }
      for (const CornerModel& k : cyc.corners)
        if (!corner_point(k, curves[k.a], curves[k.b], eps, out.hits, out.corners[k.id]))
          return false;
      const size_t n = cyc.pieces.size();
      for (size_t i = 0; i < n; ++i) {
        const Vec2 from = out.corners[cyc.corners[(i + n - 1) % n].id];
        const Vec2 to = out.corners[cyc.corners[i].id];
        const PieceModel& pm = cyc.pieces[i];
        if (!piece_between(pm, curves[pm.label], from, to, out.pieces.emplace_back())) return false;
        out.piece_label.push_back(pm.label);
      }
      out.cycle_end.push_back(static_cast<int>(out.pieces.size()));
    }
    out.component_end.push_back(static_cast<int>(out.pieces.size()));
  }
  return true;
}

namespace {

// Free components, realizable pieces and blocked area from the evaluated boundary.
void add_components(const Pair& pair, const BoundaryModel& model, SliceFromModelScratch& s,
                    Slice& slice) {
  const EvaluatedBoundary& e = s.boundary;
  // Blocked space: what the unbounded component's cycles enclose, less the bounded components.
  double enclosed = 0.0, free_bounded = 0.0;
  slice.realizable.reserve(e.pieces.size());
  int cycle = 0, piece = 0;
  for (size_t c = 0; c < model.components.size(); ++c) {
    FreeComponent& fc = slice.free_components.emplace_back();
    fc.id = static_cast<int>(c);
    fc.bounded = model.components[c].bounded;
    Box box;
    double area = 0.0;
    s.cycle.clear();
    for (const CycleModel& cyc : model.components[c].cycles) {
      std::vector<ContactPiece>& out = fc.boundary.emplace_back();
      out.reserve(cyc.pieces.size());
      for (; piece < e.cycle_end[cycle]; ++piece) {
        const Curve& curve = e.pieces[piece];
        const int id = s.label_segment[e.piece_label[piece]];
        out.push_back({id, curve});
        slice.realizable.push_back({id, reversed(curve)});
        box.add(bounding_box(curve));
        area += signed_area_contribution(curve);
        s.cycle.push_back(curve);
      }
      ++cycle;
    }
    if (fc.bounded) {
      fc.area = area;
      fc.sample = sample_inside(s.cycle, box, s.xs);
      free_bounded += area;
    } else {
      fc.area = std::numeric_limits<double>::quiet_NaN();
      fc.sample = sample_beyond(box, pair.tol);
      enclosed -= area;  // clockwise cycles around blocked space
    }
  }
  const bool unbounded_free = std::any_of(model.components.begin(), model.components.end(),
                                          [](const ComponentModel& cm) { return !cm.bounded; });
  slice.blocked_area =
      unbounded_free ? enclosed - free_bounded : std::numeric_limits<double>::infinity();
}

// Nodes: every label's segment; edges: one per corner, between its two labels' segments.
void add_contact_graph(const BoundaryModel& model, SliceFromModelScratch& s, Slice& slice) {
  std::vector<int>& nodes = slice.contact_graph.nodes;
  nodes = s.label_segment;
  std::sort(nodes.begin(), nodes.end());
  for (const ComponentModel& cm : model.components)
    for (const CycleModel& cyc : cm.cycles)
      for (const CornerModel& k : cyc.corners) {
        const int a = s.label_segment[k.a], b = s.label_segment[k.b];
        slice.contact_graph.edges.push_back(
            {std::min(a, b), std::max(a, b), s.boundary.corners[k.id]});
      }
}

}  // namespace

std::optional<Slice> slice_from_model(const Pair& pair, const BoundaryModel& model, double theta,
                                      ContactMaker& contacts, SliceFromModelScratch& scratch) {
  // A model with no component (an interval with no free space at all) evaluates to no
  // free space: the structure holds throughout the interval like any other.
  Slice slice;
  slice.theta = theta;
  slice.epsilon = pair.tol.geometric;
  contacts.segments(theta, slice.contact_segments);
  // Any perfect fit refuses, not only the labels' own: a computed slice would make it a
  // degenerate contact wherever it is free, which the model cannot tell.
  const auto point = [](const ContactSegment& c) { return c.is_point; };
  if (std::any_of(slice.contact_segments.begin(), slice.contact_segments.end(), point) ||
      !label_segments(model, slice.contact_segments, scratch.label_segment, scratch.curves) ||
      !evaluate_boundary(model, scratch.curves, pair.tol.geometric, scratch.boundary))
    return std::nullopt;
  add_components(pair, model, scratch, slice);
  add_contact_graph(model, scratch, slice);
  return slice;
}

namespace {

std::vector<std::pair<int, int>> edge_pairs(const ContactGraph& g) {
  std::vector<std::pair<int, int>> out;
  for (const ContactGraphEdge& e : g.edges) out.push_back({e.a, e.b});
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

bool model_reproduces(const BoundaryModel& model, const Slice& slice) {
  if (!slice.degenerate.empty()) return false;
  std::vector<int> ids;
  std::vector<Curve> curves;
  if (!label_segments(model, slice.contact_segments, ids, curves)) return false;
  std::vector<std::pair<int, int>> edges;
  size_t pieces = 0;
  for (const ComponentModel& cm : model.components)
    for (const CycleModel& cyc : cm.cycles) {
      pieces += cyc.pieces.size();
      for (const CornerModel& k : cyc.corners)
        edges.push_back({std::min(ids[k.a], ids[k.b]), std::max(ids[k.a], ids[k.b])});
    }
  std::sort(edges.begin(), edges.end());
  std::sort(ids.begin(), ids.end());
  return pieces == slice.realizable.size() && ids == slice.contact_graph.nodes &&
         edges == edge_pairs(slice.contact_graph);
}

}  // namespace cslice
