// The slice as JSON (docs/slice-format.md). Every curve is written the same way: its type,
// endpoints, and for arcs the centre, radius and signed sweep, so readers need one decoder.
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "cslice/slice_io.hpp"

namespace cslice {

namespace {

// Ordered so the output lists fields in the documented order.
using json = nlohmann::ordered_json;

// The reader may reverse a loop (part.cpp, reverse_loop): new edge k is input edge n-1-k and
// new vertex k is input vertex (n-k) mod n. Users know the file's numbering, so undo it.
int input_index(const Loop& loop, const Feature& f) {
  const int n = static_cast<int>(loop.edges.size());
  if (!loop.reversed || n == 0) return f.index;
  if (f.kind == FeatureKind::vertex) return (n - f.index) % n;
  return n - 1 - f.index;
}

json point(Vec2 p) {
  return json::array({p.x, p.y});
}

// NaN and infinities have no JSON spelling; null says "no value".
json number_or_null(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

// Type, endpoints and arc data of a curve, added to `out`.
void put_curve(json& out, const Curve& c, bool is_point) {
  if (is_point) {
    out["type"] = "point";
    out["from"] = point(c.from);
    out["to"] = point(c.from);
    return;
  }
  out["type"] = c.is_arc() ? "arc" : "line";
  out["from"] = point(c.from);
  out["to"] = point(c.to);
  if (!c.is_arc()) return;
  out["center"] = point(c.center);
  out["radius"] = c.radius;
  out["start_angle"] = c.start_angle;
  out["sweep"] = c.sweep;
}

json piece_json(const ContactPiece& p) {
  json out = {{"segment", p.segment}};
  put_curve(out, p.curve, false);
  return out;
}

json segments_json(const Pair& pair, const Slice& slice, const std::set<int>& realizable) {
  json out = json::array();
  for (const ContactSegment& s : slice.contact_segments) {
    json j = {{"id", s.id},
              {"moving_feature", s.moving_feature},
              {"fixed_feature", s.fixed_feature},
              {"kind", std::string(to_string(s.kind))},
              {"moving_feature_desc", describe_feature(pair.moving, s.moving_feature)},
              {"fixed_feature_desc", describe_feature(pair.fixed, s.fixed_feature)}};
    put_curve(j, s.curve, s.is_point);
    j["realizable"] = realizable.count(s.id) > 0;
    out.push_back(std::move(j));
  }
  return out;
}

json components_json(const Slice& slice) {
  json out = json::array();
  for (const FreeComponent& c : slice.free_components) {
    json cycles = json::array();
    for (const auto& cycle : c.boundary) {
      json pieces = json::array();
      for (const ContactPiece& p : cycle) pieces.push_back(piece_json(p));
      cycles.push_back(std::move(pieces));
    }
    out.push_back({{"id", c.id},
                   {"bounded", c.bounded},
                   {"area", c.bounded ? number_or_null(c.area) : json(nullptr)},
                   {"sample", point(c.sample)},
                   {"boundary", std::move(cycles)}});
  }
  return out;
}

json degenerate_json(const Slice& slice) {
  json out = json::array();
  for (const DegenerateContact& d : slice.degenerate) {
    json j = {{"segments", d.segments}};
    put_curve(j, d.curve, d.is_point || d.curve.from == d.curve.to);
    out.push_back(std::move(j));
  }
  return out;
}

json graph_json(const ContactGraph& g) {
  json edges = json::array();
  for (const ContactGraphEdge& e : g.edges)
    edges.push_back({{"a", e.a}, {"b", e.b}, {"at", point(e.at)}});
  return {{"nodes", g.nodes}, {"edges", std::move(edges)}};
}

json counts_json(const Slice& slice, const std::set<int>& realizable) {
  int bounded = 0;
  for (const FreeComponent& c : slice.free_components) bounded += c.bounded ? 1 : 0;
  return {{"contact_segments", slice.contact_segments.size()},
          {"realizable_segments", realizable.size()},
          {"realizable_pieces", slice.realizable.size()},
          {"free_components", slice.free_components.size()},
          {"bounded_free_components", bounded},
          {"degenerate_contacts", slice.degenerate.size()},
          {"graph_nodes", slice.contact_graph.nodes.size()},
          {"graph_edges", slice.contact_graph.edges.size()}};
}

}  // namespace

std::set<int> realizable_segment_ids(const Slice& slice) {
  const std::vector<int> ids = realizable_segments(slice);
  return {ids.begin(), ids.end()};
}

std::string describe_feature(const Part& part, int feature) {
  const int count = static_cast<int>(part.features.size());
  if (feature < 0 || feature >= count) return "feature " + std::to_string(feature);
  const Feature& f = part.features[feature];
  if (f.loop < 0 || f.loop >= static_cast<int>(part.loops.size()))
    return "feature " + std::to_string(feature);
  const Loop& loop = part.loops[f.loop];
  return std::string(to_string(f.kind)) + " " + std::to_string(input_index(loop, f)) + " of loop " +
         std::to_string(loop.source_index);
}

std::string slice_to_json(const Pair& pair, const Slice& slice) {
  const std::set<int> realizable = realizable_segment_ids(slice);
  json pieces = json::array();
  for (const ContactPiece& p : slice.realizable) pieces.push_back(piece_json(p));
  const json out = {{"format", "cslice-slice"},
                    {"version", 1},
                    {"pair", pair.name},
                    {"theta", slice.theta},
                    {"units", pair.units},
                    {"tolerance", pair.tol.contact},
                    {"geometric_tolerance", pair.tol.geometric},
                    {"contact_segments", segments_json(pair, slice, realizable)},
                    {"free_components", components_json(slice)},
                    {"realizable_pieces", std::move(pieces)},
                    {"degenerate_contacts", degenerate_json(slice)},
                    {"contact_graph", graph_json(slice.contact_graph)},
                    {"counts", counts_json(slice, realizable)}};
  return out.dump(2) + "\n";
}

}  // namespace cslice
