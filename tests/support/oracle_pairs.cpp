// Random pairs for the placement oracle; see oracle_pairs.hpp.
#include "support/oracle_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "cslice/geometry.hpp"

namespace cslice::testkit {

using nlohmann::json;
using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

namespace {

// A star-shaped loop around (cx, cy): n vertices at sorted angles, radii in [rmin, rmax],
// some edges bent into arcs bulging either way.
json star_loop(Rng& rng, double cx, double cy, double rmin, double rmax, double max_bulge) {
  const int n = std::uniform_int_distribution<int>(3, 10)(rng);
  std::vector<double> angles;
  // Evenly spread angles, jittered, so no two vertices crowd each other.
  const double start = uniform(rng, 0, 2 * cslice::kPi);
  for (int k = 0; k < n; ++k)
    angles.push_back(start + (k + uniform(rng, -0.3, 0.3)) * 2 * cslice::kPi / n);
  json loop = json::array();
  for (double a : angles) {
    const double r = uniform(rng, rmin, rmax);
    const double bulge = uniform(rng, 0, 1) < 0.5 ? uniform(rng, -max_bulge, max_bulge) : 0.0;
    loop.push_back({cx + r * std::cos(a), cy + r * std::sin(a), bulge});
  }
  return loop;
}

json circle_loop(double cx, double cy, double r) {
  return {{"circle", {cx, cy, r}}};
}

// A solid part of radius about `scale` around (cx, cy), sometimes with a hole; only straight
// edges unless `curved`.
json random_solid(Rng& rng, double cx, double cy, double scale, bool curved) {
  const double bulge = curved ? 1.0 : 0.0;
  json loops = json::array();
  if (curved && uniform(rng, 0, 1) < 0.1) {
    loops.push_back(circle_loop(cx, cy, scale * uniform(rng, 0.5, 1.0)));
  } else {
    loops.push_back(star_loop(rng, cx, cy, 0.6 * scale, scale, 0.3 * bulge));
  }
  const double hole = uniform(rng, 0, 1);
  if (curved && hole < 0.2)
    loops.push_back(circle_loop(cx, cy, scale * uniform(rng, 0.1, 0.25)));
  else if (hole < 0.4)
    loops.push_back(star_loop(rng, cx, cy, 0.1 * scale, 0.3 * scale, 0.2 * bulge));
  return loops;
}

// A ring (a washer) with a wide hole, for the fixed part to sit in.
json random_ring(Rng& rng, double cx, double cy, bool curved) {
  const double bulge = curved ? 1.0 : 0.0;
  json loops = json::array({star_loop(rng, cx, cy, 2.2, 2.6, 0.2 * bulge)});
  if (curved && uniform(rng, 0, 1) < 0.3)
    loops.push_back(circle_loop(cx, cy, uniform(rng, 1.3, 1.7)));
  else
    loops.push_back(star_loop(rng, cx, cy, 1.3, 1.7, 0.2 * bulge));
  return loops;
}

}  // namespace

json oracle_random_pair(Rng& rng, int index, bool curved) {
  const double bulge = curved ? 1.0 : 0.0;
  json moving = {{"loops", random_solid(rng, uniform(rng, -0.5, 0.5), uniform(rng, -0.5, 0.5),
                                        uniform(rng, 1, 2.5), curved)}};
  json fixed;
  const double kind = uniform(rng, 0, 1);
  if (kind < 0.15) {
    // A ring around a small peg: free poses with the peg inside the moving part's hole.
    moving = {
        {"loops", random_ring(rng, uniform(rng, -0.3, 0.3), uniform(rng, -0.3, 0.3), curved)}};
    fixed = {{"loops", random_solid(rng, 0, 0, uniform(rng, 0.5, 1.0), curved)}};
  } else if (kind < 0.3) {
    // An opening the moving part fits into with some room.
    fixed = {{"loops", json::array({star_loop(rng, 0, 0, 3, 4.5, 0.3 * bulge)})},
             {"enclosure", true}};
  } else if (kind < 0.45) {
    // Two separate blocks.
    json loops = random_solid(rng, -3, 0, 2, curved);
    loops.push_back(star_loop(rng, 3, 0.5, 1.2, 2, 0.3 * bulge));
    fixed = {{"loops", loops}};
  } else {
    fixed = {{"loops", random_solid(rng, 0, 0, uniform(rng, 2, 4), curved)}};
  }
  json pair = {{"name", "random-" + std::to_string(index)}, {"moving", moving}, {"fixed", fixed}};
  if (uniform(rng, 0, 1) < 0.5) pair["tolerance"] = uniform(rng, 0.002, 0.02);
  return pair;
}

std::vector<json> example_pair_files() {
  std::vector<json> out;
  const std::filesystem::path dir = std::filesystem::path(CSLICE_SOURCE_DIR) / "examples";
  if (!std::filesystem::exists(dir)) return out;
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    std::ifstream in(f);
    out.push_back(json::parse(in));
  }
  return out;
}

}  // namespace cslice::testkit
