// SVG path data and number lists (SVG 1.1, Paths: the grammar of the d attribute). Parsed to
// the end or refused: a browser draws a path up to its first error, but a part outline that
// stops there would be a different part, so the reader names the error instead.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <initializer_list>

#include "parts/svg_internal.hpp"

namespace cslice::drawing {

namespace {

class Scanner {
 public:
  explicit Scanner(std::string_view s) : s_(s) {}

  bool at_end() {
    skip_blanks();
    return i_ >= s_.size();
  }
  char peek() const { return i_ < s_.size() ? s_[i_] : '\0'; }
  void advance() { ++i_; }
  size_t position() const { return i_ + 1; }  // 1-based, for messages

  void skip_blanks() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  // Blanks with at most one comma among them, as between two numbers.
  void skip_separator() {
    skip_blanks();
    if (peek() == ',') {
      ++i_;
      skip_blanks();
    }
  }

  // A number as the grammar has it: sign, digits with at most one point, exponent. Not
  // "inf" or "nan", which from_chars would take.
  bool number(double& v, std::string& error) {
    skip_separator();
    size_t start = i_;
    if (peek() == '+') start = ++i_;  // from_chars takes '-' but not '+'
    const char c = peek();
    const char next = i_ + 1 < s_.size() ? s_[i_ + 1] : '\0';
    const bool digit_follows =
        std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && std::isdigit(static_cast<unsigned char>(next))) ||
        (c == '-' && (std::isdigit(static_cast<unsigned char>(next)) || next == '.'));
    if (!digit_follows) return expected("a number", error);
    const auto [end, ec] = std::from_chars(s_.data() + start, s_.data() + s_.size(), v);
    if (ec == std::errc::result_out_of_range || (ec == std::errc() && !std::isfinite(v))) {
      error = "the number at character " + std::to_string(start + 1) + " is out of range";
      return false;
    }
    if (ec != std::errc()) return expected("a number", error);
    i_ = static_cast<size_t>(end - s_.data());
    return true;
  }

  // An arc's flag: one digit, 0 or 1, which may run into what follows ("a1 1 0 00 1 1").
  bool flag(bool& f, std::string& error) {
    skip_separator();
    if (peek() != '0' && peek() != '1') return expected("a flag, 0 or 1", error);
    f = peek() == '1';
    ++i_;
    return true;
  }

  bool expected(std::string_view what, std::string& error) const {
    error = "expected " + std::string(what) + " at character " + std::to_string(position());
    if (i_ < s_.size()) {
      error += " ('";
      error += s_[i_];
      error += "')";
    } else {
      error += " (the end)";
    }
    return false;
  }

 private:
  std::string_view s_;
  size_t i_ = 0;
};

// The path's state between commands: where the pen is, where its subpath began, and the
// control point that S and T reflect.
class PathBuilder {
 public:
  PathBuilder(std::vector<SvgSubpath>& out) : out_(out) {}

  bool command(char cmd, Scanner& in, std::string& error) {
    const bool rel = std::islower(static_cast<unsigned char>(cmd)) != 0;
    const Vec2 base = rel ? pen_ : Vec2{};
    const auto point = [&](Vec2& p) {
      return in.number(p.x, error) && in.number(p.y, error) && ((p = p + base), true);
    };
    const char kind = static_cast<char>(std::toupper(static_cast<unsigned char>(cmd)));
    Vec2 a, b, c;
    double v = 0.0;
    switch (kind) {
      case 'M':
        if (!point(a)) return false;
        out_.emplace_back();
        pen_ = start_ = a;
        open_ = true;
        reflect_ = '\0';
        return true;
      case 'Z':
        if (pen_ != start_) line(start_);
        subpath().closed = true;
        pen_ = start_;
        open_ = false;  // a command other than M continues from the start in a new subpath
        reflect_ = '\0';
        return true;
      case 'L':
        if (!point(a)) return false;
        line(a);
        return true;
      case 'H':
        if (!in.number(v, error)) return false;
        line({rel ? pen_.x + v : v, pen_.y});
        return true;
      case 'V':
        if (!in.number(v, error)) return false;
        line({pen_.x, rel ? pen_.y + v : v});
        return true;
      case 'C':
        if (!(point(a) && point(b) && point(c))) return false;
        cubic(a, b, c);
        return true;
      case 'S':
        if (!(point(b) && point(c))) return false;
        cubic(reflect_ == 'C' ? pen_ * 2.0 - control_ : pen_, b, c);
        return true;
      case 'Q':
        if (!(point(a) && point(b))) return false;
        quadratic(a, b);
        return true;
      case 'T':
        if (!point(b)) return false;
        quadratic(reflect_ == 'Q' ? pen_ * 2.0 - control_ : pen_, b);
        return true;
      case 'A': {
        SvgSegment s;
        s.kind = SvgSegment::Kind::arc;
        if (!(in.number(s.rx, error) && in.number(s.ry, error) && in.number(s.rotation, error) &&
              in.flag(s.large, error) && in.flag(s.sweep, error) && point(a)))
          return false;
        s.p[0] = pen_;
        s.p[1] = a;
        add(s, a);
        return true;
      }
      default:  // parse_svg_path passes path commands only
        return in.expected("a path command", error);
    }
  }

 private:
  SvgSubpath& subpath() {
    if (!open_) {  // drawing on after Z: a new subpath from where the last began
      out_.emplace_back();
      open_ = true;
    }
    return out_.back();
  }
  void add(const SvgSegment& s, Vec2 to) {
    subpath().segments.push_back(s);
    pen_ = to;
    reflect_ = '\0';
  }
  void line(Vec2 to) {
    SvgSegment s;
    s.p[0] = pen_;
    s.p[1] = to;
    add(s, to);
  }
  void cubic(Vec2 c1, Vec2 c2, Vec2 to) { bezier(SvgSegment::Kind::cubic, {c1, c2, to}); }
  void quadratic(Vec2 c1, Vec2 to) { bezier(SvgSegment::Kind::quadratic, {c1, to}); }
  // From the pen through `points` (controls, then the end); S or T after it reflects its last
  // control.
  void bezier(SvgSegment::Kind kind, std::initializer_list<Vec2> points) {
    SvgSegment s;
    s.kind = kind;
    s.p[0] = pen_;
    std::copy(points.begin(), points.end(), s.p + 1);
    add(s, s.p[points.size()]);
    control_ = s.p[points.size() - 1];
    reflect_ = kind == SvgSegment::Kind::cubic ? 'C' : 'Q';
  }

  std::vector<SvgSubpath>& out_;
  Vec2 pen_, start_, control_;
  bool open_ = false;
  char reflect_ = '\0';  // 'C' or 'Q' after such a curve: S or T reflects control_
};

}  // namespace

bool parse_svg_path(std::string_view d, std::vector<SvgSubpath>& out, std::string& error) {
  out.clear();
  Scanner in(d);
  PathBuilder path(out);
  char last = '\0';
  while (!in.at_end()) {
    char cmd = in.peek();
    if (std::isalpha(static_cast<unsigned char>(cmd))) {
      if (std::string_view("MmZzLlHhVvCcSsQqTtAa").find(cmd) == std::string_view::npos)
        return in.expected("a path command (M L H V C S Q T A Z)", error);
      in.advance();
    } else if (last == '\0' || last == 'Z' || last == 'z') {
      // Numbers repeat the last command, but there is none yet, and Z takes none.
      return in.expected(last == '\0' ? "a moveto (M or m)" : "a command after Z", error);
    } else {
      cmd = last == 'M' ? 'L' : last == 'm' ? 'l' : last;  // pairs after a moveto are linetos
    }
    if (last == '\0' && cmd != 'M' && cmd != 'm') return in.expected("a moveto (M or m)", error);
    if (!path.command(cmd, in, error)) return false;
    last = cmd;
  }
  return true;
}

bool parse_svg_numbers(std::string_view s, std::vector<double>& out, std::string& error) {
  out.clear();
  Scanner in(s);
  while (!in.at_end()) {
    double v = 0.0;
    if (!in.number(v, error)) return false;
    out.push_back(v);
  }
  return true;
}

}  // namespace cslice::drawing
