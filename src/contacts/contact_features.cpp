#include "contacts/contact_features.hpp"

namespace cslice {
namespace {

// Each sets every field of `c`, which holds the last pair's feature when reused.
void from_edge(const Part& part, const Feature& f, ContactFeature& c) {
  c.kind = f.kind;
  c.can_touch = true;
  const Curve& edge = edge_of(part, f);
  c.from = edge.from;
  c.to = edge.to;
  if (f.kind == FeatureKind::segment) {
    c.center = {};
    c.rho = 0.0;
    c.normals = {f.normal_angle, 0.0};
    return;
  }
  c.center = edge.center;
  if (edge.sweep > 0.0) {
    // Material on the left of a counterclockwise arc is inside its circle: convex.
    c.rho = edge.radius;
    c.normals = {edge.start_angle, edge.sweep};
  } else {
    // Clockwise: material outside the circle, normals point at the centre.
    c.rho = -edge.radius;
    c.normals = {edge.start_angle + edge.sweep + kPi, -edge.sweep};
  }
}

void from_vertex(const Feature& f, bool all_normals, ContactFeature& c) {
  c.kind = FeatureKind::vertex;
  c.center = f.point;
  c.rho = 0.0;
  c.from = c.to = Vec2{};
  c.can_touch = f.convexity == Convexity::convex;
  c.normals = !c.can_touch && !all_normals ? AngleInterval{}
                                           : AngleInterval{f.normal_angle, std::max(0.0, f.turn)};
}

}  // namespace

std::vector<ContactFeature> contact_features(const Part& part, bool all_normals) {
  std::vector<ContactFeature> out;
  contact_features(part, all_normals, out);
  return out;
}

void contact_features(const Part& part, bool all_normals, std::vector<ContactFeature>& out) {
  // Sized first and filled in place, every field written once: a feature is mostly its
  // curve, and copying each one in cost a fair share of a one-shot slice's set-up, as did
  // clearing the whole array first (40% of this).
  out.resize(part.features.size());
  for (size_t i = 0; i < part.features.size(); ++i) {
    const Feature& f = part.features[i];
    ContactFeature& c = out[i];
    if (f.kind == FeatureKind::vertex)
      from_vertex(f, all_normals, c);
    else
      from_edge(part, f, c);
    c.feature = static_cast<int>(i);
  }
}

}  // namespace cslice
