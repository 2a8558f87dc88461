// Pair files from SVG drawings (src/parts/svg_reader.cpp, svg_path.cpp): units and the y axis,
// what each element and path command draws, transforms and reuse, the paper's examples drawn
// and read back, errors that name the element and its line, and mutated files.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "cslice/classify.hpp"
#include "cslice/drawing.hpp"
#include "support/cli_run.hpp"
#include "support/examples.hpp"
#include "support/moved_examples.hpp"
#include "support/mutations.hpp"
#include "support/random_polygons.hpp"

using namespace cslice;

namespace {

// An SVG document of user units 1:1 (no size, no viewBox) around `body`.
std::string svg(const std::string& body, const std::string& root_attributes = "") {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
         "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"" +
         root_attributes + ">\n" + body + "\n</svg>\n";
}

// A 40 x 40 square for the fixed part, where a test is about the moving one.
const std::string kFrame =
    "<g id=\"fixed\"><rect x=\"-20\" y=\"-20\" width=\"40\" height=\"40\"/></g>";

std::string moving(const std::string& elements, const std::string& attributes = "") {
  return "<g id=\"moving\"" + attributes + ">" + elements + "</g>\n" + kFrame;
}

DrawingPairResult import(const std::string& text, DrawingImportOptions options = {}) {
  return import_svg_pair(text, "drawing.svg", options);
}

Pair import_ok(const std::string& text, DrawingImportOptions options = {}) {
  DrawingPairResult r = import(text, options);
  if (!r.ok()) ADD_FAILURE() << r.error->message() << "\n" << text;
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

void expect_has(const std::string& message, const std::vector<std::string>& parts) {
  for (const std::string& p : parts)
    EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
}

std::string num(double v) {
  return nlohmann::json(v).dump();
}

// The area of a closed Bezier chain, from many points of it.
double bezier_area(const std::vector<std::vector<Vec2>>& curves) {
  testkit::LoopVertices samples;
  for (const std::vector<Vec2>& c : curves)
    for (int i = 0; i < 20000; ++i) {
      const double t = i / 20000.0, s = 1 - t;
      Vec2 p;
      if (c.size() == 3) p = s * s * c[0] + 2 * s * t * c[1] + t * t * c[2];
      if (c.size() == 4)
        p = s * s * s * c[0] + 3 * s * s * t * c[1] + 3 * s * t * t * c[2] + t * t * t * c[3];
      samples.push_back({p.x, p.y, 0.0});
    }
  return std::fabs(testkit::loop_area(samples));
}

}  // namespace

// Inkscape's layers, named by label, in a document of millimetres whose user unit is 2 mm:
// coordinates come out in mm, y turned up, the moving part about --origin (in mm, y down as
// the drawing program shows it).
TEST(SvgImport, InkscapeLayersInMillimetres) {
  const std::string text =
      svg("<g inkscape:groupmode=\"layer\" id=\"layer1\" inkscape:label=\"Housing\">"
          "<path d=\"M 5 5 H 45 V 35 H 5 Z\"/></g>"
          "<g inkscape:groupmode=\"layer\" id=\"layer2\" inkscape:label=\"Pin\">"
          "<circle cx=\"25\" cy=\"20\" r=\"2\"/></g>",
          " width=\"100mm\" height=\"80mm\" viewBox=\"0 0 50 40\"");
  DrawingImportOptions options;
  options.moving_layer = "pin";  // labels match in any case
  options.fixed_layer = "HOUSING";
  options.moving_origin = {50, 40};
  options.fixed_enclosure = true;
  const DrawingPairResult r = import(text, options);
  ASSERT_TRUE(r.ok()) << r.error->message();
  const Pair& pair = *r.pair;
  EXPECT_EQ(pair.units, "mm");
  ASSERT_EQ(pair.moving.loops.size(), 1u);
  EXPECT_TRUE(pair.moving.loops[0].is_circle());
  EXPECT_EQ(pair.moving.box.lo.x, -4.0);  // radius 2 user units = 4 mm, about the origin
  EXPECT_EQ(pair.moving.box.hi.y, 4.0);
  EXPECT_EQ(pair.fixed.box.lo.x, 10.0);
  EXPECT_EQ(pair.fixed.box.hi.x, 90.0);
  EXPECT_EQ(pair.fixed.box.lo.y, -70.0);  // y down in the drawing, up in the pair
  EXPECT_EQ(pair.fixed.box.hi.y, -10.0);
  EXPECT_EQ(r.drawn_at, (Vec2{50, -40}));
  EXPECT_EQ(classify(pair, {50, -40, 0.0}), Placement::free);
  EXPECT_EQ(classify(pair, {50, -12, 0.0}), Placement::blocked);  // within 4 of the top wall
  // Measured from the drawn placement: the fixed part's coordinates less the origin's too.
  options.fixed_origin = options.moving_origin;
  const DrawingPairResult relative = import(text, options);
  ASSERT_TRUE(relative.ok()) << relative.error->message();
  EXPECT_EQ(relative.drawn_at, (Vec2{0, 0}));
  EXPECT_EQ(relative.pair->fixed.box.lo.x, -40.0);
  EXPECT_EQ(relative.pair->fixed.box.hi.y, 30.0);  // the top wall, 10 mm down the page, 30 above 40
  EXPECT_EQ(classify(*relative.pair, {0, 0, 0.0}), Placement::free);
  // Named by id, written as href and CSS write it.
  DrawingImportOptions by_id;
  by_id.moving_layer = "#layer2";
  by_id.fixed_layer = "layer1";
  EXPECT_TRUE(import(text, by_id).ok());
  // Without a viewBox the user unit is the px, and so are the coordinates.
  const Pair px = import_ok(svg(moving("<circle r=\"2\"/>")), {});
  EXPECT_EQ(px.units, "px");
  EXPECT_EQ(px.moving.box.hi.x, 2.0);
}

// Circular arcs stay exact arcs, in either direction, large or small; elliptical arcs and
// Bezier curves become arcs within a hundredth of the tolerance; relative commands and the
// reflected controls of S and T draw what their absolute, explicit forms draw.
TEST(SvgImport, ArcsStayExactCurvesBecomeArcs) {
  // A slot: two half circles of radius 1 joined by lines 4 long; area 8 + pi.
  const Pair slot =
      import_ok(svg(moving("<path d=\"M 0 0 H 4 A 1 1 0 0 1 4 2 H 0 A 1 1 0 0 1 0 0 Z\"/>")));
  EXPECT_EQ(slot.moving.arc_count(), 2);
  EXPECT_EQ(slot.moving.segment_count(), 2);
  EXPECT_NEAR(slot.moving.area, 8 + kPi, 1e-12);
  EXPECT_NEAR(slot.moving.box.hi.x, 5.0, 1e-12);
  // The slot in relative commands, its left half circle drawn with sweep 0: it bends into
  // the slot instead of out of it, so the area is 8.
  const Pair dent = import_ok(svg(moving("<path d=\"m0,0h4a1,1,0,0,1,0,2h-4a1 1 0 0 0 0-2z\"/>")));
  EXPECT_NEAR(dent.moving.area, 8.0, 1e-12);
  EXPECT_EQ(dent.moving.arc_count(), 2);
  // A circle as two large arcs of radius 2 (three quarters and one quarter).
  const Pair disc =
      import_ok(svg(moving("<path d=\"M 2 0 A 2 2 0 1 1 0 -2 A 2 2 0 0 1 2 0 Z\"/>")));
  EXPECT_NEAR(disc.moving.area, 4 * kPi, 1e-12);
  ASSERT_EQ(disc.moving.loops.size(), 1u);
  EXPECT_TRUE(disc.moving.loops[0].is_circle());  // arcs of one circle all round
  // Radii too small for the chord are scaled up until the arc fits: a half circle.
  const Pair half = import_ok(svg(moving("<path d=\"M 0 0 A 0.1 0.1 0 0 1 2 0 Z\"/>")));
  EXPECT_NEAR(half.moving.area, kPi / 2, 1e-12);
  // An ellipse of semi-axes 3 and 1 turned 30 degrees, as two elliptical arcs: followed
  // within a hundredth of the default tolerance on its box (8.5e-5), so the area within its
  // perimeter (13.4) times that.
  const Pair ellipse = import_ok(svg(moving(
      "<path d=\"M 3 0 A 3 1 0 0 1 -3 0 A 3 1 0 0 1 3 0 Z\"/>", " transform=\"rotate(-30)\"")));
  EXPECT_NEAR(ellipse.moving.area, 3 * kPi, 2e-3);
  EXPECT_GT(ellipse.moving.arc_count(), 8);
  // A lens: a cubic Bezier below, a quadratic one above.
  const std::vector<Vec2> cubic = {{0, 0}, {1, -4}, {3, -3}, {4, 0}},
                          quad = {{4, 0}, {2, 5}, {0, 0}};
  const Pair curve = import_ok(svg(moving("<path d=\"M0 0 C 1 -4 3 -3 4 0 Q 2 5 0 0 Z\"/>")));
  EXPECT_NEAR(curve.moving.area, bezier_area({cubic, quad}), 1e-4);
  // S reflects the last cubic control, T the last quadratic one: as if written out.
  const std::string reflected = "M0 0 C 0 2 2 2 2 0 S 4 -2 4 0 Q 2 6 0 4 T -2 0 L 0 0 Z";
  const std::string explicit_ = "M0 0 C 0 2 2 2 2 0 C 2 -2 4 -2 4 0 Q 2 6 0 4 Q -2 2 -2 0 L 0 0 Z";
  const Pair a = import_ok(svg(moving("<path d=\"" + reflected + "\"/>")));
  const Pair b = import_ok(svg(moving("<path d=\"" + explicit_ + "\"/>")));
  EXPECT_EQ(a.moving.feature_count(), b.moving.feature_count());
  EXPECT_NEAR(a.moving.area, b.moving.area, 1e-12);
  // Numbers as the grammar allows them: "1.5.5" is 1.5 then .5, signs run numbers together.
  const Pair packed = import_ok(svg(moving("<path d=\"M0,0L4-0L4,2.5.5 3-2,3z\"/>")));
  const Pair spaced = import_ok(svg(moving("<path d=\"M 0 0 L 4 0 L 4 2.5 L 0.5 3 L -2 3 Z\"/>")));
  EXPECT_NEAR(packed.moving.area, spaced.moving.area, 1e-12);
}

// Transforms apply right to left and nest; <use> places its element moved by x, y; a map that
// keeps circles circles keeps arcs exact (a mirror turns them the other way), an uneven scale
// or a skew makes them ellipses, followed by arcs.
TEST(SvgImport, TransformsAndReuse) {
  // A 2 x 2 square with a half disc of radius 1 on its right side: area 4 + pi/2.
  const std::string peg = "M 0 0 H 2 A 1 1 0 0 1 2 2 H 0 Z";
  const double area = 4 + kPi / 2;
  const Pair plain = import_ok(svg(moving("<path d=\"" + peg + "\"/>")));
  EXPECT_NEAR(plain.moving.area, area, 1e-12);
  // translate(10,0) scale(2): the point (1, 0) goes to (12, 0), in the pair (12, -0).
  const Pair moved = import_ok(
      svg(moving("<path d=\"" + peg + "\"/>", " transform=\"translate(10,0) scale(2)\"")));
  EXPECT_NEAR(moved.moving.area, 4 * area, 1e-12);
  EXPECT_NEAR(moved.moving.box.lo.x, 10.0, 1e-12);
  EXPECT_NEAR(moved.moving.box.hi.x, 16.0, 1e-12);
  EXPECT_EQ(moved.moving.arc_count(), 1);
  // Mirrored: the cap on the left, exact, the same area.
  const Pair mirrored =
      import_ok(svg(moving("<path d=\"" + peg + "\"/>", " transform=\"scale(-1 1)\"")));
  EXPECT_NEAR(mirrored.moving.area, area, 1e-12);
  EXPECT_NEAR(mirrored.moving.box.lo.x, -3.0, 1e-12);
  EXPECT_EQ(mirrored.moving.arc_count(), 1);
  // Turned a quarter about (1, 1): (x, y) to (2 - y, x), the cap at the bottom of the page,
  // and of the pair, which looks as the page does.
  const Pair turned =
      import_ok(svg(moving("<path d=\"" + peg + "\" transform=\"rotate(90 1 1)\"/>")));
  EXPECT_NEAR(turned.moving.area, area, 1e-12);
  EXPECT_NEAR(turned.moving.box.lo.y, -3.0, 1e-12);
  EXPECT_NEAR(turned.moving.box.hi.x, 2.0, 1e-12);
  // Reused from <defs>, twice, each moved by the use's x and y and its transform.
  const Pair reused = import_ok(svg("<defs><path id=\"peg\" d=\"" + peg + "\"/></defs>" +
                                    moving("<use href=\"#peg\" x=\"0\" y=\"5\"/><use "
                                           "xlink:href=\"#peg\" transform=\"translate(5 0)\"/>")));
  EXPECT_EQ(reused.moving.loops.size(), 2u);
  EXPECT_NEAR(reused.moving.area, 2 * area, 1e-12);
  EXPECT_NEAR(reused.moving.box.hi.x, 8.0, 1e-12);
  EXPECT_NEAR(reused.moving.box.lo.y, -7.0, 1e-12);
  // A skew keeps areas: the half disc becomes half an ellipse, followed by arcs.
  const Pair skewed =
      import_ok(svg(moving("<path d=\"" + peg + "\"/>", " transform=\"skewX(30)\"")));
  EXPECT_NEAR(skewed.moving.area, area, 1e-3);
  EXPECT_GT(skewed.moving.arc_count(), 2);
  // An uneven scale: a circle becomes an ellipse of area pi * 3 * 1.
  const Pair squashed = import_ok(svg(moving("<circle r=\"1\"/>", " transform=\"scale(3 1)\"")));
  EXPECT_NEAR(squashed.moving.area, 3 * kPi, 2e-3);
  EXPECT_NEAR(squashed.moving.box.hi.x, 3.0, 1e-4);
}

// Each shape element, and outlines drawn as loose lines in any order and direction.
TEST(SvgImport, ShapesAndLooseLines) {
  // Rounded rectangle, rx given alone (ry follows it): 6 x 4 less four corners of radius 1.
  const Pair rounded =
      import_ok(svg(moving("<rect x=\"1\" y=\"1\" width=\"6\" height=\"4\" rx=\"1\"/>")));
  EXPECT_NEAR(rounded.moving.area, 24 - (4 - kPi), 1e-12);
  EXPECT_EQ(rounded.moving.arc_count(), 4);
  // Corners of half the width: a stadium, each end's two quarter circles one half circle (no
  // vertex where nothing happens), 2 segments, 2 arcs and 4 vertices.
  const Pair stadium = import_ok(svg(moving("<rect width=\"5\" height=\"14\" rx=\"2.5\"/>")));
  EXPECT_EQ(stadium.moving.arc_count(), 2);
  EXPECT_EQ(stadium.moving.feature_count(), 8);
  EXPECT_NEAR(stadium.moving.area, 5 * 9 + kPi * 2.5 * 2.5, 1e-12);
  // Elliptical corners, rx 2 and ry 1: arcs along them.
  const Pair oval = import_ok(svg(moving("<rect width=\"6\" height=\"4\" rx=\"2\" ry=\"1\"/>")));
  EXPECT_NEAR(oval.moving.area, 24 - 2 * (4 - kPi), 1e-3);
  // An ellipse of equal radii is a circle; a polygon; a polyline closed by a line.
  const Pair circle = import_ok(svg(moving("<ellipse cx=\"1\" cy=\"1\" rx=\"2\" ry=\"2\"/>")));
  ASSERT_EQ(circle.moving.loops.size(), 1u);
  EXPECT_TRUE(circle.moving.loops[0].is_circle());
  const Pair polygon = import_ok(svg(moving("<polygon points=\"0,0 4,0 4,3\"/>")));
  EXPECT_NEAR(polygon.moving.area, 6.0, 1e-12);
  EXPECT_EQ(polygon.moving.feature_count(), 6);
  const Pair closed_by_line = import_ok(
      svg(moving("<polyline points=\"0,0 4,0 4,3\"/><line x1=\"0\" y1=\"0\" x2=\"4\" y2=\"3\"/>")));
  EXPECT_NEAR(closed_by_line.moving.area, 6.0, 1e-12);
  // A path that comes back to its start, all but rounding, before Z has no edge of no length.
  const Pair repeated = import_ok(svg(moving("<path d=\"M 0 0 L 4 0 L 4 3 L 1e-9 0 Z\"/>")));
  EXPECT_EQ(repeated.moving.feature_count(), 6);
  // Loose lines, shuffled and some reversed, join into the triangle.
  std::mt19937 rng(5);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<std::string> lines = {"x1=\"0\" y1=\"0\" x2=\"4\" y2=\"0\"",
                                      "x1=\"4\" y1=\"3\" x2=\"4\" y2=\"0\"",
                                      "x1=\"4\" y1=\"3\" x2=\"0\" y2=\"0\""};
    std::shuffle(lines.begin(), lines.end(), rng);
    std::string body;
    for (const std::string& l : lines) body += "<line " + l + "/>";
    EXPECT_NEAR(import_ok(svg(moving(body))).moving.area, 6.0, 1e-12) << trial;
  }
  // Hidden elements in a part are not drawn; text is not an outline.
  const Pair hidden = import_ok(
      svg(moving("<circle r=\"1\"/><circle cx=\"5\" r=\"1\" style=\"fill:red; display : none\"/>"
                 "<g display=\"none\"><rect width=\"9\" height=\"9\"/></g><text>label</text>")));
  EXPECT_EQ(hidden.moving.loops.size(), 1u);
}

// The paper's four examples drawn as SVG paths (arcs as A commands, y down, the moving part
// moved by a transform and brought back by --origin) read back as the same pairs.
TEST(SvgImport, PaperExamplesDrawnAndReadBackAreTheSamePairs) {
  for (const char* name : {"knee", "cam", "fixture", "fastener"}) {
    const Pair original = testkit::load_example(name);
    const nlohmann::json file =
        nlohmann::json::parse(testkit::read_file(testkit::example_path(name)));
    std::string body;
    for (const char* part : {"moving", "fixed"}) {
      body += std::string("<g id=\"") + part + "\"" +
              (std::string(part) == "moving" ? " transform=\"translate(3 2)\"" : "") + ">";
      for (const nlohmann::json& loop : file[part]["loops"]) {
        if (loop.is_object()) {
          body += "<circle cx=\"" + num(loop["circle"][0].get<double>()) + "\" cy=\"" +
                  num(-loop["circle"][1].get<double>()) + "\" r=\"" +
                  num(loop["circle"][2].get<double>()) + "\"/>";
          continue;
        }
        std::string d;
        for (size_t i = 0; i < loop.size(); ++i) {
          const nlohmann::json& v = loop[i];
          const nlohmann::json& w = loop[(i + 1) % loop.size()];
          if (i == 0) d += "M " + num(v[0].get<double>()) + " " + num(-v[1].get<double>());
          const double bulge = v.size() > 2 ? v[2].get<double>() : 0.0;
          const Vec2 a{v[0].get<double>(), v[1].get<double>()},
              b{w[0].get<double>(), w[1].get<double>()};
          if (bulge == 0.0) {
            d += " L ";
          } else {  // y turned down: a counterclockwise arc turns clockwise, sweep flag 0
            const double sweep = 4 * std::atan(std::fabs(bulge));
            const double radius = distance(a, b) / (2 * std::sin(sweep / 2));
            d += " A " + num(radius) + " " + num(radius) + " 0 " + (sweep > kPi ? "1" : "0") +
                 (bulge > 0 ? " 0 " : " 1 ");
          }
          d += num(b.x) + " " + num(-b.y);
        }
        body += "<path d=\"" + d + " Z\"/>";
      }
      body += "</g>";
    }
    DrawingImportOptions options;
    options.moving_origin = {3, 2};
    options.fixed_enclosure = file["fixed"].value("enclosure", false);
    options.tolerance = original.requested_tolerance;
    const Pair pair = import_ok(svg(body), options);
    testkit::expect_same_pair(pair, original, name, 13);
  }
}

// Each reason names the file, the part and the element with its line.
TEST(SvgImport, ErrorsNameTheElementAndItsLine) {
  expect_has(import_error("<svg><g id=\"moving\">"),
             {"drawing.svg", "line 1", "not well-formed XML"});
  expect_has(import_error("<html/>"), {"root element is <html>"});
  expect_has(import_error(svg("<g id=\"layer1\" inkscape:label=\"Gear\"/>\n" + kFrame)),
             {"part 'moving'", "no element has the id or label 'moving'", "'Gear'"});
  expect_has(import_error(svg(moving("<text>no outline</text>"))),
             {"part 'moving'", "no outline", "<g id=\"moving\"> at line 2"});
  expect_has(
      import_error(svg(moving("\n<path id=\"p\" d=\"M 0 0 L 1 x\"/>"))),
      {"part 'moving'", "<path id=\"p\"> at line 3", "expected a number at character 11 ('x')"});
  expect_has(import_error(svg(moving("<path d=\"L 1 1\"/>"))), {"expected a moveto"});
  expect_has(import_error(svg(moving("<path d=\"M 0 0 L 1 0 Z 4 4\"/>"))), {"a command after Z"});
  expect_has(import_error(svg(moving("<path d=\"M 0 0 A 1 1 0 2 1 2 0 Z\"/>"))),
             {"a flag, 0 or 1"});
  expect_has(import_error(svg(moving("<path d=\"M 0 0 L 1e999 0 Z\"/>"))), {"out of range"});
  expect_has(import_error(svg(moving("<circle r=\"10%\"/>"))), {"r: a length in percent"});
  expect_has(import_error(svg(moving("<circle r=\"1em\"/>"))), {"unit 'em'"});
  expect_has(import_error(svg(moving("<circle r=\"-1\"/>"))), {"r is negative"});
  expect_has(import_error(svg(moving("<circle r=\"1\" transform=\"rotate(1 2)\"/>"))),
             {"transform \"rotate(1 2)\"", "an angle and a centre"});
  expect_has(import_error(svg(moving("<circle r=\"1\" transform=\"turn(1)\"/>"))),
             {"'turn' is not matrix"});
  expect_has(import_error(svg(moving("<use href=\"#nothing\"/>"))),
             {"no element has the id 'nothing'"});
  expect_has(import_error(svg("<defs><circle id=\"moving\" r=\"1\"/></defs>" + kFrame)),
             {"is a definition, not drawn"});
  expect_has(import_error(svg("<g id=\"fixed\"><g id=\"moving\"><circle r=\"1\"/></g></g>")),
             {"lies inside the other part's"});
  expect_has(import_error(svg(moving("<circle r=\"1\"/>") + "<g inkscape:label=\"MOVING\"/>")),
             {"two elements are named 'moving'"});
  expect_has(import_error(svg(moving("<line x2=\"1\"/><line x2=\"1\" y2=\"1\"/>"))),
             {"element 'moving'", "the outline is open", "<line> at line 2"});
  expect_has(import_error(svg(moving("<polygon points=\"0,0 1,1 1,0 0,1\"/>"))),
             {"part 'moving', loop 0", "(loop 0 is the <polygon> at line 2"});
  expect_has(import_error(svg(moving("<polygon points=\"0,0 1\"/>"))), {"odd count"});
  // <use> of itself: nested too deep, not forever.
  expect_has(import_error(svg(moving("<g id=\"self\"><circle r=\"1\"/><use href=\"#self\"/></g>"))),
             {"<use> elements nested deeper than 8"});
  std::string deep;
  for (int k = 0; k < 300; ++k) deep += "<g>";
  for (int k = 0; k < 300; ++k) deep += "</g>";
  expect_has(import_error(svg(moving(deep + "<circle r=\"1\"/>"))), {"nested deeper than 256"});
  DrawingImportOptions same;
  same.fixed_layer = "Moving";
  expect_has(import_error(svg(moving("<circle r=\"1\"/>")), same), {"both named 'moving'"});
}

// Mutated drawings are read or refused with a message; none crashes or hangs.
TEST(SvgImport, MutatedDrawingsAreReadOrRefusedWithAMessage) {
  const std::string base =
      svg("<defs><path id=\"t\" d=\"M0,0 a1 1 0 0 1 2,0 l0,3 h-2 z\"/></defs>"
          "<g id=\"moving\" transform=\"rotate(10) scale(1 1.5)\">"
          "<path d=\"M -1 -1 C 0 -2 1 -2 1 -1 S 2 1 1 1 Q 0 2 -1 1 T -1 -1 Z\"/>"
          "<use href=\"#t\" x=\"5\"/><ellipse cx=\"9\" rx=\"1\" ry=\"0.5\"/></g>"
          "<g id=\"fixed\"><rect x=\"-20\" y=\"-20\" width=\"40\" height=\"40\" rx=\"3\"/>"
          "<polyline points=\"30,0 34,0 34,3\"/><line x1=\"34\" y1=\"3\" x2=\"30\" y2=\"0\"/></g>",
          " width=\"100mm\" height=\"100mm\" viewBox=\"-50 -50 100 100\"");
  ASSERT_TRUE(import(base).ok()) << import(base).error->message();
  testkit::expect_mutants_read_or_refused(base, 20000, refusal);
}

class SvgImportCli : public testkit::ScratchDirTest {
 protected:
  SvgImportCli() : ScratchDirTest("cslice_svg") {}
};

// `cslice import` reads SVG by its extension or, under another name, by its first character;
// a bad drawing is exit 2 with the message and no file.
TEST_F(SvgImportCli, ReadsSvgByExtensionOrContent) {
  const std::string text = svg(moving("<rect x=\"-1\" y=\"-1\" width=\"2\" height=\"2\"/>"));
  testkit::write_file(dir_ / "d.SVG", text);
  testkit::write_file(dir_ / "d.xml", "\n  " + text);
  for (const char* file : {"d.SVG", "d.xml"}) {
    const std::string pair = testkit::quoted((dir_ / "pair.json").string());
    const testkit::RunResult ok = testkit::run_cli(
        "import " + testkit::quoted((dir_ / file).string()) + " --origin 0,0 -o " + pair, dir_);
    ASSERT_EQ(ok.status, 0) << ok.err;
    EXPECT_NE(ok.out.find("moving part 1 loop, 8 features"), std::string::npos) << ok.out;
    EXPECT_NE(ok.out.find("as drawn, the configuration 0,0,0"), std::string::npos) << ok.out;
    EXPECT_EQ(testkit::run_cli("info " + pair, dir_).status, 0);
  }
  // Far out on the sheet: a note names --fixed-origin, which measures from the drawn placement.
  testkit::write_file(
      dir_ / "far.svg",
      svg("<g id=\"fixed\"><rect x=\"1000\" y=\"990\" width=\"20\" height=\"4\"/></g>"
          "<g id=\"moving\"><circle cx=\"1010\" cy=\"1000\" r=\"2\"/></g>"));
  const std::string far = testkit::quoted((dir_ / "far.svg").string());
  const std::string far_pair = testkit::quoted((dir_ / "far.json").string());
  const testkit::RunResult noted =
      testkit::run_cli("import " + far + " --origin 1010,1000 -o " + far_pair, dir_);
  EXPECT_EQ(noted.status, 0) << noted.err;
  EXPECT_NE(noted.err.find("--fixed-origin 1010,1000"), std::string::npos) << noted.err;
  const testkit::RunResult mended = testkit::run_cli(
      "import " + far + " --origin 1010,1000 --fixed-origin 1010,1000 -o " + far_pair, dir_);
  EXPECT_EQ(mended.status, 0) << mended.err;
  EXPECT_EQ(mended.err, "");
  EXPECT_NE(mended.out.find("as drawn, the configuration 0,0,0"), std::string::npos) << mended.out;
  testkit::write_file(dir_ / "bad.svg", svg(moving("<path d=\"M 0 0 Q\"/>")));
  const std::string out = testkit::quoted((dir_ / "bad.json").string());
  const testkit::RunResult bad = testkit::run_cli(
      "import " + testkit::quoted((dir_ / "bad.svg").string()) + " -o " + out, dir_);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("bad.svg"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("<path> at line 2"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "bad.json"));
}
