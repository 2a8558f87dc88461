// What the drawing readers (dxf_reader.cpp, svg_reader.cpp) hand to the loop builder
// (drawing_loops.cpp) and the pair writer (drawing_pair.cpp): the outline pieces of one layer
// or element, each knowing the entity or element it came from.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cslice/drawing.hpp"
#include "cslice/geometry.hpp"

namespace cslice::drawing {

// Thrown while reading a drawing; pair_from_drawing's callers turn it into an InputError.
struct DrawingError {
  std::string part, reason;
};

// Where a piece came from, for messages: "the LINE at line 57".
struct Origin {
  std::string entity;  // LINE, ARC, ... for DXF; <path id="p1">, ... for SVG
  int line = 0;        // 1-based line of the file where the entity starts
  std::string block;   // for an entity of a block: " in block 'B' (the INSERT at line N)"
  std::string describe() const;
};

// One edge from `from` to `to`: straight (bulge 0) or an arc of bulge tan(sweep / 4).
struct Piece {
  Vec2 from, to;
  double bulge = 0.0;
  Origin origin;
};

// A closed loop: one drawn closed (a closed polyline, a circle), or joined from pieces. As the
// pair file writes it: vertices with the bulge of the edge each starts, or a circle.
struct DrawnLoop {
  std::vector<Piece> edges;  // empty for a circle
  bool circle = false;
  Vec2 center;
  double radius = 0.0;
  std::string origin;  // the entities it was made of, described
};

struct Layer {
  std::vector<DrawnLoop> loops;  // drawn closed
  std::vector<Piece> pieces;     // lines, arcs and open polylines' edges, to be joined
  bool empty() const { return loops.empty() && pieces.empty(); }
};

// The $INSUNITS codes of the units a pair file may name (others are unitless to cslice).
inline constexpr std::pair<int, const char*> kInsunits[] = {{1, "in"}, {2, "ft"}, {4, "mm"},
                                                            {5, "cm"}, {6, "m"},  {13, "um"}};

// Layers and elements are named ignoring case, as CAD programs match layer names (R12 files
// store them upper case, whatever the user typed).
bool same_name(std::string_view a, std::string_view b);

// ---- Curves approximated by arcs (drawing_curves.cpp) -----------------------------------

// A vertex of an approximating chain: the point and the bulge of the edge it starts.
struct ArcVertex {
  Vec2 p;
  double bulge = 0.0;
};

// Arcs (and segments) within `tolerance` of curve(u) for u from breaks.front() to
// breaks.back(), each interval between breaks fitted on its own (at least four pieces each):
// the chain's vertices into `out` and its last point into `end`. False when more than
// `max_pieces` would be needed.
bool arcs_along(const std::function<Vec2(double)>& curve, const std::vector<double>& breaks,
                double tolerance, size_t max_pieces, std::vector<ArcVertex>& out, Vec2& end);

// Arcs one curve may need, at most.
inline constexpr size_t kMaxCurvePieces = 100000;

// The arcs within a hundredth of the pair's tolerance (`tolerance`, or the default one taken
// on `box`, the curve's) of curve(u), u through `breaks`, into `out` as pieces of `origin`; a
// cusp's repeated point draws nothing. Returns why it cannot (more than kMaxCurvePieces arcs,
// points beyond the range of numbers), or an empty string.
std::string follow_curve(const std::function<Vec2(double)>& curve,
                         const std::vector<double>& breaks, const Box& box,
                         std::optional<double> tolerance, const Origin& origin,
                         std::vector<Piece>& out);

// A NURBS curve as a DXF SPLINE gives it: degree, knots, control points, weights (empty:
// all 1).
struct Nurbs {
  int degree = 3;
  std::vector<double> knots;
  std::vector<Vec2> points;
  std::vector<double> weights;
};
// Why the curve is not well formed, or empty.
std::string check_nurbs(const Nurbs& n);
// The point at u, clamped to the curve's domain [knots[degree], knots[points]].
Vec2 nurbs_point(const Nurbs& n, double u);

// The layer's loops drawn closed, each without its edges shorter than `join` (a closing edge
// back to a start the last vertex repeats), then its pieces joined end to end (ends within
// `join` meet, each with exactly one other). Returns an empty string, or why it cannot (an
// open end, ends meeting three or more at a point).
std::string build_loops(const Layer& layer, double join, std::vector<DrawnLoop>& out);

// ---- The pair (drawing_pair.cpp) ----------------------------------------------------------

// Edges a drawing may give one part. A part outline of many thousand teeth or fitted arcs has
// tens of thousands; a small drawing arraying a block a thousand by a thousand would give
// millions, and every step after would take hours.
inline constexpr size_t kMaxPartEdges = 200000;

struct DrawnParts {
  Layer moving, fixed;  // each checked to have an outline
  std::string units;    // the pair's, or empty
  // SVG: the drawing's y axis points down, the pair's up (y is negated, arcs turn the other
  // way). Either way each part's coordinates are taken from its origin in the options.
  bool y_down = false;
};

// The parts `read` gives (it throws DrawingError on bad input) as a pair file, read back by
// parse_pair. `what` names a part's source in messages ("layer" or "element"); `source` is
// the file.
DrawingPairResult import_parts(std::string_view source, const DrawingImportOptions& options,
                               std::string_view what, const std::function<DrawnParts()>& read);
// `import` of the text of the file at `path`, or the error reading it.
DrawingPairResult import_file(const std::string& path,
                              const std::function<DrawingPairResult(std::string_view)>& import);

}  // namespace cslice::drawing
