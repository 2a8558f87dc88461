// Sorting the short ranges a slice sorts by the thousand (each curve's split points, the
// half-edges around a vertex, the contact segments at a vertex): insertion below a few
// elements, std::sort above. For orders where only equal elements tie (all of its uses),
// the result is the one std::sort gives; insertion skips its call and setup.
#pragma once

#include <algorithm>
#include <boost/sort/pdqsort/pdqsort.hpp>
#include <cstddef>
#include <functional>

namespace cslice {

// Monotone runs shorter than this on average (a turn every this many keys or more often)
// are short (sort_by_runs).
constexpr std::ptrdiff_t kShortRunsTurnsPer = 4;
// The keys whose runs are counted: enough that smooth contours' (a turn every 6 or 7 keys)
// and rough ones' (every 2 or 3) stay well apart.
constexpr std::ptrdiff_t kRunSample = 128;

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

// Whether the keys come in monotone runs shorter than kShortRunsTurnsPer on average: one
// pass counts the turns, where an ascending run meets a descending one, over the first
// kRunSample keys. A slice's keys follow its curves' order, mostly one kind of contour
// throughout, and a wrong guess costs only time: both sorts sort. (The whole pass was 1% of
// a smooth star's slice.)
template <class It, class Less>
bool has_short_runs(It first, It last, Less less) {
  const std::ptrdiff_t n = std::min<std::ptrdiff_t>(last - first, kRunSample);
  if (n < 3) return false;
  last = first + n;
  std::ptrdiff_t turns = 0;
  bool rising = less(first[0], first[1]);
  for (It i = first + 2; i < last; ++i) {
    const bool up = less(*(i - 1), *i);
    turns += up != rising ? 1 : 0;
    rising = up;
  }
  return kShortRunsTurnsPer * turns > n;
}

// Sorts by `less` (not stably): std::sort where the keys come in long monotone runs (its
// branches then mostly go the same way, and are predicted), Boost's branch-free pdqsort
// where runs are short (comparisons that go either way, on which std::sort's branches
// were mispredicted half the time). A slice's key orders are of both kinds: smooth contours
// give runs of 6 or more on average, rough and curved ones of 2 or 3 (random keys: 1.5).
template <class It, class Less>
void sort_by_runs(It first, It last, Less less) {
  if (has_short_runs(first, last, less))
    boost::sort::pdqsort_branchless(first, last, less);
  else
    std::sort(first, last, less);
}

}  // namespace cslice
