// Critical orientations of a symmetric pair from a fundamental domain of theta
// (docs/symmetry.md): the criticalities found there, and their images under the pair's
// symmetries, are every criticality.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "contacts/contact_features.hpp"
#include "cslice/critical.hpp"
#include "cslice/symmetry.hpp"

namespace cslice {

// The fundamental domain of the symmetries' action on theta, an arc whose images under them
// cover the whole turn: for turns by a quarter or half turn alone, one turn divided by their
// number; with a mirror theta -> c pi / 2 - theta as
// well, half of that, starting at the mirror's fixed orientation c pi / 4. Nothing when the
// symmetries are not a group of that form (as detection within a slack could leave them), or
// there are none.
std::optional<AngleInterval> fundamental_domain(const std::vector<PairSymmetry>& symmetries);

// Where a segment_end criticality of these features happens: its family's first end at theta.
// Called from several threads at once.
using SegmentEndPoint = std::function<Vec2(const FeaturePairRef&, double theta)>;

// Adds to `kept` (the criticalities found in the fundamental domain, grown a little) the
// images of its criticalities under every symmetry, except those found directly: a
// criticality repeats another when it has the same condition and feature pairs (in order for
// an endpoint, whose first pair owns the end; as a set otherwise), its theta is within the
// critical angle and its configuration within the criticality tolerance. Criticalities that
// repeat one another (two equations finding one event) keep their multiplicity. Returns how
// many were added.
long add_symmetric_images(std::vector<Criticality>& kept,
                          const std::vector<PairSymmetry>& symmetries, const Tolerances& tol,
                          const SegmentEndPoint& segment_end_at);

// Every orientation that lies within the critical angle of the image of an earlier one (in
// theta order) under a symmetry takes that image's angle exactly, so that the slices at them
// are each other's images (the slices' mapping needs them within the angular tolerance). The
// earlier orientation's angle is its median member's, and the image of that member is a
// member of the later one unless a criticality found there directly stood in for it.
void align_symmetric_orientations(CriticalSet& set, const std::vector<PairSymmetry>& symmetries,
                                  const Tolerances& tol);

}  // namespace cslice
