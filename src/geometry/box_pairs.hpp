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

// The grid over the boxes that are not empty: cells about as large as the mean box, and
// about two per box at most.
struct BoxGridShape {
  Box all;
  size_t boxes = 0;
  int cols = 1, rows = 1;
  double per_col = 0.0, per_row = 0.0;  // cells per unit length
  // Monotone (a shift and a positive scale round monotonically), so the cell of the larger
  // of two low corners is the larger of their cells.
  int col(double x) const { return int(std::clamp((x - all.lo.x) * per_col, 0.0, cols - 1.0)); }
  int row(double y) const { return int(std::clamp((y - all.lo.y) * per_row, 0.0, rows - 1.0)); }
};

template <class BoxOf>
BoxGridShape box_grid_shape(size_t n, BoxOf box_of) {
  BoxGridShape g;
  double widths = 0.0, heights = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const Box& b = box_of(i);
    if (b.empty()) continue;
    g.all.add(b);
    widths += b.hi.x - b.lo.x;
    heights += b.hi.y - b.lo.y;
    ++g.boxes;
  }
  if (g.boxes == 0) return g;
  const double boxes = double(g.boxes);
  const double w = g.all.hi.x - g.all.lo.x, h = g.all.hi.y - g.all.lo.y;
  const double cell_side = std::sqrt(w * h / (2.0 * boxes));
  const double cell_w = std::max(widths / boxes, cell_side);
  const double cell_h = std::max(heights / boxes, cell_side);
  if (cell_w > 0.0) g.cols = int(std::clamp(std::ceil(w / cell_w), 1.0, 2.0 * boxes));
  if (cell_h > 0.0) g.rows = int(std::clamp(std::ceil(h / cell_h), 1.0, 2.0 * boxes));
  g.per_col = w > 0.0 ? g.cols / w : 0.0;
  g.per_row = h > 0.0 ? g.rows / h : 0.0;
  return g;
}

// Each box's cells, and each cell's boxes in index order (by counting), into s. False when
// the boxes cover too many cells (kBoxGridMaxCellsPerBox).
template <class BoxOf>
bool place_on_grid(size_t n, BoxOf box_of, const BoxGridShape& g, BoxGridScratch& s) {
  s.spans.resize(n);
  double covered = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const Box& b = box_of(i);
    s.spans[i] = b.empty() ? BoxGridScratch::Span{-1, -1, -1, -1}
                           : BoxGridScratch::Span{g.col(b.lo.x), g.col(b.hi.x), g.row(b.lo.y),
                                                  g.row(b.hi.y)};
    const BoxGridScratch::Span& p = s.spans[i];
    if (p.col0 >= 0) covered += double(p.col1 - p.col0 + 1) * double(p.row1 - p.row0 + 1);
  }
  if (covered > kBoxGridMaxCellsPerBox * double(g.boxes)) return false;
  const size_t cells = size_t(g.cols) * size_t(g.rows);
  const auto for_cells = [&](const BoxGridScratch::Span& p, auto&& f) {
    if (p.col0 < 0) return;
    for (int r = p.row0; r <= p.row1; ++r)
      for (int c = p.col0; c <= p.col1; ++c) f(size_t(r) * size_t(g.cols) + size_t(c));
  };
  s.start.assign(cells + 1, 0);
  for (size_t i = 0; i < n; ++i) for_cells(s.spans[i], [&](size_t cell) { ++s.start[cell + 1]; });
  for (size_t c = 0; c < cells; ++c) s.start[c + 1] += s.start[c];
  s.items.resize(size_t(s.start[cells]));
  for (size_t i = 0; i < n; ++i)
    for_cells(s.spans[i], [&](size_t cell) { s.items[size_t(s.start[cell]++)] = int(i); });
  for (size_t c = cells; c > 0; --c) s.start[c] = s.start[c - 1];
  s.start[0] = 0;
  return true;
}

// Calls visit(i, j), i < j, once for every pair of boxes that overlap by Box::overlaps (closed:
// boxes that touch overlap; an empty box overlaps none). Each pair is met in the one cell
// holding the low corner of the two boxes' common part, so it is reported once. Returns
// false, having visited nothing, when the boxes are too large for their spread
// (kBoxGridMaxCellsPerBox): the caller sweeps instead. The order of the visits is by cell,
// then i, then j: callers that need another order sort.
template <class BoxOf, class Visit>
bool for_each_overlapping_pair_on_grid(size_t n, BoxOf box_of, BoxGridScratch& s, Visit visit) {
  const BoxGridShape g = box_grid_shape(n, box_of);
  if (g.boxes < 2) return true;
  if (!place_on_grid(n, box_of, g, s)) return false;
  const size_t cells = size_t(g.cols) * size_t(g.rows);
  for (size_t cell = 0; cell < cells; ++cell) {
    const int c = int(cell % size_t(g.cols)), r = int(cell / size_t(g.cols));
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
