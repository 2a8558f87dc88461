// The sliced configuration space of a pair (paper sections 4, 7 and 2.6): the critical
// orientations, a slice at each, a representative slice in every open interval between two
// consecutive ones, and intermediate slices close enough together that linear interpolation
// between neighbours stays within the pair's contact tolerance (docs/space-format.md).
#pragma once

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cslice/critical.hpp"
#include "cslice/slice.hpp"

namespace cslice {

// Why a slice is in the space.
enum class SliceKind {
  critical,      // at a critical orientation
  interval,      // the representative of an open interval: its middle
  intermediate,  // added so that consecutive slices are at most the interpolation step apart
};
std::string_view to_string(SliceKind k);

struct SpaceSlice {
  double theta = 0.0;  // in [-pi, pi)
  SliceKind kind = SliceKind::interval;
  // Interval i runs from critical orientation i to critical orientation i + 1 (the last one
  // wraps past pi to the first). A critical slice records the interval it starts. With no
  // critical orientation there is one interval, the whole turn, starting at -pi.
  int interval = 0;
  Slice slice;
  // Evaluated from the boundary structure of its interval's representative
  // (SpaceOptions::evaluate_slices) rather than computed from scratch.
  bool evaluated = false;
  // Mapped from another slice across a symmetry of the pair (SpaceOptions::map_symmetric).
  bool mapped = false;
};

// How the realizable contact segments of slice `from` correspond to those of the next slice
// `to` (by theta, cyclically: the last slice's successor is the first), by label.
struct SliceCorrespondence {
  int from = 0, to = 0;                                  // indices into SlicedSpace::slices
  std::vector<SegmentLabel> kept, appearing, vanishing;  // each sorted
};

// ---- 3D topology (src/space/topology.cpp, docs/space-format.md) -------------------------

// A free-space cell: an open interval between two consecutive critical orientations times
// one free component of its slices, followed from slice to slice through the interval.
struct SpaceCell {
  int id = 0;
  int interval = 0;
  // The open interval (theta_from, theta_to); theta_to passes pi for the last interval, which
  // wraps to the first critical orientation + 2 pi. With no critical orientation: (-pi, pi).
  double theta_from = 0.0, theta_to = 0.0;
  int component = 0;  // its 3D free component
  bool bounded = true;
  double min_area = 0.0, max_area = 0.0;  // over its stored slices; NaN when unbounded
  // A free configuration of the cell: a component sample in the interval's representative
  // slice (its middle), or in the slice nearest it when the cell is missing there.
  double sample_theta = 0.0;
  Vec2 sample;
};

// How the cells of the interval before one group of joined cells at a critical orientation
// continue into the interval after it.
enum class TransitionKind {
  continues,    // one cell before, one after
  merge,        // several before, one after
  split,        // one before, several after
  merge_split,  // several on both sides
  appear,       // none before, one after
  vanish,       // one before, none after
};
std::string_view to_string(TransitionKind k);

struct TransitionEvent {
  TransitionKind kind = TransitionKind::continues;
  std::vector<int> before, after;        // cell ids, sorted
  std::vector<int> critical_components;  // free components of the critical slice joined in
};

// The joins across one critical orientation, from the interval ending there to the one
// starting there (the last interval before the first orientation, across theta = pi).
struct CriticalTransition {
  int critical = 0;  // index into criticals.orientations; its slice starts interval `critical`
  double theta = 0.0;
  int interval_before = 0, interval_after = 0;
  // How far before and after theta the side slices lie (radians): side_slice_angle, or less
  // when the interval's nearest stored slice is closer than that and serves instead.
  double side_before = 0.0, side_after = 0.0;
  std::vector<std::pair<int, int>> joins;  // (cell before, cell after), sorted
  std::vector<TransitionEvent> events;     // ordered by their smallest cell
  // Components of the critical slice that no cell reaches: a numerical problem (free space is
  // open, so every free point at theta extends to both sides).
  int orphan_critical_components = 0;
};

// A connected component of the 3D free space: a union of cells.
struct SpaceComponent {
  int id = 0;
  std::vector<int> cells;  // sorted
  // Maximal theta ranges it covers: runs of intervals joined through critical slices where it
  // has free space. [-pi, pi] when it spans every orientation.
  std::vector<std::pair<double, double>> theta_ranges;
  bool spans_all_theta = false;  // a cell in every interval and free space at every critical
};

// Checks that should never fail; a count above zero is a bug (or a numerical problem)
// reported, not hidden.
struct TopologyChecks {
  int interval_match_failures = 0;     // a component of one interval slice not found, both
                                       // ways, in the next slice of the same interval
  int boundary_label_mismatches = 0;   // matched components with different boundary labels
  int side_slices_not_equivalent = 0;  // a side slice not equivalent to its interval's slices
  int orphan_critical_components = 0;  // summed over the transitions
  // Not a failure: extra slices that halved a gap whose components moved further than their
  // samples' clearance between stored slices (then matched).
  int refinement_slices = 0;
  // Not a failure either: consecutive slices of an interval matched by their components'
  // boundary labels (all distinct) where even refinement left samples unmatched.
  int label_matches = 0;
  // Not a failure: critical orientations with at most one free component in the intervals on
  // either side, whose joins follow from the counts (no side slices; see compute_topology).
  int joins_by_count = 0;
  // Not a failure: sides of critical orientations (up to two each) where the interval's
  // nearest stored slice stands in for a side slice, every sample's clearance proving its
  // vertical segment free.
  int joins_by_clearance = 0;
  // Not a failure: components joined across a critical orientation by carrying their sample
  // in steps its clearance proves free, where the sample rules left them unjoined.
  int joins_by_carrying = 0;
  // Not a failure: side slices evaluated from their interval's representative's boundary
  // structure (TopologyOptions::evaluate_slices) instead of computed from scratch.
  int side_slices_evaluated = 0;
  // Not a failure: the slices the carries stepped through (joins_by_carrying), and how many
  // of them were evaluated from their interval's boundary model instead of computed.
  int carry_slices = 0;
  int carry_slices_evaluated = 0;
  std::vector<std::string> problems;  // the first few, in words
};

struct SpaceTopology {
  std::vector<SpaceCell> cells;  // by interval, then by component of the representative slice
  std::vector<CriticalTransition> transitions;  // one per critical orientation, by theta
  std::vector<SpaceComponent> components;       // by their smallest cell
  // Per slice of SlicedSpace::slices, per free component: its cell (-1 in critical slices),
  // and its 3D component (-1 for an orphan component of a critical slice).
  std::vector<std::vector<int>> slice_cells, slice_components;
  TopologyChecks checks;
};

// Reports how far a long computation has come: a stage's name and its units done out of
// total. Called from worker threads, possibly at once: it must be thread-safe.
using ProgressReport =
    std::function<void(std::string_view stage, std::size_t done, std::size_t total)>;

struct SpaceOptions {
  CriticalOptions critical;
  int threads = 0;          // slices computed at once; 0 (or more than the cores): every core
  ProgressReport progress;  // optional
  // Side slices and sample rules at every critical orientation, even where the component
  // counts decide the joins, each side slice checked against its interval's representative:
  // the same result (the tests compare), slower; it checks the critical orientations more.
  bool verify_joins = false;
  // Slices inside an interval other than its representative (the intermediate slices kept
  // for interpolation, the topology's side slices) evaluated in closed form from the
  // representative's boundary structure, which holds throughout the interval, where that
  // structure can be modelled; false computes every slice from scratch (the tests compare
  // the two). Files are read back with the default.
  bool evaluate_slices = true;
  // Slices at the image of another slice's orientation under a symmetry of the pair (a
  // quarter turn or mirror mapping both parts onto themselves, include/cslice/symmetry.hpp)
  // mapped from that slice; false computes them (the tests compare the two). Files are read
  // back with the default.
  bool map_symmetric = true;
};

struct TopologyOptions {
  int threads = 0;              // as in SpaceOptions
  bool verify_joins = false;    // as in SpaceOptions
  bool evaluate_slices = true;  // as in SpaceOptions (side slices; not when verifying joins)
};

struct SlicedSpace {
  CriticalSet criticals;
  // The largest angle between consecutive slices of an interval (radians), and the reach it
  // was derived from (space.cpp, interpolation_step).
  double max_step = 0.0;
  double reach = 0.0;
  std::vector<SpaceSlice> slices;                   // sorted by theta
  std::vector<SliceCorrespondence> correspondence;  // slice i to slice (i + 1) mod n
  SpaceTopology topology;                           // cells, transitions, 3D components
  // Wall-clock seconds: not part of the result, and the only thing that varies between runs.
  double seconds_criticals = 0.0;
  double seconds_slices = 0.0;
};

// The farthest any point P + R(theta) Q of a contact curve of the pair can lie from its
// centre of turning: max |Q| over every defining point (docs/space-format.md).
double contact_reach(const Pair& pair);

// The interpolation step for a reach and tolerance: sqrt(8 tol / reach), capped at pi / 2.
double interpolation_step(double reach, double tolerance);

SlicedSpace compute_space(const Pair& pair, const SpaceOptions& options = {});

// The 3D topology of a space whose slices and criticals are computed: cells, their joins
// across the critical orientations, the 3D free components. Computes two side slices per
// critical orientation (in parallel) where the intervals' own slices are further than
// side_slice_angle from it, except where at most one free component lies on either side
// (then the joins follow from the counts) unless options.verify_joins. compute_space calls it.
SpaceTopology compute_topology(const Pair& pair, const SlicedSpace& space,
                               const TopologyOptions& options = {});

// The side-slice angle delta of the joins across a critical orientation: side slices lie at
// most this far from it (src/space/topology.cpp explains the choice).
double side_slice_angle(const Tolerances& tol);

// The labels of the realizable contact segments of a slice, sorted and without repeats.
std::vector<SegmentLabel> realizable_labels(const Slice& slice);

// The labels of the contact segments along a free component's boundary, one per piece,
// sorted (repeats kept): what identifies a component from one slice to the next.
std::vector<SegmentLabel> boundary_labels(const Slice& slice, const FreeComponent& component);

// The version of the space file format that space_to_json writes and load_space reads.
inline constexpr int kSpaceFormatVersion = 3;

// The space as JSON text (format "cslice-space", version kSpaceFormatVersion;
// docs/space-format.md), ending in a newline. It embeds the pair (pair_file_text) so the file
// is self-contained. Without timing the text depends only on the pair and the options'
// screening.
std::string space_to_json(const Pair& pair, const SlicedSpace& space, bool with_timing = true);
// The same text written to `out` as it is made, never whole in memory.
void write_space_json(std::ostream& out, const Pair& pair, const SlicedSpace& space,
                      bool with_timing = true);

// The pair in the pair-file format (docs/pair-format.md), as a space file embeds it: its
// validated loops as the file listed them (same order, orientation, vertices and bulges, bit
// for bit), so parse_pair on this text gives the same pair, features numbered alike.
std::string pair_file_text(const Pair& pair);

// ---- Reading a space file back (src/space/space_reader.cpp) ------------------------------

struct LoadSpaceResult {
  std::optional<Pair> pair;          // rebuilt from the embedded pair
  std::optional<SlicedSpace> space;  // slices recomputed at the stored orientations
  std::optional<InputError> error;   // why not, naming the file and the field
  bool ok() const { return space.has_value() && pair.has_value(); }
};

// Reads a space file written by `cslice compute` (space_to_json): checks its format and
// version, rebuilds the embedded pair, recomputes the critical orientations, checks that
// they and the slice orientations are the ones the file lists, recomputes every slice at its
// stored orientation (in parallel, `threads` as in SpaceOptions), the correspondence and the
// topology, and checks the recomputed summaries against the stored ones (free and bounded
// component counts and areas per slice, 3D components and cells). Any difference is an
// error, never silently accepted: the file was edited, truncated or written by another
// version of the program. Timing is taken from the file when present.
LoadSpaceResult load_space(const std::string& path, int threads = 0);
// The same from the file's text; `source` names it in errors.
LoadSpaceResult parse_space(std::string_view json_text, std::string_view source, int threads = 0);

}  // namespace cslice
