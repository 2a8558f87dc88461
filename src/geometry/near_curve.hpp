// Whether a point lies within a distance of a curve, decided as distance_to_curve would
// decide it (the same answer for every input, bit for bit), but without its arc angle or
// its nearest point wherever a cheaper bound already settles it. Slice::locate asks this
// of every boundary piece, and most pieces lie far from the point asked about.
#pragma once

#include "cslice/geometry.hpp"

namespace cslice {

// distance_to_curve(c, p) <= eps, exactly.
bool within_distance(const Curve& c, Vec2 p, double eps);

// Whether p lies farther than eps outside the box of segment c's ends by a margin that
// covers every rounding of distance_to_curve on c: then its distance exceeds eps as
// computed. False means "not proved", never "near". Exposed for its test.
bool segment_box_rejects(const Curve& c, Vec2 p, double eps);

// Whether p lies farther than eps from a segment's line by a margin that covers the rounding
// of that distance and of distance_to_curve on coordinates of their size, or, on an arc,
// farther than eps from its circle and from both its ends: then distance_to_curve(c, p) >
// eps as computed. False means "not proved", never "near". Cheap (no nearest point, no
// angle) where points lie inside a curve's box but off its line: the ends and crossings of
// curves crossing it at an angle.
bool carrier_rejects(const Curve& c, Vec2 p, double eps);

}  // namespace cslice
