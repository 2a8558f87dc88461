// The library's parallel passes run in oneTBB task arenas sized from a thread count as the
// options give it (SpaceOptions::threads, CriticalOptions::threads).
#pragma once

#include <tbb/info.h>

#include <algorithm>

namespace cslice {

// Threads for an arena asked for `threads`: every core for 0 (or less), else at most one
// per core. oneTBB never runs more threads than cores anyway, but asked for more it printed
// a warning on standard error (`--threads 4` on two cores), and an arena of more than 65,536
// slots crashed it (`cslice compute --threads 100000`).
inline int arena_threads(int threads) {
  const int cores = std::max(1, tbb::info::default_concurrency());
  return threads <= 0 ? cores : std::min(threads, cores);
}

}  // namespace cslice
