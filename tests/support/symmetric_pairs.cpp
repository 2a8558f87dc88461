#include "support/symmetric_pairs.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cslice/symmetry.hpp"
#include "support/random_polygons.hpp"

namespace cslice::testkit {

namespace {

// k angles in (0, span), one per equal part of it, jittered within the part.
std::vector<double> spread_angles(std::mt19937& rng, int k, double span) {
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<double> out;
  for (int i = 0; i < k; ++i) out.push_back(span * (i + 0.5 + jitter(rng)) / k);
  return out;
}

double random_bulge(std::mt19937& rng) {
  return 0.1 * std::uniform_int_distribution<int>(-1, 1)(rng);
}

}  // namespace

SymmetricLoop mirror_star(std::mt19937& rng, int k, double r0, double r1) {
  std::uniform_real_distribution<double> radius(r0, r1);
  SymmetricLoop upper;
  for (double a : spread_angles(rng, k, kPi)) {
    const double r = radius(rng);
    upper.push_back({r * std::cos(a), r * std::sin(a), random_bulge(rng)});
  }
  // Counterclockwise: the lower half from angle -pi up, then the upper half.
  SymmetricLoop loop;
  for (int i = k - 1; i >= 0; --i) {
    // The edge from this image to the next one up mirrors the upper edge ending at vertex i;
    // the edge across the axis at angle 0 mirrors onto itself, any bulge.
    const double b = i > 0 ? upper[size_t(i - 1)][2] : random_bulge(rng);
    loop.push_back({upper[size_t(i)][0], -upper[size_t(i)][1], b});
  }
  for (const auto& v : upper) loop.push_back(v);
  loop.back()[2] = 0.0;  // the edge across the axis at angle pi: its own image reversed
  return loop;
}

SymmetricLoop quarter_star(std::mt19937& rng, int k, double r0, double r1) {
  std::uniform_real_distribution<double> radius(r0, r1);
  SymmetricLoop quarter, loop;
  for (double a : spread_angles(rng, k, kPi / 2)) {
    const double r = radius(rng);
    quarter.push_back({r * std::cos(a), r * std::sin(a), random_bulge(rng)});
  }
  for (int q = 0; q < 4; ++q)
    for (const auto& v : quarter) {
      const Vec2 p = QuarterMap{q, false}.apply({v[0], v[1]});
      loop.push_back({p.x, p.y, v[2]});
    }
  return loop;
}

std::string placed_loop_json(const SymmetricLoop& loop, int turns, Vec2 centre) {
  std::ostringstream out;
  out.precision(17);
  out << "[";
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec2 p = QuarterMap{turns, false}.apply({loop[i][0], loop[i][1]}) + centre;
    out << (i ? "," : "") << "[" << p.x << "," << p.y << "," << loop[i][2] << "]";
  }
  out << "]";
  return out.str();
}

RandomPair symmetric_pair_of(const std::string& moving, const std::string& fixed, bool enclosure,
                             const std::string& name) {
  const std::string json = "{\"name\":\"" + name + "\",\"moving\":{\"loops\":[" + moving +
                           "]},\"fixed\":{" + (enclosure ? "\"enclosure\":true," : "") +
                           "\"loops\":[" + fixed + "]}}";
  return {parse_or_throw(json, name), json};
}

RandomPair symmetric_pair(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> offset(-1.0, 1.0);
  std::uniform_int_distribution<int> count(2, 4);
  const int kind = int(seed % 4);
  const bool enclosure = kind >= 2;
  const bool turns = kind % 2 == 0;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const Vec2 centre{offset(rng), offset(rng)};
    const SymmetricLoop moving = mirror_star(rng, count(rng), 0.5, 1.0);
    // An obstacle around which the moving star turns, or an opening it barely turns in.
    const double r0 = enclosure ? 1.1 : 2.0, r1 = enclosure ? 1.5 : 3.0;
    const SymmetricLoop fixed =
        turns ? quarter_star(rng, count(rng), r0, r1) : mirror_star(rng, count(rng) + 2, r0, r1);
    try {
      return symmetric_pair_of(placed_loop_json(moving, 0, {}),
                               placed_loop_json(fixed, turns ? 0 : 1, centre), enclosure,
                               "symmetric " + std::to_string(seed));
    } catch (const std::runtime_error&) {
      // A bulge made the loop cross itself: draw again.
    }
  }
  throw std::runtime_error("symmetric_pair: no valid pair for seed " + std::to_string(seed));
}

}  // namespace cslice::testkit
