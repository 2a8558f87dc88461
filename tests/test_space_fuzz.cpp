// Robustness of the space reader (parse_space, load_space): thousands of seeded mutations of
// space files written by compute_space + space_to_json must each come back as a space or as
// an error naming the source, quickly, never as a crash, an escaped exception or a hang.
// Text mutations are the pair reader fuzz's (support/mutations.hpp); the structure-aware
// edits here work on the parsed JSON, where a random byte edit would rarely reach: keys
// dropped, duplicated or reordered, arrays resized, values replaced by extremes, wrong types,
// long strings or deep nesting, counts and indices pushed out of range. Also the regression
// tests of the bugs the fuzzing found, and `cslice query` on a mutated file.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "cslice/space.hpp"
#include "support/cli_run.hpp"
#include "support/examples.hpp"
#include "support/mutations.hpp"
#include "support/spaces.hpp"

namespace cslice {
namespace {

using ojson = nlohmann::ordered_json;

// Small pairs, so that a mutation the reader only catches after recomputing every slice (a
// summary edited deep in the file) still costs a millisecond or so: disc-in-box (no critical
// orientation, 4 slices) and a square in a box with a coarse tolerance (4 critical
// orientations with their conditions and transitions, 8 slices). The paper's examples take
// 5 to 50 ms a parse, too slow for thousands.
const char* const kSquareInBox = R"({"name": "square-in-box", "units": "mm", "tolerance": 0.1,
    "moving": {"loops": [[[-0.5,-0.5],[0.5,-0.5],[0.5,0.5],[-0.5,0.5]]]},
    "fixed": {"loops": [[[-1,-1],[1,-1],[1,1],[-1,1]]], "enclosure": true}})";

constexpr int kThreads = 1;  // the suite runs tests side by side on 2 cores
const char* const kSource = "fuzz.space.json";

// A seed space file and the shape of its space: a mutated file the reader accepts must
// describe the same space (a reader that skipped a check could accept a truncated one).
struct Seed {
  std::string text;
  size_t slices = 0, criticals = 0, components_3d = 0;
};

// With timing, fixed so that the text (and every mutation of it) is the same on every run.
Seed seed_of(const Pair& pair) {
  SlicedSpace space = testkit::space_of(pair, kThreads);
  space.seconds_criticals = 0.001;
  space.seconds_slices = 0.002;
  return {space_to_json(pair, space, true), space.slices.size(),
          space.criticals.orientations.size(), space.topology.components.size()};
}

const std::vector<Seed>& seeds() {
  static const std::vector<Seed> all = [] {
    LoadResult square = parse_pair(kSquareInBox, "square-in-box");
    if (!square.ok()) throw std::runtime_error(square.error->message());
    return std::vector<Seed>{seed_of(testkit::load_example("disc-in-box")), seed_of(*square.pair)};
  }();
  return all;
}

// ---- Structure-aware edits ----------------------------------------------------------------

// Stands for a deeply nested value, spliced into the text after dump(): building it as JSON
// would make the test's own (recursive) dump overflow the stack.
const std::string kDeepPlaceholder = "@@deep@@";

std::string deep_text(size_t depth, bool objects) {
  std::string s;
  s.reserve(depth * (objects ? 7 : 2) + 1);
  for (size_t i = 0; i < depth; ++i) s += objects ? "{\"a\": " : "[";
  s += "0";
  for (size_t i = 0; i < depth; ++i) s += objects ? '}' : ']';
  return s;
}

// Values that replace a field, by kind: extreme numbers and out-of-range indices, wrong
// types, a long string, deep nesting. An edit picks the kind first, so the rare but
// dangerous last two come up often.
std::vector<std::vector<ojson>> replacement_values() {
  using limits64 = std::numeric_limits<std::int64_t>;
  const std::vector<ojson> numbers = {1e308,
                                      -1e308,
                                      -0.0,
                                      5e-324,
                                      0,
                                      -1,
                                      2,
                                      limits64::max(),
                                      limits64::min(),
                                      std::numeric_limits<std::uint64_t>::max(),
                                      std::int64_t{1} << 31,
                                      std::int64_t{1} << 32,
                                      -(std::int64_t{1} << 31) - 1};
  const std::vector<ojson> wrong_types = {"",
                                          "x",
                                          "NaN",
                                          "2",
                                          true,
                                          nullptr,
                                          ojson::object(),
                                          ojson::array(),
                                          ojson::array({1, 2}),
                                          ojson::object({{"a", 1}})};
  return {numbers, wrong_types, {std::string(1 << 16, 'x')}, {kDeepPlaceholder}};
}

// Every value of the document, parents before children. Edits invalidate the pointers: they
// are collected again for each edit.
void collect(ojson& j, std::vector<ojson*>& out) {
  out.push_back(&j);
  if (j.is_structured())
    for (ojson& child : j) collect(child, out);
}

template <class Pred>
std::vector<ojson*> values_where(ojson& root, Pred pred) {
  std::vector<ojson*> all, fit;
  collect(root, all);
  for (ojson* v : all)
    if (pred(*v)) fit.push_back(v);
  return fit;
}

class JsonMutator {
 public:
  explicit JsonMutator(unsigned seed) : rng_(seed), replacements_(replacement_values()) {}

  // 1 or 2 edits of the document, then its text (compact or indented).
  std::string mutate(ojson doc) {
    const int edits = 1 + static_cast<int>(pick(2));
    for (int e = 0; e < edits; ++e) edit_once(doc);
    std::string text = doc.dump(pick(2) == 0 ? -1 : 1);
    const std::string placeholder = "\"" + kDeepPlaceholder + "\"";
    for (size_t at = text.find(placeholder); at != std::string::npos;
         at = text.find(placeholder, at))
      text.replace(at, placeholder.size(), deep_text(deep_depth(), pick(2) == 0));
    return text;
  }

 private:
  size_t pick(size_t n) {
    return n == 0 ? 0 : std::uniform_int_distribution<size_t>(0, n - 1)(rng_);
  }

  // Mostly beyond any sane limit (a recursive reader overflows its stack there).
  size_t deep_depth() {
    const size_t depths[] = {40, 1000, 200000};
    return depths[pick(3)];
  }

  // A value satisfying `pred`, mostly from one top-level field picked first, so that the
  // small fields read first (pair_file, tolerance, ...) get as many edits as the slices; from
  // anywhere when that field has none (the critical orientations of a pair with none).
  template <class Pred>
  ojson* pick_value(ojson& doc, Pred pred) {
    std::vector<ojson*> fit;
    if (doc.is_object() && !doc.empty() && pick(8) != 0) {
      auto it = doc.begin();
      std::advance(it, static_cast<std::ptrdiff_t>(pick(doc.size())));
      fit = values_where(*it, pred);
    }
    if (fit.empty()) fit = values_where(doc, pred);
    return fit.empty() ? nullptr : fit[pick(fit.size())];
  }

  void edit_once(ojson& doc) {
    switch (pick(8)) {
      case 0:
        return drop_key(doc);
      case 1:
        return duplicate_key(doc);
      case 2:
        return reorder_keys(doc);
      case 3:
        return resize_array(doc);
      case 4:
        return replace_value(doc);
      case 5:
        return edit_top_level(doc);
      default:
        return shift_integer(doc);
    }
  }

  void drop_key(ojson& doc) {
    ojson* obj = pick_value(doc, [](const ojson& v) { return v.is_object() && !v.empty(); });
    if (!obj) return;
    auto it = obj->begin();
    std::advance(it, static_cast<std::ptrdiff_t>(pick(obj->size())));
    obj->erase(it);
  }

  // A second entry under an existing key, with the first field's value or a replacement:
  // whichever one the parser keeps, the reader must cope.
  void duplicate_key(ojson& doc) {
    ojson* obj = pick_value(doc, [](const ojson& v) { return v.is_object() && !v.empty(); });
    if (!obj) return;
    auto& items = static_cast<ojson::object_t::Container&>(obj->get_ref<ojson::object_t&>());
    const std::string key = items[pick(items.size())].first;
    const ojson value = pick(2) == 0 ? items[0].second : replacement();
    items.emplace_back(key, value);
  }

  void reorder_keys(ojson& doc) {
    ojson* obj = pick_value(doc, [](const ojson& v) { return v.is_object() && v.size() > 1; });
    if (!obj) return;
    const auto& items =
        static_cast<const ojson::object_t::Container&>(obj->get_ref<ojson::object_t&>());
    std::vector<size_t> order(items.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::shuffle(order.begin(), order.end(), rng_);
    ojson shuffled = ojson::object();
    for (size_t i : order) shuffled[items[i].first] = items[i].second;
    *obj = std::move(shuffled);
  }

  void resize_array(ojson& doc) {
    ojson* arr = pick_value(doc, [](const ojson& v) { return v.is_array(); });
    if (arr) resize(*arr);
  }

  // One element fewer or more (a copy of one), half of them, or a null or number appended.
  void resize(ojson& arr) {
    const size_t n = arr.size();
    switch (pick(4)) {
      case 0:
        if (n > 0) arr.erase(pick(n));
        return;
      case 1:
        if (n > 0) arr.insert(arr.begin() + static_cast<std::ptrdiff_t>(pick(n)), arr[pick(n)]);
        return;
      case 2:
        arr.get_ref<ojson::array_t&>().resize(n / 2);
        return;
      default:
        arr.push_back(pick(2) == 0 ? ojson(nullptr) : ojson(n));
    }
  }

  void replace_value(ojson& doc) {
    ojson* v = pick_value(doc, [&doc](const ojson& x) { return &x != &doc; });
    if (v) *v = replacement();
  }

  // The fields read first (format, version, pair, tolerance, ...): edited here as often as
  // the thousands of values deeper in the file.
  void edit_top_level(ojson& doc) {
    if (!doc.is_object() || doc.empty()) return;
    auto it = doc.begin();
    std::advance(it, static_cast<std::ptrdiff_t>(pick(doc.size())));
    if (it.key() == "format") {
      const char* formats[] = {"cslice-slice", "CSLICE-SPACE", "cslice-space ", ""};
      *it = formats[pick(4)];
    } else if (it.key() == "version") {
      const ojson versions[] = {
          1, 2, 4, -2, 3.0, "3", kSpaceFormatVersion + (std::int64_t{1} << 32)};
      *it = versions[pick(7)];
    } else if (it->is_array() && pick(2) == 0) {
      resize(*it);  // more or fewer slices, critical orientations, ... than the pair gives
    } else {
      *it = replacement();
    }
  }

  // Counts and indices (slice, interval, component, cell, feature) off by one, negative, or
  // past any array and past int.
  void shift_integer(ojson& doc) {
    ojson* v = pick_value(doc, [](const ojson& x) { return x.is_number_integer(); });
    if (!v) return;
    // In unsigned arithmetic, which wraps where signed would overflow (on 2^63 - 1, say).
    const auto x = static_cast<std::uint64_t>(v->get<std::int64_t>());
    const std::uint64_t shifted[] = {
        x + 1, x - 1, ~x, ~std::uint64_t{0}, x + 1000, x + (std::uint64_t{1} << 32)};
    *v = static_cast<std::int64_t>(shifted[pick(6)]);
  }

  const ojson& replacement() {
    const std::vector<ojson>& kind = replacements_[pick(replacements_.size())];
    return kind[pick(kind.size())];
  }

  std::mt19937 rng_;
  std::vector<std::vector<ojson>> replacements_;
};

// ---- The fuzz loop ------------------------------------------------------------------------

struct Tally {
  int accepted = 0, rejected = 0;
  std::chrono::steady_clock::duration slowest{};
};

// One parse of `text`, a mutation of `seed`: the seed's space or an error naming the source,
// within the time budget.
void check_parse(const std::string& text, const Seed& seed, Tally& tally) {
  const auto budget = std::chrono::seconds(2);  // per parse; a hang shows as a failure here
  const auto start = std::chrono::steady_clock::now();
  const LoadSpaceResult r = parse_space(text, kSource, kThreads);
  const auto elapsed = std::chrono::steady_clock::now() - start;
  tally.slowest = std::max(tally.slowest, elapsed);
  const std::string excerpt = text.substr(0, 2000);
  ASSERT_LT(elapsed, budget) << excerpt;
  ASSERT_NE(r.ok(), r.error.has_value()) << excerpt;
  if (r.ok()) {
    ++tally.accepted;
    ASSERT_EQ(r.space->slices.size(), seed.slices) << excerpt;
    ASSERT_EQ(r.space->criticals.orientations.size(), seed.criticals) << excerpt;
    ASSERT_EQ(r.space->topology.components.size(), seed.components_3d) << excerpt;
    return;
  }
  ++tally.rejected;
  EXPECT_FALSE(r.pair.has_value());
  EXPECT_FALSE(r.space.has_value());
  ASSERT_FALSE(r.error->reason.empty()) << excerpt;
  ASSERT_EQ(r.error->message().rfind(std::string(kSource) + ": ", 0), 0u) << r.error->message();
  ASSERT_EQ(r.error->reason.find("internal error"), std::string::npos)
      << r.error->message().substr(0, 2000) << "\n"
      << excerpt;
}

double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

TEST(SpaceFuzz, SeedsAreValid) {
  for (const Seed& seed : seeds()) {
    const LoadSpaceResult r = parse_space(seed.text, "seed.space.json", kThreads);
    EXPECT_TRUE(r.ok()) << r.error->message();
  }
}

TEST(SpaceFuzz, TextMutationsNeverCrashOrHang) {
  constexpr int kIterationsPerSeed = 2000;
  Tally tally;
  const auto start = std::chrono::steady_clock::now();
  for (size_t k = 0; k < seeds().size(); ++k) {
    testkit::TextMutator mutator(4321u + static_cast<unsigned>(k));
    for (int it = 0; it < kIterationsPerSeed; ++it) {
      check_parse(mutator.mutate(seeds()[k].text), seeds()[k], tally);
      if (HasFatalFailure()) return;
    }
  }
  // Whitespace and unread fields (timing, correspondence entries) can change harmlessly, so
  // some mutations are accepted; most must be caught.
  EXPECT_GT(tally.rejected, tally.accepted);
  std::cout << "text: accepted " << tally.accepted << ", rejected " << tally.rejected
            << ", slowest parse " << seconds(tally.slowest) << " s, total "
            << seconds(std::chrono::steady_clock::now() - start) << " s\n";
}

TEST(SpaceFuzz, StructureEditsNeverCrashOrHang) {
  constexpr int kIterationsPerSeed = 1500;
  Tally tally;
  const auto start = std::chrono::steady_clock::now();
  for (size_t k = 0; k < seeds().size(); ++k) {
    const ojson doc = ojson::parse(seeds()[k].text);
    JsonMutator mutator(8765u + static_cast<unsigned>(k));
    for (int it = 0; it < kIterationsPerSeed; ++it) {
      check_parse(mutator.mutate(doc), seeds()[k], tally);
      if (HasFatalFailure()) return;
    }
  }
  EXPECT_GT(tally.rejected, tally.accepted);
  std::cout << "structure: accepted " << tally.accepted << ", rejected " << tally.rejected
            << ", slowest parse " << seconds(tally.slowest) << " s, total "
            << seconds(std::chrono::steady_clock::now() - start) << " s\n";
}

// ---- Regression tests of what the fuzzing found -------------------------------------------

// The square-in-box space, edited by `edit`, then parsed.
template <class Edit>
LoadSpaceResult parse_edited(Edit edit) {
  ojson doc = ojson::parse(seeds()[1].text);
  edit(doc);
  return parse_space(doc.dump(1), kSource, kThreads);
}

void expect_error_mentions(const LoadSpaceResult& r, const std::string& what) {
  ASSERT_FALSE(r.ok()) << "accepted; expected an error mentioning " << what;
  EXPECT_EQ(r.error->message().rfind(std::string(kSource) + ": ", 0), 0u) << r.error->message();
  EXPECT_NE(r.error->message().find(what), std::string::npos)
      << "'" << what << "' not in: " << r.error->message();
}

// The square-in-box space with the embedded moving part replaced by an array nested `depth`
// deep.
std::string deeply_nested_space(size_t depth) {
  std::string text = seeds()[1].text;
  const std::string key = "\"moving\": ";
  const size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos);
  return text.insert(at + key.size(), deep_text(depth, false) + ", \"was_moving\": ");
}

// Crashed (stack overflow): the reader re-serialises the embedded pair for the pair reader,
// and nlohmann's dump recurses once per level. Now rejected before parsing, as the pair
// reader rejects nesting deeper than a valid file's.
TEST(SpaceReader, DeeplyNestedValueIsAnErrorNotACrash) {
  expect_error_mentions(parse_space(deeply_nested_space(100000), kSource, kThreads),
                        "nested deeper than");
}

// Was "internal error while reading: [json.exception.type_error.302] ...": a timing value
// of the wrong type escaped as a library exception instead of naming the field.
TEST(SpaceReader, TimingOfTheWrongTypeIsAFieldError) {
  expect_error_mentions(parse_edited([](ojson& j) {
                          j["timing"] = {{"criticals_seconds", "fast"}, {"slices_seconds", 0.1}};
                        }),
                        "field \"timing.criticals_seconds\": must be a number");
  const LoadSpaceResult good = parse_edited([](ojson& j) {
    j["timing"] = {{"criticals_seconds", 0.25}, {"slices_seconds", 0.5}};
  });
  ASSERT_TRUE(good.ok()) << good.error->message();
  EXPECT_EQ(good.space->seconds_criticals, 0.25);
  EXPECT_EQ(good.space->seconds_slices, 0.5);
}

// Was accepted: the stored interval was cast to int before the comparison, so 2^32 + i
// read as i.
TEST(SpaceReader, IntervalBeyondIntIsAnError) {
  expect_error_mentions(parse_edited([](ojson& j) {
                          ojson& interval = j["slices"][2]["interval"];
                          interval = interval.get<std::int64_t>() + (std::int64_t{1} << 32);
                        }),
                        "field \"slices[2].interval\": the file says 4294967");
}

// Was reported as "the file says -1": an unsigned integer above the long long range wrapped.
TEST(SpaceReader, IntegerBeyondLongLongIsReportedAsWritten) {
  expect_error_mentions(parse_edited([](ojson& j) {
                          j["slices"][0]["free_components"] =
                              std::numeric_limits<std::uint64_t>::max();
                        }),
                        "field \"slices[0].free_components\": integer out of range: "
                        "18446744073709551615");
}

// ---- The CLI ------------------------------------------------------------------------------

using testkit::run_cli;
using testkit::RunResult;

class QueryCli : public testkit::ScratchDirTest {
 protected:
  QueryCli() : ScratchDirTest("cslice_space_fuzz_cli") {}

  // `cslice query` on `text` must exit 2 with the reader's error on stderr and print nothing.
  void expect_rejected(const std::string& text) {
    const std::string path = (dir_ / "bad.space.json").string();
    testkit::write_file(path, text);
    const LoadSpaceResult expected = parse_space(text, path, kThreads);
    ASSERT_FALSE(expected.ok());
    const RunResult r = run_cli("query " + testkit::quoted(path) + " --threads 1", dir_, "0 0 0\n");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_NE(r.err.find(expected.error->message()), std::string::npos)
        << "stderr: " << r.err << "\nexpected: " << expected.error->message();
  }
};

// The first few mutations of each kind that the reader rejects.
TEST_F(QueryCli, MutatedFilesExitTwoWithTheErrorOnStderr) {
  testkit::TextMutator text_mutator(99u);
  JsonMutator json_mutator(99u);
  const ojson doc = ojson::parse(seeds()[1].text);
  int text_checked = 0, json_checked = 0;
  for (int it = 0; it < 200 && (text_checked < 3 || json_checked < 3); ++it) {
    const std::string by_text = text_mutator.mutate(seeds()[1].text);
    if (text_checked < 3 && !parse_space(by_text, kSource, kThreads).ok()) {
      expect_rejected(by_text);
      ++text_checked;
    }
    const std::string by_json = json_mutator.mutate(doc);
    if (json_checked < 3 && !parse_space(by_json, kSource, kThreads).ok()) {
      expect_rejected(by_json);
      ++json_checked;
    }
  }
  EXPECT_EQ(text_checked, 3);
  EXPECT_EQ(json_checked, 3);
}

TEST_F(QueryCli, DeeplyNestedFileExitsTwo) {
  expect_rejected(deeply_nested_space(100000));
}

TEST_F(QueryCli, GoodFileAnswers) {
  const std::string path = (dir_ / "good.space.json").string();
  testkit::write_file(path, seeds()[1].text);
  const RunResult r = run_cli("query " + testkit::quoted(path) + " --threads 1", dir_, "0 0 0\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("free", 0), 0u) << r.out;
}

// The correspondence's entries are counted as they are parsed and dropped, not kept: one entry
// more or less, or a value that is not an array, is still named.
TEST(SpaceReader, TheCorrespondenceIsCountedAsItIsRead) {
  const LoadSpaceResult untouched = parse_edited([](ojson&) {});
  ASSERT_TRUE(untouched.ok()) << untouched.error->message();
  EXPECT_EQ(untouched.space->correspondence.size(), untouched.space->slices.size());
  expect_error_mentions(parse_edited([](ojson& j) {
                          j["correspondence"].push_back({{"from", 0}});
                        }),
                        "field \"correspondence\": the file says");
  expect_error_mentions(parse_edited([](ojson& j) { j["correspondence"].erase(0); }),
                        "field \"correspondence\": the file says");
  expect_error_mentions(parse_edited([](ojson& j) {
                          j["correspondence"] = {{"a", 1}};
                        }),
                        "field \"correspondence\": must be an array, got object");
  expect_error_mentions(parse_edited([](ojson& j) { j.erase("correspondence"); }),
                        "correspondence");
}

}  // namespace
}  // namespace cslice
