// Seeded mutations of JSON text for the reader fuzz tests (test_reader_fuzz.cpp for pair
// files, test_space_fuzz.cpp for space files): one copy of the machinery, so both readers
// face the same byte, number and bracket edits, and a seed names the same mutation sequence
// in both.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace cslice::testkit {

// Text that stands in for a number: extremes, non-finite spellings, wrong types.
const std::vector<std::string>& extreme_number_texts();

// Positions where a number starts (a digit or '-' not preceded by a number character).
std::vector<size_t> number_starts(const std::string& s);

// The end of the number starting at i (one past its last character).
size_t number_end(const std::string& s, size_t i);

// The closing bracket matching the opening one at `open`; npos when there is none.
size_t matching_bracket(const std::string& s, size_t open);

// Text-level mutations: each call applies 1 to 3 random edits (delete, duplicate, swap or
// insert a byte, truncate, nest in brackets, drop a key, duplicate a bracketed value, replace
// a number by an extreme). The same seed gives the same sequence of results.
class TextMutator {
 public:
  explicit TextMutator(unsigned seed) : rng_(seed) {}

  std::string mutate(std::string s);

 private:
  size_t pick(size_t n);
  std::string mutate_once(std::string s);
  std::string replace_number(std::string s);
  std::string nest(std::string s, size_t i);
  std::string drop_key(std::string s);
  std::string duplicate_bracketed(std::string s, size_t i);

  std::mt19937 rng_;
};

// `count` mutations of `base` (seeds 0 to count - 1) read by `read`, which returns the error
// message or nothing: checks that every refusal has a message and that some mutations are
// accepted and some refused (the fuzz tests of the drawing readers).
void expect_mutants_read_or_refused(
    const std::string& base, int count,
    const std::function<std::optional<std::string>(const std::string&)>& read);

}  // namespace cslice::testkit
