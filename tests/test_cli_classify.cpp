// `cslice classify` run as a program: answers on standard output, one per query, and on a bad
// query exit status 2 with nothing on standard output.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

// A unit square moving around a 2 x 2 block with a tolerance of 0.01.
constexpr const char* kPairJson = R"({
  "name": "cli-square", "units": "mm", "tolerance": 0.01,
  "moving": { "loops": [[[0, 0], [1, 0], [1, 1], [0, 1]]] },
  "fixed": { "loops": [[[0, 0], [2, 0], [2, 2], [0, 2]]], "enclosure": false }
})";

struct RunResult {
  int status = -1;
  std::string out, err;
};

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Single-quoted for the shell (the paths here contain no quotes). Built with += because
// GCC 12 at -O3 warns falsely (-Wrestrict) on the equivalent chain of operator+.
std::string quoted(const std::string& s) {
  std::string q = "'";
  q += s;
  q += "'";
  return q;
}

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

class CliClassify : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("cslice_cli_classify_" + std::to_string(::getpid()) + "_" + info->name());
    fs::create_directories(dir_);
    pair_ = dir_ / "pair.json";
    write_file(pair_, kPairJson);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `cslice classify <args>` with `input` on standard input.
  RunResult run(const std::string& args, const std::string& input = "") {
    write_file(dir_ / "in.txt", input);
    const std::string command = std::string("'") + CSLICE_CLI_PATH + "' classify " + args + " < '" +
                                (dir_ / "in.txt").string() + "' > '" + (dir_ / "out.txt").string() +
                                "' 2> '" + (dir_ / "err.txt").string() + "'";
    const int raw = std::system(command.c_str());
    RunResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = read_file(dir_ / "out.txt");
    r.err = read_file(dir_ / "err.txt");
    return r;
  }
  std::string pair() const { return quoted(pair_); }

  fs::path dir_, pair_;
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
