// The promise of the critical orientations, checked by sampling: between two consecutive
// critical orientations every slice is equivalent to the interval's representative, and
// wherever dense samples across the circle change, a reported critical orientation lies in
// the bracket where they change. A critical orientation is a group of criticalities closer
// than the critical angle and covers their span: an interval runs from the last
// criticality of one group to the first of the next.
#pragma once

#include <string>
#include <vector>

#include "cslice/critical.hpp"

namespace cslice::testkit {

struct CompletenessOptions {
  int samples_per_interval = 50;
  int dense_samples = 720;  // uniform samples over the whole circle
  // Bisection stops when the bracket is this narrow (radians).
  double bracket = 1e-9;
  // A slice decides contact within its geometric epsilon, so near a critical orientation
  // it may still show the critical structure (near a tangency, two curves stay within
  // epsilon of each other for about sqrt(epsilon / relative curvature) radians). A real
  // change stays put when the epsilon shrinks; one that is the slice's own resolution moves
  // towards its critical orientation. Each change found is re-checked with the epsilon
  // divided by this factor (and, failing that, by its square), and counted as near-critical
  // when it left its bracket and reappeared at least halfway closer to a reported critical
  // orientation. A change of the realizable labels is followed as such: other changes of the
  // finer slices (a sliver's tip resolved as a perfect fit on and off) do not stop the search.
  double epsilon_shrink = 100.0;
};

struct CompletenessReport {
  int orientations = 0;
  int intervals = 0;
  long long slices = 0;
  // Samples inside an interval that differ from its representative, by a change that
  // stays with a finer epsilon.
  std::vector<std::string> interval_failures;
  // Changes that went away with a finer epsilon (interval samples and dense brackets
  // alike): the slice's resolution next to a critical orientation.
  int near_critical = 0;
  // Changes between dense samples with no reported critical orientation in their bracket,
  // that stay with a finer epsilon.
  std::vector<std::string> missed;
  // Orientations whose neighbouring intervals have equivalent representatives.
  int extraneous = 0;
};

// The orientation and its group's criticalities, unwrapped around its theta and sorted: the
// group's span runs from the first to the last.
std::vector<double> group_thetas(const CriticalOrientation& o);

CompletenessReport check_completeness(const Pair& pair, const CriticalSet& set,
                                      const CompletenessOptions& options = {});

}  // namespace cslice::testkit
