// The contact surface of a sliced space as a triangle mesh (paper section 2.5): the boundary
// of the free space, in (x, y, theta), stitched between consecutive slices from the known
// correspondence of contact segments (src/mesh/mesh.cpp explains the construction and its
// limits), with writers for OBJ, PLY and STL (src/mesh/mesh_io.cpp).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "cslice/space.hpp"

namespace cslice {

struct MeshOptions {
  // Partial reconstruction (paper 2.5): only triangles whose three vertices have theta in
  // [theta_from, theta_to] and (x, y) in `box` are kept. theta_from > theta_to selects the
  // range that wraps through pi. The default keeps the whole turn.
  double theta_from = -kPi;
  double theta_to = kPi;
  Box box;  // empty (the default): no box
  // Largest distance from a sampled arc to its chord (the sagitta). 0: the pair's contact
  // tolerance (recovered from the space's interpolation step, or given by the Pair overload).
  double chord_tolerance = 0.0;
};

struct MeshVertex {
  double x = 0.0, y = 0.0, theta = 0.0;
  // The feature pair of the contact segment the vertex lies on: for a vertex where two
  // boundary pieces meet, the piece that starts there. {-1, -1} for the apex of a cone that
  // closes a boundary cycle with no partner.
  SegmentLabel label{-1, -1};
};

// What the construction did, for diagnostics and tests.
struct MeshStats {
  int strips = 0;             // pairs of consecutive slices stitched
  int matched_cycles = 0;     // boundary cycles stitched to a cycle of the next slice
  int matched_pieces = 0;     // boundary pieces stitched to a piece with the same label
  int unmatched_pieces = 0;   // pieces with no partner, fanned into their neighbours' gap
  int coned_cycles = 0;       // cycles with no partner, closed by a cone (see mesh.cpp)
  int unanchored_cycles = 0;  // matched cycles sharing no label (aligned by nearest start)
  int triangles_outside = 0;  // dropped by the theta range or the box
};

struct ContactMesh {
  std::vector<MeshVertex> vertices;
  // Counterclockwise seen from outside the free space: normals point into blocked space.
  std::vector<std::array<int, 3>> triangles;
  // The surface is cut at theta = pi = -pi: each pair is (vertex at theta = pi, vertex at
  // theta = -pi) with the same (x, y), one place of the closed surface.
  std::vector<std::pair<int, int>> seam;
  double chord_tolerance = 0.0;  // the one used
  MeshStats stats;
};

ContactMesh contact_mesh(const SlicedSpace& space, const MeshOptions& options = {});
// The same, with the default chord tolerance taken from pair.tol.contact.
ContactMesh contact_mesh(const Pair& pair, const SlicedSpace& space, MeshOptions options = {});

// The volume the mesh encloses, by the divergence theorem with the field (x, y, 0) / 2, which
// has no flux through planes of constant theta: the seam needs no cap. Free volume is
// positive; a blocked island in unbounded free space counts negative.
double enclosed_volume(const ContactMesh& mesh);

// File text (ASCII), theta as the third coordinate. PLY carries each vertex's
// moving_feature and fixed_feature properties.
std::string mesh_to_obj(const ContactMesh& mesh);
std::string mesh_to_ply(const ContactMesh& mesh);
std::string mesh_to_stl(const ContactMesh& mesh, const std::string& name = "cslice");

}  // namespace cslice
