// Critical orientations as JSON (docs/criticals.md, "Output"). Lives apart from the solver.
#include <nlohmann/json.hpp>
#include <set>

#include "cslice/critical.hpp"
#include "cslice/slice_io.hpp"

namespace cslice {

namespace {

using json = nlohmann::ordered_json;

json pair_json(const Pair& pair, const FeaturePairRef& p) {
  return {{"moving_feature", p.moving_feature},
          {"fixed_feature", p.fixed_feature},
          {"kind", std::string(to_string(p.kind))},
          {"moving_feature_desc", describe_feature(pair.moving, p.moving_feature)},
          {"fixed_feature_desc", describe_feature(pair.fixed, p.fixed_feature)}};
}

// One orientation: its condition (or "multiple" when its criticalities differ), the feature
// pairs involved (each once), and every criticality grouped into it.
json orientation_json(const Pair& pair, const CriticalOrientation& o) {
  std::set<CriticalCondition> conditions;
  std::set<std::pair<int, int>> seen;
  json features = json::array(), details = json::array();
  for (const Criticality& k : o.criticalities) {
    conditions.insert(k.condition);
    json pairs = json::array();
    for (const FeaturePairRef& p : k.pairs) {
      pairs.push_back(pair_json(pair, p));
      if (seen.insert({p.moving_feature, p.fixed_feature}).second)
        features.push_back(pair_json(pair, p));
    }
    details.push_back({{"theta", k.theta},
                       {"condition", std::string(to_string(k.condition))},
                       {"at", json::array({k.at.x, k.at.y})},
                       {"features", pairs}});
  }
  const std::string condition =
      conditions.size() == 1 ? std::string(to_string(*conditions.begin())) : "multiple";
  return {{"theta", o.theta},
          {"condition", condition},
          {"features", features},
          {"criticalities", details}};
}

}  // namespace

std::string critical_set_to_json(const Pair& pair, const CriticalSet& set) {
  json critical = json::array();
  for (const CriticalOrientation& o : set.orientations)
    critical.push_back(orientation_json(pair, o));
  json counts = json::object();
  for (int c = 0; c < kCriticalConditionCount; ++c)
    counts[std::string(to_string(CriticalCondition(c)))] = set.counts[c];
  counts["criticalities"] = set.stats.criticalities;
  counts["orientations"] = set.orientations.size();
  const CriticalStats& s = set.stats;
  json stats = {{"families", s.families},
                {"equations", s.equations},
                {"roots", s.roots},
                {"culled", s.culled},
                {"off_segment", s.off_segment},
                {"blocked", s.blocked},
                {"criticalities", s.criticalities},
                {"mapped", s.mapped}};
  json out = {{"format", "cslice-critical"}, {"version", 1},     {"pair", pair.name},
              {"critical", critical},        {"counts", counts}, {"stats", stats}};
  return out.dump(1) + "\n";
}

}  // namespace cslice
