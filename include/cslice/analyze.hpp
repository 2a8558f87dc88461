// What a computed space says about its pair (paper section 2): the 3D free components and
// the orientations they cover, the transitions at the critical orientations, per slice the
// free components, free area and channel width, and named checks of the paper's four
// applications when the pair is one of them (docs/space-format.md, "Analysis").
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cslice/space.hpp"

namespace cslice {

struct ComponentCoverage {
  int id = 0;
  int cells = 0;
  bool spans_all_theta = false;
  std::vector<std::pair<double, double>> theta_ranges;  // as SpaceComponent::theta_ranges
  double theta_coverage = 0.0;  // total length of the ranges, radians (2 pi: every theta)
};

struct TransitionSummary {
  int critical = 0;
  double theta = 0.0;
  int criticalities = 0;
  int counts[kCriticalConditionCount] = {};  // criticalities by condition
  // Free components (cells) in the intervals before and after, and of the critical slice.
  int components_before = 0, components_after = 0, critical_components = 0;
  std::vector<TransitionEvent> events;
};

struct SliceSummary {
  double theta = 0.0;
  SliceKind kind = SliceKind::interval;
  int interval = 0;
  int free_components = 0;
  int bounded_free_components = 0;
  double free_area = 0.0;  // of the bounded free components
  bool unbounded_free_space = false;
  // When the slice's free space is a single bounded component: its smallest extent
  // (component_min_width) and its bounding box's width and height.
  std::optional<double> channel_width;
  std::optional<Vec2> channel_box;
};

// The space is a single bounded channel: one 3D component spanning every theta, and every
// slice's free space one bounded component. Widths over the slices.
struct ChannelSummary {
  bool is_channel = false;
  double min_width = 0.0, max_width = 0.0;
};

// A named check of one of the paper's applications.
struct ApplicationCheck {
  std::string name;  // e.g. "one component spanning every theta"
  bool passed = false;
  std::string detail;  // the numbers behind it, in words
};

// cam (paper 2.2): the follower clearance at each slice, from the geometry alone: the
// opening's width and height less the cam's extent along x and y at that theta.
struct CamAnalysis {
  double min_clearance = 0.0, max_clearance = 0.0;
  double max_width_error = 0.0;  // largest |channel width - clearance| over the slices
};

// fastener (paper 2.4): theta ranges whose slices have one free component, and the critical
// orientations where the inside and outside components meet (merge or split).
struct FastenerAnalysis {
  std::vector<std::pair<double, double>> one_component_ranges;
  std::vector<double> meeting_thetas;
};

// fixture (paper 2.3): the engaging configuration and the local test (analyze.cpp,
// fixture_check): contact by classify; within `radius` of it the free component below it
// has no boundary point higher than it (`highest_boundary_y`), and no point of the upper half
// of the circle of that radius about it is in that component.
struct FixtureAnalysis {
  Pose engaging{2.1, -0.7, 0.0};
  std::string placement;  // classify at the engaging configuration
  double radius = 0.0;
  int component = -1;  // free component of the theta = 0 slice just below it
  double highest_boundary_y = 0.0;
  // How far the component's boundary stays below the engaging configuration between radius/2
  // and radius from it: positive for a strict local maximum.
  double drop = 0.0;
  int upper_circle_points_free = 0;  // points of the upper half circle in the component
};

// knee (paper 2.1): range of motion from the configuration of the paper's Figure 1.
struct KneeAnalysis {
  Pose start{5.0, -3.0, 0.5};
  int component = -1;  // its 3D component, or -1 when not free
  std::vector<std::pair<double, double>> range_of_motion;
  double coverage = 0.0;  // radians
};

struct SpaceAnalysis {
  std::string pair;
  std::vector<ComponentCoverage> components;
  std::vector<TransitionSummary> transitions;
  std::vector<SliceSummary> slices;
  ChannelSummary channel;
  // The application the pair's name matches ("cam", "fastener", "fixture", "knee"), or empty.
  std::string application;
  std::vector<ApplicationCheck> checks;
  std::optional<CamAnalysis> cam;
  std::optional<FastenerAnalysis> fastener;
  std::optional<FixtureAnalysis> fixture;
  std::optional<KneeAnalysis> knee;
  bool all_checks_passed() const;
};

SpaceAnalysis analyze_space(const Pair& pair, const SlicedSpace& space);

// The smallest extent of a free component: the least, over directions, of the length of its
// projection on that direction (its minimum width); for the cam's square channel, its side.
double component_min_width(const FreeComponent& component);

// The analysis as JSON text (format "cslice-analysis", version 1; docs/space-format.md),
// ending in a newline.
std::string analysis_to_json(const SpaceAnalysis& analysis);

}  // namespace cslice
