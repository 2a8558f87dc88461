// The pair reader: good files give the right loops, orientation, nesting and tolerances;
// every rejection names the file, part, loop and vertex it applies to and says why.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "cslice/pair.hpp"

namespace cslice {
namespace {

const char* const kSource = "test.json";
const std::string kUnitSquare = R"([[0,0],[1,0],[1,1],[0,1]])";
const std::string kBigSquare = R"([[-5,-5],[5,-5],[5,5],[-5,5]])";

// A pair file with the given part bodies (JSON objects) and extra top-level fields.
std::string pair_text(const std::string& moving, const std::string& fixed,
                      const std::string& extra = "") {
  return "{" + extra + R"("moving": )" + moving + R"(, "fixed": )" + fixed + "}";
}

std::string part_of(const std::string& loops, bool enclosure = false) {
  return R"({"loops": [)" + loops + "]" + (enclosure ? R"(, "enclosure": true)" : "") + "}";
}

// A pair whose fixed part has the given loops and whose moving part is the unit square.
std::string fixed_loops(const std::string& loops) {
  return pair_text(part_of(kUnitSquare), part_of(loops));
}
std::string moving_loops(const std::string& loops) {
  return pair_text(part_of(loops), part_of(kBigSquare));
}

Pair parse_ok(const std::string& text, const char* source = kSource) {
  LoadResult r = parse_pair(text, source);
  EXPECT_TRUE(r.ok()) << (r.error ? r.error->message() : "");
  if (!r.ok()) return Pair{};
  return std::move(*r.pair);
}

// Parses text that must fail, and checks where the error points and what it says.
InputError parse_bad(const std::string& text, const std::string& part, int loop, int vertex,
                     const std::string& reason_part) {
  const LoadResult r = parse_pair(text, kSource);
  EXPECT_FALSE(r.ok()) << "accepted: " << text;
  if (r.ok()) return InputError{};
  const InputError& e = *r.error;
  EXPECT_EQ(e.file, kSource);
  EXPECT_EQ(e.part, part) << e.message();
  EXPECT_EQ(e.loop, loop) << e.message();
  EXPECT_EQ(e.vertex, vertex) << e.message();
  EXPECT_NE(e.reason.find(reason_part), std::string::npos)
      << "reason '" << e.reason << "' lacks '" << reason_part << "'";
  EXPECT_EQ(e.message().rfind(std::string(kSource) + ": ", 0), 0u) << e.message();
  return e;
}

// ---- Good files ---------------------------------------------------------------------------

TEST(PairReader, SquareWithSquareHoleBothClockwise) {
  const std::string outer = R"([[0,0],[0,10],[10,10],[10,0]])";
  const std::string hole = R"([[3,3],[3,7],[7,7],[7,3]])";
  const Pair p = parse_ok(fixed_loops(outer + "," + hole));
  ASSERT_EQ(p.fixed.loops.size(), 2u);
  const Loop& o = p.fixed.loops[0];
  const Loop& h = p.fixed.loops[1];
  EXPECT_EQ(o.depth, 0);
  EXPECT_EQ(h.depth, 1);
  EXPECT_TRUE(o.reversed);   // was clockwise, outer boundaries run counterclockwise
  EXPECT_FALSE(h.reversed);  // holes stay clockwise
  EXPECT_EQ(o.source_index, 0);
  EXPECT_EQ(h.source_index, 1);
  EXPECT_NEAR(p.fixed.area, 100.0 - 16.0, 1e-9);
  EXPECT_EQ(p.fixed.segment_count(), 8);
  EXPECT_EQ(p.fixed.arc_count(), 0);
  EXPECT_EQ(p.fixed.vertex_count(), 8);
  EXPECT_EQ(p.fixed.feature_count(), 16);
  EXPECT_FALSE(p.fixed.enclosure);
  // Reversal keeps vertex 0 in place.
  EXPECT_EQ(o.edges[0].from, (Vec2{0, 0}));
  EXPECT_EQ(o.edges[0].to, (Vec2{10, 0}));
}

TEST(PairReader, EnclosureLoopsRunClockwise) {
  const Pair p =
      parse_ok(pair_text(part_of(kUnitSquare), part_of(R"([[-5,-5],[5,-5],[5,5],[-5,5]])", true)));
  ASSERT_EQ(p.fixed.loops.size(), 1u);
  EXPECT_TRUE(p.fixed.enclosure);
  EXPECT_TRUE(p.fixed.loops[0].reversed);  // given counterclockwise
  EXPECT_LT(signed_area_contribution(p.fixed.loops[0].edges[0]) +
                signed_area_contribution(p.fixed.loops[0].edges[1]) +
                signed_area_contribution(p.fixed.loops[0].edges[2]) +
                signed_area_contribution(p.fixed.loops[0].edges[3]),
            0.0);
  EXPECT_NEAR(p.fixed.area, 100.0, 1e-9);  // the opening, as a positive number
}

TEST(PairReader, CircleLoop) {
  const Pair p = parse_ok(moving_loops(R"({"circle": [0.5, 0.25, 2]})"));
  ASSERT_EQ(p.moving.loops.size(), 1u);
  const Loop& c = p.moving.loops[0];
  EXPECT_TRUE(c.is_circle());
  EXPECT_TRUE(c.edges[0].is_counterclockwise());
  EXPECT_EQ(p.moving.arc_count(), 1);
  EXPECT_EQ(p.moving.vertex_count(), 0);
  EXPECT_EQ(p.moving.feature_count(), 1);
  EXPECT_NEAR(p.moving.area, kPi * 4.0, 1e-9);
}

TEST(PairReader, TwoVertexLoopWithOneArc) {
  // Bulge 1 from (0,0) to (2,0): the counterclockwise half circle below; then straight back.
  const Pair p = parse_ok(moving_loops(R"([[0,0,1],[2,0]])"));
  const Loop& d = p.moving.loops[0];
  ASSERT_EQ(d.edges.size(), 2u);
  EXPECT_FALSE(d.reversed);
  EXPECT_TRUE(d.edges[0].is_arc());
  EXPECT_NEAR(d.edges[0].radius, 1.0, 1e-12);
  EXPECT_TRUE(d.edges[1].is_segment());
  EXPECT_NEAR(p.moving.area, kPi / 2.0, 1e-9);
  EXPECT_EQ(p.moving.feature_count(), 4);
}

TEST(PairReader, CrescentOfTwoArcsIsValid) {
  // Two arcs below the chord from (0,0) to (2,0): a half circle and a shallower arc inside it.
  const Pair p = parse_ok(moving_loops(R"([[0,0,1],[2,0,-0.5]])"));
  EXPECT_EQ(p.moving.arc_count(), 2);
  EXPECT_GT(p.moving.area, 0.0);
}

TEST(PairReader, DefaultsAndSize) {
  const Pair p = parse_ok(fixed_loops(R"([[0,0],[10,0],[10,10],[0,10]])"), "some/dir/cam.json");
  EXPECT_EQ(p.name, "cam");
  EXPECT_EQ(p.units, "mm");
  EXPECT_FALSE(p.requested_tolerance.has_value());
  // Fixed box [0,10]^2 and the unit square's reach sqrt(2): box [-sqrt2, 10]^2.
  const double reach = std::sqrt(2.0);
  EXPECT_NEAR(p.tol.size, std::sqrt(2.0) * (10.0 + reach), 1e-12);
  EXPECT_NEAR(p.tol.contact, 1e-3 * p.tol.size, 1e-15);
  EXPECT_NEAR(p.tol.geometric, kRelativeGeometricEpsilon * p.tol.size, 1e-20);
  EXPECT_EQ(p.moving.name, "moving");
  EXPECT_EQ(p.fixed.name, "fixed");
}

// The size reaches from the body origin to the fixed part; drawn 1,000 out, the fixed square
// makes it about 71 times what it would be centred, and so every tolerance.
TEST(PairReader, PlacementCoarseningIsTheSizeOverTheCentredSize) {
  const Pair near = parse_ok(fixed_loops(R"([[0,0],[10,0],[10,10],[0,10]])"));
  // Centred, the fixed box [-5, 5]^2 holds the unit square's reach sqrt(2).
  EXPECT_NEAR(placement_coarsening(near.moving, near.fixed), near.tol.size / (10 * std::sqrt(2.0)),
              1e-12);
  const Pair far = parse_ok(fixed_loops(R"([[1000,0],[1010,0],[1010,10],[1000,10]])"));
  const double reach = std::sqrt(2.0);
  EXPECT_NEAR(far.tol.size, std::hypot(1010 + reach, 10 + reach), 1e-9);
  EXPECT_NEAR(placement_coarsening(far.moving, far.fixed), far.tol.size / (10 * std::sqrt(2.0)),
              1e-9);
  EXPECT_GT(placement_coarsening(far.moving, far.fixed), kPlacementCoarseningWarning);
}

TEST(PairReader, ExplicitNameUnitsTolerance) {
  const Pair p = parse_ok(pair_text(part_of(kUnitSquare), part_of(kBigSquare),
                                    R"("name": "peg", "units": "in", "tolerance": 0.05, )"));
  EXPECT_EQ(p.name, "peg");
  EXPECT_EQ(p.units, "in");
  ASSERT_TRUE(p.requested_tolerance.has_value());
  EXPECT_EQ(*p.requested_tolerance, 0.05);
  EXPECT_EQ(p.tol.contact, 0.05);
}

TEST(PairReader, SizeCountsArcExtremes) {
  // Half disc centered (2,0), radius 1, right half: its farthest point (3,0) is no vertex.
  const Pair p =
      parse_ok(pair_text(part_of(R"([[2,-1,1],[2,1]])"), part_of(R"([[0,0],[1,0],[1,1],[0,1]])")));
  EXPECT_NEAR(p.tol.size, 6.0 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(pair_size(p.moving, p.fixed), p.tol.size, 0.0);
}

TEST(PairReader, NestedIslandInHole) {
  const std::string outer = R"([[0,0],[10,0],[10,10],[0,10]])";
  const std::string hole = R"([[2,2],[8,2],[8,8],[2,8]])";
  const std::string island = R"({"circle": [5, 5, 1]})";
  const Pair p = parse_ok(fixed_loops(outer + "," + hole + "," + island));
  EXPECT_EQ(p.fixed.loops[2].depth, 2);
  EXPECT_TRUE(p.fixed.loops[1].reversed);   // counterclockwise hole turned clockwise
  EXPECT_FALSE(p.fixed.loops[2].reversed);  // island is material: counterclockwise
  EXPECT_NEAR(p.fixed.area, 100.0 - 36.0 + kPi, 1e-9);
}

TEST(PairReader, LoadFromFileAndMissingFile) {
  const auto dir = std::filesystem::temp_directory_path() / "cslice_test_pair_reader";
  std::filesystem::create_directories(dir);
  const auto path = dir / "widget.json";
  std::ofstream(path) << fixed_loops(kBigSquare);
  const LoadResult r = load_pair(path.string());
  ASSERT_TRUE(r.ok()) << r.error->message();
  EXPECT_EQ(r.pair->name, "widget");
  const LoadResult missing = load_pair((dir / "nope.json").string());
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error->file, (dir / "nope.json").string());
  EXPECT_NE(missing.error->reason.find("cannot open"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(PairReader, MessageShape) {
  const InputError e{"a.json", "moving", 2, 5, "zero-length edge"};
  EXPECT_EQ(e.message(), "a.json: part 'moving', loop 2, vertex 5: zero-length edge");
  EXPECT_EQ((InputError{"a.json", "", -1, -1, "bad"}).message(), "a.json: bad");
  EXPECT_EQ((InputError{"a.json", "fixed", 1, -1, "bad"}).message(),
            "a.json: part 'fixed', loop 1: bad");
}

// ---- Rejections: one per reason -------------------------------------------------------------

TEST(PairReaderRejects, InvalidJsonWithLineAndColumn) {
  const InputError e =
      parse_bad("{\n  \"moving\": nan }", "", -1, -1, "invalid JSON at line 2, column");
  EXPECT_NE(e.message().find("test.json: invalid JSON"), std::string::npos);
}

TEST(PairReaderRejects, EmptyText) {
  parse_bad("", "", -1, -1, "invalid JSON at line 1");
}

TEST(PairReaderRejects, NumberOverflowIsInvalidJson) {
  parse_bad(moving_loops(R"([[0,0],[1e999,0],[1,1]])"), "", -1, -1, "invalid JSON");
}

TEST(PairReaderRejects, DeepNesting) {
  parse_bad(std::string(100, '[') + std::string(100, ']'), "", -1, -1, "nested deeper");
}

TEST(PairReaderRejects, TopLevelNotObject) {
  parse_bad("[1, 2]", "", -1, -1, "top level must be a JSON object, got array");
}

TEST(PairReaderRejects, MissingMoving) {
  parse_bad(R"({"fixed": )" + part_of(kBigSquare) + "}", "", -1, -1, "missing field \"moving\"");
}

TEST(PairReaderRejects, MissingFixed) {
  parse_bad(R"({"moving": )" + part_of(kUnitSquare) + "}", "", -1, -1, "missing field \"fixed\"");
}

TEST(PairReaderRejects, MissingLoops) {
  parse_bad(pair_text(R"({"enclosure": false})", part_of(kBigSquare)), "moving", -1, -1,
            "missing field \"loops\"");
}

TEST(PairReaderRejects, PartWrongType) {
  parse_bad(pair_text("[1]", part_of(kBigSquare)), "moving", -1, -1,
            "part must be an object, got array");
}

TEST(PairReaderRejects, LoopsWrongType) {
  parse_bad(pair_text(part_of(kUnitSquare), R"({"loops": 5})"), "fixed", -1, -1,
            "\"loops\" must be an array, got number");
}

TEST(PairReaderRejects, LoopWrongType) {
  parse_bad(fixed_loops(kBigSquare + ", 7"), "fixed", 1, -1, "loop must be an array of vertices");
}

TEST(PairReaderRejects, VertexWrongArity) {
  parse_bad(fixed_loops(R"([[0,0],[1,0],[1,1,0,4]])"), "fixed", 0, 2, "vertex must be [x, y]");
}

TEST(PairReaderRejects, CoordinateWrongType) {
  parse_bad(fixed_loops(R"([[0,0],["1",0],[1,1]])"), "fixed", 0, 1,
            "x coordinate must be a number, got string");
}

TEST(PairReaderRejects, EnclosureWrongType) {
  parse_bad(
      pair_text(part_of(kUnitSquare), R"({"loops": [)" + kBigSquare + R"(], "enclosure": 1})"),
      "fixed", -1, -1, "\"enclosure\" must be true or false");
}

TEST(PairReaderRejects, TopLevelFieldWrongType) {
  parse_bad(pair_text(part_of(kUnitSquare), part_of(kBigSquare), R"("tolerance": "0.1", )"), "", -1,
            -1, "tolerance must be a number, got string");
  parse_bad(pair_text(part_of(kUnitSquare), part_of(kBigSquare), R"("name": 5, )"), "", -1, -1,
            "field \"name\" must be a string");
}

TEST(PairReaderRejects, UnknownTopLevelField) {
  const InputError e =
      parse_bad(pair_text(part_of(kUnitSquare), part_of(kBigSquare), R"("tolerence": 0.1, )"), "",
                -1, -1, "unknown field \"tolerence\"");
  EXPECT_NE(e.reason.find("did you mean \"tolerance\""), std::string::npos) << e.reason;
}

TEST(PairReaderRejects, UnknownPartField) {
  parse_bad(pair_text(part_of(kUnitSquare), R"({"loop": [], "loops": [)" + kBigSquare + "]}"),
            "fixed", -1, -1, "unknown field \"loop\"");
}

TEST(PairReaderRejects, UnknownCircleField) {
  parse_bad(moving_loops(R"({"circle": [0,0,1], "radius": 1})"), "moving", 0, -1,
            "unknown field \"radius\"");
}

TEST(PairReaderRejects, AbsurdCoordinate) {
  parse_bad(fixed_loops(R"([[0,0],[1e308,0],[1,1]])"), "fixed", 0, 1,
            "exceeds the magnitude limit 1000000000");
}

TEST(PairReaderRejects, NegativeTolerance) {
  parse_bad(pair_text(part_of(kUnitSquare), part_of(kBigSquare), R"("tolerance": -0.1, )"), "", -1,
            -1, "tolerance must be positive");
}

TEST(PairReaderRejects, ZeroTolerance) {
  parse_bad(pair_text(part_of(kUnitSquare), part_of(kBigSquare), R"("tolerance": 0, )"), "", -1, -1,
            "tolerance must be positive");
}

TEST(PairReaderRejects, LoopWithOneVertex) {
  parse_bad(fixed_loops(kBigSquare + R"(, [[0,0,1]])"), "fixed", 1, -1, "at least two");
}

TEST(PairReaderRejects, LoopWithNoVertex) {
  parse_bad(moving_loops("[]"), "moving", 0, -1, "at least two");
}

TEST(PairReaderRejects, CircleZeroRadius) {
  parse_bad(moving_loops(R"({"circle": [0,0,0]})"), "moving", 0, -1, "radius must be positive");
}

TEST(PairReaderRejects, CircleNegativeRadius) {
  parse_bad(moving_loops(R"({"circle": [0,0,-1]})"), "moving", 0, -1, "radius must be positive");
}

TEST(PairReaderRejects, CircleBelowGeometricTolerance) {
  parse_bad(fixed_loops(kBigSquare + R"(, {"circle": [0,0,1e-12]})"), "fixed", 1, -1,
            "not above the geometric tolerance");
}

TEST(PairReaderRejects, CircleWrongArity) {
  parse_bad(moving_loops(R"({"circle": [0,0]})"), "moving", 0, -1, "must be [cx, cy, r]");
}

TEST(PairReaderRejects, ZeroLengthEdge) {
  parse_bad(fixed_loops(R"([[0,0],[4,0],[4,4],[4,4],[0,4]])"), "fixed", 0, 2, "zero-length edge");
}

TEST(PairReaderRejects, EdgeShorterThanGeometricTolerance) {
  parse_bad(fixed_loops(R"([[0,0],[4,0],[4,4],[4,4.000000000001],[0,4]])"), "fixed", 0, 2,
            "zero-length edge");
}

TEST(PairReaderRejects, ClosingEdgeZeroLength) {
  parse_bad(fixed_loops(R"([[0,0],[4,0],[4,4],[0,0]])"), "fixed", 0, 3, "zero-length edge");
}

TEST(PairReaderRejects, TwoVertexLoopWithStraightEdges) {
  parse_bad(moving_loops(R"([[0,0],[1,0]])"), "moving", 0, -1, "encloses no area");
}

TEST(PairReaderRejects, BulgeWrongType) {
  parse_bad(moving_loops(R"([[0,0,"x"],[1,0],[0,1]])"), "moving", 0, 0, "bulge must be a number");
}

TEST(PairReaderRejects, BulgeAbsurd) {
  parse_bad(moving_loops(R"([[0,0,1e12],[1,0],[0,1]])"), "moving", 0, 0,
            "bulge 1e+12 exceeds the magnitude limit");
}

// The pair below has size 14.1 (the 10 by 10 fixed square's diagonal): bulge 1e-5 on the edge
// of length sqrt(2) gives radius 35,355, over 100 times the size; bulge 1e-3 (radius 354)
// is read. (A stress pair with an arc of radius 4,100 times its size lost its free space in a
// slice; arcs over 300 times missed critical orientations: include/cslice/tolerance.hpp.)
TEST(PairReaderRejects, NearlyStraightArc) {
  parse_bad(moving_loops(R"([[0,0],[1,0,1e-5],[0,1]])"), "moving", 0, 1,
            "is nearly straight: radius 35355.33906 exceeds 100 times");
  EXPECT_TRUE(parse_pair(moving_loops(R"([[0,0],[1,0,1e-3],[0,1]])"), "t").ok());
}

TEST(PairReaderRejects, ArcFlatterThanTolerance) {
  parse_bad(moving_loops(R"([[0,0],[1,0,1e-12],[0,1]])"), "moving", 0, 1,
            "within the geometric tolerance of its chord");
}

TEST(PairReaderRejects, ArcCenterBeyondLimit) {
  // Radius 2e9, 14 times the size: not nearly straight, but its centre is out of range.
  parse_bad(fixed_loops(R"([[0,0],[1e8,0,0.0125],[1e8,1e8],[0,1e8]])"), "fixed", 0, 1,
            "exceeds the magnitude limit");
}

TEST(PairReaderRejects, SelfCrossingBowtie) {
  const InputError e = parse_bad(fixed_loops(R"([[0,0],[2,2],[2,0],[0,2]])"), "fixed", 0, 0,
                                 "loop crosses or touches itself: edges 0 and 2 meet at (1, 1)");
  EXPECT_EQ(e.message(),
            "test.json: part 'fixed', loop 0, vertex 0: loop crosses or touches itself: edges 0 "
            "and 2 meet at (1, 1)");
}

TEST(PairReaderRejects, SelfTouchingAtAVertex) {
  // Vertex 3 lies on edge 0 (the bottom side).
  parse_bad(fixed_loops(R"([[0,0],[4,0],[4,4],[2,0],[0,4]])"), "fixed", 0, 0,
            "edges 0 and 2 meet at (2, 0)");
}

TEST(PairReaderRejects, AdjacentEdgesFoldBack) {
  parse_bad(fixed_loops(R"([[0,0],[2,0],[1,0],[1,1]])"), "fixed", 0, 0,
            "adjacent edges 0 and 1 overlap");
}

TEST(PairReaderRejects, AdjacentArcMeetsEdgeAgain) {
  // The arc from (2,1) back to (0,0) bulges below the bottom edge and crosses it at (2,0).
  parse_bad(fixed_loops(R"([[0,0],[4,0],[2,1,-1]])"), "fixed", 0, 0,
            "adjacent edges 0 and 2 meet at (2, 0)");
}

TEST(PairReaderRejects, TwoVertexLoopOfOneArcTwice) {
  // Both edges trace the same half circle.
  parse_bad(moving_loops(R"([[0,0,1],[2,0,-1]])"), "moving", 0, 0,
            "adjacent edges 0 and 1 overlap");
}

TEST(PairReaderRejects, LoopsCross) {
  parse_bad(fixed_loops(R"([[0,0],[4,0],[4,4],[0,4]], [[2,2],[6,2],[6,6],[2,6]])"), "fixed", 0, 1,
            "loops 0 and 1 touch or cross");
}

TEST(PairReaderRejects, HoleTouchesOuterBoundary) {
  parse_bad(fixed_loops(R"([[0,0],[10,0],[10,10],[0,10]], [[0,5],[3,4],[3,6]])"), "fixed", 0, 3,
            "loops 0 and 1 touch or cross: edge 3 of loop 0 and edge 0 of loop 1 meet at (0, 5)");
}

TEST(PairReaderRejects, CirclesTouch) {
  parse_bad(moving_loops(R"({"circle": [0,0,1]}, {"circle": [2,0,1]})"), "moving", 0, -1,
            "loops 0 and 1 touch or cross");
}

TEST(PairReaderRejects, EmptyPart) {
  parse_bad(pair_text(part_of(kUnitSquare), R"({"loops": []})"), "fixed", -1, -1, "part is empty");
}

TEST(PairReaderRejects, MovingEnclosure) {
  parse_bad(pair_text(part_of(kUnitSquare, true), part_of(kBigSquare)), "moving", -1, -1,
            "moving part cannot be an enclosure");
}

TEST(PairReaderRejects, MissingFileIsADirectory) {
  const LoadResult r = load_pair(std::filesystem::temp_directory_path().string());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->reason.find("directory"), std::string::npos);
}

TEST(PairReaderRejects, UnknownFieldIsShownSafely) {
  const InputError e = parse_bad(pair_text(part_of(kUnitSquare), part_of(kBigSquare),
                                           "\"bad\\nkey" + std::string(100, 'x') + "\": 1, "),
                                 "", -1, -1, "unknown field \"bad\\nkey");
  EXPECT_EQ(e.reason.find('\n'), std::string::npos);
  EXPECT_NE(e.reason.find("...\""), std::string::npos) << e.reason;
}

// ---- Scale ----------------------------------------------------------------------------------

std::string regular_polygon(int n, double radius, bool clockwise) {
  std::string s = "[";
  for (int i = 0; i < n; ++i) {
    const double a = (clockwise ? -1.0 : 1.0) * kTwoPi * i / n;
    if (i > 0) s += ",";
    s += "[";
    s += std::to_string(radius * std::cos(a));
    s += ",";
    s += std::to_string(radius * std::sin(a));
    s += "]";
  }
  return s + "]";
}

TEST(PairReaderScale, TenThousandEdgesValidateFast) {
  const auto start = std::chrono::steady_clock::now();
  const Pair p = parse_ok(fixed_loops(regular_polygon(10000, 1000.0, true)));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(p.fixed.vertex_count(), 10000);
  EXPECT_TRUE(p.fixed.loops[0].reversed);
  EXPECT_LT(seconds, 5.0);  // quadratic pair testing takes far longer (5e7 intersections)
}

TEST(PairReaderScale, GridOfHoles) {
  std::string loops = R"([[0,0],[100,0],[100,100],[0,100]])";
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j)
      loops += R"(, {"circle": [)" + std::to_string(2 + 3 * i) + "," + std::to_string(2 + 3 * j) +
               ", 1]}";
  const Pair p = parse_ok(fixed_loops(loops));
  ASSERT_EQ(p.fixed.loops.size(), 901u);
  for (size_t k = 1; k < p.fixed.loops.size(); ++k) ASSERT_EQ(p.fixed.loops[k].depth, 1);
  EXPECT_NEAR(p.fixed.area, 10000.0 - 900.0 * kPi, 1e-6);
}

}  // namespace
}  // namespace cslice
