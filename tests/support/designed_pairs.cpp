#include "support/designed_pairs.hpp"

#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include "support/random_polygons.hpp"

namespace cslice::testkit {
namespace {

using Cell = std::pair<int, int>;

// Uniform in [lo, hi], from the generator's own output (specified by the standard, unlike
// the distributions), so that a seed names the same pair everywhere.
int pick(std::mt19937& rng, int lo, int hi) {
  return lo + int(rng() % unsigned(hi - lo + 1));
}

// A loop of the pair format: vertices, or a full circle.
struct Loop {
  LoopVertices vertices;
  bool circle = false;
  Vec2 center;
  double radius = 0.0;
};

Loop circle(Vec2 center, double radius) {
  return {{}, true, center, radius};
}
Loop polygon(LoopVertices vertices) {
  return {std::move(vertices), false, {}, 0.0};
}

std::string loop_text(const Loop& l) {
  if (!l.circle) return loop_json(l.vertices);
  const LoopVertices c{{l.center.x, l.center.y, l.radius}};  // loop_json's number format
  const std::string xyz = loop_json(c);                      // "[[x,y,r]]"
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on chains of operator+.
  std::string s = R"({"circle":)";
  s.append(xyz, 1, xyz.size() - 2);
  s += "}";
  return s;
}

std::string loops_text(const std::vector<Loop>& loops) {
  std::string s = "[";
  for (size_t i = 0; i < loops.size(); ++i) {
    if (i) s += ",";
    s += loop_text(loops[i]);
  }
  s += "]";
  return s;
}

Loop turned(const Loop& l, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  auto turn = [&](double x, double y) { return Vec2{c * x - s * y, s * x + c * y}; };
  Loop out = l;
  out.center = turn(l.center.x, l.center.y);
  for (LoopVertex& v : out.vertices) {
    const Vec2 p = turn(v.x, v.y);
    v.x = p.x;
    v.y = p.y;
  }
  return out;
}

// Grows `cells` by random 4-neighbours of its cells up to `count` cells.
std::set<Cell> grow(std::mt19937& rng, std::set<Cell> cells, int count) {
  static constexpr int kDx[4] = {1, 0, -1, 0}, kDy[4] = {0, 1, 0, -1};
  while (int(cells.size()) < count) {
    const Cell c = *std::next(cells.begin(), pick(rng, 0, int(cells.size()) - 1));
    const int d = pick(rng, 0, 3);
    cells.insert({c.first + kDx[d], c.second + kDy[d]});
  }
  return cells;
}

// The counterclockwise boundary of unit cells (cell (i, j) spans [i, i + 1] x [j, j + 1]) as
// one loop of corners, scaled by `unit` and shifted by -origin, collinear corners left out.
// Empty when it is not one simple loop: cells touching only at a corner, or around a hole.
LoopVertices cell_boundary(const std::set<Cell>& cells, double unit, Vec2 origin) {
  std::map<Cell, Cell> next;  // each boundary edge, from its start corner to its end
  auto edge = [&](Cell a, Cell b) { return next.emplace(a, b).second; };
  for (auto [i, j] : cells) {
    if ((!cells.count({i, j - 1}) && !edge({i, j}, {i + 1, j})) ||
        (!cells.count({i + 1, j}) && !edge({i + 1, j}, {i + 1, j + 1})) ||
        (!cells.count({i, j + 1}) && !edge({i + 1, j + 1}, {i, j + 1})) ||
        (!cells.count({i - 1, j}) && !edge({i, j + 1}, {i, j})))
      return {};
  }
  std::vector<Cell> loop;
  Cell at = next.begin()->first;
  do {
    loop.push_back(at);
    at = next.at(at);
  } while (at != loop.front() && loop.size() <= next.size());
  if (loop.size() != next.size()) return {};
  LoopVertices corners;
  const size_t n = loop.size();
  for (size_t k = 0; k < n; ++k) {
    const Cell p = loop[(k + n - 1) % n], q = loop[k], r = loop[(k + 1) % n];
    const int turn =
        (q.first - p.first) * (r.second - q.second) - (q.second - p.second) * (r.first - q.first);
    if (turn != 0) corners.push_back({q.first * unit - origin.x, q.second * unit - origin.y, 0.0});
  }
  return corners;
}

// A cell of `cells`: its centre or its lower left corner, as the moving part's body origin.
Vec2 cell_origin(std::mt19937& rng, const std::set<Cell>& cells) {
  const Cell c = *std::next(cells.begin(), pick(rng, 0, int(cells.size()) - 1));
  const double shift = pick(rng, 0, 1) * 0.5;
  return {c.first + shift, c.second + shift};
}

LoopVertices regular_polygon(int n, double circumradius, double phase, Vec2 center) {
  LoopVertices v;
  for (int k = 0; k < n; ++k) {
    const double a = phase + kTwoPi * k / n;
    v.push_back({center.x + circumradius * std::cos(a), center.y + circumradius * std::sin(a)});
  }
  return v;
}

// An a x b rectangle about the origin with quarter-circle corners of radius r (sharp for 0).
LoopVertices rounded_rectangle(double a, double b, double r) {
  if (r == 0.0) return rectangle(a, b);
  const double x = 0.5 * a, y = 0.5 * b, q = std::tan(kPi / 8.0);
  return {{-x + r, -y}, {x - r, -y, q}, {x, -y + r}, {x, y - r, q},
          {x - r, y},   {-x + r, y, q}, {-x, y - r}, {-x, -y + r, q}};
}

// A stadium: a w-wide bar whose straight sides are `length` long, with half-circle ends.
LoopVertices stadium(double length, double w) {
  const double x = 0.5 * length, y = 0.5 * w;
  return {{-x, -y}, {x, -y, 1.0}, {x, y}, {-x, y, 1.0}};
}

struct Parts {
  std::vector<Loop> moving, fixed;
  bool enclosure = false;
};

// A polyomino in a polyomino opening that holds it with cells to spare.
bool cells_in_opening(std::mt19937& rng, Parts& p) {
  const std::set<Cell> m = grow(rng, {{0, 0}}, pick(rng, 2, 5));
  const std::set<Cell> f = grow(rng, m, int(m.size()) + pick(rng, 2, 6));
  p.moving = {polygon(cell_boundary(m, 1.0, cell_origin(rng, m)))};
  p.fixed = {polygon(cell_boundary(f, 1.0, {}))};
  p.enclosure = true;
  return !p.moving[0].vertices.empty() && !p.fixed[0].vertices.empty();
}

// A small polyomino sliding around a larger one: parallel edges and corners meeting.
bool cells_around_cells(std::mt19937& rng, Parts& p) {
  const std::set<Cell> m = grow(rng, {{0, 0}}, pick(rng, 1, 3));
  const std::set<Cell> f = grow(rng, {{0, 0}}, pick(rng, 3, 8));
  p.moving = {polygon(cell_boundary(m, 1.0, cell_origin(rng, m)))};
  p.fixed = {polygon(cell_boundary(f, 1.0, {}))};
  return !p.moving[0].vertices.empty() && !p.fixed[0].vertices.empty();
}

// A regular polygon in a disc through its corners, a copy of itself, a polygon of twice its
// sides whose sides its corners touch, or a looser one.
bool polygon_in_opening(std::mt19937& rng, Parts& p) {
  const int n = pick(rng, 3, 8);
  const double phase = pick(rng, 0, 1) * kPi / n;
  const Vec2 origin = pick(rng, 0, 2) == 0 ? Vec2{1.0, 0.0} : Vec2{};
  p.moving = {polygon(regular_polygon(n, 1.0, phase, {-origin.x, -origin.y}))};
  p.enclosure = true;
  switch (pick(rng, 0, 3)) {
    case 0:
      p.fixed = {circle({}, 1.0)};
      break;
    case 1:
      p.fixed = {polygon(regular_polygon(n, 1.0, 0.0, {}))};
      break;
    case 2:
      p.fixed = {polygon(regular_polygon(2 * n, 1.0 / std::cos(kPi / (2 * n)), 0.0, {}))};
      break;
    default:
      p.fixed = {polygon(regular_polygon(n, 1.5, 0.0, {}))};
      break;
  }
  return true;
}

// A disc or stadium 1 wide in a stadium of exactly its width, or in corridors of unit cells.
bool round_in_slot(std::mt19937& rng, Parts& p) {
  const int length = pick(rng, 0, 2);
  p.moving = {length == 0 ? circle({pick(rng, 0, 1) * -0.25, 0.0}, 0.5)
                          : polygon(stadium(length, 1.0))};
  p.enclosure = true;
  if (pick(rng, 0, 1) == 0) {
    p.fixed = {polygon(stadium(length + pick(rng, 0, 2), 1.0))};
    return true;
  }
  const std::set<Cell> f = grow(rng, {{0, 0}}, pick(rng, 3, 7));
  p.fixed = {polygon(cell_boundary(f, 1.0, {}))};
  return !p.fixed[0].vertices.empty();
}

// Rounded rectangles in rounded openings of their size or a unit larger, with equal,
// doubled or no corner radii.
bool rounded_in_rounded(std::mt19937& rng, Parts& p) {
  const double a = pick(rng, 1, 3), b = pick(rng, 1, 3), r = 0.25 * pick(rng, 0, 1);
  const double big_a = a + pick(rng, 0, 1), big_b = b + pick(rng, 0, 1);
  double big_r = r * pick(rng, 0, 2);
  if (2.0 * big_r >= std::min(big_a, big_b)) big_r = r;
  p.moving = {polygon(rounded_rectangle(a, b, r))};
  p.fixed = {polygon(rounded_rectangle(big_a, big_b, big_r))};
  p.enclosure = true;
  return 2.0 * r < std::min(a, b);
}

// Two combs with teeth and gaps of one unit, facing each other: teeth fit between teeth.
bool interlocking_combs(std::mt19937& rng, Parts& p) {
  const int teeth = pick(rng, 1, 3), h = pick(rng, 1, 2);
  std::set<Cell> m, f;
  for (int x = 0; x <= 2 * teeth - 2; ++x) m.insert({x, 0});
  for (int i = 0; i < teeth; ++i)
    for (int y = 1; y <= h; ++y) m.insert({2 * i, y});
  for (int x = -1; x <= 2 * teeth; ++x) f.insert({x, 4});
  for (int i = -1; i < teeth; ++i)
    for (int y = 4 - h; y < 4; ++y) f.insert({2 * i + 1, y});
  p.moving = {polygon(cell_boundary(m, 1.0, cell_origin(rng, m)))};
  p.fixed = {polygon(cell_boundary(f, 1.0, {}))};
  return !p.moving[0].vertices.empty() && !p.fixed[0].vertices.empty();
}

}  // namespace

RandomPair designed_pair(unsigned seed) {
  using Kind = bool (*)(std::mt19937&, Parts&);
  static constexpr Kind kKinds[6] = {cells_in_opening, cells_around_cells, polygon_in_opening,
                                     round_in_slot,    rounded_in_rounded, interlocking_combs};
  static constexpr const char* kNames[6] = {"cells-in-opening",   "cells-around-cells",
                                            "polygon-in-opening", "round-in-slot",
                                            "rounded-in-rounded", "interlocking-combs"};
  std::mt19937 rng(seed);
  const int kind = int(seed % 6);
  // Every third round of kinds, the fixed part turned by an arbitrary angle.
  const bool turn = seed / 6 % 3 == 2;
  for (int attempt = 0; attempt < 1000; ++attempt) {
    Parts p;
    if (!kKinds[kind](rng, p)) continue;
    if (turn) {
      const double angle = kTwoPi * double(rng()) / 4294967296.0;
      for (Loop& l : p.fixed) l = turned(l, angle);
    }
    std::string json = R"({"name":"designed-)";
    json += kNames[kind];
    json += R"(","moving":{"loops":)";
    json += loops_text(p.moving);
    json += R"(},"fixed":{"enclosure":)";
    json += p.enclosure ? "true" : "false";
    json += R"(,"loops":)";
    json += loops_text(p.fixed);
    json += "}}";
    LoadResult r = parse_pair(json, "designed");
    if (r.ok()) return {std::move(*r.pair), json};
  }
  throw std::runtime_error("designed_pair: no valid pair for seed " + std::to_string(seed));
}

}  // namespace cslice::testkit
