// Parts and their features. A part is a set of closed loops of curves; after loading, every
// loop is oriented so that the part's material lies on its left (outer boundaries
// counterclockwise, holes clockwise; the reverse for an enclosure, whose material is the
// region outside its loops). Features are what the paper counts and what makes contact:
// segments, arcs, and the vertices where consecutive edges meet.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cslice/geometry.hpp"

namespace cslice {

struct Loop {
  std::vector<Curve> edges;  // edges[i] runs from vertex i to vertex i+1 (cyclically)
  int source_index = 0;      // position of this loop in the input file
  bool reversed = false;     // true when the input listed it in the opposite orientation
  int depth = 0;             // number of other loops of the part that enclose it
  bool is_circle() const { return edges.size() == 1 && edges.front().is_full_circle(); }
  // Vertex i of the input (before any reversal) is the start of some edge; the vertex count
  // equals the edge count except for a full circle, which has none.
  int vertex_count() const { return is_circle() ? 0 : static_cast<int>(edges.size()); }
};

enum class FeatureKind { segment, arc, vertex };
// "segment", "arc" or "vertex", as files and messages name them.
std::string_view to_string(FeatureKind k);

// Convexity of a feature seen from outside the material: a convex feature bulges out of the
// part (counterclockwise arc, left-turning vertex), a concave one bends into it; a smooth
// vertex joins two edges with the same tangent and is neither.
enum class Convexity { convex, concave, flat, smooth };

struct Feature {
  FeatureKind kind = FeatureKind::segment;
  int loop = 0;   // index into Part::loops
  int index = 0;  // edge index for segments and arcs; vertex index (start of edge `index`)
  Convexity convexity = Convexity::flat;
  // Outward unit normals. Segments: one normal (normal_in == normal_out). Arcs: normals at
  // the start and end. Vertices: the outward normals of the incoming edge at its end
  // (normal_in) and of the outgoing edge at its start (normal_out); the vertex's normal cone
  // runs counterclockwise from normal_in to normal_out for a convex vertex.
  Vec2 normal_in, normal_out;
  Vec2 point;  // vertex position (vertices only)
  // The normal cone as angles, which the contact step buckets by; found with the part (see
  // set_normal_angle) because their arc tangents cost a share of every one-shot slice.
  // normal_angle: the direction of normal_in (a segment's, of its edge turned right); turn:
  // the signed angle from normal_in to normal_out (vertices, where it also decides the
  // convexity; zero otherwise).
  double normal_angle = 0.0, turn = 0.0;
};

struct Part {
  std::string name;  // "moving" or "fixed"
  std::vector<Loop> loops;
  bool enclosure = false;  // material is outside the loops
  std::vector<Feature> features;
  Box box;            // bounding box of the loops
  double area = 0.0;  // area of the material; for an enclosure, the area of the openings

  int segment_count() const;
  int arc_count() const;
  int vertex_count() const;
  // Features as the paper counts them: segments, arcs and endpoints.
  int feature_count() const { return segment_count() + arc_count() + vertex_count(); }
};

// Sets f.normal_angle from its normal_in (for a segment, from its edge: edge_of). The turn is
// set where the vertex is made, and does not change when the part is placed.
void set_normal_angle(const Part& part, Feature& f);

// Fills loop orientation, depth, features, box and area from raw loops (in any orientation).
// Assumes the loops were validated: closed, simple, not crossing each other.
void finish_part(Part& part);

// The part moved by a pose (every curve rotated then translated); features keep their indices.
Part placed(const Part& part, const Pose& pose);

const Curve& edge_of(const Part& part, const Feature& f);

// A part's reach: the largest distance of a point of it from its body origin. Turning the
// moving part by dtheta moves none of its points further than reach * |dtheta|.
double moving_reach(const Part& moving);

}  // namespace cslice
