// `cslice import DRAWING.dxf|DRAWING.svg -o PAIR.json`: a pair file from two layers of a CAD
// drawing or two named elements of an SVG drawing (docs/dxf-import.md, docs/svg-import.md). The
// pair is checked as `cslice info` would read it before anything is written.
#include <cmath>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cslice/drawing.hpp"
#include "cslice/tolerance.hpp"

namespace cslice::cli {

namespace {

struct ImportOptions {
  std::string path, output = kStdout;
  std::string moving_layer = "moving", fixed_layer = "fixed", origin = "0,0", name;
  std::optional<std::string> fixed_origin;
  bool enclosure = false;
  std::optional<double> tolerance, join_tolerance;
};

std::string loops_summary(const Part& part) {
  return std::to_string(part.loops.size()) + (part.loops.size() == 1 ? " loop, " : " loops, ") +
         std::to_string(part.feature_count()) + " features";
}

void run_import(const ImportOptions& opts) {
  check_positive_length_or_exit(opts.tolerance, "--tolerance");
  check_positive_length_or_exit(opts.join_tolerance, "--join-tolerance");
  DrawingImportOptions options;
  options.moving_layer = opts.moving_layer;
  options.fixed_layer = opts.fixed_layer;
  options.fixed_enclosure = opts.enclosure;
  options.moving_origin = parse_point_or_exit(opts.origin, "--origin");
  if (opts.fixed_origin)
    options.fixed_origin = parse_point_or_exit(*opts.fixed_origin, "--fixed-origin");
  options.tolerance = opts.tolerance;
  options.join_tolerance = opts.join_tolerance;
  options.name = opts.name;
  DrawingPairResult result = load_drawing_pair(opts.path, options);
  if (!result.ok()) throw ExitError(kExitBadInput, result.error->message());
  const Pair& pair = *result.pair;
  const bool to_stdout = opts.output == kStdout;
  deliver_output(opts.output, std::move(result.pair_json));
  // A part drawn away from the drawing's origin turns about a point outside it: allowed (a
  // lever about its pivot), but more often a forgotten --origin.
  const Box& box = result.moving_box_drawn;
  const Vec2 o = options.moving_origin;
  if (box.lo.x > o.x || box.lo.y > o.y || box.hi.x < o.x || box.hi.y < o.y)
    std::cerr << "cslice: note: the moving part turns about the drawing point " << opts.origin
              << ", outside its box (" << format_point(box.lo) << " to " << format_point(box.hi)
              << "); --origin x,y names the point it turns about\n";
  // Far out on the sheet, the fixed part's coordinates are large beside the parts: say so at
  // the source, where one option mends it.
  const double coarsening = placement_coarsening(pair.moving, pair.fixed);
  if (coarsening >= kPlacementCoarseningWarning)
    std::cerr << "cslice: note: the fixed part lies far from the drawing's origin, so the pair's "
                 "tolerances are "
              << format_number(std::round(coarsening))
              << " times coarser than the parts need; --fixed-origin " << opts.origin
              << " (the --origin point) measures configurations from the drawn placement "
                 "instead, with full accuracy (docs/pair-format.md, Size and tolerances)\n";
  if (!to_stdout)
    std::cout << "wrote " << opts.output << ": pair '" << pair.name << "', moving part "
              << loops_summary(pair.moving) << ", fixed part " << loops_summary(pair.fixed)
              << "; as drawn, the configuration " << format_number(result.drawn_at.x) << ","
              << format_number(result.drawn_at.y) << ",0\n";
}

}  // namespace

void register_import(CLI::App& app) {
  auto opts = std::make_shared<ImportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "import",
      "Make a pair file from two layers of a DXF drawing, ASCII or binary (lines, arcs, circles, "
      "polylines with bulges, splines and ellipses as arcs, inserted blocks) or two named "
      "elements of an SVG drawing (paths, rectangles, circles, ellipses, polygons, reused "
      "elements; Bezier curves and elliptical arcs as arcs); loose pieces are joined end to end "
      "into loops (docs/dxf-import.md, docs/svg-import.md)");
  cmd->add_option("drawing", opts->path, "DXF (ASCII or binary) or SVG file")->required();
  cmd->add_option("-o,--output", opts->output, "Pair file to write (default: standard output)");
  cmd->add_option("--moving", opts->moving_layer,
                  "Layer (DXF) or element id or label (SVG) of the moving part (default: moving)");
  cmd->add_option("--fixed", opts->fixed_layer,
                  "Layer (DXF) or element id or label (SVG) of the fixed part (default: fixed)");
  cmd->add_flag("--enclosure", opts->enclosure,
                "The fixed part is the region outside its loops (a housing)");
  cmd->add_option("--origin", opts->origin,
                  "Drawing point x,y that becomes the moving part's body origin, the point it "
                  "turns about (default: 0,0)");
  cmd->add_option("--fixed-origin", opts->fixed_origin,
                  "Drawing point x,y that becomes the origin of the fixed part's coordinates and "
                  "of configuration space (default: the drawing's origin; the --origin point "
                  "makes the drawn placement 0,0,0)");
  cmd->add_option("--tolerance", opts->tolerance, "The pair's tolerance, in drawing units");
  cmd->add_option("--join-tolerance", opts->join_tolerance,
                  "Ends of lines and arcs this close meet (drawing units; default: 1e-6 of the "
                  "drawing's size)");
  cmd->add_option("--name", opts->name, "The pair's name (default: the file's)");
  cmd->callback([opts] { run_import(*opts); });
}

}  // namespace cslice::cli
