// Critical orientations of a symmetric pair (src/criticals/symmetric.hpp).
#include "criticals/symmetric.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>

#include "geometry/angle_search.hpp"

namespace cslice {

namespace {

// A criticality's identity up to round-off: its condition, then its feature pairs as
// (moving, fixed, kind), in order for an endpoint (its first pair owns the end) and sorted
// otherwise, unused places -1.
using Identity = std::array<int, 10>;
using PairKeys = std::array<std::array<int, 3>, 3>;  // (moving, fixed, kind), -1 unused

Identity identity_of(CriticalCondition condition, PairKeys pairs, size_t count) {
  if (condition != CriticalCondition::endpoint)
    std::sort(pairs.begin(), pairs.begin() + long(std::min<size_t>(count, 3)));
  Identity id;
  id[0] = int(condition);
  for (int i = 0; i < 9; ++i) id[size_t(1 + i)] = pairs[size_t(i / 3)][size_t(i % 3)];
  return id;
}

// The feature pairs of c, mapped by s when given.
PairKeys pair_keys(const Criticality& c, const PairSymmetry* s) {
  PairKeys keys;
  keys.fill({-1, -1, -1});
  for (size_t i = 0; i < c.pairs.size() && i < 3; ++i) {
    const FeaturePairRef& p = c.pairs[i];
    keys[i] = {s ? s->moving_map[p.moving_feature] : p.moving_feature,
               s ? s->plane.feature_map[p.fixed_feature] : p.fixed_feature, int(p.kind)};
  }
  return keys;
}

Identity identity_of(const Criticality& c) {
  return identity_of(c.condition, pair_keys(c, nullptr), c.pairs.size());
}

// Where and what a criticality is, without its list of pairs: enough to compare.
struct Place {
  Identity id;
  double theta = 0.0;
  Vec2 at;
};

// The image of c under s. A segment's end is given by its family's first end, which a mirror
// makes the last: its point is its image family's own.
Place image_place(const Criticality& c, const PairSymmetry& s, const SegmentEndPoint& end_at) {
  const PairKeys keys = pair_keys(c, &s);
  Place p{identity_of(c.condition, keys, c.pairs.size()), s.image_theta(c.theta),
          s.plane.apply(c.at)};
  if (c.condition == CriticalCondition::segment_end)
    p.at = end_at({keys[0][0], keys[0][1], c.pairs.front().kind}, p.theta);
  return p;
}

Criticality image_of(const Criticality& c, const PairSymmetry& s, const Place& place) {
  Criticality image = c;
  image.theta = place.theta;
  image.at = place.at;
  for (FeaturePairRef& p : image.pairs) {
    p.moving_feature = s.moving_map[p.moving_feature];
    p.fixed_feature = s.plane.feature_map[p.fixed_feature];
  }
  return image;
}

// The criticalities found directly, by identity, for finding one at an image.
class Found {
 public:
  Found(const std::vector<Criticality>& kept, const Tolerances& tol) : tol_(tol) {
    for (size_t i = 0; i < kept.size(); ++i) {
      places_.push_back({identity_of(kept[i]), kept[i].theta, kept[i].at});
      by_id_.push_back({places_.back().id, int(i)});
    }
    std::sort(by_id_.begin(), by_id_.end());
  }

  const Place& place(size_t i) const { return places_[i]; }

  // The first criticality found that p repeats, or -1.
  int find(const Place& p) const {
    auto it = std::lower_bound(by_id_.begin(), by_id_.end(), std::pair{p.id, -1});
    for (; it != by_id_.end() && it->first == p.id; ++it)
      if (same(places_[size_t(it->second)], p)) return it->second;
    return -1;
  }

  bool same(const Place& a, const Place& b) const {
    return a.id == b.id && std::fabs(wrap_angle(a.theta - b.theta)) <= tol_.critical_angle &&
           distance(a.at, b.at) <= tol_.criticality;
  }

 private:
  const Tolerances& tol_;
  std::vector<Place> places_;
  std::vector<std::pair<Identity, int>> by_id_;
};

struct Image {
  Place place;
  int found = -1;  // the criticality found directly that it repeats, or -1
};

}  // namespace

std::optional<AngleInterval> fundamental_domain(const std::vector<PairSymmetry>& symmetries) {
  if (symmetries.empty()) return std::nullopt;
  bool turns[4] = {true, false, false, false};
  int mirror = -1;  // the least c of a mirror theta -> c pi / 2 - theta
  int mirrors = 0;
  for (const PairSymmetry& s : symmetries) {
    if (s.reverses_theta) {
      ++mirrors;
      if (mirror < 0 || s.quarter_turns < mirror) mirror = s.quarter_turns;
    } else {
      turns[s.quarter_turns] = true;
    }
  }
  const int count = int(std::count(std::begin(turns), std::end(turns), true));
  // The turns must be a subgroup of the quarter turns: none, the half turn, or all four.
  if (count == 3 || (count == 2 && !turns[2])) return std::nullopt;
  if (mirror >= 0 && mirrors != count) return std::nullopt;  // one mirror per turn
  const double period = kTwoPi / count;
  if (mirror < 0) return AngleInterval{-kPi, period};
  return AngleInterval{wrap_angle(mirror * (kPi / 4)), period / 2};
}

long add_symmetric_images(std::vector<Criticality>& kept,
                          const std::vector<PairSymmetry>& symmetries, const Tolerances& tol,
                          const SegmentEndPoint& segment_end_at) {
  const size_t originals = kept.size(), n = symmetries.size();
  const Found found(kept, tol);
  // Every image, and the criticality found directly that it repeats. Found criticalities
  // that repeat one another (two equations finding one event) form a class, named by its
  // first member. In parallel (in the caller's arena), each stored at its own index.
  std::vector<Image> images(originals * n);
  std::vector<int> class_of(originals);
  tbb::parallel_for(size_t(0), originals, [&](size_t i) {
    class_of[i] = found.find(found.place(i));
    for (size_t s = 0; s < n; ++s) {
      Image& m = images[i * n + s];
      m.place = image_place(kept[i], symmetries[s], segment_end_at);
      m.found = found.find(m.place);
    }
  });
  // A class is the image of an earlier one when found at an image directly (a mirror's two
  // sides of theta = 0, say); only the others, the representatives, have their images added.
  std::vector<char> represents(originals, true);
  for (size_t i = 0; i < originals; ++i) {
    if (class_of[i] != int(i) || !represents[i]) continue;
    for (size_t s = 0; s < n; ++s) {
      const int j = images[i * n + s].found;
      if (j >= 0 && class_of[size_t(j)] != int(i)) represents[size_t(class_of[size_t(j)])] = false;
    }
  }
  const size_t before = kept.size();
  kept.reserve(originals * (n + 1));
  for (size_t i = 0; i < originals; ++i) {
    if (!represents[size_t(class_of[i])]) continue;
    for (size_t s = 0; s < n; ++s) {
      const Image& m = images[i * n + s];
      // Found directly (or the criticality itself, on a mirror's axis), or already an image
      // of this one under another symmetry.
      if (m.found >= 0) continue;
      bool repeated = false;
      for (size_t t = 0; t < s && !repeated; ++t)
        repeated = images[i * n + t].found < 0 && found.same(images[i * n + t].place, m.place);
      if (!repeated) kept.push_back(image_of(kept[i], symmetries[s], m.place));
    }
  }
  return long(kept.size() - before);
}

void align_symmetric_orientations(CriticalSet& set, const std::vector<PairSymmetry>& symmetries,
                                  const Tolerances& tol) {
  std::vector<CriticalOrientation>& o = set.orientations;  // sorted by theta
  const int n = int(o.size());
  std::vector<char> aligned(o.size(), false);
  const auto near = [&](double theta) {
    return index_near_angle(o, theta, tol.critical_angle,
                            [](const CriticalOrientation& c) { return c.theta; });
  };
  std::vector<std::pair<int, double>> moves;  // applied after the searches, which need order
  for (int i = 0; i < n; ++i) {
    if (aligned[i]) continue;
    for (const PairSymmetry& s : symmetries) {
      const double image = s.image_theta(o[i].theta);
      const int j = near(image);
      if (j > i && !aligned[j]) {
        moves.push_back({j, image});
        aligned[j] = true;
      }
    }
  }
  for (const auto& [j, theta] : moves) o[j].theta = theta;
  std::stable_sort(o.begin(), o.end(),
                   [](const auto& a, const auto& b) { return a.theta < b.theta; });
}

}  // namespace cslice
