// Whether a configuration lies outside the contact tolerance band, for comparing answers
// with `classify`, which decides contact within that band (shared by the query tests and the
// stress driver).
#pragma once

#include <string>

#include "cslice/classify.hpp"
#include "cslice/query.hpp"
#include "cslice/slice.hpp"
#include "cslice/space.hpp"

namespace cslice::testkit {

// Blocked, and still blocked moved by d in each of eight directions.
bool deep_blocked(PlacementTester& tester, const Pose& pose, double d);

// Whether a realizable piece or a perfect fit of the slice at the pose's theta passes within
// d of it: the eight probes of deep_blocked miss the tip of a free wedge narrower than their
// spacing (stress seeds 100050, 100158, 100206: blocked in all eight directions, yet 0.0078
// from the tip of a thin pocket, with a contact tolerance of 0.0086).
bool near_realizable(const Pair& pair, const Pose& pose, double d);
// Whether a critical orientation lies within the critical angle of the pose's theta with a
// realizable piece within d of (x, y) in its slice, where the query answers from.
bool near_realizable_at_critical(const Pair& pair, const SlicedSpace& space, const Pose& pose,
                                 double d);

// Where query configurations are drawn: every contact curve of the stored slices, with a
// margin.
Box query_box(const SlicedSpace& space);

struct QueryAgreement {
  int checked = 0, free_count = 0, blocked_count = 0, mismatches = 0;
};

// Point queries against classify at `queries` random configurations: half anywhere in the
// query box, half near realizable contact of a stored slice (a random point of a random
// piece, moved by 0.05% to 5% of the pair's size, theta by up to a slice step), where free
// and blocked space meet. Configurations within the contact tolerance band (2 tolerances, by
// boundary distance, eight probes or the realizable pieces) are skipped; every other answer
// must be classify's, and free ones carry a valid 3D component. Failures are reported
// through GoogleTest, the first ten in full.
QueryAgreement compare_queries_with_classify(const Pair& pair, const SlicedSpace& space,
                                             SpaceQuery& q, int queries, unsigned seed,
                                             const std::string& name);

}  // namespace cslice::testkit
