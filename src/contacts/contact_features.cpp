#include "contacts/contact_features.hpp"

namespace cslice {
namespace {

void from_edge(const Part& part, const Feature& f, ContactFeature& c) {
  c.kind = f.kind;
  c.edge = edge_of(part, f);
  if (f.kind == FeatureKind::segment) {
    c.normals = {f.normal_angle, 0.0};
    return;
  }
  c.center = c.edge.center;
  if (c.edge.sweep > 0.0) {
    // Material on the left of a counterclockwise arc is inside its circle: convex.
    c.rho = c.edge.radius;
    c.normals = {c.edge.start_angle, c.edge.sweep};
  } else {
    // Clockwise: material outside the circle, normals point at the centre.
    c.rho = -c.edge.radius;
    c.normals = {c.edge.start_angle + c.edge.sweep + kPi, -c.edge.sweep};
  }
}

void from_vertex(const Feature& f, bool all_normals, ContactFeature& c) {
  c.kind = FeatureKind::vertex;
  c.center = f.point;
  c.can_touch = f.convexity == Convexity::convex;
  if (!c.can_touch && !all_normals) return;
  c.normals = {f.normal_angle, std::max(0.0, f.turn)};
}

}  // namespace

std::vector<ContactFeature> contact_features(const Part& part, bool all_normals) {
  std::vector<ContactFeature> out;
  contact_features(part, all_normals, out);
  return out;
}

void contact_features(const Part& part, bool all_normals, std::vector<ContactFeature>& out) {
  // Sized first and filled in place: a feature is mostly its curve, and copying each one
  // in cost a fair share of a one-shot slice's set-up.
  out.assign(part.features.size(), ContactFeature{});
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
