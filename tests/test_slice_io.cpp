// Slices written out: slice_to_json's documented shape (docs/slice-format.md) on hand-made
// slices, render_slice_svg's regions, arcs (with the sweep flag right under the y flip) and
// legend, and `cslice slice` as a program: outputs on success, no file on bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <regex>
#include <stdexcept>
#include <string>

#include "cslice/pair.hpp"
#include "cslice/render_svg.hpp"
#include "cslice/slice.hpp"
#include "cslice/slice_io.hpp"
#include "support/cli_run.hpp"
#include "support/examples.hpp"

namespace cslice {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testkit::quoted;
using testkit::read_file;
using testkit::run_cli;
using testkit::RunResult;

// Moving: a unit square (features: vertex 0, segment 0, vertex 1, ...). Fixed: loop 0 a big
// square listed clockwise (so the reader reverses it), loop 1 a circle hole.
constexpr const char* kPairJson = R"({
  "name": "io-test", "units": "in", "tolerance": 0.01,
  "moving": { "loops": [[[0, 0], [1, 0], [1, 1], [0, 1]]] },
  "fixed": { "loops": [[[-5, -5], [-5, 5], [5, 5], [5, -5]], {"circle": [0, 0, 1]}] }
})";

Pair load_pair_text(const char* text) {
  LoadResult r = parse_pair(text, "test");
  if (!r.ok()) throw std::runtime_error(r.error->message());
  return std::move(*r.pair);
}

ContactSegment segment(int id, ContactKind kind, Curve curve, bool is_point = false) {
  ContactSegment s;
  s.id = id;
  s.moving_feature = 0;
  s.fixed_feature = 1;
  s.kind = kind;
  s.curve = curve;
  s.is_point = is_point;
  return s;
}

ContactPiece piece(int id, Curve curve) {
  return ContactPiece{id, curve};
}

// The square [0, 2]^2 as one bounded component: four line pieces, counterclockwise; its
// contact segments run the other way (blocked outside, on their left) and are longer.
Slice square_slice() {
  Slice s;
  s.theta = 0.5;
  const Vec2 a{0, 0}, b{2, 0}, c{2, 2}, d{0, 2};
  s.contact_segments = {segment(0, ContactKind::vertex_segment, make_segment({3, 0}, {-1, 0})),
                        segment(1, ContactKind::segment_vertex, make_segment(c, b)),
                        segment(2, ContactKind::vertex_segment, make_segment(d, c)),
                        segment(3, ContactKind::segment_vertex, make_segment(a, d)),
                        segment(4, ContactKind::vertex_segment, make_segment({5, 5}, {6, 5}))};
  FreeComponent f;
  f.id = 0;
  f.bounded = true;
  f.area = 4.0;
  f.sample = {1, 1};
  f.boundary = {{piece(0, make_segment(a, b)), piece(1, make_segment(b, c)),
                 piece(2, make_segment(c, d)), piece(3, make_segment(d, a))}};
  s.free_components = {f};
  s.realizable = f.boundary.front();
  s.contact_graph.nodes = {0, 1, 2, 3};
  s.contact_graph.edges = {{0, 1, b}, {1, 2, c}, {2, 3, d}, {0, 3, a}};
  return s;
}

// A half disc {|p| < 1, y > 0}: a segment along the x axis and a counterclockwise half arc.
Slice half_disc_slice() {
  Slice s;
  s.theta = 0.0;
  const Curve arc = make_arc({0, 0}, 1.0, 0.0, kPi);
  s.contact_segments = {segment(0, ContactKind::arc_vertex, make_segment({1, 0}, {-1, 0})),
                        segment(1, ContactKind::arc_arc, reversed(arc))};
  FreeComponent f;
  f.bounded = true;
  f.area = kPi / 2.0;
  f.sample = {0, 0.5};
  f.boundary = {{piece(0, make_segment({-1, 0}, {1, 0})), piece(1, arc)}};
  s.free_components = {f};
  s.realizable = f.boundary.front();
  s.contact_graph.nodes = {0, 1};
  return s;
}

// Free space everywhere except the square island [0, 1]^2 (one clockwise cycle), with a
// perfect fit at (3, 3) and a full-circle contact segment nobody realizes.
Slice unbounded_slice() {
  Slice s;
  s.theta = 1.0;
  const Vec2 a{0, 0}, b{1, 0}, c{1, 1}, d{0, 1};
  s.contact_segments = {segment(0, ContactKind::vertex_segment, make_segment(a, d)),
                        segment(1, ContactKind::vertex_segment, make_segment(d, c)),
                        segment(2, ContactKind::vertex_segment, make_segment(c, b)),
                        segment(3, ContactKind::vertex_segment, make_segment(b, a)),
                        segment(4, ContactKind::arc_arc, make_segment({3, 3}, {3, 3}), true),
                        segment(5, ContactKind::vertex_arc, make_circle({8, 8}, 0.5))};
  FreeComponent f;
  f.bounded = false;
  f.area = std::numeric_limits<double>::quiet_NaN();
  f.sample = {-3, -3};
  f.boundary = {{piece(0, make_segment(d, a)), piece(1, make_segment(c, d)),
                 piece(2, make_segment(b, c)), piece(3, make_segment(a, b))}};
  s.free_components = {f};
  s.realizable = f.boundary.front();
  s.realizable.push_back(piece(4, make_segment({3, 3}, {3, 3})));
  DegenerateContact dc;
  dc.segments = {4};
  dc.curve = make_segment({3, 3}, {3, 3});
  dc.is_point = true;
  s.degenerate = {dc};
  s.contact_graph.nodes = {0, 1, 2, 3, 4};
  return s;
}

void expect_point(const json& j, double x, double y) {
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 2u);
  EXPECT_DOUBLE_EQ(j[0].get<double>(), x);
  EXPECT_DOUBLE_EQ(j[1].get<double>(), y);
}

// ---- Feature descriptions ------------------------------------------------------------

TEST(DescribeFeature, UsesTheFileNumbering) {
  const Pair pair = load_pair_text(kPairJson);
  EXPECT_EQ(describe_feature(pair.moving, 0), "vertex 0 of loop 0");
  EXPECT_EQ(describe_feature(pair.moving, 1), "segment 0 of loop 0");
  EXPECT_EQ(describe_feature(pair.moving, 7), "segment 3 of loop 0");
  EXPECT_EQ(describe_feature(pair.moving, 99), "feature 99");
  EXPECT_EQ(describe_feature(pair.moving, -1), "feature -1");
}

// The fixed square was listed clockwise; after reversal its oriented vertex k is file vertex
// (n - k) mod n and oriented edge k is file edge n - 1 - k.
TEST(DescribeFeature, UndoesLoopReversal) {
  const Pair pair = load_pair_text(kPairJson);
  ASSERT_TRUE(pair.fixed.loops[0].reversed);
  for (int i = 0; i < static_cast<int>(pair.fixed.features.size()); ++i) {
    const Feature& f = pair.fixed.features[i];
    if (f.loop != 0) continue;
    const std::string desc = describe_feature(pair.fixed, i);
    if (f.kind == FeatureKind::vertex) {
      EXPECT_EQ(desc, "vertex " + std::to_string((4 - f.index) % 4) + " of loop 0");
    } else {
      EXPECT_EQ(desc, "segment " + std::to_string(3 - f.index) + " of loop 0");
    }
  }
  EXPECT_EQ(describe_feature(pair.fixed, static_cast<int>(pair.fixed.features.size()) - 1),
            "arc 0 of loop 1");
}

// The oriented vertex the description names sits where the file put it.
TEST(DescribeFeature, NamedVertexIsAtTheFilePosition) {
  const Pair pair = load_pair_text(kPairJson);
  const Vec2 file_vertices[] = {{-5, -5}, {-5, 5}, {5, 5}, {5, -5}};
  for (int i = 0; i < static_cast<int>(pair.fixed.features.size()); ++i) {
    const Feature& f = pair.fixed.features[i];
    if (f.loop != 0 || f.kind != FeatureKind::vertex) continue;
    const std::string desc = describe_feature(pair.fixed, i);
    const int file_index = desc[7] - '0';
    EXPECT_EQ(f.point, file_vertices[file_index]) << desc;
  }
}

// ---- JSON ----------------------------------------------------------------------------

TEST(SliceJson, TopLevelFields) {
  const Pair pair = load_pair_text(kPairJson);
  const json j = json::parse(slice_to_json(pair, square_slice()));
  EXPECT_EQ(j["format"], "cslice-slice");
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["pair"], "io-test");
  EXPECT_DOUBLE_EQ(j["theta"].get<double>(), 0.5);
  EXPECT_EQ(j["units"], "in");
  EXPECT_DOUBLE_EQ(j["tolerance"].get<double>(), 0.01);
  for (const char* key : {"contact_segments", "free_components", "realizable_pieces",
                          "degenerate_contacts", "contact_graph", "counts"})
    EXPECT_TRUE(j.contains(key)) << key;
}

TEST(SliceJson, ContactSegments) {
  const Pair pair = load_pair_text(kPairJson);
  const json j = json::parse(slice_to_json(pair, square_slice()));
  const json& segs = j["contact_segments"];
  ASSERT_EQ(segs.size(), 5u);
  const json& s0 = segs[0];
  EXPECT_EQ(s0["id"], 0);
  EXPECT_EQ(s0["moving_feature"], 0);
  EXPECT_EQ(s0["fixed_feature"], 1);
  EXPECT_EQ(s0["kind"], "vertex_segment");
  EXPECT_EQ(s0["moving_feature_desc"], "vertex 0 of loop 0");
  EXPECT_EQ(s0["fixed_feature_desc"], describe_feature(pair.fixed, 1));
  EXPECT_EQ(s0["type"], "line");
  expect_point(s0["from"], 3, 0);
  expect_point(s0["to"], -1, 0);
  EXPECT_FALSE(s0.contains("center"));
  EXPECT_EQ(s0["realizable"], true);
  EXPECT_EQ(segs[1]["kind"], "segment_vertex");
  EXPECT_EQ(segs[4]["realizable"], false);
}

TEST(SliceJson, BoundedComponentWithLinePieces) {
  const Pair pair = load_pair_text(kPairJson);
  const json j = json::parse(slice_to_json(pair, square_slice()));
  ASSERT_EQ(j["free_components"].size(), 1u);
  const json& c = j["free_components"][0];
  EXPECT_EQ(c["id"], 0);
  EXPECT_EQ(c["bounded"], true);
  EXPECT_DOUBLE_EQ(c["area"].get<double>(), 4.0);
  expect_point(c["sample"], 1, 1);
  ASSERT_EQ(c["boundary"].size(), 1u);
  const json& cycle = c["boundary"][0];
  ASSERT_EQ(cycle.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(cycle[i]["segment"], i);
    EXPECT_EQ(cycle[i]["type"], "line");
    EXPECT_EQ(cycle[i]["to"], cycle[(i + 1) % 4]["from"]);  // closed
  }
  expect_point(cycle[0]["from"], 0, 0);
  expect_point(cycle[0]["to"], 2, 0);
  EXPECT_EQ(j["realizable_pieces"].size(), 4u);
}

TEST(SliceJson, ArcsCarryCenterRadiusAndSignedSweep) {
  const Pair pair = load_pair_text(kPairJson);
  const json j = json::parse(slice_to_json(pair, half_disc_slice()));
  const json& arc_piece = j["free_components"][0]["boundary"][0][1];
  EXPECT_EQ(arc_piece["type"], "arc");
  expect_point(arc_piece["center"], 0, 0);
  EXPECT_DOUBLE_EQ(arc_piece["radius"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(arc_piece["sweep"].get<double>(), kPi);
  expect_point(arc_piece["from"], 1, 0);
  // The contact segment runs the other way round: clockwise, negative sweep.
  const json& seg = j["contact_segments"][1];
  EXPECT_EQ(seg["type"], "arc");
  EXPECT_EQ(seg["kind"], "arc_arc");
  EXPECT_DOUBLE_EQ(seg["sweep"].get<double>(), -kPi);
  EXPECT_DOUBLE_EQ(seg["radius"].get<double>(), 1.0);
}

TEST(SliceJson, UnboundedAreaIsNullAndPointsArePoints) {
  const Pair pair = load_pair_text(kPairJson);
  const json j = json::parse(slice_to_json(pair, unbounded_slice()));
  const json& c = j["free_components"][0];
  EXPECT_EQ(c["bounded"], false);
  EXPECT_TRUE(c["area"].is_null());
  const json& point_seg = j["contact_segments"][4];
  EXPECT_EQ(point_seg["type"], "point");
  EXPECT_EQ(point_seg["from"], point_seg["to"]);
  EXPECT_EQ(j["contact_segments"][5]["type"], "arc");
  EXPECT_DOUBLE_EQ(j["contact_segments"][5]["sweep"].get<double>(), kTwoPi);
  EXPECT_EQ(j["contact_segments"][5]["realizable"], false);
  ASSERT_EQ(j["degenerate_contacts"].size(), 1u);
  const json& d = j["degenerate_contacts"][0];
  EXPECT_EQ(d["type"], "point");
  EXPECT_EQ(d["segments"], json::array({4}));
  expect_point(d["from"], 3, 3);
}

// A bounded component whose area could not be computed gets null too, never "NaN".
TEST(SliceJson, NanAreaOfBoundedComponentIsNull) {
  const Pair pair = load_pair_text(kPairJson);
  Slice s = square_slice();
  s.free_components[0].area = std::numeric_limits<double>::quiet_NaN();
  const std::string text = slice_to_json(pair, s);
  EXPECT_EQ(text.find("NaN"), std::string::npos);
  EXPECT_TRUE(json::parse(text)["free_components"][0]["area"].is_null());
}

TEST(SliceJson, ContactGraphAndCounts) {
  const Pair pair = load_pair_text(kPairJson);
  const json j = json::parse(slice_to_json(pair, square_slice()));
  EXPECT_EQ(j["contact_graph"]["nodes"], json::array({0, 1, 2, 3}));
  const json& e = j["contact_graph"]["edges"];
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e[0]["a"], 0);
  EXPECT_EQ(e[0]["b"], 1);
  expect_point(e[0]["at"], 2, 0);
  const json& n = j["counts"];
  EXPECT_EQ(n["contact_segments"], 5);
  EXPECT_EQ(n["realizable_segments"], 4);
  EXPECT_EQ(n["free_components"], 1);
  EXPECT_EQ(n["bounded_free_components"], 1);
  EXPECT_EQ(n["degenerate_contacts"], 0);
  EXPECT_EQ(n["graph_edges"], 4);
}

// Pieces name only the lowest of coincident segments; a graph node is realizable anyway.
TEST(SliceJson, GraphNodesCountAsRealizable) {
  const Pair pair = load_pair_text(kPairJson);
  Slice s = square_slice();
  s.contact_graph.nodes.push_back(4);
  const json j = json::parse(slice_to_json(pair, s));
  EXPECT_EQ(j["contact_segments"][4]["realizable"], true);
  EXPECT_EQ(j["counts"]["realizable_segments"], 5);
}

TEST(SliceJson, NumbersRoundTrip) {
  const Pair pair = load_pair_text(kPairJson);
  Slice s = square_slice();
  s.theta = 0.1 + 0.2;  // not short in decimal
  s.free_components[0].sample = {1.0 / 3.0, 2.0 / 3.0};
  const json j = json::parse(slice_to_json(pair, s));
  EXPECT_EQ(j["theta"].get<double>(), 0.1 + 0.2);
  EXPECT_EQ(j["free_components"][0]["sample"][0].get<double>(), 1.0 / 3.0);
}

// ---- SVG -----------------------------------------------------------------------------

int count_of(const std::string& s, const std::string& needle) {
  int n = 0;
  for (auto pos = s.find(needle); pos != std::string::npos; pos = s.find(needle, pos + 1)) ++n;
  return n;
}

struct SvgArc {
  Vec2 from, to;
  double r = 0.0;
  bool large = false, sweep = false;
};

// Every "M x,y A r r 0 large sweep x,y" (a path that starts with an arc).
std::vector<SvgArc> leading_arcs(const std::string& svg) {
  static const std::regex re(
      R"(M([-\d.]+),([-\d.]+)A([-\d.]+) ([-\d.]+) 0 ([01]) ([01]) ([-\d.]+),([-\d.]+))");
  std::vector<SvgArc> out;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), re); it != std::sregex_iterator();
       ++it) {
    const std::smatch& m = *it;
    SvgArc a;
    a.from = {std::stod(m[1]), std::stod(m[2])};
    a.r = std::stod(m[3]);
    a.large = m[5] == "1";
    a.sweep = m[6] == "1";
    a.to = {std::stod(m[7]), std::stod(m[8])};
    out.push_back(a);
  }
  return out;
}

// The midpoint of an SVG arc, by the SVG specification's endpoint-to-centre conversion
// (appendix F.6.5): what a browser draws, independent of our own conventions.
Vec2 svg_arc_midpoint(const SvgArc& a) {
  const Vec2 h = 0.5 * (a.from - a.to);
  const double d2 = length_squared(h);
  const double k = std::sqrt(std::max(0.0, (a.r * a.r - d2) / d2));
  const double sign = a.large != a.sweep ? 1.0 : -1.0;
  const Vec2 cp = sign * k * Vec2{h.y, -h.x};
  const Vec2 center = cp + 0.5 * (a.from + a.to);
  const double t1 = std::atan2(h.y - cp.y, h.x - cp.x);
  double dt = std::atan2(-h.y - cp.y, -h.x - cp.x) - t1;
  if (a.sweep && dt < 0.0) dt += kTwoPi;
  if (!a.sweep && dt > 0.0) dt -= kTwoPi;
  return center + a.r * unit_vector(t1 + 0.5 * dt);
}

TEST(SliceSvg, IsAnSvgWithTitleLegendAndScaleBar) {
  const Pair pair = load_pair_text(kPairJson);
  const std::string svg = render_slice_svg(pair, square_slice());
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("theta = 0.5"), std::string::npos);
  EXPECT_NE(svg.find("vertex_segment"), std::string::npos);
  EXPECT_NE(svg.find("segment_vertex"), std::string::npos);
  EXPECT_EQ(svg.find("arc_arc"), std::string::npos);  // only kinds present are listed
  EXPECT_NE(svg.find("blocked space"), std::string::npos);
  EXPECT_NE(svg.find("free space"), std::string::npos);
  EXPECT_NE(svg.find(" in</text>"), std::string::npos);  // scale bar in the pair's units
  EXPECT_EQ(count_of(svg, "<svg"), 1);
}

// Bounded: grey background, then the component's cycles filled white with even-odd.
TEST(SliceSvg, BoundedComponentIsWhiteOnGrey) {
  const Pair pair = load_pair_text(kPairJson);
  const std::string svg = render_slice_svg(pair, square_slice());
  const auto grey = svg.find("fill=\"#c8c8c8\"");
  const auto white_path = svg.find("fill=\"#ffffff\" fill-rule=\"evenodd\"");
  ASSERT_NE(grey, std::string::npos);
  ASSERT_NE(white_path, std::string::npos);
  EXPECT_LT(grey, white_path);
}

// Unbounded: the view turns white and the islands the cycles enclose grey again.
TEST(SliceSvg, UnboundedComponentIsGreyIslandsOnWhite) {
  const Pair pair = load_pair_text(kPairJson);
  const std::string svg = render_slice_svg(pair, unbounded_slice());
  const auto grey_island = svg.find("fill=\"#c8c8c8\" fill-rule=\"evenodd\"");
  ASSERT_NE(grey_island, std::string::npos);
  const auto white_view = svg.rfind("fill=\"#ffffff\"/>", grey_island);
  EXPECT_NE(white_view, std::string::npos);
  EXPECT_NE(svg.find("degenerate contact"), std::string::npos);
  EXPECT_NE(svg.find("<circle"), std::string::npos);  // the perfect fit as a dot
}

// The world arc over the top of the half disc must be drawn over the top: y flips, so a
// counterclockwise arc needs sweep-flag 0.
TEST(SliceSvg, ArcsBulgeTheRightWay) {
  const Pair pair = load_pair_text(kPairJson);
  const std::string svg = render_slice_svg(pair, half_disc_slice());
  const std::vector<SvgArc> arcs = leading_arcs(svg);
  ASSERT_FALSE(arcs.empty());
  for (const SvgArc& a : arcs) {
    EXPECT_FALSE(a.sweep);
    EXPECT_GT(a.from.x, a.to.x);  // from (1, 0) to (-1, 0): right to left
    const Vec2 mid = svg_arc_midpoint(a);
    EXPECT_LT(mid.y, a.from.y - 0.9 * a.r);  // above the chord (smaller pixel y), by ~r
  }
  // The clockwise contact segment, when drawn, turns the other way and bulges the same.
  SlicePictureOptions all;
  all.show_all_segments = true;
  Slice s = half_disc_slice();
  s.realizable.clear();
  s.contact_graph.nodes.clear();
  const std::vector<SvgArc> cw = leading_arcs(render_slice_svg(pair, s, all));
  ASSERT_FALSE(cw.empty());
  for (const SvgArc& a : cw) {
    EXPECT_TRUE(a.sweep);
    EXPECT_LT(svg_arc_midpoint(a).y, a.from.y - 0.9 * a.r);
  }
}

// A full circle cannot be one SVG arc (equal endpoints draw nothing): two halves.
TEST(SliceSvg, FullCircleIsTwoHalfArcs) {
  const Pair pair = load_pair_text(kPairJson);
  SlicePictureOptions all;
  all.show_all_segments = true;
  const std::string svg = render_slice_svg(pair, unbounded_slice(), all);
  static const std::regex two_halves(R"(M[-\d.,]+A[^"]*A[^"]*")");
  EXPECT_TRUE(std::regex_search(svg, two_halves));
}

TEST(SliceSvg, MarkAndCustomTitle) {
  const Pair pair = load_pair_text(kPairJson);
  SlicePictureOptions o;
  o.mark = Vec2{1.5, 0.25};
  o.title = "Figure <1>";
  const std::string svg = render_slice_svg(pair, square_slice(), o);
  EXPECT_NE(svg.find("(1.5, 0.25)"), std::string::npos);
  EXPECT_NE(svg.find("#e4002b"), std::string::npos);
  EXPECT_NE(svg.find("Figure &lt;1&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("theta ="), std::string::npos);
}

TEST(SliceSvg, EmptySliceStillDraws) {
  const Pair pair = load_pair_text(kPairJson);
  Slice s;
  const std::string svg = render_slice_svg(pair, s);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

// ---- The command ---------------------------------------------------------------------

class CliSlice : public testkit::ScratchDirTest {
 protected:
  CliSlice() : ScratchDirTest("cslice_cli_slice") {}

  RunResult run(const std::string& args) { return run_cli("slice " + args, dir_); }
  static std::string example(const std::string& name) {
    return quoted(testkit::example_path(name));
  }
  std::string path(const std::string& name) const { return quoted((dir_ / name).string()); }
  bool exists(const std::string& name) const { return fs::exists(dir_ / name); }
};

TEST_F(CliSlice, WritesJsonAndSvg) {
  const RunResult r = run(example("fastener") + " --theta 0 --json " + path("s.json") + " --svg " +
                          path("s.svg") + " --mark 0,-3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "");
  const json j = json::parse(read_file(dir_ / "s.json"));
  EXPECT_EQ(j["format"], "cslice-slice");
  EXPECT_EQ(j["pair"], "fastener");
  const json& n = j["counts"];
  EXPECT_EQ(n["contact_segments"], j["contact_segments"].size());
  EXPECT_EQ(n["free_components"], j["free_components"].size());
  EXPECT_EQ(n["degenerate_contacts"], j["degenerate_contacts"].size());
  EXPECT_EQ(n["graph_edges"], j["contact_graph"]["edges"].size());
  int realizable = 0;
  for (const json& s : j["contact_segments"]) realizable += s["realizable"].get<bool>() ? 1 : 0;
  EXPECT_EQ(n["realizable_segments"], realizable);
  // Paper section 2.4: the horizontal pin has two free components, inside and outside.
  EXPECT_EQ(n["free_components"], 2);
  EXPECT_EQ(n["bounded_free_components"], 1);
  const std::string svg = read_file(dir_ / "s.svg");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("(0, -3)"), std::string::npos);
  for (const auto& e : fs::directory_iterator(dir_))  // no temporaries left behind
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}

TEST_F(CliSlice, JsonToStandardOutput) {
  const RunResult r = run(example("disc-in-box") + " --theta 0 --json - --svg " + path("s.svg"));
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["counts"]["free_components"], 1);
  EXPECT_DOUBLE_EQ(j["free_components"][0]["area"].get<double>(), 16.0);
  EXPECT_TRUE(exists("s.svg"));
  EXPECT_EQ(run(example("disc-in-box") + " --theta 0 --json - --svg -").status, 2);
}

TEST_F(CliSlice, SummaryWithoutOutputs) {
  const RunResult r = run(example("fastener") + " --theta 1.5708 --mark=0,3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("theta"), std::string::npos);
  EXPECT_NE(r.out.find("free components"), std::string::npos);
  EXPECT_NE(r.out.find("component 0: unbounded"), std::string::npos);
  EXPECT_NE(r.out.find("mark (0, 3)"), std::string::npos);
}

TEST_F(CliSlice, BadThetaWritesNothing) {
  for (const char* theta : {"nan", "inf", "abc", "1e999"}) {
    const RunResult r = run(example("knee") + " --theta " + theta + " --json " + path("s.json") +
                            " --svg " + path("s.svg"));
    EXPECT_EQ(r.status, 2) << theta << ": " << r.err;
    EXPECT_EQ(r.out, "") << theta;
    EXPECT_FALSE(exists("s.json")) << theta;
    EXPECT_FALSE(exists("s.svg")) << theta;
  }
}

TEST_F(CliSlice, BadInputsWriteNothing) {
  const std::string outputs = " --json " + path("s.json") + " --svg " + path("s.svg");
  const std::vector<std::string> cases = {
      path("missing.json") + " --theta 0" + outputs,
      example("knee") + " --theta 0 --mark 1" + outputs,
      example("knee") + outputs,  // no --theta
      // The SVG cannot be written: the JSON must not be left behind either.
      example("knee") + " --theta 0 --json " + path("s.json") + " --svg " +
          path("no-such-dir/s.svg")};
  for (const std::string& args : cases) {
    const RunResult r = run(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
    EXPECT_FALSE(exists("s.json")) << args;
    EXPECT_FALSE(exists("s.svg")) << args;
  }
}

}  // namespace
}  // namespace cslice
