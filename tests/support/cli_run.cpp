#include "support/cli_run.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace cslice::testkit {

namespace fs = std::filesystem;

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

// Built with += because GCC 12 at -O3 warns falsely (-Wrestrict) on the equivalent chain of
// operator+.
std::string quoted(const std::string& s) {
  std::string q = "'";
  q += s;
  q += "'";
  return q;
}

fs::path make_test_dir(const std::string& prefix) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = prefix;
  name += "_";
  name += std::to_string(::getpid());
  name += "_";
  name += info ? info->name() : "no-test";
  const fs::path dir = fs::temp_directory_path() / name;
  fs::create_directories(dir);
  return dir;
}

RunResult run_cli(const std::string& args, const fs::path& dir, const std::string& input) {
  return run_cli_with_memory_limit(args, dir, 0, input);
}

RunResult run_cli_with_memory_limit(const std::string& args, const fs::path& dir, long kilobytes,
                                    const std::string& input) {
  const fs::path in = dir / "in.txt", out = dir / "out.txt", err = dir / "err.txt";
  write_file(in, input);
  std::string command = kilobytes > 0 ? "ulimit -v " + std::to_string(kilobytes) + " && " : "";
  command += quoted(CSLICE_CLI_PATH);
  command += " ";
  command += args;
  command += " < " + quoted(in.string());
  command += " > " + quoted(out.string());
  command += " 2> " + quoted(err.string());
  const int raw = std::system(command.c_str());
  RunResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

}  // namespace cslice::testkit
