// The direct placement test: the ground truth every faster structure is checked against.
// Places the moving part and compares it with the fixed part curve by curve; no
// precomputation beyond the pair itself, so it is simple enough to be obviously right.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "cslice/pair.hpp"

namespace cslice {

enum class Placement { free, contact, blocked };

std::string_view to_string(Placement p);

// Blocked when the interiors of the placed moving part and the fixed part overlap (by more
// than the geometric epsilon); contact when they do not overlap but come within the pair's
// contact tolerance; free otherwise.
Placement classify(const Pair& pair, const Pose& pose);

// The same test with reusable scratch memory, for many queries on one pair.
class PlacementTester {
 public:
  explicit PlacementTester(const Pair& pair);
  ~PlacementTester();
  // Not copyable: the indexes carry scratch state; make one tester per thread.
  PlacementTester(const PlacementTester&) = delete;
  PlacementTester& operator=(const PlacementTester&) = delete;
  Placement classify(const Pose& pose);
  // classify(pose) == Placement::blocked, without measuring clearance when it is not.
  bool blocked(const Pose& pose);
  // Smallest distance between the placed boundaries (0 when they meet).
  double boundary_distance(const Pose& pose);

 private:
  void place(const Pose& pose);
  void place_edge(size_t i);  // moving edge i and its box, once per placement
  void place_all();           // every moving edge, and the moving part's box
  // Whether the placed moving part comes within the contact tolerance of the fixed part's box.
  bool within_reach() const;
  bool interiors_overlap();
  bool boundaries_within(double distance_limit) const;
  bool moving_contains(Vec2 p) const;
  bool near_moving_boundary(Vec2 p, double limit) const;
  bool piece_inside_other(const Curve& edge, std::vector<double>& splits,
                          bool edge_is_moving) const;

  struct Indexes;  // curves bucketed by height (src/parts/row_index.hpp)

  const Pair& pair_;
  std::vector<Curve> fixed_edges_;
  std::vector<Curve> body_edges_;    // moving part in its body frame
  std::vector<Curve> moving_edges_;  // placed copy, rebuilt per query
  std::vector<Box> moving_boxes_;
  Box moving_box_;
  Transform placement_;
  std::vector<unsigned> placed_at_;  // per moving edge, the placement_count_ it was placed for
  unsigned placement_count_ = 1;
  bool boxed_ = false;  // moving_box_ is the union of every placed box
  // The moving edge that settled the last blocked placement: tried first next time, since
  // the placements tested in a row are mostly near each other. The answer does not depend
  // on the order (interiors_overlap).
  size_t first_edge_ = 0;
  std::unique_ptr<Indexes> indexes_;  // of the fixed part, and of the moving body
  std::vector<std::vector<double>> moving_splits_, fixed_splits_;  // reused scratch
};

}  // namespace cslice
