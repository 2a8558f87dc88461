// `cslice stats PAIR.json... [--threads N] [--runs N]`: the paper's run-time table (Figure 8,
// section 2.6) for the given pairs, measured here, as a Markdown table with one row per pair.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cslice/space.hpp"

namespace cslice::cli {

namespace {

struct StatsCommand {
  std::vector<std::string> pair_paths;
  int threads = 1;
  int runs = 1;
};

// Three significant digits: run-to-run noise swamps any more.
std::string milliseconds(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", seconds * 1e3);
  return buf;
}

// "2 (5 of 40 slices)": the most free components any slice has, and how many slices have it.
std::string components_cell(const SlicedSpace& space) {
  size_t most = 0;
  for (const SpaceSlice& s : space.slices) most = std::max(most, s.slice.free_components.size());
  const auto with_most = std::count_if(space.slices.begin(), space.slices.end(), [&](auto& s) {
    return s.slice.free_components.size() == most;
  });
  return std::to_string(most) + " (" + std::to_string(with_most) + " of " +
         std::to_string(space.slices.size()) + " slices)";
}

// "2 (1 spans every θ)": the connected components of the 3D free space, and how many of them
// have free space at every orientation.
std::string components_3d_cell(const SlicedSpace& space) {
  const auto& comps = space.topology.components;
  const auto spanning = std::count_if(comps.begin(), comps.end(),
                                      [](const SpaceComponent& c) { return c.spans_all_theta; });
  return std::to_string(comps.size()) + " (" + std::to_string(spanning) + " span" +
         (spanning == 1 ? "s" : "") + " every θ)";
}

std::string row(const Pair& pair, const SlicedSpace& space) {
  const int moving = pair.moving.feature_count(), fixed = pair.fixed.feature_count();
  const std::vector<std::string> cells = {
      pair.name,
      std::to_string(moving + fixed) + " (" + std::to_string(moving) + "+" + std::to_string(fixed) +
          ")",
      std::to_string(space.criticals.orientations.size()) + " (" +
          std::to_string(space.criticals.stats.criticalities) + ")",
      milliseconds(space.seconds_criticals),
      std::to_string(space.slices.size()),
      milliseconds(space.seconds_slices),
      milliseconds(space.seconds_criticals + space.seconds_slices),
      components_cell(space),
      components_3d_cell(space)};
  std::string out = "|";
  for (const std::string& c : cells) out += " " + c + " |";
  return out + "\n";
}

// The pair's space computed `runs` times, keeping the fastest run (by total time). The space
// is the same every run; only the times differ. On a shared machine one run's time is mostly
// what its neighbours did meanwhile, and the first run in a fresh process also pays for
// touching its memory for the first time (docs/performance.md, "What the machine does to the
// times"); the fastest of a few is what the computation itself costs.
SlicedSpace fastest_run(const Pair& pair, const SpaceOptions& options, int runs) {
  SlicedSpace best = compute_space(pair, options);
  const auto total = [](const SlicedSpace& s) { return s.seconds_criticals + s.seconds_slices; };
  for (int r = 1; r < runs; ++r) {
    SlicedSpace space = compute_space(pair, options);
    if (total(space) < total(best)) best = std::move(space);
  }
  return best;
}

void run(const StatsCommand& cmd) {
  check_threads_or_exit(cmd.threads);
  if (cmd.runs < 1) throw ExitError(kExitBadInput, "--runs: expected 1 or more");
  // Every pair is read before anything is computed or printed: bad input prints nothing.
  std::vector<Pair> pairs;
  for (const std::string& path : cmd.pair_paths) pairs.push_back(load_pair_or_exit(path));
  SpaceOptions options;
  options.threads = cmd.threads;
  std::string out =
      "| example | features (moving+fixed) | critical orientations (criticalities) | time, ms "
      "| slices | time, ms | total time, ms | free components (slices with that many) "
      "| 3D free components |\n"
      "| :--- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const Pair& pair : pairs) out += row(pair, fastest_run(pair, options, cmd.runs));
  std::cout << out << std::flush;
}

}  // namespace

void register_stats(CLI::App& app) {
  auto cmd = std::make_shared<StatsCommand>();
  CLI::App* sub = app.add_subcommand(
      "stats",
      "The paper's run-time table (Figure 8) for the given pairs, as Markdown: features,\n"
      "criticalities and the time to find them, slices and the time to compute them, total\n"
      "time, the most free components in a slice, and the connected components of the 3D free\n"
      "space.");
  sub->add_option("pairs", cmd->pair_paths, "Pair files (JSON, see docs/pair-format.md)")
      ->required();
  sub->add_option("--threads", cmd->threads,
                  "Slices computed at once (default 1, as the paper's timings; 0: every core)");
  sub->add_option("--runs", cmd->runs,
                  "Compute each pair this many times and report the fastest run (default 1: "
                  "a single run, as a one-off `cslice compute` costs)");
  sub->callback([cmd] { run(*cmd); });
}

}  // namespace cslice::cli
