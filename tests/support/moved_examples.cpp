#include "support/moved_examples.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "cslice/classify.hpp"

#include "support/examples.hpp"
#include "support/random_polygons.hpp"

namespace cslice::testkit {

namespace {

nlohmann::json example_json(const std::string& name) {
  std::ifstream in(example_path(name));
  return nlohmann::json::parse(in);
}

// Calls on_point(xy, radius) for every vertex and circle of a part: xy is its [x, y, ...]
// array (a vertex's bulge follows), radius the circle's radius entry or nullptr.
template <class OnPoint>
void for_each_point(nlohmann::json& part, OnPoint on_point) {
  for (auto& loop : part["loops"]) {
    if (loop.is_object()) {
      nlohmann::json& circle = loop["circle"];
      on_point(circle, &circle[2]);
    } else {
      for (auto& vertex : loop) on_point(vertex, nullptr);
    }
  }
}

Pair parse_json_or_throw(const nlohmann::json& j, const std::string& name) {
  return parse_or_throw(j.dump(), name);
}

nlohmann::json moved_json(nlohmann::json j, double scale, double angle, Vec2 shift,
                          Vec2 fixed_offset = {}) {
  const Transform t(Pose{shift.x, shift.y, angle});
  for (const char* part : {"moving", "fixed"}) {
    const Vec2 offset = std::string(part) == "fixed" ? fixed_offset : Vec2{};
    for_each_point(j[part], [&](nlohmann::json& xy, nlohmann::json* radius) {
      const Vec2 p = t.apply({scale * xy[0].get<double>(), scale * xy[1].get<double>()}) + offset;
      xy[0] = p.x;
      xy[1] = p.y;
      if (radius) *radius = scale * radius->get<double>();
    });
  }
  if (j.contains("tolerance") && j["tolerance"].is_number())
    j["tolerance"] = scale * j["tolerance"].get<double>();
  return j;
}

}  // namespace

Pair moved_pair(const std::string& json_text, const std::string& name, double scale, double angle,
                Vec2 shift, Vec2 fixed_offset) {
  return parse_json_or_throw(
      moved_json(nlohmann::json::parse(json_text), scale, angle, shift, fixed_offset), name);
}

Pair moved_example(const std::string& name, double scale, double angle, Vec2 shift) {
  return parse_json_or_throw(moved_json(example_json(name), scale, angle, shift), name);
}

Pair mirrored_example(const std::string& name) {
  nlohmann::json j = example_json(name);
  for (const char* part : {"moving", "fixed"}) {
    for_each_point(j[part], [](nlohmann::json& xy, const nlohmann::json* radius) {
      xy[0] = -xy[0].get<double>();
      if (!radius && xy.size() > 2) xy[2] = -xy[2].get<double>();  // the bulge
    });
  }
  return parse_json_or_throw(j, name);
}

void expect_same_pair(const Pair& read, const Pair& original, const std::string& name,
                      unsigned seed) {
  EXPECT_EQ(read.moving.feature_count(), original.moving.feature_count()) << name;
  EXPECT_EQ(read.fixed.feature_count(), original.fixed.feature_count()) << name;
  EXPECT_NEAR(read.moving.area, original.moving.area, 1e-9 * original.tol.size) << name;
  EXPECT_NEAR(read.fixed.area, original.fixed.area, 1e-9 * original.tol.size) << name;
  EXPECT_NEAR(read.tol.contact, original.tol.contact, 1e-12 * original.tol.size) << name;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int differ = 0;
  for (int k = 0; k < 2000; ++k) {
    const Pose pose{u(rng) * original.tol.size / 2, u(rng) * original.tol.size / 2, u(rng) * kPi};
    differ += classify(read, pose) != classify(original, pose) ? 1 : 0;
  }
  EXPECT_EQ(differ, 0) << name;
}

}  // namespace cslice::testkit
