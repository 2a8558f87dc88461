// DXF drawings as pair files (docs/dxf-import.md). A DXF file is a list of groups, each two
// lines of an ASCII file, an integer code and a value (or, in a binary file, a code of one or
// two bytes and a value of the type its code says). We read the header's unit and the ENTITIES
// section, and of its entities those on the two chosen layers: LINE, ARC, CIRCLE, LWPOLYLINE
// and POLYLINE (with its VERTEX entities), SPLINE and ELLIPSE (as arcs within a hundredth of the
// tolerance), and the entities of the blocks INSERTs place.
//
// Read here rather than with dxflib (Debian's libdxflib 3.26.4): that library crashed on a
// LWPOLYLINE declaring 99999999999 vertices (it sizes an array from the count) and asked for
// 32 GB on 2e9, where bad input must get a message and exit status 2. The few entities a
// part outline uses are short to read, and every value is checked as it is taken.
#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <set>
#include <span>
#include <tuple>

#include "cslice/drawing.hpp"
#include "cslice/tolerance.hpp"
#include "parts/drawing_internal.hpp"
#include "parts/validate.hpp"

namespace cslice {

namespace {

using drawing::DrawnLoop;
using drawing::Layer;
using drawing::Origin;
using drawing::Piece;

struct Group {
  int code = 0;
  std::string_view value;
  int line = 0;  // 1-based line of the code
};

using drawing::DrawingError;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::string quoted(std::string_view s) {
  return "'" + std::string(s.substr(0, 40)) + (s.size() > 40 ? "...'" : "'");
}

// The type of a group's value in a binary DXF file, by its code (the DXF reference's table
// of group code ranges).
enum class BinaryValue { text, real, int16, int32, int64, boolean, chunk, unknown };
BinaryValue binary_value_type(int code) {
  const auto in = [code](int lo, int hi) { return code >= lo && code <= hi; };
  if (in(0, 9) || in(100, 105) || in(300, 309) || in(320, 369) || in(390, 399) || in(410, 419) ||
      in(430, 439) || in(470, 481) || code == 999 || in(1000, 1003) || in(1005, 1009))
    return BinaryValue::text;
  if (in(10, 59) || in(110, 149) || in(210, 239) || in(460, 469) || in(1010, 1059))
    return BinaryValue::real;
  if (in(60, 79) || in(170, 179) || in(270, 289) || in(370, 389) || in(400, 409) || in(1060, 1070))
    return BinaryValue::int16;
  if (in(90, 99) || in(420, 429) || in(440, 459) || code == 1071) return BinaryValue::int32;
  if (in(160, 169)) return BinaryValue::int64;
  if (in(290, 299)) return BinaryValue::boolean;
  if (in(310, 319) || code == 1004) return BinaryValue::chunk;
  return BinaryValue::unknown;
}

// The groups of a binary DXF file, each value written out as the ASCII file would hold it
// (numbers to the last bit) into `values`, whose elements stay where they are. Group codes
// take two bytes (R13 on) or one (R12, 255 then two for larger codes); a group's "line" is the
// one it would have in the ASCII file, two lines a group.
std::vector<Group> read_binary_groups(std::string_view data, std::deque<std::string>& values) {
  size_t at = 22;  // "AutoCAD Binary DXF\r\n\x1a\0"
  const bool wide_codes = data.size() >= at + 2 && data[at] == '\0' && data[at + 1] == '\0';
  const auto take = [&](size_t n) {
    if (data.size() - at < n)
      throw DrawingError{"", "byte " + std::to_string(at) + ": the binary DXF file is cut short"};
    const std::string_view bytes = data.substr(at, n);
    at += n;
    return bytes;
  };
  const auto little = [&](size_t n) {
    uint64_t v = 0;
    const std::string_view b = take(n);
    for (size_t k = n; k-- > 0;) v = (v << 8) | static_cast<unsigned char>(b[k]);
    return v;
  };
  std::vector<Group> groups;
  while (at < data.size()) {
    Group g;
    g.line = 2 * static_cast<int>(groups.size()) + 1;
    const size_t start = at;
    g.code = static_cast<int>(wide_codes ? static_cast<int16_t>(little(2)) : little(1));
    if (!wide_codes && g.code == 255) g.code = static_cast<int16_t>(little(2));
    std::string& value = values.emplace_back();
    switch (binary_value_type(g.code)) {
      case BinaryValue::text: {
        const size_t end = data.find('\0', at);
        if (end == std::string_view::npos) take(data.size() - at + 1);  // cut short
        value = std::string(trim(take(end - at)));
        take(1);
        break;
      }
      case BinaryValue::real: {
        const double v = std::bit_cast<double>(little(8));
        char buffer[32];
        value.assign(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
        break;
      }
      case BinaryValue::int16:
        value = std::to_string(static_cast<int16_t>(little(2)));
        break;
      case BinaryValue::int32:
        value = std::to_string(static_cast<int32_t>(little(4)));
        break;
      case BinaryValue::int64:
        value = std::to_string(static_cast<int64_t>(little(8)));
        break;
      case BinaryValue::boolean:
        value = std::to_string(little(1));
        break;
      case BinaryValue::chunk:
        take(little(1));
        break;  // binary data: nothing of an outline
      case BinaryValue::unknown:
        throw DrawingError{"", "byte " + std::to_string(start) + ": group code " +
                                   std::to_string(g.code) + " has no type a binary DXF file knows"};
    }
    g.value = value;
    groups.push_back(g);
    if (g.code == 0 && value == "EOF") break;
  }
  if (groups.empty()) throw DrawingError{"", "the binary DXF file holds no groups"};
  return groups;
}

// The groups of the text: a code line (an integer), then its value line.
std::vector<Group> read_groups(std::string_view text, std::deque<std::string>& binary_values) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a UTF-8 byte order mark
  if (text.substr(0, 18) == "AutoCAD Binary DXF") return read_binary_groups(text, binary_values);
  std::vector<std::string_view> lines;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    lines.push_back(trim(text.substr(start, end - start)));
    start = end + 1;
  }
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  if (lines.empty()) throw DrawingError{"", "the file is empty: not a DXF drawing"};
  std::vector<Group> groups;
  for (size_t i = 0; i < lines.size(); i += 2) {
    Group g;
    g.line = static_cast<int>(i) + 1;
    const std::string_view code = lines[i];
    const auto [end, ec] = std::from_chars(code.data(), code.data() + code.size(), g.code);
    if (code.empty() || ec != std::errc() || end != code.data() + code.size())
      throw DrawingError{"", "line " + std::to_string(g.line) + ": group code " + quoted(code) +
                                 " is not an integer: not an ASCII DXF file"};
    if (i + 1 >= lines.size())
      throw DrawingError{"", "line " + std::to_string(g.line) + ": group code " +
                                 std::string(code) + " has no value: the file is cut short"};
    g.value = lines[i + 1];
    groups.push_back(g);
  }
  return groups;
}

// One entity: its type, the line it starts at and its groups (up to the next code 0).
struct Entity {
  std::string_view type;
  int line = 0;
  std::span<const Group> groups;
  std::string_view layer() const {
    for (const Group& g : groups)
      if (g.code == 8) return g.value;
    return "0";  // DXF's default layer
  }
};

// The drawing's two layers, filled entity by entity.
class Reader {
 public:
  explicit Reader(const DrawingImportOptions& options) : options_(options) {}

  Layer moving, fixed;
  std::set<std::string> layers_seen;  // layers holding any entity, for messages
  std::string units;

  void read(const std::vector<Group>& groups) {
    std::vector<EntityWithVertices> entities;
    size_t i = 0;
    while (i < groups.size()) {
      if (groups[i].code == 0 && groups[i].value == "EOF") break;
      if (groups[i].code == 0 && groups[i].value == "SECTION" && i + 1 < groups.size() &&
          groups[i + 1].code == 2) {
        const std::string_view name = groups[i + 1].value;
        i += 2;
        const size_t end = section_end(groups, i);
        const std::span<const Group> section{groups.data() + i, end - i};
        if (name == "HEADER") read_header(section);
        if (name == "BLOCKS") read_blocks(section);
        if (name == "ENTITIES") entities = read_entities(section);
        i = end;
        continue;
      }
      ++i;
    }
    // After the whole file: an INSERT may come before its block's definition.
    for (const EntityWithVertices& e : entities) entity(e.entity, &e.vertices);
  }

 private:
  static size_t section_end(const std::vector<Group>& groups, size_t i) {
    while (i < groups.size() && !(groups[i].code == 0 && groups[i].value == "ENDSEC")) ++i;
    return i;
  }

  void read_header(std::span<const Group> groups) {
    for (size_t i = 0; i + 1 < groups.size(); ++i)
      if (groups[i].code == 9 && groups[i].value == "$INSUNITS" && groups[i + 1].code == 70) {
        int code = 0;
        const std::string_view v = groups[i + 1].value;
        std::from_chars(v.data(), v.data() + v.size(), code);
        for (const auto& [c, name] : drawing::kInsunits)
          if (c == code) units = name;
      }
  }

  struct EntityWithVertices {
    Entity entity;
    std::vector<Entity> vertices;  // a POLYLINE's VERTEX entities
  };

  static std::vector<EntityWithVertices> read_entities(std::span<const Group> groups) {
    std::vector<EntityWithVertices> out;
    size_t i = 0;
    while (i < groups.size()) {
      if (groups[i].code != 0) {
        ++i;
        continue;
      }
      size_t end = i + 1;
      while (end < groups.size() && groups[end].code != 0) ++end;
      EntityWithVertices& e = out.emplace_back();
      e.entity = {groups[i].value, groups[i].line, groups.subspan(i + 1, end - i - 1)};
      i = end;
      if (e.entity.type != "POLYLINE") continue;
      // Its vertices follow as entities of their own, up to SEQEND.
      while (i < groups.size() && groups[i].value != "SEQEND" &&
             (groups[i].code != 0 || groups[i].value == "VERTEX")) {
        size_t v_end = i + 1;
        while (v_end < groups.size() && groups[v_end].code != 0) ++v_end;
        if (groups[i].code == 0)
          e.vertices.push_back(
              {groups[i].value, groups[i].line, groups.subspan(i + 1, v_end - i - 1)});
        i = v_end;
      }
    }
    return out;
  }

  // Block definitions: BLOCK (its name, code 2, and base point), its entities, ENDBLK.
  struct Block {
    Vec2 base;
    std::vector<EntityWithVertices> entities;
  };

  void read_blocks(std::span<const Group> groups) {
    size_t i = 0;
    while (i < groups.size()) {
      if (!(groups[i].code == 0 && groups[i].value == "BLOCK")) {
        ++i;
        continue;
      }
      size_t end = i + 1;
      while (end < groups.size() && !(groups[end].code == 0 && groups[end].value == "ENDBLK"))
        ++end;
      size_t header_end = i + 1;
      while (header_end < end && groups[header_end].code != 0) ++header_end;
      const Entity header{groups[i].value, groups[i].line,
                          groups.subspan(i + 1, header_end - i - 1)};
      std::string name;
      Block block;
      for (const Group& g : header.groups) {
        if (g.code == 2) name = upper(g.value);
        if (g.code == 10) block.base.x = number(g, origin_of("BLOCK", header.line));
        if (g.code == 20) block.base.y = number(g, origin_of("BLOCK", header.line));
      }
      block.entities = read_entities(groups.subspan(header_end, end - header_end));
      blocks_[name] = std::move(block);
      i = end;
    }
  }

  static std::string upper(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
  }

  // The entity's layer. In a block, layer 0 means the layer of the INSERT that places it
  // (DXF's rule).
  std::string layer_name(const Entity& e) const {
    std::string name(trim(e.layer()));
    return name == "0" && !inserts_.empty() ? inserts_.back().layer : name;
  }

  Layer* layer_of(const Entity& e, std::string& part) {
    const std::string name = layer_name(e);
    layers_seen.insert(name);
    if (drawing::same_name(name, options_.moving_layer)) {
      part = "moving";
      return &moving;
    }
    if (drawing::same_name(name, options_.fixed_layer)) {
      part = "fixed";
      return &fixed;
    }
    return nullptr;
  }

  void entity(const Entity& e, const std::vector<Entity>* vertices) {
    if (e.type == "INSERT") return insert(e);
    std::string part;
    Layer* layer = layer_of(e, part);
    if (!layer) return;
    part_ = part;
    const Origin origin = origin_of(e.type, e.line);
    if (e.type == "LINE")
      line(e, origin, *layer);
    else if (e.type == "ARC")
      arc(e, origin, *layer);
    else if (e.type == "CIRCLE")
      circle(e, origin, *layer);
    else if (e.type == "LWPOLYLINE")
      lwpolyline(e, origin, *layer);
    else if (e.type == "POLYLINE")
      polyline(e, *vertices, origin, *layer);
    else if (e.type == "SPLINE")
      spline(e, origin, *layer);
    else if (e.type == "ELLIPSE")
      ellipse(e, origin, *layer);
    // Anything else (text, dimensions, hatches, points) annotates the drawing: not outline.
  }

  [[noreturn]] void fail(const std::string& reason) const {
    if (part_.empty()) throw DrawingError{"", reason};
    throw DrawingError{part_, "layer '" + current_layer() + "': " + reason};
  }
  std::string current_layer() const {
    return part_ == "moving" ? options_.moving_layer : options_.fixed_layer;
  }

  double number(const Group& g, const Origin& origin) const {
    double v = 0.0;
    const std::string_view s = g.value;
    const char* first = s.data() + (!s.empty() && s.front() == '+' ? 1 : 0);
    const auto [end, ec] = std::from_chars(first, s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v))
      fail(origin.describe() + ": line " + std::to_string(g.line + 1) + ": " + quoted(s) +
           " is not a number (group code " + std::to_string(g.code) + ")");
    return v;
  }

  // The value of `code` in the entity, or `fallback` when it has none.
  double value(const Entity& e, int code, const Origin& origin, double fallback) const {
    for (const Group& g : e.groups)
      if (g.code == code) return number(g, origin);
    return fallback;
  }
  // The entity's flags (group code 70, bits of a 16-bit integer; 0 when absent).
  int flags(const Entity& e, const Origin& origin) const {
    const double v = value(e, 70, origin, 0.0);
    if (!(v >= 0.0 && v <= 65535.0 && v == std::floor(v)))
      fail(origin.describe() + ": flags (group code 70) " + detail::format_number(v) +
           " are not a 16-bit integer");
    return static_cast<int>(v);
  }
  double required(const Entity& e, int code, const Origin& origin) const {
    for (const Group& g : e.groups)
      if (g.code == code) return number(g, origin);
    fail(origin.describe() + ": no group code " + std::to_string(code));
  }

  // Whether the entity's coordinates are mirrored (extrusion direction (0, 0, -1), how CAD
  // programs store a mirrored arc); anything but +-z is out of the drawing's plane.
  bool mirrored(const Entity& e, const Origin& origin) const {
    const double x = value(e, 210, origin, 0.0), y = value(e, 220, origin, 0.0),
                 z = value(e, 230, origin, 1.0);
    if (std::fabs(x) > 1e-12 || std::fabs(y) > 1e-12 || z == 0.0)
      fail(origin.describe() + ": drawn out of the XY plane (extrusion direction " +
           detail::format_number(x) + ", " + detail::format_number(y) + ", " +
           detail::format_number(z) + ")");
    return z < 0.0;
  }

  // An entity's point in the drawing: from its object coordinates (with the extrusion along -z
  // the x axis is reversed, DXF's arbitrary axis rule), through the INSERTs placing it.
  Vec2 drawing_point(Vec2 p, bool mirror) const {
    if (mirror) p.x = -p.x;
    return placed(p);
  }

  // An edge in the drawing's coordinates, into `out`; a mirror, of the entity or of an
  // INSERT, turns its arc the other way. Under a block scaled unevenly an arc is part of an
  // ellipse, followed by arcs. Ends must be numbers: an arc's start angle of 1e308 degrees has
  // no cosine.
  void add_edge(Piece p, bool mirror, std::vector<Piece>& out) const {
    const Vec2 from = drawing_point(p.from, mirror), to = drawing_point(p.to, mirror);
    if (!(is_finite(from) && is_finite(to) && std::isfinite(p.bulge)))
      fail(p.origin.describe() + ": its ends are beyond the range of numbers");
    if (p.bulge == 0.0 || inserts_keep_circles()) {
      p.bulge = mirror != inserts_mirror() ? -p.bulge : p.bulge;
      p.from = from;
      p.to = to;
      out.push_back(p);
      return;
    }
    const Curve arc = make_bulge_arc(p.from, p.to, p.bulge);
    const size_t first = out.size();
    add_curve_pieces([&](double t) { return point_at(arc, t); }, {0.0, 0.25, 0.5, 0.75, 1.0},
                     bounding_box(arc), mirror, p.origin, out);
    if (out.size() > first) {  // the ends exactly where the neighbouring edges meet them
      out[first].from = from;
      out.back().to = to;
    }
  }

  // Where an entity is, for messages: in a block, with the INSERT placing it.
  Origin origin_of(std::string_view type, int line) const {
    return {std::string(type), line, inserts_.empty() ? "" : inserts_.back().context};
  }

  // ---- Blocks placed by INSERT ---------------------------------------------------------
  // An INSERT draws its block's entities moved from the block's base point, scaled, turned
  // and moved to the insertion point (and mirrored when its extrusion is along -z). Blocks
  // may insert blocks, up to kMaxBlockDepth deep.
  struct Insert {
    std::string layer;    // the INSERT's layer, which the block's layer-0 entities take
    std::string context;  // " in block 'B' (the INSERT at line N)", for messages
    Vec2 base, at;
    double sx = 1.0, sy = 1.0, c = 1.0, s = 0.0;
    bool ocs_mirror = false;
  };
  static constexpr size_t kMaxBlockDepth = 8;
  // Entities drawn through blocks, at most: a block inserting another ten times, eight deep,
  // would otherwise draw 10^8.
  static constexpr long long kMaxBlockEntities = 1000000;

  void insert(const Entity& e) {
    part_.clear();  // an INSERT belongs to no part; its errors name none
    const Origin o = origin_of("INSERT", e.line);
    std::string name;
    for (const Group& g : e.groups)
      if (g.code == 2) name = upper(g.value);
    const auto it = blocks_.find(name);
    if (it == blocks_.end()) return;  // an undefined block draws nothing readable
    if (inserts_.size() >= kMaxBlockDepth)
      fail(o.describe() + ": blocks nested deeper than " + std::to_string(kMaxBlockDepth) +
           " (does a block insert itself?)");
    Insert in;
    in.layer = layer_name(e);
    in.context = " in block '" + name + "' (" + o.describe() + ")";
    in.base = it->second.base;
    in.at = {value(e, 10, o, 0.0), value(e, 20, o, 0.0)};
    in.sx = value(e, 41, o, 1.0);
    in.sy = value(e, 42, o, 1.0);
    if (in.sx == 0.0 || in.sy == 0.0)
      fail(o.describe() + ": a scale of 0 flattens its block to nothing");
    const double turn = value(e, 50, o, 0.0) * kPi / 180.0;
    in.c = std::cos(turn);
    in.s = std::sin(turn);
    in.ocs_mirror = mirrored(e, o);
    // MINSERT: columns (code 70) and rows (71) of copies, spaced (44, 45) along the turned axes.
    const double columns = value(e, 70, o, 1.0), rows = value(e, 71, o, 1.0);
    for (double count : {columns, rows})
      if (!(count >= 1.0 && count <= 32767.0 && count == std::floor(count)))
        fail(o.describe() + ": " + detail::format_number(count) +
             " columns or rows (group codes 70, 71) are not a count from 1 to 32767");
    const Vec2 step{value(e, 44, o, 0.0), value(e, 45, o, 0.0)}, at = in.at;
    for (int row = 0; row < static_cast<int>(rows); ++row)
      for (int column = 0; column < static_cast<int>(columns); ++column) {
        const Vec2 d{column * step.x, row * step.y};
        in.at = at + Vec2{in.c * d.x - in.s * d.y, in.s * d.x + in.c * d.y};
        if (columns * rows > 1.0)
          in.context = " in block '" + name + "' (" + o.describe() + ", row " +
                       std::to_string(row + 1) + ", column " + std::to_string(column + 1) + ")";
        inserts_.push_back(in);
        for (const EntityWithVertices& b : it->second.entities) {
          if (++block_entities_ > kMaxBlockEntities)
            fail(o.describe() + ": its blocks draw more than " + std::to_string(kMaxBlockEntities) +
                 " entities");
          entity(b.entity, &b.vertices);
        }
        inserts_.pop_back();
      }
  }

  // A block's point in the drawing, through every INSERT placing it (the innermost first).
  Vec2 placed(Vec2 p) const {
    for (auto in = inserts_.rbegin(); in != inserts_.rend(); ++in) {
      const Vec2 q{(p.x - in->base.x) * in->sx, (p.y - in->base.y) * in->sy};
      p = {in->c * q.x - in->s * q.y + in->at.x, in->s * q.x + in->c * q.y + in->at.y};
      if (in->ocs_mirror) p.x = -p.x;
    }
    return p;
  }
  bool inserts_mirror() const {
    bool mirror = false;
    for (const Insert& in : inserts_) mirror ^= (in.sx * in.sy < 0.0) != in.ocs_mirror;
    return mirror;
  }
  double inserts_scale() const {
    double scale = 1.0;
    for (const Insert& in : inserts_) scale *= std::fabs(in.sx);
    return scale;
  }
  // Whether every INSERT placing the entity scales evenly (turns and mirrors keep circles).
  bool inserts_keep_circles() const {
    for (const Insert& in : inserts_)
      if (std::fabs(std::fabs(in.sx) - std::fabs(in.sy)) > 1e-12 * std::fabs(in.sx)) return false;
    return true;
  }

  void line(const Entity& e, const Origin& o, Layer& layer) {
    Piece p{
        {required(e, 10, o), required(e, 20, o)}, {required(e, 11, o), required(e, 21, o)}, 0.0, o};
    add_edge(p, mirrored(e, o), layer.pieces);
  }

  void arc(const Entity& e, const Origin& o, Layer& layer) {
    const Vec2 c{required(e, 10, o), required(e, 20, o)};
    const double r = required(e, 40, o);
    const double start = required(e, 50, o), end = required(e, 51, o);
    if (!(r > 0.0))
      fail(o.describe() + ": radius " + detail::format_number(r) + " is not positive");
    double sweep = std::fmod(end - start, 360.0);
    if (sweep <= 0.0) sweep += 360.0;
    if (!(sweep > 0.0 && sweep < 360.0))
      fail(o.describe() + ": its start and end angles are one angle; draw a CIRCLE for a full one");
    const double a0 = start * kPi / 180.0, a1 = end * kPi / 180.0;
    Piece p{c + Vec2{r * std::cos(a0), r * std::sin(a0)},
            c + Vec2{r * std::cos(a1), r * std::sin(a1)}, std::tan(sweep * kPi / 180.0 / 4.0), o};
    add_edge(p, mirrored(e, o), layer.pieces);
  }

  void circle(const Entity& e, const Origin& o, Layer& layer) {
    DrawnLoop loop;
    loop.circle = true;
    const Vec2 center{required(e, 10, o), required(e, 20, o)};
    const double radius = required(e, 40, o);
    if (!(radius > 0.0))
      fail(o.describe() + ": radius " + detail::format_number(radius) + " is not positive");
    const bool mirror = mirrored(e, o);
    if (!inserts_keep_circles()) {  // an ellipse: its two halves, followed by arcs
      loop.circle = false;
      loop.origin = o.describe();
      for (double side : {1.0, -1.0})
        add_edge({center + Vec2{side * radius, 0.0}, center - Vec2{side * radius, 0.0}, 1.0, o},
                 mirror, loop.edges);
      layer.loops.push_back(loop);
      return;
    }
    loop.center = drawing_point(center, mirror);
    loop.radius = radius * inserts_scale();
    if (!(is_finite(loop.center) && std::isfinite(loop.radius)))
      fail(o.describe() + ": its centre or radius is beyond the range of numbers");
    loop.origin = o.describe();
    layer.loops.push_back(loop);
  }

  // ---- Curves other than lines and arcs -----------------------------------------------

  // The arcs along curve(u) (in the entity's coordinates, within `box`), u through `breaks`,
  // into `out`. They follow the curve as drawn, through the INSERTs placing it, so that the
  // tolerance is the drawing's and an uneven scale draws what it should.
  void add_curve_pieces(const std::function<Vec2(double)>& curve, const std::vector<double>& breaks,
                        const Box& box, bool mirror, const Origin& o,
                        std::vector<Piece>& out) const {
    Box drawn;
    for (Vec2 corner : {box.lo, box.hi, Vec2{box.lo.x, box.hi.y}, Vec2{box.hi.x, box.lo.y}})
      drawn.add(drawing_point(corner, mirror));
    if (const std::string problem =
            drawing::follow_curve([&](double u) { return drawing_point(curve(u), mirror); }, breaks,
                                  drawn, options_.tolerance, o, out);
        !problem.empty())
      fail(o.describe() + ": " + problem);
  }

  void spline(const Entity& e, const Origin& o, Layer& layer) {
    drawing::Nurbs n;
    const double degree = value(e, 71, o, 3.0);
    if (!(degree >= 1.0 && degree <= 10.0 && degree == std::floor(degree)))
      fail(o.describe() + ": degree " + detail::format_number(degree) + " is not 1 to 10");
    n.degree = static_cast<int>(degree);
    for (const Group& g : e.groups) {
      if (g.code == 40) n.knots.push_back(number(g, o));
      if (g.code == 41) n.weights.push_back(number(g, o));
      if (g.code == 10) n.points.push_back({number(g, o), 0.0});
      if (g.code == 20 && !n.points.empty()) n.points.back().y = number(g, o);
    }
    if (const std::string problem = drawing::check_nurbs(n); !problem.empty())
      fail(o.describe() + ": " + problem);
    std::vector<double> breaks;  // the distinct knots of its domain
    for (size_t k = static_cast<size_t>(n.degree); k <= n.points.size(); ++k)
      if (breaks.empty() || n.knots[k] > breaks.back()) breaks.push_back(n.knots[k]);
    Box box;
    for (Vec2 p : n.points) box.add(p);
    add_curve_pieces([&](double u) { return drawing::nurbs_point(n, u); }, breaks, box,
                     mirrored(e, o), o, layer.pieces);
  }

  void ellipse(const Entity& e, const Origin& o, Layer& layer) {
    const Vec2 c{required(e, 10, o), required(e, 20, o)};
    const Vec2 major{required(e, 11, o), required(e, 21, o)};
    const double ratio = required(e, 40, o);
    if (!(length(major) > 0.0) || !(ratio > 0.0 && ratio <= 1.0))
      fail(o.describe() + ": its major axis must have a length and its ratio lie in (0, 1]");
    const double t0 = value(e, 41, o, 0.0), t1 = value(e, 42, o, kTwoPi);
    double sweep = std::fmod(t1 - t0, kTwoPi);
    if (!(sweep > 0.0)) sweep += kTwoPi;
    const Vec2 minor{-major.y * ratio, major.x * ratio};
    std::vector<double> breaks;
    for (int k = 0; k <= 4; ++k) breaks.push_back(t0 + sweep * k / 4.0);
    const double r = length(major);
    Box box;
    box.add(c - Vec2{r, r});
    box.add(c + Vec2{r, r});
    add_curve_pieces([&](double t) { return c + major * std::cos(t) + minor * std::sin(t); },
                     breaks, box, mirrored(e, o), o, layer.pieces);
  }

  struct Vertex {
    Vec2 p;
    double bulge = 0.0;
  };

  void lwpolyline(const Entity& e, const Origin& o, Layer& layer) {
    std::vector<Vertex> vertices;
    for (const Group& g : e.groups) {
      if (g.code == 10) vertices.push_back({{number(g, o), 0.0}, 0.0});
      if (vertices.empty()) continue;
      if (g.code == 20) vertices.back().p.y = number(g, o);
      if (g.code == 42) vertices.back().bulge = number(g, o);
    }
    add_polyline(vertices, (flags(e, o) & 1) != 0, mirrored(e, o), o, layer);
  }

  void polyline(const Entity& e, const std::vector<Entity>& vertex_entities, const Origin& o,
                Layer& layer) {
    const int polyline_flags = flags(e, o);
    if (polyline_flags & (8 | 16 | 64))
      fail(o.describe() + ": a 3D polyline or mesh, not a planar outline");
    std::vector<Vertex> vertices;
    for (const Entity& v : vertex_entities) {
      const Origin vo = origin_of("VERTEX", v.line);
      if (flags(v, vo) & 16) continue;  // a spline's control point
      vertices.push_back({{required(v, 10, vo), required(v, 20, vo)}, value(v, 42, vo, 0.0)});
    }
    add_polyline(vertices, (polyline_flags & 1) != 0, mirrored(e, o), o, layer);
  }

  // A closed polyline is a loop. An open one gives pieces to join with the layer's lines and
  // arcs (one whose last vertex repeats its first joins itself).
  void add_polyline(const std::vector<Vertex>& v, bool closed, bool mirror, const Origin& o,
                    Layer& layer) {
    if (v.size() < 2) fail(o.describe() + ": fewer than two vertices");
    std::vector<Piece> edges;
    const size_t n = closed ? v.size() : v.size() - 1;
    for (size_t i = 0; i < n; ++i)
      add_edge({v[i].p, v[(i + 1) % v.size()].p, v[i].bulge, o}, mirror, edges);
    if (!closed) {
      layer.pieces.insert(layer.pieces.end(), edges.begin(), edges.end());
      return;
    }
    DrawnLoop loop;
    loop.edges = std::move(edges);
    loop.origin = o.describe();
    layer.loops.push_back(std::move(loop));
  }

 private:
  const DrawingImportOptions& options_;
  std::string part_;
  std::map<std::string, Block> blocks_;  // by upper-case name
  std::vector<Insert> inserts_;          // the INSERTs placing the entities being read
  long long block_entities_ = 0;
};

std::string layer_list(const std::set<std::string>& layers) {
  if (layers.empty()) return "the drawing has no entities";
  std::string out = "layers with entities:";
  for (const std::string& name : layers) out += " '" + name + "'";
  return out;
}

// The two layers' outlines, each checked to be there.
drawing::DrawnParts read_parts(std::string_view text, const DrawingImportOptions& options) {
  if (drawing::same_name(options.moving_layer, options.fixed_layer))
    throw DrawingError{"", "the moving and the fixed part are both on layer '" +
                               options.moving_layer + "': name one layer for each"};
  Reader reader(options);
  std::deque<std::string> binary_values;  // a binary file's values, as text
  reader.read(read_groups(text, binary_values));
  for (const auto& [layer, part, name] :
       {std::tuple{&reader.moving, "moving", options.moving_layer},
        std::tuple{&reader.fixed, "fixed", options.fixed_layer}})
    if (layer->empty())
      throw DrawingError{
          part, "no outline (line, arc, circle, polyline, spline or ellipse) on layer '" + name +
                    "' (" + layer_list(reader.layers_seen) + ")"};
  drawing::DrawnParts parts;
  parts.moving = std::move(reader.moving);
  parts.fixed = std::move(reader.fixed);
  parts.units = reader.units;
  return parts;
}

}  // namespace

DrawingPairResult import_dxf_pair(std::string_view dxf_text, std::string_view source,
                                  const DrawingImportOptions& options) {
  return drawing::import_parts(source, options, "layer",
                               [&] { return read_parts(dxf_text, options); });
}

DrawingPairResult load_dxf_pair(const std::string& path, const DrawingImportOptions& options) {
  return drawing::import_file(
      path, [&](std::string_view text) { return import_dxf_pair(text, path, options); });
}

}  // namespace cslice
