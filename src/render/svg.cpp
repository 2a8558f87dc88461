// SVG pictures of a pair at one pose. Geometry stays in world units (the view box is in the
// pair's units), so arcs keep their exact radii; only y is negated, because SVG's y axis
// points down and the pictures must read like the paper's figures, with y up.
#include <algorithm>
#include <cmath>
#include <string>

#include "cslice/render_svg.hpp"
#include "render/svg_writer.hpp"

namespace cslice {
namespace {

// Colours: the fixed part grey like the paper's blocked space, the moving part a translucent
// blue so the fixed part's edges stay visible where they touch.
constexpr const char* kFixedFill = "#c8c8c8";
constexpr const char* kFixedStroke = "#404040";
constexpr const char* kMovingFill = "#3b7dd8";
constexpr const char* kMovingStroke = "#1f4e99";
constexpr const char* kMarker = "#c0392b";
constexpr double kMovingOpacity = 0.45;

// An enclosure has no outer edge, so its material is drawn as a frame this much wider than
// the openings (fraction of their larger side).
constexpr double kEnclosureFrame = 0.15;
// Empty space around the drawing, and the band below it for the scale bar (fractions of the
// drawing's larger side).
constexpr double kMargin = 0.06;
constexpr double kScaleBand = 0.08;
// Line and text sizes in pixels of the final picture.
constexpr double kStrokePx = 1.3;
constexpr double kFontPx = 14.0;
constexpr double kTitleFontPx = 17.0;

// No "-0" or "1e-17" noise from round-off.
std::string num(double v) {
  return svg::number(std::fabs(v) < 1e-12 ? 0.0 : v, 7);
}

// World point to SVG user space.
std::string pt(Vec2 p) {
  return num(p.x) + " " + num(-p.y);
}

// One SVG arc command (flags: svg::arc_flags). |sweep| must be below 2pi (full circles are
// split by the caller).
std::string arc_command(const Curve& c) {
  const svg::ArcFlags flags = svg::arc_flags(c);
  return "A " + num(c.radius) + " " + num(c.radius) + " 0 " + (flags.large ? "1 " : "0 ") +
         (flags.sweep ? "1 " : "0 ") + pt(c.to) + " ";
}

void append_edge(std::string& d, const Curve& c) {
  if (c.is_segment()) {
    d += "L " + pt(c.to) + " ";
  } else if (c.is_full_circle()) {
    const auto [first, second] = svg::split_full_circle(c);
    d += arc_command(first) + arc_command(second);
  } else {
    d += arc_command(c);
  }
}

std::string loops_path(const Part& part) {
  std::string d;
  for (const Loop& loop : part.loops) {
    if (loop.edges.empty()) continue;
    d += "M " + pt(loop.edges.front().from) + " ";
    for (const Curve& c : loop.edges) append_edge(d, c);
    d += "Z ";
  }
  return d;
}

std::string rect_path(const Box& b) {
  return "M " + pt(b.lo) + " L " + pt({b.hi.x, b.lo.y}) + " L " + pt(b.hi) + " L " +
         pt({b.lo.x, b.hi.y}) + " Z ";
}

Box curves_box(const Part& part) {
  Box b;
  for (const Loop& loop : part.loops)
    for (const Curve& c : loop.edges) b.add(bounding_box(c));
  return b;
}

// The region drawn as material: the loops' box, or for an enclosure a frame around it.
Box material_box(const Part& part) {
  Box b = curves_box(part);
  if (part.enclosure) b = b.inflated(kEnclosureFrame * svg::larger_side(b));
  return b;
}

// Where things go: the world box drawn, and the scale from world units to pixels.
struct Layout {
  Box content;      // both parts (and the enclosure frame)
  Box view;         // content plus margins, scale band and title band
  double px = 1.0;  // pixels per world unit
  double unit(double pixels) const { return pixels / px; }
};

Layout make_layout(const Box& content, const SvgOptions& options) {
  Layout l;
  l.content = content;
  double side = svg::larger_side(content);
  if (!(side > 0.0)) side = 1.0;  // a degenerate drawing still gets a visible frame
  const double margin = kMargin * side;
  l.view = content.inflated(margin);
  if (options.show_scale_bar) l.view.lo.y -= kScaleBand * side;
  l.px = options.width_px / (l.view.hi.x - l.view.lo.x);
  if (!options.title.empty()) l.view.hi.y += l.unit(2.0 * kTitleFontPx);
  return l;
}

std::string header(const Layout& l, const SvgOptions& options) {
  const double w = l.view.hi.x - l.view.lo.x;
  const double h = l.view.hi.y - l.view.lo.y;
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(options.width_px) +
         "\" height=\"" + num(std::ceil(h * l.px)) + "\" viewBox=\"" + num(l.view.lo.x) + " " +
         num(-l.view.hi.y) + " " + num(w) + " " + num(h) + "\">\n";
}

std::string background(const Layout& l) {
  return "<path d=\"" + rect_path(l.view) + "\" fill=\"white\"/>\n";
}

std::string fixed_part(const Part& fixed, const Layout& l) {
  std::string fill_path = loops_path(fixed);
  if (fixed.enclosure) fill_path = rect_path(material_box(fixed)) + fill_path;
  const std::string stroke = num(l.unit(kStrokePx));
  // Filled without stroke, then outlined: an enclosure's frame rectangle is no real edge.
  return "<g id=\"fixed\">\n<path d=\"" + fill_path + "\" fill=\"" + kFixedFill +
         "\" fill-rule=\"evenodd\" stroke=\"none\"/>\n<path d=\"" + loops_path(fixed) +
         "\" fill=\"none\" stroke=\"" + kFixedStroke + "\" stroke-width=\"" + stroke +
         "\" stroke-linejoin=\"round\"/>\n</g>\n";
}

std::string moving_part(const Part& moving, const Layout& l) {
  std::string fill_path = loops_path(moving);
  if (moving.enclosure) fill_path = rect_path(material_box(moving)) + fill_path;
  return "<g id=\"moving\">\n<path d=\"" + fill_path + "\" fill=\"" + kMovingFill +
         "\" fill-opacity=\"" + num(kMovingOpacity) + "\" fill-rule=\"evenodd\" stroke=\"" +
         kMovingStroke + "\" stroke-width=\"" + num(l.unit(kStrokePx)) +
         "\" stroke-linejoin=\"round\"/>\n</g>\n";
}

std::string line(Vec2 a, Vec2 b, const std::string& colour, double width) {
  return "<path d=\"M " + pt(a) + " L " + pt(b) + "\" stroke=\"" + colour + "\" stroke-width=\"" +
         num(width) + "\" fill=\"none\"/>\n";
}

// A cross at the reference point (x, y) and a short arrow-less line along the body x axis,
// so both the position and the orientation theta can be read off the picture.
std::string reference_marker(const Pose& pose, const Layout& l) {
  const Vec2 o{pose.x, pose.y};
  const double arm = l.unit(6.0);
  const double axis = l.unit(28.0);
  const double w = l.unit(1.6);
  std::string s = "<g id=\"reference\">\n";
  s += line(o - Vec2{arm, 0}, o + Vec2{arm, 0}, kMarker, w);
  s += line(o - Vec2{0, arm}, o + Vec2{0, arm}, kMarker, w);
  s += line(o, o + axis * unit_vector(pose.theta), kMarker, w);
  s += "<circle cx=\"" + num(o.x) + "\" cy=\"" + num(-o.y) + "\" r=\"" + num(l.unit(2.5)) +
       "\" fill=\"" + kMarker + "\"/>\n</g>\n";
  return s;
}

std::string text(Vec2 at, double font_units, const std::string& anchor, const std::string& s) {
  return "<text x=\"" + num(at.x) + "\" y=\"" + num(-at.y) + "\" font-family=\"sans-serif\" " +
         "font-size=\"" + num(font_units) + "\" text-anchor=\"" + anchor + "\">" +
         svg::xml_escape(s) + "</text>\n";
}

std::string scale_bar(const Layout& l, const std::string& units) {
  const double side = svg::larger_side(l.content);
  const double length = svg::nice_step(0.25 * (l.content.hi.x - l.content.lo.x));
  const Vec2 a{l.content.lo.x, l.content.lo.y - 0.5 * kScaleBand * side};
  const Vec2 b = a + Vec2{length, 0};
  const Vec2 tick{0, l.unit(4.0)};
  const double w = l.unit(1.5);
  std::string s = "<g id=\"scale-bar\">\n";
  s += line(a, b, "black", w) + line(a - tick, a + tick, "black", w) +
       line(b - tick, b + tick, "black", w);
  s += text(b + Vec2{l.unit(8.0), -l.unit(kFontPx * 0.35)}, l.unit(kFontPx), "start",
            num(length) + " " + units);
  return s + "</g>\n";
}

std::string title(const Layout& l, const std::string& t) {
  const Vec2 at{0.5 * (l.view.lo.x + l.view.hi.x), l.view.hi.y - l.unit(1.4 * kTitleFontPx)};
  return text(at, l.unit(kTitleFontPx), "middle", t);
}

}  // namespace

std::string render_pair_svg(const Pair& pair, const Pose& pose, const SvgOptions& given) {
  SvgOptions options = given;
  if (!std::isfinite(options.width_px) || options.width_px <= 0.0) options.width_px = 800.0;
  const Part moving = placed(pair.moving, pose);
  Box content = material_box(pair.fixed);
  content.add(material_box(moving));
  content.add(Vec2{pose.x, pose.y});
  const Layout l = make_layout(content, options);

  std::string out = header(l, options);
  out += "<title>" + svg::xml_escape(pair.name.empty() ? "cslice pair" : pair.name) + "</title>\n";
  out += background(l);
  out += fixed_part(pair.fixed, l);
  out += moving_part(moving, l);
  if (options.show_reference_point) out += reference_marker(pose, l);
  if (options.show_scale_bar) out += scale_bar(l, pair.units);
  if (!options.title.empty()) out += title(l, options.title);
  return out + "</svg>\n";
}

}  // namespace cslice
