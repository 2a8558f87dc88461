// Contact segments proven to lie in blocked space, left out of the arrangement.
//
// A point of the moving part's boundary strictly inside the fixed material, or the reverse,
// makes the parts overlap. Each part's straight edges carry a region of material
// (parts/material_regions.hpp). A contact segment of a vertex or an arc on a segment (either
// part's) runs along the translations where one point of the vertex or arc touches the
// segment; swept to its blocked side through that segment's region, it becomes a slab of
// translations where that point lies inside the region, more than `margin` from the other
// part's boundary below the slab's depth less margin: blocked space with that margin. A
// contact segment covered end to end by other segments' slabs lies in blocked space with the
// margin all along, so leaving it out of the arrangement only merges blocked faces: no free
// point, and no piece of the free space's boundary, lies within the margin of it. It stays in
// the slice's contact segments. A line is covered by the spans of several slabs together; an
// arc (arc/arc and vertex/arc contacts: the tips and roots of gear teeth) by one slab, or
// its halves (or their halves, a few times over) each by one.
//
// Where contact segments greatly outnumber features (rough contours, whose contact segments
// cross in a band of shallow overlap along the boundary of the free space) most of them are
// proven blocked this way, and the arrangement shrinks by as much; elsewhere few are, and
// the slice does not look (worth_proving).
#pragma once

#include <vector>

#include "cslice/slice.hpp"
#include "parts/material_regions.hpp"

namespace cslice {

// Whether the slice looks for contact segments proven blocked: when there are more than two
// contact segments per feature of the pair, or 4.5 when the parts have no arcs (see
// blocked_proof.cpp and docs/performance.md).
bool worth_proving(const Pair& pair, size_t contact_segments);

// For tests: look always, never, or when worth_proving says (the default). Process-wide.
enum class BlockedProofMode { automatic, always, never };
void set_blocked_proof_mode(BlockedProofMode mode);

// The material regions of both parts of a pair, found once per pair.
struct PairRegions {
  std::vector<MaterialRegion> moving, fixed;
};

// The margin every proof on the pair keeps: kProvenBlockedMarginPerGeometric geometric
// epsilons.
double proof_margin(const Pair& pair);
// Both parts' material regions for that margin.
PairRegions pair_regions(const Pair& pair);

// Finds the contact segments proven blocked, one slice after another in the same buffers.
class BlockedProof {
 public:
  // proven[id] = 1 for every contact segment (indexed by id) covered by other segments'
  // slabs; 0 for the others.
  void find(const std::vector<ContactSegment>& segments, const PairRegions& regions, double margin,
            std::vector<char>& proven);

  struct Span {  // open, along a target: 0 and 1 at its ends
    double lo, hi;
  };
  struct ArcTarget;  // an arc target or a piece of one (blocked_proof.cpp)

 private:
  // A slab in its contact segment's frame (x along it from its start, y across it into the
  // blocked side): low < y < high, cross(start_side, (x, y)) < 0 and
  // cross(end_side, (x - length, y)) > 0, as in MaterialRegion with the margin taken off.
  struct Slab {
    Vec2 from, along, across;  // along: unit direction; across: unit normal to its left
    double length, low, high;
    Vec2 start_side, end_side;
    int segment;
  };
  struct CellRange {
    int x0, x1, y0, y1;
  };
  // The grid cells a box overlaps, clamped to the grid.
  CellRange cells(const Box& b) const;
  void collect(const std::vector<ContactSegment>& segments, const PairRegions& regions,
               double margin);
  size_t walk_index(Vec2 p) const;
  void order_by_depth();
  void index_slabs();
  void order_targets();
  bool covered(Vec2 from, Vec2 to, int id);  // a line target
  bool covered_arc(const ArcTarget& arc, int halvings);
  template <class Stop>
  bool any_slab_near(const Box& b, Stop stop);

  std::vector<Slab> slabs_;
  std::vector<Box> slab_boxes_;
  // Uniform grid over the slabs: the slabs overlapping cell c are
  // cell_slabs_[cell_start_[c] .. cell_start_[c + 1]), with their boxes alongside.
  std::vector<int> cell_start_, cell_slabs_, fill_;
  std::vector<Box> cell_boxes_;
  std::vector<CellRange> slab_cells_;          // per slab: the cells its box overlaps
  std::vector<int> by_depth_;                  // the slabs, deepest first (order_by_depth)
  std::vector<int> group_start_, group_fill_;  // group_by's buffers, for either ordering
  std::vector<size_t> target_cells_;           // per target, in contact segment order: its cell
  std::vector<int> near_;   // any_slab_near: the slabs in one cell whose boxes overlap
  std::vector<int> stamp_;  // per slab: the last query (a target, or a piece of an arc) to test it
  int query_ = -1;
  // The targets, by the cell of their box's centre, with a line's ends: read in this order,
  // from the contact segments they were a cache miss each.
  struct Target {
    Vec2 from, to;
    int id;
    bool line;
  };
  std::vector<Target> unordered_;    // the targets in contact segment order
  std::vector<Vec2> target_points_;  // their boxes' centres, alongside
  Box all_;                          // every target and slab
  std::vector<int> target_order_;    // order_targets: the targets' indices in walk order
  std::vector<Target> targets_;
  std::vector<Span> spans_;  // on the target in hand: the spans found so far, merged
  Vec2 origin_;
  double cell_ = 1.0, per_cell_ = 1.0;
  int columns_ = 0, rows_ = 0;
  int hint_ = -1;            // the slab that held the last arc target (or piece) held by one slab
  std::vector<int> recent_;  // the slabs that gave spans to the last line target proven
  std::vector<int> giving_;  // the same for the line target in hand
};

}  // namespace cslice
