#include "slice/close_points.hpp"

#include <algorithm>
#include <cmath>

namespace cslice {

// Unites every two points of `points` (`id`: their split points) within eps of each other,
// by cells eps / 2 wide. Two points of one cell are at most 0.71 eps apart: one cluster, made
// with a union per point. Points within eps lie at most 3 cells apart in x and in y, and a
// pair of cells needs no comparison once their clusters are one; otherwise their points are
// compared until one pair is within eps, which makes them one. So a cluster of many
// coincident points (a perfect fit where many contact segments meet) costs about its size,
// not its square.
void unite_close_by_cells(const std::vector<Vec2>& points, const std::vector<int>& id, double eps,
                          UnionFind& uf, CellScratch& scratch) {
  using Cell = CellScratch::Cell;
  const double h = eps / 2;
  auto& [by_cell, cells, first] = scratch;
  by_cell.clear();
  for (size_t i = 0; i < points.size(); ++i)
    by_cell.push_back({{static_cast<long long>(std::floor(points[i].x / h)),
                        static_cast<long long>(std::floor(points[i].y / h))},
                       static_cast<int>(i)});
  std::sort(by_cell.begin(), by_cell.end());
  cells.clear();
  first.clear();
  for (size_t i = 0; i < by_cell.size(); ++i) {
    if (cells.empty() || cells.back() != by_cell[i].first) {
      cells.push_back(by_cell[i].first);
      first.push_back(i);
    } else {
      uf.unite(id[by_cell[first.back()].second], id[by_cell[i].second]);
    }
  }
  first.push_back(by_cell.size());
  const auto point = [&](size_t i) { return points[by_cell[i].second]; };
  const auto member = [&](size_t i) { return id[by_cell[i].second]; };
  for (size_t k = 0; k < cells.size(); ++k)
    for (long long dx = 0; dx <= 3; ++dx)
      for (long long dy = -3; dy <= 3; ++dy) {
        if (dx == 0 && dy <= 0) continue;
        const Cell other{cells[k].first + dx, cells[k].second + dy};
        const auto it = std::lower_bound(cells.begin(), cells.end(), other);
        if (it == cells.end() || *it != other) continue;
        const size_t m = static_cast<size_t>(it - cells.begin());
        if (uf.find(member(first[k])) == uf.find(member(first[m]))) continue;
        bool joined = false;
        for (size_t i = first[k]; i < first[k + 1] && !joined; ++i)
          for (size_t j = first[m]; j < first[m + 1] && !joined; ++j)
            if (distance(point(i), point(j)) <= eps) {
              uf.unite(member(i), member(j));
              joined = true;
            }
      }
}

}  // namespace cslice
