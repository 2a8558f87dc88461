// Pieces shared by the SVG writers: svg.cpp (a pair at one pose, drawn in world units with
// y negated) and slice_svg.cpp (a slice, drawn in pixels). Private to the library.
#pragma once

#include <array>
#include <string>

#include "cslice/geometry.hpp"

namespace cslice::svg {

// Concatenation by appending: GCC 12 warns falsely (-Wrestrict) on long operator+ chains.
template <typename... Parts>
std::string cat(const Parts&... parts) {
  std::string s;
  (s += ... += parts);
  return s;
}

// `v` with `digits` significant digits (printf's %g), never "-0".
std::string number(double v, int digits);
// `v` with `decimals` digits after the point (printf's %f).
std::string fixed(double v, int decimals);

// Text safe inside an XML element or a quoted attribute: & < > " ' as entities.
std::string xml_escape(const std::string& s);

// The larger of a box's width and height.
double larger_side(const Box& b);

// The largest 1, 2 or 5 times a power of ten not above `limit`: a round length for scale
// bars and tick spacing.
double nice_step(double limit);

// SVG arc flags for the world arc `c` (not a segment, not a full circle) drawn with y
// flipped, as both pictures are, since SVG's y axis points down. SVG's sweep flag 1 means
// increasing screen angle; the flip turns a counterclockwise world arc clockwise on screen,
// so a counterclockwise arc takes sweep flag 0 and a clockwise one sweep flag 1.
struct ArcFlags {
  bool large = false;
  bool sweep = false;
};
ArcFlags arc_flags(const Curve& c);

// An SVG arc whose ends coincide draws nothing, so a full circle goes as these two half
// circles (neither of them large), the first ending halfway round.
std::array<Curve, 2> split_full_circle(const Curve& c);

}  // namespace cslice::svg
