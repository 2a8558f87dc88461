// Point queries on a computed sliced space (`cslice query`): whether a configuration
// (x, y, theta) is free (and in which 3D free component), in contact (with which feature pair)
// or blocked, answered from the stored structure rather than by the placement test
// (src/space/query.cpp explains how, and when it falls back to a slice computed at theta).
#pragma once

#include <cstddef>
#include <memory>

#include "cslice/classify.hpp"
#include "cslice/space.hpp"

namespace cslice {

struct QueryAnswer {
  Placement placement = Placement::blocked;
  int component = -1;            // free: the 3D free component (SpaceTopology::components), or -1
  SegmentLabel contact{-1, -1};  // contact: the touching moving and fixed features
};

// How the answers were reached so far (for tests, benchmarks and reports).
struct QueryStats {
  std::size_t queries = 0;
  std::size_t at_stored_slice = 0;  // at a critical orientation: the stored slice answered
  std::size_t evaluated = 0;        // the interval's boundary evaluated in closed form at theta
  // Of those, answered by the interval's nearest stored slice: no realizable contact curve
  // comes within the contact tolerance of (x, y) between its orientation and theta.
  std::size_t far_from_contact = 0;
  std::size_t fallback = 0;                // a slice computed at theta (compute_slice) answered
  int intervals = 0, exact_intervals = 0;  // intervals whose boundary model validated
};

// Built once from a pair and its computed space (both must outlive it). Not thread-safe:
// it caches evaluated curves and fallback slices; make one per thread.
class SpaceQuery {
 public:
  SpaceQuery(const Pair& pair, const SlicedSpace& space);
  ~SpaceQuery();
  SpaceQuery(const SpaceQuery&) = delete;
  SpaceQuery& operator=(const SpaceQuery&) = delete;

  QueryAnswer query(const Pose& pose);
  const QueryStats& stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cslice
