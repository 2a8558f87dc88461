// The pairs of overlapping boxes among many, found on a uniform grid. A sweep along x, the
// usual way, meets every box whose x-range overlaps; for boxes spread around a ring (the
// contact families of a gear in a ring gear, in one bin of orientations) that was fifteen
// times the pairs that overlap. On the grid a box meets only those sharing a cell with it.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "cslice/geometry.hpp"

namespace cslice {

// The grid's lists, kept by the caller from call to call with their capacity.
struct BoxGridScratch {
  std::vector<int> start;  // per cell, where its boxes begin in `items`; one more at the end
  std::vector<int> items;  // box indices, ascending within a cell
  struct Span {
    int col0, col1, row0, row1;  // the cells a box covers, inclusive; col0 < 0: empty box
  };
  std::vector<Span> spans;
};

// A grid costs more than a sweep once the boxes cover this many cells each, on average (a
// few boxes as large as the whole are in every cell, and their pairs are met in each).
constexpr double kBoxGridMaxCellsPerBox = 8.0;

// Calls visit(i, j), i < j, once for every pair of boxes that overlap by Box::overlaps (closed:
// boxes that touch overlap; an empty box overlaps none). Each pair is met in the one cell
// holding the low corner of the two boxes' common part, so it is reported once. Returns
// false, having visited nothing, when the boxes are too large for their spread
// (kBoxGridMaxCellsPerBox): the caller sweeps instead. The order of the visits is by cell,
// then i, then j: callers that need another order sort.
template <class BoxOf, class Visit>
bool for_each_overlapping_pair_on_grid(size_t n, BoxOf box_of, BoxGridScratch& s, Visit visit) {
  Box all;
  double widths = 0.0, heights = 0.0;
  size_t boxes = 0;
  for (size_t i = 0; i < n; ++i) {
    const Box& b = box_of(i);
    if (b.empty()) continue;
    all.add(b);
    widths += b.hi.x - b.lo.x;
    heights += b.hi.y - b.lo.y;
    ++boxes;
  }
  if (boxes < 2) return true;
  // Cells about as large as the mean box, and about two per box at most.
  const double w = all.hi.x - all.lo.x, h = all.hi.y - all.lo.y;
  const double cell_area = w * h / (2.0 * double(boxes));
  const double cell_w = std::max(widths / double(boxes), std::sqrt(cell_area));
  const double cell_h = std::max(heights / double(boxes), std::sqrt(cell_area));
  const double max_axis = 2.0 * double(boxes);
  const int cols = cell_w > 0.0 ? int(std::clamp(std::ceil(w / cell_w), 1.0, max_axis)) : 1;
  const int rows = cell_h > 0.0 ? int(std::clamp(std::ceil(h / cell_h), 1.0, max_axis)) : 1;
  const double per_col = w > 0.0 ? cols / w : 0.0, per_row = h > 0.0 ? rows / h : 0.0;
  // Monotone in x (a shift and a positive scale round monotonically), so the cell of the
  // larger of two low corners is the larger of their cells.
  const auto col = [&](double x) {
    return int(std::clamp((x - all.lo.x) * per_col, 0.0, cols - 1.0));
  };
  const auto row = [&](double y) {
    return int(std::clamp((y - all.lo.y) * per_row, 0.0, rows - 1.0));
  };
  s.spans.resize(n);
  double covered = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const Box& b = box_of(i);
    if (b.empty()) {
      s.spans[i] = {-1, -1, -1, -1};
      continue;
    }
    s.spans[i] = {col(b.lo.x), col(b.hi.x), row(b.lo.y), row(b.hi.y)};
    const BoxGridScratch::Span& p = s.spans[i];
    covered += double(p.col1 - p.col0 + 1) * double(p.row1 - p.row0 + 1);
  }
  if (covered > kBoxGridMaxCellsPerBox * double(boxes)) return false;
  // Each cell's boxes in index order, by counting.
  const size_t cells = size_t(cols) * size_t(rows);
  s.start.assign(cells + 1, 0);
  const auto for_cells = [&](const BoxGridScratch::Span& p, auto&& f) {
    for (int r = p.row0; r <= p.row1; ++r)
      for (int c = p.col0; c <= p.col1; ++c) f(size_t(r) * size_t(cols) + size_t(c));
  };
  for (size_t i = 0; i < n; ++i)
    if (s.spans[i].col0 >= 0) for_cells(s.spans[i], [&](size_t cell) { ++s.start[cell + 1]; });
  for (size_t c = 0; c < cells; ++c) s.start[c + 1] += s.start[c];
  s.items.resize(size_t(s.start[cells]));
  for (size_t i = 0; i < n; ++i)
    if (s.spans[i].col0 >= 0)
      for_cells(s.spans[i], [&](size_t cell) { s.items[size_t(s.start[cell]++)] = int(i); });
  for (size_t c = cells; c > 0; --c) s.start[c] = s.start[c - 1];
  s.start[0] = 0;
  for (size_t cell = 0; cell < cells; ++cell) {
    const int c = int(cell % size_t(cols)), r = int(cell / size_t(cols));
    for (int k = s.start[cell]; k < s.start[cell + 1]; ++k) {
      const int i = s.items[size_t(k)];
      const BoxGridScratch::Span& a = s.spans[size_t(i)];
      const Box& bi = box_of(size_t(i));
      for (int m = k + 1; m < s.start[cell + 1]; ++m) {
        const int j = s.items[size_t(m)];
        const BoxGridScratch::Span& b = s.spans[size_t(j)];
        if (std::max(a.col0, b.col0) != c || std::max(a.row0, b.row0) != r) continue;
        if (bi.overlaps(box_of(size_t(j)))) visit(size_t(i), size_t(j));
      }
    }
  }
  return true;
}

}  // namespace cslice
