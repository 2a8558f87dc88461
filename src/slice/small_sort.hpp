// Sorting the short ranges a slice sorts by the thousand (each curve's split points, the
// half-edges around a vertex, the contact segments at a vertex): insertion below a few
// elements, std::sort above. For orders where only equal elements tie (all of its uses),
// the result is the one std::sort gives; insertion skips its call and setup. And the long
// ones sorted by a coarse key first (bucket_sort): a coordinate, an angle, a family.
#pragma once

#include <algorithm>
#include <boost/sort/pdqsort/pdqsort.hpp>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

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

// The working arrays of bucket_sort, kept by callers that sort often.
template <class T>
struct BucketSortBuffers {
  std::vector<size_t> start, next;
  std::vector<T> sorted;
};

// Sorts items by `less` in two steps: a counting sort by bucket_of(item) in [0, buckets),
// which must never put an item in a lower bucket than one `less` orders before it, then each
// bucket by small_sort. Items that `less` leaves unordered must be alike for the sequence to
// be that of std::sort; it has fewer comparisons when the buckets split the items evenly (a
// coarse key: an angle, a coordinate, a first family).
template <class T, class BucketOf, class Less>
void bucket_sort(std::vector<T>& items, size_t buckets, BucketOf bucket_of, Less less,
                 BucketSortBuffers<T>& b) {
  b.start.assign(buckets + 1, 0);
  for (const T& x : items) ++b.start[bucket_of(x) + 1];
  for (size_t k = 0; k < buckets; ++k) b.start[k + 1] += b.start[k];
  b.sorted.resize(items.size());
  b.next.assign(b.start.begin(), b.start.end() - 1);
  for (const T& x : items) b.sorted[b.next[bucket_of(x)]++] = x;
  for (size_t k = 0; k < buckets; ++k)
    if (b.start[k + 1] - b.start[k] > 1)
      small_sort(b.sorted.begin() + std::ptrdiff_t(b.start[k]),
                 b.sorted.begin() + std::ptrdiff_t(b.start[k + 1]), less);
  items.swap(b.sorted);
}

template <class T, class BucketOf, class Less>
void bucket_sort(std::vector<T>& items, size_t buckets, BucketOf bucket_of, Less less) {
  BucketSortBuffers<T> b;
  bucket_sort(items, buckets, bucket_of, less, b);
}

// Sorts items by key(item), a coordinate spread over its range (not stably): bucket_sort into
// one bucket per item by where the key lies between the least and the greatest, a monotone
// map (each step rounds monotonically). With a NaN or infinite key, which has no bucket,
// sort_by_runs.
template <class T, class Key>
void sort_by_coordinate(std::vector<T>& items, Key key, BucketSortBuffers<T>& b) {
  const auto less = [&](const T& x, const T& y) { return key(x) < key(y); };
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  bool nan = false;
  for (const T& x : items) {
    const double k = key(x);
    nan |= k != k;
    lo = std::min(lo, k);
    hi = std::max(hi, k);
  }
  if (nan || !std::isfinite(lo) || !std::isfinite(hi) || items.size() < 2)
    return sort_by_runs(items.begin(), items.end(), less);
  const size_t buckets = items.size();
  const double per_unit = hi > lo ? double(buckets) / (hi - lo) : 0.0, last = double(buckets - 1);
  const auto bucket_of = [&](const T& x) {
    return size_t(std::min((key(x) - lo) * per_unit, last));
  };
  bucket_sort(items, buckets, bucket_of, less, b);
}

}  // namespace cslice
