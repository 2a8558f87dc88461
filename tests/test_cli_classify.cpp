// `cslice classify` run as a program: answers on standard output, one per query, and on a bad
// query exit status 2 with nothing on standard output.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace cslice::testkit;

// A unit square moving around a 2 x 2 block with a tolerance of 0.01.
constexpr const char* kPairJson = R"({
  "name": "cli-square", "units": "mm", "tolerance": 0.01,
  "moving": { "loops": [[[0, 0], [1, 0], [1, 1], [0, 1]]] },
  "fixed": { "loops": [[[0, 0], [2, 0], [2, 2], [0, 2]]], "enclosure": false }
})";

class CliClassify : public ScratchDirTest {
 protected:
  CliClassify() : ScratchDirTest("cslice_cli_classify") {}
  void SetUp() override {
    pair_ = dir_ / "pair.json";
    write_file(pair_, kPairJson);
  }

  // Runs `cslice classify <args>` with `input` on standard input.
  RunResult run(const std::string& args, const std::string& input = "") {
    return run_cli("classify " + args, dir_, input);
  }
  std::string pair() const { return quoted(pair_); }

  fs::path pair_;
};

TEST_F(CliClassify, ReadsPosesFromStandardInput) {
  const RunResult r = run(pair(),
                          "# x y theta\n"
                          "0.5 0.5 0\n"
                          "\n"
                          "   \n"
                          "5,5,0.3\n"
                          "2 0.5 0\n"
                          "  # indented comment\n"
                          "-1, -1, 0\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "blocked\nfree\ncontact\ncontact\n");
}

// Text saved on Windows: a UTF-8 byte order mark first and CR LF line ends (the mark made the
// first line malformed, exit 2).
TEST_F(CliClassify, ReadsWindowsTextWithAByteOrderMark) {
  const RunResult r = run(pair(),
                          "\xEF\xBB\xBF"
                          "0.5 0.5 0\r\n5,5,0.3\r\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "blocked\nfree\n");
  const RunResult comment = run(pair(), "\xEF\xBB\xBF# x y theta\r\n5,5,0.3\r\n");
  EXPECT_EQ(comment.status, 0) << comment.err;
  EXPECT_EQ(comment.out, "free\n");
}

// The same pair with the fixed block drawn 1,000 mm out: the answers shift with it, and the
// command warns that the tolerances have grown with the distance (every pair file is loaded
// the same way, so every command does).
TEST_F(CliClassify, WarnsWhenTheFixedPartIsDrawnFarFromTheOrigin) {
  const RunResult centred = run(pair() + " --at 2,0.5,0");
  EXPECT_EQ(centred.status, 0) << centred.err;
  EXPECT_EQ(centred.err, "");
  write_file(dir_ / "far.json", R"({
    "name": "cli-square-far", "units": "mm", "tolerance": 0.01,
    "moving": { "loops": [[[0, 0], [1, 0], [1, 1], [0, 1]]] },
    "fixed": { "loops": [[[1000, 0], [1002, 0], [1002, 2], [1000, 2]]] }
  })");
  const RunResult far = run(quoted(dir_ / "far.json") + " --at 1002,0.5,0 --at 1000.5,0.5,0");
  EXPECT_EQ(far.status, 0) << far.err;
  EXPECT_EQ(far.out, "contact\nblocked\n");
  EXPECT_NE(far.err.find("far.json: the fixed part lies far from the moving part's body origin"),
            std::string::npos)
      << far.err;
  EXPECT_NE(far.err.find("times coarser"), std::string::npos) << far.err;
}

TEST_F(CliClassify, EmptyInputGivesEmptyOutput) {
  const RunResult r = run(pair(), "");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(CliClassify, RepeatedAtOptions) {
  // Options before and after the pair file; a negative number right after --at.
  const RunResult r = run("--at 0.5,0.5,0 " + pair() + " --at 5,5,0 --at -1,0.5,0", "bad\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "blocked\nfree\ncontact\n");
}

TEST_F(CliClassify, MalformedLineExitsTwoWithEmptyOutput) {
  const RunResult r = run(pair(), "0.5 0.5 0\n# fine\n5 5 0\n1 2\n3 3 3\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("line 4"), std::string::npos) << r.err;
}

TEST_F(CliClassify, RejectsExtraFieldsAndNonFiniteNumbers) {
  for (const std::string bad : {"1 2 3 4\n", "nan 0 0\n", "1 inf 0\n", "a b c\n", "1;2;3\n"}) {
    const RunResult r = run(pair(), "0 0 0\n" + bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_EQ(r.out, "") << bad;
    EXPECT_NE(r.err.find("line 2"), std::string::npos) << r.err;
  }
}

TEST_F(CliClassify, MalformedAtExitsTwo) {
  const RunResult r = run(pair() + " --at 1,2");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
}

TEST_F(CliClassify, MissingPairFileExitsTwo) {
  const RunResult r = run(quoted(dir_ / "absent.json"), "0 0 0\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(r.err.empty());
}

}  // namespace
