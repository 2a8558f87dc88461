// SVG drawings as pair files (docs/svg-import.md). The moving and the fixed part are two
// elements of the drawing, named by id or by Inkscape layer label: every outline under each
// (path, rect, circle, ellipse, line, polyline, polygon, and what <use> places) with the
// transforms above it. Circular arcs stay exact where the transform keeps circles circles;
// elliptical arcs, Bezier curves and circles under an uneven scale or a skew become circular
// arcs within a hundredth of the tolerance. Styles other than display:none are not read: a
// part is its outlines' geometry, stroked or filled.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <pugixml.hpp>
#include <unordered_map>

#include "cslice/drawing.hpp"
#include "cslice/tolerance.hpp"
#include "parts/drawing_internal.hpp"
#include "parts/svg_internal.hpp"
#include "parts/validate.hpp"

namespace cslice {

namespace {

using drawing::DrawingError;
using drawing::DrawnLoop;
using drawing::Layer;
using drawing::Origin;
using drawing::Piece;
using drawing::same_name;
using drawing::SvgSegment;
using drawing::SvgSubpath;

// x' = a x + c y + e, y' = b x + d y + f: SVG's matrix(a b c d e f).
struct Affine {
  double a = 1.0, b = 0.0, c = 0.0, d = 1.0, e = 0.0, f = 0.0;
  Vec2 operator()(Vec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
  // This map after `inner`.
  Affine operator*(const Affine& m) const {
    return {a * m.a + c * m.b, b * m.a + d * m.b,     a * m.c + c * m.d,
            b * m.c + d * m.d, a * m.e + c * m.f + e, b * m.e + d * m.f + f};
  }
  double det() const { return a * d - b * c; }
  // The scale of a map that keeps circles circles (a turn, a mirror and one scale), else 0.
  double circle_scale() const {
    const double s1 = std::hypot(a, b), s2 = std::hypot(c, d);
    if (!(s1 > 0.0 && s2 > 0.0)) return 0.0;
    if (std::fabs(s1 - s2) > 1e-12 * std::max(s1, s2) || std::fabs(a * c + b * d) > 1e-12 * s1 * s2)
      return 0.0;
    return std::sqrt(s1 * s2);
  }
};

Affine translation(double x, double y) {
  return {1.0, 0.0, 0.0, 1.0, x, y};
}
Affine scaling(double x, double y) {
  return {x, 0.0, 0.0, y, 0.0, 0.0};
}

std::string trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return std::string(s);
}

// CSS units in user units (px) per unit.
std::optional<double> px_per(std::string_view unit) {
  if (unit.empty() || unit == "px") return 1.0;
  if (unit == "mm") return 96.0 / 25.4;
  if (unit == "cm") return 96.0 / 2.54;
  if (unit == "in") return 96.0;
  if (unit == "pt") return 96.0 / 72.0;
  if (unit == "pc") return 16.0;
  return std::nullopt;
}

// A length attribute ("12", "3.5mm") in `unit` (user units, px, by default), or why not.
bool parse_length(std::string_view text, double& out, std::string& error,
                  std::string_view unit_wanted = "px") {
  const std::string s = trim(text);
  size_t unit_at = s.size();
  while (unit_at > 0 && std::isalpha(static_cast<unsigned char>(s[unit_at - 1]))) --unit_at;
  if (unit_at > 0 && s[unit_at - 1] == '%') {
    error = "a length in percent ('" + s + "'), which depends on the viewport: give it in units";
    return false;
  }
  const std::string unit = s.substr(unit_at);
  const std::optional<double> factor = px_per(unit);
  if (!factor) {
    error = "unit '" + unit + "' of '" + s + "' is not one of px, mm, cm, in, pt, pc";
    return false;
  }
  std::vector<double> v;
  if (!drawing::parse_svg_numbers(std::string_view(s).substr(0, unit_at), v, error)) return false;
  if (v.size() != 1) {
    error = "'" + s + "' is not one length";
    return false;
  }
  out = v[0] * (*factor / *px_per(unit_wanted));  // exactly v[0] in the unit wanted
  return std::isfinite(out) || (error = "'" + s + "' is beyond the range of numbers", false);
}

// The part a named element starts.
enum class Part { none, moving, fixed };

class SvgReader {
 public:
  SvgReader(std::string_view text, const DrawingImportOptions& options)
      : text_(text), options_(options) {
    for (size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') line_starts_.push_back(i + 1);
  }

  drawing::DrawnParts read() {
    const pugi::xml_parse_result parsed =
        document_.load_buffer(text_.data(), text_.size(), pugi::parse_default, pugi::encoding_auto);
    if (!parsed)
      throw DrawingError{"", "line " + std::to_string(line_of(parsed.offset)) +
                                 ": not well-formed XML: " + parsed.description()};
    const pugi::xml_node root = document_.document_element();
    if (local_name(root) != "svg")
      throw DrawingError{"", "not an SVG drawing: its root element is <" +
                                 std::string(root.name()) + ">, not <svg>"};
    index_ids(root);
    Context top;
    top.map = document_frame(root);
    walk_children(root, top, 1);
    for (const auto& [layer, part, name, found] :
         {std::tuple{&parts_.moving, "moving", &options_.moving_layer, &moving_found_},
          std::tuple{&parts_.fixed, "fixed", &options_.fixed_layer, &fixed_found_}}) {
      if (found->empty())
        throw DrawingError{
            part, "no element has the id or label '" + *name + "' (" + named_groups() + ")"};
      if (layer->empty())
        throw DrawingError{part,
                           "no outline (path, rect, circle, ellipse, line, polyline or "
                           "polygon) in " +
                               *found};
    }
    parts_.y_down = true;
    return std::move(parts_);
  }

 private:
  struct Context {
    Affine map;  // the element's user units to the drawing's coordinates
    Part part = Part::none;
    bool hidden = false;   // display:none on the way down, since the part's element
    bool in_defs = false;  // in <defs> or a <symbol>: a definition, drawn only by <use>
    int uses = 0;          // <use> elements on the way down
    std::string placed;    // " (placed by the <use> at line N)"
  };

  static constexpr int kMaxDepth = 256;
  static constexpr int kMaxUses = 8;
  static constexpr long long kMaxElements = 1000000;

  int line_of(ptrdiff_t offset) const {
    if (offset < 0) return 0;
    return static_cast<int>(std::upper_bound(line_starts_.begin(), line_starts_.end(),
                                             static_cast<size_t>(offset)) -
                            line_starts_.begin());  // the line starts at or before it
  }

  static std::string_view local_name(pugi::xml_node n) {
    std::string_view name = n.name();
    if (name.substr(0, 4) == "svg:") name.remove_prefix(4);
    return name;
  }

  // "<path id="p3">", as messages name an element's tag.
  static std::string tag(pugi::xml_node n) {
    std::string out = "<" + std::string(local_name(n));
    if (const char* id = n.attribute("id").value(); *id) out += " id=\"" + std::string(id) + "\"";
    return out + ">";
  }
  // "<path id="p3"> at line 12", as messages name an element.
  std::string describe(pugi::xml_node n) const {
    return tag(n) + " at line " + std::to_string(line_of(n.offset_debug()));
  }

  [[noreturn]] void fail(pugi::xml_node n, const Context& ctx, const std::string& reason) const {
    const char* part = ctx.part == Part::moving ? "moving" : ctx.part == Part::fixed ? "fixed" : "";
    throw DrawingError{part, "the " + describe(n) + ctx.placed + ": " + reason};
  }

  void index_ids(pugi::xml_node root) {
    for (pugi::xml_node n = root; n; n = next_in_document(n, root))
      if (const char* id = n.attribute("id").value(); *id) ids_.emplace(id, n);
  }

  // Document order without recursion (a deeply nested file must not exhaust the stack).
  static pugi::xml_node next_in_document(pugi::xml_node n, pugi::xml_node root) {
    if (pugi::xml_node child = n.first_child()) return child;
    for (; n && n != root; n = n.parent())
      if (pugi::xml_node sibling = n.next_sibling()) return sibling;
    return {};
  }

  // ---- The document's units ---------------------------------------------------------

  // User units to the drawing's coordinates: the document's unit (mm, cm or in, from the root's
  // width and viewBox) with y down, as the drawing program shows them.
  Affine document_frame(pugi::xml_node root) {
    Context none;
    double width = 0.0, height = 0.0;
    std::string unit = "px";
    const std::string width_text = trim(root.attribute("width").value());
    const std::string height_text = trim(root.attribute("height").value());
    std::string error;
    const bool sized = !width_text.empty() && !height_text.empty() && width_text.back() != '%' &&
                       height_text.back() != '%';
    for (const char* u : {"mm", "cm", "in"})
      if (sized && width_text.size() > 2 && width_text.substr(width_text.size() - 2) == u) unit = u;
    const double to_unit = 1.0 / *px_per(unit);  // user units without a viewBox are px
    parts_.units = unit;
    if (sized && !(parse_length(width_text, width, error, unit) &&
                   parse_length(height_text, height, error, unit)))
      fail(root, none, error);
    const std::string box_text = root.attribute("viewBox").value();
    if (box_text.empty()) return scaling(to_unit, to_unit);
    std::vector<double> box;
    if (!drawing::parse_svg_numbers(box_text, box, error) || box.size() != 4 ||
        !(box[2] > 0.0 && box[3] > 0.0))
      fail(root, none,
           "viewBox \"" + box_text + "\" is not four numbers x y width height, " +
               "the last two positive");
    if (!sized) return translation(-box[0], -box[1]);
    return viewbox_map(root, box, width, height);
  }

  // The viewBox onto a viewport w by h (SVG's preserveAspectRatio: align, then meet or slice).
  Affine viewbox_map(pugi::xml_node root, const std::vector<double>& box, double w, double h) {
    const double sx = w / box[2], sy = h / box[3];
    const std::string aspect = trim(root.attribute("preserveAspectRatio").value());
    if (aspect.substr(0, 4) == "none") return scaling(sx, sy) * translation(-box[0], -box[1]);
    const auto align = [&](std::string_view axis) {  // "xMid" -> 0.5
      const size_t at = aspect.find(axis);
      if (aspect.empty() || at == std::string::npos) return 0.5;
      const std::string_view which = std::string_view(aspect).substr(at + 1, 3);
      return which == "Min" ? 0.0 : which == "Max" ? 1.0 : 0.5;
    };
    const double s =
        aspect.find("slice") != std::string::npos ? std::max(sx, sy) : std::min(sx, sy);
    const double tx = align("xM") * (w - box[2] * s), ty = align("YM") * (h - box[3] * s);
    return translation(tx, ty) * scaling(s, s) * translation(-box[0], -box[1]);
  }

  // ---- The walk ----------------------------------------------------------------------

  void walk_children(pugi::xml_node parent, const Context& ctx, int depth) {
    for (pugi::xml_node n = parent.first_child(); n; n = n.next_sibling())
      if (n.type() == pugi::node_element) visit(n, ctx, depth);
  }

  Part named_part(pugi::xml_node n) const {
    for (const char* attribute : {"id", "inkscape:label"}) {
      const char* name = n.attribute(attribute).value();
      if (!*name) continue;
      if (same_name(name, options_.moving_layer)) return Part::moving;
      if (same_name(name, options_.fixed_layer)) return Part::fixed;
    }
    return Part::none;
  }

  // The element's part: the one its name starts, else its parent's.
  void enter_part(pugi::xml_node n, Context& ctx) {
    const Part named = ctx.uses > 0 ? Part::none : named_part(n);  // a copy is not the element
    if (named == Part::none) return;
    const std::string& name = named == Part::moving ? options_.moving_layer : options_.fixed_layer;
    if (ctx.in_defs)
      fail(n, ctx, "'" + name + "' is a definition, not drawn; name the <use> that draws it");
    if (ctx.part != Part::none && ctx.part != named)
      fail(n, ctx,
           "the " + std::string(named == Part::moving ? "moving" : "fixed") +
               " part's element lies inside the other part's");
    std::string& found = named == Part::moving ? moving_found_ : fixed_found_;
    if (!found.empty() && ctx.part != named)
      fail(n, ctx, "two elements are named '" + name + "': this one and the " + found);
    if (found.empty()) found = describe(n);
    ctx.part = named;
    ctx.hidden = false;
  }

  static bool hidden(pugi::xml_node n) {
    if (trim(n.attribute("display").value()) == "none") return true;
    std::string style = n.attribute("style").value();
    style.erase(std::remove_if(style.begin(), style.end(),
                               [](char c) { return std::isspace(static_cast<unsigned char>(c)); }),
                style.end());
    return (";" + style).find(";display:none") != std::string::npos;
  }

  void visit(pugi::xml_node n, Context ctx, int depth) {
    if (depth > kMaxDepth) fail(n, ctx, "elements nested deeper than " + std::to_string(kMaxDepth));
    if (++elements_ > kMaxElements)
      fail(n, ctx, "more than " + std::to_string(kMaxElements) + " elements, counting reuses");
    const std::string_view name = local_name(n);
    ctx.hidden = ctx.hidden || hidden(n);
    enter_part(n, ctx);
    if (const char* t = n.attribute("transform").value(); *t)
      ctx.map = ctx.map * transform(n, ctx, t);
    if (name == "g" || name == "a" || name == "switch") return walk_children(n, ctx, depth + 1);
    if (name == "defs" || name == "symbol") {
      ctx.in_defs = true;
      return walk_children(n, ctx, depth + 1);
    }
    if (name == "svg") {
      ctx.map = ctx.map * translation(length(n, ctx, "x"), length(n, ctx, "y"));
      if (*n.attribute("viewBox").value())
        fail(n, ctx, "an <svg> inside the drawing with its own viewBox is not read");
      return walk_children(n, ctx, depth + 1);
    }
    if (name == "use") return use(n, ctx, depth);
    if (ctx.part == Part::none || ctx.hidden || ctx.in_defs) return;
    Layer& layer = ctx.part == Part::moving ? parts_.moving : parts_.fixed;
    const Origin origin{tag(n), line_of(n.offset_debug()), ctx.placed};
    Shapes shapes{*this, n, ctx, origin, layer};
    if (name == "path") shapes.path();
    if (name == "rect") shapes.rect();
    if (name == "circle" || name == "ellipse") shapes.ellipse(name == "circle");
    if (name == "line") shapes.line();
    if (name == "polyline" || name == "polygon") shapes.poly(name == "polygon");
  }

  void use(pugi::xml_node n, Context ctx, int depth) {
    std::string_view href = n.attribute("href").value();
    if (href.empty()) href = n.attribute("xlink:href").value();
    // A copy is never the named element, so a <use> outside the parts draws nothing read.
    if (ctx.part == Part::none || ctx.hidden || ctx.in_defs) return;
    if (href.empty() || href.front() != '#')
      fail(n, ctx, "its href \"" + std::string(href) + "\" is not a reference #id in this file");
    const auto it = ids_.find(std::string(href.substr(1)));
    if (it == ids_.end())
      fail(n, ctx, "no element has the id '" + std::string(href.substr(1)) + "'");
    if (ctx.uses >= kMaxUses)
      fail(n, ctx, "<use> elements nested deeper than " + std::to_string(kMaxUses));
    ctx.map = ctx.map * translation(length(n, ctx, "x"), length(n, ctx, "y"));
    ctx.uses += 1;
    if (ctx.placed.empty())
      ctx.placed =
          " (placed by the <use> at line " + std::to_string(line_of(n.offset_debug())) + ")";
    const pugi::xml_node target = it->second;
    if (local_name(target) == "symbol") {
      if (*target.attribute("viewBox").value())
        fail(target, ctx, "a <symbol> with a viewBox is not read");
      return walk_children(target, ctx, depth + 1);
    }
    visit(target, ctx, depth + 1);
  }

  double length(pugi::xml_node n, const Context& ctx, const char* attribute,
                double fallback = 0.0) const {
    const char* text = n.attribute(attribute).value();
    if (!*text) return fallback;
    double v = 0.0;
    std::string error;
    if (!parse_length(text, v, error)) fail(n, ctx, std::string(attribute) + ": " + error);
    return v;
  }

  // The transform attribute: matrix, translate, scale, rotate, skewX, skewY, applied right to
  // left as listed.
  Affine transform(pugi::xml_node n, const Context& ctx, std::string_view text) const {
    Affine out;
    size_t i = 0;
    const auto bad = [&](const std::string& why) {
      fail(n, ctx, "transform \"" + std::string(text) + "\": " + why);
    };
    while (true) {
      while (i < text.size() &&
             (std::isspace(static_cast<unsigned char>(text[i])) || text[i] == ','))
        ++i;
      if (i == text.size()) return out;
      const size_t name_at = i;
      while (i < text.size() && std::isalpha(static_cast<unsigned char>(text[i]))) ++i;
      const std::string_view name = text.substr(name_at, i - name_at);
      while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      const size_t close = text.find(')', i);
      if (name.empty() || i == text.size() || text[i] != '(' || close == std::string_view::npos)
        bad("expected name(numbers) at character " + std::to_string(name_at + 1));
      std::vector<double> v;
      std::string error;
      if (!drawing::parse_svg_numbers(text.substr(i + 1, close - i - 1), v, error))
        bad(std::string(name) + ": " + error);
      i = close + 1;
      out = out * transform_function(name, v, bad);
    }
  }

  template <class Bad>
  static Affine transform_function(std::string_view name, const std::vector<double>& v, Bad bad) {
    const auto count = [&](size_t lo, size_t hi) {
      if (v.size() < lo || v.size() > hi)
        bad(std::string(name) + " takes " + std::to_string(lo) +
            (hi > lo ? " to " + std::to_string(hi) : std::string()) + " numbers, not " +
            std::to_string(v.size()));
    };
    const double rad = kPi / 180.0;
    if (name == "matrix") {
      count(6, 6);
      return {v[0], v[1], v[2], v[3], v[4], v[5]};
    }
    if (name == "translate") {
      count(1, 2);
      return translation(v[0], v.size() > 1 ? v[1] : 0.0);
    }
    if (name == "scale") {
      count(1, 2);
      return scaling(v[0], v.size() > 1 ? v[1] : v[0]);
    }
    if (name == "rotate") {
      if (v.size() == 2) bad("rotate takes an angle, or an angle and a centre x y, not 2 numbers");
      count(1, 3);
      const double c = std::cos(v[0] * rad), s = std::sin(v[0] * rad);
      const Affine turn{c, s, -s, c, 0.0, 0.0};
      if (v.size() == 1) return turn;
      return translation(v[1], v[2]) * turn * translation(-v[1], -v[2]);
    }
    if (name == "skewX") {
      count(1, 1);
      return {1.0, 0.0, std::tan(v[0] * rad), 1.0, 0.0, 0.0};
    }
    if (name == "skewY") {
      count(1, 1);
      return {1.0, std::tan(v[0] * rad), 0.0, 1.0, 0.0, 0.0};
    }
    bad("'" + std::string(name) + "' is not matrix, translate, scale, rotate, skewX or skewY");
    return {};
  }

  // ---- Shapes --------------------------------------------------------------------------

  // One element's outline into its part's layer: closed subpaths as loops, open ones as
  // pieces to join.
  struct Shapes {
    SvgReader& reader;
    pugi::xml_node n;
    const Context& ctx;
    Origin origin;
    Layer& layer;

    [[noreturn]] void fail(const std::string& why) const { reader.fail(n, ctx, why); }
    double length(const char* attribute, double fallback = 0.0) const {
      return reader.length(n, ctx, attribute, fallback);
    }
    double positive_length(const char* attribute) const {
      const double v = length(attribute);
      if (v < 0.0) fail(std::string(attribute) + " is negative");
      return v;
    }

    void path() {
      std::vector<SvgSubpath> subpaths;
      std::string error;
      if (!drawing::parse_svg_path(n.attribute("d").value(), subpaths, error))
        fail("path data (d): " + error);
      for (const SvgSubpath& s : subpaths) add(s);
    }

    void rect() {
      const double x = length("x"), y = length("y");
      const double w = positive_length("width"), h = positive_length("height");
      if (w == 0.0 || h == 0.0) return;  // not drawn
      const bool has_rx = *n.attribute("rx").value(), has_ry = *n.attribute("ry").value();
      double rx = positive_length("rx"), ry = positive_length("ry");
      if (!has_rx) rx = ry;
      if (!has_ry) ry = rx;
      rx = std::min(rx, w / 2.0);
      ry = std::min(ry, h / 2.0);
      SvgSubpath s;
      s.closed = true;
      const Vec2 corners[4] = {{x + w, y}, {x + w, y + h}, {x, y + h}, {x, y}};
      const Vec2 out[4] = {{-rx, 0.0}, {0.0, -ry}, {rx, 0.0}, {0.0, ry}};  // back along the side in
      const Vec2 in[4] = {{0.0, ry}, {-rx, 0.0}, {0.0, -ry}, {rx, 0.0}};   // on along the next
      Vec2 pen = corners[3] + in[3];
      for (int k = 0; k < 4; ++k) {
        segment(s, pen, corners[k] + out[k]);
        pen = corners[k] + out[k];
        if (rx > 0.0 && ry > 0.0)
          s.segments.push_back(turning_arc(pen, corners[k] + in[k], rx, ry));
        pen = corners[k] + in[k];
      }
      add(s);
    }

    // The arc of at most half a turn of the axis-aligned ellipse of radii rx, ry from `from` to
    // `to`, turning as angles grow (SVG's sweep flag 1).
    static SvgSegment turning_arc(Vec2 from, Vec2 to, double rx, double ry) {
      SvgSegment arc;
      arc.kind = SvgSegment::Kind::arc;
      arc.p[0] = from;
      arc.p[1] = to;
      arc.rx = rx;
      arc.ry = ry;
      arc.sweep = true;
      return arc;
    }

    static void segment(SvgSubpath& s, Vec2 from, Vec2 to) {
      SvgSegment line;
      line.p[0] = from;
      line.p[1] = to;
      s.segments.push_back(line);
    }

    void ellipse(bool circle) {
      const Vec2 c{length("cx"), length("cy")};
      double rx = positive_length(circle ? "r" : "rx");
      double ry = circle ? rx : positive_length("ry");
      if (!circle && !*n.attribute("rx").value()) rx = ry;  // SVG 2: auto, the other radius
      if (!circle && !*n.attribute("ry").value()) ry = rx;
      if (rx == 0.0 || ry == 0.0) return;  // not drawn
      const Affine& m = ctx.map;
      if (rx == ry && m.circle_scale() > 0.0) {
        DrawnLoop loop;
        loop.circle = true;
        loop.center = m(c);
        loop.radius = rx * m.circle_scale();
        loop.origin = origin.describe();
        if (!(is_finite(loop.center) && std::isfinite(loop.radius) && loop.radius > 0.0))
          fail("its centre or radius is beyond the range of numbers");
        layer.loops.push_back(loop);
        return;
      }
      SvgSubpath s;  // two half ellipses
      s.closed = true;
      for (double side : {1.0, -1.0})
        s.segments.push_back(
            turning_arc(c + Vec2{side * rx, 0.0}, c - Vec2{side * rx, 0.0}, rx, ry));
      add(s);
    }

    void line() {
      SvgSubpath s;
      segment(s, {length("x1"), length("y1")}, {length("x2"), length("y2")});
      add(s);
    }

    void poly(bool closed) {
      std::vector<double> v;
      std::string error;
      if (!drawing::parse_svg_numbers(n.attribute("points").value(), v, error))
        fail("points: " + error);
      if (v.size() % 2 != 0)
        fail("points: an odd count of numbers (" + std::to_string(v.size()) + ")");
      SvgSubpath s;
      s.closed = closed;
      for (size_t i = 2; i < v.size(); i += 2) segment(s, {v[i - 2], v[i - 1]}, {v[i], v[i + 1]});
      if (closed && v.size() >= 4) segment(s, {v[v.size() - 2], v.back()}, {v[0], v[1]});
      add(s);
    }

    void add(const SvgSubpath& s) {
      std::vector<Piece> pieces;
      for (const SvgSegment& g : s.segments) drawn(g, pieces);
      for (const Piece& p : pieces)
        if (!(is_finite(p.from) && is_finite(p.to) && std::isfinite(p.bulge)))
          fail("a point beyond the range of numbers");
      if (pieces.empty()) return;
      if (!s.closed) {
        layer.pieces.insert(layer.pieces.end(), pieces.begin(), pieces.end());
        return;
      }
      DrawnLoop loop;
      loop.edges = std::move(pieces);
      loop.origin = origin.describe();
      layer.loops.push_back(std::move(loop));
    }

    // One segment in the drawing's coordinates: a line, or a circular arc kept exact, or arcs
    // along the curve.
    void drawn(const SvgSegment& g, std::vector<Piece>& out) const {
      const Affine& m = ctx.map;
      switch (g.kind) {
        case SvgSegment::Kind::line:
          if (g.p[0] != g.p[1]) out.push_back({m(g.p[0]), m(g.p[1]), 0.0, origin});
          return;
        case SvgSegment::Kind::arc:
          return elliptical_arc(g, out);
        case SvgSegment::Kind::quadratic:
        case SvgSegment::Kind::cubic: {
          const int degree = g.kind == SvgSegment::Kind::cubic ? 3 : 2;
          Vec2 q[4];
          bool moves = false;
          for (int k = 0; k <= degree; ++k) {
            q[k] = m(g.p[k]);
            moves = moves || g.p[k] != g.p[0];
          }
          if (!moves) return;
          const auto bezier = [q, degree](double t) {
            const double s = 1.0 - t;
            if (degree == 2) return s * s * q[0] + 2.0 * s * t * q[1] + t * t * q[2];
            return s * s * s * q[0] + 3.0 * s * s * t * q[1] + 3.0 * s * t * t * q[2] +
                   t * t * t * q[3];
          };
          Box box;
          for (int k = 0; k <= degree; ++k) box.add(q[k]);
          return fitted(bezier, {0.0, 1.0}, box, out);
        }
      }
    }

    // SVG's endpoint arc (SVG 1.1, F.6.5 and F.6.6: radii too small are scaled up until the
    // arc fits), as a circular arc when the ellipse is a circle and the map keeps it one.
    void elliptical_arc(const SvgSegment& g, std::vector<Piece>& out) const {
      const Vec2 p0 = g.p[0], p1 = g.p[1];
      if (p0 == p1) return;  // SVG: no arc at all
      double rx = std::fabs(g.rx), ry = std::fabs(g.ry);
      const Affine& m = ctx.map;
      if (rx == 0.0 || ry == 0.0) {
        out.push_back({m(p0), m(p1), 0.0, origin});
        return;
      }
      const double phi = g.rotation * kPi / 180.0, cp = std::cos(phi), sp = std::sin(phi);
      const Vec2 h = (p0 - p1) * 0.5;
      const Vec2 q{cp * h.x + sp * h.y, -sp * h.x + cp * h.y};  // p0 in the ellipse's frame
      const double fit = q.x * q.x / (rx * rx) + q.y * q.y / (ry * ry);
      if (fit > 1.0) {
        rx *= std::sqrt(fit);
        ry *= std::sqrt(fit);
      }
      const double num = rx * rx * ry * ry - rx * rx * q.y * q.y - ry * ry * q.x * q.x;
      const double den = rx * rx * q.y * q.y + ry * ry * q.x * q.x;
      const double k = std::sqrt(std::max(0.0, num / den)) * (g.large == g.sweep ? -1.0 : 1.0);
      const Vec2 cq{k * rx * q.y / ry, -k * ry * q.x / rx};
      const Vec2 center = Vec2{cp * cq.x - sp * cq.y, sp * cq.x + cp * cq.y} + (p0 + p1) * 0.5;
      const double t0 = std::atan2((q.y - cq.y) / ry, (q.x - cq.x) / rx);
      const double t1 = std::atan2((-q.y - cq.y) / ry, (-q.x - cq.x) / rx);
      double sweep = t1 - t0;
      if (g.sweep && sweep < 0.0) sweep += kTwoPi;
      if (!g.sweep && sweep > 0.0) sweep -= kTwoPi;
      const auto at = [&](double t) {
        const Vec2 e{rx * std::cos(t), ry * std::sin(t)};
        return m(center + Vec2{cp * e.x - sp * e.y, sp * e.x + cp * e.y});
      };
      if (std::fabs(rx - ry) <= 1e-12 * rx && m.circle_scale() > 0.0) {
        // The map turns the arc over when it mirrors: y down stays y down, but a mirror in the
        // transforms reverses the arc's direction.
        const double turn = m.det() < 0.0 ? -1.0 : 1.0;
        out.push_back({m(p0), m(p1), turn * std::tan(sweep / 4.0), origin});
        return;
      }
      const int quarters = std::max(1, static_cast<int>(std::ceil(std::fabs(sweep) / (kPi / 2.0))));
      std::vector<double> breaks;
      for (int i = 0; i <= quarters; ++i) breaks.push_back(t0 + sweep * i / quarters);
      Box box;
      box.add(m(center - Vec2{std::max(rx, ry), std::max(rx, ry)}));
      box.add(m(center + Vec2{std::max(rx, ry), std::max(rx, ry)}));
      const size_t first = out.size();
      fitted(at, breaks, box, out);
      if (out.size() > first) {  // the ends exactly where the neighbouring segments meet them
        out[first].from = m(p0);
        out.back().to = m(p1);
      }
    }

    void fitted(const std::function<Vec2(double)>& curve, const std::vector<double>& breaks,
                const Box& box, std::vector<Piece>& out) const {
      if (const std::string problem =
              drawing::follow_curve(curve, breaks, box, reader.options_.tolerance, origin, out);
          !problem.empty())
        fail(problem);
    }
  };

  // Groups' ids and labels, for the message that names none of them.
  std::string named_groups() const {
    std::vector<std::string> names;
    const pugi::xml_node root = document_.document_element();
    for (pugi::xml_node n = root; n; n = next_in_document(n, root)) {
      if (local_name(n) != "g") continue;
      std::string name;
      for (const char* attribute : {"inkscape:label", "id"})
        if (const char* v = n.attribute(attribute).value(); *v && name.empty()) name = v;
      if (!name.empty()) names.push_back("'" + name + "'");
    }
    if (names.empty()) return "the drawing has no named groups";
    std::string out = "groups:";
    for (size_t i = 0; i < names.size() && i < 12; ++i) out += " " + names[i];
    if (names.size() > 12) out += " and " + std::to_string(names.size() - 12) + " more";
    return out;
  }

  std::string_view text_;
  const DrawingImportOptions& options_;
  std::vector<size_t> line_starts_{0};
  pugi::xml_document document_;
  std::unordered_map<std::string, pugi::xml_node> ids_;
  drawing::DrawnParts parts_;
  std::string moving_found_, fixed_found_;  // the named elements, described
  long long elements_ = 0;
};

}  // namespace

DrawingPairResult import_svg_pair(std::string_view svg_text, std::string_view source,
                                  const DrawingImportOptions& drawing_options) {
  DrawingImportOptions options = drawing_options;
  for (std::string* name : {&options.moving_layer, &options.fixed_layer})
    if (name->size() > 1 && name->front() == '#') name->erase(0, 1);  // as href and CSS write ids
  return drawing::import_parts(source, options, "element", [&] {
    if (same_name(options.moving_layer, options.fixed_layer))
      throw DrawingError{"", "the moving and the fixed part are both named '" +
                                 options.moving_layer + "': name one element for each"};
    return SvgReader(svg_text, options).read();
  });
}

DrawingPairResult load_svg_pair(const std::string& path, const DrawingImportOptions& options) {
  return drawing::import_file(
      path, [&](std::string_view text) { return import_svg_pair(text, path, options); });
}

}  // namespace cslice
