// The planar arrangement of contact segments: vertices where they meet, edges (pieces of
// contact segments between vertices, coincident pieces merged and carrying every label),
// and faces traced from a half-edge structure, holes attached to the faces around them.
#pragma once

#include <span>
#include <vector>

#include "cslice/geometry.hpp"
#include "cslice/tolerance.hpp"

namespace cslice {

// A contact segment running along an edge; its blocked side is on the edge's left when
// blocked_left, else on its right.
struct EdgeLabel {
  int segment = 0;
  bool blocked_left = true;
};

struct ArrangementEdge {
  int u = 0, v = 0;  // vertex ids; the curve runs from u to v
  Curve curve;
  std::vector<EdgeLabel> labels;
  int source = -1;  // index of the curve this piece was cut from (the first, when merged)
  // Unit tangents of the unsnapped contact segment at u and at v (both along the curve):
  // snapping ends to merged vertices would tilt a short piece by up to eps / length.
  Vec2 tangent_u, tangent_v;
};

// A closed walk of half-edges with its face on the left.
struct ArrangementCycle {
  std::vector<int> half_edges;
  double area = 0.0;  // signed: counterclockwise (> 0) around a bounded face
  Box box;
  int face = -1;
  int component = -1;  // connected component of the graph
};

struct ArrangementFace {
  bool bounded = false;
  std::vector<int> cycles;  // the outer cycle first when bounded
};

// Half-edge h runs along edge h / 2, forward (u to v) when h is even.
struct Arrangement {
  std::vector<Vec2> vertices;
  // Half-edges leaving each vertex, counterclockwise: those of vertex v are
  // outgoing_edges[outgoing_start[v] .. outgoing_start[v + 1]).
  std::vector<int> outgoing_start, outgoing_edges;
  std::span<const int> outgoing(int v) const {
    return {outgoing_edges.data() + outgoing_start[v],
            outgoing_edges.data() + outgoing_start[v + 1]};
  }
  std::vector<ArrangementEdge> edges;
  std::vector<int> next;      // per half-edge: the next one around its face
  std::vector<int> cycle_of;  // per half-edge
  std::vector<ArrangementCycle> cycles;
  std::vector<ArrangementFace> faces;  // faces[0] is the unbounded face

  int origin(int h) const { return h % 2 == 0 ? edges[h / 2].u : edges[h / 2].v; }
  int target(int h) const { return h % 2 == 0 ? edges[h / 2].v : edges[h / 2].u; }
  int face_of(int h) const { return cycles[cycle_of[h]].face; }
  Curve half_curve(int h) const;  // the edge's curve oriented along h
  Vec2 direction(int h) const;    // unit tangent of h where it leaves its origin
  // Whether h's face (its left side) is on the blocked side of label l of h's edge.
  static bool left_is_blocked(int h, const EdgeLabel& l) { return (h % 2 == 0) == l.blocked_left; }
};

// Builds the arrangement of `curves` (each oriented with its blocked side on the left);
// label ids are the curves' indices in `segment_ids`.
Arrangement build_arrangement(const std::vector<Curve>& curves, const std::vector<int>& segment_ids,
                              const Tolerances& tol);

}  // namespace cslice
