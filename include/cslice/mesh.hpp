// The contact surface of a sliced space as a triangle mesh (paper section 2.5): the boundary
// of the free space, in (x, y, theta), stitched between consecutive slices from the known
// correspondence of contact segments, through branchings at critical slices, whole or clipped
// to a theta range and a box (docs/mesh.md explains the construction, its error bound and its
// limits), with writers for OBJ, PLY and STL (src/mesh/mesh_io.cpp).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "cslice/space.hpp"

namespace cslice {

struct MeshOptions {
  // Partial reconstruction (paper 2.5): the surface clipped exactly at theta_from and
  // theta_to and at the sides of `box` (triangles crossing them are split along them).
  // theta_from > theta_to selects the range that wraps through pi. The default keeps the
  // whole turn.
  double theta_from = -kPi;
  double theta_to = kPi;
  Box box;  // empty (the default): no box
  // Largest distance from a sampled arc to its chord (the sagitta). 0: the pair's contact
  // tolerance (recovered from the space's interpolation step, or given by the Pair overload).
  double chord_tolerance = 0.0;
  // How far the surface between two slices may stray from the true one beyond the chords'
  // sagitta (docs/mesh.md). 0: the chord tolerance. With the Pair overload, a strip further
  // off than the sum of both halfway between its slices is split by the slice computed there.
  double interpolation_tolerance = 0.0;
};

struct MeshVertex {
  double x = 0.0, y = 0.0, theta = 0.0;
  // The feature pair of the contact segment the vertex lies on: for a vertex where two
  // boundary pieces meet, the piece that starts there. {-1, -1} for the apex of a cone that
  // closes a boundary cycle with no partner.
  SegmentLabel label{-1, -1};
};

// What the construction did, for diagnostics and tests (docs/mesh.md).
struct MeshStats {
  int strips = 0;             // pairs of consecutive stored slices stitched
  int matched_cycles = 0;     // boundary cycles stitched to a cycle, or walked through darts
  int matched_pieces = 0;     // boundary pieces stitched to pieces with the same label
  int unmatched_pieces = 0;   // pieces with no partner, tiled into their neighbours' gap
  int coned_cycles = 0;       // cycles with nothing to close onto, closed by a cone
  int unanchored_cycles = 0;  // matched cycles sharing no label (aligned by nearest start)
  // Across a critical slice: cycles of a vanishing component or hole closed onto the
  // degenerate point or curve they shrink to; walks joined through a degenerate contact (a
  // sliding fit opening), or by a straight edge when none joins them.
  int collapsed_to_point = 0;
  int collapsed_to_curve = 0;
  // Cycles of a critical slice with nothing on one side (a sliver that vanishes at the
  // critical orientation itself, up to round-off), closed flat in the critical slice.
  int capped_cycles = 0;
  // Pairs of triangles with the same corners in opposite orders, removed: a sheet of zero
  // thickness where a part fits an opening exactly at one orientation only (a fin).
  int cancelled_sheets = 0;
  // Cycles tiled through a branching: a cycle of the regular slice walking the pieces of
  // several cycles of the critical one (the merged cycle), or the reverse (the split one).
  int branched_cycles = 0;
  int degenerate_joins = 0;
  int straight_joins = 0;
  // Walks joined across a lens: two contact curves crossing at a shallow angle that become
  // tangent and part within the critical orientation's angle, just beyond its slice (a merge
  // or split there, not yet at it). The walk jumps along one curve between the lens's ends and
  // back along the other, so the two straight edges pair up; not a guess.
  int lens_joins = 0;
  // Refinement (Pair overload only): slices computed between stored ones, and strips left
  // further than the tolerances from the true surface because refining them would have taken
  // slices closer than side_slice_angle to a critical one (or made the stitching worse).
  int refined_slices = 0;
  int unconverged_strips = 0;
  // The largest distance, halfway between two slices, of a strip's edges from the true
  // contact curves, over the strips kept (Pair overload only; 0 otherwise).
  double max_deviation = 0.0;
  int triangles_cut = 0;      // split by the seam or by the planes of a partial reconstruction
  int triangles_outside = 0;  // dropped by the theta range or the box, after splitting
};

struct ContactMesh {
  std::vector<MeshVertex> vertices;
  // Counterclockwise seen from outside the free space: normals point into blocked space.
  std::vector<std::array<int, 3>> triangles;
  // The surface is cut at theta = pi = -pi: each pair is (vertex at theta = pi, vertex at
  // theta = -pi) with the same (x, y), one place of the closed surface.
  std::vector<std::pair<int, int>> seam;
  // The tolerances used. Where refined (the Pair overload), the surface lies within their sum
  // of the true one, and the enclosed volume within their sum times the integral of the free
  // space's perimeter over theta of the true free volume (docs/mesh.md).
  double chord_tolerance = 0.0;
  double interpolation_tolerance = 0.0;
  MeshStats stats;
};

// From the stored slices alone: the surface between two slices is interpolated, never refined.
ContactMesh contact_mesh(const SlicedSpace& space, const MeshOptions& options = {});
// The same, with the default tolerances taken from pair.tol.contact, and each strip refined
// by slices computed in between until it lies within the tolerances of the true surface.
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
