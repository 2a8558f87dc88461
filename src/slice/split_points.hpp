// The first step of the arrangement: where its curves must be cut. Every curve's ends, every
// point where two curves meet (as the intersection step says), and points copied between
// curves that run within eps of each other, so that their pieces coincide.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "cslice/geometry.hpp"
#include "slice/small_sort.hpp"

namespace cslice {

// How the intersection step said two curves meet at a point.
enum class Meeting : char { other, tangent, crossing };

struct SplitPoint {
  int curve;
  double t;
  Vec2 p;
  int met = -1;  // the other curve, when this point is where the two touch or cross
  Meeting how = Meeting::other;
};

// Split point indices from `first` on, grouped by curve (counting sort): those of curve c are
// index[start[c] .. start[c + 1]). Rebuilt in place, so its buffers serve many slices.
struct SplitsByCurve {
  std::vector<int> start, index, fill;
  void build(const std::vector<SplitPoint>& splits, size_t first, size_t curves);
  std::span<const int> of(int c) const {
    return {index.data() + start[c], index.data() + start[c + 1]};
  }
};

// Two curves that meet, and where they may run within eps of each other: a piece shared by
// both (collinear or co-circular within eps), as parameter ranges, or, for curves meeting at
// points, their whole ranges (near = true: only points within eps of the other count).
// Segments meeting end to end at an angle (segment_pair_shortcut), most pairs of a slice, are
// kept apart as SplitScratch::end_to_end: near, and nothing else to say.
struct SharedPiece {
  int a, b;
  double a_lo, a_hi, b_lo, b_hi;
  bool near = false;
};

// A fresh split point in curve order, with where it is on its own curve once located.
struct FreshSplit {
  double t;
  int met, curve;
  Vec2 p, on_curve;
  bool located;
};

// Split points (curve, p) whose t is closest_parameter(curve, p), by the bits of p: a copy
// of p onto that curve would repeat one of them exactly (same curve, t and p), and adds
// nothing, so it is not made. Open addressing; cleared slot by slot, as few are used.
class ClosestPoints {
 public:
  // Whether (curve, p) is in the set; adds it when not.
  bool insert(int curve, Vec2 p);
  void clear();

 private:
  struct Key {
    uint64_t x, y;
    int curve;
  };
  std::vector<int> slot_;  // index + 1 into keys_, or 0
  std::vector<Key> keys_;
  std::vector<size_t> used_;
};

// Buffers of split_points, kept between calls (one per thread): small slices would
// otherwise spend more in the allocator than in the geometry.
struct SplitScratch {
  std::vector<Box> boxes;  // each curve's box grown by eps
  std::vector<int> order;  // the curves by their boxes' left x
  BucketSortBuffers<int> by_x;
  std::vector<Box> sorted;
  std::vector<std::pair<int, int>> pairs;
  std::vector<SharedPiece> shared;
  std::vector<std::pair<int, int>> end_to_end;  // segments meeting end to end at an angle
  SplitsByCurve fresh, all;
  std::vector<FreshSplit> points;
  std::vector<SplitPoint> added;
  std::vector<int> closest_hits;  // split points of shared pieces whose t is closest_parameter
  ClosestPoints copied;
  // After split_points: which of `fresh` and `all` groups every split point, as
  // SplitsByCurve::build(splits, 0, curves) would, when one does (no points were added
  // after it was built); null when neither does.
  enum class Grouped : char { none, fresh, all } grouped = Grouped::none;
  const SplitsByCurve* grouping() const {
    return grouped == Grouped::fresh ? &fresh : grouped == Grouped::all ? &all : nullptr;
  }
};

// Replaces `splits` with the split points of `curves` (each curve's two ends first, in curve
// order, then the meetings of candidate pairs, then the shared points).
void split_points(const std::vector<Curve>& curves, double eps, SplitScratch& scratch,
                  std::vector<SplitPoint>& splits);

}  // namespace cslice
