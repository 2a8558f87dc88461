// `cslice info PAIR.json [--json]`: what the reader made of a pair file. Counts follow the
// paper (features = segments + arcs + vertices); the JSON fields are documented in
// docs/pair-format.md.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/commands.hpp"
#include "cslice/symmetry.hpp"

namespace cslice::cli {

namespace {

struct InfoOptions {
  std::string path;
  bool json = false;
};

// Role of a loop, from its depth: what lies just inside it.
std::string loop_role(const Part& part, const Loop& loop) {
  const bool even = loop.depth % 2 == 0;
  if (part.enclosure) return even ? "opening" : "island";
  return even ? "outer" : "hole";
}

std::string area_kind(const Part& part) {
  return part.enclosure ? "openings" : "material";
}

nlohmann::ordered_json part_json(const Part& part) {
  nlohmann::ordered_json loops = nlohmann::ordered_json::array();
  for (const Loop& loop : part.loops)
    loops.push_back({{"index", loop.source_index},
                     {"role", loop_role(part, loop)},
                     {"depth", loop.depth},
                     {"edges", loop.edges.size()},
                     {"circle", loop.is_circle()},
                     {"reversed", loop.reversed}});
  return {
      {"enclosure", part.enclosure},
      {"loops", part.loops.size()},
      {"segments", part.segment_count()},
      {"arcs", part.arc_count()},
      {"vertices", part.vertex_count()},
      {"features", part.feature_count()},
      {"box", {{"min", {part.box.lo.x, part.box.lo.y}}, {"max", {part.box.hi.x, part.box.hi.y}}}},
      {"area", part.area},
      {"area_kind", area_kind(part)},
      {"loop_details", loops}};
}

// What each symmetry of the pair does to theta ("pi - theta"), as docs/symmetry.md writes it.
std::vector<std::string> symmetry_names(const Pair& pair) {
  static const char* const turned[4] = {"theta", "theta + pi/2", "theta + pi", "theta - pi/2"};
  static const char* const reversed[4] = {"-theta", "pi/2 - theta", "pi - theta", "-pi/2 - theta"};
  std::vector<std::string> out;
  for (const PairSymmetry& s : pair_symmetries(pair))
    out.push_back((s.reverses_theta ? reversed : turned)[s.quarter_turns]);
  return out;
}

std::string info_json(const Pair& pair) {
  nlohmann::ordered_json requested = nullptr;
  if (pair.requested_tolerance) requested = *pair.requested_tolerance;
  const nlohmann::ordered_json out = {
      {"name", pair.name},
      {"units", pair.units},
      {"size", pair.tol.size},
      {"tolerance",
       {{"requested", requested},
        {"contact", pair.tol.contact},
        {"geometric", pair.tol.geometric},
        {"angular", pair.tol.angular}}},
      {"features", pair.moving.feature_count() + pair.fixed.feature_count()},
      {"symmetries", symmetry_names(pair)},
      {"moving", part_json(pair.moving)},
      {"fixed", part_json(pair.fixed)}};
  return out.dump(2) + "\n";
}

std::string count_of(int n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// "2 (1 outer loop, 1 hole)": the loop count and how nesting split it.
std::string loops_line(const Part& part) {
  int even = 0, odd = 0;
  for (const Loop& loop : part.loops) (loop.depth % 2 == 0 ? even : odd) += 1;
  std::string s = std::to_string(part.loops.size()) + " (" +
                  count_of(even, part.enclosure ? "opening" : "outer loop");
  if (odd > 0) s += ", " + count_of(odd, part.enclosure ? "island" : "hole");
  return s + ")";
}

void write_part(std::ostream& out, const Pair& pair, const Part& part) {
  out << part.name << " part"
      << (part.enclosure ? " (enclosure: the material is outside its loops)" : "") << "\n";
  const auto row = [&](const char* label, const std::string& value) {
    out << "  " << summary_row(label, 11, value);
  };
  row("loops", loops_line(part));
  row("segments", std::to_string(part.segment_count()));
  row("arcs", std::to_string(part.arc_count()));
  row("vertices", std::to_string(part.vertex_count()));
  row("features", std::to_string(part.feature_count()));
  row("box", format_point(part.box.lo) + " to " + format_point(part.box.hi));
  row("area", format_number(part.area) + " " + pair.units + "^2" +
                  (part.enclosure ? " (area of the openings)" : ""));
}

std::string info_text(const Pair& pair) {
  std::ostringstream out;
  const auto row = [&](const char* label, const std::string& value) {
    out << summary_row(label, 11, value);
  };
  row("pair", pair.name);
  row("units", pair.units);
  row("size", format_number(pair.tol.size) + " " + pair.units);
  row("tolerance", format_number(pair.tol.contact) + " " + pair.units +
                       (pair.requested_tolerance ? "" : " (default: 0.1% of the size)"));
  row("geometric", format_number(pair.tol.geometric) + " " + pair.units);
  row("features", std::to_string(pair.moving.feature_count() + pair.fixed.feature_count()) +
                      " (moving " + std::to_string(pair.moving.feature_count()) + ", fixed " +
                      std::to_string(pair.fixed.feature_count()) + ")");
  std::string symmetries;
  for (const std::string& name : symmetry_names(pair))
    symmetries += (symmetries.empty() ? "theta -> " : ", ") + name;
  row("symmetry", symmetries.empty() ? "none" : symmetries + " (docs/symmetry.md)");
  out << "\n";
  write_part(out, pair, pair.moving);
  out << "\n";
  write_part(out, pair, pair.fixed);
  return out.str();
}

void run_info(const InfoOptions& opts) {
  const Pair pair = load_pair_or_exit(opts.path);
  // Built completely before anything is written, so a failure leaves stdout empty.
  const std::string text = opts.json ? info_json(pair) : info_text(pair);
  std::cout << text << std::flush;
}

}  // namespace

void register_info(CLI::App& app) {
  auto opts = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand(
      "info", "Read and check a pair file; print its parts' loops, features, box and area");
  cmd->add_option("pair", opts->path, "Pair file (JSON, see docs/pair-format.md)")->required();
  cmd->add_flag("--json", opts->json, "Print the summary as JSON");
  cmd->callback([opts] { run_info(*opts); });
}

}  // namespace cslice::cli
