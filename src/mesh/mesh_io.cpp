// Contact meshes as OBJ, PLY and STL text (all ASCII), theta as the third coordinate. Numbers
// are written with 17 significant digits, so a reader gets the doubles back exactly.
#include <cmath>
#include <cstdio>
#include <string>

#include "cslice/mesh.hpp"

namespace cslice {

namespace {

void put(std::string& out, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  out += buf;
}

void put_xyz(std::string& out, double x, double y, double z) {
  put(out, x);
  out += ' ';
  put(out, y);
  out += ' ';
  put(out, z);
}

}  // namespace

std::string mesh_to_obj(const ContactMesh& mesh) {
  std::string out = "# cslice contact mesh: x y theta\n";
  out += "# " + std::to_string(mesh.vertices.size()) + " vertices, " +
         std::to_string(mesh.triangles.size()) + " triangles\n";
  for (const MeshVertex& v : mesh.vertices) {
    out += "v ";
    put_xyz(out, v.x, v.y, v.theta);
    out += '\n';
  }
  for (const auto& t : mesh.triangles)
    out += "f " + std::to_string(t[0] + 1) + ' ' + std::to_string(t[1] + 1) + ' ' +
           std::to_string(t[2] + 1) + '\n';
  return out;
}

std::string mesh_to_ply(const ContactMesh& mesh) {
  std::string out = "ply\nformat ascii 1.0\ncomment cslice contact mesh: z is theta\n";
  out += "element vertex " + std::to_string(mesh.vertices.size()) + '\n';
  out += "property double x\nproperty double y\nproperty double z\n";
  out += "property int moving_feature\nproperty int fixed_feature\n";
  out += "element face " + std::to_string(mesh.triangles.size()) + '\n';
  out += "property list uchar int vertex_indices\nend_header\n";
  for (const MeshVertex& v : mesh.vertices) {
    put_xyz(out, v.x, v.y, v.theta);
    out += ' ' + std::to_string(v.label.moving_feature) + ' ' +
           std::to_string(v.label.fixed_feature) + '\n';
  }
  for (const auto& t : mesh.triangles)
    out += "3 " + std::to_string(t[0]) + ' ' + std::to_string(t[1]) + ' ' + std::to_string(t[2]) +
           '\n';
  return out;
}

std::string mesh_to_stl(const ContactMesh& mesh, const std::string& name) {
  std::string out = "solid " + name + '\n';
  for (const auto& t : mesh.triangles) {
    const MeshVertex &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double ux = b.x - a.x, uy = b.y - a.y, ut = b.theta - a.theta;
    const double wx = c.x - a.x, wy = c.y - a.y, wt = c.theta - a.theta;
    double nx = uy * wt - ut * wy, ny = ut * wx - ux * wt, nt = ux * wy - uy * wx;
    const double n = std::sqrt(nx * nx + ny * ny + nt * nt);
    if (n > 0.0) {
      nx /= n;
      ny /= n;
      nt /= n;
    }
    out += "  facet normal ";
    put_xyz(out, nx, ny, nt);
    out += "\n    outer loop\n";
    for (const MeshVertex* v : {&a, &b, &c}) {
      out += "      vertex ";
      put_xyz(out, v->x, v->y, v->theta);
      out += '\n';
    }
    out += "    endloop\n  endfacet\n";
  }
  out += "endsolid " + name + '\n';
  return out;
}

}  // namespace cslice
