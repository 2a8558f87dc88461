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

}  // namespace cslice
