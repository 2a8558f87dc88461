// Clustering points closer than eps, for the arrangement's vertices (arrangement.cpp,
// merge_points): the cell method for clusters too dense for a sweep in x.
#pragma once

#include <utility>
#include <vector>

#include "cslice/geometry.hpp"
#include "geometry/union_find.hpp"

namespace cslice {

// Working arrays of unite_close_by_cells, kept between calls.
struct CellScratch {
  using Cell = std::pair<long long, long long>;
  std::vector<std::pair<Cell, int>> by_cell;  // each point's cell, sorted
  std::vector<Cell> cells;                    // the distinct cells, sorted
  std::vector<size_t> first;                  // cells[k] holds by_cell[first[k] .. first[k + 1])
};

// Unites id[a] and id[b] for every two points a, b of `points` within eps of each other
// (distance(a, b) <= eps), in O(n log n) plus about one comparison per point however densely
// they cluster.
void unite_close_by_cells(const std::vector<Vec2>& points, const std::vector<int>& id, double eps,
                          UnionFind& uf, CellScratch& scratch);

}  // namespace cslice
