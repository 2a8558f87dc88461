// The sliced configuration space: which orientations are sliced, the interpolation step, the
// correspondence of contact segments, determinism under threads, and the `cslice compute`
// and `cslice stats` commands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "cslice/space.hpp"
#include "support/cli_run.hpp"
#include "support/completeness.hpp"
#include "support/examples.hpp"
#include "support/random_parts.hpp"
#include "support/random_polygons.hpp"

using namespace cslice;

namespace {

// Round-off slack when comparing angles built as a + L k / m (radians).
constexpr double kAngleSlack = 1e-12;

const char* const kPaperExamples[] = {"knee", "cam", "fixture", "fastener"};

int count_kind(const SlicedSpace& space, SliceKind kind) {
  int n = 0;
  for (const SpaceSlice& s : space.slices) n += s.kind == kind ? 1 : 0;
  return n;
}

// Gap from slice i to the next, cyclically (the last one's successor is the first + 2 pi).
double gap_after(const SlicedSpace& space, size_t i) {
  const size_t n = space.slices.size();
  const double next = i + 1 < n ? space.slices[i + 1].theta : space.slices[0].theta + kTwoPi;
  return next - space.slices[i].theta;
}

// No interval has more slices than keeping them max_step apart needs: an interval of
// length L gets ceil(L / max_step) - 1 inner slices, and at least one (its representative).
void expect_fewest_slices(const SlicedSpace& space, const std::string& name) {
  const auto& criticals = space.criticals.orientations;
  if (criticals.empty()) return;
  std::map<int, int> inner;  // per interval, its non-critical slices
  for (const SpaceSlice& s : space.slices)
    if (s.kind != SliceKind::critical) inner[s.interval] += 1;
  const int n = static_cast<int>(criticals.size());
  for (int i = 0; i < n; ++i) {
    const double end = i + 1 < n ? criticals[i + 1].theta : criticals[0].theta + kTwoPi;
    const double length = end - criticals[i].theta;
    const int parts = std::max(2, static_cast<int>(std::ceil(length / space.max_step)));
    EXPECT_EQ(inner[i], parts - 1) << name << ": interval " << i << " of length " << length;
  }
}

// A critical orientation covers its group's span, from its first criticality to its last
// (docs/criticals.md, grouping): every other slice lies strictly between two spans, in the
// open interval the topology gives it.
void expect_slices_between_spans(const SlicedSpace& space, const std::string& name) {
  const auto& criticals = space.criticals.orientations;
  const int n = static_cast<int>(criticals.size());
  if (n == 0) return;
  std::vector<std::pair<double, double>> spans;  // unwrapped around each orientation's theta
  for (const CriticalOrientation& o : criticals) {
    const std::vector<double> at = testkit::group_thetas(o);
    spans.push_back({at.front(), at.back()});
  }
  for (const SpaceSlice& s : space.slices) {
    if (s.kind == SliceKind::critical) continue;
    const int i = s.interval;
    const double after = wrap_angle(s.theta - spans[i].second);
    const double next_first = i + 1 < n ? spans[i + 1].first : spans[0].first + kTwoPi;
    const double before = wrap_angle(next_first - s.theta);
    EXPECT_GT(after, 0.0) << name << ": slice at " << s.theta << " inside the span of orientation "
                          << i;
    EXPECT_GT(before, 0.0) << name << ": slice at " << s.theta
                           << " inside the span of the orientation after interval " << i;
  }
}

// The structural promises every computed space keeps.
void expect_well_formed(const SlicedSpace& space, const std::string& name) {
  const size_t criticals = space.criticals.orientations.size();
  ASSERT_FALSE(space.slices.empty()) << name;
  EXPECT_GE(space.slices.size(), 2 * criticals) << name;
  EXPECT_EQ(count_kind(space, SliceKind::critical), static_cast<int>(criticals)) << name;
  EXPECT_EQ(count_kind(space, SliceKind::interval),
            static_cast<int>(std::max<size_t>(1, criticals)))
      << name;
  for (size_t i = 0; i < space.slices.size(); ++i) {
    const SpaceSlice& s = space.slices[i];
    EXPECT_GE(s.theta, -kPi) << name;
    EXPECT_LT(s.theta, kPi) << name;
    EXPECT_EQ(s.slice.theta, s.theta) << name;
    EXPECT_GT(gap_after(space, i), 0.0) << name << ": slices " << i << " out of order";
    EXPECT_LE(gap_after(space, i), space.max_step + kAngleSlack) << name << " after slice " << i;
  }
  expect_fewest_slices(space, name);
  expect_slices_between_spans(space, name);
}

// The correspondence is the set algebra of the two slices' labels.
void expect_correspondence_consistent(const SlicedSpace& space) {
  ASSERT_EQ(space.correspondence.size(), space.slices.size());
  for (size_t i = 0; i < space.correspondence.size(); ++i) {
    const SliceCorrespondence& c = space.correspondence[i];
    ASSERT_EQ(c.from, static_cast<int>(i));
    ASSERT_EQ(c.to, static_cast<int>((i + 1) % space.slices.size()));
    std::vector<SegmentLabel> from = c.kept, to = c.kept;
    from.insert(from.end(), c.vanishing.begin(), c.vanishing.end());
    to.insert(to.end(), c.appearing.begin(), c.appearing.end());
    std::sort(from.begin(), from.end());
    std::sort(to.begin(), to.end());
    EXPECT_EQ(from, realizable_labels(space.slices[c.from].slice));
    EXPECT_EQ(to, realizable_labels(space.slices[c.to].slice));
  }
}

// The contact segments at theta by label, where the label makes exactly one.
std::map<SegmentLabel, Curve> single_segments(const Pair& pair, double theta) {
  std::map<SegmentLabel, Curve> out;
  std::map<SegmentLabel, int> count;
  for (const ContactSegment& s : contact_segments(pair, theta)) {
    const SegmentLabel label{s.moving_feature, s.fixed_feature};
    count[label] += 1;
    out[label] = s.curve;
  }
  std::erase_if(out, [&](const auto& entry) { return count[entry.first] != 1; });
  return out;
}

// Largest distance, at the middle of [a, b], between a defining point of a contact segment
// and the average of its positions at a and b.
double interpolation_error(const Pair& pair, double a, double b) {
  const auto at_a = single_segments(pair, a), at_b = single_segments(pair, b);
  double worst = 0.0;
  for (const auto& [label, mid] : single_segments(pair, (a + b) / 2)) {
    if (!at_a.count(label) || !at_b.count(label)) continue;
    const Curve &ca = at_a.at(label), &cb = at_b.at(label);
    if (mid.is_arc() != ca.is_arc() || mid.is_arc() != cb.is_arc()) continue;
    const auto error = [](Vec2 p, Vec2 q, Vec2 m) { return distance(lerp(p, q, 0.5), m); };
    if (mid.is_arc()) {
      worst = std::max(worst, error(ca.center, cb.center, mid.center));
    } else {
      worst = std::max(worst, error(ca.from, cb.from, mid.from));
      worst = std::max(worst, error(ca.to, cb.to, mid.to));
    }
  }
  return worst;
}

SpaceOptions with_threads(int threads) {
  SpaceOptions o;
  o.threads = threads;
  return o;
}

}  // namespace

// ---- Library ----------------------------------------------------------------------------

TEST(Space, InterpolationStepBoundsTheSagitta) {
  const double reach = 2.5, tol = 1e-3;
  const double step = interpolation_step(reach, tol);
  EXPECT_DOUBLE_EQ(step, std::sqrt(8 * tol / reach));
  // The exact sagitta of a point at the reach, turned by one step, is within the tolerance.
  EXPECT_LE(reach * (1 - std::cos(step / 2)), tol);
  EXPECT_DOUBLE_EQ(interpolation_step(0.0, tol), kPi / 2);
  EXPECT_DOUBLE_EQ(interpolation_step(1e-9, 1.0), kPi / 2);
}

TEST(Space, PaperExamplesAreWellFormed) {
  for (const char* name : kPaperExamples) {
    const Pair pair = testkit::load_example(name);
    const SlicedSpace space = compute_space(pair, with_threads(2));
    expect_well_formed(space, name);
    expect_correspondence_consistent(space);
    EXPECT_GT(space.reach, 0.0) << name;
    EXPECT_GE(space.seconds_criticals, 0.0);
    EXPECT_GE(space.seconds_slices, 0.0);
  }
}

// Random curved pairs (the stress seeds of tests/test_critical_completeness.cpp's span case
// among them: groups there spread over 10^-8 rad) keep the same promises.
TEST(Space, RandomCurvedPairsAreWellFormed) {
  for (unsigned seed = 100220; seed < 100236; ++seed) {
    const testkit::RandomPair p = testkit::stress_pair(seed);
    const SlicedSpace space = compute_space(p.pair, with_threads(2));
    expect_well_formed(space, "random pair " + std::to_string(seed));
    expect_correspondence_consistent(space);
  }
}

// The bound itself, measured: halfway between two consecutive slices of an interval, the
// defining points of every contact segment (a line's ends, an arc's centre) lie within the
// tolerance of the average of their positions in the two slices.
TEST(Space, InterpolationBetweenSlicesStaysWithinTheTolerance) {
  for (const char* name : kPaperExamples) {
    const Pair pair = testkit::load_example(name);
    const SlicedSpace space = compute_space(pair);
    double worst = 0.0;
    for (size_t i = 0; i + 1 < space.slices.size(); ++i) {
      const double a = space.slices[i].theta, b = space.slices[i + 1].theta;
      worst = std::max(worst, interpolation_error(pair, a, b));
    }
    EXPECT_LE(worst, pair.tol.contact) << name;
    EXPECT_GT(worst, pair.tol.contact / 100) << name << ": the bound is far from tight";
  }
}

// The fastener is symmetric: its criticals come from a fundamental domain and most of its
// slices are mapped (docs/symmetry.md), the same whatever the thread count too.
TEST(Space, SameJsonWhateverTheThreadCount) {
  for (const char* name : {"knee", "fastener"}) {
    const Pair pair = testkit::load_example(name);
    const std::string one = space_to_json(pair, compute_space(pair, with_threads(1)), false);
    const std::string two = space_to_json(pair, compute_space(pair, with_threads(2)), false);
    EXPECT_EQ(one, two) << name;
    EXPECT_EQ(one.find("timing"), std::string::npos) << name;
  }
}

// The file is written a slice and a correspondence at a time, not as one document (which
// took more memory than the space itself); its text is still exactly that document's dump.
TEST(Space, TheFileIsTheDumpOfOneDocument) {
  for (const char* name : {"knee", "fastener"}) {
    const Pair pair = testkit::load_example(name);
    const SlicedSpace space = compute_space(pair, with_threads(2));
    const std::string text = space_to_json(pair, space, true);
    const nlohmann::ordered_json document = nlohmann::ordered_json::parse(text);
    // Compared by the first difference: a diff of two texts this long would take minutes.
    const std::string dumped = document.dump(2) + "\n";
    const size_t differ =
        std::mismatch(dumped.begin(), dumped.end(), text.begin(), text.end()).first -
        dumped.begin();
    EXPECT_TRUE(dumped == text) << name << ": first difference at byte " << differ << ": '"
                                << text.substr(differ, 40) << "' instead of '"
                                << dumped.substr(differ, 40) << "'";
    EXPECT_EQ(document["slices"].size(), space.slices.size()) << name;
    EXPECT_EQ(document["correspondence"].size(), space.correspondence.size()) << name;
    // `cslice compute` writes the same text to its file as it is made.
    std::ostringstream streamed;
    write_space_json(streamed, pair, space, true);
    EXPECT_TRUE(streamed.str() == text) << name;
  }
}

// A unit disc in the box [-3, 3]^2 (examples/disc-in-box.json, tolerance 0.001): turning a
// disc about its centre changes nothing, so there is no critical orientation and no contact
// point moves (reach 0): the slices are spaced evenly by the capped step, pi / 2, and each
// has one free component, the square [-(s - r), s - r]^2 with s = 3, r = 1: area
// (2 (s - r))^2 = 16.
TEST(Space, DiscInBoxHasEvenlySpacedIdenticalSlices) {
  const Pair pair = testkit::load_example("disc-in-box");
  const SlicedSpace space = compute_space(pair);
  EXPECT_TRUE(space.criticals.orientations.empty());
  EXPECT_DOUBLE_EQ(space.reach, 0.0);
  EXPECT_DOUBLE_EQ(space.max_step, kPi / 2);
  expect_well_formed(space, "disc-in-box");
  expect_correspondence_consistent(space);
  const int expected = 4;
  ASSERT_EQ(static_cast<int>(space.slices.size()), expected);
  EXPECT_DOUBLE_EQ(space.slices.front().theta, -kPi);
  const double s = 3.0, r = 1.0;
  for (size_t i = 0; i < space.slices.size(); ++i) {
    EXPECT_NEAR(gap_after(space, i), kTwoPi / expected, 1e-12);
    const Slice& slice = space.slices[i].slice;
    ASSERT_EQ(slice.free_components.size(), 1u) << "slice " << i;
    EXPECT_TRUE(slice.free_components[0].bounded);
    EXPECT_NEAR(slice.free_components[0].area, std::pow(2 * (s - r), 2), 1e-9);
  }
  for (const SliceCorrespondence& c : space.correspondence) {
    EXPECT_EQ(c.kept.size(), 4u);  // the disc on each of the four walls, throughout
    EXPECT_TRUE(c.appearing.empty());
    EXPECT_TRUE(c.vanishing.empty());
  }
}

// ---- The commands -----------------------------------------------------------------------

class SpaceCli : public testkit::ScratchDirTest {
 protected:
  SpaceCli() : ScratchDirTest("cslice_space") {}

  testkit::RunResult compute(const std::string& pair, const std::string& out,
                             const std::string& extra = "") {
    return testkit::run_cli("compute " + testkit::quoted(pair) + " -o " + testkit::quoted(out) +
                                (extra.empty() ? "" : " " + extra),
                            dir_);
  }
};

TEST_F(SpaceCli, ComputeWritesAParseableVersionedFile) {
  const std::string out = (dir_ / "space.json").string();
  const testkit::RunResult r = compute(testkit::example_path("fastener"), out);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(testkit::read_file(out));
  EXPECT_EQ(j["format"], "cslice-space");
  EXPECT_EQ(j["version"], kSpaceFormatVersion);
  EXPECT_EQ(j["pair"], "fastener");
  ASSERT_TRUE(j["slices"].is_array());
  EXPECT_EQ(j["slices"].size(), j["counts"]["slices"].get<size_t>());
  EXPECT_EQ(j["correspondence"].size(), j["slices"].size());
  EXPECT_GE(j["slices"].size(), 2 * j["critical_orientations"].size());
  const nlohmann::json& first = j["slices"][0];
  for (const char* field :
       {"theta", "kind", "interval", "free_components", "bounded_free_components", "components",
        "realizable_labels", "contact_graph_edges"})
    EXPECT_TRUE(first.contains(field)) << field;
  EXPECT_TRUE(j["timing"]["slices_seconds"].is_number());
}

TEST_F(SpaceCli, ThreadCountChangesOnlyTheTiming) {
  const std::string a = (dir_ / "one.json").string(), b = (dir_ / "two.json").string();
  ASSERT_EQ(compute(testkit::example_path("knee"), a, "--threads 1").status, 0);
  ASSERT_EQ(compute(testkit::example_path("knee"), b, "--threads 2").status, 0);
  nlohmann::json ja = nlohmann::json::parse(testkit::read_file(a));
  nlohmann::json jb = nlohmann::json::parse(testkit::read_file(b));
  ja.erase("timing");
  jb.erase("timing");
  EXPECT_EQ(ja.dump(), jb.dump());
}

// More threads than cores are as many as cores: the same space, and nothing on standard
// error. oneTBB warned there ("the number of workers is currently limited") and crashed when
// asked for more than 65,536 (`--threads 100000`).
TEST_F(SpaceCli, MoreThreadsThanCoresComputeTheSameSpaceQuietly) {
  const std::string one = (dir_ / "one.json").string();
  ASSERT_EQ(compute(testkit::example_path("cam"), one, "--threads 1").status, 0);
  nlohmann::json expected = nlohmann::json::parse(testkit::read_file(one));
  expected.erase("timing");
  for (const char* threads : {"64", "100000"}) {
    const std::string many = (dir_ / (std::string(threads) + ".json")).string();
    const testkit::RunResult r =
        compute(testkit::example_path("cam"), many, std::string("--threads ") + threads);
    ASSERT_EQ(r.status, 0) << threads;
    EXPECT_EQ(r.err, "") << threads;
    nlohmann::json got = nlohmann::json::parse(testkit::read_file(many));
    got.erase("timing");
    EXPECT_EQ(got.dump(), expected.dump()) << threads;
  }
}

// Out of memory is said as such, exit 3 and no file: a pair too large for the machine (here a
// 600-feature star pair, which needs about 4 GB, with 300 MB allowed) was reported as
// "internal error: std::bad_alloc".
TEST_F(SpaceCli, OutOfMemoryIsSaidAndWritesNothing) {
  std::mt19937 rng(2176);
  const testkit::StarPairLoops star = testkit::lobed_star_pair(rng, 150, 0.0, 0.0);
  const std::filesystem::path pair = dir_ / "star.json", out = dir_ / "star-space.json";
  testkit::write_file(pair, testkit::pair_json("star", {star.moving}, {star.fixed}));
  const testkit::RunResult r = testkit::run_cli_with_memory_limit(
      // One thread: no worker stacks to count against the limit, whatever the machine.
      "compute " + testkit::quoted(pair.string()) + " -o " + testkit::quoted(out.string()) +
          " --threads 1",
      dir_, 300000);
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("out of memory"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// --from-scratch computes every slice (none evaluated from its interval's structure): the
// same slices by their summaries and the same topology; only the count of evaluated side
// slices tells them apart.
TEST_F(SpaceCli, FromScratchGivesTheSameSpace) {
  const std::string a = (dir_ / "evaluated.json").string(), b = (dir_ / "scratch.json").string();
  ASSERT_EQ(compute(testkit::example_path("fastener"), a).status, 0);
  ASSERT_EQ(compute(testkit::example_path("fastener"), b, "--from-scratch").status, 0);
  nlohmann::json ja = nlohmann::json::parse(testkit::read_file(a));
  nlohmann::json jb = nlohmann::json::parse(testkit::read_file(b));
  EXPECT_GT(ja["topology"]["checks"]["side_slices_evaluated"].get<int>(), 0);
  EXPECT_EQ(jb["topology"]["checks"]["side_slices_evaluated"].get<int>(), 0);
  for (const char* key : {"transitions", "components", "slice_components"})
    EXPECT_EQ(ja["topology"][key], jb["topology"][key]) << key;
  ASSERT_EQ(ja["slices"].size(), jb["slices"].size());
  for (size_t i = 0; i < ja["slices"].size(); ++i)
    for (const char* key : {"free_components", "realizable_labels", "contact_graph_edges"})
      EXPECT_EQ(ja["slices"][i][key], jb["slices"][i][key]) << "slice " << i << " " << key;
}

TEST_F(SpaceCli, ProgressShowsOnATerminalOnly) {
  const std::string out = (dir_ / "space.json").string();
  const testkit::RunResult piped = compute(testkit::example_path("cam"), out);
  ASSERT_EQ(piped.status, 0);
  EXPECT_EQ(piped.err, "");
  // script(1) (util-linux, in every Debian) gives the command a terminal; its output is what
  // the terminal showed.
  const std::string command = testkit::quoted(CSLICE_CLI_PATH) + " compute " +
                              testkit::quoted(testkit::example_path("cam")) + " -o " +
                              testkit::quoted(out);
  const std::string log = (dir_ / "terminal.txt").string();
  ASSERT_EQ(std::system(("script -qec " + testkit::quoted(command) + " /dev/null > " +
                         testkit::quoted(log) + " 2>&1 < /dev/null")
                            .c_str()),
            0);
  const std::string shown = testkit::read_file(log);
  EXPECT_NE(shown.find("cslice compute: critical orientations"), std::string::npos) << shown;
  EXPECT_NE(shown.find("cslice compute: slices"), std::string::npos) << shown;
  EXPECT_NE(shown.find("\033[K"), std::string::npos) << "the line is cleared at the end";
}

TEST_F(SpaceCli, BadInputExitsTwoWithNoFile) {
  testkit::write_file(dir_ / "bad.json", "{\"name\": 3");
  const std::string out = (dir_ / "space.json").string();
  const testkit::RunResult r = compute((dir_ / "bad.json").string(), out);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  for (const auto& entry : std::filesystem::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename().string().find("space.json"), std::string::npos);
}

// The lines of a command's output.
std::vector<std::string> lines_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST_F(SpaceCli, StatsPrintsOneMarkdownRowPerPair) {
  const testkit::RunResult r =
      testkit::run_cli("stats " + testkit::quoted(testkit::example_path("disc-in-box")) + " " +
                           testkit::quoted(testkit::example_path("square-peg-hole")),
                       dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 4u) << r.out;  // header, alignment row, one row per pair
  EXPECT_EQ(lines[1].rfind("| :---", 0), 0u);
  EXPECT_EQ(lines[2].rfind("| disc-in-box | 9 (1+8) | 0 (0) |", 0), 0u) << lines[2];
  EXPECT_EQ(lines[3].rfind("| square-peg-hole |", 0), 0u) << lines[3];
  const auto columns = [](const std::string& s) { return std::count(s.begin(), s.end(), '|'); };
  for (const std::string& line : lines) EXPECT_EQ(columns(line), 10) << line;
  EXPECT_NE(lines[2].find("| 1 (4 of 4 slices) |"), std::string::npos) << lines[2];
}

// The row with its three time cells (criticals, slices, total) blanked: all that may differ
// from run to run.
std::string without_times(const std::string& row) {
  std::vector<std::string> cells;
  std::istringstream in(row);
  for (std::string cell; std::getline(in, cell, '|');) cells.push_back(cell);
  for (size_t i : {4u, 6u, 7u}) cells.at(i) = " t ";  // cells[0] is before the first bar
  std::string out;
  for (const std::string& c : cells) out += c + "|";
  return out;
}

TEST_F(SpaceCli, StatsRunsRepeatsAndKeepsTheTable) {
  const std::string pair = testkit::quoted(testkit::example_path("cam"));
  const testkit::RunResult once = testkit::run_cli("stats " + pair, dir_);
  const testkit::RunResult thrice = testkit::run_cli("stats --runs 3 " + pair, dir_);
  ASSERT_EQ(once.status, 0) << once.err;
  ASSERT_EQ(thrice.status, 0) << thrice.err;
  const std::vector<std::string> a = lines_of(once.out), b = lines_of(thrice.out);
  ASSERT_EQ(a.size(), 3u) << once.out;
  ASSERT_EQ(b.size(), 3u) << thrice.out;
  EXPECT_EQ(a[0], b[0]);
  EXPECT_EQ(without_times(a[2]), without_times(b[2])) << a[2] << "\n" << b[2];
  EXPECT_EQ(b[2].rfind("| cam | 16 (8+8) |", 0), 0u) << b[2];
}

TEST_F(SpaceCli, StatsRejectsRunsBelowOne) {
  for (const char* runs : {"0", "-2"}) {
    const testkit::RunResult r = testkit::run_cli(
        std::string("stats --runs ") + runs + " " + testkit::quoted(testkit::example_path("cam")),
        dir_);
    EXPECT_EQ(r.status, 2) << runs;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_NE(r.err.find("--runs"), std::string::npos) << r.err;
  }
}

TEST_F(SpaceCli, StatsOnBadInputPrintsNothing) {
  testkit::write_file(dir_ / "bad.json", "{\"name\": 3");
  const testkit::RunResult r =
      testkit::run_cli("stats " + testkit::quoted(testkit::example_path("cam")) + " " +
                           testkit::quoted((dir_ / "bad.json").string()),
                       dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
}
