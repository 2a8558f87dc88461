// `cslice critical PAIR.json [--json OUT] [--unscreened] [--whole-turn]`: the critical orientations
// of a pair, as a table with a summary of counts by condition, or as JSON (docs/criticals.md).
#include <chrono>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cslice/critical.hpp"
#include "cslice/slice_io.hpp"

namespace cslice::cli {

namespace {

struct CriticalCommand {
  std::string pair_path;
  std::string json_path;
  bool unscreened = false;
  bool whole_turn = false;
};

std::string pair_words(const Pair& pair, const FeaturePairRef& p) {
  return describe_feature(pair.moving, p.moving_feature) + " / " +
         describe_feature(pair.fixed, p.fixed_feature);
}

std::string table_text(const Pair& pair, const CriticalSet& set, double milliseconds) {
  std::string out;
  for (const CriticalOrientation& o : set.orientations) {
    out += "theta " + format_number(o.theta) + "\n";
    for (const Criticality& k : o.criticalities) {
      out += "  " + std::string(to_string(k.condition)) + ":";
      for (size_t i = 0; i < k.pairs.size(); ++i)
        out += (i ? "; " : " ") + pair_words(pair, k.pairs[i]);
      out += " at " + format_point(k.at) + "\n";
    }
  }
  out += summary_row("pair", 22, pair.name);
  out += summary_row("critical orientations", 22, std::to_string(set.orientations.size()));
  out += summary_row("criticalities", 22, std::to_string(set.stats.criticalities));
  for (int c = 0; c < kCriticalConditionCount; ++c)
    out += summary_row("  " + std::string(to_string(CriticalCondition(c))), 22,
                       std::to_string(set.counts[c]));
  out += summary_row("screened as blocked", 22, std::to_string(set.stats.blocked));
  out += summary_row("contact families", 22, std::to_string(set.stats.families));
  out += summary_row("equations solved", 22, std::to_string(set.stats.equations));
  out += summary_row("roots", 22, std::to_string(set.stats.roots));
  out += summary_row("  culled", 22, std::to_string(set.stats.culled));
  out += summary_row("  off their segments", 22, std::to_string(set.stats.off_segment));
  out += summary_row("mapped by symmetry", 22, std::to_string(set.stats.mapped));
  out += summary_row("time", 22, format_number(milliseconds) + " ms");
  return out;
}

void run(const CriticalCommand& cmd) {
  const Pair pair = load_pair_or_exit(cmd.pair_path);
  CriticalOptions options;
  options.screen_blocked = !cmd.unscreened;
  options.map_symmetric = !cmd.whole_turn;
  const auto start = std::chrono::steady_clock::now();
  const CriticalSet set = critical_orientations(pair, options);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (cmd.json_path.empty()) {
    std::cout << table_text(pair, set, ms) << std::flush;
    return;
  }
  deliver_output(cmd.json_path, critical_set_to_json(pair, set));
}

}  // namespace

void register_critical(CLI::App& app) {
  auto cmd = std::make_shared<CriticalCommand>();
  CLI::App* sub = app.add_subcommand(
      "critical",
      "The critical orientations of a pair: where the slice's contact graph can change.\n"
      "Prints each with its condition and feature pairs, then counts by condition.");
  sub->add_option("pair", cmd->pair_path, "Pair file (JSON, see docs/pair-format.md)")->required();
  sub->add_option("--json", cmd->json_path,
                  "Write them as JSON (docs/criticals.md); - for standard output");
  sub->add_flag("--unscreened", cmd->unscreened,
                "Keep criticalities that happen only in blocked space");
  sub->add_flag("--whole-turn", cmd->whole_turn,
                "Search every orientation, even those a symmetry of the pair maps from others\n"
                "(docs/symmetry.md; slower, the same critical orientations)");
  sub->callback([cmd] { run(*cmd); });
}

}  // namespace cslice::cli
