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
                          UnionFind& uf, std::vector<int>& by_cell) {
  using Cell = std::pair<long long, long long>;
  const double h = eps / 2;
  const auto cell = [&](int i) -> Cell {
    return {static_cast<long long>(std::floor(points[i].x / h)),
            static_cast<long long>(std::floor(points[i].y / h))};
  };
  by_cell.resize(points.size());
  std::iota(by_cell.begin(), by_cell.end(), 0);
  std::sort(by_cell.begin(), by_cell.end(), [&](int a, int b) { return cell(a) < cell(b); });
  std::vector<Cell> cells;
  std::vector<size_t> first;  // cells[k] holds by_cell[first[k] .. first[k + 1])
  for (size_t i = 0; i < by_cell.size(); ++i) {
    const Cell c = cell(by_cell[i]);
    if (cells.empty() || cells.back() != c) {
      cells.push_back(c);
      first.push_back(i);
    } else {
      uf.unite(id[by_cell[first.back()]], id[by_cell[i]]);
    }
  }
  first.push_back(by_cell.size());
  for (size_t k = 0; k < cells.size(); ++k)
    for (long long dx = 0; dx <= 3; ++dx)
      for (long long dy = -3; dy <= 3; ++dy) {
        if (dx == 0 && dy <= 0) continue;
        const Cell other{cells[k].first + dx, cells[k].second + dy};
        const auto it = std::lower_bound(cells.begin(), cells.end(), other);
        if (it == cells.end() || *it != other) continue;
        const size_t m = static_cast<size_t>(it - cells.begin());
        if (uf.find(id[by_cell[first[k]]]) == uf.find(id[by_cell[first[m]]])) continue;
        bool joined = false;
        for (size_t i = first[k]; i < first[k + 1] && !joined; ++i)
          for (size_t j = first[m]; j < first[m + 1] && !joined; ++j)
            if (distance(points[by_cell[i]], points[by_cell[j]]) <= eps) {
              uf.unite(id[by_cell[i]], id[by_cell[j]]);
              joined = true;
            }
      }
}

}  // namespace cslice
