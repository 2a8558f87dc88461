// Sorting the short ranges a slice sorts by the thousand (each curve's split points, the
// half-edges around a vertex, the contact segments at a vertex): insertion below a few
// elements, std::sort above. For orders where only equal elements tie (all of its uses),
// the result is the one std::sort gives; insertion skips its call and setup.
#pragma once

#include <algorithm>
#include <functional>

namespace cslice {

template <class It, class Less = std::less<>>
void small_sort(It first, It last, Less less = {}) {
  if (last - first > 16) return std::sort(first, last, less);
  if (first == last) return;
  for (It i = first + 1; i < last; ++i) {
    auto x = std::move(*i);
    It j = i;
    for (; j > first && less(x, *(j - 1)); --j) *j = std::move(*(j - 1));
    *j = std::move(x);
  }
}

}  // namespace cslice
