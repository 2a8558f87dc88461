#include "support/random_polygons.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

namespace cslice::testkit {
namespace {

double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Signed turn from direction a to direction b, in (-pi, pi].
double turn_between(Vec2 a, Vec2 b) {
  return std::atan2(cross(a, b), dot(a, b));
}

}  // namespace

LoopVertices random_star(std::mt19937& rng, const StarOptions& o) {
  const int n = o.vertices;
  // The smooth contour: harmonics 2, 3, ... with random phases and weights summing to the
  // lobe depth (frequency 1 would only shift the shape).
  std::vector<double> amplitude(o.lobes), phase(o.lobes);
  double weight_sum = 0.0;
  for (int j = 0; j < o.lobes; ++j) {
    amplitude[j] = uniform(rng, 0.2, 1.0) / (j + 1);
    phase[j] = uniform(rng, 0.0, kTwoPi);
    weight_sum += amplitude[j];
  }
  for (double& a : amplitude) a *= o.lobe_depth / weight_sum;

  LoopVertices loop(n);
  for (int i = 0; i < n; ++i) {
    const double angle = kTwoPi * (i + o.angle_jitter * uniform(rng, 0.0, 1.0)) / n;
    double r = 1.0;
    for (int j = 0; j < o.lobes; ++j) r += amplitude[j] * std::cos((j + 2) * angle + phase[j]);
    r *= o.radius * (1.0 + o.radial_jitter * uniform(rng, -1.0, 1.0));
    loop[i] = {o.center.x + r * std::cos(angle), o.center.y + r * std::sin(angle), 0.0};
  }
  if (o.arc_fraction <= 0.0) return loop;

  // Turn of the polygon at each vertex; an arc edge sweeps the mean of its ends' turns.
  std::vector<double> turn(n);
  for (int i = 0; i < n; ++i) {
    const LoopVertex& p = loop[(i + n - 1) % n];
    const LoopVertex& v = loop[i];
    const LoopVertex& q = loop[(i + 1) % n];
    turn[i] = turn_between({v.x - p.x, v.y - p.y}, {q.x - v.x, q.y - v.y});
  }
  for (int i = 0; i < n; ++i) {
    const bool arc = uniform(rng, 0.0, 1.0) < o.arc_fraction;
    const double scale = 1.0 + o.bulge_noise * uniform(rng, -1.0, 1.0);
    if (!arc) continue;
    const double sweep = 0.5 * (turn[i] + turn[(i + 1) % n]) * scale;
    const LoopVertex& q = loop[(i + 1) % n];
    const double chord = std::hypot(q.x - loop[i].x, q.y - loop[i].y);
    const double bulge = std::tan(sweep / 4.0);
    if (0.5 * chord * std::fabs(bulge) >= o.min_sagitta) loop[i].bulge = bulge;
  }
  return loop;
}

StarPairLoops lobed_star_pair(std::mt19937& rng, int vertices, double radial_jitter,
                              double arc_fraction) {
  StarOptions f;
  f.vertices = vertices;
  f.radius = 3.0;
  f.radial_jitter = radial_jitter;
  f.angle_jitter = 0.8;
  f.lobes = 3;
  f.lobe_depth = 0.3;
  f.arc_fraction = arc_fraction;
  f.min_sagitta = 1e-7;  // about 8 times the reader's geometric tolerance for these pairs
  StarOptions m = f;
  m.radius = 1.0;
  m.center = {0.1, -0.2};
  StarPairLoops p;
  p.fixed = random_star(rng, f);
  p.moving = random_star(rng, m);
  return p;
}

LoopVertices random_comb(std::mt19937& rng, const CombOptions& o) {
  const double d = o.part_size;
  struct Tooth {
    double left = 0.0, right = 0.0;  // stem
    double height = 0.0;             // stem height above the bar
    double cap = 0.0;                // cap thickness (0: no cap)
    double over_left = 0.0, over_right = 0.0;
  };
  std::vector<Tooth> teeth(o.teeth);
  double x = uniform(rng, 0.5, 1.5) * d;
  for (int i = 0; i < o.teeth; ++i) {
    Tooth& t = teeth[i];
    const bool capped = uniform(rng, 0.0, 1.0) < o.cap_probability;
    t.cap = capped ? uniform(rng, 0.2, 0.6) * d : 0.0;
    t.height = uniform(rng, 1.6, 3.5) * d;
    if (i == 0 && capped) t.over_left = uniform(rng, 0.1, 0.8) * d;
    t.left = x;
    t.right = x + uniform(rng, 0.3, 1.2) * d;
    x = t.right;
    if (i + 1 == o.teeth) {
      if (capped) t.over_right = uniform(rng, 0.1, 0.8) * d;
      break;
    }
    // The pocket to the next tooth: a mouth around the part's width, the overhangs of the
    // two caps on top of it (an uncapped side has none).
    const double mouth = uniform(rng, 0.3, 1.7) * d;
    t.over_right = capped ? uniform(rng, 0.15, 0.8) * d : 0.0;
    const double next_over_left = uniform(rng, 0.15, 0.8) * d;  // dropped if uncapped
    teeth[i + 1].over_left = next_over_left;
    x += t.over_right + mouth + next_over_left;
  }
  // An uncapped tooth has no overhang: its neighbour's pocket simply gets wider.
  for (Tooth& t : teeth)
    if (t.cap == 0.0) t.over_left = t.over_right = 0.0;
  const double width = x + uniform(rng, 0.5, 1.5) * d;
  const double bar = uniform(rng, 0.5, 1.5) * d;

  std::vector<Vec2> pts{{0.0, 0.0}, {width, 0.0}, {width, bar}};
  for (int i = o.teeth - 1; i >= 0; --i) {
    const Tooth& t = teeth[i];
    const double top = bar + t.height;
    pts.push_back({t.right, bar});
    pts.push_back({t.right, top});
    if (t.cap > 0.0) {
      pts.push_back({t.right + t.over_right, top});
      pts.push_back({t.right + t.over_right, top + t.cap});
      pts.push_back({t.left - t.over_left, top + t.cap});
      pts.push_back({t.left - t.over_left, top});
    } else {
      // A convex roof instead of a cap: the same vertex count for every tooth.
      const double w = t.right - t.left;
      pts.push_back({t.right - 0.2 * w, top + 0.15 * d});
      pts.push_back({t.right - 0.4 * w, top + 0.25 * d});
      pts.push_back({t.left + 0.4 * w, top + 0.25 * d});
      pts.push_back({t.left + 0.2 * w, top + 0.15 * d});
    }
    pts.push_back({t.left, top});
    pts.push_back({t.left, bar});
  }
  pts.push_back({0.0, bar});

  const double c = std::cos(o.turn), s = std::sin(o.turn);
  LoopVertices loop;
  loop.reserve(pts.size());
  for (Vec2 p : pts)
    loop.push_back({c * p.x - s * p.y + o.offset.x, s * p.x + c * p.y + o.offset.y, 0.0});
  return loop;
}

LoopVertices rectangle(double w, double h, Vec2 center, double turn) {
  const double c = std::cos(turn), s = std::sin(turn);
  LoopVertices loop;
  for (Vec2 p :
       {Vec2{-w / 2, -h / 2}, Vec2{w / 2, -h / 2}, Vec2{w / 2, h / 2}, Vec2{-w / 2, h / 2}})
    loop.push_back({c * p.x - s * p.y + center.x, s * p.x + c * p.y + center.y, 0.0});
  return loop;
}

LoopVertices gear(const GearShape& g) {
  const double pitch = kTwoPi / g.teeth;
  const auto at = [](double r, double a, double sweep) {
    return LoopVertex{r * std::cos(a), r * std::sin(a), std::tan(sweep / 4)};
  };
  LoopVertices loop;
  for (int i = 0; i < g.teeth; ++i) {
    const double c = g.phase + i * pitch;
    loop.push_back(at(g.root, c - g.root_half, 0.0));                      // rising flank
    loop.push_back(at(g.tip, c - g.tip_half, 2 * g.tip_half));             // tip arc
    loop.push_back(at(g.tip, c + g.tip_half, 0.0));                        // falling flank
    loop.push_back(at(g.root, c + g.root_half, pitch - 2 * g.root_half));  // root arc
  }
  return loop;
}

std::string gear_in_ring_json(int teeth, double tip, double root, int ring_teeth, double ring_tip,
                              double ring_root, double tolerance) {
  const double pitch = kTwoPi / teeth, ring_pitch = kTwoPi / ring_teeth;
  const LoopVertices g = gear({teeth, tip, root, 0.126 * pitch, 0.2625 * pitch, 0.0});
  const LoopVertices ring = gear(
      {ring_teeth, ring_tip, ring_root, 0.2625 * ring_pitch, 0.126 * ring_pitch, ring_pitch / 2});
  std::string json = "{\"name\":\"gear in ring\",";
  if (tolerance > 0.0) json += "\"tolerance\":" + std::to_string(tolerance) + ",";
  return json + "\"moving\":{\"loops\":[" + loop_json(g) +
         "]},\"fixed\":{\"enclosure\":true,\"loops\":[" + loop_json(ring) + "]}}";
}

double loop_area(const LoopVertices& loop) {
  double area = 0.0;
  const size_t n = loop.size();
  for (size_t i = 0; i < n; ++i) {
    const LoopVertex& a = loop[i];
    const LoopVertex& b = loop[(i + 1) % n];
    area += 0.5 * (a.x * b.y - a.y * b.x);
    if (a.bulge != 0.0) {
      // The circular segment between the chord and the arc, signed with the sweep.
      const double sweep = 4.0 * std::atan(a.bulge);
      const double chord = std::hypot(b.x - a.x, b.y - a.y);
      const double r = chord / (2.0 * std::sin(std::fabs(sweep) / 2.0));
      area += 0.5 * r * r * (sweep - std::sin(sweep));
    }
  }
  return area;
}

std::string loop_json(const LoopVertices& loop) {
  std::ostringstream out;
  out.precision(17);
  out << "[";
  for (size_t i = 0; i < loop.size(); ++i) {
    out << (i ? "," : "") << "[" << loop[i].x << "," << loop[i].y;
    if (loop[i].bulge != 0.0) out << "," << loop[i].bulge;
    out << "]";
  }
  out << "]";
  return out.str();
}

std::string pair_json(const std::string& name, const std::vector<LoopVertices>& moving,
                      const std::vector<LoopVertices>& fixed) {
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on a chain of operator+.
  auto append_loops = [](std::string& s, const std::vector<LoopVertices>& ls) {
    s += "[";
    for (size_t i = 0; i < ls.size(); ++i) {
      if (i) s += ",";
      s += loop_json(ls[i]);
    }
    s += "]";
  };
  std::string s = R"({"name":")";
  s += name;
  s += R"(","moving":{"loops":)";
  append_loops(s, moving);
  s += R"(},"fixed":{"loops":)";
  append_loops(s, fixed);
  s += "}}";
  return s;
}

Pair parse_or_throw(const std::string& json, const std::string& source) {
  LoadResult r = parse_pair(json, source);
  if (!r.ok()) throw std::runtime_error(r.error->message());
  return std::move(*r.pair);
}

AcceptedStarPair accepted_star_pair(int vertices, double radial_jitter, double arc_fraction,
                                    unsigned first_seed, unsigned seed_step, int tries,
                                    const std::string& name) {
  std::string why;
  for (int k = 0; k < tries; ++k) {
    std::mt19937 rng(first_seed + unsigned(k) * seed_step);
    StarPairLoops loops = lobed_star_pair(rng, vertices, radial_jitter, arc_fraction);
    std::string json = pair_json(name, {loops.moving}, {loops.fixed});
    LoadResult r = parse_pair(json, name);
    if (r.ok()) return {std::move(loops), std::move(json), std::move(*r.pair)};
    why = r.error->message();
  }
  throw std::runtime_error(name + ": no valid star pair in " + std::to_string(tries) +
                           " draws from seed " + std::to_string(first_seed) + " (last: " + why +
                           ")");
}

Pair curved_star_pair(int vertices) {
  return accepted_star_pair(vertices, 0.1, 0.5, 2026 + unsigned(vertices), 1, 74, "curved").pair;
}

Pair gear_pair(int teeth) {
  const double k = teeth / 8.0;
  return parse_or_throw(gear_in_ring_json(teeth, 1.0 + 4.0 * k, 1.0 + 4.0 * k - 2.25, 2 * teeth,
                                          3.0 + 4.0 * k, 5.25 + 4.0 * k, 0.001),
                        "gear");
}

const Pair& made_once(Pair (*make)(int), int n) {
  static std::map<std::pair<Pair (*)(int), int>, Pair> made;
  const auto key = std::make_pair(make, n);
  if (auto it = made.find(key); it != made.end()) return it->second;
  return made.emplace(key, make(n)).first->second;
}

}  // namespace cslice::testkit
