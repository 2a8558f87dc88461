// The direct placement test.
//
// Interiors overlap exactly when (a) the boundaries share a piece that both parts travel in
// the same direction (both materials on one side), or (b) some piece of one boundary lies
// inside the other part. Pieces are the edges cut at every point where they meet the other
// boundary, so each piece is wholly inside or wholly outside the other part and its
// midpoint decides. A midpoint within the geometric epsilon of the other boundary belongs
// to a touching piece (sliding or perfect-fit contact) and decides nothing. This needs no
// case analysis of vertex contacts: an edge poking past a vertex leaves a piece inside.
#include <algorithm>

#include "cslice/classify.hpp"
#include "parts/loop_queries.hpp"

namespace cslice {

std::string_view to_string(Placement p) {
  switch (p) {
    case Placement::free:
      return "free";
    case Placement::contact:
      return "contact";
    case Placement::blocked:
      return "blocked";
  }
  return "?";
}

PlacementTester::PlacementTester(const Pair& pair) : pair_(pair) {
  for (const Loop& loop : pair.fixed.loops) {
    for (const Curve& c : loop.edges) {
      fixed_edges_.push_back(c);
      fixed_boxes_.push_back(bounding_box(c));
    }
  }
  for (const Loop& loop : pair.moving.loops) {
    body_loop_starts_.push_back(static_cast<int>(body_edges_.size()));
    body_edges_.insert(body_edges_.end(), loop.edges.begin(), loop.edges.end());
  }
  body_loop_starts_.push_back(static_cast<int>(body_edges_.size()));
  moving_edges_.resize(body_edges_.size());
  moving_boxes_.resize(body_edges_.size());
  moving_splits_.resize(body_edges_.size());
  fixed_splits_.resize(fixed_edges_.size());
}

void PlacementTester::place(const Pose& pose) {
  const Transform t(pose);
  moving_box_ = Box{};
  for (size_t i = 0; i < body_edges_.size(); ++i) {
    moving_edges_[i] = transformed(body_edges_[i], t);
    moving_boxes_[i] = bounding_box(moving_edges_[i]);
    moving_box_.add(moving_boxes_[i]);
  }
}

bool PlacementTester::moving_contains(Vec2 p) const {
  bool inside = false;
  for (size_t k = 0; k + 1 < body_loop_starts_.size(); ++k) {
    const std::span<const Curve> loop(moving_edges_.data() + body_loop_starts_[k],
                                      moving_edges_.data() + body_loop_starts_[k + 1]);
    if (loop_encloses(loop, p)) inside = !inside;
  }
  return inside;
}

// Cuts `edge` at `splits` and reports whether any piece lies inside the other part, deeper
// than the geometric epsilon.
bool PlacementTester::piece_inside_other(const Curve& edge, std::vector<double>& splits,
                                         bool edge_is_moving) const {
  const double eps = pair_.tol.geometric;
  splits.push_back(0.0);
  splits.push_back(1.0);
  std::sort(splits.begin(), splits.end());
  for (size_t k = 0; k + 1 < splits.size(); ++k) {
    if (splits[k + 1] <= splits[k]) continue;
    const Vec2 mid = point_at(edge, 0.5 * (splits[k] + splits[k + 1]));
    const bool inside = edge_is_moving ? contains_point(pair_.fixed, mid) : moving_contains(mid);
    if (!inside) continue;
    const double depth = edge_is_moving ? distance_to_boundary(pair_.fixed, mid)
                                        : distance_to_curves(moving_edges_, mid);
    if (depth > eps) return true;
  }
  return false;
}

bool PlacementTester::interiors_overlap() {
  const double eps = pair_.tol.geometric;
  for (auto& s : moving_splits_) s.clear();
  for (auto& s : fixed_splits_) s.clear();
  for (size_t i = 0; i < moving_edges_.size(); ++i) {
    const Box mb = moving_boxes_[i].inflated(eps);
    for (size_t j = 0; j < fixed_edges_.size(); ++j) {
      if (!mb.overlaps(fixed_boxes_[j])) continue;
      const Intersection x = intersect(moving_edges_[i], fixed_edges_[j], eps);
      if (x.kind == IntersectionKind::overlapping && x.same_direction) return true;
      for (int h = 0; h < x.count; ++h) {
        moving_splits_[i].insert(moving_splits_[i].end(), {x.hits[h].ta0, x.hits[h].ta1});
        fixed_splits_[j].insert(fixed_splits_[j].end(), {x.hits[h].tb0, x.hits[h].tb1});
      }
    }
  }
  for (size_t i = 0; i < moving_edges_.size(); ++i)
    if (piece_inside_other(moving_edges_[i], moving_splits_[i], true)) return true;
  for (size_t j = 0; j < fixed_edges_.size(); ++j)
    if (piece_inside_other(fixed_edges_[j], fixed_splits_[j], false)) return true;
  return false;
}

bool PlacementTester::boundaries_within(double distance_limit) const {
  for (size_t i = 0; i < moving_edges_.size(); ++i) {
    const Box mb = moving_boxes_[i].inflated(distance_limit);
    for (size_t j = 0; j < fixed_edges_.size(); ++j) {
      if (!mb.overlaps(fixed_boxes_[j])) continue;
      if (distance_between(moving_edges_[i], fixed_edges_[j]) <= distance_limit) return true;
    }
  }
  return false;
}

Placement PlacementTester::classify(const Pose& pose) {
  place(pose);
  const Box reach = moving_box_.inflated(pair_.tol.contact);
  if (!reach.overlaps(pair_.fixed.box)) {
    // Far from every fixed loop: inside the material only for an enclosure.
    return pair_.fixed.enclosure ? Placement::blocked : Placement::free;
  }
  if (interiors_overlap()) return Placement::blocked;
  return boundaries_within(pair_.tol.contact) ? Placement::contact : Placement::free;
}

double PlacementTester::boundary_distance(const Pose& pose) {
  place(pose);
  double best = std::numeric_limits<double>::infinity();
  for (const Curve& m : moving_edges_)
    for (const Curve& f : fixed_edges_) best = std::min(best, distance_between(m, f));
  return best;
}

Placement classify(const Pair& pair, const Pose& pose) {
  PlacementTester tester(pair);
  return tester.classify(pose);
}

}  // namespace cslice
