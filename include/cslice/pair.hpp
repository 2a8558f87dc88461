// A pair: the moving part (in its body frame) and the fixed part, read from a pair file.
// The file format is documented in docs/pair-format.md.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "cslice/part.hpp"
#include "cslice/tolerance.hpp"

namespace cslice {

struct Pair {
  std::string name;
  std::string units = "mm";
  std::optional<double> requested_tolerance;  // as given in the file
  Part moving;
  Part fixed;
  Tolerances tol;  // derived from the pair's size and the requested tolerance
};

// Why an input was rejected. Fields that do not apply are empty or -1; loop and vertex are
// 0-based indices as they appear in the file.
struct InputError {
  std::string file;
  std::string part;  // "moving" or "fixed"
  int loop = -1;
  int vertex = -1;
  std::string reason;
  // "file: part 'moving', loop 2, vertex 5: zero-length edge (...)"
  std::string message() const;
};

struct LoadResult {
  std::optional<Pair> pair;
  std::optional<InputError> error;
  bool ok() const { return pair.has_value(); }
};

// Parses and validates a pair from JSON text; `source` names it in errors.
LoadResult parse_pair(std::string_view json_text, std::string_view source);
// Reads a pair file from disk.
LoadResult load_pair(const std::string& path);

// The size every tolerance scales with: the diagonal of the box holding the fixed part and
// the moving part's disc of reach (its farthest point from the body origin, any rotation).
double pair_size(const Part& moving, const Part& fixed);
// How many times pair_size exceeds what it would be with the fixed part's box centred on the
// moving part's body origin (1 for a centred pair): a fixed part drawn far from that origin
// makes every tolerance this many times coarser than the parts themselves need, because
// round-off grows with the coordinates.
double placement_coarsening(const Part& moving, const Part& fixed);

}  // namespace cslice
