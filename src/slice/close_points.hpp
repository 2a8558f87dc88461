// Clustering points closer than eps, for the arrangement's vertices (arrangement.cpp,
// merge_points): the cell method for clusters too dense for a sweep in x.
#pragma once

#include <numeric>
#include <vector>

#include "cslice/geometry.hpp"
#include "geometry/union_find.hpp"

namespace cslice {

// Unites id[a] and id[b] for every two points a, b of `points` within eps of each other
// (distance(a, b) <= eps), in O(n log n) plus about one comparison per point however densely
// they cluster. `by_cell` is scratch.
void unite_close_by_cells(const std::vector<Vec2>& points, const std::vector<int>& id, double eps,
                          UnionFind& uf, std::vector<int>& by_cell);

}  // namespace cslice
