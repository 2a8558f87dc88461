// Features as contact makers: each arc or vertex is a disc boundary with a signed radius,
// each segment a straight edge, and each carries the interval of outward normals along
// which it can touch another part.
#pragma once

#include <vector>

#include "cslice/part.hpp"

namespace cslice {

// Counterclockwise angle interval [lo, lo + span], span in [0, 2pi] (a segment: span 0).
struct AngleInterval {
  double lo = 0.0;
  double span = 0.0;
};

struct ContactFeature {
  int feature = 0;  // index into Part::features
  FeatureKind kind = FeatureKind::segment;
  bool can_touch = true;  // false for reflex and smooth vertices
  Vec2 center;            // arcs: circle centre; vertices: the vertex
  double rho = 0.0;       // +r convex arc, -r concave arc, 0 vertex
  Curve edge;             // segments and arcs: the edge itself
  AngleInterval normals;  // outward normals the feature can touch along
};

std::vector<ContactFeature> contact_features(const Part& part);

}  // namespace cslice
