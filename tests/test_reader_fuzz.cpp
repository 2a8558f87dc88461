// Robustness of the pair reader: thousands of seeded mutations of valid pair files must each
// come back as a pair or as an error with a message, quickly, never as a crash or a hang.
// Also the `cslice info` exit statuses on a bad and a good file.
#include <gtest/gtest.h>

#include <cctype>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "cslice/pair.hpp"
#include "support/cli_run.hpp"

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

const std::vector<std::string> kNumberReplacements = {"nan",
                                                      "NaN",
                                                      "1e308",
                                                      "-1e308",
                                                      "-0",
                                                      "1e999",
                                                      "-1e999",
                                                      "1e9",
                                                      "1.0000001e9",
                                                      "0",
                                                      "1e-300",
                                                      "5e-324",
                                                      "123456789012345678901234567890",
                                                      "-",
                                                      "Infinity",
                                                      "0.5",
                                                      "3",
                                                      "1e-9",
                                                      "-1",
                                                      "2.5",
                                                      "\"7\"",
                                                      "true",
                                                      "null",
                                                      "[]",
                                                      "{}",
                                                      "[1,2]"};

const std::string kInsertable = "[]{},:\"0123456789.-e \n\\tfnu";

// Positions where a number starts (a digit or '-' not preceded by a number character).
std::vector<size_t> number_starts(const std::string& s) {
  std::vector<size_t> out;
  for (size_t i = 0; i < s.size(); ++i) {
    const bool starts = std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '-';
    const bool after_number = i > 0 && (std::isdigit(static_cast<unsigned char>(s[i - 1])) ||
                                        s[i - 1] == '.' || s[i - 1] == 'e' || s[i - 1] == '-');
    if (starts && !after_number) out.push_back(i);
  }
  return out;
}

size_t number_end(const std::string& s, size_t i) {
  while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.' ||
                          s[i] == 'e' || s[i] == 'E' || s[i] == '-' || s[i] == '+'))
    ++i;
  return i;
}

class Mutator {
 public:
  explicit Mutator(unsigned seed) : rng_(seed) {}

  std::string mutate(std::string s) {
    const int rounds = 1 + pick(3);
    for (int r = 0; r < rounds; ++r) s = mutate_once(std::move(s));
    return s;
  }

 private:
  size_t pick(size_t n) {
    return n == 0 ? 0 : std::uniform_int_distribution<size_t>(0, n - 1)(rng_);
  }

  std::string mutate_once(std::string s) {
    if (s.empty()) return "{";
    const size_t i = pick(s.size());
    switch (pick(10)) {
      case 0:
        return s.erase(i, 1);
      case 1:
        return s.insert(i, 1, s[i]);
      case 2:
        if (i + 1 < s.size()) std::swap(s[i], s[i + 1]);
        return s;
      case 3:
        return s.insert(i, 1, kInsertable[pick(kInsertable.size())]);
      case 4:
        return s.substr(0, i);
      case 5:
        return nest(std::move(s), i);
      case 6:
        return drop_key(std::move(s));
      case 7:
        return duplicate_bracketed(std::move(s), i);
      default:
        return replace_number(std::move(s));
    }
  }

  std::string replace_number(std::string s) {
    const std::vector<size_t> starts = number_starts(s);
    if (starts.empty()) return s;
    const size_t at = starts[pick(starts.size())];
    return s.replace(at, number_end(s, at) - at,
                     kNumberReplacements[pick(kNumberReplacements.size())]);
  }

  // Wraps from position i to the end of the next bracketed value, or many open brackets.
  std::string nest(std::string s, size_t i) {
    if (pick(4) == 0) return s.insert(i, std::string(1 + pick(200), '['));
    const size_t open = s.find_first_of("[{", i);
    if (open == std::string::npos) return s;
    const size_t close = matching(s, open);
    if (close == std::string::npos) return s;
    s.insert(close + 1, "]");
    return s.insert(open, "[");
  }

  // Removes a "key": value pair (the value up to the next comma or closing brace).
  std::string drop_key(std::string s) {
    std::vector<size_t> keys;
    for (size_t p = s.find("\":"); p != std::string::npos; p = s.find("\":", p + 1))
      keys.push_back(p);
    if (keys.empty()) return s;
    const size_t colon = keys[pick(keys.size())];
    const size_t key_start = s.rfind('"', colon - 1);
    if (key_start == std::string::npos) return s;
    size_t end = colon + 2;
    while (end < s.size() && s[end] == ' ') ++end;
    if (end < s.size() && (s[end] == '[' || s[end] == '{')) {
      const size_t close = matching(s, end);
      end = close == std::string::npos ? s.size() : close + 1;
    } else {
      end = s.find_first_of(",}", end);
      if (end == std::string::npos) end = s.size();
    }
    if (end < s.size() && s[end] == ',') ++end;
    return s.erase(key_start, end - key_start);
  }

  // Copies a bracketed value (a vertex, a loop, a part) right after itself.
  std::string duplicate_bracketed(std::string s, size_t i) {
    const size_t open = s.find('[', i);
    if (open == std::string::npos) return s;
    const size_t close = matching(s, open);
    if (close == std::string::npos) return s;
    return s.insert(close + 1, "," + s.substr(open, close + 1 - open));
  }

  static size_t matching(const std::string& s, size_t open) {
    int depth = 0;
    for (size_t k = open; k < s.size(); ++k) {
      if (s[k] == '[' || s[k] == '{') ++depth;
      if (s[k] == ']' || s[k] == '}')
        if (--depth == 0) return k;
    }
    return std::string::npos;
  }

  std::mt19937 rng_;
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
    Mutator mutator(1234u + static_cast<unsigned>(seed_index));
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
