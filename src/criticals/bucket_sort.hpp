// A comparison sort helped by a coarse key: candidates are many, and a key that splits them
// evenly (their angle, their first family) leaves each comparison sort a short run.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace cslice {

// Sorts items by `less` in two steps: a counting sort by bucket_of(item) in [0, buckets),
// which must never put an item in a lower bucket than one `less` orders before it, then each
// bucket by `less`. Items that `less` leaves unordered must be alike: the sequence is then
// that of std::sort, with fewer comparisons when the buckets split the items evenly.
template <class T, class BucketOf, class Less>
void bucket_sort(std::vector<T>& items, size_t buckets, BucketOf bucket_of, Less less) {
  std::vector<size_t> start(buckets + 1, 0);
  for (const T& x : items) ++start[bucket_of(x) + 1];
  for (size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
  std::vector<T> sorted(items.size());
  std::vector<size_t> next(start.begin(), start.end() - 1);
  for (const T& x : items) sorted[next[bucket_of(x)]++] = x;
  for (size_t b = 0; b < buckets; ++b)
    std::sort(sorted.begin() + std::ptrdiff_t(start[b]),
              sorted.begin() + std::ptrdiff_t(start[b + 1]), less);
  items = std::move(sorted);
}

}  // namespace cslice
