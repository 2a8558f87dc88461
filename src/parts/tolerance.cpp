#include "cslice/tolerance.hpp"

#include <algorithm>

namespace cslice {

Tolerances make_tolerances(double size, std::optional<double> user_tolerance) {
  Tolerances t;
  t.size = size;
  t.geometric = kRelativeGeometricEpsilon * size;
  t.contact = std::max(user_tolerance.value_or(kDefaultRelativeTolerance * size), t.geometric);
  t.angular = kRelativeGeometricEpsilon;
  t.criticality = kCriticalityPerGeometric * t.geometric;
  t.critical_angle = kCriticalityPerGeometric * t.angular;
  return t;
}

}  // namespace cslice
