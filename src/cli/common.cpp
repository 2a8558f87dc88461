#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <istream>
#include <sstream>

#include "cli/commands.hpp"

namespace cslice::cli {

namespace {

// Blank lines and '#' comments carry no pose; everything else must be one.
bool is_skipped_line(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#';
}

// Reads one finite number into each of `values` from `text`, where commas count as spaces;
// false if any is missing or not finite, or anything follows them.
bool read_finite_numbers(const std::string& text, std::initializer_list<double*> values) {
  std::string normalized = text;
  for (char& ch : normalized)
    if (ch == ',') ch = ' ';
  std::istringstream in(normalized);
  for (double* v : values)
    if (!(in >> *v) || !std::isfinite(*v)) return false;
  std::string extra;
  return !(in >> extra);
}

// A pair whose tolerances are much coarser than its parts need only because the fixed part
// sits far from the moving part's body origin still gets its answer, with the reason and the
// remedy on standard error.
void warn_if_placed_far(const std::string& path, const Pair& pair) {
  const double coarsening = placement_coarsening(pair.moving, pair.fixed);
  if (!(coarsening >= kPlacementCoarseningWarning)) return;
  std::fprintf(stderr,
               "cslice: warning: %s: the fixed part lies far from the moving part's body origin, "
               "so every tolerance is %.0f times coarser than the parts need (geometric %.3g, "
               "contact %.3g %s); draw the fixed part near the origin for full accuracy "
               "(docs/pair-format.md, Size and tolerances)\n",
               path.c_str(), coarsening, pair.tol.geometric, pair.tol.contact, pair.units.c_str());
}

}  // namespace

Pair load_pair_or_exit(const std::string& path) {
  LoadResult result = load_pair(path);
  if (!result.ok()) throw ExitError(kExitBadInput, result.error->message());
  warn_if_placed_far(path, *result.pair);
  return std::move(*result.pair);
}

void check_threads_or_exit(int threads) {
  if (threads < 0) throw ExitError(kExitBadInput, "--threads: expected 0 or more");
}

void check_positive_length_or_exit(const std::optional<double>& value, const std::string& option) {
  if (value && !(std::isfinite(*value) && *value > 0.0))
    throw ExitError(kExitBadInput, option + ": expected a positive length");
}

LoadSpaceResult load_space_or_exit(const std::string& path, int threads) {
  LoadSpaceResult result = load_space(path, threads);
  if (!result.ok()) throw ExitError(kExitBadInput, result.error->message());
  return result;
}

Pose parse_pose_or_exit(const std::string& text, const std::string& what) {
  Pose p;
  if (!read_finite_numbers(text, {&p.x, &p.y, &p.theta})) {
    throw ExitError(kExitBadInput,
                    what + ": expected three finite numbers x,y,theta, got '" + text + "'");
  }
  return p;
}

Vec2 parse_point_or_exit(const std::string& text, const std::string& what) {
  Vec2 p;
  if (!read_finite_numbers(text, {&p.x, &p.y}))
    throw ExitError(kExitBadInput, what + ": expected two finite numbers x,y, got '" + text + "'");
  return p;
}

Box parse_box_or_exit(const std::string& text, const std::string& what) {
  double x0, y0, x1, y1;
  if (!read_finite_numbers(text, {&x0, &y0, &x1, &y1}) || x0 >= x1 || y0 >= y1)
    throw ExitError(kExitBadInput,
                    what + ": expected X0,Y0,X1,Y1 with X0 < X1 and Y0 < Y1, got '" + text + "'");
  Box box;
  box.add(Vec2{x0, y0});
  box.add(Vec2{x1, y1});
  return box;
}

std::pair<double, double> parse_range_or_exit(const std::string& text, const std::string& what) {
  double a, b;
  if (!read_finite_numbers(text, {&a, &b}))
    throw ExitError(kExitBadInput, what + ": expected two finite angles A,B, got '" + text + "'");
  return {a, b};
}

std::vector<Pose> read_poses_or_exit(std::istream& in) {
  std::vector<Pose> poses;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    // A byte order mark, as editors on Windows save UTF-8 text, is not part of the first pose.
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (is_skipped_line(line)) continue;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    poses.push_back(parse_pose_or_exit(line, "standard input, line " + std::to_string(number)));
  }
  return poses;
}

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string format_point(Vec2 p) {
  return "(" + format_number(p.x) + ", " + format_number(p.y) + ")";
}

std::string summary_row(const std::string& label, int width, const std::string& value) {
  std::string row = label;
  if (row.size() < static_cast<std::size_t>(width)) row.resize(width, ' ');
  return row + value + "\n";
}

}  // namespace cslice::cli
