// Finding an angle in a list sorted by angle, round through theta = +-pi.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "cslice/geometry.hpp"

namespace cslice {

// The index of an element of `sorted` (ascending by theta_of, angles in [-pi, pi)) within
// `tolerance` of theta: of the two either side of where theta would go, the one after first,
// the first and the last being neighbours across theta = +-pi. -1 when neither is, or the
// list is empty.
template <class T, class ThetaOf>
int index_near_angle(const std::vector<T>& sorted, double theta, double tolerance,
                     ThetaOf theta_of) {
  const int n = static_cast<int>(sorted.size());
  if (n == 0) return -1;
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), theta,
                                   [&](const T& e, double t) { return theta_of(e) < t; });
  const int at = static_cast<int>(it - sorted.begin());
  for (int i : {at % n, (at + n - 1) % n})
    if (std::fabs(wrap_angle(theta_of(sorted[size_t(i)]) - theta)) <= tolerance) return i;
  return -1;
}

}  // namespace cslice
