// A slice as an SVG picture, after the paper's Figure 1 (right): blocked space grey, free
// space white, the realizable contact pieces on top coloured by contact kind. World
// coordinates are mapped to pixels here (+y up becomes SVG's +y down), so text stays upright
// and stroke widths are in pixels whatever the pair's size.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "cslice/render_svg.hpp"
#include "cslice/slice.hpp"
#include "cslice/slice_io.hpp"
#include "render/svg_writer.hpp"

namespace cslice {

namespace {

// Layout, in pixels.
constexpr double kPad = 16.0;
constexpr double kTitleBand = 40.0;   // above the plot
constexpr double kLeftBand = 64.0;    // left of the plot: y tick labels
constexpr double kBottomBand = 64.0;  // below the plot: x tick labels and the scale bar
constexpr double kLegendWidth = 250.0;
constexpr double kLegendRow = 22.0;
constexpr double kMaxAspect = 1.5;  // the plot is at most this many times taller than wide
// Margin around the fitted pieces, as a fraction of the larger side of their box.
constexpr double kMarginFraction = 0.06;

constexpr const char* kBlockedFill = "#c8c8c8";
constexpr const char* kFreeFill = "#ffffff";
constexpr const char* kMarkStyle = "fill=\"#e4002b\" stroke=\"#ffffff\" stroke-width=\"1.5\"";
constexpr const char* kEvenOdd = " fill-rule=\"evenodd\"";
constexpr const char* kDashed = " stroke-dasharray=\"4 3\"";

using svg::cat;

// Pixel coordinates and sizes.
std::string num(double v) {
  return svg::fixed(v, 2);
}

// World values (tick labels, lengths, the theta of the title).
std::string label(double v) {
  return svg::number(v, 6);
}

std::string fill(const char* colour) {
  return cat("fill=\"", colour, "\"");
}

// One colour per contact kind, in enum order (distinct on white and on grey).
const char* kind_colour(ContactKind k) {
  switch (k) {
    case ContactKind::vertex_segment:
      return "#1f77b4";
    case ContactKind::segment_vertex:
      return "#ff7f0e";
    case ContactKind::arc_segment:
      return "#2ca02c";
    case ContactKind::segment_arc:
      return "#9467bd";
    case ContactKind::arc_arc:
      return "#d62728";
    case ContactKind::vertex_arc:
      return "#8c564b";
    case ContactKind::arc_vertex:
      return "#e377c2";
  }
  return "#555555";
}

constexpr ContactKind kAllKinds[] = {ContactKind::vertex_segment, ContactKind::segment_vertex,
                                     ContactKind::arc_segment,    ContactKind::segment_arc,
                                     ContactKind::arc_arc,        ContactKind::vertex_arc,
                                     ContactKind::arc_vertex};

// World-to-pixel mapping of the plot area.
struct View {
  Box world;
  double scale = 1.0;  // pixels per unit
  double left = 0.0, top = 0.0;
  double width() const { return (world.hi.x - world.lo.x) * scale; }
  double height() const { return (world.hi.y - world.lo.y) * scale; }
  Vec2 px(Vec2 p) const {
    return {left + (p.x - world.lo.x) * scale, top + (world.hi.y - p.y) * scale};
  }
};

std::string xy(Vec2 p) {
  return cat(num(p.x), ",", num(p.y));
}

bool has_unbounded(const Slice& slice) {
  return std::any_of(slice.free_components.begin(), slice.free_components.end(),
                     [](const FreeComponent& c) { return !c.bounded; });
}

Box curve_box(const Curve& c, bool is_point) {
  if (!is_point) return bounding_box(c);
  Box b;
  b.add(c.from);
  return b;
}

// The region to show: every realizable piece, or every contact segment when free space runs
// off to infinity (its far side is then only bounded by the picture).
Box world_box(const Pair& pair, const Slice& slice, const SlicePictureOptions& options) {
  Box b;
  for (const ContactPiece& p : slice.realizable) b.add(bounding_box(p.curve));
  for (const DegenerateContact& d : slice.degenerate) b.add(curve_box(d.curve, d.is_point));
  if (has_unbounded(slice) || b.empty())
    for (const ContactSegment& s : slice.contact_segments) b.add(curve_box(s.curve, s.is_point));
  if (options.mark) b.add(*options.mark);
  if (b.empty()) b = pair.fixed.box;
  if (b.empty()) b.add(Vec2{0.0, 0.0});
  double side = svg::larger_side(b);
  // A lone point has no extent; show a patch the size of the pair around it.
  if (!(side > 0.0)) side = pair.tol.size > 0.0 ? pair.tol.size : 1.0;
  return b.inflated(kMarginFraction * side);
}

View make_view(const Box& world, double width_px) {
  View v;
  v.world = world;
  const double w = world.hi.x - world.lo.x, h = world.hi.y - world.lo.y;
  v.scale = std::min(width_px / w, kMaxAspect * width_px / h);
  v.left = kLeftBand;
  v.top = kTitleBand;
  return v;
}

// ---- Paths ---------------------------------------------------------------------------

// One SVG arc command to `to_px`, with the flags of svg::arc_flags.
std::string arc_to(double r_px, svg::ArcFlags flags, Vec2 to_px) {
  return cat("A", num(r_px), " ", num(r_px), " 0 ", flags.large ? "1" : "0", " ",
             flags.sweep ? "1" : "0", " ", xy(to_px));
}

// Commands tracing `c` from its start, where the pen already is. A full circle goes as two
// halves (svg::split_full_circle), the second ending exactly where the pen started.
std::string curve_commands(const View& v, const Curve& c) {
  if (c.is_segment()) return cat("L", xy(v.px(c.to)));
  const double r = c.radius * v.scale;
  if (c.is_full_circle()) {
    const auto [first, second] = svg::split_full_circle(c);
    return cat(arc_to(r, svg::arc_flags(first), v.px(first.to)),
               arc_to(r, svg::arc_flags(second), v.px(c.from)));
  }
  return arc_to(r, svg::arc_flags(c), v.px(c.to));
}

std::string curve_path(const View& v, const Curve& c) {
  return cat("M", xy(v.px(c.from)), curve_commands(v, c));
}

// One closed subpath per cycle. Consecutive pieces should meet; a gap is bridged by a line
// rather than leaving the fill open.
std::string cycles_path(const View& v, const std::vector<std::vector<ContactPiece>>& cycles) {
  std::string d;
  for (const auto& cycle : cycles) {
    if (cycle.empty()) continue;
    d += cat("M", xy(v.px(cycle.front().curve.from)));
    Vec2 pen = cycle.front().curve.from;
    for (const ContactPiece& p : cycle) {
      if (!(p.curve.from == pen)) d += cat("L", xy(v.px(p.curve.from)));
      d += curve_commands(v, p.curve);
      pen = p.curve.to;
    }
    d += "Z";
  }
  return d;
}

// ---- Layers --------------------------------------------------------------------------

std::string rect(double x, double y, double w, double h, const std::string& attrs) {
  return cat("<rect x=\"", num(x), "\" y=\"", num(y), "\" width=\"", num(w), "\" height=\"", num(h),
             "\" ", attrs, "/>\n");
}

std::string plot_rect(const View& v, const std::string& attrs) {
  return rect(v.left, v.top, v.width(), v.height(), attrs);
}

std::string path(const std::string& d, const std::string& attrs) {
  return cat("<path d=\"", d, "\" ", attrs, "/>\n");
}

std::string dot(Vec2 p_px, double r, const std::string& attrs) {
  return cat("<circle cx=\"", num(p_px.x), "\" cy=\"", num(p_px.y), "\" r=\"", num(r), "\" ", attrs,
             "/>\n");
}

// Everything starts blocked. The unbounded component frees the whole view except the
// islands its (clockwise) cycles enclose; bounded components then free the inside of their
// outer cycle minus their holes, which even-odd filling gives directly. Bounded components
// come last because they can sit inside the unbounded component's islands.
std::string regions_layer(const View& v, const Slice& slice) {
  std::string out = plot_rect(v, fill(kBlockedFill));
  for (const FreeComponent& c : slice.free_components) {
    if (c.bounded) continue;
    out += plot_rect(v, fill(kFreeFill));
    const std::string d = cycles_path(v, c.boundary);
    if (!d.empty()) out += path(d, cat(fill(kBlockedFill), kEvenOdd));
  }
  for (const FreeComponent& c : slice.free_components) {
    if (!c.bounded) continue;
    const std::string d = cycles_path(v, c.boundary);
    if (!d.empty()) out += path(d, cat(fill(kFreeFill), kEvenOdd));
  }
  return out;
}

std::map<int, const ContactSegment*> segments_by_id(const Slice& slice) {
  std::map<int, const ContactSegment*> by_id;
  for (const ContactSegment& s : slice.contact_segments) by_id[s.id] = &s;
  return by_id;
}

std::string stroke(const char* colour, double width) {
  return cat("fill=\"none\" stroke=\"", colour, "\" stroke-width=\"", num(width),
             "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"");
}

// Contact segments that bound no free space: thin and dashed, only on request.
std::string unrealizable_layer(const View& v, const Slice& slice) {
  const std::set<int> realizable = realizable_segment_ids(slice);
  std::string out;
  for (const ContactSegment& s : slice.contact_segments) {
    if (s.is_point || realizable.count(s.id)) continue;
    out += path(curve_path(v, s.curve),
                cat(stroke(kind_colour(s.kind), 0.8), kDashed, " opacity=\"0.7\""));
  }
  return out;
}

// Degenerate curves thick and black underneath, so the coloured piece drawn over them shows
// its kind inside a black border; degenerate points as dots on top of everything.
std::string degenerate_curves_layer(const View& v, const Slice& slice) {
  std::string out;
  for (const DegenerateContact& d : slice.degenerate)
    if (!d.is_point && !(d.curve.from == d.curve.to && d.curve.is_segment()))
      out += path(curve_path(v, d.curve), stroke("#000000", 6.0));
  return out;
}

std::string degenerate_points_layer(const View& v, const Slice& slice) {
  std::string out;
  for (const DegenerateContact& d : slice.degenerate)
    if (d.is_point || (d.curve.from == d.curve.to && d.curve.is_segment()))
      out += dot(v.px(d.curve.from), 4.5, "fill=\"#000000\"");
  return out;
}

std::string pieces_layer(const View& v, const Slice& slice,
                         const std::map<int, const ContactSegment*>& by_id) {
  std::string out;
  for (const ContactPiece& p : slice.realizable) {
    const auto it = by_id.find(p.segment);
    const char* colour = it == by_id.end() ? "#555555" : kind_colour(it->second->kind);
    out += path(curve_path(v, p.curve), stroke(colour, 2.2));
  }
  return out;
}

// ---- Frame, ticks, scale bar, legend -------------------------------------------------

std::string text(Vec2 at, const std::string& s, const std::string& attrs) {
  return cat("<text x=\"", num(at.x), "\" y=\"", num(at.y), "\" ", attrs, ">", svg::xml_escape(s),
             "</text>\n");
}

std::string line(Vec2 a, Vec2 b, const std::string& attrs) {
  return cat("<line x1=\"", num(a.x), "\" y1=\"", num(a.y), "\" x2=\"", num(b.x), "\" y2=\"",
             num(b.y), "\" ", attrs, "/>\n");
}

// Ticks at round coordinates on the bottom and left edges, so positions can be read off.
std::string ticks_layer(const View& v) {
  const Box& w = v.world;
  const double step = svg::nice_step(svg::larger_side(w) / 6.0);
  const std::string tick = "stroke=\"#000000\" stroke-width=\"1\"";
  const std::string font = "font-family=\"sans-serif\" font-size=\"11\"";
  std::string out;
  const double bottom = v.top + v.height();
  // Counted in whole steps, so the labels carry no accumulated rounding.
  for (double i = std::ceil(w.lo.x / step); i * step <= w.hi.x; i += 1.0) {
    const double px = v.px({i * step, 0.0}).x;
    out += line({px, bottom}, {px, bottom + 5.0}, tick);
    out += text({px, bottom + 17.0}, label(i * step), cat(font, " text-anchor=\"middle\""));
  }
  for (double i = std::ceil(w.lo.y / step); i * step <= w.hi.y; i += 1.0) {
    const double py = v.px({0.0, i * step}).y;
    out += line({v.left - 5.0, py}, {v.left, py}, tick);
    out += text({v.left - 8.0, py + 4.0}, label(i * step), cat(font, " text-anchor=\"end\""));
  }
  return out;
}

std::string scale_bar(const View& v, const std::string& units) {
  const double len = svg::nice_step((v.world.hi.x - v.world.lo.x) / 4.0);
  const double y = v.top + v.height() + 44.0;
  const double x0 = v.left, x1 = v.left + len * v.scale;
  const std::string s = "stroke=\"#000000\" stroke-width=\"2\"";
  std::string out = line({x0, y}, {x1, y}, s);
  out += line({x0, y - 5.0}, {x0, y + 5.0}, s) + line({x1, y - 5.0}, {x1, y + 5.0}, s);
  out += text({x1 + 8.0, y + 4.0}, cat(label(len), " ", units),
              "font-family=\"sans-serif\" font-size=\"12\"");
  return out;
}

struct LegendEntry {
  std::string swatch;  // drawn in a 24 x 14 box whose top-left corner is (0, 0)
  std::string text;
};

std::vector<LegendEntry> legend_entries(const Slice& slice, const SlicePictureOptions& options,
                                        const std::map<int, const ContactSegment*>& by_id) {
  std::vector<LegendEntry> entries;
  const std::string outline = " stroke=\"#000000\" stroke-width=\"0.8\"";
  entries.push_back({rect(0, 0, 24, 14, cat(fill(kBlockedFill), outline)), "blocked space"});
  entries.push_back({rect(0, 0, 24, 14, cat(fill(kFreeFill), outline)), "free space"});
  std::set<ContactKind> present;
  for (const ContactPiece& p : slice.realizable)
    if (const auto it = by_id.find(p.segment); it != by_id.end()) present.insert(it->second->kind);
  for (ContactKind k : kAllKinds)
    if (present.count(k))
      entries.push_back(
          {line({0, 7}, {24, 7}, stroke(kind_colour(k), 2.2)), std::string(to_string(k))});
  if (!slice.degenerate.empty())
    entries.push_back(
        {line({2, 7}, {22, 7}, stroke("#000000", 6.0)) + dot({12, 7}, 4.5, "fill=\"#000000\""),
         "degenerate contact"});
  const bool any_unrealizable =
      realizable_segment_ids(slice).size() < slice.contact_segments.size();
  if (options.show_all_segments && any_unrealizable)
    entries.push_back(
        {line({0, 7}, {24, 7}, cat(stroke("#555555", 0.8), kDashed)), "unrealizable segment"});
  if (options.mark)
    entries.push_back({dot({12, 7}, 5.0, kMarkStyle), cat("configuration (", label(options.mark->x),
                                                          ", ", label(options.mark->y), ")")});
  return entries;
}

std::string legend_layer(const std::vector<LegendEntry>& entries, double x, double y) {
  std::string out;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const double row_y = y + static_cast<double>(i) * kLegendRow;
    out += cat("<g transform=\"translate(", num(x), ",", num(row_y), ")\">\n", entries[i].swatch);
    out += text({32, 11.5}, entries[i].text, "font-family=\"sans-serif\" font-size=\"13\"");
    out += "</g>\n";
  }
  return out;
}

std::string default_title(const Pair& pair, const Slice& slice) {
  const std::string t = cat("theta = ", label(slice.theta));
  return pair.name.empty() ? t : cat(pair.name, ": ", t);
}

}  // namespace

std::string render_slice_svg(const Pair& pair, const Slice& slice,
                             const SlicePictureOptions& options) {
  const View v = make_view(world_box(pair, slice, options), options.width_px);
  const auto by_id = segments_by_id(slice);
  const std::vector<LegendEntry> entries =
      options.show_legend ? legend_entries(slice, options, by_id) : std::vector<LegendEntry>{};
  const double legend_w = options.show_legend ? kLegendWidth : 0.0;
  const double width = v.left + v.width() + kPad + legend_w;
  const double height = std::max(v.top + v.height() + kBottomBand,
                                 v.top + static_cast<double>(entries.size()) * kLegendRow) +
                        kPad;

  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\""
      << num(height) << "\" viewBox=\"0 0 " << num(width) << " " << num(height) << "\">\n";
  out << rect(0, 0, width, height, "fill=\"#ffffff\"");
  out << text({v.left, 26.0}, options.title.empty() ? default_title(pair, slice) : options.title,
              "font-family=\"sans-serif\" font-size=\"16\"");
  // Everything geometric is clipped to the plot, so off-view segments cannot spill over.
  out << "<defs><clipPath id=\"plot\">" << plot_rect(v, "") << "</clipPath></defs>\n";
  out << "<g clip-path=\"url(#plot)\">\n";
  out << regions_layer(v, slice);
  if (options.show_all_segments) out << unrealizable_layer(v, slice);
  out << degenerate_curves_layer(v, slice) << pieces_layer(v, slice, by_id)
      << degenerate_points_layer(v, slice);
  if (options.mark) out << dot(v.px(*options.mark), 5.0, kMarkStyle);
  out << "</g>\n";
  out << plot_rect(v, "fill=\"none\" stroke=\"#000000\" stroke-width=\"1\"") << ticks_layer(v);
  if (options.show_scale_bar) out << scale_bar(v, pair.units);
  out << legend_layer(entries, v.left + v.width() + kPad + 8.0, v.top);
  out << "</svg>\n";
  return out.str();
}

}  // namespace cslice
