#include "support/completeness.hpp"

#include <algorithm>
#include <cstdio>

#include "cslice/equivalence.hpp"

namespace cslice::testkit {

namespace {

std::string describe(double theta, const std::string& what) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "theta %.17g: ", theta);
  return buf + what;
}

// The feature pairs of the realizable contact segments, sorted, each as often as it occurs.
std::vector<std::pair<int, int>> realizable_labels(const Slice& s) {
  std::vector<std::pair<int, int>> out;
  for (int id : s.contact_graph.nodes)
    out.emplace_back(s.contact_segments[id].moving_feature, s.contact_segments[id].fixed_feature);
  std::sort(out.begin(), out.end());
  return out;
}

struct Checker {
  const Pair& pair;
  const std::vector<Pair>& finer;        // the pair with finer and finer geometric epsilons
  const Pair* fine = nullptr;            // the pair with a finer geometric epsilon
  const std::vector<double>& criticals;  // sorted, in [-pi, pi)
  // Per critical orientation, the first and last of its grouped criticalities, unwrapped
  // around its theta (lo <= theta <= hi): the orientation covers that span.
  const std::vector<std::pair<double, double>>& spans;
  const CompletenessOptions& options;
  CompletenessReport& report;

  using Slicer = Slice (Checker::*)(double);

  Slice slice(double theta) {
    ++report.slices;
    return compute_slice(pair, theta);
  }

  Slice fine_slice(double theta) {
    ++report.slices;
    return compute_slice(*fine, theta);
  }

  // Whether a reported critical orientation (the span of its group) meets [lo, hi]
  // (hi - lo < 2 pi, lo may be below -pi), widened by the angular tolerance.
  bool critical_within(double lo, double hi) const {
    const double slack = pair.tol.angular;
    for (const auto& [first, last] : spans)
      for (double shift : {-kTwoPi, 0.0, kTwoPi})
        if (last + shift >= lo - slack && first + shift <= hi + slack) return true;
    return false;
  }

  // Bisects [lo, hi], where the slices differ, down to the bracket width; `known` is the
  // slice at lo (from_low) or at hi.
  // With by_labels, slices count as the same when their realizable labels are.
  std::pair<double, double> narrow(double lo, double hi, const Slice& known, bool from_low,
                                   Slicer make = &Checker::slice, bool by_labels = false) {
    Slice end = known;
    while (hi - lo > options.bracket) {
      const double mid = 0.5 * (lo + hi);
      Slice m = (this->*make)(mid);
      const bool same = by_labels ? realizable_labels(end) == realizable_labels(m)
                                  : slices_equivalent(end, m).equivalent;
      if (same == from_low)
        lo = mid;
      else
        hi = mid;
      if (same) end = std::move(m);
    }
    return {lo, hi};
  }

  // Whether the change in the narrow bracket [a, b] is the slice's resolution next to a
  // reported critical orientation c: with a finer epsilon it must leave the bracket and
  // reappear at least halfway closer to c, or at c itself. A real change stays put.
  // A change of the realizable labels is followed as such with the finer epsilon: a sliver
  // narrower than the epsilon for a long turn (designed pairs 9912 and 10740: one growing
  // like the cube of the turn after an exact alignment) shows its own tip as a perfect fit on
  // and off at the finer epsilons, changes of the slice that are not the one followed.
  bool resolution_artifact(double a, double b) {
    const bool by_labels = realizable_labels(slice(a)) != realizable_labels(slice(b));
    for (const Pair& p : finer) {
      fine = &p;
      if (moves_towards_critical(a, b, by_labels)) return true;
    }
    return false;
  }

  bool moves_towards_critical(double a, double b, bool by_labels) {
    if (criticals.empty() || !slices_equivalent(fine_slice(a), fine_slice(b)).equivalent)
      return false;
    const double m = 0.5 * (a + b);
    double d = kPi;  // signed angle from m to the nearest critical orientation
    for (double c : criticals)
      if (std::fabs(wrap_angle(c - m)) < std::fabs(d)) d = wrap_angle(c - m);
    const double margin = 2.0 * pair.tol.critical_angle;
    if (std::fabs(d) <= 2.0 * margin) return true;
    const double q = m + d - std::copysign(margin, d);
    const Slice at_m = fine_slice(m);
    if (slices_equivalent(at_m, fine_slice(q)).equivalent) return true;  // the change is at c
    const auto [x, y] = d > 0 ? narrow(m, q, at_m, true, &Checker::fine_slice, by_labels)
                              : narrow(q, m, at_m, false, &Checker::fine_slice, by_labels);
    return std::fabs(m + d - 0.5 * (x + y)) <= 0.5 * std::fabs(d);
  }

  void check_intervals() {
    const size_t n = criticals.size();
    report.intervals = int(std::max<size_t>(n, 1));
    std::vector<Slice> representatives;
    for (size_t i = 0; i < std::max<size_t>(n, 1); ++i) {
      // Between the groups: a slice inside a group's span is that critical orientation's.
      const double lo = n ? spans[i].second : -kPi;
      const double hi = n ? (i + 1 < n ? spans[i + 1].first : spans[0].first + kTwoPi) : kPi;
      const double mid = lo + (hi - lo) * 0.5;
      const int k = options.samples_per_interval;
      const Slice rep = slice(mid);
      for (int s = 0; s < k; ++s) {
        const double theta = lo + (hi - lo) * (s + 0.5) / k;
        const EquivalenceResult r = slices_equivalent(rep, slice(theta));
        if (r.equivalent) continue;
        // Where between the middle and the sample does the slice change?
        const auto [a, b] =
            theta < mid ? narrow(theta, mid, rep, false) : narrow(mid, theta, rep, true);
        if (resolution_artifact(a, b))
          ++report.near_critical;
        else
          report.interval_failures.push_back(
              describe(theta, "differs from its interval's middle: " + r.difference));
      }
      representatives.push_back(rep);
    }
    for (size_t i = 0; i < n; ++i) {
      const Slice& before = representatives[(i + n - 1) % n];
      if (slices_equivalent(before, representatives[i]).equivalent) ++report.extraneous;
    }
  }

  void check_dense() {
    const int k = options.dense_samples;
    Slice prev = slice(-kPi);
    for (int s = 1; s <= k; ++s) {
      const double lo = -kPi + kTwoPi * (s - 1) / k, hi = -kPi + kTwoPi * s / k;
      Slice next = slice(hi);
      const EquivalenceResult r = slices_equivalent(prev, next);
      if (!r.equivalent && !critical_within(lo, hi)) {
        const auto [a, b] = narrow(lo, hi, prev, true);
        if (critical_within(a, b))
          ;  // a reported change, seen between its neighbours' samples
        else if (resolution_artifact(a, b))
          ++report.near_critical;
        else
          report.missed.push_back(describe(0.5 * (a + b),
                                           "change with no critical orientation "
                                           "in a bracket this wide: " +
                                               r.difference));
      }
      prev = std::move(next);
    }
  }
};

}  // namespace

std::vector<double> group_thetas(const CriticalOrientation& o) {
  std::vector<double> at{o.theta};
  for (const Criticality& k : o.criticalities)
    at.push_back(o.theta + wrap_angle(k.theta - o.theta));
  std::sort(at.begin(), at.end());
  return at;
}

CompletenessReport check_completeness(const Pair& pair, const CriticalSet& set,
                                      const CompletenessOptions& options) {
  CompletenessReport report;
  std::vector<double> criticals;
  std::vector<std::pair<double, double>> spans;
  for (const CriticalOrientation& o : set.orientations) {
    criticals.push_back(o.theta);
    // The span is trusted only as the grouping rule makes it: a chain of criticalities
    // each within the critical angle of the next.
    const std::vector<double> at = group_thetas(o);
    for (size_t k = 1; k < at.size(); ++k)
      if (at[k] - at[k - 1] > pair.tol.critical_angle)
        report.interval_failures.push_back(
            describe(o.theta, "a gap in its group wider than the critical angle"));
    spans.push_back({at.front(), at.back()});
  }
  report.orientations = int(criticals.size());
  std::vector<Pair> finer(2, pair);
  finer[0].tol.geometric /= options.epsilon_shrink;
  finer[1].tol.geometric = finer[0].tol.geometric / options.epsilon_shrink;
  Checker checker{pair, finer, nullptr, criticals, spans, options, report};
  checker.check_intervals();
  checker.check_dense();
  return report;
}

}  // namespace cslice::testkit
