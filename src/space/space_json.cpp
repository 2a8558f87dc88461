// The sliced space as JSON (docs/space-format.md): the pair itself, in the pair-file format,
// and per slice a summary, not the whole slice (`cslice slice` gives that, and the reader
// recomputes it), so the file stays small enough to read back quickly.
#include <tbb/parallel_for.h>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <string_view>

#include "cslice/space.hpp"

namespace cslice {

namespace {

// Ordered so the output lists fields in the documented order.
using json = nlohmann::ordered_json;

// NaN and infinities have no JSON spelling; null says "no value".
json number_or_null(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

// One loop in the pair-file format, as the file gave it: loading reorients a loop so its
// material lies on its left (reverse_loop in src/parts/part.cpp: new edge k is the reversal of
// old edge n - 1 - k), so a reversed loop is turned back, which restores the file's vertices
// and bulges bit for bit (reversal only swaps ends and negates the bulge). Read again, it
// gives the same curves, the same orientation and the same feature numbering.
json loop_json(const Loop& loop) {
  if (loop.is_circle()) {
    const Curve& c = loop.edges.front();
    return {{"circle", json::array({c.center.x, c.center.y, c.radius})}};
  }
  json out = json::array();
  const size_t n = loop.edges.size();
  for (size_t k = 0; k < n; ++k) {
    Vec2 p;
    double bulge = 0.0;
    if (loop.reversed) {
      const Curve& e = loop.edges[n - 1 - k];
      p = e.to;
      bulge = -e.bulge;
    } else {
      p = loop.edges[k].from;
      bulge = loop.edges[k].bulge;
    }
    json v = json::array({p.x, p.y});
    if (bulge != 0.0) v.push_back(bulge);
    out.push_back(std::move(v));
  }
  return out;
}

json part_json(const Part& part) {
  std::vector<const Loop*> loops;
  for (const Loop& loop : part.loops) loops.push_back(&loop);
  std::stable_sort(loops.begin(), loops.end(),
                   [](const Loop* a, const Loop* b) { return a->source_index < b->source_index; });
  json list = json::array();
  for (const Loop* loop : loops) list.push_back(loop_json(*loop));
  json out = {{"loops", std::move(list)}};
  if (part.enclosure) out["enclosure"] = true;
  return out;
}

json pair_file_json(const Pair& pair) {
  json out = {{"name", pair.name}, {"units", pair.units}};
  if (pair.requested_tolerance) out["tolerance"] = *pair.requested_tolerance;
  out["moving"] = part_json(pair.moving);
  out["fixed"] = part_json(pair.fixed);
  return out;
}

json labels_json(const std::vector<SegmentLabel>& labels) {
  json out = json::array();
  for (const SegmentLabel& l : labels)
    out.push_back(json::array({l.moving_feature, l.fixed_feature}));
  return out;
}

json criticals_json(const CriticalSet& set) {
  json out = json::array();
  for (const CriticalOrientation& o : set.orientations) {
    json conditions = json::array();
    for (const Criticality& k : o.criticalities) conditions.push_back(to_string(k.condition));
    out.push_back({{"theta", o.theta}, {"conditions", std::move(conditions)}});
  }
  return out;
}

json components_json(const Slice& slice) {
  json out = json::array();
  for (const FreeComponent& c : slice.free_components)
    out.push_back({{"id", c.id},
                   {"bounded", c.bounded},
                   {"area", c.bounded ? number_or_null(c.area) : json(nullptr)},
                   {"sample", json::array({c.sample.x, c.sample.y})}});
  return out;
}

json slice_json(const SpaceSlice& s) {
  int bounded = 0;
  for (const FreeComponent& c : s.slice.free_components) bounded += c.bounded ? 1 : 0;
  return {{"theta", s.theta},
          {"kind", to_string(s.kind)},
          {"interval", s.interval},
          {"free_components", s.slice.free_components.size()},
          {"bounded_free_components", bounded},
          {"components", components_json(s.slice)},
          {"realizable_labels", labels_json(realizable_labels(s.slice))},
          {"contact_graph_edges", s.slice.contact_graph.edges.size()}};
}

json correspondence_json(const SliceCorrespondence& c) {
  return {{"from", c.from},
          {"to", c.to},
          {"kept", labels_json(c.kept)},
          {"appearing", labels_json(c.appearing)},
          {"vanishing", labels_json(c.vanishing)}};
}

json counts_json(const SlicedSpace& space) {
  int by_kind[3] = {};
  for (const SpaceSlice& s : space.slices) by_kind[static_cast<int>(s.kind)] += 1;
  return {{"critical_orientations", space.criticals.orientations.size()},
          {"criticalities", space.criticals.stats.criticalities},
          {"slices", space.slices.size()},
          {"critical_slices", by_kind[0]},
          {"interval_slices", by_kind[1]},
          {"intermediate_slices", by_kind[2]}};
}

json cells_json(const std::vector<SpaceCell>& cells) {
  json out = json::array();
  for (const SpaceCell& c : cells)
    out.push_back(
        {{"id", c.id},
         {"interval", c.interval},
         {"theta_range", json::array({c.theta_from, c.theta_to})},
         {"component", c.component},
         {"bounded", c.bounded},
         {"area_range", json::array({number_or_null(c.min_area), number_or_null(c.max_area)})},
         {"sample", json::array({c.sample.x, c.sample.y, c.sample_theta})}});
  return out;
}

json transitions_json(const std::vector<CriticalTransition>& list) {
  json out = json::array();
  for (const CriticalTransition& t : list) {
    json joins = json::array(), events = json::array(), kinds = json::array();
    for (const auto& [a, b] : t.joins) joins.push_back(json::array({a, b}));
    std::vector<std::string> names;
    for (const TransitionEvent& e : t.events) {
      events.push_back({{"kind", to_string(e.kind)},
                        {"before", e.before},
                        {"after", e.after},
                        {"critical_components", e.critical_components}});
      names.emplace_back(to_string(e.kind));
    }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    for (const std::string& name : names) kinds.push_back(name);
    out.push_back({{"critical", t.critical},
                   {"theta", t.theta},
                   {"interval_before", t.interval_before},
                   {"interval_after", t.interval_after},
                   {"side_angles", json::array({t.side_before, t.side_after})},
                   {"kinds", std::move(kinds)},
                   {"events", std::move(events)},
                   {"joins", std::move(joins)},
                   {"orphan_critical_components", t.orphan_critical_components}});
  }
  return out;
}

json topology_json(const SpaceTopology& topo) {
  json components = json::array();
  for (const SpaceComponent& c : topo.components) {
    json ranges = json::array();
    for (const auto& [from, to] : c.theta_ranges) ranges.push_back(json::array({from, to}));
    components.push_back({{"id", c.id},
                          {"cells", c.cells},
                          {"spans_all_theta", c.spans_all_theta},
                          {"theta_ranges", std::move(ranges)}});
  }
  const TopologyChecks& k = topo.checks;
  return {{"free_components_3d", topo.components.size()},
          {"cells", cells_json(topo.cells)},
          {"transitions", transitions_json(topo.transitions)},
          {"components", std::move(components)},
          {"slice_components", topo.slice_components},
          {"checks",
           {{"interval_match_failures", k.interval_match_failures},
            {"boundary_label_mismatches", k.boundary_label_mismatches},
            {"side_slices_not_equivalent", k.side_slices_not_equivalent},
            {"joins_by_count", k.joins_by_count},
            {"joins_by_clearance", k.joins_by_clearance},
            {"joins_by_carrying", k.joins_by_carrying},
            {"side_slices_evaluated", k.side_slices_evaluated},
            {"carry_slices", k.carry_slices},
            {"carry_slices_evaluated", k.carry_slices_evaluated},
            {"orphan_critical_components", k.orphan_critical_components},
            {"refinement_slices", k.refinement_slices},
            {"label_matches", k.label_matches},
            {"problems", k.problems}}}};
}

// The two long arrays, slices and correspondence, stand as placeholders in the document until
// their text replaces them, written one element's document at a time. A document of every
// element took more memory than the space itself and most of the time spent writing it.
constexpr const char* kSlicesPlaceholder = "\x01slices\x01";
constexpr const char* kCorrespondencePlaceholder = "\x01correspondence\x01";

// The array as `dump(2)` lays out a top-level key's array: each element indented by 4, the
// closing bracket by 2. Elements are independent, so blocks of them are laid out in parallel
// (a fixed order of emitting keeps the text the same), one block's text in memory at a time.
template <class T, class ToJson, class Emit>
void emit_array(const std::vector<T>& items, ToJson to_json, Emit&& emit) {
  if (items.empty()) {
    emit("[]");
    return;
  }
  constexpr size_t kBlock = 512;
  std::vector<std::string> laid(std::min(kBlock, items.size()));
  emit("[");
  for (size_t first = 0; first < items.size(); first += kBlock) {
    const size_t count = std::min(kBlock, items.size() - first);
    tbb::parallel_for(size_t(0), count, [&](size_t k) {
      const std::string element = to_json(items[first + k]).dump(2);
      std::string& out = laid[k];
      out.clear();
      out += first + k == 0 ? "\n    " : ",\n    ";
      for (const char c : element) {
        out += c;
        if (c == '\n') out += "    ";
      }
    });
    for (size_t k = 0; k < count; ++k) emit(laid[k]);
  }
  emit("\n  ]");
}

// Emits `document` up to `placeholder` (a string value in it) and removes that part.
template <class Emit>
void emit_until(std::string_view& document, const char* placeholder, Emit&& emit) {
  const std::string quoted = json(placeholder).dump();
  const size_t at = document.find(quoted);
  emit(document.substr(0, at));
  document.remove_prefix(at + quoted.size());
}

// The file's text, piece by piece, to `emit`: the two long arrays a block at a time, so that
// a writer to disk never holds the whole text (1.15 GB for a 600-feature pair).
template <class Emit>
void emit_space(const Pair& pair, const SlicedSpace& space, bool with_timing, Emit&& emit) {
  json out = {{"format", "cslice-space"},
              {"version", kSpaceFormatVersion},
              {"pair", pair.name},
              {"units", pair.units},
              {"pair_file", pair_file_json(pair)},
              {"tolerance",
               {{"contact", pair.tol.contact},
                {"geometric", pair.tol.geometric},
                {"critical_angle", pair.tol.critical_angle}}},
              {"interpolation", {{"reach", space.reach}, {"max_step", space.max_step}}},
              {"critical_orientations", criticals_json(space.criticals)},
              {"slices", kSlicesPlaceholder},
              {"correspondence", kCorrespondencePlaceholder},
              {"topology", topology_json(space.topology)},
              {"counts", counts_json(space)}};
  if (with_timing)
    out["timing"] = {{"criticals_seconds", space.seconds_criticals},
                     {"slices_seconds", space.seconds_slices}};
  const std::string skeleton = out.dump(2) + "\n";
  std::string_view rest = skeleton;
  emit_until(rest, kSlicesPlaceholder, emit);
  emit_array(space.slices, slice_json, emit);
  emit_until(rest, kCorrespondencePlaceholder, emit);
  emit_array(space.correspondence, correspondence_json, emit);
  emit(rest);
}

}  // namespace

std::string pair_file_text(const Pair& pair) {
  return pair_file_json(pair).dump(2) + "\n";
}

std::string space_to_json(const Pair& pair, const SlicedSpace& space, bool with_timing) {
  std::string text;
  emit_space(pair, space, with_timing, [&](std::string_view piece) { text += piece; });
  return text;
}

void write_space_json(std::ostream& out, const Pair& pair, const SlicedSpace& space,
                      bool with_timing) {
  emit_space(pair, space, with_timing, [&](std::string_view piece) {
    out.write(piece.data(), static_cast<std::streamsize>(piece.size()));
  });
}

}  // namespace cslice
