#include "support/random_parts.hpp"

#include <sstream>

#include "cslice/space.hpp"

namespace cslice::testkit {

std::string random_loop_json(std::mt19937& rng, const RandomLoopOptions& o) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::ostringstream out;
  out.precision(17);
  out << "[";
  for (int i = 0; i < o.vertices; ++i) {
    const double angle = kTwoPi * (i + 0.8 * unit(rng)) / o.vertices;
    const double r = o.radius * (1.0 - o.roughness + 2.0 * o.roughness * unit(rng));
    const double bulge = unit(rng) < o.arc_fraction ? o.max_bulge * (2.0 * unit(rng) - 1.0) : 0.0;
    out << (i ? "," : "") << "[" << o.center.x + r * std::cos(angle) << ","
        << o.center.y + r * std::sin(angle) << "," << bulge << "]";
  }
  out << "]";
  return out.str();
}

RandomPair random_pair(std::mt19937& rng, int moving_vertices, int fixed_vertices, bool holes) {
  for (int attempt = 0;; ++attempt) {
    RandomLoopOptions m{moving_vertices, 1.0, 0.4, 0.5, 0.35, {0.0, 0.0}};
    RandomLoopOptions f{fixed_vertices, 3.0, 0.35, 0.5, 0.3, {0.0, 0.0}};
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on chains of operator+.
    std::string json = R"({"name":"random","moving":{"loops":[)";
    json += random_loop_json(rng, m);
    json += R"(]},"fixed":{"loops":[)";
    json += random_loop_json(rng, f);
    if (holes) {
      RandomLoopOptions h{std::max(3, fixed_vertices / 2), 1.3, 0.2, 0.5, 0.3, {0.0, 0.0}};
      json += ",";
      json += random_loop_json(rng, h);
    }
    json += "]}}";
    LoadResult r = parse_pair(json, "random");
    if (r.ok()) return {std::move(*r.pair), json};
    if (attempt > 1000)
      throw std::runtime_error("random_pair: no valid pair: " + r.error->message());
  }
}

RandomPair stress_pair(unsigned seed) {
  std::mt19937 rng(seed);
  return random_pair(rng, 3 + int(seed % 6), 4 + int(seed / 7 % 8), seed % 3 == 0);
}

Pair tight_pair(std::mt19937& rng, int k) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (;;) {
    RandomLoopOptions m{4 + k % 4, 1.0, 0.3, 0.5, 0.3, {0.0, 0.0}};
    RandomLoopOptions h{5 + k % 3, 1.15 + 0.4 * u(rng), 0.15, 0.5, 0.25, {0.0, 0.0}};
    std::string json = R"({"name":"tight","moving":{"loops":[)";
    json += random_loop_json(rng, m);
    json += k % 2 == 0 ? R"(]},"fixed":{"enclosure":true,"loops":[)"
                       : R"(]},"fixed":{"loops":[[[-4,-4],[4,-4],[4,4],[-4,4]],)";
    json += random_loop_json(rng, h);
    json += "]}}";
    LoadResult r = parse_pair(json, "tight");
    if (!r.ok()) continue;
    SpaceOptions options;
    options.threads = 2;
    const SlicedSpace space = compute_space(*r.pair, options);
    for (const SpaceSlice& s : space.slices)
      if (!s.slice.free_components.empty()) return std::move(*r.pair);
  }
}

}  // namespace cslice::testkit
