// `cslice path`: exit 0 with one certified configuration a line (or JSON), exit 1 with the
// reason when there is no path (different components, an end blocked or in contact), exit 2
// with nothing on standard output for bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cslice/classify.hpp"
#include "support/cli_run.hpp"
#include "support/examples.hpp"

using namespace cslice;
namespace fs = std::filesystem;

namespace {

class PathCli : public testkit::ScratchDirTest {
 protected:
  PathCli() : ScratchDirTest("cslice_path") {}

  // The square peg and plate: inside the hole and outside the plate are two components.
  std::string space() {
    const std::string path = (dir_ / "peg-space.json").string();
    const testkit::RunResult r =
        testkit::run_cli("compute " + testkit::quoted(testkit::example_path("square-peg-hole")) +
                             " -o " + testkit::quoted(path),
                         dir_);
    EXPECT_EQ(r.status, 0) << r.err;
    return path;
  }

  testkit::RunResult path(const std::string& space_path, const std::string& args) {
    return testkit::run_cli("path " + testkit::quoted(space_path) + " " + args, dir_);
  }
};

std::vector<Pose> read_lines(const std::string& text) {
  std::vector<Pose> poses;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    Pose p;
    std::string extra;
    EXPECT_TRUE(words >> p.x >> p.y >> p.theta) << line;
    EXPECT_FALSE(words >> extra) << line;
    poses.push_back(p);
  }
  return poses;
}

}  // namespace

TEST_F(PathCli, PrintsOneFreeConfigurationPerLine) {
  const std::string s = space();
  const testkit::RunResult r = path(s, "--from 0.2,0.1,0 --to 0,0,0.7853981633974483");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<Pose> poses = read_lines(r.out);
  ASSERT_GE(poses.size(), 2u) << r.out;
  EXPECT_EQ(poses.front().x, 0.2);
  EXPECT_EQ(poses.front().y, 0.1);
  EXPECT_EQ(poses.back().theta, 0.7853981633974483);
  const Pair pair = testkit::load_example("square-peg-hole");
  PlacementTester tester(pair);
  for (const Pose& p : poses) EXPECT_EQ(tester.classify(p), Placement::free);
}

TEST_F(PathCli, JsonAndOutputFile) {
  const std::string s = space();
  const fs::path out = dir_ / "path.json";
  const testkit::RunResult r =
      path(s, "--from 0.2,0.1,0 --to -0.05,0.05,1 --json -o " + testkit::quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  const nlohmann::json j = nlohmann::json::parse(testkit::read_file(out));
  EXPECT_EQ(j.at("status"), "found");
  EXPECT_EQ(j.at("from"), nlohmann::json::parse("[0.2, 0.1, 0.0]"));
  const auto& poses = j.at("path");
  ASSERT_GE(poses.size(), 2u);
  EXPECT_EQ(poses.size(), j.at("clearance").size());
  EXPECT_EQ(poses.back(), nlohmann::json::parse("[-0.05, 0.05, 1.0]"));
  EXPECT_EQ(j.at("component"), j.at("start").at("component"));
  EXPECT_GT(j.at("reach").get<double>(), 1.41);
  EXPECT_EQ(j.at("contact_tolerance").get<double>(), 0.001);
}

TEST_F(PathCli, DifferentComponentsIsExitOneNamingThem) {
  const std::string s = space();
  const testkit::RunResult r = path(s, "--from 0,0,0 --to 8,0,0");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("no path: start is in free component"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", goal in free component"), std::string::npos) << r.out;
  const testkit::RunResult j = path(s, "--from 0,0,0 --to 8,0,0 --json");
  EXPECT_EQ(j.status, 1);
  const nlohmann::json answer = nlohmann::json::parse(j.out);
  EXPECT_EQ(answer.at("status"), "different_components");
  EXPECT_NE(answer.at("start").at("component"), answer.at("goal").at("component"));
  EXPECT_FALSE(answer.contains("path"));
}

TEST_F(PathCli, EndNotFreeIsExitOneSayingWhichAndWhat) {
  const std::string s = space();
  const testkit::RunResult blocked = path(s, "--from 1.5,0,0 --to 0,0,0");
  EXPECT_EQ(blocked.status, 1);
  EXPECT_NE(blocked.out.find("the start (1.5, 0, 0) is blocked"), std::string::npos) << blocked.out;
  EXPECT_NE(blocked.out.find("moving feature"), std::string::npos) << blocked.out;
  const testkit::RunResult contact = path(s, "--from 0,0,0 --to 0.5,0,0");
  EXPECT_EQ(contact.status, 1);
  EXPECT_NE(contact.out.find("the goal (0.5, 0, 0) is in contact: moving feature"),
            std::string::npos)
      << contact.out;
}

TEST_F(PathCli, BadInputIsExitTwoWithNothingPrinted) {
  const std::string s = space();
  for (const std::string& args :
       {std::string("--from 1,2 --to 0,0,0"), std::string("--from 0,0,0 --to a,b,c"),
        std::string("--from 0,0,0 --to 0,0,nan"), std::string("--from 0,0,0")}) {
    const testkit::RunResult r = path(s, args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_TRUE(r.out.empty()) << args << ": " << r.out;
    EXPECT_FALSE(r.err.empty()) << args;
  }
  EXPECT_NE(path(s, "--from 1,2 --to 0,0,0").err.find("--from"), std::string::npos);
  testkit::write_file(dir_ / "bad.json", "{\"format\": \"cslice-space\"");
  const testkit::RunResult bad = path((dir_ / "bad.json").string(), "--from 0,0,0 --to 0.1,0,0");
  EXPECT_EQ(bad.status, 2);
  EXPECT_TRUE(bad.out.empty());
  EXPECT_NE(bad.err.find("bad.json"), std::string::npos) << bad.err;
  const testkit::RunResult missing =
      path((dir_ / "none.json").string(), "--from 0,0,0 --to 0.1,0,0");
  EXPECT_EQ(missing.status, 2);
  EXPECT_TRUE(missing.out.empty());
}
