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

#include <functional>
#include <utility>
#include <vector>

#include "slice/arrangement.hpp"

namespace cslice {

// A piece of a curve between two consecutive vertices along it, before it is an edge: its
// ends, its label's contact segment (blocked on its left), its curve and where along that
// curve it starts (the caller's index; it ends at the next).
struct Piece {
  int u, v, segment, curve, at;
};

// Working arrays of edges_from_pieces, kept between calls.
struct PieceScratch {
  std::vector<std::pair<int, int>> end_pairs;  // per piece: its lower end, then the other
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

// For tests: whether slices peel dangling edges (the default) or keep them. Process-wide.
void set_slice_peeling(bool on);
bool slice_peeling();

// Makes the edges of the pieces: `emit(p)` appends to `edges` the edge of piece p, the first
// of its coincident ones (same ends, midpoints within eps), and the others' labels are added
// to it. With peel, dangling edges are not emitted. Edges come in the order of their lower
// end vertex, then their other one. `curve_of(p)` is the piece's curve, asked only of pieces
// that share both ends with another.
void edges_from_pieces(const std::vector<Piece>& pieces, size_t vertices, double eps, bool peel,
                       const std::function<Curve(const Piece&)>& curve_of,
                       const std::function<void(const Piece&)>& emit, PieceScratch& scratch,
                       std::vector<ArrangementEdge>& edges);

}  // namespace cslice
