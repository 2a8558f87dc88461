// A slice as a DXF drawing (docs/dxf-import.md, Slices as drawings): each free component's
// boundary cycles as closed polylines with bulges on a layer of its own, so a CAD program
// shows the exact arcs and can measure and dimension them. Written as DXF R12, the version
// every reader takes with nothing but an ENTITIES section: POLYLINE and VERTEX entities,
// not LWPOLYLINE (R2000 files need handles and tables).
#include <charconv>
#include <cmath>

#include "cslice/dxf.hpp"
#include "parts/drawing_internal.hpp"

namespace cslice {

namespace {

class Groups {
 public:
  void add(int code, std::string_view value) {
    text_ += code < 10 ? "  " : code < 100 ? " " : "";
    text_ += std::to_string(code);
    text_ += '\n';
    text_ += value;
    text_ += '\n';
  }
  // The shortest text that reads back as the same double.
  void add(int code, double value) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value == 0.0 ? 0.0 : value);
    add(code, std::string_view(buf, ec == std::errc() ? end - buf : 0));
  }
  std::string take() { return std::move(text_); }

 private:
  std::string text_;
};

// The $INSUNITS code of the pair's units, as the importer reads them (0: unitless).
int insunits(const std::string& units) {
  for (const auto& [code, name] : drawing::kInsunits)
    if (units == name) return code;
  return 0;
}

void cycle(Groups& g, const std::string& layer, const std::vector<ContactPiece>& pieces) {
  if (pieces.size() == 1 && pieces[0].curve.is_full_circle()) {
    g.add(0, "CIRCLE");
    g.add(8, layer);
    g.add(10, pieces[0].curve.center.x);
    g.add(20, pieces[0].curve.center.y);
    g.add(40, pieces[0].curve.radius);
    return;
  }
  g.add(0, "POLYLINE");
  g.add(8, layer);
  g.add(66, "1");
  g.add(10, 0.0);
  g.add(20, 0.0);
  g.add(70, "1");  // closed
  for (const ContactPiece& piece : pieces) {
    g.add(0, "VERTEX");
    g.add(8, layer);
    g.add(10, piece.curve.from.x);
    g.add(20, piece.curve.from.y);
    if (piece.curve.is_arc()) g.add(42, piece.curve.bulge);
  }
  g.add(0, "SEQEND");
  g.add(8, layer);
}

}  // namespace

std::string slice_to_dxf(const Pair& pair, const Slice& slice) {
  Groups g;
  g.add(0, "SECTION");
  g.add(2, "HEADER");
  g.add(9, "$ACADVER");
  g.add(1, "AC1009");
  g.add(9, "$INSUNITS");
  g.add(70, std::to_string(insunits(pair.units)));
  g.add(0, "ENDSEC");
  g.add(0, "SECTION");
  g.add(2, "ENTITIES");
  for (const FreeComponent& c : slice.free_components)
    for (const std::vector<ContactPiece>& pieces : c.boundary)
      if (!pieces.empty()) cycle(g, "FREE_" + std::to_string(c.id), pieces);
  for (const DegenerateContact& d : slice.degenerate) {
    if (d.is_point) {
      g.add(0, "POINT");
      g.add(8, "PERFECT_FIT");
      g.add(10, d.curve.from.x);
      g.add(20, d.curve.from.y);
      continue;
    }
    // A sliding fit: free space pinched to a curve, drawn as that curve.
    g.add(0, d.curve.is_arc() ? "ARC" : "LINE");
    g.add(8, "SLIDING_FIT");
    if (d.curve.is_arc()) {
      // DXF arcs run counterclockwise from the start angle (degrees).
      const Curve& c = d.curve;
      const double a0 = c.start_angle * 180.0 / kPi, a1 = (c.start_angle + c.sweep) * 180.0 / kPi;
      g.add(10, c.center.x);
      g.add(20, c.center.y);
      g.add(40, c.radius);
      g.add(50, c.sweep > 0.0 ? a0 : a1);
      g.add(51, c.sweep > 0.0 ? a1 : a0);
    } else {
      g.add(10, d.curve.from.x);
      g.add(20, d.curve.from.y);
      g.add(11, d.curve.to.x);
      g.add(21, d.curve.to.y);
    }
  }
  g.add(0, "ENDSEC");
  g.add(0, "EOF");
  return g.take();
}

}  // namespace cslice
