// CAD drawings in and out (docs/dxf-import.md). In: the outlines on two layers of an ASCII DXF
// file become the moving and the fixed part; lines, arcs, circles, polylines (with bulges),
// splines and ellipses (as arcs) and inserted blocks are read, and the pieces are joined end
// to end into closed loops. Out: a
// slice's free-space boundary as exact lines and arcs.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "cslice/geometry.hpp"
#include "cslice/pair.hpp"
#include "cslice/slice.hpp"

namespace cslice {

struct DxfImportOptions {
  std::string moving_layer = "moving";
  std::string fixed_layer = "fixed";
  bool fixed_enclosure = false;  // the fixed part is the region outside its loops
  // The drawing point that becomes the moving part's body origin, the point it turns about.
  Vec2 moving_origin;
  std::optional<double> tolerance;       // the pair's tolerance, in drawing units
  std::optional<double> join_tolerance;  // ends this close meet (default: kDxfJoinRelative)
  std::string name;                      // the pair's name (default: the source's)
};

// The drawing's text (`source` names it in errors) as a pair file's text, checked as
// parse_pair reads it: an error of the pair's loops names the DXF entities the loop came from.
struct DxfPairResult {
  std::optional<Pair> pair;
  std::string pair_json;
  std::optional<InputError> error;
  bool ok() const { return pair.has_value(); }
};
DxfPairResult import_dxf_pair(std::string_view dxf_text, std::string_view source,
                              const DxfImportOptions& options);
// import_dxf_pair of the file at `path`.
DxfPairResult load_dxf_pair(const std::string& path, const DxfImportOptions& options);

// The slice as a DXF drawing (R12, ASCII): each free component's boundary cycles as closed
// POLYLINEs with bulges (a whole circle as a CIRCLE) on layer FREE_<id>, perfect fits as POINTs
// on PERFECT_FIT, sliding fits as LINEs and ARCs on SLIDING_FIT. Coordinates are the moving
// part's body origin's, in the pair's units.
std::string slice_to_dxf(const Pair& pair, const Slice& slice);

}  // namespace cslice
