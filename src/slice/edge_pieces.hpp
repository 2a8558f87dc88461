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
// Where two one-sided contact segments a and b cross at a vertex where nothing else meets (a
// simple crossing), one of a's two pieces leaving it lies on b's blocked side, and one of b's
// on a's: the two bounding the sector blocked by both. Each such piece has, next to the
// crossing, a sector on b's blocked side on either hand (b's line splits the plane there and
// the piece splits b's blocked half), so both its faces are blocked, as the labels of b's
// pieces say, and removing it only merges blocked faces. At a rough contour's crossings
// deep in blocked space this takes half the pieces, and what dangles after goes too. Which
// piece is inside is the sign of the cross product of the two tangents, as the ordering
// of crossing curves at a vertex decides it; crossings at an angle within the angular
// tolerance keep their pieces.
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

// A piece that leaves the simple crossing at `vertex` (above) into the other curve's
// blocked side.
struct InsidePiece {
  int piece, vertex;
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
  std::vector<int> going;  // edges of inside pieces, taken out before peeling
};

// For tests: whether slices peel dangling edges (the default) or keep them. Process-wide.
void set_slice_peeling(bool on);
bool slice_peeling();

// Makes the edges of the pieces: `emit(p)` appends to `edges` the edge of piece p, the first
// of its coincident ones (same ends, midpoints within eps), and the others' labels are added
// to it. With peel, dangling edges are not emitted, and neither are the `inside` pieces of
// crossings still simple once their edges are made, nor what dangles once they are gone.
// Edges come in the order of their lower end vertex, then their other one. `curve_of(p)` is
// the piece's curve, asked only of pieces that share both ends with another.
void edges_from_pieces(const std::vector<Piece>& pieces, size_t vertices, double eps, bool peel,
                       const std::vector<InsidePiece>& inside,
                       const std::function<Curve(const Piece&)>& curve_of,
                       const std::function<void(const Piece&)>& emit, PieceScratch& scratch,
                       std::vector<ArrangementEdge>& edges);

}  // namespace cslice
