// Pictures of a pair: render_pair_svg's output is well-formed enough for a browser, draws
// arcs as true arcs, carries a scale bar, and frames both parts; `cslice render` refuses a
// bad pose without leaving a file behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "cslice/pair.hpp"
#include "cslice/part.hpp"
#include "cslice/render_svg.hpp"
#include "support/cli_run.hpp"

namespace cslice {
namespace {

namespace fs = std::filesystem;
using namespace testkit;

// A unit disc beside a 2 x 2 block: one arc edge, four segments.
constexpr const char* kDiscPair = R"({
  "name": "disc", "units": "mm",
  "moving": { "loops": [{ "circle": [0, 0, 1] }] },
  "fixed": { "loops": [[[2, -1], [4, -1], [4, 1], [2, 1]]] }
})";

// Segments only: a square in a square opening.
constexpr const char* kSquarePair = R"({
  "name": "square", "units": "in",
  "moving": { "loops": [[[-1, -1], [1, -1], [1, 1], [-1, 1]]] },
  "fixed": { "loops": [[[-3, -3], [3, -3], [3, 3], [-3, 3]]], "enclosure": true }
})";

// A half-disc: one segment and one counterclockwise half-circle arc (bulge 1).
constexpr const char* kHalfDiscPair = R"({
  "name": "half-disc", "units": "mm",
  "moving": { "loops": [[[-1, 0], [1, 0, 1]]] },
  "fixed": { "loops": [[[-10, -5], [10, -5], [10, -3], [-10, -3]]] }
})";

Pair load(const char* json) {
  LoadResult r = parse_pair(json, "test");
  if (!r.ok()) throw std::runtime_error(r.error->message());
  return std::move(*r.pair);
}

int count_of(const std::string& s, const std::string& needle) {
  int n = 0;
  for (auto pos = s.find(needle); pos != std::string::npos; pos = s.find(needle, pos + 1)) ++n;
  return n;
}

// Every element opened is closed, in order: a stack over the tags, self-closing tags skipped.
bool tags_balanced(const std::string& svg) {
  std::vector<std::string> open;
  const std::regex tag(R"(<(/?)([A-Za-z][\w:-]*)[^>]*?(/?)>)");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), tag); it != std::sregex_iterator();
       ++it) {
    const std::smatch& m = *it;
    if (m[3] == "/") continue;
    if (m[1] == "/") {
      if (open.empty() || open.back() != m[2]) return false;
      open.pop_back();
    } else {
      open.push_back(m[2]);
    }
  }
  return open.empty();
}

// The path data ("d" attributes), where drawing commands live.
std::string path_data(const std::string& svg) {
  std::string all;
  const std::regex d(R"re(\sd="([^"]*)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), d); it != std::sregex_iterator();
       ++it)
    all += (*it)[1].str() + "\n";
  return all;
}

// The view box in world coordinates (x, y up): undoes the renderer's negation of y.
Box view_box(const std::string& svg) {
  std::smatch m;
  const std::regex vb(R"re(viewBox="([^ ]+) ([^ ]+) ([^ ]+) ([^ "]+)")re");
  if (!std::regex_search(svg, m, vb)) throw std::runtime_error("no viewBox");
  const double x = std::stod(m[1]), y = std::stod(m[2]);
  const double w = std::stod(m[3]), h = std::stod(m[4]);
  Box b;
  b.add(Vec2{x, -y});
  b.add(Vec2{x + w, -(y + h)});
  return b;
}

bool contains(const Box& outer, const Box& inner) {
  return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.hi.x >= inner.hi.x &&
         outer.hi.y >= inner.hi.y;
}

TEST(RenderSvg, IsWellFormed) {
  const Pair pair = load(kDiscPair);
  const std::string svg = render_pair_svg(pair, {0.5, 0.25, 0.3});
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  EXPECT_TRUE(tags_balanced(svg));
  EXPECT_EQ(count_of(svg, "<svg"), 1);
  EXPECT_EQ(count_of(svg, "</svg>"), 1);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(RenderSvg, DrawsArcsAsArcs) {
  const std::string disc = path_data(render_pair_svg(load(kDiscPair), {0, 0, 0}));
  // A full circle is drawn as two half arcs of radius 1.
  EXPECT_GE(count_of(disc, "A 1 1 0 "), 2);
  const std::string square = path_data(render_pair_svg(load(kSquarePair), {0, 0, 0.2}));
  EXPECT_EQ(square.find('A'), std::string::npos);
}

// With y negated, a counterclockwise world arc is clockwise on screen: sweep flag 0.
TEST(RenderSvg, ArcSweepFollowsTheFlip) {
  const std::string d = path_data(render_pair_svg(load(kHalfDiscPair), {0, 0, 0}));
  // The half circle from (1, 0) to (-1, 0) over the top: radius 1, not large, sweep 0.
  EXPECT_NE(d.find("A 1 1 0 0 0 -1 0"), std::string::npos) << d;
  // Turned upside down it still runs counterclockwise in the world.
  const std::string flipped = path_data(render_pair_svg(load(kHalfDiscPair), {0, 0, kPi}));
  EXPECT_NE(flipped.find("A 1 1 0 0 0 1 0"), std::string::npos) << flipped;
}

TEST(RenderSvg, HasScaleBarAndTitle) {
  SvgOptions options;
  options.title = "a <b> & c";
  const std::string svg = render_pair_svg(load(kSquarePair), {0, 0, 0}, options);
  EXPECT_TRUE(std::regex_search(svg, std::regex(R"(>[0-9.]+ in</text>)"))) << svg;
  EXPECT_NE(svg.find("a &lt;b&gt; &amp; c"), std::string::npos);
  options.show_scale_bar = false;
  options.title.clear();
  const std::string bare = render_pair_svg(load(kSquarePair), {0, 0, 0}, options);
  EXPECT_EQ(bare.find("</text>"), std::string::npos);
}

TEST(RenderSvg, ViewBoxHoldsBothParts) {
  const Pair pair = load(kDiscPair);
  for (const Pose& pose : {Pose{0, 0, 0}, Pose{-7, 3, 1}, Pose{10, -9, -2}}) {
    const Box view = view_box(render_pair_svg(pair, pose));
    EXPECT_TRUE(contains(view, pair.fixed.box));
    EXPECT_TRUE(contains(view, placed(pair.moving, pose).box));
  }
}

TEST(RenderSvg, WidthSetsThePictureSize) {
  SvgOptions options;
  options.width_px = 321;
  const std::string svg = render_pair_svg(load(kDiscPair), {0, 0, 0}, options);
  EXPECT_NE(svg.find("width=\"321\""), std::string::npos);
}

// ---- The command-line program ------------------------------------------------------------

class CliRender : public ScratchDirTest {
 protected:
  CliRender() : ScratchDirTest("cslice_cli_render") {}
  void SetUp() override {
    pair_ = dir_ / "pair.json";
    write_file(pair_, kDiscPair);
  }

  // Runs `cslice render` with extra arguments; returns the exit status.
  int render(const std::string& args) {
    return run_cli("render " + quoted(pair_.string()) + " " + args, dir_).status;
  }

  fs::path pair_;
};

TEST_F(CliRender, WritesAPicture) {
  const fs::path out = dir_ / "out.svg";
  ASSERT_EQ(render("--at 0.5,0,0.3 --width 400 --title T -o '" + out.string() + "'"), 0);
  const std::string svg = read_file(out);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("width=\"400\""), std::string::npos);
}

TEST_F(CliRender, BadPoseExitsTwoWithoutFile) {
  for (const char* pose : {"1,2", "a,b,c", "1,2,3,4", "1,nan,0"}) {
    const fs::path out = dir_ / "bad.svg";
    EXPECT_EQ(render(std::string("--at ") + pose + " -o '" + out.string() + "'"), 2) << pose;
    EXPECT_FALSE(fs::exists(out)) << pose;
  }
}

TEST_F(CliRender, BadWidthOrPairExitsTwoWithoutFile) {
  const fs::path out = dir_ / "bad.svg";
  EXPECT_EQ(render("--at 0,0,0 --width -5 -o '" + out.string() + "'"), 2);
  EXPECT_FALSE(fs::exists(out));
  pair_ = dir_ / "missing.json";
  EXPECT_EQ(render("--at 0,0,0 -o '" + out.string() + "'"), 2);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace cslice
