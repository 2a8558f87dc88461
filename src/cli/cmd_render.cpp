// `cslice render PAIR.json --at x,y,theta -o out.svg`: a picture of the pair with the moving
// part placed at one pose. Everything is checked and the picture built in memory before the
// output file is opened, so a failed run leaves no file behind.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "cslice/render_svg.hpp"

namespace cslice::cli {
namespace {

struct RenderOptions {
  std::string pair_path;
  std::string at;
  std::string output;
  double width = 800.0;
  std::string title;
};

void write_output(const std::string& path, const std::string& svg) {
  if (path == "-") {
    std::cout << svg << std::flush;
    return;
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw ExitError(kExitBadInput, "cannot open '" + path + "' for writing");
  out << svg;
  out.close();
  if (!out) {
    std::remove(path.c_str());  // a truncated picture is worse than none
    throw ExitError(kExitBadInput, "cannot write '" + path + "'");
  }
}

void run_render(const RenderOptions& options) {
  if (!std::isfinite(options.width) || options.width <= 0.0)
    throw ExitError(kExitBadInput, "--width: expected a positive number of pixels");
  const Pose pose = parse_pose_or_exit(options.at, "--at");
  const Pair pair = load_pair_or_exit(options.pair_path);
  SvgOptions svg_options;
  svg_options.width_px = options.width;
  svg_options.title = options.title;
  write_output(options.output, render_pair_svg(pair, pose, svg_options));
}

}  // namespace

void register_render(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Draw the pair as SVG with the moving part placed at a pose: the fixed part shaded,\n"
      "the moving part translucent, its reference point and body x axis marked.");
  cmd->add_option("pair", options->pair_path, "Pair file (JSON)")->required();
  cmd->add_option("--at", options->at,
                  "Pose x,y,theta (theta in radians; use --at=-1,0,0 for negative x)")
      ->required();
  cmd->add_option("-o,--output", options->output, "Output SVG file ('-' for standard output)")
      ->required();
  cmd->add_option("--width", options->width, "Picture width in pixels (default 800)");
  cmd->add_option("--title", options->title, "Caption drawn at the top");
  cmd->callback([options] { run_render(*options); });
}

}  // namespace cslice::cli
