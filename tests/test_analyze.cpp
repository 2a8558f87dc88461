// Reading space files back (load_space) and analysing them (analyze_space, `cslice analyze`):
// round trips on the examples, bad and tampered files, and the checks of the paper's
// applications (section 2) against what examples/README.md derives by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cslice/analyze.hpp"
#include "cslice/classify.hpp"
#include "support/cli_run.hpp"
#include "support/examples.hpp"

using namespace cslice;

namespace {

const char* const kExamples[] = {"knee",
                                 "cam",
                                 "fixture",
                                 "fastener",
                                 "disc-in-box",
                                 "square-peg-hole",
                                 "disc-half-plane",
                                 "pin-exact-fit"};

class SpaceFile : public testkit::ScratchDirTest {
 protected:
  SpaceFile() : ScratchDirTest("cslice_analyze") {}

  // The example's space written to a file; its text (with timing) in `text`.
  std::string write_space(const std::string& name, std::string* text = nullptr) {
    const Pair pair = testkit::load_example(name);
    const std::string json = space_to_json(pair, compute_space(pair));
    const std::string path = (dir_ / (name + ".space.json")).string();
    testkit::write_file(path, json);
    if (text) *text = json;
    return path;
  }

  // The error load_space gives for `text`, written to bad.json; empty when it loads.
  std::string load_error(const std::string& text) {
    const std::string path = (dir_ / "bad.json").string();
    testkit::write_file(path, text);
    const LoadSpaceResult r = load_space(path);
    if (r.ok()) return "";
    EXPECT_FALSE(r.pair.has_value());
    EXPECT_FALSE(r.space.has_value());
    return r.error->message();
  }

  // The example's space as JSON, edited by `edit`, then its load error.
  template <class Edit>
  std::string tampered_error(const std::string& name, Edit edit) {
    std::string text;
    write_space(name, &text);
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(text);
    edit(j);
    return load_error(j.dump(2));
  }
};

void expect_mentions(const std::string& message, const std::string& what) {
  EXPECT_NE(message.find(what), std::string::npos) << "'" << what << "' not in: " << message;
}

SpaceAnalysis analysis_of(const std::string& name) {
  const Pair pair = testkit::load_example(name);
  return analyze_space(pair, compute_space(pair));
}

}  // namespace

// ---- The embedded pair and the reader ---------------------------------------------------

// The embedded pair reads back to the same pair, curve for curve, bit for bit: loops keep
// the file's order and orientation, so features are numbered alike.
TEST(PairFile, RoundTripIsExact) {
  for (const char* name : kExamples) {
    const Pair pair = testkit::load_example(name);
    const LoadResult r = parse_pair(pair_file_text(pair), "embedded");
    ASSERT_TRUE(r.ok()) << name << ": " << r.error->message();
    const Pair& back = *r.pair;
    EXPECT_EQ(back.name, pair.name);
    EXPECT_EQ(back.units, pair.units);
    EXPECT_EQ(back.requested_tolerance, pair.requested_tolerance);
    EXPECT_EQ(back.tol.contact, pair.tol.contact) << name;
    for (const auto& [a, b] : {std::pair{&pair.moving, &back.moving}, {&pair.fixed, &back.fixed}}) {
      ASSERT_EQ(a->loops.size(), b->loops.size()) << name;
      EXPECT_EQ(a->enclosure, b->enclosure);
      EXPECT_EQ(a->features.size(), b->features.size()) << name;
      for (size_t l = 0; l < a->loops.size(); ++l) {
        ASSERT_EQ(a->loops[l].edges.size(), b->loops[l].edges.size()) << name;
        EXPECT_EQ(a->loops[l].reversed, b->loops[l].reversed) << name;
        for (size_t e = 0; e < a->loops[l].edges.size(); ++e) {
          const Curve &ca = a->loops[l].edges[e], &cb = b->loops[l].edges[e];
          EXPECT_TRUE(ca.from == cb.from && ca.to == cb.to)
              << name << " loop " << l << " edge " << e;
          EXPECT_EQ(ca.bulge, cb.bulge);
          EXPECT_TRUE(ca.center == cb.center) << name;
          EXPECT_EQ(ca.radius, cb.radius);
          EXPECT_EQ(ca.start_angle, cb.start_angle);
          EXPECT_EQ(ca.sweep, cb.sweep);
        }
      }
    }
  }
}

// Written, read back and written again, the file is the same (without timing): the reader
// rebuilds the very space, and everything the file states matched the recomputation.
TEST_F(SpaceFile, RoundTripOnTheExamples) {
  for (const char* name : kExamples) {
    const Pair pair = testkit::load_example(name);
    const SlicedSpace space = compute_space(pair);
    const std::string path = write_space(name);
    const LoadSpaceResult r = load_space(path, 2);
    ASSERT_TRUE(r.ok()) << name << ": " << r.error->message();
    EXPECT_FALSE(r.error.has_value());
    ASSERT_EQ(r.space->slices.size(), space.slices.size()) << name;
    for (size_t i = 0; i < space.slices.size(); ++i) {
      EXPECT_EQ(r.space->slices[i].theta, space.slices[i].theta) << name;
      EXPECT_EQ(r.space->slices[i].kind, space.slices[i].kind) << name;
      EXPECT_EQ(r.space->slices[i].slice.free_components.size(),
                space.slices[i].slice.free_components.size())
          << name;
    }
    EXPECT_EQ(r.space->criticals.orientations.size(), space.criticals.orientations.size());
    EXPECT_EQ(r.space->topology.components.size(), space.topology.components.size());
    EXPECT_EQ(space_to_json(*r.pair, *r.space, false), space_to_json(pair, space, false)) << name;
  }
}

TEST_F(SpaceFile, TruncatedJsonIsAClearError) {
  std::string text;
  write_space("cam", &text);
  const std::string e = load_error(text.substr(0, text.size() / 2));
  expect_mentions(e, "bad.json: ");
  expect_mentions(e, "invalid JSON at line");
  EXPECT_NE(load_error(""), "");
  expect_mentions(load_error("[1, 2]"), "the top level must be a JSON object");
}

TEST_F(SpaceFile, WrongFormatOrVersionIsRejected) {
  expect_mentions(tampered_error("cam", [](auto& j) { j["version"] = kSpaceFormatVersion + 1; }),
                  "bad.json: field \"version\": version 4 is newer than this cslice reads (3)");
  expect_mentions(tampered_error("cam", [](auto& j) { j["version"] = 1; }),
                  "field \"version\": version 1 files do not embed their pair");
  expect_mentions(tampered_error("cam", [](auto& j) { j["version"] = 2; }),
                  "field \"version\": version 2 files place their slices by an earlier plan");
  expect_mentions(tampered_error("cam", [](auto& j) { j["version"] = 0; }),
                  "field \"version\": version 0 is not a space file version");
  expect_mentions(tampered_error("cam", [](auto& j) { j["version"] = "3"; }),
                  "field \"version\": must be an integer, got string");
  expect_mentions(tampered_error("cam", [](auto& j) { j["format"] = "cslice-slice"; }),
                  "field \"format\": expected \"cslice-space\", got \"cslice-slice\"");
}

TEST_F(SpaceFile, MissingFieldIsNamed) {
  expect_mentions(tampered_error("cam", [](auto& j) { j.erase("pair_file"); }),
                  "bad.json: missing field \"pair_file\"");
  expect_mentions(tampered_error("cam", [](auto& j) { j["slices"][3].erase("kind"); }),
                  "missing field \"slices[3].kind\"");
  expect_mentions(tampered_error("cam", [](auto& j) { j["topology"].erase("free_components_3d"); }),
                  "missing field \"topology.free_components_3d\"");
  expect_mentions(tampered_error("cam", [](auto& j) { j["slices"][0]["theta"] = nullptr; }),
                  "field \"slices[0].theta\": must be a number, got null");
}

// A summary that no longer matches the recomputation is an error, never accepted.
TEST_F(SpaceFile, TamperedSummariesAreErrors) {
  expect_mentions(
      tampered_error("fastener", [](auto& j) { j["slices"][5]["free_components"] = 3; }),
      "field \"slices[5].free_components\": the file says 3, recomputed ");
  expect_mentions(
      tampered_error("cam", [](auto& j) { j["slices"][7]["components"][0]["area"] = 0.05; }),
      "field \"slices[7].components[0].area\": the file says 0.05");
  // The slices' summaries are read before the slices are recomputed, and checked after.
  expect_mentions(
      tampered_error("cam", [](auto& j) { j["slices"][7]["realizable_labels"][0][1] = 999; }),
      "field \"slices[7].realizable_labels\": differ from the recomputed ones [[");
  expect_mentions(
      tampered_error("cam", [](auto& j) { j["slices"][7]["realizable_labels"][0] = "x"; }),
      "field \"slices[7].realizable_labels\": differ from the recomputed ones [[");
  expect_mentions(
      tampered_error("cam", [](auto& j) { j["slices"][7]["components"][0]["area"] = "big"; }),
      "field \"slices[7].components[0].area\": must be a number, got string");
  expect_mentions(
      tampered_error("cam", [](auto& j) { j["slices"][7]["components"][0]["bounded"] = 1; }),
      "field \"slices[7].components[0].bounded\": must be true or false, got number");
  expect_mentions(tampered_error("cam", [](auto& j) { j["critical_orientations"].erase(0); }),
                  "field \"critical_orientations\": the file says 11, recomputed 12");
  expect_mentions(tampered_error("cam", [](auto& j) { j["slices"].erase(4); }),
                  "field \"slices\": the file says 175, recomputed 176");
  expect_mentions(
      tampered_error("fastener", [](auto& j) { j["topology"]["free_components_3d"] = 2; }),
      "field \"topology.free_components_3d\": the file says 2, recomputed 1");
  // Editing the pair changes what the summaries describe.
  expect_mentions(tampered_error("cam",
                                 [](auto& j) {
                                   j["pair_file"]["fixed"]["loops"][0][1][0] = 5.2;
                                   j["pair_file"]["fixed"]["loops"][0][2][0] = 5.2;
                                 }),
                  "bad.json: field \"");
  expect_mentions(tampered_error("cam", [](auto& j) { j["pair_file"]["moving"]["loops"] = 3; }),
                  "field \"pair_file\": part 'moving': \"loops\" must be an array");
  expect_mentions(tampered_error("cam", [](auto& j) { j["pair"] = "other"; }),
                  "field \"pair\": \"other\" but the embedded pair is named \"cam\"");
}

TEST_F(SpaceFile, UnreadablePathsAreErrors) {
  expect_mentions(load_space((dir_ / "missing.json").string()).error->message(), "cannot open");
  expect_mentions(load_space(dir_.string()).error->message(), "is a directory");
}

// ---- The analysis -----------------------------------------------------------------------

// The smallest extent: the free square of a unit disc in [-3, 3]^2 has side 4; the peg's
// free square in its hole at theta = 0 has side b - a = 1 (examples/README.md).
TEST(Analyze, ComponentMinWidth) {
  const Slice disc = compute_slice(testkit::load_example("disc-in-box"), 0.3);
  ASSERT_EQ(disc.free_components.size(), 1u);
  EXPECT_NEAR(component_min_width(disc.free_components[0]), 4.0, 1e-9);
  const Slice peg = compute_slice(testkit::load_example("square-peg-hole"), 0.0);
  const int inside = peg.locate({0, 0});
  ASSERT_GE(inside, 0);
  EXPECT_NEAR(component_min_width(peg.free_components[inside]), 1.0, 1e-9);
  // Turned by pi/4 the peg leaves a square of side b - a sqrt 2 = 3 - 2.828...
  const Slice turned = compute_slice(testkit::load_example("square-peg-hole"), kPi / 4);
  const int in_turned = turned.locate({0, 0});
  ASSERT_GE(in_turned, 0);
  EXPECT_NEAR(component_min_width(turned.free_components[in_turned]), 3.0 - 2.0 * std::sqrt(2.0),
              1e-9);
}

// The cam (paper 2.2; examples/README.md): one channel through every theta whose width, the
// backlash, is the follower clearance 10.2 - 10 = 0.2 at every slice.
TEST(Analyze, CamTurnsWithoutInterferenceWithBacklashTheClearance) {
  const SpaceAnalysis a = analysis_of("cam");
  EXPECT_EQ(a.application, "cam");
  ASSERT_EQ(a.components.size(), 1u);
  EXPECT_TRUE(a.components[0].spans_all_theta);
  EXPECT_NEAR(a.components[0].theta_coverage, kTwoPi, 1e-12);
  ASSERT_TRUE(a.channel.is_channel);
  const double backlash = 10.2 - 10.0;
  EXPECT_NEAR(a.channel.min_width, backlash, 1e-9);
  EXPECT_NEAR(a.channel.max_width, backlash, 1e-9);
  for (const SliceSummary& s : a.slices) {
    ASSERT_TRUE(s.channel_width.has_value()) << s.theta;
    EXPECT_NEAR(*s.channel_width, backlash, 1e-9) << s.theta;
    EXPECT_NEAR(s.free_area, backlash * backlash, 1e-9) << s.theta;
  }
  ASSERT_TRUE(a.cam.has_value());
  EXPECT_NEAR(a.cam->min_clearance, backlash, 1e-9);
  EXPECT_NEAR(a.cam->max_clearance, backlash, 1e-9);
  EXPECT_LT(a.cam->max_width_error, 1e-9);
  ASSERT_EQ(a.checks.size(), 2u);
  EXPECT_TRUE(a.all_checks_passed()) << a.checks[0].detail << "; " << a.checks[1].detail;
  for (const TransitionSummary& t : a.transitions) {
    ASSERT_EQ(t.events.size(), 1u);
    EXPECT_EQ(t.events[0].kind, TransitionKind::continues);
  }
}

// The fastener (paper 2.4; examples/README.md): one free component for |theta| in
// (1.2525, 1.8891), the pin near vertical, two otherwise; they meet at the critical
// orientations where the pin touches the opposite slot corners: 2.6 sin t - 1.5 cos t = 2,
// and their mirror images pi - t.
TEST(Analyze, FastenerOneComponentNearVerticalTwoOtherwise) {
  const SpaceAnalysis a = analysis_of("fastener");
  EXPECT_TRUE(a.all_checks_passed());
  ASSERT_TRUE(a.fastener.has_value());
  // 2.6 sin t - 1.5 cos t = 2: sqrt(2.6^2 + 1.5^2) sin(t - atan2(1.5, 2.6)) = 2.
  const double t = std::asin(2.0 / std::hypot(2.6, 1.5)) + std::atan2(1.5, 2.6);
  EXPECT_NEAR(t, 1.25251, 1e-5);
  const auto& ranges = a.fastener->one_component_ranges;
  ASSERT_EQ(ranges.size(), 2u);
  EXPECT_NEAR(ranges[0].first, -(kPi - t), 1e-9);
  EXPECT_NEAR(ranges[0].second, -t, 1e-9);
  EXPECT_NEAR(ranges[1].first, t, 1e-9);
  EXPECT_NEAR(ranges[1].second, kPi - t, 1e-9);
  for (const double end : {-(kPi - t), -t, t, kPi - t}) {
    bool found = false;
    for (const double m : a.fastener->meeting_thetas) found = found || std::abs(m - end) < 1e-9;
    EXPECT_TRUE(found) << end;
  }
  for (const SliceSummary& s : a.slices) {
    if (s.kind == SliceKind::critical) continue;
    const double at = std::abs(s.theta);
    EXPECT_EQ(s.free_components, at > t && at < kPi - t ? 1 : 2) << s.theta;
  }
  // Transitions where they meet: 2 components on one side, 1 on the other.
  for (const TransitionSummary& tr : a.transitions) {
    const bool meets =
        std::abs(std::abs(tr.theta) - t) < 1e-9 || std::abs(std::abs(tr.theta) - (kPi - t)) < 1e-9;
    if (!meets) continue;
    EXPECT_EQ(tr.components_before + tr.components_after, 3) << tr.theta;
    ASSERT_EQ(tr.events.size(), 1u);
    EXPECT_TRUE(tr.events[0].kind == TransitionKind::merge ||
                tr.events[0].kind == TransitionKind::split);
  }
}

// The fixture (paper 2.3; examples/README.md): the engaging configuration is contact and a
// strict local maximum of the theta = 0 slice: near it the contact space is the circle of
// radius 1.3 about (2.1, -2.0), so at distance d along it the boundary lies d^2 / 2.6 lower.
TEST(Analyze, FixtureEngagingConfigurationIsALocalMaximum) {
  const Pair pair = testkit::load_example("fixture");
  const SpaceAnalysis a = analyze_space(pair, compute_space(pair));
  ASSERT_TRUE(a.fixture.has_value());
  EXPECT_TRUE(a.all_checks_passed());
  EXPECT_EQ(a.fixture->placement, "contact");
  EXPECT_GE(a.fixture->component, 0);
  EXPECT_NEAR(a.fixture->highest_boundary_y, -0.7, 1e-9);
  EXPECT_EQ(a.fixture->upper_circle_points_free, 0);
  const double half = a.fixture->radius / 2;
  EXPECT_GE(a.fixture->drop, 1.3 - std::sqrt(1.3 * 1.3 - half * half) - 1e-9);
  // The same local picture by direct placement: higher or sideways is blocked, below free.
  EXPECT_EQ(classify(pair, {2.1, -0.69, 0}), Placement::blocked);
  EXPECT_EQ(classify(pair, {2.2, -0.7, 0}), Placement::blocked);
  EXPECT_EQ(classify(pair, {2.1, -0.75, 0}), Placement::free);
}

// The knee (paper 2.1): the configuration of Figure 1 is free and its 3D component gives the
// range of motion. The model has no ligaments, so the femur can be lifted clear and turned
// through every orientation: the range is the whole turn.
TEST(Analyze, KneeRangeOfMotion) {
  const SpaceAnalysis a = analysis_of("knee");
  ASSERT_TRUE(a.knee.has_value());
  EXPECT_TRUE(a.all_checks_passed());
  EXPECT_EQ(a.knee->component, 0);
  ASSERT_EQ(a.knee->range_of_motion.size(), 1u);
  EXPECT_NEAR(a.knee->coverage, kTwoPi, 1e-12);
}

TEST(Analyze, OtherPairsGetNoApplicationChecks) {
  const SpaceAnalysis a = analysis_of("square-peg-hole");
  EXPECT_TRUE(a.application.empty());
  EXPECT_TRUE(a.checks.empty());
  EXPECT_FALSE(a.channel.is_channel);  // two components: the hole and outside the plate
  const SpaceAnalysis disc = analysis_of("disc-in-box");
  ASSERT_TRUE(disc.channel.is_channel);
  EXPECT_NEAR(disc.channel.min_width, 4.0, 1e-9);
}

TEST(Analyze, JsonIsVersionedAndComplete) {
  const SpaceAnalysis a = analysis_of("cam");
  const nlohmann::json j = nlohmann::json::parse(analysis_to_json(a));
  EXPECT_EQ(j["format"], "cslice-analysis");
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["slices"].size(), a.slices.size());
  EXPECT_EQ(j["transitions"].size(), a.transitions.size());
  EXPECT_TRUE(j["channel"]["is_channel"].get<bool>());
  EXPECT_NEAR(j["slices"][0]["channel_width"].get<double>(), 0.2, 1e-9);
  EXPECT_TRUE(j["all_checks_passed"].get<bool>());
  EXPECT_EQ(j["checks"].size(), 2u);
}

// ---- The command ------------------------------------------------------------------------

class AnalyzeCli : public SpaceFile {};

TEST_F(AnalyzeCli, ReportsTheCamChannel) {
  const std::string path = write_space("cam");
  const testkit::RunResult r = testkit::run_cli("analyze " + testkit::quoted(path), dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  expect_mentions(r.out, "3D free components    1");
  expect_mentions(r.out, "channel: one bounded channel through every theta, width 0.2 to 0.2");
  expect_mentions(r.out, "[pass] one component spanning every theta");
  expect_mentions(r.out, "[pass] channel width equals the follower clearance");
  const testkit::RunResult j = testkit::run_cli("analyze --json " + testkit::quoted(path), dir_);
  ASSERT_EQ(j.status, 0) << j.err;
  EXPECT_EQ(nlohmann::json::parse(j.out)["pair"], "cam");
}

TEST_F(AnalyzeCli, BadFileExitsTwoWithNoOutput) {
  std::string text;
  write_space("fastener", &text);
  const auto bad = [&](const std::string& content, const std::string& what) {
    testkit::write_file(dir_ / "bad.json", content);
    for (const char* flags : {"", "--json "}) {
      const testkit::RunResult r = testkit::run_cli(
          std::string("analyze ") + flags + testkit::quoted((dir_ / "bad.json").string()), dir_);
      EXPECT_EQ(r.status, 2) << what;
      EXPECT_TRUE(r.out.empty()) << r.out;
      expect_mentions(r.err, "bad.json: ");
      expect_mentions(r.err, what);
    }
  };
  bad(text.substr(0, 1000), "invalid JSON");
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(text);
  j["slices"][0]["free_components"] = 7;
  bad(j.dump(), "slices[0].free_components");
  const testkit::RunResult r =
      testkit::run_cli("analyze " + testkit::quoted((dir_ / "none.json").string()), dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
}

// A failed check is a negative answer: the report, then exit status 1. The square peg in its
// hole, named "cam", is no channel.
TEST_F(AnalyzeCli, FailedCheckExitsOne) {
  Pair pair = testkit::load_example("square-peg-hole");
  pair.name = "cam";
  testkit::write_file(dir_ / "peg.json", space_to_json(pair, compute_space(pair)));
  const testkit::RunResult r =
      testkit::run_cli("analyze " + testkit::quoted((dir_ / "peg.json").string()), dir_);
  EXPECT_EQ(r.status, 1) << r.err;
  expect_mentions(r.out, "[FAIL] one component spanning every theta");
}

TEST_F(AnalyzeCli, ComputeThenAnalyzeEveryPaperExample) {
  for (const char* name : {"knee", "cam", "fixture", "fastener"}) {
    const std::string out = (dir_ / (std::string(name) + ".json")).string();
    ASSERT_EQ(testkit::run_cli("compute " + testkit::quoted(testkit::example_path(name)) + " -o " +
                                   testkit::quoted(out),
                               dir_)
                  .status,
              0);
    const testkit::RunResult r = testkit::run_cli("analyze " + testkit::quoted(out), dir_);
    EXPECT_EQ(r.status, 0) << name << ": " << r.out << r.err;
    EXPECT_EQ(r.out.find("[FAIL]"), std::string::npos) << r.out;
  }
}
