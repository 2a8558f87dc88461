// Curves bucketed into horizontal rows, so that a question about one point or one box looks
// only at the curves reaching its heights: even-odd containment, nearness, and the curves
// whose boxes meet a box. Answers are exactly those of the plain loops over all curves.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "cslice/geometry.hpp"

namespace cslice {

class RowIndex {
 public:
  RowIndex() = default;
  explicit RowIndex(std::span<const Curve> curves);

  // Even-odd containment of p in the region bounded by all the curves (closed loops).
  bool encloses(Vec2 p) const;
  // Whether some curve passes within `limit` of p.
  bool near(Vec2 p, double limit) const;
  // Calls fn(i) once for every curve i whose box meets `box`. Not reentrant (it marks the
  // curves it visits): fn must not query the same index.
  template <class Fn>
  void for_each_meeting(const Box& box, Fn fn) const {
    if (rows_.empty() || box.hi.y < y0_ || box.lo.y > y1_) return;
    ++stamp_;
    for (size_t r = row_of(box.lo.y), last = row_of(box.hi.y); r <= last; ++r) {
      for (int i : rows_[r]) {
        if (seen_[i] == stamp_ || !boxes_[i].overlaps(box)) continue;
        seen_[i] = stamp_;
        fn(i);
      }
    }
  }

 private:
  // Inline: called for both ends of every box and point looked up.
  size_t row_of(double y) const {
    const double r = std::floor((y - y0_) / height_);
    return size_t(std::clamp(r, 0.0, double(rows_.size() - 1)));
  }

  std::vector<Curve> curves_;
  std::vector<Box> boxes_;
  std::vector<std::vector<int>> rows_;
  double y0_ = 0.0, y1_ = 0.0, height_ = 1.0;
  mutable std::vector<unsigned> seen_;
  mutable unsigned stamp_ = 0;
};

}  // namespace cslice
