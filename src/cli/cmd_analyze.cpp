// `cslice analyze SPACE.json [--json] [--threads N]`: what a computed space says about its
// pair: 3D components and their theta coverage, the transitions at the critical orientations,
// per slice the free components, free area and channel width, and the checks of the paper's
// applications for the pairs that model them (docs/space-format.md, "Analysis").
#include <memory>
#include <sstream>

#include "cli/commands.hpp"
#include "cslice/analyze.hpp"

namespace cslice::cli {

namespace {

struct AnalyzeCommand {
  std::string space_path;
  bool json = false;
  int threads = 0;
};

std::string ranges_text(const std::vector<std::pair<double, double>>& ranges) {
  std::string out;
  for (const auto& [a, b] : ranges) {
    // Appended piecewise: GCC 12 -Wrestrict false alarm on chained concatenation.
    if (!out.empty()) out += ", ";
    out += "(";
    out += format_number(a);
    out += ", ";
    out += format_number(b);
    out += ")";
  }
  return out.empty() ? "none" : out;
}

std::string cells_text(const std::vector<int>& cells) {
  if (cells.empty()) return "-";
  std::string out;
  for (int c : cells) out += (out.empty() ? "" : ",") + std::to_string(c);
  return out;
}

std::string padded(std::string text, size_t width) {
  if (text.size() < width) text.resize(width, ' ');
  return text;
}

std::string report(const SpaceAnalysis& a, const SlicedSpace& space) {
  std::ostringstream out;
  const int w = 22;
  out << summary_row("pair", w, a.pair);
  out << summary_row("critical orientations", w,
                     std::to_string(space.criticals.orientations.size()));
  out << summary_row("slices", w, std::to_string(space.slices.size()));
  out << summary_row("3D free components", w, std::to_string(a.components.size()));
  for (const ComponentCoverage& c : a.components)
    out << "  component " << c.id << ": " << c.cells << " cell" << (c.cells == 1 ? "" : "s")
        << ", theta in " << ranges_text(c.theta_ranges) << " (" << format_number(c.theta_coverage)
        << " rad" << (c.spans_all_theta ? ", spans every theta" : "") << ")\n";

  out << "\ntransitions (components before -> at -> after the critical orientation):\n";
  for (const TransitionSummary& t : a.transitions) {
    std::string kinds;
    for (const TransitionEvent& e : t.events)
      kinds += (kinds.empty() ? "" : "; ") + std::string(to_string(e.kind)) + " " +
               cells_text(e.before) + " -> " + cells_text(e.after);
    out << "  theta " << padded(format_number(t.theta), 12)
        << padded(std::to_string(t.criticalities) + " criticalit" +
                      (t.criticalities == 1 ? "y" : "ies"),
                  18)
        << padded(std::to_string(t.components_before) + " -> " +
                      std::to_string(t.critical_components) + " -> " +
                      std::to_string(t.components_after),
                  14)
        << "cells " << kinds << "\n";
  }

  out << "\nslices:\n  " << padded("theta", 13) << padded("kind", 14) << padded("interval", 10)
      << padded("free", 6) << padded("free area", 14) << "channel width\n";
  for (const SliceSummary& s : a.slices) {
    std::string area = format_number(s.free_area);
    if (s.unbounded_free_space)
      area += s.bounded_free_components > 0 ? " + unbounded" : "unbounded";
    if (s.unbounded_free_space && s.bounded_free_components == 0) area = "unbounded";
    out << "  " << padded(format_number(s.theta), 13) << padded(std::string(to_string(s.kind)), 14)
        << padded(std::to_string(s.interval), 10) << padded(std::to_string(s.free_components), 6)
        << padded(area, 14) << (s.channel_width ? format_number(*s.channel_width) : "-") << "\n";
  }

  out << "\n";
  if (a.channel.is_channel)
    out << "channel: one bounded channel through every theta, width "
        << format_number(a.channel.min_width) << " to " << format_number(a.channel.max_width)
        << "\n";
  else
    out << "channel: none (the free space is not a single bounded channel)\n";

  if (!a.application.empty()) {
    out << "\nchecks (" << a.application << ", paper section 2):\n";
    for (const ApplicationCheck& c : a.checks)
      out << "  [" << (c.passed ? "pass" : "FAIL") << "] " << c.name
          << (c.detail.empty() ? "" : ": " + c.detail) << "\n";
  }
  return out.str();
}

void run(const AnalyzeCommand& cmd) {
  check_threads_or_exit(cmd.threads);
  const LoadSpaceResult loaded = load_space_or_exit(cmd.space_path, cmd.threads);
  const SpaceAnalysis analysis = analyze_space(*loaded.pair, *loaded.space);
  deliver_output(kStdout, cmd.json ? analysis_to_json(analysis) : report(analysis, *loaded.space));
  // A failed check of the paper's applications is a negative answer, printed then reported.
  if (!analysis.all_checks_passed()) throw ExitError(1, "");
}

}  // namespace

void register_analyze(CLI::App& app) {
  auto cmd = std::make_shared<AnalyzeCommand>();
  CLI::App* sub = app.add_subcommand(
      "analyze",
      "Analyze a computed space (cslice compute): 3D free components and their theta\n"
      "coverage, transitions at the critical orientations, free components, free area and\n"
      "channel width per slice, and checks of the paper's applications (cam, fastener,\n"
      "fixture, knee). Exit status 1 when such a check fails.");
  sub->add_option("space", cmd->space_path, "Space file (JSON, see docs/space-format.md)")
      ->required();
  sub->add_flag("--json", cmd->json, "Print the analysis as JSON instead of a report");
  sub->add_option("--threads", cmd->threads,
                  "Slices recomputed at once when reading the file (default 0: every core)");
  sub->callback([cmd] { run(*cmd); });
}

}  // namespace cslice::cli
