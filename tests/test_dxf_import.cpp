// Pair files from DXF drawings (src/parts/dxf_reader.cpp, dxf_loops.cpp): what each entity
// draws, loops joined from loose pieces, the paper's examples drawn and read back, errors that
// name the entity, and mutated files.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "cslice/classify.hpp"
#include "cslice/dxf.hpp"
#include "cslice/slice.hpp"
#include "support/cli_run.hpp"
#include "support/examples.hpp"
#include "support/moved_examples.hpp"
#include "support/mutations.hpp"
#include "support/random_polygons.hpp"

using namespace cslice;

namespace {

struct V {
  double x, y, bulge = 0.0;
};

// A DXF drawing written group by group, as a CAD program saves one.
class Drawing {
 public:
  explicit Drawing(int insunits = 4) {
    add(0, "SECTION");
    add(2, "HEADER");
    add(9, "$INSUNITS");
    add(70, std::to_string(insunits));
    add(0, "ENDSEC");
    add(0, "SECTION");
    add(2, "ENTITIES");
  }
  Drawing& lwpolyline(const std::string& layer, const std::vector<V>& vertices, bool closed = true,
                      bool mirrored = false) {
    add(0, "LWPOLYLINE");
    add(8, layer);
    add(90, std::to_string(vertices.size()));
    add(70, closed ? "1" : "0");
    for (const V& v : vertices) {
      add(10, num(v.x));
      add(20, num(v.y));
      if (v.bulge != 0.0) add(42, num(v.bulge));
    }
    if (mirrored) extrusion_down();
    return *this;
  }
  Drawing& line(const std::string& layer, V a, V b) {
    add(0, "LINE");
    add(8, layer);
    add(10, num(a.x));
    add(20, num(a.y));
    add(30, "0.0");
    add(11, num(b.x));
    add(21, num(b.y));
    add(31, "0.0");
    return *this;
  }
  // Counterclockwise from a0 to a1 degrees (in the entity's own frame when mirrored).
  Drawing& arc(const std::string& layer, V c, double r, double a0, double a1,
               bool mirrored = false) {
    add(0, "ARC");
    add(8, layer);
    add(10, num(c.x));
    add(20, num(c.y));
    add(40, num(r));
    add(50, num(a0));
    add(51, num(a1));
    if (mirrored) extrusion_down();
    return *this;
  }
  Drawing& circle(const std::string& layer, V c, double r) {
    add(0, "CIRCLE");
    add(8, layer);
    add(10, num(c.x));
    add(20, num(c.y));
    add(40, num(r));
    return *this;
  }
  Drawing& entity(const std::string& type, const std::string& layer) {
    add(0, type);
    add(8, layer);
    return *this;
  }
  Drawing& add(int code, const std::string& value) {
    text_ += "  " + std::to_string(code) + "\n" + value + "\n";
    return *this;
  }
  std::string text() const { return text_ + "  0\nENDSEC\n  0\nEOF\n"; }

 private:
  static std::string num(double v) { return nlohmann::json(v).dump(); }
  void extrusion_down() {
    add(210, "0.0");
    add(220, "0.0");
    add(230, "-1.0");
  }
  std::string text_;
};

DrawingPairResult import(const std::string& text, DrawingImportOptions options = {}) {
  return import_dxf_pair(text, "drawing.dxf", options);
}

Pair import_ok(const std::string& text, DrawingImportOptions options = {}) {
  DrawingPairResult r = import(text, options);
  if (!r.ok()) ADD_FAILURE() << r.error->message();
  return r.ok() ? *r.pair : Pair{};
}

// Why the drawing is refused, or nothing when it is read (for the mutation tests).
std::optional<std::string> refusal(const std::string& text) {
  const DrawingPairResult r = import(text);
  if (r.ok()) return std::nullopt;
  return r.error->message();
}

std::string import_error(const std::string& text, DrawingImportOptions options = {}) {
  const DrawingPairResult r = import(text, options);
  EXPECT_FALSE(r.ok()) << "accepted:\n" << text;
  return r.ok() ? "" : r.error->message();
}

// The entities of a Drawing, without its sections.
std::string body(Drawing& d) {
  const std::string text = d.text();
  const size_t from = text.find("ENTITIES\n") + 9, to = text.rfind("  0\nENDSEC");
  return text.substr(from, to - from);
}

// A number as text that reads back as the same double.
std::string exact(double v) {
  return nlohmann::json(v).dump();
}

// A 4 x 2 block for the fixed part, the same in every test that needs one.
Drawing& with_block(Drawing& d) {
  return d.lwpolyline("fixed", {{10, 0}, {14, 0}, {14, 2}, {10, 2}});
}

}  // namespace

// A closed polyline with a bulge is the loop it draws: a 2 x 2 square whose top edge is a
// half circle bulging out (bulge -1 travelling from (1, 1) to (-1, 1) counterclockwise round
// the square: the arc turns clockwise, out of the square).
TEST(DxfImport, PolylineWithBulgesIsTheLoopItDraws) {
  Drawing d;
  d.lwpolyline("moving", {{-1, -1}, {1, -1}, {1, 1, 1.0}, {-1, 1}});
  const std::string text = with_block(d).text();
  const Pair pair = import_ok(text);
  EXPECT_EQ(pair.moving.segment_count(), 3);
  EXPECT_EQ(pair.moving.arc_count(), 1);
  EXPECT_NEAR(pair.moving.area, 4 + kPi / 2, 1e-12);
  EXPECT_NEAR(pair.fixed.area, 8, 1e-12);
  EXPECT_EQ(pair.units, "mm");
  // Saved by an editor that starts UTF-8 text with a byte order mark: the same drawing.
  EXPECT_NEAR(import_ok("\xEF\xBB\xBF" + text).moving.area, 4 + kPi / 2, 1e-12);
  // A closed polyline whose last vertex repeats its first has no edge of no length.
  Drawing repeated;
  repeated.lwpolyline("moving", {{-1, -1}, {1, -1}, {1, 1, 1.0}, {-1, 1}, {-1, -1}});
  const Pair again = import_ok(with_block(repeated).text());
  EXPECT_EQ(again.moving.feature_count(), 8);
  EXPECT_NEAR(again.moving.area, 4 + kPi / 2, 1e-12);
}

// The same outline as loose lines and an arc, in any order and direction, is the same loop.
TEST(DxfImport, LooseLinesAndArcsJoinInAnyOrderAndDirection) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    // The square above: three lines and the half circle of centre (0, 1) from 0 to 180 deg.
    std::vector<std::pair<V, V>> lines = {
        {{-1, 1}, {-1, -1}}, {{-1, -1}, {1, -1}}, {{1, -1}, {1, 1}}};
    std::shuffle(lines.begin(), lines.end(), rng);
    Drawing d;
    const int arc_at = static_cast<int>(rng() % 4);
    for (int k = 0; k < 4; ++k) {
      if (k == arc_at) d.arc("moving", {0, 1}, 1.0, 0.0, 180.0);
      if (k == 3) break;
      const auto [a, b] = lines[k];
      if (rng() % 2)
        d.line("moving", a, b);
      else
        d.line("moving", b, a);
    }
    const Pair pair = import_ok(with_block(d).text());
    EXPECT_EQ(pair.moving.loops.size(), 1u);
    EXPECT_EQ(pair.moving.feature_count(), 8);
    EXPECT_NEAR(pair.moving.area, 4 + kPi / 2, 1e-12) << trial;
  }
}

// An arc stored mirrored (extrusion along -z, as CAD programs save a mirrored copy) lies at
// its mirror image: centre (-1, 0) in its own frame is (1, 0) in the drawing, and its
// counterclockwise sweep there turns clockwise.
TEST(DxfImport, MirroredArcLiesWhereItIsDrawn) {
  Drawing direct, mirrored;
  // A half disc right of x = 1: the diameter from (1, -1) to (1, 1), the arc round x = 2.
  direct.line("moving", {1, 1}, {1, -1}).arc("moving", {1, 0}, 1.0, -90.0, 90.0);
  mirrored.line("moving", {1, 1}, {1, -1}).arc("moving", {-1, 0}, 1.0, 90.0, 270.0, true);
  const Pair a = import_ok(with_block(direct).text()), b = import_ok(with_block(mirrored).text());
  EXPECT_NEAR(a.moving.area, kPi / 2, 1e-12);
  EXPECT_NEAR(b.moving.area, kPi / 2, 1e-12);
  EXPECT_NEAR(b.moving.box.hi.x, 2.0, 1e-12);
  EXPECT_NEAR(b.moving.box.lo.x, 1.0, 1e-12);
}

// Curves that are not lines or arcs become arcs within a hundredth of the tolerance: an
// ellipse; a circle drawn as a rational quadratic spline (its arcs exact); a cubic Bezier
// closed by a line, against its area from Bernstein polynomials.
TEST(DxfImport, SplinesAndEllipsesBecomeArcs) {
  Drawing frame;
  frame.lwpolyline("fixed", {{-20, -20}, {20, -20}, {20, 20}, {-20, 20}});
  const std::string frame_text = body(frame);
  const std::string head = "  0\nSECTION\n  2\nENTITIES\n", tail = "  0\nENDSEC\n  0\nEOF\n";
  // An ellipse of semi-axes 2 and 1, its major axis along (1, 1).
  Drawing ellipse;
  ellipse.entity("ELLIPSE", "moving").add(10, "0").add(20, "0").add(11, exact(std::sqrt(2.0)));
  ellipse.add(21, exact(std::sqrt(2.0))).add(40, "0.5");
  Pair pair = import_ok(head + body(ellipse) + frame_text + tail);
  EXPECT_NEAR(pair.moving.area, 2 * kPi, 1e-3);
  EXPECT_NEAR(pair.moving.box.hi.x, std::sqrt(2.5),
              1e-4);  // max of 2 cos t / sqrt 2 - sin t / sqrt 2
  EXPECT_LT(pair.moving.arc_count(), 200);
  // The unit circle as a rational quadratic NURBS of 9 control points.
  Drawing circle;
  circle.entity("SPLINE", "moving").add(70, "1").add(71, "2");
  for (double k : {0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0})
    circle.add(40, exact(k));
  const double h = std::sqrt(0.5);
  for (double w : {1.0, h, 1.0, h, 1.0, h, 1.0, h, 1.0}) circle.add(41, exact(w));
  for (const V& p :
       std::vector<V>{{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}})
    circle.add(10, exact(p.x)).add(20, exact(p.y));
  pair = import_ok(head + body(circle) + frame_text + tail);
  EXPECT_NEAR(pair.moving.area, kPi, 1e-9);
  // Four pieces per knot span, each exact, all of one circle: the circle.
  ASSERT_EQ(pair.moving.loops.size(), 1u);
  EXPECT_TRUE(pair.moving.loops[0].is_circle());
  // A cubic Bezier from (0, 0) round to (4, 0), closed by the line back.
  const V c[4] = {{0, 0}, {0, 4}, {4, 4}, {4, 0}};
  Drawing bezier;
  bezier.entity("SPLINE", "moving").add(71, "3");
  for (double k : {0, 0, 0, 0, 1, 1, 1, 1}) bezier.add(40, exact(k));
  for (const V& p : c) bezier.add(10, exact(p.x)).add(20, exact(p.y));
  bezier.line("moving", {4, 0}, {0, 0});
  pair = import_ok(head + body(bezier) + frame_text + tail);
  testkit::LoopVertices samples;
  for (int i = 0; i <= 20000; ++i) {
    const double t = i / 20000.0, s = 1 - t;
    const double b[4] = {s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t};
    samples.push_back({b[0] * c[0].x + b[1] * c[1].x + b[2] * c[2].x + b[3] * c[3].x,
                       b[0] * c[0].y + b[1] * c[1].y + b[2] * c[2].y + b[3] * c[3].y, 0.0});
  }
  EXPECT_NEAR(pair.moving.area, std::fabs(testkit::loop_area(samples)), 1e-4);
  EXPECT_NEAR(pair.moving.box.hi.y, 3.0, 1e-4);  // the curve's top, at t = 1/2
}

// Old-style POLYLINE with VERTEX entities, and a CIRCLE.
TEST(DxfImport, PolylineVerticesAndCircles) {
  Drawing d;
  d.entity("POLYLINE", "moving").add(66, "1").add(70, "1");
  for (const V& v : std::vector<V>{{-1, -1}, {1, -1, 0.5}, {1, 1}, {-1, 1}}) {
    d.entity("VERTEX", "moving").add(10, std::to_string(v.x)).add(20, std::to_string(v.y));
    if (v.bulge != 0.0) d.add(42, "0.5");
  }
  d.entity("SEQEND", "moving");
  d.circle("fixed", {10, 0}, 2.0);
  const Pair pair = import_ok(d.text());
  EXPECT_EQ(pair.moving.arc_count(), 1);
  EXPECT_EQ(pair.moving.segment_count(), 3);
  ASSERT_EQ(pair.fixed.loops.size(), 1u);
  EXPECT_TRUE(pair.fixed.loops[0].is_circle());
  EXPECT_NEAR(pair.fixed.area, 4 * kPi, 1e-12);
}

// The paper's four examples drawn as DXF (each loop a polyline, circles as circles, the moving
// part moved by `shift` and brought back by --origin) read back as the same pairs: the same
// features, areas and tolerance, and the same placements at random configurations.
TEST(DxfImport, PaperExamplesDrawnAndReadBackAreTheSamePairs) {
  for (const char* name : {"knee", "cam", "fixture", "fastener"}) {
    const Pair original = testkit::load_example(name);
    const nlohmann::json file =
        nlohmann::json::parse(testkit::read_file(testkit::example_path(name)));
    const V shift{3.0, -2.0};
    Drawing d;
    for (const char* part : {"moving", "fixed"})
      for (const nlohmann::json& loop : file[part]["loops"]) {
        const double dx = std::string(part) == "moving" ? shift.x : 0.0;
        const double dy = std::string(part) == "moving" ? shift.y : 0.0;
        if (loop.is_object()) {
          d.circle(part,
                   {loop["circle"][0].get<double>() + dx, loop["circle"][1].get<double>() + dy},
                   loop["circle"][2].get<double>());
          continue;
        }
        std::vector<V> vertices;
        for (const nlohmann::json& v : loop)
          vertices.push_back({v[0].get<double>() + dx, v[1].get<double>() + dy,
                              v.size() > 2 ? v[2].get<double>() : 0.0});
        d.lwpolyline(part, vertices);
      }
    DrawingImportOptions options;
    options.moving_origin = {shift.x, shift.y};
    options.fixed_enclosure = file["fixed"].value("enclosure", false);
    options.tolerance = original.requested_tolerance;
    const Pair pair = import_ok(d.text(), options);
    testkit::expect_same_pair(pair, original, name, 11);
  }
}

// Each reason names the file, the part, the layer and the entity with its line.
TEST(DxfImport, ErrorsNameTheLayerTheEntityAndItsLine) {
  const auto expect_has = [](const std::string& message, const std::vector<std::string>& parts) {
    for (const std::string& p : parts)
      EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
  };
  Drawing open;
  open.line("moving", {0, 0}, {1, 0}).line("moving", {1, 0}, {1, 1});
  expect_has(
      import_error(with_block(open).text()),
      {"drawing.dxf", "part 'moving'", "layer 'moving'", "the outline is open", "LINE at line"});
  Drawing three;
  three.line("moving", {0, 0}, {1, 0})
      .line("moving", {1, 0}, {0, 1})
      .line("moving", {0, 1}, {0, 0});
  three.line("moving", {0, 0}, {-1, -1});
  expect_has(import_error(with_block(three).text()),
             {"three outline ends meet at (0, 0)", "LINE at line"});
  Drawing missing;
  missing.lwpolyline("PART", {{0, 0}, {1, 0}, {0, 1}});
  expect_has(import_error(with_block(missing).text()), {"no outline", "layer 'moving'", "'PART'"});
  Drawing bad_number;
  bad_number.lwpolyline("moving", {{0, 0}, {1, 0}, {0, 1}}).add(10, "1.5.2");
  expect_has(import_error(with_block(bad_number).text()),
             {"'1.5.2' is not a number", "LWPOLYLINE"});
  Drawing far_angle;
  far_angle.line("moving", {1, 1}, {1, -1}).arc("moving", {1, 0}, 1.0, 1e308, 90.0);
  expect_has(import_error(with_block(far_angle).text()), {"ARC at line", "beyond the range"});
  Drawing huge_flags;
  huge_flags.entity("LWPOLYLINE", "moving").add(70, "1e300").add(10, "0").add(20, "0");
  huge_flags.add(10, "1").add(20, "0").add(10, "0").add(20, "1");
  expect_has(import_error(with_block(huge_flags).text()), {"flags (group code 70) 1e+300"});
  Drawing spline;
  spline.entity("SPLINE", "moving").add(71, "3").add(40, "0").add(40, "1");
  spline.add(10, "0").add(20, "0").add(10, "1").add(20, "0");
  expect_has(import_error(with_block(spline).text()), {"SPLINE at line", "too few for degree 3"});
  Drawing tilted;
  tilted.lwpolyline("moving", {{0, 0}, {1, 0}, {0, 1}}).add(210, "0.6").add(230, "0.8");
  expect_has(import_error(with_block(tilted).text()), {"out of the XY plane"});
  // A loop the pair reader rejects names the entity it came from.
  Drawing crossing;
  crossing.lwpolyline("moving", {{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  expect_has(import_error(with_block(crossing).text()),
             {"part 'moving', loop 0",
              "(loop 0 is the LWPOLYLINE at line 15; vertex 0 starts the edge drawn by the "
              "LWPOLYLINE at line 15)"});
  DrawingImportOptions one_layer;
  one_layer.fixed_layer = "moving";
  expect_has(import_error(with_block(open).text(), one_layer), {"both on layer 'moving'"});
  expect_has(import_error(""), {"empty"});
  expect_has(import_error(std::string("AutoCAD Binary DXF\r\n\x1a\0", 22)), {"holds no groups"});
  expect_has(import_error("0\nSECTION\nxyz\n"), {"line 3: group code 'xyz' is not an integer"});
}

// Mutated drawings are read or refused with a message; none crashes or hangs.
TEST(DxfImport, MutatedDrawingsAreReadOrRefusedWithAMessage) {
  Drawing d;
  d.lwpolyline("moving", {{-1, -1}, {1, -1, 0.3}, {1, 1}, {-1, 1}});
  d.line("fixed", {5, 0}, {9, 0}).line("fixed", {9, 0}, {9, 3}).arc("fixed", {7, 3}, 2.0, 0, 180);
  d.line("fixed", {5, 3}, {5, 0}).circle("fixed", {20, 0}, 1.0);
  const std::string base = d.text();
  ASSERT_TRUE(import(base).ok());
  testkit::expect_mutants_read_or_refused(base, 20000, refusal);
}

// A drawing whose BLOCKS section defines `blocks` (name, base point, the entities' text as a
// Drawing writes them), then whose entities are `entities`.
std::string with_blocks(const std::vector<std::tuple<std::string, V, std::string>>& blocks,
                        const std::string& entities) {
  std::string text = "  0\nSECTION\n  2\nBLOCKS\n";
  for (const auto& [name, base, body] : blocks)
    text += "  0\nBLOCK\n  8\n0\n  2\n" + name + "\n 10\n" + std::to_string(base.x) + "\n 20\n" +
            std::to_string(base.y) + "\n" + body + "  0\nENDBLK\n";
  return text + "  0\nENDSEC\n  0\nSECTION\n  2\nENTITIES\n" + entities + "  0\nENDSEC\n  0\nEOF\n";
}

std::string insert(const std::string& layer, const std::string& block, V at, double scale_x,
                   double scale_y, double degrees) {
  return "  0\nINSERT\n  8\n" + layer + "\n  2\n" + block + "\n 10\n" + std::to_string(at.x) +
         "\n 20\n" + std::to_string(at.y) + "\n 41\n" + std::to_string(scale_x) + "\n 42\n" +
         std::to_string(scale_y) + "\n 50\n" + std::to_string(degrees) + "\n";
}

// Blocks are drawn where INSERTs place them: moved from their base point, scaled, turned and
// moved; mirrored by a negative scale; their layer-0 entities on the INSERT's layer; blocks
// within blocks.
TEST(DxfImport, BlocksAreDrawnWhereTheyAreInserted) {
  Drawing peg, cap, frame;
  // A 1 x 1 square with a half-disc cap on its right side, base point at its lower left.
  peg.lwpolyline("0", {{0, 0}, {1, 0, 1.0}, {1, 1}, {0, 1}});
  frame.lwpolyline("fixed", {{-20, -20}, {20, -20}, {20, 20}, {-20, 20}});
  cap.add(0, "INSERT").add(8, "0").add(2, "PEG").add(10, "0").add(20, "0");
  const std::string blocks_text = body(peg), frame_text = body(frame);
  const double area = 1 + kPi / 8;
  // Doubled and turned a quarter: the square's corner at (3, 4), the cap on top.
  Pair pair = import_ok(with_blocks(
      {{"PEG", {0, 0}, blocks_text}, {"FRAME", {0, 0}, frame_text}},
      insert("moving", "peg", {3, 4}, 2, 2, 90) + insert("LAYOUT", "FRAME", {0, 0}, 1, 1, 0)));
  EXPECT_NEAR(pair.moving.area, 4 * area, 1e-12);
  EXPECT_NEAR(pair.moving.box.lo.x, 1.0, 1e-12);
  EXPECT_NEAR(pair.moving.box.hi.x, 3.0, 1e-12);
  EXPECT_NEAR(pair.moving.box.hi.y, 7.0, 1e-12);  // 4 + 2 + the cap's radius 1
  EXPECT_NEAR(pair.fixed.area, 1600, 1e-9);       // FRAME's entity keeps its own layer
  // Mirrored by a negative x scale: the cap on the left, the same area.
  pair = import_ok(with_blocks({{"PEG", {0, 0}, blocks_text}},
                               insert("moving", "PEG", {0, 0}, -1, 1, 0) + frame_text));
  EXPECT_NEAR(pair.moving.area, area, 1e-12);
  EXPECT_NEAR(pair.moving.box.lo.x, -1.5, 1e-12);
  // A block inserting the block, each moving it by its base point.
  pair = import_ok(with_blocks({{"PEG", {1, 1}, blocks_text}, {"CAP", {-5, 0}, body(cap)}},
                               insert("moving", "CAP", {0, 0}, 1, 1, 0) + frame_text));
  EXPECT_NEAR(pair.moving.area, area, 1e-12);
  EXPECT_NEAR(pair.moving.box.lo.x, 4.0, 1e-12);  // -1 for PEG's base, +5 for CAP's
  EXPECT_NEAR(pair.moving.box.lo.y, -1.0, 1e-12);
  // Scaled unevenly, 1 by 2: the cap is half an ellipse, followed by arcs; the area doubles.
  pair = import_ok(with_blocks({{"PEG", {0, 0}, blocks_text}},
                               insert("moving", "PEG", {0, 0}, 1, 2, 0) + frame_text));
  EXPECT_NEAR(pair.moving.area, 2 * area, 1e-4);
  EXPECT_NEAR(pair.moving.box.hi.x, 1.5, 1e-5);
  EXPECT_NEAR(pair.moving.box.hi.y, 2.0, 1e-12);
  EXPECT_GT(pair.moving.arc_count(), 1);
  // An array (MINSERT): 3 columns 4 apart, 2 rows 5 apart, turned a quarter: six pegs.
  pair = import_ok(with_blocks({{"PEG", {0, 0}, blocks_text}},
                               insert("moving", "PEG", {0, 0}, 1, 1, 90) +
                                   "  70\n3\n 71\n2\n 44\n4\n 45\n5\n" + frame_text));
  EXPECT_EQ(pair.moving.loops.size(), 6u);
  EXPECT_NEAR(pair.moving.area, 6 * area, 1e-9);
  EXPECT_NEAR(pair.moving.box.hi.y, 9.5, 1e-12);   // columns along the turned x axis: y
  EXPECT_NEAR(pair.moving.box.lo.x, -6.0, 1e-12);  // rows along the turned y axis: -x
  // Refused, and soon: an array giving a part more edges than a drawing may (250 x 250 pegs
  // of 4 edges), and copies with no spacing, which lie on each other (60 x 60 of them).
  const std::string huge = import_error(with_blocks(
      {{"PEG", {0, 0}, blocks_text}}, insert("moving", "PEG", {0, 0}, 1, 1, 0) +
                                          "  70\n250\n 71\n250\n 44\n2\n 45\n2\n" + frame_text));
  EXPECT_NE(huge.find("250000 outline edges, more than the 200000"), std::string::npos) << huge;
  const std::string piled = import_error(
      with_blocks({{"PEG", {0, 0}, blocks_text}},
                  insert("moving", "PEG", {0, 0}, 1, 1, 0) + "  70\n60\n 71\n60\n" + frame_text));
  EXPECT_NE(piled.find("touch or cross"), std::string::npos) << piled;
  // Refused: a scale of 0, a block inserting itself.
  const std::string flat = import_error(with_blocks(
      {{"PEG", {0, 0}, blocks_text}}, insert("moving", "PEG", {0, 0}, 1, 0, 0) + frame_text));
  EXPECT_NE(flat.find("a scale of 0"), std::string::npos) << flat;
  Drawing loop;
  loop.add(0, "INSERT").add(8, "0").add(2, "LOOP").add(10, "1").add(20, "0");
  const std::string nested = import_error(with_blocks(
      {{"LOOP", {0, 0}, body(loop)}}, insert("moving", "LOOP", {0, 0}, 1, 1, 0) + frame_text));
  EXPECT_NE(nested.find("nested deeper than 8"), std::string::npos) << nested;
}

// The drawing as a binary DXF file writes it: the sentinel, then each group's code in two
// bytes (one before R13, 255 then two for larger codes) and its value by the code's type
// (only the codes the Drawing helper writes: text, reals, 16- and 32-bit integers).
std::string binary(const std::string& ascii, bool wide_codes = true) {
  std::string out("AutoCAD Binary DXF\r\n\x1a\0", 22);
  std::istringstream in(ascii);
  std::string code_line, value;
  const auto bytes = [&](uint64_t v, int n) {
    for (int k = 0; k < n; ++k) out += static_cast<char>((v >> (8 * k)) & 0xFF);
  };
  while (std::getline(in, code_line) && std::getline(in, value)) {
    const int code = std::stoi(code_line);
    if (wide_codes) {
      bytes(static_cast<uint64_t>(code), 2);
    } else if (code < 255) {
      bytes(static_cast<uint64_t>(code), 1);
    } else {
      bytes(255, 1);
      bytes(static_cast<uint64_t>(code), 2);
    }
    if (code <= 9) {
      out += value;
      out += '\0';
    } else if (code >= 60 && code <= 79) {
      bytes(static_cast<uint64_t>(std::stoi(value)), 2);
    } else if (code >= 90 && code <= 99) {
      bytes(static_cast<uint64_t>(std::stol(value)), 4);
    } else {
      bytes(std::bit_cast<uint64_t>(std::stod(value)), 8);
    }
  }
  return out;
}

// A binary DXF file (as AutoCAD saves one on request) is read as its ASCII twin: the same pair
// file to the last bit, with two-byte group codes and one-byte ones; cut short or mutated,
// it is refused with a message.
TEST(DxfImport, BinaryFilesAreReadAsTheirAsciiTwins) {
  Drawing d;
  d.lwpolyline("moving", {{-1, -1}, {1, -1, 0.3}, {1, 1}, {-1, 1}});
  d.line("fixed", {5, 0}, {9, 0}).line("fixed", {9, 0}, {9, 3}).arc("fixed", {7, 3}, 2.0, 0, 180);
  d.line("fixed", {5, 3}, {5, 0}).circle("fixed", {20, 0}, 1.0 / 3.0);
  const std::string text = d.text();
  const DrawingPairResult ascii = import(text);
  ASSERT_TRUE(ascii.ok()) << ascii.error->message();
  for (bool wide : {true, false}) {
    const DrawingPairResult r = import(binary(text, wide));
    ASSERT_TRUE(r.ok()) << r.error->message();
    EXPECT_EQ(r.pair_json, ascii.pair_json) << (wide ? "two-byte codes" : "one-byte codes");
  }
  const std::string whole = binary(text);
  EXPECT_NE(import_error(whole.substr(0, whole.size() / 2)).find("cut short"), std::string::npos);
  testkit::expect_mutants_read_or_refused(whole, 5000, refusal);
}

class DxfImportCli : public testkit::ScratchDirTest {
 protected:
  DxfImportCli() : ScratchDirTest("cslice_dxf") {}
};

// `cslice import` writes a pair that `cslice info` reads; a bad drawing is exit 2 with the
// message and no file.
TEST_F(DxfImportCli, WritesAPairFileOrNothing) {
  Drawing d;
  d.lwpolyline("PIN", {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  d.lwpolyline("FRAME", {{-5, -5}, {5, -5}, {5, 5}, {-5, 5}});
  testkit::write_file(dir_ / "d.dxf", d.text());
  const std::string pair = testkit::quoted((dir_ / "pair.json").string());
  const testkit::RunResult ok =
      testkit::run_cli("import " + testkit::quoted((dir_ / "d.dxf").string()) +
                           " --moving PIN --fixed FRAME --enclosure --origin 0,0 -o " + pair,
                       dir_);
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(ok.out.find("moving part 1 loop, 8 features"), std::string::npos) << ok.out;
  const testkit::RunResult info = testkit::run_cli("info " + pair, dir_);
  EXPECT_EQ(info.status, 0) << info.err;
  EXPECT_NE(info.out.find("enclosure"), std::string::npos) << info.out;
  EXPECT_EQ(ok.err, "");
  // A moving part drawn away from the drawing's origin gets a note (and its pair).
  Drawing away;
  away.lwpolyline("PIN", {{99, 49}, {101, 49}, {101, 51}, {99, 51}});
  away.lwpolyline("FRAME", {{90, 40}, {110, 40}, {110, 60}, {90, 60}});
  testkit::write_file(dir_ / "away.dxf", away.text());
  const testkit::RunResult noted =
      testkit::run_cli("import " + testkit::quoted((dir_ / "away.dxf").string()) +
                           " --moving PIN --fixed FRAME --enclosure -o " + pair,
                       dir_);
  EXPECT_EQ(noted.status, 0) << noted.err;
  EXPECT_NE(noted.err.find("note: the moving part turns about the drawing point 0,0, outside its "
                           "box ((99, 49) to (101, 51))"),
            std::string::npos)
      << noted.err;
  const std::string other = testkit::quoted((dir_ / "other.json").string());
  const testkit::RunResult bad = testkit::run_cli(
      "import " + testkit::quoted((dir_ / "d.dxf").string()) + " --moving NONE -o " + other, dir_);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("no outline"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "other.json"));
  const testkit::RunResult join = testkit::run_cli(
      "import " + testkit::quoted((dir_ / "d.dxf").string()) + " --join-tolerance -1 -o " + other,
      dir_);
  EXPECT_EQ(join.status, 2);
  EXPECT_NE(join.err.find("--join-tolerance: expected a positive length"), std::string::npos)
      << join.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "other.json"));
}

// The bundled drawing (examples/drawings/gear-in-ring.dxf): a gear polyline in a ring of loose
// lines and arcs, with annotation on other layers.
TEST(DxfImport, BundledGearDrawing) {
  DrawingImportOptions options;
  options.moving_layer = "gear";  // layer names ignore case, as in CAD programs
  options.fixed_layer = "Ring";
  options.fixed_enclosure = true;
  const DrawingPairResult r = load_dxf_pair(
      std::string(CSLICE_SOURCE_DIR) + "/examples/drawings/gear-in-ring.dxf", options);
  ASSERT_TRUE(r.ok()) << r.error->message();
  EXPECT_EQ(r.pair->moving.loops.size(), 1u);
  EXPECT_EQ(r.pair->fixed.loops.size(), 1u);
  EXPECT_EQ(r.pair->moving.feature_count(), 64);
  EXPECT_EQ(r.pair->fixed.feature_count(), 128);
  EXPECT_EQ(classify(*r.pair, {0.0, 0.0, 0.0}), Placement::free);     // in the middle
  EXPECT_EQ(classify(*r.pair, {4.0, 0.0, 0.0}), Placement::blocked);  // tooth into tooth
}

namespace {

// The polylines and circles of each layer of a DXF text, read here independently of the
// importer: per layer, each loop's absolute area (arcs included).
std::map<std::string, std::vector<double>> loop_areas_by_layer(const std::string& text) {
  std::vector<std::pair<int, std::string>> groups;
  std::istringstream in(text);
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value))
    groups.emplace_back(std::stoi(code), value);
  std::map<std::string, std::vector<double>> out;
  testkit::LoopVertices loop;
  std::string layer, type;
  const auto finish = [&] {
    if (type == "SEQEND" && !loop.empty())
      out[layer].push_back(std::fabs(testkit::loop_area(loop)));
  };
  double cx = 0, cy = 0, r = 0;
  for (const auto& [c, v] : groups) {
    if (c == 0) {
      if (type == "CIRCLE") out[layer].push_back(kPi * r * r);
      if (v == "POLYLINE") loop.clear();
      type = v;
      finish();
      continue;
    }
    if (c == 8 && type == "POLYLINE") layer = v;
    if (c == 8 && type == "CIRCLE") layer = v;
    if (type == "VERTEX" && c == 10) loop.push_back({std::stod(v), 0.0, 0.0});
    if (type == "VERTEX" && c == 20) loop.back().y = std::stod(v);
    if (type == "VERTEX" && c == 42) loop.back().bulge = std::stod(v);
    if (type == "CIRCLE" && c == 10) cx = std::stod(v);
    if (type == "CIRCLE" && c == 20) cy = std::stod(v);
    if (type == "CIRCLE" && c == 40) r = std::stod(v);
  }
  (void)cx;
  (void)cy;
  return out;
}

}  // namespace

// A slice written as DXF: each bounded component's layer holds its outer cycle and its holes,
// whose areas give the component's area; perfect fits are points.
TEST(DxfExport, SliceBoundariesGiveTheComponentsAreas) {
  const std::pair<const char*, double> cases[] = {
      {"knee", 0.5},         {"cam", 0.3},         {"fixture", 0.0},        {"fastener", 0.0},
      {"fastener", kPi / 2}, {"disc-in-box", 0.0}, {"square-peg-hole", 0.3}};
  int bounded = 0;
  for (const auto& [name, theta] : cases) {
    const Pair pair = testkit::load_example(name);
    const Slice slice = compute_slice(pair, theta);
    const auto areas = loop_areas_by_layer(slice_to_dxf(pair, slice));
    for (const FreeComponent& c : slice.free_components) {
      const std::string layer = "FREE_" + std::to_string(c.id);
      ASSERT_TRUE(areas.count(layer)) << name << " " << layer;
      const std::vector<double>& loops = areas.at(layer);
      EXPECT_EQ(loops.size(), c.boundary.size()) << name << " " << layer;
      if (!c.bounded || loops.empty()) continue;
      ++bounded;
      double area = loops[0];
      for (size_t k = 1; k < loops.size(); ++k) area -= loops[k];
      EXPECT_NEAR(area, c.area, 1e-9 * pair.tol.size * pair.tol.size) << name << " " << layer;
    }
  }
  // A square peg in a round hole: the free region is bounded by arcs (a vertex on the hole's
  // circle); a disc in a round hole: a whole circle.
  for (const char* json :
       {R"({"moving": {"loops": [[[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]]},
            "fixed": {"enclosure": true, "loops": [{"circle": [0, 0, 1]}]}})",
        R"({"moving": {"loops": [{"circle": [0, 0, 0.5]}]},
            "fixed": {"enclosure": true, "loops": [{"circle": [0, 0, 1]}]}})"}) {
    const Pair pair = *parse_pair(json, "round hole").pair;
    const Slice slice = compute_slice(pair, 0.3);
    ASSERT_EQ(slice.free_components.size(), 1u);
    const auto areas = loop_areas_by_layer(slice_to_dxf(pair, slice));
    ASSERT_EQ(areas.at("FREE_0").size(), 1u);
    EXPECT_NEAR(areas.at("FREE_0")[0], slice.free_components[0].area, 1e-12);
    EXPECT_GT(slice.free_components[0].area, 0.0);
    ++bounded;
  }
  EXPECT_GE(bounded, 6);
  const Pair pin = testkit::load_example("pin-exact-fit");
  const std::string dxf = slice_to_dxf(pin, compute_slice(pin, 0.0));
  EXPECT_NE(dxf.find("POINT\n  8\nPERFECT_FIT"), std::string::npos) << dxf;
}

// Read back by the importer: the fastener's cavity (its bounded free component at theta = 0)
// as a part has the component's area.
TEST(DxfExport, TheImporterReadsASliceBack) {
  const Pair pair = testkit::load_example("fastener");
  const Slice slice = compute_slice(pair, 0.0);
  ASSERT_EQ(slice.free_components.size(), 2u);
  const FreeComponent& cavity =
      slice.free_components[0].bounded ? slice.free_components[0] : slice.free_components[1];
  const FreeComponent& outside =
      slice.free_components[0].bounded ? slice.free_components[1] : slice.free_components[0];
  DrawingImportOptions options;
  options.moving_layer = "FREE_" + std::to_string(cavity.id);
  options.fixed_layer = "FREE_" + std::to_string(outside.id);
  const DrawingPairResult r = import(slice_to_dxf(pair, slice), options);
  ASSERT_TRUE(r.ok()) << r.error->message();
  EXPECT_NEAR(r.pair->moving.area, cavity.area, 1e-9 * pair.tol.size * pair.tol.size);
}
