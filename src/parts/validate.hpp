// Validation of pair files, shared by the reader (pair_reader.cpp) and its tests. The reader
// turns JSON into raw loops (numbers as written, in file order); these routines check them in
// two stages: first the raw numbers (counts, degenerate edges) so curves can be built safely,
// then the built curves (simple loops, loops of a part disjoint). Each check returns the
// first problem as an InputError without the file name; the reader fills that in.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cslice/pair.hpp"

namespace cslice::detail {

// Largest coordinate, radius, bulge or tolerance magnitude a pair file may hold. Doubles
// resolve about 1e-16 of a magnitude, so with coordinates up to 1e9 the geometric epsilon
// (1e-9 of the size) still spans many representable values; larger values are almost always
// unit mistakes or corrupt files.
inline constexpr double kMaxMagnitude = 1e9;

struct RawVertex {
  Vec2 p;
  double bulge = 0.0;
};

// One loop as written: a vertex list, or a circle.
struct RawLoop {
  std::vector<RawVertex> vertices;
  bool is_circle = false;
  Vec2 center;
  double radius = 0.0;
};

struct RawPart {
  std::string name;  // "moving" or "fixed"
  std::vector<RawLoop> loops;
  bool enclosure = false;
};

// Size estimate from the raw numbers (vertices and circles only, arcs' bulges ignored): the
// same box as pair_size but without the arcs' extreme points, so it never exceeds it. Used
// to get a geometric epsilon before any curve exists.
double raw_pair_size(const RawPart& moving, const RawPart& fixed);

// Structural checks on raw loops: vertex counts, circle radii, zero-length edges, arcs too
// flat to tell from a segment, two-vertex loops without area.
std::optional<InputError> check_raw_part(const RawPart& part, const Tolerances& tol);

// Builds the part's loops (file order, file orientation) from validated raw loops.
Part build_part(const RawPart& raw);

// Checks the built curves: arc centers and radii within kMaxMagnitude, every loop simple
// (edges meet only at shared vertices), and no two loops of the part touching or crossing.
// Candidate edge pairs come from a bounding-box sweep, so the cost is near-linear for parts
// whose edges are small compared with the part.
std::optional<InputError> check_part_curves(const Part& part, const Tolerances& tol);

// The whole file at `path` into `text`, or why not (a directory, cannot open, read error).
std::optional<InputError> read_input_file(const std::string& path, std::string& text);

// Number formatting for messages: shortest form that still tells values apart.
std::string format_number(double v);
std::string format_point(Vec2 p);

}  // namespace cslice::detail
