// Reads a space file back (docs/space-format.md, "Reading a space file"): the embedded pair
// is rebuilt with the pair reader, the slices are recomputed at the stored orientations, and
// everything the file states about them is checked against the recomputation. The file is
// a summary (no slice geometry), so trusting it would mean trusting whoever last edited it;
// recomputing costs what `cslice compute` costs, a few milliseconds on the examples.
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cslice/space.hpp"
#include "parts/json_text.hpp"
#include "parts/validate.hpp"
#include "space/space_build.hpp"

namespace cslice {

namespace {

using json = nlohmann::json;

// Problems travel inside this file as an exception and leave it only as an InputError.
struct ReadFailure {
  std::string reason;
};

[[noreturn]] void fail(std::string reason) {
  throw ReadFailure{std::move(reason)};
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// "slices[3].kind" for the key "kind" of the object at "slices[3]".
std::string field_name(const std::string& where, std::string_view key) {
  return where.empty() ? std::string(key) : where + "." + std::string(key);
}

std::string indexed(const std::string& where, size_t i) {
  return where + "[" + std::to_string(i) + "]";
}

[[noreturn]] void fail_field(const std::string& field, const std::string& reason) {
  fail("field \"" + field + "\": " + reason);
}

const json& require(const json& obj, const std::string& where, std::string_view key) {
  if (!obj.is_object())
    fail_field(where.empty() ? "(top level)" : where,
               std::string("must be an object, got ") + obj.type_name());
  const auto it = obj.find(std::string(key));
  if (it == obj.end()) fail("missing field \"" + field_name(where, key) + "\"");
  return *it;
}

const json& require_array(const json& obj, const std::string& where, std::string_view key) {
  const json& v = require(obj, where, key);
  if (!v.is_array())
    fail_field(field_name(where, key), std::string("must be an array, got ") + v.type_name());
  return v;
}

double read_number(const json& v, const std::string& field) {
  if (!v.is_number()) fail_field(field, std::string("must be a number, got ") + v.type_name());
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail_field(field, "must be a finite number");
  return d;
}

double number_field(const json& obj, const std::string& where, std::string_view key) {
  return read_number(require(obj, where, key), field_name(where, key));
}

long long read_integer(const json& v, const std::string& field) {
  if (!v.is_number_integer())
    fail_field(field, std::string("must be an integer, got ") +
                          (v.is_number() ? "a fraction" : v.type_name()));
  // Above the long long range an unsigned integer would wrap (to -1 for 2^64 - 1).
  if (v.is_number_unsigned() && v.get<unsigned long long>() > LLONG_MAX)
    fail_field(field, "integer out of range: " + v.dump());
  return v.get<long long>();
}

long long integer_field(const json& obj, const std::string& where, std::string_view key) {
  return read_integer(require(obj, where, key), field_name(where, key));
}

std::string string_field(const json& obj, const std::string& where, std::string_view key) {
  const json& v = require(obj, where, key);
  if (!v.is_string())
    fail_field(field_name(where, key), std::string("must be a string, got ") + v.type_name());
  return v.get<std::string>();
}

bool bool_field(const json& obj, const std::string& where, std::string_view key) {
  const json& v = require(obj, where, key);
  if (!v.is_boolean())
    fail_field(field_name(where, key), std::string("must be true or false, got ") + v.type_name());
  return v.get<bool>();
}

// Equal up to round-off: the file holds every number to full precision, so a recomputation
// on the same program agrees exactly; the slack only absorbs a different compiler's or
// machine's last bits.
bool close(double a, double b, double absolute) {
  return std::fabs(a - b) <= absolute + 1e-9 * std::max(std::fabs(a), std::fabs(b));
}

void expect_count(const std::string& field, long long stored, long long recomputed,
                  const std::string& context = "") {
  if (stored != recomputed)
    fail_field(field, "the file says " + std::to_string(stored) + ", recomputed " +
                          std::to_string(recomputed) + context +
                          ": the file was edited or written by another version");
}

// The correspondence's entries are only counted (the reader recomputes the correspondence
// from the slices): each is dropped as soon as it is parsed. Kept, they made half of a large
// file's document in memory.
json parse_text(std::string_view text, long long& correspondence_entries) {
  // Far deeper than a valid file (7 levels) would overflow the stack where values are dumped.
  if (std::optional<std::string> why = detail::json_nesting_error(text)) fail(*why);
  std::string top_key;  // the top-level key whose value is being parsed
  const auto drop_entries = [&](int depth, json::parse_event_t event, json& parsed) {
    if (depth == 1 && event == json::parse_event_t::key) {
      top_key = parsed.get<std::string>();
      if (top_key == "correspondence") correspondence_entries = 0;  // the last one counts
      return true;
    }
    const bool entry_parsed = event == json::parse_event_t::object_end ||
                              event == json::parse_event_t::array_end ||
                              event == json::parse_event_t::value;
    if (depth != 2 || !entry_parsed || top_key != "correspondence") return true;
    ++correspondence_entries;
    return false;
  };
  try {
    return json::parse(text.begin(), text.end(), drop_entries);
  } catch (const json::parse_error& e) {
    // what() reads "[json.exception.parse_error.101] parse error at line L, column C: why".
    const std::string what = e.what();
    const size_t at = what.find("line ");
    fail("invalid JSON" +
         (at == std::string::npos ? std::string(": ") + what : " at " + what.substr(at)));
  } catch (const json::exception& e) {
    fail(std::string("invalid JSON: ") + e.what());
  }
}

void check_format(const json& top) {
  if (!top.is_object())
    fail(std::string("the top level must be a JSON object, got ") + top.type_name());
  const std::string format = string_field(top, "", "format");
  if (format != "cslice-space")
    fail_field("format", "expected \"cslice-space\", got \"" + format + "\"");
  const long long version = integer_field(top, "", "version");
  // Version 1 files lack their pair; version 2 files slice each interval an even number of
  // times (before 2026-11-25), which the recomputed plan no longer matches.
  if (version == 1)
    fail_field("version",
               "version 1 files do not embed their pair and cannot be read back; "
               "recompute the space with `cslice compute`");
  if (version == 2)
    fail_field("version",
               "version 2 files place their slices by an earlier plan and cannot be read "
               "back; recompute the space with `cslice compute`");
  if (version < kSpaceFormatVersion)
    fail_field("version", "version " + std::to_string(version) + " is not a space file version");
  if (version > kSpaceFormatVersion)
    fail_field("version", "version " + std::to_string(version) +
                              " is newer than this cslice reads (" +
                              std::to_string(kSpaceFormatVersion) + ")");
}

Pair read_pair(const json& top) {
  const json& file = require(top, "", "pair_file");
  if (!file.is_object())
    fail_field("pair_file", std::string("must be an object, got ") + file.type_name());
  LoadResult r = parse_pair(file.dump(), "");
  if (!r.ok()) fail_field("pair_file", r.error->message());
  Pair pair = std::move(*r.pair);
  const std::string name = string_field(top, "", "pair");
  if (name != pair.name)
    fail_field("pair", "\"" + name + "\" but the embedded pair is named \"" + pair.name + "\"");
  const std::string units = string_field(top, "", "units");
  if (units != pair.units)
    fail_field("units", "\"" + units + "\" but the embedded pair's are \"" + pair.units + "\"");
  const json& tol = require(top, "", "tolerance");
  const auto check_tol = [&](const char* key, double recomputed) {
    const double stored = number_field(tol, "tolerance", key);
    if (!close(stored, recomputed, 0.0))
      fail_field(field_name("tolerance", key), "the file says " + number_text(stored) +
                                                   ", the embedded pair gives " +
                                                   number_text(recomputed));
  };
  check_tol("contact", pair.tol.contact);
  check_tol("geometric", pair.tol.geometric);
  check_tol("critical_angle", pair.tol.critical_angle);
  return pair;
}

// The critical orientations, recomputed; they must be the ones the file lists.
CriticalSet read_criticals(const json& top, const Pair& pair) {
  const json& stored = require_array(top, "", "critical_orientations");
  CriticalSet set = critical_orientations(pair);
  expect_count("critical_orientations", static_cast<long long>(stored.size()),
               static_cast<long long>(set.orientations.size()), " critical orientations");
  for (size_t k = 0; k < stored.size(); ++k) {
    const std::string where = indexed("critical_orientations", k);
    CriticalOrientation& o = set.orientations[k];
    const double theta = number_field(stored[k], where, "theta");
    if (!close(theta, o.theta, pair.tol.critical_angle))
      fail_field(field_name(where, "theta"),
                 "the file says " + number_text(theta) + ", recomputed " + number_text(o.theta));
    const json& conditions = require_array(stored[k], where, "conditions");
    expect_count(field_name(where, "conditions"), static_cast<long long>(conditions.size()),
                 static_cast<long long>(o.criticalities.size()), " criticalities");
    for (size_t i = 0; i < conditions.size(); ++i) {
      const std::string field = indexed(field_name(where, "conditions"), i);
      const std::string name = conditions[i].is_string() ? conditions[i].get<std::string>() : "";
      if (name != to_string(o.criticalities[i].condition))
        fail_field(field, "the file says " + conditions[i].dump() + ", recomputed \"" +
                              std::string(to_string(o.criticalities[i].condition)) + "\"");
    }
    o.theta = theta;  // the file's own value: its critical slices lie exactly there
  }
  return set;
}

SliceKind read_kind(const json& slice, const std::string& where) {
  const std::string kind = string_field(slice, where, "kind");
  for (SliceKind k : {SliceKind::critical, SliceKind::interval, SliceKind::intermediate})
    if (kind == to_string(k)) return k;
  fail_field(field_name(where, "kind"),
             "expected \"critical\", \"interval\" or \"intermediate\", got \"" + kind + "\"");
}

// The stored orientations, which must be the ones compute_space plans for these critical
// orientations and this step: that is what makes the space's promises (a slice at every
// critical orientation, one in every interval, interpolation within the tolerance) hold.
std::vector<detail::PlannedSlice> read_plan(const json& stored, const Pair& pair,
                                            const CriticalSet& criticals, double max_step) {
  const std::vector<detail::PlannedSlice> plan = detail::plan_slices(criticals, max_step);
  expect_count("slices", static_cast<long long>(stored.size()), static_cast<long long>(plan.size()),
               " slices for the pair's critical orientations and interpolation step");
  std::vector<detail::PlannedSlice> out;
  for (size_t i = 0; i < stored.size(); ++i) {
    const std::string where = indexed("slices", i);
    detail::PlannedSlice s;
    s.theta = number_field(stored[i], where, "theta");
    s.kind = read_kind(stored[i], where);
    const long long interval = integer_field(stored[i], where, "interval");
    if (!close(s.theta, plan[i].theta, pair.tol.angular))
      fail_field(field_name(where, "theta"), "the file says " + number_text(s.theta) +
                                                 ", the plan gives " + number_text(plan[i].theta));
    if (s.kind != plan[i].kind)
      fail_field(field_name(where, "kind"), "the file says \"" + std::string(to_string(s.kind)) +
                                                "\", the plan gives \"" +
                                                std::string(to_string(plan[i].kind)) + "\"");
    // Compared as read: narrowed to int first, 2^32 + i would pass as i.
    expect_count(field_name(where, "interval"), interval, plan[i].interval);
    s.interval = plan[i].interval;
    out.push_back(s);
  }
  return out;
}

// What the file says of one slice, read from its document before the slices are recomputed
// (the documents of a larger pair's slices took a gigabyte more than these). Fields of the
// wrong type are named here, as they are read; what the values must be is checked against
// the recomputed slice (check_slice).
struct StoredSlice {
  struct Component {
    bool bounded = false;
    json area;  // a number, null, or {"type": name} for a value of another type
  };
  long long free_components = 0, bounded_free_components = 0, contact_graph_edges = 0;
  std::vector<Component> components;
  // The realizable labels as pairs of numbers; nullopt when an entry is not two numbers (it
  // then differs from any recomputed label).
  std::optional<std::vector<std::pair<double, double>>> labels;
};

StoredSlice read_stored_slice(const json& stored, size_t i) {
  const std::string where = indexed("slices", i);
  StoredSlice s;
  s.free_components = integer_field(stored, where, "free_components");
  s.bounded_free_components = integer_field(stored, where, "bounded_free_components");
  const json& components = require_array(stored, where, "components");
  for (size_t c = 0; c < components.size(); ++c) {
    const std::string cw = indexed(field_name(where, "components"), c);
    StoredSlice::Component& sc = s.components.emplace_back();
    sc.bounded = bool_field(components[c], cw, "bounded");
    // A value of another type is kept as {"type": its name} for the message.
    const json& area = require(components[c], cw, "area");
    sc.area =
        area.is_number() || area.is_null() ? area : json::object({{"type", area.type_name()}});
  }
  s.labels.emplace();
  for (const json& l : require_array(stored, where, "realizable_labels")) {
    if (!l.is_array() || l.size() != 2 || !l[0].is_number() || !l[1].is_number()) {
      s.labels.reset();
      break;
    }
    s.labels->emplace_back(l[0].get<double>(), l[1].get<double>());
  }
  s.contact_graph_edges = integer_field(stored, where, "contact_graph_edges");
  return s;
}

// Every summary the file gives for slice i against the recomputed slice.
void check_slice(const StoredSlice& stored, size_t i, const SpaceSlice& s, const Pair& pair) {
  const std::string where = indexed("slices", i);
  const std::string at = " (theta " + number_text(s.theta) + ")";
  const Slice& slice = s.slice;
  int bounded = 0;
  for (const FreeComponent& c : slice.free_components) bounded += c.bounded ? 1 : 0;
  expect_count(field_name(where, "free_components"), stored.free_components,
               static_cast<long long>(slice.free_components.size()), at);
  expect_count(field_name(where, "bounded_free_components"), stored.bounded_free_components,
               bounded, at);
  expect_count(field_name(where, "components"), static_cast<long long>(stored.components.size()),
               static_cast<long long>(slice.free_components.size()), " components" + at);
  const double area_slack = pair.tol.geometric * pair.tol.size;
  for (size_t c = 0; c < stored.components.size(); ++c) {
    const std::string cw = indexed(field_name(where, "components"), c);
    const FreeComponent& fc = slice.free_components[c];
    if (stored.components[c].bounded != fc.bounded)
      fail_field(field_name(cw, "bounded"), std::string("the file says ") +
                                                (fc.bounded ? "false" : "true") + ", recomputed " +
                                                (fc.bounded ? "true" : "false"));
    const json& area = stored.components[c].area;
    if (!fc.bounded || !std::isfinite(fc.area)) {
      if (!area.is_null()) fail_field(field_name(cw, "area"), "must be null for this component");
      continue;
    }
    if (area.is_object())  // another type, as read_number names it
      fail_field(field_name(cw, "area"),
                 "must be a number, got " + area["type"].get<std::string>());
    const double a = read_number(area, field_name(cw, "area"));
    if (!close(a, fc.area, area_slack))
      fail_field(field_name(cw, "area"),
                 "the file says " + number_text(a) + ", recomputed " + number_text(fc.area) + at);
  }
  const std::vector<SegmentLabel> labels = realizable_labels(slice);
  bool same = stored.labels && stored.labels->size() == labels.size();
  for (size_t k = 0; same && k < labels.size(); ++k)
    same = (*stored.labels)[k].first == labels[k].moving_feature &&
           (*stored.labels)[k].second == labels[k].fixed_feature;
  if (!same) {
    json recomputed = json::array();
    for (const SegmentLabel& l : labels)
      recomputed.push_back(json::array({l.moving_feature, l.fixed_feature}));
    fail_field(field_name(where, "realizable_labels"),
               "differ from the recomputed ones " + recomputed.dump() + at);
  }
  expect_count(field_name(where, "contact_graph_edges"), stored.contact_graph_edges,
               static_cast<long long>(slice.contact_graph.edges.size()), at);
}

void check_topology(const json& top, const SlicedSpace& space, long long correspondence_entries) {
  const json& topo = require(top, "", "topology");
  const SpaceTopology& t = space.topology;
  expect_count("topology.free_components_3d", integer_field(topo, "topology", "free_components_3d"),
               static_cast<long long>(t.components.size()));
  expect_count("topology.cells",
               static_cast<long long>(require_array(topo, "topology", "cells").size()),
               static_cast<long long>(t.cells.size()), " cells");
  expect_count("topology.transitions",
               static_cast<long long>(require_array(topo, "topology", "transitions").size()),
               static_cast<long long>(t.transitions.size()), " transitions");
  const json& stored = require_array(topo, "topology", "slice_components");
  if (stored != json(t.slice_components))
    fail_field("topology.slice_components",
               "differ from the recomputed 3D components of the slices' free components");
  require_array(top, "", "correspondence");  // its entries were counted and dropped
  expect_count("correspondence", correspondence_entries,
               static_cast<long long>(space.correspondence.size()), " entries");
}

void check_counts(const json& top, const SlicedSpace& space) {
  const json& counts = require(top, "", "counts");
  expect_count("counts.critical_orientations",
               integer_field(counts, "counts", "critical_orientations"),
               static_cast<long long>(space.criticals.orientations.size()));
  expect_count("counts.criticalities", integer_field(counts, "counts", "criticalities"),
               space.criticals.stats.criticalities);
  expect_count("counts.slices", integer_field(counts, "counts", "slices"),
               static_cast<long long>(space.slices.size()));
}

SlicedSpace read_space(json& top, long long correspondence_entries, const Pair& pair, int threads) {
  SlicedSpace space;
  space.criticals = read_criticals(top, pair);
  const json& interpolation = require(top, "", "interpolation");
  space.reach = contact_reach(pair);
  space.max_step = interpolation_step(space.reach, pair.tol.contact);
  const double reach = number_field(interpolation, "interpolation", "reach");
  const double step = number_field(interpolation, "interpolation", "max_step");
  if (!close(reach, space.reach, pair.tol.geometric))
    fail_field("interpolation.reach",
               "the file says " + number_text(reach) + ", recomputed " + number_text(space.reach));
  if (!close(step, space.max_step, pair.tol.angular))
    fail_field("interpolation.max_step", "the file says " + number_text(step) + ", recomputed " +
                                             number_text(space.max_step));
  const json& stored = require_array(top, "", "slices");
  const auto plan = read_plan(stored, pair, space.criticals, space.max_step);
  std::vector<StoredSlice> summaries;
  for (size_t i = 0; i < stored.size(); ++i) summaries.push_back(read_stored_slice(stored[i], i));
  top.erase("slices");  // its documents are read: free them before the slices take the memory
  // Everything the recomputation needs is known to be well formed; now the slices.
  // As compute_space: the side slices reuse the models built for the intermediate ones.
  detail::KnownModels models;
  space.slices = detail::compute_slices(pair, plan, {threads, true, true}, {}, &models);
  for (size_t i = 0; i < summaries.size(); ++i) check_slice(summaries[i], i, space.slices[i], pair);
  space.correspondence = detail::slice_correspondences(space.slices);
  space.topology = detail::compute_topology(pair, space, {threads, false, true}, &models);
  check_topology(top, space, correspondence_entries);
  check_counts(top, space);
  if (const auto it = top.find("timing"); it != top.end() && it->is_object()) {
    // Optional, but a value of another type is named (json::value would throw type_error).
    const auto seconds = [&](const char* key) {
      const auto v = it->find(key);
      return v == it->end() ? 0.0 : read_number(*v, field_name("timing", key));
    };
    space.seconds_criticals = seconds("criticals_seconds");
    space.seconds_slices = seconds("slices_seconds");
  }
  return space;
}

}  // namespace

namespace {

// The space from its text; `release`, when given, frees the text as soon as it is parsed (a
// larger pair's file is a gigabyte, and recomputing its slices needs the memory).
LoadSpaceResult read_space_text(std::string_view json_text, std::string_view source, int threads,
                                const std::function<void()>& release) {
  LoadSpaceResult result;
  try {
    long long correspondence_entries = 0;
    json top = parse_text(json_text, correspondence_entries);
    if (release) release();
    check_format(top);
    Pair pair = read_pair(top);
    result.space = read_space(top, correspondence_entries, pair, threads);
    result.pair = std::move(pair);
  } catch (const ReadFailure& f) {
    result.error = InputError{"", "", -1, -1, f.reason};
  } catch (const std::exception& e) {
    // Not a problem we know of; still reported as data, never thrown to the caller.
    result.error =
        InputError{"", "", -1, -1, std::string("internal error while reading: ") + e.what()};
  }
  if (result.error) {
    result.pair.reset();
    result.space.reset();
    result.error->file = std::string(source);
  }
  return result;
}

}  // namespace

LoadSpaceResult parse_space(std::string_view json_text, std::string_view source, int threads) {
  return read_space_text(json_text, source, threads, {});
}

LoadSpaceResult load_space(const std::string& path, int threads) {
  std::string text;
  if (std::optional<InputError> error = detail::read_input_file(path, text)) {
    LoadSpaceResult result;
    result.error = std::move(error);
    return result;
  }
  return read_space_text(text, path, threads, [&] { std::string().swap(text); });
}

}  // namespace cslice
