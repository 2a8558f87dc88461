#include "support/mutations.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <utility>

namespace cslice::testkit {

namespace {

// Bytes worth inserting into JSON: structure, number characters, escapes, literal letters.
const std::string kInsertable = "[]{},:\"0123456789.-e \n\\tfnu";

bool is_digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

}  // namespace

const std::vector<std::string>& extreme_number_texts() {
  static const std::vector<std::string> texts = {"nan",
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
  return texts;
}

std::vector<size_t> number_starts(const std::string& s) {
  std::vector<size_t> out;
  for (size_t i = 0; i < s.size(); ++i) {
    const bool starts = is_digit(s[i]) || s[i] == '-';
    const bool after_number =
        i > 0 && (is_digit(s[i - 1]) || s[i - 1] == '.' || s[i - 1] == 'e' || s[i - 1] == '-');
    if (starts && !after_number) out.push_back(i);
  }
  return out;
}

size_t number_end(const std::string& s, size_t i) {
  while (i < s.size() && (is_digit(s[i]) || s[i] == '.' || s[i] == 'e' || s[i] == 'E' ||
                          s[i] == '-' || s[i] == '+'))
    ++i;
  return i;
}

size_t matching_bracket(const std::string& s, size_t open) {
  int depth = 0;
  for (size_t k = open; k < s.size(); ++k) {
    if (s[k] == '[' || s[k] == '{') ++depth;
    if (s[k] == ']' || s[k] == '}')
      if (--depth == 0) return k;
  }
  return std::string::npos;
}

std::string TextMutator::mutate(std::string s) {
  const int rounds = 1 + static_cast<int>(pick(3));
  for (int r = 0; r < rounds; ++r) s = mutate_once(std::move(s));
  return s;
}

size_t TextMutator::pick(size_t n) {
  return n == 0 ? 0 : std::uniform_int_distribution<size_t>(0, n - 1)(rng_);
}

std::string TextMutator::mutate_once(std::string s) {
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

std::string TextMutator::replace_number(std::string s) {
  const std::vector<size_t> starts = number_starts(s);
  if (starts.empty()) return s;
  const size_t at = starts[pick(starts.size())];
  const std::vector<std::string>& texts = extreme_number_texts();
  return s.replace(at, number_end(s, at) - at, texts[pick(texts.size())]);
}

// Wraps from position i to the end of the next bracketed value, or many open brackets.
std::string TextMutator::nest(std::string s, size_t i) {
  if (pick(4) == 0) return s.insert(i, std::string(1 + pick(200), '['));
  const size_t open = s.find_first_of("[{", i);
  if (open == std::string::npos) return s;
  const size_t close = matching_bracket(s, open);
  if (close == std::string::npos) return s;
  s.insert(close + 1, 1, ']');
  return s.insert(open, 1, '[');
}

// Removes a "key": value pair (the value up to the next comma or closing brace).
std::string TextMutator::drop_key(std::string s) {
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
    const size_t close = matching_bracket(s, end);
    end = close == std::string::npos ? s.size() : close + 1;
  } else {
    end = s.find_first_of(",}", end);
    if (end == std::string::npos) end = s.size();
  }
  if (end < s.size() && s[end] == ',') ++end;
  return s.erase(key_start, end - key_start);
}

// Copies a bracketed value (a vertex, a loop, a part) right after itself.
std::string TextMutator::duplicate_bracketed(std::string s, size_t i) {
  const size_t open = s.find('[', i);
  if (open == std::string::npos) return s;
  const size_t close = matching_bracket(s, open);
  if (close == std::string::npos) return s;
  // Built piecewise: `"," + s.substr(...)` trips GCC 12's -Wrestrict false alarm.
  std::string copy = ",";
  copy += s.substr(open, close + 1 - open);
  return s.insert(close + 1, copy);
}

void expect_mutants_read_or_refused(
    const std::string& base, int count,
    const std::function<std::optional<std::string>(const std::string&)>& read) {
  int accepted = 0, refused = 0;
  for (int seed = 0; seed < count; ++seed) {
    TextMutator mutator(static_cast<unsigned>(seed));
    const std::optional<std::string> error = read(mutator.mutate(base));
    if (!error) {
      ++accepted;
    } else {
      ++refused;
      EXPECT_FALSE(error->empty()) << "seed " << seed;
    }
  }
  EXPECT_GT(accepted, 0);
  EXPECT_GT(refused, 0);
}

}  // namespace cslice::testkit
