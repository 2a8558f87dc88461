// Union-find whose root is always the smallest member, so the classes and their
// representatives do not depend on the order of the unions (the arrangement's vertices, the
// sliced space's cells). reset() reuses the array.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

namespace cslice {

class UnionFind {
 public:
  explicit UnionFind(size_t n = 0) { reset(n); }
  void reset(size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  // A new single-member class; returns its member.
  int add() {
    parent_.push_back(static_cast<int>(parent_.size()));
    return parent_.back();
  }
  size_t size() const { return parent_.size(); }
  int find(int a) {
    while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
    return a;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

}  // namespace cslice
