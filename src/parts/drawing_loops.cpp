// Closed loops from the outline pieces of a DXF layer. A drawing's outline is often loose
// lines and arcs, each drawn on its own, in any order and direction; they form a loop where
// their ends meet. Ends are matched by distance (within the join tolerance), and each must meet
// exactly one other: an end meeting none leaves the outline open, and three or more ends at
// one point leave open which continues which. Both are errors, never guessed.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "parts/drawing_internal.hpp"
#include "parts/validate.hpp"

namespace cslice::drawing {

std::string Origin::describe() const {
  return "the " + entity + " at line " + std::to_string(line) + block;
}

namespace {

struct CellHash {
  size_t operator()(const std::pair<int64_t, int64_t>& c) const {
    return std::hash<int64_t>()(c.first * 0x9E3779B97F4A7C15ll ^ c.second);
  }
};

// Cell of a point in a grid of cells `join` wide: ends within `join` of each other lie in the
// same or neighbouring cells. Clamped, so that far coordinates and tiny join tolerances still
// give an integer.
int64_t cell(double v, double join) {
  const double c = std::floor(v / join);
  return std::isfinite(c) ? static_cast<int64_t>(std::clamp(c, -4e18, 4e18)) : 0;
}

// Every end's partner (its index: 2 * piece + 0 at its start, 1 at its end), or an error. A
// grid of cells `join` wide keeps the search near each end, however the ends line up.
std::string match_ends(const std::vector<Piece>& pieces, double join, std::vector<int>& partner) {
  const auto point = [&](int e) { return e % 2 ? pieces[e / 2].to : pieces[e / 2].from; };
  const int count = 2 * static_cast<int>(pieces.size());
  std::unordered_map<std::pair<int64_t, int64_t>, std::vector<int>, CellHash> grid;
  for (int e = 0; e < count; ++e)
    grid[{cell(point(e).x, join), cell(point(e).y, join)}].push_back(e);
  std::vector<std::vector<int>> near(count);
  for (int e = 0; e < count; ++e) {
    const Vec2 p = point(e);
    const int64_t cx = cell(p.x, join), cy = cell(p.y, join);
    for (int64_t dx = -1; dx <= 1 && near[e].size() < 3; ++dx)
      for (int64_t dy = -1; dy <= 1 && near[e].size() < 3; ++dy) {
        const auto it = grid.find({cx + dx, cy + dy});
        if (it == grid.end()) continue;
        for (int o : it->second) {
          if (near[e].size() == 3) break;  // three tell all: too many
          if (o != e && distance(point(o), p) <= join) near[e].push_back(o);
        }
      }
  }
  partner.assign(count, -1);
  const auto where = [&](int e) {
    const Piece& piece = pieces[e / 2];
    return piece.origin.describe() + " at " + detail::format_point(e % 2 ? piece.to : piece.from);
  };
  for (int e = 0; e < count; ++e) {
    const std::vector<int>& others = near[e];
    if (others.size() == 1 && others[0] / 2 == e / 2)
      return where(e) + " is shorter than the join tolerance " + detail::format_number(join) +
             ": its two ends are one point";
    if (others.empty())
      return "the outline is open: the " + std::string(e % 2 ? "end" : "start") + " of " +
             where(e) + " meets no other end within the join tolerance " +
             detail::format_number(join);
    if (others.size() > 1) {
      std::string names = pieces[e / 2].origin.describe();
      for (int o : others) names += ", " + pieces[o / 2].origin.describe();
      return std::string(others.size() > 2 ? "four or more" : "three") + " outline ends meet at " +
             detail::format_point(e % 2 ? pieces[e / 2].to : pieces[e / 2].from) + " (" + names +
             "): each end must meet exactly one other";
    }
    partner[e] = others[0];
  }
  return "";
}

Piece oriented(const Piece& p, bool reversed) {
  if (!reversed) return p;
  Piece r = p;
  std::swap(r.from, r.to);
  r.bulge = -p.bulge;
  return r;
}

// "the LINE at line 57" or "the LINE at line 57 and 3 more entities".
// An open polyline gives several pieces, each naming it: counted once.
std::string describe_all(const std::vector<Origin>& origins) {
  std::vector<int> lines;
  for (const Origin& o : origins) lines.push_back(o.line);
  std::sort(lines.begin(), lines.end());
  const size_t others = std::unique(lines.begin(), lines.end()) - lines.begin() - 1;
  std::string out = origins.front().describe();
  if (others > 0)
    out += " and " + std::to_string(others) + " more " + (others == 1 ? "entity" : "entities");
  return out;
}

// A loop drawn closed whose last vertex repeats its first has an edge of no length back to
// it (SVG paths often close so): dropped, the next edge starting where the dropped one did.
DrawnLoop without_short_edges(const DrawnLoop& loop, double join) {
  DrawnLoop out = loop;
  out.edges.clear();
  for (const Piece& edge : loop.edges) {
    if (distance(edge.from, edge.to) > join || loop.edges.size() <= 2)
      out.edges.push_back(edge);
    else if (!out.edges.empty())
      out.edges.back().to = edge.to;
  }
  if (out.edges.size() >= 2) out.edges.front().from = out.edges.back().to;
  return out;
}

// Consecutive arcs of one circle, turning the same way, as one arc: drawing programs split
// circular outlines where nothing happens (a rounded rectangle's corners at the quarter
// points, an arc of more than half a turn in halves), and each such vertex would be a feature
// of the part, making contacts and critical orientations that change nothing. Arcs of one
// circle all round make the circle.
void merge_arcs_of_one_circle(DrawnLoop& loop, double join) {
  const auto same_circle = [join](const Curve& a, const Curve& b) {
    return a.is_arc() && b.is_arc() && (a.sweep > 0.0) == (b.sweep > 0.0) &&
           distance(a.center, b.center) <= join && std::fabs(a.radius - b.radius) <= join &&
           std::fabs(a.sweep + b.sweep) < kTwoPi - 1e-9;
  };
  bool merged = true;
  while (merged && loop.edges.size() > 2) {
    merged = false;
    for (size_t i = 0; i < loop.edges.size() && loop.edges.size() > 2; ++i) {
      const size_t j = (i + 1) % loop.edges.size();
      const Piece& a = loop.edges[i];
      const Piece& b = loop.edges[j];
      const Curve ca = make_bulge_arc(a.from, a.to, a.bulge);
      const Curve cb = make_bulge_arc(b.from, b.to, b.bulge);
      if (!same_circle(ca, cb)) continue;
      Piece joined = a;
      joined.to = b.to;
      joined.bulge = std::tan((ca.sweep + cb.sweep) / 4.0);
      if (j == 0) {  // the last edge and the first: the loop now starts where the last did
        loop.edges.front() = joined;
        loop.edges.pop_back();
      } else {
        loop.edges[i] = joined;
        loop.edges.erase(loop.edges.begin() + static_cast<std::ptrdiff_t>(j));
      }
      merged = true;
    }
  }
  if (loop.edges.size() != 2) return;  // arcs of one circle all round: the circle
  const Curve a = make_bulge_arc(loop.edges[0].from, loop.edges[0].to, loop.edges[0].bulge);
  const Curve b = make_bulge_arc(loop.edges[1].from, loop.edges[1].to, loop.edges[1].bulge);
  if (!(a.is_arc() && b.is_arc() && (a.sweep > 0.0) == (b.sweep > 0.0) &&
        distance(a.center, b.center) <= join && std::fabs(a.radius - b.radius) <= join))
    return;
  loop.circle = true;
  loop.center = 0.5 * (a.center + b.center);
  loop.radius = 0.5 * (a.radius + b.radius);
  loop.edges.clear();
}

}  // namespace

std::string build_loops(const Layer& layer, double join, std::vector<DrawnLoop>& out) {
  const size_t first = out.size();
  for (const DrawnLoop& loop : layer.loops) out.push_back(without_short_edges(loop, join));
  std::vector<int> partner;
  if (std::string problem = match_ends(layer.pieces, join, partner); !problem.empty())
    return problem;
  std::vector<char> used(layer.pieces.size(), 0);
  for (size_t first = 0; first < layer.pieces.size(); ++first) {
    if (used[first]) continue;
    DrawnLoop& loop = out.emplace_back();
    std::vector<Origin> origins;
    int piece = static_cast<int>(first);
    bool reversed = false;
    while (!used[piece]) {
      used[piece] = 1;
      loop.edges.push_back(oriented(layer.pieces[piece], reversed));
      origins.push_back(layer.pieces[piece].origin);
      const int next = partner[2 * piece + (reversed ? 0 : 1)];  // the end we leave by
      piece = next / 2;
      reversed = next % 2 == 1;  // entered at its end: travelled backwards
    }
    loop.origin = describe_all(origins);
  }
  for (size_t k = first; k < out.size(); ++k)
    if (!out[k].circle) merge_arcs_of_one_circle(out[k], join);
  return "";
}

}  // namespace cslice::drawing
