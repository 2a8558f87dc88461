// The configuration-space slice at one orientation: the (x, y) plane of reference-point
// positions of the moving part rotated by theta, split by contact segments into free and
// blocked regions (paper sections 4, 6.1, 6.2, 6.5 and 7).
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "cslice/pair.hpp"

namespace cslice {

// The kinds of feature pair that make contact segments, moving feature first.
enum class ContactKind {
  vertex_segment,  // moving vertex on a fixed segment: a line segment
  segment_vertex,  // moving segment on a fixed vertex: a line segment
  arc_segment,     // moving arc on a fixed segment: a line segment
  segment_arc,     // moving segment on a fixed arc: a line segment
  arc_arc,         // arcs on both sides: a circular arc
  vertex_arc,      // moving vertex on a fixed arc: a circular arc
  arc_vertex,      // moving arc on a fixed vertex: a circular arc
};
std::string_view to_string(ContactKind k);

// A feature pair, the label of a contact segment (paper section 4).
struct SegmentLabel {
  int moving_feature = 0;
  int fixed_feature = 0;
  friend auto operator<=>(const SegmentLabel&, const SegmentLabel&) = default;
};

// The configurations where one moving feature touches one fixed feature, at this theta.
struct ContactSegment {
  int id = 0;
  int moving_feature = 0;  // index into pair.moving.features
  int fixed_feature = 0;   // index into pair.fixed.features
  ContactKind kind = ContactKind::vertex_segment;
  // Oriented so the blocked side (where the two features overlap) lies on its left.
  Curve curve;
  // A perfect fit (e.g. a pin in a hole of its own radius): the whole contact set is the
  // single point curve.from.
  bool is_point = false;
};

// A piece of a realizable contact segment: part of the free-space boundary, or a degenerate
// piece of contact space with blocked space on both sides (a sliding fit).
// Pieces listed in Slice::realizable keep their contact segment's direction (blocked side
// on the left); pieces in a free component's boundary run the other way (free on the left).
struct ContactPiece {
  int segment = 0;  // contact segment id: the lowest of those that coincide along the piece
  Curve curve;      // (all of them are nodes of the contact graph)
};

struct FreeComponent {
  int id = 0;
  bool bounded = true;
  double area = 0.0;  // NaN when unbounded
  Vec2 sample;        // strictly inside, as far from the boundary as a few scan lines find
  // Boundary cycles: for a bounded component the outer cycle first (counterclockwise), then
  // its holes (clockwise); for the unbounded one, only clockwise cycles. Each piece runs
  // with the component on its left.
  std::vector<std::vector<ContactPiece>> boundary;
};

struct ContactGraphEdge {
  int a = 0, b = 0;  // contact segment ids, a < b
  Vec2 at;
};

// Nodes are the realizable contact segments; edges the points where two of them meet.
struct ContactGraph {
  std::vector<int> nodes;
  std::vector<ContactGraphEdge> edges;
};

// Contact configurations with no free space around them: free space shrunk to a point (a
// perfect fit) or a curve (a sliding fit). Kept, never dropped.
struct DegenerateContact {
  std::vector<int> segments;  // contact segments through it
  Curve curve;                // a point when curve.from == curve.to
  bool is_point = false;
};

struct Slice {
  double theta = 0.0;  // the orientation asked for, in [-pi, pi) (principal_angle)
  std::vector<ContactSegment> contact_segments;
  std::vector<FreeComponent> free_components;
  // Every realizable piece of positive length: free-space boundary and sliding fits.
  // Degenerate points (perfect fits) are in `degenerate` only.
  std::vector<ContactPiece> realizable;
  std::vector<DegenerateContact> degenerate;
  ContactGraph contact_graph;
  // Area of blocked space; infinite when it is unbounded (the fixed part is an enclosure).
  double blocked_area = 0.0;
  double epsilon = 0.0;  // the pair's geometric epsilon: locate's band around contact space
  // Some realizable piece lies along two or more contact segments: it names the one of lowest
  // id, an order that a slice mapped across a symmetry does not keep (symmetry.hpp).
  bool coincident_pieces = false;

  // The free component whose interior holds p, or -1 (blocked, or within the geometric
  // epsilon of contact space).
  int locate(Vec2 p) const;
  // locate for a point already known to lie farther than epsilon from every boundary piece:
  // the same answer by the parity tests alone.
  int locate_off_boundary(Vec2 p) const;
};

// Contact segments of every compatible feature pair at theta, after local overlap filtering.
std::vector<ContactSegment> contact_segments(const Pair& pair, double theta);

// The whole slice at theta (any finite angle: one outside [-pi, pi) is wrapped there, by the
// true turn when it is far, as std::sin and std::cos take it). Thread-safe; the calling thread
// keeps the working buffers for its next call while they hold at most about 64 MB (released
// after a larger slice: a smooth pair of 40,000 features, or a rough one of 8,000), but
// nothing of the pair: each call reads it anew. For many slices of one pair, a Slicer also keeps
// the pair's contact data.
Slice compute_slice(const Pair& pair, double theta);

// Ids of the realizable contact segments, sorted, each once: the contact graph's nodes, plus
// any segment a realizable piece or a degenerate contact names. Pieces name only the lowest
// of coincident segments, so pieces alone would miss the others.
std::vector<int> realizable_segments(const Slice& slice);
// The same as marks by id (1: realizable), into a buffer the caller keeps from slice to slice.
void mark_realizable_segments(const Slice& slice, std::vector<char>& marked);

// Many slices of one pair (the engine behind compute_slice): the features' contact data and
// the placement tester's indexes are built once instead of per slice. Not thread-safe, as
// it keeps scratch state: one per thread. The pair must outlive it.
class Slicer {
 public:
  explicit Slicer(const Pair& pair);
  ~Slicer();
  Slicer(Slicer&&) noexcept;
  Slicer& operator=(Slicer&&) noexcept;
  Slice slice(double theta);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace cslice
