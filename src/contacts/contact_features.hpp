// Features as contact makers: each arc or vertex is a disc boundary with a signed radius,
// each segment a straight edge, and each carries the interval of outward normals along
// which it can touch another part.
#pragma once

#include <vector>

#include "cslice/slice.hpp"

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

// One per feature of the part, in feature order (element i describes feature i).
std::vector<ContactFeature> contact_features(const Part& part);

// Whether a feature pair can touch at some orientation (local overlap filtering by
// convexity; the normal sets decide at which orientations): reflex vertices, segment pairs,
// concave pairs, vertex pairs and convex features too big for a concave one never touch.
bool pair_can_touch(const ContactFeature& m, const ContactFeature& f, double eps);
ContactKind contact_kind(const ContactFeature& m, const ContactFeature& f);

// Appends the contact segments of one feature pair at theta (none when the pair cannot
// touch there), by the rules contact_segments applies to every pair; ids continue from
// out.size().
void add_pair_contacts(const Pair& pair, const ContactFeature& m, const ContactFeature& f,
                       double theta, std::vector<ContactSegment>& out);

}  // namespace cslice
