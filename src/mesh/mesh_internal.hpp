// Internals of the contact-surface mesh (src/mesh, docs/mesh.md): sampled slices, the bands
// of the correspondence between two slices, tiling, and plane cuts. Not a public header.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "cslice/mesh.hpp"

namespace cslice::mesh_detail {

using Triangle = std::array<int, 3>;

// The vertices of the mesh under construction, with what the stages below need to know of
// each besides its position and label.
struct VertexStore {
  std::vector<MeshVertex>& vertices;
  // Per vertex: the label of the boundary piece that ends there ({-1, -1} inside a piece),
  // so that a corner knows both contact segments it lies on.
  std::vector<SegmentLabel> end_label;

  explicit VertexStore(std::vector<MeshVertex>& v) : vertices(v) {}
  int add(Vec2 p, double theta, SegmentLabel label) {
    vertices.push_back({p.x, p.y, theta, label});
    end_label.push_back({-1, -1});
    return static_cast<int>(vertices.size()) - 1;
  }
  Vec2 xy(int v) const { return {vertices[v].x, vertices[v].y}; }
};

// A boundary piece (or a degenerate dart) of one slice, sampled: a polyline from its start
// corner to its end corner, running with free space on its left. `offset` is each vertex's
// material coordinate (a length) from the start: along the contact segment for a line, along
// the contact circle (by world angle) for an arc, so that the vertices of two slices with the
// same coordinate are the same point of the moving or fixed feature (docs/mesh.md).
struct Piece {
  SegmentLabel label{-1, -1};
  Curve curve;
  std::vector<int> verts;
  std::vector<double> offset;
  double start = 0.0;   // absolute material coordinate of the start
  double period = 0.0;  // for arcs, 2 pi r: absolute coordinates are taken modulo it
  double length() const { return offset.empty() ? 0.0 : offset.back(); }
  int first() const { return verts.front(); }
  int last() const { return verts.back(); }
};

// A degenerate point of contact space in a slice (a perfect fit, or a free region shrunk to
// a point): where a vanishing boundary cycle closes.
struct DegeneratePoint {
  int vertex = 0;
  std::vector<SegmentLabel> labels;
};

struct SampledSlice {
  double theta = 0.0;  // of its vertices (theta + 2 pi for the copy of the first slice)
  const Slice* slice = nullptr;
  const CriticalTransition* transition = nullptr;  // set for a critical slice
  std::vector<Piece> pieces;  // every boundary piece, then every degenerate dart
  int boundary_pieces = 0;    // pieces [0, boundary_pieces) lie on boundary cycles
  // Per free component, per boundary cycle: its pieces in order.
  std::vector<std::vector<std::vector<int>>> cycles;
  std::vector<int> cells;       // per free component: its cell, -1 in a critical slice
  std::vector<int> components;  // per free component: its 3D component (-1 if unknown)
  std::vector<DegeneratePoint> points;
  // Per piece of a critical slice: the labels of the other contact segments that run along
  // all of it (find_coinciding_labels); empty elsewhere.
  std::vector<std::vector<SegmentLabel>> coinciding;
  bool critical() const { return transition != nullptr; }
};

struct SamplingOptions {
  double chord_tolerance = 0.0;  // largest sagitta of an arc's chord
  // Longest chord of a line that turns with theta (a moving segment's contact), so that the
  // strips on either side stay within the tolerance despite the twist (docs/mesh.md).
  double twist_chord = 0.0;
  // Whether corners of different boundary cycles within the epsilon are one vertex: in a
  // critical slice (a pinch walked through), not in a regular one (mesh_sample.cpp).
  bool weld_across_cycles = true;
};

// Samples every boundary piece and degenerate contact of a slice into mesh vertices at
// `theta`, welding corners closer than the slice's epsilon.
SampledSlice sample_slice(const Slice& slice, double theta, const SamplingOptions& options,
                          VertexStore& store);

// At a critical slice two contact segments may coincide along a piece, which bears only the
// lowest one's label (ContactPiece) while a regular slice on either side bears the other:
// fills SampledSlice::coinciding.
void find_coinciding_labels(SampledSlice& s);

// One band of a strip between two slices: the lower polyline (at the lower slice) and the
// upper one, both running the same way with free space on their left, tiled into triangles.
// When both carry coordinates (the same contact segment on both sides, in one frame), the
// tiling advances by coordinate, otherwise by arc-length fraction.
struct Band {
  std::vector<int> lower, upper;
  std::vector<double> lower_coord, upper_coord;  // empty, or one per vertex
};

// What stitching one strip produced and how.
struct StripResult {
  std::vector<Band> bands;
  std::vector<Triangle> triangles;  // cones, besides the bands
  MeshStats stats;
};

// Which free components of two consecutive slices belong together (the space's topology).
struct ComponentLinks {
  // Groups of (lower components, upper components) that one patch of surface joins: a cell
  // seen in both slices, or one event of a critical transition.
  std::vector<std::pair<std::vector<int>, std::vector<int>>> groups;
};

// The bands of the strip between slices a (lower) and b (upper) (mesh_stitch.cpp).
StripResult stitch_strip(const SampledSlice& a, const SampledSlice& b, const ComponentLinks& links,
                         VertexStore& store);

// The strip between regular slice r and critical slice c, r below c when r_lower
// (mesh_walk.cpp).
StripResult walk_critical(const SampledSlice& r, const SampledSlice& c, bool r_lower,
                          const ComponentLinks& links, VertexStore& store);

using Cycle = std::vector<int>;  // piece indices, in order around a boundary cycle

// The vertices of `count` consecutive pieces of a cycle from position `first`, corners once.
// With count = 0, the corner where piece `first` starts.
std::vector<int> cycle_polyline(const SampledSlice& s, const Cycle& cycle, int first, int count);

// The shift from the material coordinates of `frame` to those of `part` (a piece of the same
// contact segment): the difference of their starts, taken modulo the circle for arcs.
double shift_into(const Piece& frame, const Piece& part);

// The number of positions strictly between `from` and `to` going forward around n.
int cyclic_gap(int from, int to, int n);

// The last resort: closes a cycle of slice s by a cone to the centroid of its vertices, at
// the other slice's theta (counted in stats.coned_cycles).
void add_cone(const SampledSlice& s, const Cycle& c, double other_theta, bool lower,
              VertexStore& store, StripResult& out);

// Tiles a band into triangles, normals pointing out of free space; triangles with a repeated
// vertex (a polyline that has shrunk to a point there) are left out.
void tile_band(const Band& band, const VertexStore& store, std::vector<Triangle>& out);
// Removes each pair of triangles with the same corners in opposite orders (a sheet of zero
// thickness, traversed once each way) from among the candidates (indices, ascending); returns
// the pairs removed.
int cancel_opposite_triangles(std::vector<Triangle>& triangles,
                              const std::vector<size_t>& candidates);
// The triangles with an edge in the slice at theta that some triangle runs the other way:
// the only ones a sheet can be made of, in a strip next to a critical slice.
std::vector<size_t> triangles_on_two_way_edges(const std::vector<Triangle>& triangles,
                                               const VertexStore& store, double theta);

// ---- Plane cuts (mesh_cut.cpp) ---------------------------------------------------------

// Splits every triangle that crosses the plane coordinate[axis] = value (axis 0: x, 1: y,
// 2: theta) into triangles on either side, sharing one new vertex per cut edge. Vertices
// within `snap` of the plane are first moved onto it, so no sliver is left. Returns the
// number of triangles split.
int split_by_plane(std::vector<MeshVertex>& vertices, std::vector<Triangle>& triangles, int axis,
                   double value, double snap);

// Cuts a mesh built over [theta_0, theta_0 + 2 pi] at theta = pi and moves what lies beyond
// down by 2 pi: vertex v with original[v] >= 0 (the first slice's copy at theta + 2 pi) becomes
// that vertex, one cut at pi gets a partner at -pi (ContactMesh::seam).
void cut_seam(ContactMesh& mesh, const std::vector<int>& original, double snap);

// Partial reconstruction: splits the triangles at the planes of the options' theta range and
// box, and drops what lies outside.
void clip(ContactMesh& mesh, const MeshOptions& options, double theta_snap, double xy_snap);

// Drops unused vertices (renumbering triangles and seam, in order of first use) and repeated
// seam pairs.
void compact(ContactMesh& mesh);

}  // namespace cslice::mesh_detail
