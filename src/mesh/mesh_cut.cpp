// Plane cuts of the contact mesh: the seam at theta = pi = -pi, and partial reconstruction
// (paper section 2.5), which clips the surface exactly at the planes of a theta range and of a
// box. A triangle that crosses a plane is split along it, one new vertex per cut edge shared
// by the triangles on both sides, so the pieces tile the triangle exactly and the surface
// stays watertight away from the cut.
#include <algorithm>
#include <map>
#include <tuple>

#include "mesh/mesh_internal.hpp"

namespace cslice::mesh_detail {

namespace {

double& coordinate(MeshVertex& v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.theta;
}
double coordinate(const MeshVertex& v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.theta;
}

int side(const MeshVertex& v, int axis, double value) {
  const double c = coordinate(v, axis);
  return c < value ? -1 : c > value ? 1 : 0;
}

class PlaneSplitter {
 public:
  PlaneSplitter(std::vector<MeshVertex>& vertices, int axis, double value)
      : vertices_(vertices), axis_(axis), value_(value) {}

  // Appends t, or its pieces on either side; returns whether it was split.
  bool split(Triangle t, std::vector<Triangle>& out) {
    int s[3];
    for (int k = 0; k < 3; ++k) s[k] = side(vertices_[t[k]], axis_, value_);
    const bool below = s[0] < 0 || s[1] < 0 || s[2] < 0;
    const bool above = s[0] > 0 || s[1] > 0 || s[2] > 0;
    if (!(below && above)) {
      out.push_back(t);
      return false;
    }
    const int on = (s[0] == 0) + (s[1] == 0) + (s[2] == 0);
    // Rotate (keeping orientation) so that t[0] is the vertex on the plane, or the one alone
    // on its side.
    const auto lone = [&](int k) {
      if (on == 1) return s[k] == 0;
      return s[k] != s[(k + 1) % 3] && s[k] != s[(k + 2) % 3];
    };
    int r = 0;
    while (!lone(r)) ++r;
    std::rotate(t.begin(), t.begin() + r, t.end());
    if (on == 1) {
      const int c = cut(t[1], t[2]);
      out.push_back({t[0], t[1], c});
      out.push_back({t[0], c, t[2]});
      return true;
    }
    const int c1 = cut(t[0], t[1]), c2 = cut(t[0], t[2]);
    out.push_back({t[0], c1, c2});
    out.push_back({c1, t[1], t[2]});
    out.push_back({c1, t[2], c2});
    return true;
  }

 private:
  std::vector<MeshVertex>& vertices_;
  int axis_;
  double value_;
  std::map<std::pair<int, int>, int> cuts_;

  // The point of edge (u, w) on the plane, one vertex for both triangles sharing the edge.
  // Interpolated from the end first in (x, y, theta) order, so that the two copies of an edge
  // on either side of the seam (same x and y, theta pi and -pi) are cut at the same (x, y).
  int cut(int u, int w) {
    const auto key = std::minmax(u, w);
    const auto it = cuts_.find(key);
    if (it != cuts_.end()) return it->second;
    MeshVertex a = vertices_[key.first], b = vertices_[key.second];
    if (std::tie(b.x, b.y, b.theta) < std::tie(a.x, a.y, a.theta)) std::swap(a, b);
    const double t =
        (value_ - coordinate(a, axis_)) / (coordinate(b, axis_) - coordinate(a, axis_));
    MeshVertex v{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.theta + t * (b.theta - a.theta),
                 a.label};
    coordinate(v, axis_) = value_;
    vertices_.push_back(v);
    return cuts_[key] = static_cast<int>(vertices_.size()) - 1;
  }
};

}  // namespace

int split_by_plane(std::vector<MeshVertex>& vertices, std::vector<Triangle>& triangles, int axis,
                   double value, double snap) {
  std::vector<char> used(vertices.size(), 0);
  for (const Triangle& t : triangles)
    for (int v : t) used[v] = 1;
  for (size_t v = 0; v < used.size(); ++v)
    if (used[v] && std::fabs(coordinate(vertices[v], axis) - value) <= snap)
      coordinate(vertices[v], axis) = value;
  PlaneSplitter splitter(vertices, axis, value);
  std::vector<Triangle> out;
  out.reserve(triangles.size());
  int split = 0;
  for (const Triangle& t : triangles) split += splitter.split(t, out);
  triangles = std::move(out);
  return split;
}

void cut_seam(ContactMesh& mesh, const std::vector<int>& original, double snap) {
  std::vector<MeshVertex>& vs = mesh.vertices;
  mesh.stats.triangles_cut += split_by_plane(vs, mesh.triangles, 2, kPi, snap);
  // Decided for every triangle before any vertex moves.
  std::vector<char> beyond(mesh.triangles.size());
  for (size_t k = 0; k < beyond.size(); ++k) {
    const Triangle& t = mesh.triangles[k];
    beyond[k] = vs[t[0]].theta > kPi || vs[t[1]].theta > kPi || vs[t[2]].theta > kPi;
  }
  std::vector<int> moved(vs.size(), -1);  // vertex -> its place below the seam
  for (size_t k = 0; k < beyond.size(); ++k) {
    if (!beyond[k]) continue;
    for (int& v : mesh.triangles[k]) {
      if (moved[v] < 0) {
        if (v < static_cast<int>(original.size()) && original[v] >= 0) {
          moved[v] = original[v];  // the first slice's copy at theta + 2 pi: the slice itself
        } else if (vs[v].theta == kPi) {
          MeshVertex d = vs[v];
          d.theta = -kPi;
          vs.push_back(d);
          moved[v] = static_cast<int>(vs.size()) - 1;
          moved.push_back(-1);
          mesh.seam.push_back({v, moved[v]});
        } else {
          vs[v].theta -= kTwoPi;
          moved[v] = v;
        }
      }
      v = moved[v];
    }
  }
  // Where the first slice lies on the seam, its copy at pi stays as the other side of it.
  for (size_t v = 0; v < original.size(); ++v)
    if (original[v] >= 0 && vs[v].theta == kPi)
      mesh.seam.push_back({static_cast<int>(v), original[v]});
}

// A plane that cuts the seam cuts each pair of its edges at the same (x, y), computed alike
// from the same end points: such new vertices at pi and -pi are paired like the others.
void pair_seam_cuts(ContactMesh& mesh) {
  std::map<std::pair<double, double>, int> at_minus_pi;
  std::vector<char> paired(mesh.vertices.size(), 0);
  for (auto [a, b] : mesh.seam) paired[a] = paired[b] = 1;
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!paired[v] && mesh.vertices[v].theta == -kPi)
      at_minus_pi[{mesh.vertices[v].x, mesh.vertices[v].y}] = static_cast<int>(v);
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (paired[v] || mesh.vertices[v].theta != kPi) continue;
    const auto it = at_minus_pi.find({mesh.vertices[v].x, mesh.vertices[v].y});
    if (it != at_minus_pi.end()) mesh.seam.push_back({static_cast<int>(v), it->second});
  }
}

void clip(ContactMesh& mesh, const MeshOptions& o, double theta_snap, double xy_snap) {
  const bool range = o.theta_from > -kPi || o.theta_to < kPi;
  int& cut = mesh.stats.triangles_cut;
  if (range) {
    cut += split_by_plane(mesh.vertices, mesh.triangles, 2, o.theta_from, theta_snap);
    cut += split_by_plane(mesh.vertices, mesh.triangles, 2, o.theta_to, theta_snap);
  }
  const Box& box = o.box;
  if (!box.empty()) {
    cut += split_by_plane(mesh.vertices, mesh.triangles, 0, box.lo.x, xy_snap);
    cut += split_by_plane(mesh.vertices, mesh.triangles, 0, box.hi.x, xy_snap);
    cut += split_by_plane(mesh.vertices, mesh.triangles, 1, box.lo.y, xy_snap);
    cut += split_by_plane(mesh.vertices, mesh.triangles, 1, box.hi.y, xy_snap);
  }
  const size_t split = mesh.triangles.size();
  // After the splits no triangle has vertices strictly on both sides of a plane: it is inside
  // when none of its vertices is strictly outside (a vertex on a plane is on both sides).
  const auto vertex_in = [&](const MeshVertex& v, bool low_part) {
    const bool in_range = o.theta_from <= o.theta_to
                              ? v.theta >= o.theta_from && v.theta <= o.theta_to
                              : (low_part ? v.theta <= o.theta_to : v.theta >= o.theta_from);
    return in_range && (box.empty() ||
                        (v.x >= box.lo.x && v.x <= box.hi.x && v.y >= box.lo.y && v.y <= box.hi.y));
  };
  const auto inside = [&](const Triangle& t) {
    for (bool low_part : {false, true})
      if (vertex_in(mesh.vertices[t[0]], low_part) && vertex_in(mesh.vertices[t[1]], low_part) &&
          vertex_in(mesh.vertices[t[2]], low_part))
        return true;
    return false;
  };
  std::erase_if(mesh.triangles, [&](const Triangle& t) { return !inside(t); });
  mesh.stats.triangles_outside += static_cast<int>(split - mesh.triangles.size());
  pair_seam_cuts(mesh);
}

void compact(ContactMesh& mesh) {
  std::vector<int> index(mesh.vertices.size(), -1);
  std::vector<MeshVertex> vertices;
  for (Triangle& t : mesh.triangles)
    for (int& v : t) {
      if (index[v] < 0) {
        index[v] = static_cast<int>(vertices.size());
        vertices.push_back(mesh.vertices[v]);
      }
      v = index[v];
    }
  std::vector<std::pair<int, int>> seam;
  for (auto [a, b] : mesh.seam)
    if (index[a] >= 0 && index[b] >= 0) seam.push_back({index[a], index[b]});
  std::sort(seam.begin(), seam.end());
  seam.erase(std::unique(seam.begin(), seam.end()), seam.end());
  mesh.vertices = std::move(vertices);
  mesh.seam = std::move(seam);
}

}  // namespace cslice::mesh_detail
