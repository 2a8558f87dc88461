// A stable counting sort by a small integer key, for the arrangement's grouping steps.
#pragma once

#include <vector>

namespace cslice {

// Groups 0 .. n - 1 by key(i) in [0, keys) (counting sort, stable): the members of group g
// are order[start[g] .. start[g + 1]), in increasing i. `fill` is a buffer.
template <class Key>
void group_by(size_t n, size_t keys, Key key, std::vector<int>& start, std::vector<int>& order,
              std::vector<int>& fill) {
  start.assign(keys + 1, 0);
  for (size_t i = 0; i < n; ++i) ++start[key(i) + 1];
  for (size_t g = 0; g < keys; ++g) start[g + 1] += start[g];
  order.resize(n);
  fill.assign(start.begin(), start.end() - 1);
  for (size_t i = 0; i < n; ++i) order[fill[key(i)]++] = int(i);
}

}  // namespace cslice
