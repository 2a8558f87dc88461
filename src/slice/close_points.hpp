// Clustering points closer than eps, for the arrangement's vertices (arrangement.cpp,
// merge_points): a union-find whose roots do not depend on the order of the unions, and the
// cell method for clusters too dense for a sweep in x.
#pragma once

#include <numeric>
#include <vector>

#include "cslice/geometry.hpp"

namespace cslice {

// Union-find over 0 .. n - 1, reset in place so its array serves many arrangements.
class UnionFind {
 public:
  void reset(size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int a) {
    while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
    return a;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);  // the lowest index represents
  }

 private:
  std::vector<int> parent_;
};

// Unites id[a] and id[b] for every two points a, b of `points` within eps of each other
// (distance(a, b) <= eps), in O(n log n) plus about one comparison per point however densely
// they cluster. `by_cell` is scratch.
void unite_close_by_cells(const std::vector<Vec2>& points, const std::vector<int>& id, double eps,
                          UnionFind& uf, std::vector<int>& by_cell);

}  // namespace cslice
