// CAD drawings as pair files (docs/dxf-import.md, docs/svg-import.md). The outlines of two
// layers of a DXF drawing (ASCII or binary), or of two named elements of an SVG drawing,
// become the moving and the fixed part: lines, circular and elliptical arcs, circles,
// polylines, splines and Bezier curves (curves other than circular arcs as arcs within a
// hundredth of the tolerance), blocks and reused elements where they are placed. Loose pieces
// are joined end to end into loops.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "cslice/geometry.hpp"
#include "cslice/pair.hpp"

namespace cslice {

struct DrawingImportOptions {
  // The DXF layers, or the SVG elements (by id or Inkscape label), of the two parts.
  std::string moving_layer = "moving";
  std::string fixed_layer = "fixed";
  bool fixed_enclosure = false;  // the fixed part is the region outside its loops
  // The drawing point that becomes the moving part's body origin, the point it turns about.
  Vec2 moving_origin;
  // The drawing point that becomes the origin of the fixed part's coordinates, and so of
  // configuration space: by default the drawing's own origin; the moving origin's point makes
  // the drawn placement the configuration (0, 0, 0) and keeps the tolerances fine when the
  // parts lie far out on the sheet (docs/pair-format.md, Size and tolerances).
  Vec2 fixed_origin;
  std::optional<double> tolerance;       // the pair's tolerance, in drawing units
  std::optional<double> join_tolerance;  // ends this close meet (default: kDxfJoinRelative)
  std::string name;                      // the pair's name (default: the source's)
};

// The pair file's text, checked as parse_pair reads it: an error of the pair's loops names
// the drawing's entities or elements the loop came from.
struct DrawingPairResult {
  std::optional<Pair> pair;
  std::string pair_json;
  std::optional<InputError> error;
  // The configuration (drawn_at, 0) places the moving part as the drawing shows it.
  Vec2 drawn_at;
  // The moving part's box in the drawing's own coordinates, to tell whether --origin lies in it.
  Box moving_box_drawn;
  bool ok() const { return pair.has_value(); }
};

// The DXF drawing's text (`source` names it in errors).
DrawingPairResult import_dxf_pair(std::string_view dxf_text, std::string_view source,
                                  const DrawingImportOptions& options);
DrawingPairResult load_dxf_pair(const std::string& path, const DrawingImportOptions& options);

// The SVG drawing's text. Its y axis points down; the pair's points up, so the parts are the
// drawing's as seen on the page. Coordinates are in the document's unit (mm, cm or in from the
// root's width and viewBox; px otherwise), and so are the options' lengths.
DrawingPairResult import_svg_pair(std::string_view svg_text, std::string_view source,
                                  const DrawingImportOptions& options);
DrawingPairResult load_svg_pair(const std::string& path, const DrawingImportOptions& options);

// load_svg_pair or load_dxf_pair by the file's extension (.svg or .dxf, any case), else by
// its first non-blank character ('<' is SVG).
DrawingPairResult load_drawing_pair(const std::string& path, const DrawingImportOptions& options);

}  // namespace cslice
