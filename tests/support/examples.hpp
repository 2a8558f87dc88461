// The bundled example pairs (examples/*.json), for tests and benchmarks. Header-only so the
// benchmarks can use it without the test support library; CSLICE_SOURCE_DIR is defined for
// both.
#pragma once

#include <stdexcept>
#include <string>

#include "cslice/pair.hpp"

namespace cslice::testkit {

inline std::string example_path(const std::string& name) {
  std::string path = CSLICE_SOURCE_DIR;  // appended piecewise: GCC 12 -Wrestrict false alarm
  path += "/examples/";
  path += name;
  path += ".json";
  return path;
}

// The example pair, or an exception naming why it does not load.
inline Pair load_example(const std::string& name) {
  LoadResult r = load_pair(example_path(name));
  if (!r.ok()) throw std::runtime_error(r.error->message());
  return std::move(*r.pair);
}

}  // namespace cslice::testkit
