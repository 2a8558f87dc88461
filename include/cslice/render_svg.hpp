// SVG pictures of a pair. Lives apart from the core: nothing in the geometry depends on it.
#pragma once

#include <string>

#include "cslice/pair.hpp"

namespace cslice {

struct SvgOptions {
  double width_px = 800.0;  // drawing width; height follows the aspect ratio
  bool show_scale_bar = true;
  bool show_reference_point = true;
  std::string title;  // optional caption drawn at the top
};

// The fixed part shaded, the moving part placed at `pose`, its reference point marked, arcs
// drawn as true SVG arcs, with a scale bar in the pair's units.
std::string render_pair_svg(const Pair& pair, const Pose& pose, const SvgOptions& options = {});

// ---- Slices ------------------------------------------------------------------------------
// (src/render/slice_svg.cpp) A slice drawn like the paper's Figure 1 (right).

struct Slice;

struct SlicePictureOptions {
  double width_px = 800.0;  // plot width; its height follows the view's aspect ratio
  bool show_scale_bar = true;
  bool show_legend = true;
  // Also draw the contact segments that bound no free space, thin and dashed.
  bool show_all_segments = false;
  std::optional<Vec2> mark;  // a configuration (x, y) to mark with a dot
  std::string title;         // empty: "<pair>: theta = <theta>"
};

// Blocked space grey, free space white, realizable contact pieces coloured by contact kind
// (with a legend), degenerate contacts thick and black, arcs as true SVG arcs (+y up), a
// scale bar in the pair's units. The view fits the realizable pieces, or every contact
// segment when free space is unbounded.
std::string render_slice_svg(const Pair& pair, const Slice& slice,
                             const SlicePictureOptions& options = {});

}  // namespace cslice
