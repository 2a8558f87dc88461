// Chains of contact segments that meet nothing but each other, end to end, without closing a
// loop: left out of a slice's arrangement (arrangement.hpp).
//
// Every contact segment has its blocked side on its left (its own features overlap just
// across it there). A connected set of segments that no other curve comes within eps of,
// joined only at exactly shared ends and forming a tree, lies inside one face of the other
// curves' arrangement, with that face on both sides of every segment: so that face is
// blocked all over (a face is all free or all blocked). Leaving the tree out merges nothing
// but blocked space: no free point and no piece of the free space's boundary moves, and the
// face loses only a proof of being blocked that its other edges, or the direct placement
// test, still give. Rough contours leave dozens of such dangling chains in the band of
// shallow overlap, and each was a component to place in its face (docs/performance.md,
// twenty-second session).
#pragma once

#include <vector>

#include "cslice/geometry.hpp"
#include "geometry/union_find.hpp"
#include "slice/split_points.hpp"

namespace cslice {

// Working arrays of find_lone_trees, kept between calls.
struct LoneTreeScratch {
  UnionFind curves;                 // curves joined end to end
  std::vector<char> met_otherwise;  // per curve, then per class: meets a curve another way
  std::vector<int> links,
      excess;  // per curve: its end_to_end pairs as a; per class: curves - links
};

// left_out[c] = 1 for every curve c of a lone tree: segments whose only meetings (in
// `shared`, split_points' list of every pair within eps) are end_to_end ones among
// themselves, one fewer than the segments. Such pairs share one end each, so their graph is
// a tree, and so is the one they draw; three or more meeting at one point make more pairs
// than that and are kept (as are arcs), which only costs time.
void find_lone_trees(const std::vector<Curve>& curves, const std::vector<SharedPiece>& shared,
                     LoneTreeScratch& scratch, std::vector<char>& left_out);

}  // namespace cslice
