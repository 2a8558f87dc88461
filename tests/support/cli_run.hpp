// Running the cslice program (CSLICE_CLI_PATH) from tests: its exit status and what it
// wrote, through files in a per-test scratch directory.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace cslice::testkit {

struct RunResult {
  int status = -1;  // the exit status; -1 if the program did not exit normally
  std::string out, err;
};

// The whole file; empty if it cannot be read.
std::string read_file(const std::filesystem::path& p);
void write_file(const std::filesystem::path& p, const std::string& text);

// Single-quoted for the shell (the paths here contain no quotes).
std::string quoted(const std::string& s);

// A fresh directory for the running test, <temp>/<prefix>_<pid>_<test name>. The caller
// removes it (fs::remove_all) when the test ends.
std::filesystem::path make_test_dir(const std::string& prefix);

// A fixture whose every test gets its own fresh directory `dir_` (make_test_dir), removed in
// TearDown.
class ScratchDirTest : public ::testing::Test {
 protected:
  explicit ScratchDirTest(const std::string& prefix) : dir_(make_test_dir(prefix)) {}
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
};

// Runs `cslice <args>` (`args` already quoted for the shell) with `input` on standard input.
// Standard input, output and error go through in.txt, out.txt and err.txt in `dir`.
RunResult run_cli(const std::string& args, const std::filesystem::path& dir,
                  const std::string& input = "");
// The same with the program's virtual memory limited to `kilobytes` (ulimit -v; 0: no limit).
RunResult run_cli_with_memory_limit(const std::string& args, const std::filesystem::path& dir,
                                    long kilobytes, const std::string& input = "");

}  // namespace cslice::testkit
