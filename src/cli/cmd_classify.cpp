// `cslice classify PAIR.json`: the direct placement test from the command line. Poses come
// from repeated --at options or, without them, one per line on standard input; the answer
// for each is one word (free, contact or blocked) on its own line.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cslice/classify.hpp"

namespace cslice::cli {
namespace {

struct ClassifyOptions {
  std::string pair_path;
  std::vector<std::string> at;
};

std::vector<Pose> poses_from_options(const std::vector<std::string>& at) {
  std::vector<Pose> poses;
  poses.reserve(at.size());
  for (std::size_t i = 0; i < at.size(); ++i)
    poses.push_back(parse_pose_or_exit(at[i], "--at #" + std::to_string(i + 1)));
  return poses;
}

void run_classify(const ClassifyOptions& options) {
  const Pair pair = load_pair_or_exit(options.pair_path);
  const std::vector<Pose> poses =
      options.at.empty() ? read_poses_or_exit(std::cin) : poses_from_options(options.at);
  PlacementTester tester(pair);
  // Buffered so that standard output stays empty if anything below throws.
  std::string out;
  out.reserve(poses.size() * 8);
  for (const Pose& pose : poses) {
    out += to_string(tester.classify(pose));
    out += '\n';
  }
  std::cout << out << std::flush;
}

}  // namespace

void register_classify(CLI::App& app) {
  auto options = std::make_shared<ClassifyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "classify",
      "Classify placements of the moving part as free, contact or blocked.\n"
      "Reads 'x y theta' lines (theta in radians; commas also separate; blank lines and\n"
      "lines starting with # are skipped) from standard input unless --at is given.");
  cmd->add_option("pair", options->pair_path, "Pair file (JSON)")->required();
  cmd->add_option("--at", options->at, "Pose x,y,theta to classify (repeatable; theta in radians)")
      ->allow_extra_args(false);
  cmd->callback([options] { run_classify(*options); });
}

}  // namespace cslice::cli
