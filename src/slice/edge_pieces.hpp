// From the pieces of curves between vertices to the arrangement's edges: coincident pieces
// merged into one edge carrying every label, and, in a slice's arrangement, edges dangling
// into blocked faces peeled off.
//
// An edge one of whose vertices nothing else leaves has the same face on both sides. When its
// labels put blocked space on one side only, that face is blocked (a face is all free or all
// blocked), and removing the edge merges nothing: no free point and no piece of the free
// space's boundary moves. Peeling goes on from the vertex the edge led to, so chains of
// contact segments that meet nothing else go whole. Rough contours leave a third of their
// edges dangling in the band of shallow overlap, smooth ones a fifth (the ends of contact
// segments past their crossings on the free space's boundary).
//
// The test for a perfect fit at a vertex (slice.cpp, sectors_explained_locally) reads the
// labels of every half-edge leaving it, so edges are peeled only between vertices whose own
// edges are all one-sided and name at most two contact segments. Two one-sided contact
// segments through a point never explain every sector around it (the sector on the free side
// of both stays unexplained), with or without some of their half-edges, so such a vertex is
// no candidate before peeling or after.
#pragma once

#include <utility>
#include <vector>

#include "slice/arrangement.hpp"

namespace cslice {

// Working arrays of edges_from_pieces, kept between calls.
struct PieceScratch {
  std::vector<std::pair<int, int>> end_pairs;  // per piece: its lower end, then the other
  std::vector<int> segment_of;                 // per piece: its label's contact segment
  std::vector<int> start, order, fill;
  std::vector<int> edge_of;  // per piece: its edge, before peeling
  std::vector<int> first;    // per edge: its first piece
  std::vector<Vec2> mid;     // per edge, when it has coincident pieces: its midpoint
  std::vector<int> merged;   // the pieces merged into an earlier one's edge, in order
  std::vector<char> same_way, one_sided, peeled;
  std::vector<int> degree, edge_xor, first_id, second_id, leaves, index;
  std::vector<int> ends_xor;  // per edge: u ^ v (the other end from either)
  std::vector<char> simple;
};

// Appends to `edges` the edges the pieces make (each piece has one label, blocked on its
// left, and ends u and v among `vertices` vertices); pieces are moved from. Coincident
// pieces (same ends, midpoints within eps) make one edge. With peel, dangling edges are left
// out. Edges come in the order of their lower end vertex, then their other one.
void edges_from_pieces(std::vector<ArrangementEdge>& pieces, size_t vertices, double eps, bool peel,
                       PieceScratch& scratch, std::vector<ArrangementEdge>& edges);

}  // namespace cslice
