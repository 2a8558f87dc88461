// Symmetries of a pair: quarter turns and mirrors that map each part onto itself and so map
// the slice at one orientation onto the slice at another (docs/symmetry.md). Designed parts
// are often drawn symmetric (the paper's fixture, fastener and cam are), and a slice mapped
// across a symmetry costs a few percent of one computed from scratch.
#pragma once

#include <vector>

#include "cslice/pair.hpp"

namespace cslice {

struct Slice;

// A linear map of the plane that is exact in floating point: a turn by quarter_turns * pi / 2
// after, when `mirror`, the mirror y -> -y. Coordinates only change sign and swap places, so
// the image of a point is exact.
struct QuarterMap {
  int quarter_turns = 0;  // 0 to 3
  bool mirror = false;

  Vec2 apply(Vec2 p) const;
  // The angle of apply(unit_vector(a)): a turned (or mirrored, then turned) exactly.
  double apply_angle(double a) const;
};

// An isometry p -> map(p) + shift that maps a part onto itself, with what it does to the part's
// features: feature i goes to feature feature_map[i] (same kind).
struct PartSymmetry {
  QuarterMap map;
  Vec2 shift;
  std::vector<int> feature_map;

  Vec2 apply(Vec2 p) const { return map.apply(p) + shift; }
};

// The symmetries of a part among the eight quarter maps, the identity first. The moving
// part's must fix its body origin (about_origin: no shift); the fixed part's may move the
// origin, as long as they map the part's bounding box onto itself. A map counts when every
// feature's image lies within kRelativeSymmetrySlack sizes of a feature of the same kind,
// one for one.
std::vector<PartSymmetry> part_symmetries(const Part& part, bool about_origin, double size);

// A symmetry of the pair: the fixed part's symmetry `plane` (mapping the fixed part onto
// itself) paired with a symmetry of the moving part that mirrors as it does. It maps the
// slice at theta onto the slice at image_theta(theta): a configuration (p, theta) goes to
// (plane.apply(p), image_theta(theta)), and a contact segment labelled (m, f) to the one
// labelled (moving_map[m], plane.feature_map[f]).
struct PairSymmetry {
  PartSymmetry plane;           // acts on the slice's plane and the fixed features
  std::vector<int> moving_map;  // acts on the moving features
  int quarter_turns = 0;        // image_theta adds quarter_turns * pi / 2 ...
  bool reverses_theta = false;  // ... to theta, or to -theta when the maps mirror

  double image_theta(double theta) const;  // wrapped to [-pi, pi)
};

// Every symmetry of the pair except the identity (an empty list for most pairs). Symmetries
// that map theta the same way are listed once.
std::vector<PairSymmetry> pair_symmetries(const Pair& pair);

// The slice at symmetry.image_theta(slice.theta), from `slice`: every curve and point mapped
// by the plane isometry (a mirror also reverses curves and boundary cycles, so blocked space
// stays on the left of contact segments and free space on the left of boundary pieces),
// every label mapped, ids and order kept. `theta` is the orientation to record, the image
// of slice.theta to within the angular tolerance.
Slice mapped_slice(const Slice& slice, const PairSymmetry& symmetry, double theta);

}  // namespace cslice
