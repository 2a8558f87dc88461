// The direct placement test.
//
// Interiors overlap exactly when (a) the boundaries share a piece that both parts travel in
// the same direction (both materials on one side), or (b) some piece of one boundary lies
// inside the other part. Pieces are the edges cut at every point where they meet the other
// boundary, so each piece is wholly inside or wholly outside the other part and its
// midpoint decides. A midpoint within the geometric epsilon of the other boundary belongs
// to a touching piece (sliding or perfect-fit contact) and decides nothing. This needs no
// case analysis of vertex contacts: an edge poking past a vertex leaves a piece inside.
//
// For large parts the curves are bucketed by height (RowIndex), which only skips curves that
// cannot matter: those out of reach of a box or a point. The moving part's index is built
// once in its body frame; points are carried into that frame instead.
#include <algorithm>

#include "cslice/classify.hpp"
#include "parts/loop_queries.hpp"
#include "parts/row_index.hpp"

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

struct PlacementTester::Indexes {
  RowIndex fixed, body;
};

PlacementTester::PlacementTester(const Pair& pair) : pair_(pair) {
  for (const Loop& loop : pair.fixed.loops)
    fixed_edges_.insert(fixed_edges_.end(), loop.edges.begin(), loop.edges.end());
  for (const Loop& loop : pair.moving.loops)
    body_edges_.insert(body_edges_.end(), loop.edges.begin(), loop.edges.end());
  indexes_ = std::make_unique<Indexes>(Indexes{RowIndex(fixed_edges_), RowIndex(body_edges_)});
  placed_at_.assign(body_edges_.size(), 0u);
  moving_edges_.resize(body_edges_.size());
  moving_boxes_.resize(body_edges_.size());
  moving_splits_.resize(body_edges_.size());
  fixed_splits_.resize(fixed_edges_.size());
}

PlacementTester::~PlacementTester() = default;

// The moving edges are placed lazily, each when first needed (a blocked placement usually
// settles on an edge or two), and their box once all are.
void PlacementTester::place(const Pose& pose) {
  placement_ = Transform(pose);
  if (++placement_count_ == 0) {  // wrapped: no stale mark may match
    std::fill(placed_at_.begin(), placed_at_.end(), 0u);
    placement_count_ = 1;
  }
  boxed_ = false;
}

void PlacementTester::place_edge(size_t i) {
  if (placed_at_[i] == placement_count_) return;
  placed_at_[i] = placement_count_;
  moving_edges_[i] = transformed(body_edges_[i], placement_);
  moving_boxes_[i] = bounding_box(moving_edges_[i]);
}

// The union in edge order, as an eager placement builds it (even the signs of zeros agree).
void PlacementTester::place_all() {
  if (boxed_) return;
  for (size_t i = 0; i < body_edges_.size(); ++i) place_edge(i);
  moving_box_ = Box{};
  for (const Box& b : moving_boxes_) moving_box_.add(b);
  boxed_ = true;
}

namespace {
// The world point p seen in the moving part's body frame.
Vec2 to_body(const Transform& t, Vec2 p) {
  const Vec2 d = p - t.offset;
  return {t.c * d.x + t.s * d.y, -t.s * d.x + t.c * d.y};
}
}  // namespace

bool PlacementTester::moving_contains(Vec2 p) const {
  return indexes_->body.encloses(to_body(placement_, p));
}

bool PlacementTester::near_moving_boundary(Vec2 p, double limit) const {
  return indexes_->body.near(to_body(placement_, p), limit);
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
    const bool inside = edge_is_moving ? indexes_->fixed.encloses(mid) != pair_.fixed.enclosure
                                       : moving_contains(mid);
    if (!inside) continue;
    const bool shallow =
        edge_is_moving ? indexes_->fixed.near(mid, eps) : near_moving_boundary(mid, eps);
    if (!shallow) return true;
  }
  return false;
}

// The answer is an "or" of independent tests, so it is settled by the first that holds, in
// any order. A moving edge's splits come only from its own meetings with the fixed edges, so
// its pieces are tested as soon as those are known: a blocked placement usually stops at the
// first edge that pokes into the fixed part, before the others are intersected (starting
// with the edge that settled the last one). The fixed edges' splits need every moving edge,
// so their pieces come last.
bool PlacementTester::interiors_overlap() {
  const double eps = pair_.tol.geometric;
  for (auto& s : moving_splits_) s.clear();
  for (auto& s : fixed_splits_) s.clear();
  const size_t n = moving_edges_.size(), first = first_edge_;
  for (size_t k = 0; k < n; ++k) {
    const size_t i = first + k < n ? first + k : first + k - n;
    place_edge(i);
    bool same_side = false;
    indexes_->fixed.for_each_meeting(moving_boxes_[i].inflated(eps), [&](int j) {
      const Intersection x = intersect(moving_edges_[i], fixed_edges_[j], eps);
      if (x.kind == IntersectionKind::overlapping && x.same_direction) same_side = true;
      for (int h = 0; h < x.count; ++h) {
        moving_splits_[i].insert(moving_splits_[i].end(), {x.hits[h].ta0, x.hits[h].ta1});
        fixed_splits_[j].insert(fixed_splits_[j].end(), {x.hits[h].tb0, x.hits[h].tb1});
      }
    });
    if (same_side || piece_inside_other(moving_edges_[i], moving_splits_[i], true)) {
      first_edge_ = i;
      return true;
    }
  }
  // A fixed edge away from the (bounded) moving part has no piece inside it.
  place_all();
  bool inside = false;
  indexes_->fixed.for_each_meeting(moving_box_.inflated(eps), [&](int j) {
    inside = inside || piece_inside_other(fixed_edges_[j], fixed_splits_[j], false);
  });
  return inside;
}

bool PlacementTester::boundaries_within(double distance_limit) const {
  bool within = false;
  for (size_t i = 0; i < moving_edges_.size() && !within; ++i) {
    indexes_->fixed.for_each_meeting(moving_boxes_[i].inflated(distance_limit), [&](int j) {
      within = within || distance_between(moving_edges_[i], fixed_edges_[j]) <= distance_limit;
    });
  }
  return within;
}

Placement PlacementTester::classify(const Pose& pose) {
  if (blocked(pose)) return Placement::blocked;
  place_all();
  if (!within_reach()) return Placement::free;
  return boundaries_within(pair_.tol.contact) ? Placement::contact : Placement::free;
}

bool PlacementTester::blocked(const Pose& pose) {
  place(pose);
  // Far from every fixed loop: inside the material only for an enclosure.
  // An edge's box lies in the moving part's box, and inflating and comparing are monotone
  // (in floating point too): if it reaches the fixed part, so does the part.
  bool reach = false;
  if (!body_edges_.empty()) {
    const size_t first = first_edge_;
    place_edge(first);
    reach = moving_boxes_[first].inflated(pair_.tol.contact).overlaps(pair_.fixed.box);
  }
  if (!reach) {
    place_all();
    if (!within_reach()) return pair_.fixed.enclosure;
  }
  return interiors_overlap();
}

bool PlacementTester::within_reach() const {
  return moving_box_.inflated(pair_.tol.contact).overlaps(pair_.fixed.box);
}

double PlacementTester::boundary_distance(const Pose& pose) {
  place(pose);
  place_all();
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
