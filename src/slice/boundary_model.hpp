// The free-space boundary of a slice as a structure that survives turning (paper section 4:
// between two critical orientations the contact structure is fixed). Per free component, per
// boundary cycle, it keeps the label of each piece and, for each corner between two pieces,
// which intersection of the two labels' contact curves the corner is (its rank along the
// first). Taken from one slice of an interval and evaluated at another theta of it, from the
// labels' contact curves there, it gives that slice's exact free-space boundary without an
// arrangement: the queries (src/space/query.cpp) and the intermediate slices of a sliced space
// (slice_from_model below) are built that way.
#pragma once

#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "cslice/slice.hpp"

namespace cslice {

class ContactMaker;

struct CornerModel {
  int id = 0;        // index among the model's corners
  int a = 0, b = 0;  // label indices of the pieces before and after the corner
  int rank = 0;      // which hit of the two curves, in order along a's curve
  int count = 0;     // how many hits the two curves have throughout the interval
};

struct PieceModel {
  int label = 0;
  int sweep_sign = 0;  // arcs: direction of travel (+1 counterclockwise); segments: 0
};

struct CycleModel {
  std::vector<PieceModel> pieces;
  std::vector<CornerModel> corners;  // corner k ends piece k and starts piece k + 1
  bool full_circle = false;          // one piece, a whole circle
};

struct ComponentModel {
  bool bounded = true;
  std::vector<CycleModel> cycles;
};

struct BoundaryModel {
  std::vector<SegmentLabel> labels;
  std::vector<std::pair<SegmentLabel, int>> by_label;  // (label, its index), sorted
  std::vector<ComponentModel> components;              // in the slice's order
  int corners = 0;
};

// The index of label l in the model, or -1 (a binary search: models of big slices have
// thousands of labels).
int label_index(const BoundaryModel& model, SegmentLabel l);

// Each label's contact segment among `segments` (one slice's): its id into ids[l] and its curve
// into curves[l]; false unless every label has exactly one, and none of them is a point.
bool label_segments(const BoundaryModel& model, std::span<const ContactSegment> segments,
                    std::vector<int>& ids, std::vector<Curve>& curves);

// Transversal hits of two curves, sorted along the first.
using SortedHits = std::vector<std::pair<double, Vec2>>;

// The hits of a and b into `hits`, sorted along a; false when the curves overlap or touch
// along a piece, where a corner's rank means nothing.
bool sorted_hits(const Curve& a, const Curve& b, double eps, SortedHits& hits);

// The model of slice's free-space boundary; nullopt when the slice has degenerate contacts,
// a piece's label has other than one contact segment (or a point), a cycle runs along one
// label across a corner, two consecutive labels' curves overlap, or a corner is not within
// the criticality tolerance of a hit of its curves.
std::optional<BoundaryModel> model_boundary(const Slice& slice, const Tolerances& tol);

// The corner point of k from its labels' curves at some theta; false when they no longer
// meet k.count times there.
bool corner_point(const CornerModel& k, const Curve& a, const Curve& b, double eps,
                  SortedHits& hits, Vec2& out);

// The piece of contact curve c from corner `from` to corner `to`, travelled as the model says.
bool piece_between(const PieceModel& piece, const Curve& c, Vec2 from, Vec2 to, Curve& out);

// The boundary evaluated at one theta: every cycle's pieces, component by component and
// cycle by cycle in the model's order.
struct EvaluatedBoundary {
  std::vector<Curve> pieces;
  std::vector<int> piece_label;
  std::vector<int> cycle_end;      // pieces of cycle k (counting over all components)
  std::vector<int> component_end;  // pieces of component c: [end[c - 1], end[c])
  std::vector<Vec2> corners;       // by corner id
  SortedHits hits;                 // scratch
};

// Evaluates the model from the contact curve of each of its labels (curves[l] for label l);
// false when a corner's curves do not meet as the model says.
bool evaluate_boundary(const BoundaryModel& model, std::span<const Curve> curves, double eps,
                       EvaluatedBoundary& out);

// Buffers of slice_from_model, kept between calls.
struct SliceFromModelScratch {
  EvaluatedBoundary boundary;
  std::vector<Curve> curves, cycle;
  std::vector<int> label_segment;
  std::vector<double> xs;
};

// The slice at theta built from a model taken from a slice of the same interval: every
// contact segment at theta (from `contacts`), and the free components, realizable pieces and
// contact graph of the evaluated boundary. nullopt where it cannot be evaluated there (a
// label with other than one contact segment, a corner's curves meeting otherwise, a perfect
// fit): the caller computes that slice instead.
std::optional<Slice> slice_from_model(const Pair& pair, const BoundaryModel& model, double theta,
                                      ContactMaker& contacts, SliceFromModelScratch& scratch);

// Whether slice_from_model at the slice's own theta would rebuild the structure of the slice
// the model was taken from: its realizable pieces are the model's pieces, its contact graph
// has the model's labels as nodes and its corners as edges. The model can miss what the
// arrangement sees (contact segments coinciding along a piece, a piece split where another
// segment ends on it), so a model passes this once before it stands in for its interval's
// other slices.
bool model_reproduces(const BoundaryModel& model, const Slice& slice);

}  // namespace cslice
