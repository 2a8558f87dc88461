// Reads pair files (docs/pair-format.md): JSON to raw loops, then the checks of validate.cpp,
// then finished parts. Problems travel inside this file as a private exception (so deep
// readers stay short) and leave it only as an InputError value.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cslice/pair.hpp"
#include "parts/json_text.hpp"
#include "parts/validate.hpp"

namespace cslice {

namespace {

using detail::format_number;
using detail::kMaxMagnitude;
using detail::RawLoop;
using detail::RawPart;
using detail::RawVertex;
using nlohmann::json;

struct ReadFailure {
  InputError error;
};

struct Where {
  std::string part;
  int loop = -1;
  int vertex = -1;
};

[[noreturn]] void fail(const Where& w, std::string reason) {
  throw ReadFailure{InputError{"", w.part, w.loop, w.vertex, std::move(reason)}};
}

[[noreturn]] void fail(const InputError& e) {
  throw ReadFailure{e};
}

// ---- JSON text ------------------------------------------------------------------------

json parse_json(std::string_view text) {
  if (std::optional<std::string> why = detail::json_nesting_error(text)) fail(Where{}, *why);
  try {
    return json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    // what() reads "[json.exception.parse_error.101] parse error at line L, column C: why".
    const std::string what = e.what();
    const size_t at = what.find("line ");
    fail(Where{},
         "invalid JSON at " +
             (at == std::string::npos ? detail::line_column_at(text, e.byte) : what.substr(at)));
  } catch (const json::out_of_range& e) {
    // A number too large for a double ("number overflow parsing '1e999'") carries no
    // position; the offending token's first occurrence gives one.
    const std::string what = e.what();
    const size_t quote = what.find('\'');
    const std::string token =
        quote == std::string::npos ? "" : what.substr(quote + 1, what.size() - quote - 2);
    const size_t pos = token.empty() ? std::string_view::npos : text.find(token);
    const std::string why = what.substr(what.find(']') + 2);
    fail(Where{},
         "invalid JSON" +
             (pos == std::string_view::npos ? "" : " at " + detail::line_column_at(text, pos)) +
             ": " + why);
  }
}

// ---- Fields ---------------------------------------------------------------------------

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// A key from the file as it appears in a message: quoted, control characters escaped, long
// keys cut short, so a corrupt file cannot garble the terminal or flood it.
std::string quoted_key(const std::string& key) {
  constexpr size_t kShown = 40;
  std::string q = json(key.substr(0, kShown)).dump(-1, ' ', false, json::error_handler_t::replace);
  if (key.size() > kShown) q.insert(q.size() - 1, "...");
  return q;
}

// Fails on the first key not in `known`, suggesting a known key within two typos.
void check_keys(const json& obj, std::initializer_list<const char*> known, const Where& w) {
  for (const auto& item : obj.items()) {
    const std::string& key = item.key();
    if (std::any_of(known.begin(), known.end(), [&](const char* k) { return key == k; })) continue;
    std::string reason = "unknown field " + quoted_key(key);
    for (const char* k : known)
      if (edit_distance(key, k) <= 2) reason += std::string(" (did you mean \"") + k + "\"?)";
    reason += "; known fields:";
    for (const char* k : known) reason += std::string(" \"") + k + "\"";
    fail(w, reason);
  }
}

const json& require(const json& obj, const char* key, const Where& w, std::string_view what) {
  const auto it = obj.find(key);
  if (it == obj.end())
    fail(w, std::string("missing field \"") + key + "\" in " + std::string(what));
  return *it;
}

double read_number(const json& v, const Where& w, const std::string& what) {
  if (!v.is_number()) fail(w, what + " must be a number, got " + v.type_name());
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail(w, what + " is not a finite number");
  if (std::fabs(d) > kMaxMagnitude)
    fail(w, what + " " + format_number(d) + " exceeds the magnitude limit " +
                format_number(kMaxMagnitude));
  return d;
}

std::string read_string(const json& obj, const char* key, const std::string& fallback) {
  const auto it = obj.find(key);
  if (it == obj.end()) return fallback;
  if (!it->is_string())
    fail(Where{}, std::string("field \"") + key + "\" must be a string, got " + it->type_name());
  return it->get<std::string>();
}

// ---- Parts ----------------------------------------------------------------------------

RawVertex read_vertex(const json& v, const Where& w) {
  if (!v.is_array() || v.size() < 2 || v.size() > 3)
    fail(w, std::string("vertex must be [x, y] or [x, y, bulge], got ") +
                (v.is_array() ? "an array of " + std::to_string(v.size()) + " values"
                              : v.type_name()));
  RawVertex r;
  r.p = {read_number(v[0], w, "x coordinate"), read_number(v[1], w, "y coordinate")};
  if (v.size() == 3) r.bulge = read_number(v[2], w, "bulge");
  return r;
}

RawLoop read_circle(const json& obj, const Where& w) {
  check_keys(obj, {"circle"}, w);
  const json& c = require(obj, "circle", w, "a circle loop");
  if (!c.is_array() || c.size() != 3)
    fail(w, "\"circle\" must be [cx, cy, r], got " +
                (c.is_array() ? "an array of " + std::to_string(c.size()) + " values"
                              : std::string(c.type_name())));
  RawLoop loop;
  loop.is_circle = true;
  loop.center = {read_number(c[0], w, "circle center x"), read_number(c[1], w, "circle center y")};
  loop.radius = read_number(c[2], w, "circle radius");
  return loop;
}

RawLoop read_loop(const json& v, Where w) {
  if (v.is_object()) return read_circle(v, w);
  if (!v.is_array())
    fail(w, std::string("loop must be an array of vertices or {\"circle\": [cx, cy, r]}, got ") +
                v.type_name());
  RawLoop loop;
  for (size_t i = 0; i < v.size(); ++i) {
    w.vertex = static_cast<int>(i);
    loop.vertices.push_back(read_vertex(v[i], w));
  }
  return loop;
}

RawPart read_part(const json& top, const char* name) {
  Where w{name};
  const json& v = require(top, name, Where{}, "the pair");
  if (!v.is_object()) fail(w, std::string("part must be an object, got ") + v.type_name());
  check_keys(v, {"loops", "enclosure"}, w);
  RawPart part;
  part.name = name;
  if (const auto it = v.find("enclosure"); it != v.end()) {
    if (!it->is_boolean())
      fail(w, std::string("\"enclosure\" must be true or false, got ") + it->type_name());
    part.enclosure = it->get<bool>();
  }
  const json& loops = require(v, "loops", w, "the part");
  if (!loops.is_array())
    fail(w, std::string("\"loops\" must be an array, got ") + loops.type_name());
  if (loops.empty()) fail(w, "part is empty: \"loops\" has no loop");
  for (size_t i = 0; i < loops.size(); ++i)
    part.loops.push_back(read_loop(loops[i], Where{name, static_cast<int>(i)}));
  if (part.enclosure && part.name == "moving")
    fail(w, "the moving part cannot be an enclosure: it must be bounded");
  return part;
}

std::optional<double> read_tolerance(const json& top) {
  const auto it = top.find("tolerance");
  if (it == top.end()) return std::nullopt;
  const double t = read_number(*it, Where{}, "tolerance");
  if (!(t > 0.0)) fail(Where{}, "tolerance must be positive, got " + format_number(t));
  return t;
}

// ---- Assembly -------------------------------------------------------------------------

void check_raw(const RawPart& moving, const RawPart& fixed, const Tolerances& tol) {
  if (auto e = detail::check_raw_part(moving, tol)) fail(*e);
  if (auto e = detail::check_raw_part(fixed, tol)) fail(*e);
}

// Checks in the order that keeps every step well defined: raw numbers with an epsilon from
// the raw size, then curves (which need non-degenerate edges), then the final size and
// epsilon (which need the curves' extreme points), then the curve-level checks.
Pair assemble(const RawPart& raw_moving, const RawPart& raw_fixed, Pair pair) {
  check_raw(raw_moving, raw_fixed, make_tolerances(detail::raw_pair_size(raw_moving, raw_fixed)));
  pair.moving = detail::build_part(raw_moving);
  pair.fixed = detail::build_part(raw_fixed);
  const double size = pair_size(pair.moving, pair.fixed);
  if (!(size > 0.0) || !std::isfinite(size))
    fail(Where{}, "the pair has no usable extent (size " + format_number(size) + ")");
  pair.tol = make_tolerances(size, pair.requested_tolerance);
  check_raw(raw_moving, raw_fixed, pair.tol);
  if (auto e = detail::check_part_curves(pair.moving, pair.tol)) fail(*e);
  if (auto e = detail::check_part_curves(pair.fixed, pair.tol)) fail(*e);
  finish_part(pair.moving);
  finish_part(pair.fixed);
  return pair;
}

std::string default_name(std::string_view source) {
  const std::string stem = std::filesystem::path(std::string(source)).stem().string();
  return stem.empty() ? "pair" : stem;
}

Pair read_pair(std::string_view text, std::string_view source) {
  const json top = parse_json(text);
  if (!top.is_object())
    fail(Where{}, std::string("the top level must be a JSON object, got ") + top.type_name());
  check_keys(top, {"name", "units", "tolerance", "moving", "fixed"}, Where{});
  Pair pair;
  pair.name = read_string(top, "name", default_name(source));
  pair.units = read_string(top, "units", "mm");
  pair.requested_tolerance = read_tolerance(top);
  const RawPart moving = read_part(top, "moving");
  const RawPart fixed = read_part(top, "fixed");
  return assemble(moving, fixed, std::move(pair));
}

}  // namespace

std::string InputError::message() const {
  std::string m = file.empty() ? "" : file + ": ";
  std::string where;
  if (!part.empty()) where = "part '" + part + "'";
  if (loop >= 0) where += (where.empty() ? "" : ", ") + std::string("loop ") + std::to_string(loop);
  if (vertex >= 0)
    where += (where.empty() ? "" : ", ") + std::string("vertex ") + std::to_string(vertex);
  if (!where.empty()) m += where + ": ";
  return m + reason;
}

namespace {

Box fixed_box(const Part& fixed) {
  Box box;
  for (const Loop& loop : fixed.loops)
    for (const Curve& c : loop.edges) box.add(bounding_box(c));
  return box;
}

// The diagonal of `box` and the moving part's disc of reach about the origin.
double size_with_reach(Box box, const Part& moving) {
  const bool any_moving = std::any_of(moving.loops.begin(), moving.loops.end(),
                                      [](const Loop& loop) { return !loop.edges.empty(); });
  if (any_moving) {
    const double reach = moving_reach(moving);
    box.add(Vec2{-reach, -reach});
    box.add(Vec2{reach, reach});
  }
  return box.diagonal();
}

}  // namespace

double pair_size(const Part& moving, const Part& fixed) {
  return size_with_reach(fixed_box(fixed), moving);
}

double placement_coarsening(const Part& moving, const Part& fixed) {
  const Box box = fixed_box(fixed);
  if (box.empty()) return 1.0;
  const Vec2 centre = 0.5 * (box.lo + box.hi);
  Box centred;
  centred.add(box.lo - centre);
  centred.add(box.hi - centre);
  const double centred_size = size_with_reach(centred, moving);
  return centred_size > 0.0 ? size_with_reach(box, moving) / centred_size : 1.0;
}

LoadResult parse_pair(std::string_view json_text, std::string_view source) {
  LoadResult result;
  try {
    result.pair = read_pair(json_text, source);
  } catch (const ReadFailure& f) {
    result.error = f.error;
  } catch (const std::exception& e) {
    // Not an input problem we know of; still reported as data, never thrown to the caller.
    result.error =
        InputError{"", "", -1, -1, std::string("internal error while reading: ") + e.what()};
  }
  if (result.error) result.error->file = std::string(source);
  return result;
}

std::optional<InputError> detail::read_input_file(const std::string& path, std::string& text) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return InputError{path, "", -1, -1, "is a directory, not a file"};
  std::ifstream in(path, std::ios::binary);
  if (!in) return InputError{path, "", -1, -1, std::string("cannot open: ") + std::strerror(errno)};
  // Straight into the string: through a string stream the text was held twice (a space file
  // of a larger pair is a gigabyte).
  // Sized first where the file has a size, so the string is not regrown (to twice the text).
  text.clear();
  std::error_code size_error;
  const auto size = std::filesystem::file_size(path, size_error);
  if (!size_error) text.reserve(static_cast<size_t>(size));
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    text.append(buffer, static_cast<size_t>(in.gcount()));
  if (in.bad()) return InputError{path, "", -1, -1, "read error"};
  return std::nullopt;
}

LoadResult load_pair(const std::string& path) {
  std::string text;
  if (std::optional<InputError> error = detail::read_input_file(path, text))
    return LoadResult{std::nullopt, std::move(error)};
  return parse_pair(text, path);
}

}  // namespace cslice
