// `cslice query SPACE.json`: point queries answered from a computed space (SpaceQuery). Reads
// 'x y theta' lines from standard input, all of them before answering any, and prints one
// answer a line: `free C` (C the 3D free component), `contact M F` (the touching moving and
// fixed features) or `blocked`.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cslice/query.hpp"

namespace cslice::cli {
namespace {

struct QueryCommand {
  std::string space_path;
  int threads = 0;
};

void run(const QueryCommand& cmd) {
  check_threads_or_exit(cmd.threads);
  const LoadSpaceResult loaded = load_space_or_exit(cmd.space_path, cmd.threads);
  const std::vector<Pose> poses = read_poses_or_exit(std::cin);
  SpaceQuery query(*loaded.pair, *loaded.space);
  std::string out;
  out.reserve(poses.size() * 10);
  for (const Pose& pose : poses) {
    const QueryAnswer a = query.query(pose);
    switch (a.placement) {
      case Placement::free:
        out += "free " + std::to_string(a.component) + "\n";
        break;
      case Placement::contact:
        out += "contact " + std::to_string(a.contact.moving_feature) + " " +
               std::to_string(a.contact.fixed_feature) + "\n";
        break;
      case Placement::blocked:
        out += "blocked\n";
        break;
    }
  }
  deliver_output(kStdout, std::move(out));
}

}  // namespace

void register_query(CLI::App& app) {
  auto cmd = std::make_shared<QueryCommand>();
  CLI::App* sub = app.add_subcommand(
      "query",
      "Answer placements from a computed space (cslice compute): reads 'x y theta' lines\n"
      "(theta in radians; commas also separate; blank lines and lines starting with # are\n"
      "skipped) and prints 'free C' (C the 3D free component), 'contact M F' (the touching\n"
      "moving and fixed features) or 'blocked' for each.");
  sub->add_option("space", cmd->space_path, "Space file (JSON, see docs/space-format.md)")
      ->required();
  sub->add_option("--threads", cmd->threads,
                  "Slices recomputed at once when reading the file (default 0: every core)");
  sub->callback([cmd] { run(*cmd); });
}

}  // namespace cslice::cli
