// An independent oracle for the direct placement test. Every arc is cut into chords (sagitta
// at most delta), so each part becomes a set of CGAL polygons; CGAL then decides whether the
// placed interiors intersect (exact Boolean operations) and how far apart the boundaries are.
// Nothing here uses cslice geometry: the pair JSON is read directly, and only parse_pair (for
// the tolerances and the object under test) and PlacementTester come from the library.
//
// Polygonisation and the contact tolerance blur the answer near contact, so random poses are
// compared only where the oracle is decisive (the rest are counted and must be few). Contact
// itself is checked by walking from a blocked pose to a free one and bisecting the places
// where the answer changes: the boundaries must meet where blocked ends and be a tolerance
// apart where free begins.
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "cslice/classify.hpp"
#include "cslice/pair.hpp"
#include "support/oracle_pairs.hpp"

namespace {

using cslice::Placement;
using cslice::Pose;
using nlohmann::json;
using Ek = CGAL::Exact_predicates_exact_constructions_kernel;
using Ik = CGAL::Exact_predicates_inexact_constructions_kernel;
using EPolygon = CGAL::Polygon_2<Ek>;
using EPolygonWithHoles = CGAL::Polygon_with_holes_2<Ek>;
using IPoint = Ik::Point_2;
using ISegment = Ik::Segment_2;

constexpr double kPi = 3.14159265358979323846;

struct Pt {
  double x = 0, y = 0;
};

// ---- Polygonisation (independent of cslice's arc code) -----------------------------------

// Points of the arc from p to q with bulge b (tan of a quarter of the signed sweep), from p
// up to but excluding q, with chords whose sagitta is at most delta.
void append_arc(Pt p, Pt q, double b, double delta, std::vector<Pt>& out) {
  out.push_back(p);
  if (b == 0.0) return;
  const double dx = q.x - p.x, dy = q.y - p.y, chord = std::hypot(dx, dy);
  const double sweep = 4.0 * std::atan(b);
  // The centre lies on the chord's bisector at (chord / 2) cot(sweep / 2), left of p -> q.
  const double offset = chord * (1.0 - b * b) / (4.0 * b);
  const Pt c{(p.x + q.x) / 2 - dy / chord * offset, (p.y + q.y) / 2 + dx / chord * offset};
  const double r = chord * (1.0 + b * b) / (4.0 * std::fabs(b));
  const double max_step = delta >= r ? kPi : 2.0 * std::acos(1.0 - delta / r);
  const int n = std::max(1, static_cast<int>(std::ceil(std::fabs(sweep) / max_step)));
  const double a0 = std::atan2(p.y - c.y, p.x - c.x);
  for (int k = 1; k < n; ++k) {
    const double a = a0 + sweep * k / n;
    out.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
}

std::vector<Pt> polygonize_loop(const json& loop, double delta) {
  std::vector<Pt> pts;
  if (loop.is_object()) {
    const auto& c = loop["circle"];
    const double cx = c[0], cy = c[1], r = c[2];
    const double max_step = delta >= r ? kPi / 2 : 2.0 * std::acos(1.0 - delta / r);
    const int n = std::max(4, static_cast<int>(std::ceil(2 * kPi / max_step)));
    for (int k = 0; k < n; ++k)
      pts.push_back({cx + r * std::cos(2 * kPi * k / n), cy + r * std::sin(2 * kPi * k / n)});
    return pts;
  }
  for (size_t i = 0; i < loop.size(); ++i) {
    const json& v = loop[i];
    const json& w = loop[(i + 1) % loop.size()];
    const double b = v.size() > 2 ? v[2].get<double>() : 0.0;
    append_arc({v[0], v[1]}, {w[0], w[1]}, b, delta, pts);
  }
  return pts;
}

double signed_area(const std::vector<Pt>& pts) {
  double a = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    const Pt& p = pts[i];
    const Pt& q = pts[(i + 1) % pts.size()];
    a += p.x * q.y - p.y * q.x;
  }
  return a / 2;
}

double perimeter(const std::vector<Pt>& pts) {
  double l = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    const Pt& q = pts[(i + 1) % pts.size()];
    l += std::hypot(q.x - pts[i].x, q.y - pts[i].y);
  }
  return l;
}

std::vector<IPoint> to_ipoints(const std::vector<Pt>& pts) {
  std::vector<IPoint> out;
  out.reserve(pts.size());
  for (const Pt& p : pts) out.emplace_back(p.x, p.y);
  return out;
}

bool encloses(const std::vector<IPoint>& loop, const IPoint& p) {
  return CGAL::bounded_side_2(loop.begin(), loop.end(), p, Ik()) == CGAL::ON_BOUNDED_SIDE;
}

// ---- Oracle parts ------------------------------------------------------------------------

// A part as polygons: its loops (for an enclosure, preceded by a frame far outside every
// placement), which of them are outer boundaries, and the nesting that makes components.
struct OraclePart {
  std::vector<std::vector<Pt>> loops;  // any orientation
  std::vector<int> parent;             // enclosing loop one level up, or -1
  std::vector<bool> outer;             // material on the inside of this loop
  int first_real = 0;                  // 1 when loops[0] is an enclosure's frame
  double perimeter = 0;                // of the real loops
  double area = 0;                     // material, or the openings of an enclosure
};

OraclePart make_oracle_part(const json& part, double delta, double frame_margin) {
  OraclePart o;
  const bool enclosure = part.value("enclosure", false);
  double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
  std::vector<std::vector<Pt>> real;
  for (const json& loop : part["loops"]) {
    real.push_back(polygonize_loop(loop, delta));
    for (const Pt& p : real.back()) {
      lo_x = std::min(lo_x, p.x), lo_y = std::min(lo_y, p.y);
      hi_x = std::max(hi_x, p.x), hi_y = std::max(hi_y, p.y);
    }
  }
  if (enclosure) {
    const double m = frame_margin;
    o.loops.push_back(
        {{lo_x - m, lo_y - m}, {hi_x + m, lo_y - m}, {hi_x + m, hi_y + m}, {lo_x - m, hi_y + m}});
    o.first_real = 1;
  }
  for (auto& l : real) o.loops.push_back(std::move(l));
  const size_t n = o.loops.size();
  std::vector<std::vector<IPoint>> ip;
  for (const auto& l : o.loops) ip.push_back(to_ipoints(l));
  // Depth = number of loops around a loop; the parent is the enclosing loop of greatest depth.
  std::vector<int> depth(n, 0);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j)
      if (i != j && encloses(ip[j], ip[i].front())) ++depth[i];
  o.parent.assign(n, -1);
  o.outer.assign(n, false);
  for (size_t i = 0; i < n; ++i) {
    o.outer[i] = depth[i] % 2 == 0;
    for (size_t j = 0; j < n; ++j)
      if (i != j && depth[j] == depth[i] - 1 && encloses(ip[j], ip[i].front()))
        o.parent[i] = static_cast<int>(j);
  }
  for (size_t i = o.first_real; i < n; ++i) {
    o.perimeter += perimeter(o.loops[i]);
    // Real outer loops add, real holes subtract; for an enclosure the roles swap.
    const double a = std::fabs(signed_area(o.loops[i]));
    o.area += (o.outer[i] != enclosure) ? a : -a;
  }
  return o;
}

std::vector<Pt> transformed(const std::vector<Pt>& pts, const Pose& pose) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  std::vector<Pt> out;
  out.reserve(pts.size());
  for (const Pt& p : pts) out.push_back({c * p.x - s * p.y + pose.x, s * p.x + c * p.y + pose.y});
  return out;
}

OraclePart placed(const OraclePart& body, const Pose& pose) {
  OraclePart o = body;
  for (auto& l : o.loops) l = transformed(l, pose);
  return o;
}

// Every real boundary chord of the part, with its bounding box.
struct Chords {
  std::vector<ISegment> segments;
  std::vector<CGAL::Bbox_2> boxes;
  CGAL::Bbox_2 box;
};

Chords chords_of(const OraclePart& part) {
  Chords c;
  for (size_t i = part.first_real; i < part.loops.size(); ++i) {
    const auto& l = part.loops[i];
    for (size_t k = 0; k < l.size(); ++k) {
      const Pt& p = l[k];
      const Pt& q = l[(k + 1) % l.size()];
      c.segments.emplace_back(IPoint(p.x, p.y), IPoint(q.x, q.y));
      c.boxes.push_back(c.segments.back().bbox());
      c.box += c.boxes.back();
    }
  }
  return c;
}

bool boxes_within(const CGAL::Bbox_2& a, const CGAL::Bbox_2& b, double d) {
  return a.xmin() - d <= b.xmax() && b.xmin() - d <= a.xmax() && a.ymin() - d <= b.ymax() &&
         b.ymin() - d <= a.ymax();
}

// Distance between the two boundaries (0 when they cross), or +infinity when it exceeds limit.
double chord_distance(const Chords& a, const Chords& b, double limit) {
  double best = std::numeric_limits<double>::infinity();
  if (!boxes_within(a.box, b.box, limit)) return best;
  for (size_t i = 0; i < a.segments.size(); ++i) {
    if (!boxes_within(a.boxes[i], b.box, std::min(best, limit))) continue;
    for (size_t j = 0; j < b.segments.size(); ++j) {
      if (!boxes_within(a.boxes[i], b.boxes[j], std::min(best, limit))) continue;
      if (CGAL::do_intersect(a.segments[i], b.segments[j])) return 0.0;
      const double d =
          std::sqrt(CGAL::to_double(CGAL::squared_distance(a.segments[i], b.segments[j])));
      if (d <= limit) best = std::min(best, d);
    }
  }
  return best;
}

// Whether p lies in the part's material: inside an odd number of its loops (frame included).
bool in_material(const std::vector<std::vector<IPoint>>& loops, Pt p) {
  int count = 0;
  const IPoint q(p.x, p.y);
  for (const auto& l : loops) count += encloses(l, q) ? 1 : 0;
  return count % 2 == 1;
}

std::vector<std::vector<IPoint>> ipoints_of(const OraclePart& part) {
  std::vector<std::vector<IPoint>> out;
  for (const auto& l : part.loops) out.push_back(to_ipoints(l));
  return out;
}

// With the boundaries apart, the interiors meet exactly when some boundary point of one part
// lies in the other's material.
bool nested(const OraclePart& a, const OraclePart& b) {
  const auto ia = ipoints_of(a), ib = ipoints_of(b);
  for (size_t i = a.first_real; i < a.loops.size(); ++i)
    if (in_material(ib, a.loops[i].front())) return true;
  for (size_t i = b.first_real; i < b.loops.size(); ++i)
    if (in_material(ia, b.loops[i].front())) return true;
  return false;
}

double distance_to_chords(const Chords& c, Pt p, double stop_below) {
  const IPoint q(p.x, p.y);
  double best = std::numeric_limits<double>::infinity();
  for (const ISegment& s : c.segments) {
    best = std::min(best, std::sqrt(CGAL::to_double(CGAL::squared_distance(s, q))));
    if (best < stop_below) break;
  }
  return best;
}

// How deep the boundary of `a` reaches into the material of `b`: the largest distance to b's
// boundary over points of a's boundary (sampled every `spacing`) that lie in b's material.
double deepest_penetration(const OraclePart& a, const OraclePart& b, const Chords& b_chords,
                           double spacing) {
  const auto ib = ipoints_of(b);
  double deepest = 0;
  for (size_t i = a.first_real; i < a.loops.size(); ++i) {
    const auto& l = a.loops[i];
    for (size_t k = 0; k < l.size(); ++k) {
      const Pt p = l[k], q = l[(k + 1) % l.size()];
      const int n =
          std::max(1, static_cast<int>(std::ceil(std::hypot(q.x - p.x, q.y - p.y) / spacing)));
      for (int j = 0; j < n; ++j) {
        const Pt s{p.x + (q.x - p.x) * j / n, p.y + (q.y - p.y) * j / n};
        // Outside the box of a solid part's boundary means outside its material.
        const bool near_b = boxes_within(CGAL::Bbox_2(s.x, s.y, s.x, s.y), b_chords.box, 0);
        if (!near_b && b.first_real == 0) continue;
        if (!in_material(ib, s)) continue;
        deepest = std::max(deepest, distance_to_chords(b_chords, s, deepest));
      }
    }
  }
  return deepest;
}

EPolygon exact_polygon(const std::vector<Pt>& pts, bool counterclockwise) {
  EPolygon poly;
  for (const Pt& p : pts) poly.push_back(Ek::Point_2(p.x, p.y));
  if ((poly.orientation() == CGAL::COUNTERCLOCKWISE) != counterclockwise)
    poly.reverse_orientation();
  return poly;
}

std::vector<EPolygonWithHoles> components(const OraclePart& part) {
  std::vector<EPolygonWithHoles> out;
  std::vector<int> index_of(part.loops.size(), -1);
  for (size_t i = 0; i < part.loops.size(); ++i) {
    if (!part.outer[i]) continue;
    index_of[i] = static_cast<int>(out.size());
    out.emplace_back(exact_polygon(part.loops[i], true));
  }
  for (size_t i = 0; i < part.loops.size(); ++i)
    if (!part.outer[i]) out[index_of[part.parent[i]]].add_hole(exact_polygon(part.loops[i], false));
  return out;
}

double area_of(const EPolygonWithHoles& p) {
  Ek::FT a = p.outer_boundary().area();
  for (auto h = p.holes_begin(); h != p.holes_end(); ++h) a += h->area();
  return CGAL::to_double(a);
}

double intersection_area(const std::vector<EPolygonWithHoles>& a,
                         const std::vector<EPolygonWithHoles>& b) {
  double total = 0;
  std::vector<EPolygonWithHoles> out;
  for (const auto& pa : a)
    for (const auto& pb : b) {
      out.clear();
      CGAL::intersection(pa, pb, std::back_inserter(out));
      for (const auto& p : out) total += area_of(p);
    }
  return total;
}

// ---- The oracle ---------------------------------------------------------------------------

struct Case {
  json pair_json;
  cslice::Pair pair;
  OraclePart moving, fixed;  // polygonised with delta
  Chords fixed_chords;
  std::vector<EPolygonWithHoles> fixed_components;
  double delta = 0;
};

std::optional<Case> make_case(const json& pair_json, double relative_delta,
                              bool delta_below_tolerance) {
  cslice::LoadResult r = cslice::parse_pair(pair_json.dump(), "oracle");
  if (!r.ok()) return std::nullopt;
  Case c{pair_json, std::move(*r.pair), {}, {}, {}, {}, 0};
  const cslice::Tolerances& tol = c.pair.tol;
  c.delta = relative_delta * tol.size;
  if (delta_below_tolerance) c.delta = std::min(c.delta, tol.contact / 50);
  c.moving = make_oracle_part(pair_json["moving"], c.delta, 0);
  c.fixed = make_oracle_part(pair_json["fixed"], c.delta, 4 * tol.size);
  c.fixed_chords = chords_of(c.fixed);
  c.fixed_components = components(c.fixed);
  return c;
}

enum class Verdict { free, blocked, undecided };

struct OracleAnswer {
  Verdict verdict = Verdict::undecided;
  double distance = 0;   // between the polygon boundaries; +inf when far
  bool by_area = false;  // blocked decided by the overlap area
};

// Spacing of the boundary samples searched for deep penetration, relative to the pair size.
constexpr double kPenetrationSpacing = 2e-3;

// The oracle's answer at one pose: free or blocked where decisive, else undecided.
OracleAnswer oracle(const Case& c, const Pose& pose) {
  const OraclePart m = placed(c.moving, pose);
  const Chords m_chords = chords_of(m);
  const double tol = c.pair.tol.contact, d = c.delta;
  const double threshold = tol + 2 * d;
  OracleAnswer a;
  a.distance = chord_distance(m_chords, c.fixed_chords, threshold);
  if (a.distance > 2 * d + c.pair.tol.geometric) {
    // The true boundaries do not cross either, so nesting decides overlap.
    if (nested(m, c.fixed))
      a.verdict = Verdict::blocked;
    else if (a.distance > threshold)
      a.verdict = Verdict::free;
    return a;
  }
  // The polygons overlap, or nearly. Thin overlaps along the boundaries are what
  // polygonisation alone can produce; a large overlap area is not.
  const double smaller = std::min(c.moving.perimeter, c.fixed.perimeter);
  if (intersection_area(components(m), c.fixed_components) > smaller * threshold) {
    a.verdict = Verdict::blocked;
    a.by_area = true;
    return a;
  }
  // A boundary point deeper than 2 delta inside the other polygon has a point of the true
  // boundary within delta of it, inside the true other part.
  const double spacing = kPenetrationSpacing * c.pair.tol.size;
  const double depth = std::max(deepest_penetration(m, c.fixed, c.fixed_chords, spacing),
                                deepest_penetration(c.fixed, m, m_chords, spacing));
  if (depth > 3 * d) a.verdict = Verdict::blocked;
  return a;
}

std::string describe(const Case& c, const Pose& p) {
  char pose[160];
  std::snprintf(pose, sizeof pose, "pose %.17g %.17g %.17g", p.x, p.y, p.theta);
  return std::string(pose) + "\npair " + c.pair_json.dump();
}

// ---- Random cases ---------------------------------------------------------------------------

using cslice::testkit::example_pair_files;
using cslice::testkit::oracle_random_pair;
using cslice::testkit::uniform;
using Rng = std::mt19937_64;

// Whether the polygonisation is a valid input for CGAL's Boolean operations: simple loops
// whose boundaries keep apart.
bool polygons_valid(const OraclePart& part) {
  for (const auto& l : part.loops)
    if (!exact_polygon(l, true).is_simple()) return false;
  for (size_t i = 0; i < part.loops.size(); ++i)
    for (size_t j = i + 1; j < part.loops.size(); ++j) {
      OraclePart a, b;
      a.loops = {part.loops[i]};
      b.loops = {part.loops[j]};
      if (chord_distance(chords_of(a), chords_of(b), 0) == 0.0) return false;
    }
  return true;
}

std::optional<Case> random_case(Rng& rng, int index, double relative_delta, bool fine,
                                bool curved = true) {
  for (int attempt = 0; attempt < 50; ++attempt) {
    std::optional<Case> c = make_case(oracle_random_pair(rng, index, curved), relative_delta, fine);
    if (c && polygons_valid(c->moving) && polygons_valid(c->fixed)) return c;
  }
  return std::nullopt;
}

// A random pose whose placed moving part is near the fixed part: the reference point within
// the fixed part's box grown by the moving part's reach.
Pose random_pose(Rng& rng, const Case& c) {
  double reach = 0;
  for (const auto& l : c.moving.loops)
    for (const Pt& p : l) reach = std::max(reach, std::hypot(p.x, p.y));
  const CGAL::Bbox_2& b = c.fixed_chords.box;
  return {uniform(rng, b.xmin() - reach, b.xmax() + reach),
          uniform(rng, b.ymin() - reach, b.ymax() + reach), uniform(rng, -kPi, kPi)};
}

// ---- Random poses against the oracle -----------------------------------------------------

struct Tally {
  long checked = 0, skipped = 0, free = 0, blocked = 0, blocked_by_area = 0;
};

// Compares the tester with the oracle at `count` random poses; false on the first mismatch.
bool compare_random_poses(const Case& c, Rng& rng, int count, Tally& tally) {
  cslice::PlacementTester tester(c.pair);
  for (int i = 0; i < count; ++i) {
    const Pose pose = random_pose(rng, c);
    const OracleAnswer o = oracle(c, pose);
    if (o.verdict == Verdict::undecided) {
      ++tally.skipped;
      continue;
    }
    ++tally.checked;
    const Placement got = tester.classify(pose);
    const Placement want = o.verdict == Verdict::free ? Placement::free : Placement::blocked;
    ++(want == Placement::free ? tally.free : tally.blocked);
    if (o.by_area) ++tally.blocked_by_area;
    if (got != want) {
      ADD_FAILURE() << "classify says " << cslice::to_string(got) << ", oracle says "
                    << cslice::to_string(want) << " (boundary distance " << o.distance << ", delta "
                    << c.delta << ")\n"
                    << describe(c, pose);
      return false;
    }
  }
  return true;
}

void report(const char* what, const Tally& t) {
  const long total = t.checked + t.skipped;
  std::cout << what << ": " << t.checked << " checked (" << t.free << " free, " << t.blocked
            << " blocked, " << t.blocked_by_area << " of them by overlap area), " << t.skipped
            << " skipped near contact (" << (total ? 100.0 * t.skipped / total : 0.0) << "%)\n";
}

TEST(CgalClassifyOracle, PolygonisationMatchesPartArea) {
  Rng rng(101);
  for (int i = 0; i < 200; ++i) {
    std::optional<Case> c = random_case(rng, i, 1e-4, false);
    ASSERT_TRUE(c);
    // Chords cut off at most delta * perimeter of area.
    EXPECT_NEAR(c->moving.area, c->pair.moving.area, c->moving.perimeter * c->delta)
        << c->pair_json.dump();
    EXPECT_NEAR(c->fixed.area, c->pair.fixed.area, c->fixed.perimeter * c->delta)
        << c->pair_json.dump();
  }
}

TEST(CgalClassifyOracle, RandomPairsAtRandomPoses) {
  Rng rng(202);
  Tally tally;
  for (int i = 0; i < 500; ++i) {
    std::optional<Case> c = random_case(rng, i, 1e-4, false);
    ASSERT_TRUE(c) << "could not build random pair " << i;
    if (!compare_random_poses(*c, rng, 100, tally)) break;
  }
  report("random pairs", tally);
  EXPECT_GT(tally.free, tally.checked / 10);
  EXPECT_GT(tally.blocked, tally.checked / 10);
  EXPECT_LT(tally.skipped, (tally.checked + tally.skipped) / 20);
}

TEST(CgalClassifyOracle, ExamplesAtRandomPoses) {
  const std::vector<json> examples = example_pair_files();
  if (examples.empty()) GTEST_SKIP() << "no examples yet";
  Rng rng(303);
  Tally tally;
  for (const json& e : examples) {
    std::optional<Case> c = make_case(e, 1e-4, false);
    ASSERT_TRUE(c) << e.dump();
    if (!compare_random_poses(*c, rng, 4000, tally)) break;
  }
  report("examples", tally);
  EXPECT_LT(tally.skipped, (tally.checked + tally.skipped) / 20);
}

// ---- Contact along rays --------------------------------------------------------------------

struct RayTally {
  long rays = 0, no_endpoints = 0;
};

// Shrinks [lo, hi] to width `step` keeping inside(lo) and !inside(hi).
template <class Inside>
std::pair<double, double> bisect(double lo, double hi, double step, Inside inside) {
  while (hi - lo > step) {
    const double mid = 0.5 * (lo + hi);
    (inside(mid) ? lo : hi) = mid;
  }
  return {lo, hi};
}

// A random pose at orientation theta with the wanted answer, if one turns up quickly.
std::optional<Pose> pose_with(Rng& rng, const Case& c, cslice::PlacementTester& tester,
                              double theta, Placement want) {
  for (int attempt = 0; attempt < 60; ++attempt) {
    Pose p = random_pose(rng, c);
    p.theta = theta;
    if (tester.classify(p) == want) return p;
  }
  return std::nullopt;
}

// Walks from a blocked pose to a free one. Where blocked ends the answer must be contact and
// the boundaries must (nearly) meet; where free begins the last pose before must be contact
// and the boundaries must be a contact tolerance apart.
bool check_ray(const Case& c, cslice::PlacementTester& tester, const Pose& from, const Pose& to) {
  const double tol = c.pair.tol.contact, d = c.delta;
  const double length = std::hypot(to.x - from.x, to.y - from.y);
  const double step = 1e-3 * tol;  // bisection resolution, as a length
  const double slack = step + 2 * d + 10 * c.pair.tol.geometric;
  const auto at = [&](double s) {
    return Pose{from.x + s * (to.x - from.x), from.y + s * (to.y - from.y), from.theta};
  };
  const auto distance = [&](double s) {
    return chord_distance(chords_of(placed(c.moving, at(s))), c.fixed_chords, 4 * tol);
  };
  const auto [s1, s2] = bisect(0.0, 1.0, step / length, [&](double s) {
    return tester.classify(at(s)) == Placement::blocked;
  });
  const Placement after_blocked = tester.classify(at(s2));
  const double d2 = distance(s2);
  EXPECT_TRUE(after_blocked == Placement::contact && d2 <= slack)
      << "leaving blocked space: classify says " << cslice::to_string(after_blocked)
      << ", boundary distance " << d2 << " (allowed " << slack << ")\n"
      << describe(c, at(s2));
  if (::testing::Test::HasFailure()) return false;
  const auto [s3, s4] = bisect(s2, 1.0, step / length,
                               [&](double s) { return tester.classify(at(s)) != Placement::free; });
  const Placement before_free = tester.classify(at(s3));
  const double d3 = distance(s3), d4 = distance(s4);
  const bool nested_at_free = nested(placed(c.moving, at(s4)), c.fixed);
  EXPECT_TRUE(before_free == Placement::contact && d3 <= tol + slack && d4 >= tol - slack &&
              !nested_at_free)
      << "entering free space: classify says " << cslice::to_string(before_free)
      << " then free; boundary distances " << d3 << " and " << d4 << " (tolerance " << tol
      << ", slack " << slack << ")" << (nested_at_free ? ", but the parts are nested" : "") << "\n"
      << describe(c, at(s4));
  return !::testing::Test::HasFailure();
}

bool check_rays(const Case& c, Rng& rng, int count, RayTally& tally) {
  cslice::PlacementTester tester(c.pair);
  for (int i = 0; i < count; ++i) {
    const double theta = uniform(rng, -kPi, kPi);
    const auto from = pose_with(rng, c, tester, theta, Placement::blocked);
    const auto to = pose_with(rng, c, tester, theta, Placement::free);
    if (!from || !to) {
      ++tally.no_endpoints;
      continue;
    }
    ++tally.rays;
    if (!check_ray(c, tester, *from, *to)) return false;
  }
  return true;
}

TEST(CgalClassifyOracle, RandomPairsContactAlongRays) {
  Rng rng(404);
  RayTally tally;
  for (int i = 0; i < 400; ++i) {
    std::optional<Case> c = random_case(rng, i, 1e-4, true);
    ASSERT_TRUE(c) << "could not build random pair " << i;
    if (!check_rays(*c, rng, 10, tally)) break;
  }
  std::cout << "random pairs: " << tally.rays << " rays checked, " << tally.no_endpoints
            << " without endpoints\n";
  EXPECT_GT(tally.rays, 3000);
}

TEST(CgalClassifyOracle, ExamplesContactAlongRays) {
  const std::vector<json> examples = example_pair_files();
  if (examples.empty()) GTEST_SKIP() << "no examples yet";
  Rng rng(505);
  RayTally tally;
  for (const json& e : examples) {
    std::optional<Case> c = make_case(e, 1e-4, true);
    ASSERT_TRUE(c) << e.dump();
    if (!check_rays(*c, rng, 250, tally)) break;
  }
  std::cout << "examples: " << tally.rays << " rays checked, " << tally.no_endpoints
            << " without endpoints\n";
  EXPECT_GT(tally.rays, 100 * static_cast<long>(examples.size()));
}

// ---- Touching poses of polygonal parts -------------------------------------------------------
// Without arcs the polygons are the parts, so the oracle is exact (up to rounding in placing
// the moving part) even where features touch: flush edges, a vertex on an edge, two vertices.

struct Edge {
  Pt a, b, outward;  // outward: unit normal pointing away from the material
};

std::vector<Edge> edges_of(const OraclePart& part) {
  std::vector<Edge> out;
  for (size_t i = part.first_real; i < part.loops.size(); ++i) {
    const auto& l = part.loops[i];
    // The material lies left of a counterclockwise outer loop or a clockwise hole.
    const bool material_left = (signed_area(l) > 0) == part.outer[i];
    for (size_t k = 0; k < l.size(); ++k) {
      const Pt a = l[k], b = l[(k + 1) % l.size()];
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      const Pt left{-(b.y - a.y) / len, (b.x - a.x) / len};
      out.push_back({a, b, material_left ? Pt{-left.x, -left.y} : left});
    }
  }
  return out;
}

Pt lerp(Pt a, Pt b, double t) {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
}

// The pose that turns the body point `body` by theta and puts it on `world`.
Pose pose_putting(Pt body, double theta, Pt world) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {world.x - (c * body.x - s * body.y), world.y - (s * body.x + c * body.y), theta};
}

// One of five kinds of touching pose, picked at random.
Pose touching_pose(Rng& rng, const std::vector<Edge>& moving, const std::vector<Edge>& fixed) {
  const auto pick = [&](const std::vector<Edge>& v) -> const Edge& {
    return v[std::uniform_int_distribution<size_t>(0, v.size() - 1)(rng)];
  };
  const Edge& m = pick(moving);
  const Edge& f = pick(fixed);
  const double theta = uniform(rng, -kPi, kPi);
  const double flush =
      std::atan2(-f.outward.y, -f.outward.x) - std::atan2(m.outward.y, m.outward.x);
  switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
    case 0:  // flush: outward normals opposite, the moving edge's midpoint on the fixed edge
      return pose_putting(lerp(m.a, m.b, 0.5), flush, lerp(f.a, f.b, uniform(rng, 0.1, 0.9)));
    case 1:  // the same edges with the materials on one side: they overlap
      return pose_putting(lerp(m.a, m.b, 0.5), flush + kPi, lerp(f.a, f.b, uniform(rng, 0.1, 0.9)));
    case 2:  // a moving vertex on a fixed edge
      return pose_putting(m.a, theta, lerp(f.a, f.b, uniform(rng, 0, 1)));
    case 3:  // a fixed vertex on a moving edge
      return pose_putting(lerp(m.a, m.b, uniform(rng, 0, 1)), theta, f.a);
    default:  // vertex on vertex
      return pose_putting(m.a, theta, f.a);
  }
}

// Exact verdict for polygonal parts, from the overlap regions CGAL computes exactly. Each
// corner of an overlap region lies on one boundary; one farther than a rounding sliver from
// the other boundary is a point of one boundary deep inside the other part: blocked. So is a
// large overlap area (two bars crossing have no deep corner). Contact when the overlap is
// nothing but rounding slivers and the boundaries touch.
Verdict touching_verdict(const Case& c, const Pose& pose) {
  const OraclePart m = placed(c.moving, pose);
  const Chords m_chords = chords_of(m);
  const double smaller = std::min(c.moving.perimeter, c.fixed.perimeter);
  const double sliver = 100 * c.pair.tol.geometric;
  double area = 0, depth = 0;
  std::vector<EPolygonWithHoles> out;
  for (const auto& pa : components(m))
    for (const auto& pb : c.fixed_components) {
      out.clear();
      CGAL::intersection(pa, pb, std::back_inserter(out));
      for (const auto& o : out) {
        area += area_of(o);
        for (auto v = o.outer_boundary().vertices_begin(); v != o.outer_boundary().vertices_end();
             ++v) {
          const Pt p{CGAL::to_double(v->x()), CGAL::to_double(v->y())};
          depth = std::max(depth, std::max(distance_to_chords(m_chords, p, 0),
                                           distance_to_chords(c.fixed_chords, p, 0)));
        }
      }
    }
  if (area > smaller * c.pair.tol.contact || depth > sliver) return Verdict::blocked;
  if (area <= smaller * sliver && depth <= sliver &&
      chord_distance(m_chords, c.fixed_chords, sliver) <= sliver)
    return Verdict::free;  // stands for contact: the parts touch without overlapping
  return Verdict::undecided;
}

TEST(CgalClassifyOracle, PolygonsAtTouchingPoses) {
  Rng rng(606);
  Tally tally;
  for (int i = 0; i < 500; ++i) {
    std::optional<Case> c = random_case(rng, i, 1e-4, false, false);
    ASSERT_TRUE(c) << "could not build random pair " << i;
    cslice::PlacementTester tester(c->pair);
    const std::vector<Edge> moving = edges_of(c->moving), fixed = edges_of(c->fixed);
    for (int k = 0; k < 60; ++k) {
      const Pose pose = touching_pose(rng, moving, fixed);
      const Verdict v = touching_verdict(*c, pose);
      if (v == Verdict::undecided) {
        ++tally.skipped;
        continue;
      }
      ++tally.checked;
      const Placement want = v == Verdict::free ? Placement::contact : Placement::blocked;
      ++(want == Placement::contact ? tally.free : tally.blocked);
      const Placement got = tester.classify(pose);
      ASSERT_EQ(cslice::to_string(got), cslice::to_string(want))
          << "(a fresh tester says " << cslice::to_string(cslice::classify(c->pair, pose)) << ")\n"
          << describe(*c, pose);
    }
  }
  std::cout << "touching poses: " << tally.checked << " checked (" << tally.free << " contact, "
            << tally.blocked << " blocked), " << tally.skipped << " skipped\n";
  EXPECT_GT(tally.free, tally.checked / 10);
  EXPECT_GT(tally.blocked, tally.checked / 10);
  EXPECT_LT(tally.skipped, (tally.checked + tally.skipped) / 20);
}

}  // namespace
