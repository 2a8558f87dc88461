// `cslice mesh SPACE.json -o contact.obj|.ply|.stl [--theta A,B] [--box X0,Y0,X1,Y1]
// [--tolerance T]`: the contact surface of a computed space as triangles (include/cslice/mesh.hpp),
// whole or in part (paper section 2.5). The format follows the output's extension.
#include <cmath>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cslice/mesh.hpp"

namespace cslice::cli {

namespace {

struct MeshCommand {
  std::string space_path;
  std::string out_path;
  std::string theta_range;
  std::string box;
  std::optional<double> tolerance;  // unset: the pair's contact tolerance
  int threads = 0;
};

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

MeshOptions mesh_options(const MeshCommand& cmd) {
  MeshOptions options;
  if (!cmd.theta_range.empty()) {
    const auto [from, to] = parse_range_or_exit(cmd.theta_range, "--theta");
    options.theta_from = wrap_angle(from);
    options.theta_to = to >= kPi ? kPi : wrap_angle(to);
  }
  if (!cmd.box.empty()) options.box = parse_box_or_exit(cmd.box, "--box");
  options.chord_tolerance = options.interpolation_tolerance = cmd.tolerance.value_or(0.0);
  return options;
}

void run(const MeshCommand& cmd) {
  std::string (*writer)(const ContactMesh&) = nullptr;
  if (ends_with(cmd.out_path, ".obj")) writer = &mesh_to_obj;
  if (ends_with(cmd.out_path, ".ply")) writer = &mesh_to_ply;
  const bool stl = ends_with(cmd.out_path, ".stl");
  if (!writer && !stl)
    throw ExitError(kExitBadInput, "-o: the output must end in .obj, .ply or .stl");
  check_threads_or_exit(cmd.threads);
  check_positive_length_or_exit(cmd.tolerance, "--tolerance");
  const MeshOptions options = mesh_options(cmd);
  const LoadSpaceResult loaded = load_space_or_exit(cmd.space_path, cmd.threads);
  const ContactMesh mesh = contact_mesh(*loaded.pair, *loaded.space, options);
  deliver_output(cmd.out_path, stl ? mesh_to_stl(mesh, loaded.pair->name) : writer(mesh));
}

}  // namespace

void register_mesh(CLI::App& app) {
  auto cmd = std::make_shared<MeshCommand>();
  CLI::App* sub = app.add_subcommand(
      "mesh",
      "The contact surface of a computed space as triangles in (x, y, theta): OBJ, PLY (with\n"
      "each vertex's feature pair) or STL, by the output's extension.");
  sub->add_option("space", cmd->space_path, "Space file (from cslice compute)")->required();
  sub->add_option("-o,--output", cmd->out_path, "Mesh file: .obj, .ply or .stl")->required();
  sub->add_option("--theta", cmd->theta_range,
                  "Clip the surface to theta in A,B (radians; A > B wraps through pi)");
  sub->add_option("--box", cmd->box, "Clip the surface to (x, y) in the box X0,Y0,X1,Y1");
  sub->add_option("--tolerance", cmd->tolerance,
                  "How far chords may cut arcs, and the surface between slices stray beyond "
                  "them (default: the pair's contact tolerance; docs/mesh.md, The bound). A "
                  "pair computed to a fine tolerance makes a large mesh: a coarser one here "
                  "makes a smaller one");
  sub->add_option("--threads", cmd->threads, "Slices recomputed at once (default: every core)");
  sub->callback([cmd] { run(*cmd); });
}

}  // namespace cslice::cli
