// The loops read from a drawing (DXF or SVG) as a pair file, read back as `cslice info` reads
// pair files, so that an imported pair is checked exactly as a written one. Errors of a loop
// then name the drawing's entities it was made of.
#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>

#include "cslice/tolerance.hpp"
#include "parts/drawing_internal.hpp"
#include "parts/validate.hpp"

namespace cslice::drawing {

namespace {

Box layer_box(const Layer& layer) {
  Box box;
  for (const Piece& p : layer.pieces) {
    box.add(p.from);
    box.add(p.to);
  }
  for (const DrawnLoop& loop : layer.loops) {
    for (const Piece& p : loop.edges) box.add(p.from);
    if (loop.circle) {
      box.add(loop.center - Vec2{loop.radius, loop.radius});
      box.add(loop.center + Vec2{loop.radius, loop.radius});
    }
  }
  return box;
}

// A drawing point in the pair's coordinates, relative to `origin`.
struct ToPair {
  Vec2 origin;
  bool y_down = false;
  Vec2 operator()(Vec2 p) const {
    const Vec2 d = p - origin;
    return y_down ? Vec2{d.x, 0.0 - d.y} : d;  // 0 - y: no -0 in the file
  }
};

// One loop a line: [[x, y], [x, y, bulge], ...] or {"circle": [cx, cy, r]}, numbers as
// nlohmann writes them (they read back as the same doubles). Negating y turns an arc the
// other way, so its bulge changes sign.
std::string loops_text(const std::vector<DrawnLoop>& loops, const ToPair& to_pair) {
  const auto num = [](double v) { return nlohmann::json(v).dump(); };
  std::string out = "[";
  for (size_t k = 0; k < loops.size(); ++k) {
    const DrawnLoop& loop = loops[k];
    out += k == 0 ? "\n      " : ",\n      ";
    if (loop.circle) {
      const Vec2 c = to_pair(loop.center);
      out += "{\"circle\": [" + num(c.x) + ", " + num(c.y) + ", " + num(loop.radius) + "]}";
      continue;
    }
    out += "[";
    for (size_t i = 0; i < loop.edges.size(); ++i) {
      const Piece& p = loop.edges[i];
      const Vec2 v = to_pair(p.from);
      out += (i == 0 ? "[" : ", [") + num(v.x) + ", " + num(v.y);
      if (p.bulge != 0.0) out += ", " + num(to_pair.y_down ? -p.bulge : p.bulge);
      out += "]";
    }
    out += "]";
  }
  return out + "\n    ]";
}

std::string pair_name(std::string_view source, const DrawingImportOptions& options) {
  if (!options.name.empty()) return options.name;
  std::string name(source.substr(source.find_last_of('/') + 1));
  if (const size_t dot = name.rfind('.'); dot != std::string::npos && dot > 0) name.resize(dot);
  return name;
}

// The pair reader numbers loops as the pair file lists them: say which entities those are,
// and which entity drew the edge a vertex starts.
void name_the_entities(InputError& error, const std::vector<DrawnLoop>& loops) {
  const int loop = error.loop, vertex = error.vertex;
  if (loop < 0 || loop >= static_cast<int>(loops.size())) return;
  error.reason += " (loop " + std::to_string(loop) + " is " + loops[loop].origin;
  if (vertex >= 0 && vertex < static_cast<int>(loops[loop].edges.size()))
    error.reason += "; vertex " + std::to_string(vertex) + " starts the edge drawn by " +
                    loops[loop].edges[vertex].origin.describe();
  error.reason += ")";
}

DrawingPairResult failed(std::string_view source, const DrawingError& e) {
  DrawingPairResult result;
  InputError& error = result.error.emplace();
  error.file = std::string(source);
  error.part = e.part;
  error.reason = e.reason;
  return result;
}

DrawingPairResult pair_from_drawing(const DrawnParts& parts, std::string_view source,
                                    const DrawingImportOptions& options, std::string_view what) {
  Box box = layer_box(parts.moving);
  const Box moving_box = box;
  const Box fixed_box = layer_box(parts.fixed);
  box.add(fixed_box.lo);
  box.add(fixed_box.hi);
  const double join = options.join_tolerance.value_or(kDxfJoinRelative * box.diagonal());
  std::vector<DrawnLoop> moving, fixed;
  for (const auto& [layer, loops, part, name] :
       {std::tuple{&parts.moving, &moving, "moving", &options.moving_layer},
        std::tuple{&parts.fixed, &fixed, "fixed", &options.fixed_layer}}) {
    if (std::string problem = build_loops(*layer, join, *loops); !problem.empty())
      return failed(source, {part, std::string(what) + " '" + *name + "': " + problem});
    size_t edges = 0;
    for (const DrawnLoop& loop : *loops) edges += loop.circle ? 1 : loop.edges.size();
    if (edges > kMaxPartEdges)
      return failed(source,
                    {part, std::string(what) + " '" + *name + "': " + std::to_string(edges) +
                               " outline edges, more than the " + std::to_string(kMaxPartEdges) +
                               " a drawing may give a part (a block arrayed too often?)"});
  }
  const ToPair moving_to_pair{options.moving_origin, parts.y_down};
  const ToPair fixed_to_pair{options.fixed_origin, parts.y_down};
  std::string json = "{\n  \"name\": " + nlohmann::json(pair_name(source, options)).dump() + ",\n";
  if (!parts.units.empty()) json += "  \"units\": " + nlohmann::json(parts.units).dump() + ",\n";
  if (options.tolerance)
    json += "  \"tolerance\": " + nlohmann::json(*options.tolerance).dump() + ",\n";
  json += "  \"moving\": {\n    \"loops\": " + loops_text(moving, moving_to_pair) + "\n  },\n";
  json += "  \"fixed\": {\n    \"enclosure\": " +
          std::string(options.fixed_enclosure ? "true" : "false") +
          ",\n    \"loops\": " + loops_text(fixed, fixed_to_pair) + "\n  }\n}\n";
  DrawingPairResult result;
  result.drawn_at = fixed_to_pair(options.moving_origin);
  result.moving_box_drawn = moving_box;
  LoadResult loaded = parse_pair(json, source);
  result.pair_json = std::move(json);
  if (loaded.ok()) {
    result.pair = std::move(loaded.pair);
    return result;
  }
  result.error = loaded.error;
  name_the_entities(*result.error, result.error->part == "moving" ? moving : fixed);
  return result;
}

}  // namespace

bool same_name(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) ==
           std::tolower(static_cast<unsigned char>(y));
  });
}

DrawingPairResult import_parts(std::string_view source, const DrawingImportOptions& options,
                               std::string_view what, const std::function<DrawnParts()>& read) {
  DrawnParts parts;
  try {
    parts = read();
  } catch (const DrawingError& e) {
    return failed(source, e);
  }
  return pair_from_drawing(parts, source, options, what);
}

DrawingPairResult import_file(const std::string& path,
                              const std::function<DrawingPairResult(std::string_view)>& import) {
  std::string text;
  if (std::optional<InputError> error = detail::read_input_file(path, text)) {
    DrawingPairResult result;
    result.error = std::move(error);
    return result;
  }
  return import(text);
}

}  // namespace cslice::drawing

namespace cslice {

DrawingPairResult load_drawing_pair(const std::string& path, const DrawingImportOptions& options) {
  return drawing::import_file(path, [&](std::string_view text) {
    std::string extension = path.substr(std::min(path.size(), path.rfind('.') + 1));
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    bool svg = extension == "svg";
    if (extension != "svg" && extension != "dxf") {  // by the first character
      const size_t first = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
      svg = first != std::string_view::npos && text[first] == '<';
    }
    return svg ? import_svg_pair(text, path, options) : import_dxf_pair(text, path, options);
  });
}

}  // namespace cslice
