// `cslice path SPACE.json --from x,y,theta --to x,y,theta [--json] [-o FILE]`: a certified
// collision-free path between two configurations (include/cslice/path.hpp, docs/path.md).
// Exit 0 with the path; exit 1 with the answer why there is none (different free
// components, an end blocked or in contact, or no certified path found); exit 2 on bad input.
#include <charconv>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/commands.hpp"
#include "cslice/path.hpp"

namespace cslice::cli {
namespace {

struct PathCommand {
  std::string space_path, from, to, output = kStdout;
  bool json = false;
  int threads = 0;
};

// The shortest text that reads back as the same double: the printed path is exactly the one
// certified.
std::string exact(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string pose_text(const Pose& p) {
  return "(" + format_number(p.x) + ", " + format_number(p.y) + ", " + format_number(p.theta) + ")";
}

std::string feature_pair(const SegmentLabel& l) {
  return "moving feature " + std::to_string(l.moving_feature) + ", fixed feature " +
         std::to_string(l.fixed_feature);
}

// Why an end is not free, in words.
std::string end_problem(const char* which, const Pose& pose, const PathEnd& end) {
  std::string m = std::string("the ") + which + " " + pose_text(pose) + " is ";
  if (end.placement == Placement::contact)
    return m + "in contact: " + feature_pair(end.contact) + " touch";
  m += "blocked: the moving part overlaps the fixed part";
  if (end.contact.moving_feature >= 0) m += " (" + feature_pair(end.contact) + " cross)";
  return m;
}

std::string no_path_message(const PathCommand& cmd, const PathResult& r, const Pose& from,
                            const Pose& to) {
  switch (r.status) {
    case PathStatus::start_not_free:
      return "no path: " + end_problem("start", from, r.start);
    case PathStatus::goal_not_free:
      return "no path: " + end_problem("goal", to, r.goal);
    case PathStatus::different_components:
      return "no path: start is in free component " + std::to_string(r.start.component) +
             ", goal in free component " + std::to_string(r.goal.component);
    default:
      (void)cmd;
      return "no path found: start and goal are in free component " +
             std::to_string(r.start.component) + " but no certified path was found (" + r.problem +
             ")";
  }
}

using Json = nlohmann::ordered_json;

Json pose_json(const Pose& p) {
  return Json::array({p.x, p.y, p.theta});
}

Json end_json(const PathEnd& e) {
  Json j{{"placement", std::string(to_string(e.placement))}};
  if (e.placement == Placement::free) {
    j["component"] = e.component;
    j["clearance"] = e.clearance;
  } else if (e.contact.moving_feature >= 0) {
    j["moving_feature"] = e.contact.moving_feature;
    j["fixed_feature"] = e.contact.fixed_feature;
  }
  return j;
}

// Pretty-printed like the other commands' JSON, except that the path has one configuration
// a line. Numbers are printed exactly (shortest round trip).
std::string json_text(const PathResult& r, const Pose& from, const Pose& to,
                      const std::string& message, double tolerance) {
  Json j{{"status", std::string(to_string(r.status))},
         {"from", pose_json(from)},
         {"to", pose_json(to)},
         {"start", end_json(r.start)},
         {"goal", end_json(r.goal)}};
  if (r.status != PathStatus::found) {
    j["message"] = message;
    return j.dump(2) + "\n";
  }
  j["component"] = r.component;
  j["reach"] = r.reach;
  j["contact_tolerance"] = tolerance;
  std::string text = j.dump(2);
  text.resize(text.size() - 2);  // reopen the object: drop "\n}"
  text += ",\n  \"path\": [";
  for (size_t i = 0; i < r.poses.size(); ++i)
    text += (i ? ",\n    " : "\n    ") + pose_json(r.poses[i]).dump();
  text += "\n  ],\n  \"clearance\": " + Json(r.clearance).dump() + "\n}\n";
  return text;
}

void run(const PathCommand& cmd) {
  check_threads_or_exit(cmd.threads);
  const Pose from = parse_pose_or_exit(cmd.from, "--from");
  const Pose to = parse_pose_or_exit(cmd.to, "--to");
  const LoadSpaceResult loaded = load_space_or_exit(cmd.space_path, cmd.threads);
  const PathResult r = find_path(*loaded.pair, *loaded.space, from, to);
  const std::string message =
      r.status == PathStatus::found ? "" : no_path_message(cmd, r, from, to);
  std::string text;
  if (cmd.json) {
    text = json_text(r, from, to, message, loaded.pair->tol.contact);
  } else if (r.status == PathStatus::found) {
    for (const Pose& p : r.poses)
      text += exact(p.x) + " " + exact(p.y) + " " + exact(p.theta) + "\n";
  } else {
    text = message + "\n";
  }
  deliver_output(cmd.output, std::move(text));
  if (r.status != PathStatus::found)
    throw ExitError(1, cmd.output == kStdout ? "" : message);  // the answer is the output
}

}  // namespace

void register_path(CLI::App& app) {
  auto cmd = std::make_shared<PathCommand>();
  CLI::App* sub = app.add_subcommand(
      "path",
      "A collision-free path between two configurations, from a computed space (cslice\n"
      "compute): one 'x y theta' configuration a line, consecutive ones close enough that the\n"
      "straight motion between them (theta the short way round) is certified free. Exit 1,\n"
      "with the reason, when there is none: the ends in different free components, an end\n"
      "blocked or in contact, or no certified path found (docs/path.md).");
  sub->add_option("space", cmd->space_path, "Space file (JSON, see docs/space-format.md)")
      ->required();
  sub->add_option("--from", cmd->from, "Start configuration x,y,theta (theta in radians)")
      ->required();
  sub->add_option("--to", cmd->to, "Goal configuration x,y,theta")->required();
  sub->add_flag("--json", cmd->json,
                "Print JSON: status, ends, component, reach, path and clearances");
  sub->add_option("-o,--output", cmd->output, "Write to this file instead of standard output");
  sub->add_option("--threads", cmd->threads,
                  "Slices recomputed at once when reading the file (default 0: every core)");
  sub->callback([cmd] { run(*cmd); });
}

}  // namespace cslice::cli
