// Robustness of the pair reader: thousands of seeded mutations of valid pair files must each
// come back as a pair or as an error with a message, quickly, never as a crash or a hang.
// Also the `cslice info` exit statuses on a bad and a good file.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cslice/pair.hpp"
#include "support/cli_run.hpp"
#include "support/mutations.hpp"

namespace cslice {
namespace {

const std::vector<std::string> kSeeds = {
    R"({"name": "peg", "units": "mm", "tolerance": 0.01,
        "moving": {"loops": [[[0,0],[1,0],[1,1],[0,1]]]},
        "fixed": {"loops": [[[-5,-5],[5,-5],[5,5],[-5,5]], [[-1,-1],[-1,2],[2,2],[2,-1]]]}})",
    R"({"moving": {"loops": [{"circle": [0.5, 0, 1]}, [[0,0,1],[1,0]]]},
        "fixed": {"loops": [[[-9,-9],[9,-9],[9,9],[-9,9]]], "enclosure": true}})",
    R"({"name": "cam", "moving": {"loops": [[[0,0],[4,0,-0.5],[4,2],[2,2],[2,4,1],[0,4]]]},
        "fixed": {"loops": [[[10,0,0.4],[20,0],[20,10,-0.3],[10,10]], {"circle": [15,5,1]}],
                  "enclosure": false}})",
};

TEST(ReaderFuzz, SeedsAreValid) {
  for (const std::string& seed : kSeeds) {
    const LoadResult r = parse_pair(seed, "seed.json");
    EXPECT_TRUE(r.ok()) << r.error->message();
  }
}

TEST(ReaderFuzz, MutationsNeverCrashOrHang) {
  constexpr int kIterationsPerSeed = 15000;
  const auto budget = std::chrono::seconds(2);  // per parse; a hang shows as a failure here
  int accepted = 0, rejected = 0;
  for (size_t seed_index = 0; seed_index < kSeeds.size(); ++seed_index) {
    testkit::TextMutator mutator(1234u + static_cast<unsigned>(seed_index));
    for (int it = 0; it < kIterationsPerSeed; ++it) {
      const std::string text = mutator.mutate(kSeeds[seed_index]);
      const auto start = std::chrono::steady_clock::now();
      const LoadResult r = parse_pair(text, "fuzz.json");
      const auto elapsed = std::chrono::steady_clock::now() - start;
      ASSERT_LT(elapsed, budget) << text;
      ASSERT_NE(r.ok(), r.error.has_value()) << text;
      if (r.ok()) {
        ++accepted;
        EXPECT_GT(r.pair->tol.size, 0.0) << text;
        EXPECT_FALSE(r.pair->moving.loops.empty());
        EXPECT_FALSE(r.pair->fixed.loops.empty());
      } else {
        ++rejected;
        ASSERT_FALSE(r.error->reason.empty()) << text;
        ASSERT_EQ(r.error->message().rfind("fuzz.json: ", 0), 0u) << r.error->message();
        ASSERT_EQ(r.error->reason.find("internal error"), std::string::npos)
            << r.error->message() << "\n"
            << text;
      }
    }
  }
  // Both outcomes must occur, or the mutations are not exercising the reader.
  EXPECT_GT(accepted, 100);
  EXPECT_GT(rejected, 100);
  std::cout << "accepted " << accepted << ", rejected " << rejected << "\n";
}

// ---- The CLI ------------------------------------------------------------------------------

using testkit::run_cli;
using testkit::RunResult;
using testkit::write_file;

class InfoCli : public testkit::ScratchDirTest {
 protected:
  InfoCli() : ScratchDirTest("cslice_info_cli") {}
  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto p = dir_ / name;
    write_file(p, text);
    return p;
  }
};

TEST_F(InfoCli, BadFileExitsTwoWithMessageOnStderr) {
  const auto bad = write("bad.json", R"({"moving": {"loops": [[[0,0],[2,2],[2,0],[0,2]]]},
      "fixed": {"loops": [[[-5,-5],[5,-5],[5,5],[-5,5]]]}})");
  const RunResult r = run_cli("info '" + bad.string() + "'", dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("bad.json: part 'moving', loop 0, vertex 0: loop crosses"),
            std::string::npos)
      << r.err;
}

TEST_F(InfoCli, MissingFileExitsTwo) {
  const RunResult r = run_cli("info '" + (dir_ / "missing.json").string() + "' --json", dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("cannot open"), std::string::npos) << r.err;
}

TEST_F(InfoCli, GoodFileExitsZero) {
  const auto good = write("good.json", kSeeds[0]);
  const RunResult text = run_cli("info '" + good.string() + "'", dir_);
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("peg"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("features"), std::string::npos) << text.out;
  const RunResult json = run_cli("info '" + good.string() + "' --json", dir_);
  EXPECT_EQ(json.status, 0) << json.err;
  EXPECT_NE(json.out.find("\"features\": 24"), std::string::npos) << json.out;
  EXPECT_TRUE(json.err.empty()) << json.err;
}

}  // namespace
}  // namespace cslice
