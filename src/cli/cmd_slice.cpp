// `cslice slice PAIR.json --theta T [--json OUT] [--svg OUT] [--dxf OUT] [--mark x,y]`: the
// slice of configuration space at one orientation, as JSON (docs/slice-format.md), as an SVG
// picture, as a DXF drawing, or as a short summary on standard output. Every output is built in
// memory first and the files are only written once everything has succeeded, so a failure leaves
// none behind.
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/commands.hpp"
#include "cslice/dxf.hpp"
#include "cslice/render_svg.hpp"
#include "cslice/slice.hpp"
#include "cslice/slice_io.hpp"

namespace cslice::cli {

namespace {

struct SliceOptions {
  std::string pair_path;
  double theta = 0.0;
  std::string json_path;
  std::string svg_path;
  std::string dxf_path;
  std::string mark;
  bool all_segments = false;
};

// Summary lines: the label column is 21 wide.
std::string row(const char* label, const std::string& value) {
  return summary_row(label, 21, value);
}

std::string summary_text(const Pair& pair, const Slice& slice, const std::optional<Vec2>& mark) {
  const std::size_t realizable = realizable_segment_ids(slice).size();
  int bounded = 0;
  for (const FreeComponent& c : slice.free_components) bounded += c.bounded ? 1 : 0;
  std::string out = row("pair", pair.name) + row("theta", format_number(slice.theta) + " rad");
  out += row("contact segments", std::to_string(slice.contact_segments.size()) + " (" +
                                     std::to_string(realizable) + " realizable)");
  out += row("free components", std::to_string(slice.free_components.size()) + " (" +
                                    std::to_string(bounded) + " bounded)");
  out += row("degenerate contacts", std::to_string(slice.degenerate.size()));
  out += row("contact graph edges", std::to_string(slice.contact_graph.edges.size()));
  for (const FreeComponent& c : slice.free_components) {
    const std::string area =
        c.bounded ? "bounded, area " + format_number(c.area) + " " + pair.units + "^2"
                  : "unbounded";
    out += "component " + std::to_string(c.id) + ": " + area + ", sample " +
           format_point(c.sample) + "\n";
  }
  if (mark) {
    const int where = slice.locate(*mark);
    out += "mark " + format_point(*mark) + ": " +
           (where < 0 ? std::string("blocked or in contact")
                      : "free component " + std::to_string(where)) +
           "\n";
  }
  return out;
}

void run_slice(const SliceOptions& options) {
  const Pair pair = load_pair_or_exit(options.pair_path);
  if (!std::isfinite(options.theta))
    throw ExitError(kExitBadInput, "--theta: expected a finite angle in radians");
  if ((options.json_path == kStdout) + (options.svg_path == kStdout) +
          (options.dxf_path == kStdout) >
      1)
    throw ExitError(kExitBadInput, "only one of --json, --svg and --dxf can go to standard output");
  SlicePictureOptions picture;
  picture.show_all_segments = options.all_segments;
  if (!options.mark.empty()) picture.mark = parse_point_or_exit(options.mark, "--mark");
  const Slice slice = compute_slice(pair, options.theta);

  std::vector<std::pair<std::string, std::string>> outputs;
  if (!options.json_path.empty())
    outputs.emplace_back(options.json_path, slice_to_json(pair, slice));
  if (!options.svg_path.empty())
    outputs.emplace_back(options.svg_path, render_slice_svg(pair, slice, picture));
  if (!options.dxf_path.empty()) outputs.emplace_back(options.dxf_path, slice_to_dxf(pair, slice));
  if (outputs.empty()) {
    std::cout << summary_text(pair, slice, picture.mark) << std::flush;
    return;
  }
  deliver_outputs(std::move(outputs));
}

}  // namespace

void register_slice(CLI::App& app) {
  auto options = std::make_shared<SliceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "slice",
      "Compute the configuration-space slice at one orientation: contact segments, free\n"
      "components and the contact graph. Without --json, --svg or --dxf, prints a summary.");
  cmd->add_option("pair", options->pair_path, "Pair file (JSON, see docs/pair-format.md)")
      ->required();
  cmd->add_option("--theta", options->theta, "Orientation of the moving part, radians")->required();
  cmd->add_option("--json", options->json_path,
                  "Write the slice as JSON (docs/slice-format.md); - for standard output");
  cmd->add_option("--svg", options->svg_path,
                  "Write a picture of the slice as SVG; - for standard output");
  cmd->add_option("--dxf", options->dxf_path,
                  "Write the free-space boundary as a DXF drawing: exact lines and arcs, a layer "
                  "per free component (docs/dxf-import.md); - for standard output");
  cmd->add_option("--mark", options->mark,
                  "Mark the configuration x,y in the SVG and say which component holds it");
  cmd->add_flag("--all-segments", options->all_segments,
                "In the SVG, also draw contact segments that bound no free space (dashed)");
  cmd->callback([options] { run_slice(*options); });
}

}  // namespace cslice::cli
