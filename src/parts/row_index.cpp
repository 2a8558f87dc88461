#include "parts/row_index.hpp"

#include <algorithm>
#include <cmath>

#include "parts/loop_queries.hpp"

namespace cslice {

RowIndex::RowIndex(std::span<const Curve> curves) : curves_(curves.begin(), curves.end()) {
  if (curves_.empty()) return;
  Box all;
  for (const Curve& c : curves_) {
    boxes_.push_back(bounding_box(c));
    all.add(boxes_.back());
  }
  y0_ = all.lo.y;
  y1_ = all.hi.y;
  // About sqrt(n) rows: a row holds few curves, a curve spans few rows.
  const size_t rows = std::max<size_t>(1, size_t(std::sqrt(double(curves_.size()))));
  height_ = std::max((y1_ - y0_) / double(rows), std::numeric_limits<double>::min());
  rows_.resize(rows);
  for (size_t i = 0; i < curves_.size(); ++i)
    for (size_t r = row_of(boxes_[i].lo.y), last = row_of(boxes_[i].hi.y); r <= last; ++r)
      rows_[r].push_back(int(i));
  seen_.assign(curves_.size(), 0);
}

// Only curves whose box reaches p's height can toggle the parity (their chords and circular
// segments lie inside their boxes), and those are all in p's row.
bool RowIndex::encloses(Vec2 p) const {
  if (rows_.empty() || p.y < y0_ || p.y > y1_) return false;
  bool inside = false;
  for (int i : rows_[row_of(p.y)])
    if (p.y >= boxes_[i].lo.y && p.y <= boxes_[i].hi.y && toggles_parity(curves_[i], p))
      inside = !inside;
  return inside;
}

bool RowIndex::near(Vec2 p, double limit) const {
  Box around;
  around.add(p);
  around = around.inflated(limit);
  bool found = false;
  for_each_meeting(around,
                   [&](int i) { found = found || distance_to_curve(curves_[i], p) <= limit; });
  return found;
}

}  // namespace cslice
