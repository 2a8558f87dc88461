// Which pairs and triples of contact families can meet, and at which orientations: theta is
// cut into bins, each family alive in a bin gets its cover at the bin's middle and a margin
// for how far its contact segments drift within the bin, and only families whose covers come
// within their margins are paired (a sweep along x). A pair or triple remembers the bins
// where it may meet, so that a root of its equation elsewhere is dropped unvalidated.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "criticals/families.hpp"

namespace cslice {

// Equal bins over the whole turn [-pi, pi), or over an arc of it: a symmetric pair's
// fundamental domain, whose images are the rest.
struct Binning {
  int count = 1;
  double from = -kPi;
  double width = kTwoPi;
  bool whole_turn = true;

  explicit Binning(int bins);
  // `bins` bins over [from, from + span], span < 2 pi.
  Binning(int bins, double from, double span);
  // The bin holding theta; off an arc, the bin at its nearer end.
  int bin_of(double theta) const;
  double lower(int bin) const { return from + bin * width; }
};

// A family alive in a bin: its cover at the bin's middle orientation, how far its contact
// segments can stray from that cover within the bin, and the box holding them all.
struct BinEntry {
  int family = 0;
  Curve cover;
  double margin = 0.0;
  Box box;
};

// The families alive in each bin (indices, ascending).
std::vector<std::vector<int>> alive_families_by_bin(const std::vector<ContactFamily>& families,
                                                    const Binning& binning);

// Where the whole curves two covers lie on cross (the full circle of an arc; the line of a
// segment, as far as 4 sizes past its ends), each crossing with the sine of the angle between
// the curves there. Covers drift within a bin, so two of them can come to cross anywhere
// their whole curves cross, not only where the covers themselves cross at the bin's middle.
// Written out per pair of shapes: whole curves need none of the arc parameters and end tests
// of `intersect`, which were most of the meeting pass. False when the curves do not cross,
// run together, or touch within eps (a tangency, crossing at angle ~0): no bound then.
struct CurveCrossings {
  int count = 0;
  std::array<Vec2, 2> point{};
  std::array<double, 2> sine{};
};
bool whole_curves_cross(const Curve& x, const Curve& y, double size, double eps,
                        CurveCrossings& out);

// The entries of one bin, sorted by the left side of their boxes.
std::vector<BinEntry> bin_entries(const std::vector<ContactFamily>& families,
                                  const std::vector<int>& alive, const Binning& binning, int bin,
                                  double tolerance);

// A pair (c = -1) or triple of family indices, ascending, and a bin where they may meet.
struct MeetingCandidate {
  int a = 0, b = 0, c = -1;
  int bin = 0;
  friend auto operator<=>(const MeetingCandidate&, const MeetingCandidate&) = default;
};

// Where a bin lies and what its meeting test needs besides the entries: the families (their
// shared ends bound where a triple can be), the criticality tolerance, the geometric epsilon
// for crossings, and the pair's size (a crossing so shallow that it could drift across all of
// it gives no bound).
struct BinScope {
  const std::vector<ContactFamily>* families = nullptr;
  Binning binning{1};
  int bin = 0;
  double tolerance = 0.0, geometric = 0.0, size = 1.0;
};

// The pairs and triples of one bin's entries that may meet within it.
void meeting_candidates(const std::vector<BinEntry>& entries, const BinScope& scope,
                        std::vector<MeetingCandidate>& pairs,
                        std::vector<MeetingCandidate>& triples);

// Candidates grouped: each distinct pair or triple once, with the bins where it may meet as
// at most two runs of consecutive bins (fixed size: there are millions of triples on large
// pairs). A third run merges into the second, gap included: more bins, never fewer.
struct MeetingTask {
  int a = 0, b = 0, c = -1;
  std::array<std::array<int, 2>, 2> runs{};  // [first, last] bins, ascending
  int run_count = 0;

  // Bins arrive in ascending order.
  void add_run(int first, int last);
  void add_bin(int bin) { add_run(bin, bin); }
  // Whether theta lies in one of the runs, widened by `slack` radians. Inline: it is asked of
  // every root.
  bool near(const Binning& binning, double theta, double slack) const {
    for (int r = 0; r < run_count; ++r) {
      const double d = ccw_turn(binning.lower(runs[r][0]), theta);
      const double span = (runs[r][1] - runs[r][0] + 1) * binning.width;
      if (d <= span + slack || d >= kTwoPi - slack) return true;
    }
    return false;
  }
  // The runs as windows of orientations, each widened by twice `slack` (once for `near`,
  // once for a root's own round-off): roots outside them would all be culled.
  int windows(const Binning& binning, double slack, std::array<AngleWindow, 2>& out) const;
};

// Sorted by (a, b, c); `candidates` is sorted on the way.
std::vector<MeetingTask> group_candidates(std::vector<MeetingCandidate>& candidates);

// Merges `later` (whose bins all come after those of `tasks`) into `tasks`, both sorted.
void merge_tasks(std::vector<MeetingTask>& tasks, const std::vector<MeetingTask>& later);

}  // namespace cslice
