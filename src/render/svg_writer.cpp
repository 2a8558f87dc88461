#include "render/svg_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cslice::svg {

std::string number(double v, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v == 0.0 ? 0.0 : v);  // no "-0"
  return buf;
}

std::string fixed(double v, int decimals) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

double larger_side(const Box& b) {
  return std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y);
}

double nice_step(double limit) {
  const double decade = std::pow(10.0, std::floor(std::log10(limit)));
  for (double step : {5.0, 2.0, 1.0})
    if (step * decade <= limit) return step * decade;
  return decade;
}

ArcFlags arc_flags(const Curve& c) {
  return {std::fabs(c.sweep) > kPi, c.sweep < 0.0};
}

std::array<Curve, 2> split_full_circle(const Curve& c) {
  return {make_arc(c.center, c.radius, c.start_angle, c.sweep / 2),
          make_arc(c.center, c.radius, c.start_angle + c.sweep / 2, c.sweep / 2)};
}

}  // namespace cslice::svg
