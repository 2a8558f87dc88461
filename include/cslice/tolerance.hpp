// Every tolerance cslice uses, named by purpose. All lengths derive from one base value: the
// size of the pair (the diagonal of the bounding box of both parts, the moving part swept
// through every orientation about its origin). Nothing else in the code base may invent an
// epsilon; add it here with its unit and reason.
#pragma once

#include <optional>

namespace cslice {

// Relative round-off slack for lengths (dimensionless). Double arithmetic on coordinates of
// magnitude `size` is accurate to about 1e-15 * size; chained constructions (rotation,
// circle-circle intersection, square roots near tangency) lose up to half the digits, so
// 1e-9 leaves a wide margin while staying far below any length a designer means.
inline constexpr double kRelativeGeometricEpsilon = 1e-9;

// Default accuracy the user gets when the pair file names no tolerance: 0.1% of the size.
inline constexpr double kDefaultRelativeTolerance = 1e-3;

// How far a computed criticality may lie from the contact curves it involves, relative to
// the geometric epsilon (dimensionless). Closed-form roots are accurate to round-off at
// simple roots, but a near-double root (a grazing contact) keeps only about half the digits
// before polishing, and the point built from it (a radical centre, a foot of perpendicular)
// amplifies that again; a thousand geometric epsilons still sits far below any designed
// length.
inline constexpr double kCriticalityPerGeometric = 1e3;
// A triple point (three contact curves through one point) computed from two linear equations
// that lies within this much of all three curves, relative to its distance from the origin
// (at least 1), is kept without looking further: round-off of a well-conditioned solution,
// far below the criticality tolerance that validates it (src/criticals/events.cpp).
inline constexpr double kWellPlacedTriplePoint = 1e-12;

// A criticality equation whose extremum lies this close to zero, relative to its largest
// coefficient (dimensionless), has a double root there even when round-off makes it cross:
// a few hundred units in the last place of the terms that built the coefficients. The two
// roots such a crossing gives lie within sqrt(2 * this) ~ 3e-7 rad of each other, inside one
// critical angle, so merging them moves no critical orientation; it only stops the rounding
// from deciding where the event is validated (src/criticals/trig.cpp).
inline constexpr double kDoubleRootDepth = 4e-14;
// Two roots are merged as one double root only when this close (radians): one critical angle
// at any size, so that a merge never moves a critical orientation.
inline constexpr double kDoubleRootSpan = kCriticalityPerGeometric * kRelativeGeometricEpsilon;

// The flattest arc a part may have: its radius at most this many times the pair's size
// (dimensionless); flatter arcs are refused with a message to make them straight. Contact
// points of an arc's contacts travel at up to its radius R per radian (a vertex on a fixed
// arc follows the arc's normal as the vertex turns), so a critical orientation found to the
// angular tolerance (geometric / size) is placed to within R / size geometric epsilons, and
// validation and screening judge it within kCriticalityPerGeometric of them: R up to a tenth
// of that many sizes keeps a tenfold margin. Measured by stress runs on random curved pairs
// (completeness test of the critical orientations), by the radius of the flattest arcs in
// sizes: no failure in 102 pairs at 100 to 300 nor in 48 spread over 100 to 1,000; 2 of 66
// failed at 300 to 1,000, 9 of 47 at 10^3 to 10^4, 22 of 39 at 10^4 to 10^5, and beyond 10^5
// the slices themselves went wrong.
// At the limit an arc's sagitta is below size / 800.
inline constexpr double kMaxArcRadiusPerSize = kCriticalityPerGeometric / 10;

// How far from a critical orientation the 3D topology takes its side slices, as the square of
// the angle in angular tolerances (src/space/topology.cpp, side_slice_angle): at a tangency
// two contact curves separate quadratically in the angle, so at delta = sqrt(1e3 angular)
// they are a criticality tolerance (1e3 geometric epsilons at the pair's size) apart, enough
// for the side slice to show the interval's topology rather than the critical one; at a
// transversal crossing they are then sqrt(1e3 / angular) ~ 3e4 times further apart still.
inline constexpr double kSideSliceAngleSquaredPerAngular = kCriticalityPerGeometric;

// The contact mesh (src/mesh, docs/mesh.md). A strip triangle spans a chord of a slice, longer
// than the geometric epsilon (closer corners are one vertex), and the step in theta between
// two slices, at least half the critical angle (consecutive critical orientations are further
// apart, and an interval's slice lies between them): its area, in length x radians, is at
// least half their product. Triangles below this fraction of geometric x critical_angle are
// degenerate.
inline constexpr double kMeshTriangleAreaPerEpsilonAngle = 0.25;
// A critical slice's boundary cycle may run out and straight back along a piece barely longer
// than the geometric epsilon (a spike: blocked space of zero width reaching into free space,
// where three contact curves nearly meet at the critical orientation). Such a spike no longer
// than a criticality tolerance (kCriticalityPerGeometric geometric epsilons: the distance
// within which a criticality's configuration counts as on its curves) is that round-off; the
// mesh leaves it out of the cycle, or the strips on both sides of the slice would each attach
// to both of its passes.
inline constexpr double kMeshSpikePerGeometric = kCriticalityPerGeometric;
// Cutting the mesh at a plane (the seam at theta = pi, partial reconstruction) first moves
// onto the plane the vertices closer to it than this fraction of the critical angle (theta
// planes) or of the geometric epsilon (x and y planes), so that no cut leaves a sliver thinner
// than the slices themselves may be apart.
inline constexpr double kMeshPlaneSnapPerTolerance = 0.5;

// A part is symmetric under a quarter turn or mirror (include/cslice/symmetry.hpp) when every
// feature's image lies within this much of a feature of the same kind, relative to the pair's
// size: the round-off of coordinates drawn symmetric about a line off the origin (a mirror
// about x = 2.1 computes 4.2 - x, a unit in the last place of the coordinates), with a
// thousandfold margin. It sits a thousand times below the geometric epsilon, so a slice mapped
// across the symmetry differs from the slice computed at the image orientation by less than
// the round-off the computation carries anyway, and no part that a designer drew asymmetric on
// purpose passes for symmetric.
inline constexpr double kRelativeSymmetrySlack = 1e-12;
// Every tolerance scales with the pair's size, which reaches from the moving part's body
// origin to the fixed part (round-off grows with the coordinates). A fixed part drawn so far
// out that its size is this many times its centred size (placement_coarsening,
// include/cslice/pair.hpp) gets tolerances that much coarser than its own features need, and
// the command line warns. Stress runs with the fixed part moved away (cslice_stress --offset,
// every check; docs/pair-format.md, Size and tolerances): centred, no failure in 12,000
// designed and 1,000 random pairs; moved 30 (coarsening 7 to 12), 3 of 1,500 designed pairs;
// 100 (about 23), 3 of 1,500; 1,000 (about 220), 16 of 2,000, and 9 of 200 random pairs (about
// 130); 10,000 (about 1,300), 40 of 200 random pairs. The failures are fits and slivers that
// the slices resolve only to the coarser epsilon, over wider angles than the checks allow.
inline constexpr double kPlacementCoarseningWarning = 10.0;
// Outline pieces of a DXF drawing (lines, arcs, open polylines) continue each other where
// their ends lie this close, relative to the size of the drawing's two layers
// (dimensionless; src/parts/dxf_loops.cpp). CAD programs write coordinates to 16 digits, so
// ends meant to meet agree to about 1e-15 of the size; some exporters round to six decimals,
// 5e-7 of a drawing unit, which is 5e-9 of a 100 mm part. A thousandth of the default contact
// tolerance covers both, and ends that far apart were never meant to be one point.
inline constexpr double kDxfJoinRelative = 1e-6;
// A DXF SPLINE or ELLIPSE becomes circular arcs that stay within this fraction of the pair's
// tolerance of it (dimensionless; src/parts/dxf_curves.cpp): the approximation moves contact
// by a hundredth of what the user allows, and arcs follow a smooth curve closely with few
// pieces (the error of an arc through three points of a curve falls as the cube of its
// length). Without a tolerance given, the default one is taken on the curve's own box.
inline constexpr double kDxfCurveFitPerTolerance = 0.01;
// A path step is certified when its sweep stays below the clearances at its ends less twice
// the contact tolerance (docs/path.md, The certificate). Those clearances and the sweep are
// rounded relative to the magnitudes in play (the pair's size, the sweep, the clearances, the
// ends' coordinates), so this much of their sum comes off the margin too: a thousand times
// the relative error of the few operations behind them. Far out that matters: from a start at
// x = 1e300 the clearance and the sweep to a goal behind a wall were the same double, and the
// bare test certified the straight motion through the wall.
inline constexpr double kPathRelativeRounding = 1e-12;
// A contact segment is left out of a slice's arrangement only when proven blocked with this
// many geometric epsilons to spare all along (src/slice/blocked_proof.cpp): farther from
// free space than the arrangement ever joins points (eps) or copies split points between
// curves running side by side (eps), with room for the round-off of the proof's few
// operations (about 1e-15 of the size). Dimensionless, times Tolerances::geometric.
inline constexpr double kProvenBlockedMarginPerGeometric = 8.0;

struct Tolerances {
  // Length unit of the pair file (mm, in, ...). Base value everything scales with.
  double size = 1.0;
  // Two points closer than this are the same point; a curve closer than this to a point
  // passes through it; two curves this close are tangent or overlapping. Decides topology.
  double geometric = kRelativeGeometricEpsilon;
  // The user's accuracy: configurations within this distance of contact space may be
  // reported as contact. Always >= geometric.
  double contact = kDefaultRelativeTolerance;
  // Angles closer than this are equal (radians): the geometric epsilon seen at unit lever
  // arm of the pair's size, so that turning by it moves no point by more than `geometric`.
  double angular = kRelativeGeometricEpsilon;
  // A criticality's configuration lies on a contact curve when within this distance of it,
  // and in blocked space only when the parts overlap deeper than this (criticalities
  // screened out of blocked space must not be lost to their own round-off).
  double criticality = kCriticalityPerGeometric * kRelativeGeometricEpsilon;
  // Criticalities closer than this (radians) are one critical orientation: the criticality
  // tolerance seen at the pair's size as lever arm. Symmetric and parallel designs put
  // several exactly at one orientation, which round-off scatters by far less than this.
  double critical_angle = kCriticalityPerGeometric * kRelativeGeometricEpsilon;
};

// Derives every tolerance from the pair's size and the user's tolerance (if any).
// `size` must be positive and finite.
Tolerances make_tolerances(double size, std::optional<double> user_tolerance = std::nullopt);

}  // namespace cslice
