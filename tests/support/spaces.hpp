// Computing a pair's sliced space in tests, on a fixed thread count (header-only).
#pragma once

#include "cslice/space.hpp"

namespace cslice::testkit {

inline SlicedSpace space_of(const Pair& pair, int threads = 2) {
  SpaceOptions options;
  options.threads = threads;
  return compute_space(pair, options);
}

}  // namespace cslice::testkit
