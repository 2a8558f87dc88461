// `cslice import DRAWING.dxf -o PAIR.json`: a pair file from two layers of a CAD drawing
// (docs/dxf-import.md). The pair is checked as `cslice info` would read it before anything
// is written.
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cslice/dxf.hpp"

namespace cslice::cli {

namespace {

struct ImportOptions {
  std::string path, output = kStdout;
  std::string moving_layer = "moving", fixed_layer = "fixed", origin = "0,0", name;
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
  DxfImportOptions options;
  options.moving_layer = opts.moving_layer;
  options.fixed_layer = opts.fixed_layer;
  options.fixed_enclosure = opts.enclosure;
  options.moving_origin = parse_point_or_exit(opts.origin, "--origin");
  options.tolerance = opts.tolerance;
  options.join_tolerance = opts.join_tolerance;
  options.name = opts.name;
  DxfPairResult result = load_dxf_pair(opts.path, options);
  if (!result.ok()) throw ExitError(kExitBadInput, result.error->message());
  const Pair& pair = *result.pair;
  const bool to_stdout = opts.output == kStdout;
  deliver_output(opts.output, std::move(result.pair_json));
  // A part drawn away from the drawing's origin turns about a point outside it: allowed (a
  // lever about its pivot), but more often a forgotten --origin.
  const Box& box = pair.moving.box;
  if (box.lo.x > 0.0 || box.lo.y > 0.0 || box.hi.x < 0.0 || box.hi.y < 0.0)
    std::cerr << "cslice: note: the moving part turns about the drawing point " << opts.origin
              << ", outside its box (" << format_point(box.lo + options.moving_origin) << " to "
              << format_point(box.hi + options.moving_origin)
              << "); --origin x,y names the point it turns about\n";
  if (!to_stdout)
    std::cout << "wrote " << opts.output << ": pair '" << pair.name << "', moving part "
              << loops_summary(pair.moving) << ", fixed part " << loops_summary(pair.fixed) << "\n";
}

}  // namespace

void register_import(CLI::App& app) {
  auto opts = std::make_shared<ImportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "import",
      "Make a pair file from two layers of an ASCII DXF drawing: lines, arcs, circles, "
      "polylines (with bulges), splines and ellipses (as arcs) and inserted blocks; loose "
      "pieces are joined end to end into loops (docs/dxf-import.md)");
  cmd->add_option("drawing", opts->path, "DXF file (ASCII)")->required();
  cmd->add_option("-o,--output", opts->output, "Pair file to write (default: standard output)");
  cmd->add_option("--moving", opts->moving_layer, "Layer of the moving part (default: moving)");
  cmd->add_option("--fixed", opts->fixed_layer, "Layer of the fixed part (default: fixed)");
  cmd->add_flag("--enclosure", opts->enclosure,
                "The fixed part is the region outside its loops (a housing)");
  cmd->add_option("--origin", opts->origin,
                  "Drawing point x,y that becomes the moving part's body origin, the point it "
                  "turns about (default: 0,0)");
  cmd->add_option("--tolerance", opts->tolerance, "The pair's tolerance, in drawing units");
  cmd->add_option("--join-tolerance", opts->join_tolerance,
                  "Ends of lines and arcs this close meet (drawing units; default: 1e-6 of the "
                  "drawing's size)");
  cmd->add_option("--name", opts->name, "The pair's name (default: the file's)");
  cmd->callback([opts] { run_import(*opts); });
}

}  // namespace cslice::cli
