// The SVG reader's path and number parsing (svg_path.cpp), apart from the document walk
// (svg_reader.cpp).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cslice/geometry.hpp"

namespace cslice::drawing {

// One drawing command of a path, in the path's own coordinates, absolute.
struct SvgSegment {
  enum class Kind { line, quadratic, cubic, arc };
  Kind kind = Kind::line;
  // line: p[0] to p[1]; quadratic: p[0], control p[1], p[2]; cubic: p[0], p[1], p[2], p[3];
  // arc: p[0] to p[1] on the ellipse of radii rx, ry turned by `rotation` degrees, with
  // SVG's large-arc and sweep flags.
  Vec2 p[4];
  double rx = 0.0, ry = 0.0, rotation = 0.0;
  bool large = false, sweep = false;
};

struct SvgSubpath {
  std::vector<SvgSegment> segments;
  bool closed = false;  // ended by Z (its closing line is the last segment, if it has length)
};

// The subpaths of path data (SVG 1.1's grammar: M L H V C S Q T A Z, relative in lower case,
// numbers as "-1.5e3", ".5", "1.5.5" is 1.5 then .5, flags as single digits). On a syntax
// error returns false with `error` saying what was expected where ("at character 17").
bool parse_svg_path(std::string_view d, std::vector<SvgSubpath>& out, std::string& error);

// The numbers of a list (a points attribute, a viewBox), separated by blanks or commas.
bool parse_svg_numbers(std::string_view s, std::vector<double>& out, std::string& error);

}  // namespace cslice::drawing
