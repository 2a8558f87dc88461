// Symmetries of parts and pairs (include/cslice/symmetry.hpp, docs/symmetry.md).
#include "cslice/symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "cslice/tolerance.hpp"

namespace cslice {

namespace {

// cos and sin of quarter_turns * pi / 2, exactly.
constexpr int kQuarterCos[4] = {1, 0, -1, 0};
constexpr int kQuarterSin[4] = {0, 1, 0, -1};

// Where a feature is: a vertex's point, an edge's midpoint along the curve (the image of an
// edge's midpoint is its image's midpoint whichever way the image runs).
Vec2 feature_point(const Part& part, const Feature& f) {
  return f.kind == FeatureKind::vertex ? f.point : point_at(edge_of(part, f), 0.5);
}

bool same_point(Vec2 a, Vec2 b, double slack) {
  return std::fabs(a.x - b.x) <= slack && std::fabs(a.y - b.y) <= slack;
}

// Whether edge `b` is the image of edge `a` under s: the same ends, in either order (a
// mirror reverses the loops), and the same midpoint, checked by the caller.
bool ends_match(const Curve& a, const Curve& b, const PartSymmetry& s, double slack) {
  const Vec2 from = s.apply(a.from), to = s.apply(a.to);
  return (same_point(from, b.from, slack) && same_point(to, b.to, slack)) ||
         (same_point(from, b.to, slack) && same_point(to, b.from, slack));
}

// The feature permutation of s, or an empty one when some feature has no image among the
// part's features (or two share one). Features sorted by x find their image's neighbours
// by binary search: parts of thousands of features are checked in n log n.
std::vector<int> feature_map_of(const Part& part, const PartSymmetry& s, double slack) {
  const size_t n = part.features.size();
  std::vector<Vec2> at(n);
  for (size_t i = 0; i < n; ++i) at[i] = feature_point(part, part.features[i]);
  std::vector<int> by_x(n);
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(), [&](int a, int b) { return at[a].x < at[b].x; });
  std::vector<int> map(n, -1);
  std::vector<char> taken(n, false);
  for (size_t i = 0; i < n; ++i) {
    const Feature& f = part.features[i];
    const Vec2 image = s.apply(at[i]);
    auto it = std::lower_bound(by_x.begin(), by_x.end(), image.x - slack,
                               [&](int k, double x) { return at[k].x < x; });
    for (; it != by_x.end() && at[*it].x <= image.x + slack; ++it) {
      const Feature& g = part.features[*it];
      if (g.kind != f.kind || !same_point(at[*it], image, slack)) continue;
      if (f.kind != FeatureKind::vertex &&
          !ends_match(edge_of(part, f), edge_of(part, g), s, slack))
        continue;
      map[i] = *it;
      break;
    }
    if (map[i] < 0 || taken[map[i]]) return {};
    taken[map[i]] = true;
  }
  return map;
}

int compose_turns(int a, int b) {
  return ((a + b) % 4 + 4) % 4;
}

}  // namespace

Vec2 QuarterMap::apply(Vec2 p) const {
  const double c = kQuarterCos[quarter_turns], s = kQuarterSin[quarter_turns];
  const double y = mirror ? -p.y : p.y;
  return {c * p.x - s * y, s * p.x + c * y};
}

double QuarterMap::apply_angle(double a) const {
  return (mirror ? -a : a) + quarter_turns * (kPi / 2);
}

std::vector<PartSymmetry> part_symmetries(const Part& part, bool about_origin, double size) {
  const double slack = kRelativeSymmetrySlack * size;
  const Vec2 centre = 0.5 * (part.box.lo + part.box.hi);
  std::vector<PartSymmetry> out;
  for (bool mirror : {false, true}) {
    for (int turns = 0; turns < 4; ++turns) {
      PartSymmetry s;
      s.map = {turns, mirror};
      // The box's centre stays put: the map of a box under a quarter map is a box.
      if (!about_origin) s.shift = centre - s.map.apply(centre);
      s.feature_map = feature_map_of(part, s, slack);
      if (!s.feature_map.empty() || part.features.empty()) out.push_back(std::move(s));
    }
  }
  return out;
}

// A fixed map A = L + shift and a moving map g that both mirror or both do not. For a
// turn L = R(a) and g = R(b): A(R(theta) M + t) = R(theta + a) M + A t = R(theta + a - b) g M,
// so the slice at theta + a - b is A of the slice at theta, moving feature m becoming g(m).
// For mirrors L = R(a) S and g = R(b) S (S: y -> -y, with S R(theta) = R(-theta) S):
// L R(theta) M = R(a - theta) S M = R(a - theta - b) g M, so theta goes to -theta + a - b.
double PairSymmetry::image_theta(double theta) const {
  return wrap_angle((reverses_theta ? -theta : theta) + quarter_turns * (kPi / 2));
}

std::vector<PairSymmetry> pair_symmetries(const Pair& pair) {
  const double size = pair.tol.size;
  const std::vector<PartSymmetry> fixed = part_symmetries(pair.fixed, false, size);
  const std::vector<PartSymmetry> moving = part_symmetries(pair.moving, true, size);
  std::vector<PairSymmetry> out;
  for (const PartSymmetry& a : fixed) {
    for (const PartSymmetry& g : moving) {
      if (a.map.mirror != g.map.mirror) continue;
      PairSymmetry s;
      s.quarter_turns = compose_turns(a.map.quarter_turns, -g.map.quarter_turns);
      s.reverses_theta = a.map.mirror;
      if (s.quarter_turns == 0 && !s.reverses_theta) continue;  // theta stays: nothing gained
      const bool listed = std::any_of(out.begin(), out.end(), [&](const PairSymmetry& o) {
        return o.quarter_turns == s.quarter_turns && o.reverses_theta == s.reverses_theta;
      });
      if (listed) continue;
      s.plane = a;
      s.moving_map = g.feature_map;
      out.push_back(std::move(s));
    }
  }
  return out;
}

}  // namespace cslice
