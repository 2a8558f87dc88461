// `cslice compute PAIR.json -o SPACE.json [--threads N] [--verify-joins] [--from-scratch]`: the
// sliced configuration space of a pair (critical orientations, slices, correspondence), as JSON
// (docs/space-format.md).
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "cslice/space.hpp"

namespace cslice::cli {

namespace {

struct ComputeCommand {
  std::string pair_path;
  std::string out_path;
  int threads = 0;
  bool verify_joins = false;
  bool from_scratch = false;
};

void run(const ComputeCommand& cmd) {
  const Pair pair = load_pair_or_exit(cmd.pair_path);
  check_threads_or_exit(cmd.threads);
  SpaceOptions options;
  options.threads = cmd.threads;
  options.verify_joins = cmd.verify_joins;
  options.evaluate_slices = !cmd.from_scratch;
  options.map_symmetric = !cmd.from_scratch;
  std::optional<ProgressLine> progress(std::in_place, "cslice compute");
  options.progress = progress->report();
  const SlicedSpace space = compute_space(pair, options);
  progress.reset();  // the line is cleared before any message
  deliver_written(cmd.out_path, [&](std::ostream& out) { write_space_json(out, pair, space); });
}

}  // namespace

void register_compute(CLI::App& app) {
  auto cmd = std::make_shared<ComputeCommand>();
  CLI::App* sub = app.add_subcommand(
      "compute",
      "Compute the sliced configuration space of a pair: a slice at every critical\n"
      "orientation, one in every interval between them, and enough in between for linear\n"
      "interpolation to stay within the pair's tolerance (docs/space-format.md).");
  sub->add_option("pair", cmd->pair_path, "Pair file (JSON, see docs/pair-format.md)")->required();
  sub->add_option("-o,--output", cmd->out_path, "Space file to write; - for standard output")
      ->required();
  sub->add_option("--threads", cmd->threads,
                  "Slices computed at once (default 0: every core); the output is the same");
  sub->add_flag("--verify-joins", cmd->verify_joins,
                "Side slices at every critical orientation, each checked against its interval,\n"
                "even where the free-component counts decide the joins (slower; same result)");
  sub->add_flag("--from-scratch", cmd->from_scratch,
                "Every slice computed from scratch, none evaluated from its interval's\n"
                "representative or mapped across a symmetry of the pair (slower; the same\n"
                "result to round-off)");
  sub->callback([cmd] { run(*cmd); });
}

}  // namespace cslice::cli
