#include "support/moved_examples.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "support/examples.hpp"

namespace cslice::testkit {

namespace {

nlohmann::json example_json(const std::string& name) {
  std::ifstream in(example_path(name));
  return nlohmann::json::parse(in);
}

Pair parse_or_throw(const nlohmann::json& j, const std::string& name) {
  LoadResult r = parse_pair(j.dump(), name);
  if (!r.ok()) throw std::runtime_error(r.error->message());
  return std::move(*r.pair);
}

nlohmann::json moved_json(nlohmann::json j, double scale, double angle, Vec2 shift,
                          Vec2 fixed_offset = {}) {
  const Transform t(Pose{shift.x, shift.y, angle});
  for (const char* part : {"moving", "fixed"}) {
    const Vec2 offset = std::string(part) == "fixed" ? fixed_offset : Vec2{};
    auto move = [&](nlohmann::json& xy) {
      const Vec2 p = t.apply({scale * xy[0].get<double>(), scale * xy[1].get<double>()}) + offset;
      xy[0] = p.x;
      xy[1] = p.y;
    };
    for (auto& loop : j[part]["loops"]) {
      if (loop.is_object()) {
        nlohmann::json& circle = loop["circle"];
        move(circle);
        circle[2] = scale * circle[2].get<double>();
      } else {
        for (auto& vertex : loop) move(vertex);
      }
    }
  }
  if (j.contains("tolerance") && j["tolerance"].is_number())
    j["tolerance"] = scale * j["tolerance"].get<double>();
  return j;
}

}  // namespace

Pair moved_pair(const std::string& json_text, const std::string& name, double scale, double angle,
                Vec2 shift, Vec2 fixed_offset) {
  return parse_or_throw(
      moved_json(nlohmann::json::parse(json_text), scale, angle, shift, fixed_offset), name);
}

Pair moved_example(const std::string& name, double scale, double angle, Vec2 shift) {
  return parse_or_throw(moved_json(example_json(name), scale, angle, shift), name);
}

Pair mirrored_example(const std::string& name) {
  nlohmann::json j = example_json(name);
  for (const char* part : {"moving", "fixed"}) {
    for (auto& loop : j[part]["loops"]) {
      if (loop.is_object()) {
        loop["circle"][0] = -loop["circle"][0].get<double>();
      } else {
        for (auto& vertex : loop) {
          vertex[0] = -vertex[0].get<double>();
          if (vertex.size() > 2) vertex[2] = -vertex[2].get<double>();
        }
      }
    }
  }
  return parse_or_throw(j, name);
}

}  // namespace cslice::testkit
