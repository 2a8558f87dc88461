// Subcommands of the cslice program. Each lives in its own cmd_*.cpp and registers itself
// on the CLI11 app; main.cpp only dispatches and turns errors into exit statuses.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cslice/pair.hpp"
#include "cslice/space.hpp"

namespace cslice::cli {

// Exit statuses: 0 success, 1 a negative answer (e.g. no path), 2 bad input or usage.
inline constexpr int kExitBadInput = 2;

// Thrown by a command to stop with a message on standard error and the given status. A
// command writes nothing to standard output before it has succeeded.
struct ExitError : std::runtime_error {
  int code;
  ExitError(int exit_code, const std::string& message)
      : std::runtime_error(message), code(exit_code) {}
};

// An output path that means standard output.
inline constexpr const char* kStdout = "-";

// Writes every (path, text) output, or none: files go to temporaries renamed into place once
// all were written, and standard output ("-") comes last. Throws ExitError(2) on failure.
void deliver_outputs(std::vector<std::pair<std::string, std::string>> outputs);
// The same for one output, moved in: a braced list would copy the text (a space file of a
// larger pair is a gigabyte).
void deliver_output(const std::string& path, std::string text);
// The same for one output written as it is made (a space file of a larger pair is a gigabyte
// of text): to a temporary file renamed into place when `write` has finished, removed if it
// throws. Standard output gets the text once it is whole, as every output does.
void deliver_written(const std::string& path, const std::function<void(std::ostream&)>& write);

// Throws ExitError(2) unless a --threads value is 0 (every core) or more.
void check_threads_or_exit(int threads);
// Throws ExitError(2) naming `option` when a length given is not positive and finite.
void check_positive_length_or_exit(const std::optional<double>& value, const std::string& option);

// Loads a pair file or throws ExitError(2) with the reader's message.
Pair load_pair_or_exit(const std::string& path);
// Loads a space file (recomputing its slices on `threads`, 0 for every core) or throws
// ExitError(2) with the reader's message. The result's pair and space are both set.
LoadSpaceResult load_space_or_exit(const std::string& path, int threads);
// Parses "x,y,theta" (theta in radians) or throws ExitError(2) naming `what`.
Pose parse_pose_or_exit(const std::string& text, const std::string& what);
// Every pose of `in`, one "x y theta" per line (blank lines and '#' comments skipped), read
// before anything is answered so that a bad line stops the run with nothing printed; throws
// ExitError(2) naming the line.
std::vector<Pose> read_poses_or_exit(std::istream& in);
// Parses "x,y" or throws ExitError(2) naming `what`. Like a pose, commas or spaces separate.
Vec2 parse_point_or_exit(const std::string& text, const std::string& what);

// Parses "X0,Y0,X1,Y1" (X0 < X1, Y0 < Y1) or throws ExitError(2) naming `what`.
Box parse_box_or_exit(const std::string& text, const std::string& what);
// Parses "A,B" (two finite numbers) or throws ExitError(2) naming `what`.
std::pair<double, double> parse_range_or_exit(const std::string& text, const std::string& what);

// Numbers as the commands print them: six significant digits (printf's %g).
std::string format_number(double v);
// "(x, y)".
std::string format_point(Vec2 p);
// One line of a text summary: `label` padded to `width` columns, then `value`.
std::string summary_row(const std::string& label, int width, const std::string& value);

void register_info(CLI::App& app);
void register_classify(CLI::App& app);
void register_render(CLI::App& app);
void register_equivalent(CLI::App& app);
void register_slice(CLI::App& app);
void register_critical(CLI::App& app);
void register_mesh(CLI::App& app);
void register_compute(CLI::App& app);
void register_stats(CLI::App& app);
void register_analyze(CLI::App& app);
void register_query(CLI::App& app);
void register_path(CLI::App& app);
void register_view(CLI::App& app);
void register_import(CLI::App& app);

}  // namespace cslice::cli
