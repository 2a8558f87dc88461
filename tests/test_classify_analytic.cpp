// The direct placement test on scenes whose answer is known in closed form: discs and
// squares in openings and against blocks, exact fits, containment, and the invariances any
// correct test must have (moving the whole scene, swapping the roles of the parts).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "cslice/classify.hpp"
#include "cslice/pair.hpp"

namespace cslice {
namespace {

using nlohmann::json;

// ---- Scene building ----------------------------------------------------------------------

json rect_loop(double x0, double y0, double x1, double y1) {
  return json::array({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}
json circle_loop(double cx, double cy, double r) {
  return {{"circle", {cx, cy, r}}};
}
json part_json(json loops, bool enclosure = false) {
  return {{"loops", std::move(loops)}, {"enclosure", enclosure}};
}

Pair make_pair(const json& moving, const json& fixed, std::optional<double> tolerance) {
  json j = {{"name", "analytic"}, {"units", "mm"}, {"moving", moving}, {"fixed", fixed}};
  if (tolerance) j["tolerance"] = *tolerance;
  LoadResult r = parse_pair(j.dump(), "analytic");
  if (!r.ok()) throw std::runtime_error("test pair rejected: " + r.error->message());
  return std::move(*r.pair);
}

// ---- Expected answers --------------------------------------------------------------------

// Width of the bands around the two thresholds (gap 0 and gap tol.contact) where rounding in
// the scene or the test may tip the answer either way; far wider than tol.geometric and far
// narrower than tol.contact.
double band(const Tolerances& tol) {
  return 1e-6 * tol.size;
}

// The answer for a signed gap between the boundaries (negative: the interiors overlap by
// that depth), or nothing when the gap is too close to a threshold to be decisive.
std::optional<Placement> expected_for_gap(double gap, const Tolerances& tol) {
  const double m = band(tol);
  if (gap < -m) return Placement::blocked;
  if (gap > tol.contact + m) return Placement::free;
  if (gap > m && gap < tol.contact - m) return Placement::contact;
  return std::nullopt;
}

// Checks the tester against a closed-form gap at `count` random poses in a box; also checks
// that every answer class came up, so a scene cannot pass by missing the interesting region.
template <class GapFn>
void check_against_gap(const Pair& pair, Box poses, int count, GapFn gap_of, unsigned seed) {
  PlacementTester tester(pair);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(poses.lo.x, poses.hi.x), uy(poses.lo.y, poses.hi.y);
  std::uniform_real_distribution<double> ut(-kPi, kPi);
  std::array<int, 3> seen{};
  for (int i = 0; i < count; ++i) {
    const Pose pose{ux(rng), uy(rng), ut(rng)};
    const double gap = gap_of(pose);
    const auto expected = expected_for_gap(gap, pair.tol);
    if (!expected) continue;
    ++seen[static_cast<int>(*expected)];
    ASSERT_EQ(to_string(tester.classify(pose)), to_string(*expected))
        << "pose " << pose.x << "," << pose.y << "," << pose.theta << " gap " << gap;
  }
  EXPECT_GT(seen[0], 0) << "no free pose sampled";
  EXPECT_GT(seen[2], 0) << "no blocked pose sampled";
}

// Poses drawn by `pose_of(u, v, w)` from three uniform numbers in [0, 1), meant to land on
// the thin band around contact that a uniform sample of the plane would rarely hit.
template <class PoseFn, class GapFn>
void check_near_contact(const Pair& pair, int count, PoseFn pose_of, GapFn gap_of, unsigned seed) {
  PlacementTester tester(pair);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int contacts = 0;
  for (int i = 0; i < count; ++i) {
    const double a = u(rng), b = u(rng), c = u(rng);
    const Pose pose = pose_of(a, b, c);
    const double gap = gap_of(pose);
    if (expected_for_gap(gap, pair.tol) != Placement::contact) continue;
    ++contacts;
    ASSERT_EQ(to_string(tester.classify(pose)), "contact")
        << "pose " << pose.x << "," << pose.y << "," << pose.theta << " gap " << gap;
  }
  EXPECT_GT(contacts, count / 2);
}

double angle_of(double unit) {
  return -kPi + kTwoPi * unit;
}

Box box_of(double x0, double y0, double x1, double y1) {
  return Box{{x0, y0}, {x1, y1}};
}

// ---- Disc in a square opening ------------------------------------------------------------

constexpr double kHalfSide = 10.0;
constexpr double kDiscRadius = 3.0;
constexpr double kSceneTol = 0.01;

Pair disc_in_square_opening() {
  return make_pair(part_json({circle_loop(0, 0, kDiscRadius)}),
                   part_json({rect_loop(-kHalfSide, -kHalfSide, kHalfSide, kHalfSide)}, true),
                   kSceneTol);
}

// Inside the opening, the nearest wall is the one the centre is closest to.
double disc_in_square_gap(const Pose& p) {
  return kHalfSide - kDiscRadius - std::max(std::fabs(p.x), std::fabs(p.y));
}

TEST(ClassifyAnalytic, DiscInSquareOpeningRandom) {
  const Pair pair = disc_in_square_opening();
  // Out to where the disc is wholly outside the opening, inside the enclosure's material.
  const double reach = 1.5 * (kHalfSide + kDiscRadius);
  check_against_gap(pair, box_of(-reach, -reach, reach, reach), 20000, disc_in_square_gap, 1);
}

TEST(ClassifyAnalytic, DiscInSquareOpeningContactSquare) {
  const Pair pair = disc_in_square_opening();
  PlacementTester tester(pair);
  const double c = kHalfSide - kDiscRadius;  // half-side of the contact square
  const double t = pair.tol.contact;
  for (int i = 0; i <= 40; ++i) {
    const double along = -c + 2.0 * c * i / 40.0;
    const double theta = -kPi + kTwoPi * i / 40.0;  // the disc is rotation invariant
    for (const Pose& p : {Pose{c, along, theta}, Pose{-c, along, theta}, Pose{along, c, theta},
                          Pose{along, -c, theta}}) {
      EXPECT_EQ(to_string(tester.classify(p)), "contact") << p.x << "," << p.y;
      // Half a tolerance inwards is still contact; half a tolerance outwards overlaps.
      const Vec2 out =
          normalized(Vec2{std::fabs(p.x) == c ? p.x : 0, std::fabs(p.y) == c ? p.y : 0});
      const Pose in{p.x - 0.5 * t * out.x, p.y - 0.5 * t * out.y, theta};
      const Pose over{p.x + 0.5 * t * out.x, p.y + 0.5 * t * out.y, theta};
      EXPECT_EQ(to_string(tester.classify(in)), "contact") << in.x << "," << in.y;
      EXPECT_EQ(to_string(tester.classify(over)), "blocked") << over.x << "," << over.y;
    }
  }
}

TEST(ClassifyAnalytic, DiscInSquareOpeningBoundaryDistance) {
  const Pair pair = disc_in_square_opening();
  PlacementTester tester(pair);
  std::mt19937_64 rng(2);
  const double c = kHalfSide - kDiscRadius;
  std::uniform_real_distribution<double> u(-c, c), ut(-kPi, kPi);
  for (int i = 0; i < 2000; ++i) {
    const Pose p{u(rng), u(rng), ut(rng)};
    EXPECT_NEAR(tester.boundary_distance(p), disc_in_square_gap(p), band(pair.tol));
  }
}

TEST(ClassifyAnalytic, DiscInSquareOpeningNearContact) {
  const Pair pair = disc_in_square_opening();
  // Centres within a tolerance inside the contact square, on its right side.
  const double c = kHalfSide - kDiscRadius, t = pair.tol.contact;
  const auto pose_of = [&](double u, double v, double w) {
    return Pose{c - u * t, -c + 2 * c * v, angle_of(w)};
  };
  check_near_contact(pair, 4000, pose_of, disc_in_square_gap, 3);
}

// ---- Disc against a rectangular block ------------------------------------------------------

double distance_to_rect(Vec2 p, double x0, double y0, double x1, double y1) {
  const double dx = std::max({x0 - p.x, 0.0, p.x - x1});
  const double dy = std::max({y0 - p.y, 0.0, p.y - y1});
  return std::hypot(dx, dy);
}

TEST(ClassifyAnalytic, DiscAgainstBlock) {
  const double r = 1.0;
  const Pair pair =
      make_pair(part_json({circle_loop(0, 0, r)}), part_json({rect_loop(0, 0, 4, 2)}), kSceneTol);
  const auto gap = [&](const Pose& p) {
    // A centre inside the block overlaps by at least r.
    const double d = distance_to_rect({p.x, p.y}, 0, 0, 4, 2);
    return d > 0.0 ? d - r : -r;
  };
  check_against_gap(pair, box_of(-2.5, -2.5, 6.5, 4.5), 20000, gap, 4);
  const double t = pair.tol.contact;
  const auto left_face = [&](double u, double v, double w) {
    return Pose{-r - u * t, -1 + 4 * v, angle_of(w)};
  };
  const auto corner = [&](double u, double v, double w) {  // the rounded corner at (4, 2)
    const Vec2 c = Vec2{4, 2} + (r + u * t) * unit_vector(v * kPi / 2);
    return Pose{c.x, c.y, angle_of(w)};
  };
  check_near_contact(pair, 2000, left_face, gap, 5);
  check_near_contact(pair, 4000, corner, gap, 6);
}

// ---- Discs against discs: arc to arc --------------------------------------------------------

TEST(ClassifyAnalytic, DiscAgainstDisc) {
  const double r = 1.0, big = 2.5;
  const Pair pair =
      make_pair(part_json({circle_loop(0, 0, r)}), part_json({circle_loop(1, -1, big)}), kSceneTol);
  const auto gap = [&](const Pose& p) { return std::hypot(p.x - 1, p.y + 1) - r - big; };
  check_against_gap(pair, box_of(-4, -6, 6, 4), 20000, gap, 12);
  const auto around = [&](double u, double v, double w) {
    const Vec2 c = Vec2{1, -1} + (r + big + u * pair.tol.contact) * unit_vector(angle_of(v));
    return Pose{c.x, c.y, angle_of(w)};
  };
  check_near_contact(pair, 4000, around, gap, 13);
}

TEST(ClassifyAnalytic, DiscInRoundHole) {
  // The hole's centre is off the plate's, so no symmetry hides a wrong sign.
  const double r = 1.0, hole = 1.75;
  const Pair pair =
      make_pair(part_json({circle_loop(0, 0, r)}),
                part_json({rect_loop(-4, -4, 4, 4), circle_loop(0.5, 0.25, hole)}), kSceneTol);
  // Outside the hole the disc overlaps the plate; inside, the gap is to the hole's rim.
  const auto gap = [&](const Pose& p) { return hole - r - std::hypot(p.x - 0.5, p.y - 0.25); };
  check_against_gap(pair, box_of(-1.5, -1.75, 2.5, 2.25), 20000, gap, 14);
  const auto inside = [&](double u, double v, double w) {
    const Vec2 c = Vec2{0.5, 0.25} + (hole - r - u * pair.tol.contact) * unit_vector(angle_of(v));
    return Pose{c.x, c.y, angle_of(w)};
  };
  check_near_contact(pair, 4000, inside, gap, 15);
}

// ---- Square peg in a square hole -----------------------------------------------------------

TEST(ClassifyAnalytic, SquarePegInSquareHole) {
  const double a = 2.0, b = 3.0;
  const Pair pair = make_pair(part_json({rect_loop(-a / 2, -a / 2, a / 2, a / 2)}),
                              part_json({rect_loop(-b / 2, -b / 2, b / 2, b / 2)}, true), 0.005);
  // The rotated peg reaches a/2 (|cos| + |sin|) along both axes.
  const auto gap = [&](const Pose& p) {
    const double h = a / 2 * (std::fabs(std::cos(p.theta)) + std::fabs(std::sin(p.theta)));
    return b / 2 - h - std::max(std::fabs(p.x), std::fabs(p.y));
  };
  check_against_gap(pair, box_of(-0.8, -0.8, 0.8, 0.8), 20000, gap, 7);
  // Against the right wall, a fraction of a tolerance away.
  const auto pose_of = [&](double u, double v, double w) {
    const double theta = angle_of(w);
    const double h = a / 2 * (std::fabs(std::cos(theta)) + std::fabs(std::sin(theta)));
    const double x = b / 2 - h - u * pair.tol.contact;
    return Pose{x, (v - 0.5) * x, theta};
  };
  check_near_contact(pair, 4000, pose_of, gap, 8);
}

// ---- Two unit squares ---------------------------------------------------------------------

Pair two_unit_squares() {
  return make_pair(part_json({rect_loop(0, 0, 1, 1)}), part_json({rect_loop(0, 0, 1, 1)}),
                   std::nullopt);
}

TEST(ClassifyAnalytic, SquaresEdgeToEdge) {
  const Pair pair = two_unit_squares();
  const double size = pair.tol.size, tol = pair.tol.contact;
  for (double y : {-0.75, -0.3, 0.0, 0.5, 0.99}) {
    EXPECT_EQ(to_string(classify(pair, {1.0, y, 0.0})), "contact") << y;
    EXPECT_EQ(to_string(classify(pair, {-1.0, y, 0.0})), "contact") << y;
    EXPECT_EQ(to_string(classify(pair, {y, 1.0, 0.0})), "contact") << y;
    EXPECT_EQ(to_string(classify(pair, {1.0 - 1e-3 * size, y, 0.0})), "blocked") << y;
    EXPECT_EQ(to_string(classify(pair, {1.0 + 2 * tol, y, 0.0})), "free") << y;
    EXPECT_EQ(to_string(classify(pair, {1.0 + 0.5 * tol, y, 0.0})), "contact") << y;
  }
  // Sliding contact turned half a turn about the shared edge's midpoint: still edge to edge.
  EXPECT_EQ(to_string(classify(pair, {2.0, 1.0, kPi})), "contact");
}

TEST(ClassifyAnalytic, SquaresCoincident) {
  const Pair pair = two_unit_squares();
  EXPECT_EQ(to_string(classify(pair, {0, 0, 0})), "blocked");
  // Same region traversed from another corner.
  EXPECT_EQ(to_string(classify(pair, {1, 1, kPi})), "blocked");
  EXPECT_EQ(to_string(classify(pair, {1, 0, kPi / 2})), "blocked");
}

TEST(ClassifyAnalytic, SquaresVertexToVertex) {
  const Pair pair = two_unit_squares();
  const double tol = pair.tol.contact;
  EXPECT_EQ(to_string(classify(pair, {1, 1, 0})), "contact");
  EXPECT_EQ(to_string(classify(pair, {-1, -1, 0})), "contact");
  EXPECT_EQ(to_string(classify(pair, {1, -1, 0})), "contact");
  EXPECT_EQ(to_string(classify(pair, {1 + 2 * tol, 1 + 2 * tol, 0})), "free");
  // Turned by 45 degrees the moving square stands on its corner at (1, 1), entirely above
  // y = 1: only the two corners meet.
  EXPECT_EQ(to_string(classify(pair, {1, 1, kPi / 4})), "contact");
  EXPECT_EQ(to_string(classify(pair, {1, 1 + 2 * tol, kPi / 4})), "free");
  EXPECT_EQ(to_string(classify(pair, {1, 1 - 0.01, kPi / 4})), "blocked");
}

// ---- Exact fit, containment, clearance ------------------------------------------------------

TEST(ClassifyAnalytic, PinExactlyFillingHole) {
  const double r = 1.0;
  const Pair pair =
      make_pair(part_json({circle_loop(0, 0, r)}),
                part_json({rect_loop(-3, -3, 3, 3), circle_loop(0, 0, r)}), std::nullopt);
  const double size = pair.tol.size;
  for (double theta : {-3.0, -1.0, 0.0, 0.5, 2.0, kPi / 3}) {
    EXPECT_EQ(to_string(classify(pair, {0, 0, theta})), "contact") << theta;
    EXPECT_EQ(to_string(classify(pair, {1e-3 * size, 0, theta})), "blocked") << theta;
    EXPECT_EQ(to_string(classify(pair, {0, -1e-3 * size, theta})), "blocked") << theta;
    EXPECT_EQ(to_string(classify(pair, {0.5, 0.5, theta})), "blocked") << theta;
  }
}

// A pin in a slot of exactly its width, the slot turned by an arbitrary angle: every place
// along the slot's straight part touches both sides (a sliding fit), nothing is blocked. The
// pin's far point reaches the centre of the slot's rounded end when the pin is at the
// middle, on that half circle's chord, which the containment test put outside the opening
// (designed stress pair 33).
TEST(ClassifyAnalytic, PinSlidesAlongATurnedSlotOfItsWidth) {
  int contacts = 0;
  for (int k = 0; k < 60; ++k) {
    const double turn = 0.1047 * k + 0.0123, c = std::cos(turn), s = std::sin(turn);
    const auto at = [&](double u, double v) {
      return std::array<double, 2>{c * u - s * v, s * u + c * v};
    };
    const auto p0 = at(-0.5, -0.5), p1 = at(0.5, -0.5), p2 = at(0.5, 0.5), p3 = at(-0.5, 0.5);
    const json slot =
        json::array({{p0[0], p0[1]}, {p1[0], p1[1], 1.0}, {p2[0], p2[1]}, {p3[0], p3[1], 1.0}});
    const Pair pair =
        make_pair(part_json({circle_loop(-0.25, 0, 0.5)}), part_json({slot}, true), std::nullopt);
    for (const double theta : {0.0, 1.5707963267948966, 1.1938052083641217, -2.5}) {
      // The pin's centre, at body (-0.25, 0), turned by theta: placed on the slot's axis.
      const double cx = -0.25 * std::cos(theta), cy = -0.25 * std::sin(theta);
      for (const double along : {-0.5, -0.2, 0.0, 0.3, 0.5}) {
        const auto q = at(along, 0.0);
        EXPECT_EQ(to_string(classify(pair, {q[0] - cx, q[1] - cy, theta})), "contact")
            << turn << " " << theta << " " << along;
        ++contacts;
      }
      const auto off = at(0.0, 1e-3);
      EXPECT_EQ(to_string(classify(pair, {off[0] - cx, off[1] - cy, theta})), "blocked");
    }
  }
  EXPECT_EQ(contacts, 60 * 4 * 5);
}

TEST(ClassifyAnalytic, ContainmentWithoutBoundaryContactIsBlocked) {
  const json small = part_json({rect_loop(-0.5, -0.5, 0.5, 0.5)});
  const json big = part_json({rect_loop(-5, -5, 5, 5)});
  const Pair small_in_big = make_pair(small, big, std::nullopt);
  const Pair big_around_small = make_pair(big, small, std::nullopt);
  for (double theta : {0.0, 0.3, 1.2, -2.5}) {
    EXPECT_EQ(to_string(classify(small_in_big, {1, -2, theta})), "blocked") << theta;
    EXPECT_EQ(to_string(classify(big_around_small, {0.5, 1, theta})), "blocked") << theta;
  }
  // A disc inside a disc: no vertices to meet at all.
  const Pair discs = make_pair(part_json({circle_loop(0, 0, 0.5)}),
                               part_json({circle_loop(0, 0, 4)}), std::nullopt);
  EXPECT_EQ(to_string(classify(discs, {1, 1, 0.7})), "blocked");
}

TEST(ClassifyAnalytic, PartInsideHoleWithClearanceIsFree) {
  const json plate = part_json({rect_loop(-5, -5, 5, 5), rect_loop(-2, -2, 2, 2)});
  const Pair disc = make_pair(part_json({circle_loop(0, 0, 1)}), plate, std::nullopt);
  const Pair square = make_pair(part_json({rect_loop(-1, -1, 1, 1)}), plate, std::nullopt);
  for (double theta : {0.0, 0.3, 1.2, -2.5}) {
    EXPECT_EQ(to_string(classify(disc, {0, 0, theta})), "free") << theta;
    EXPECT_EQ(to_string(classify(disc, {0.5, -0.5, theta})), "free") << theta;
    EXPECT_EQ(to_string(classify(square, {0, 0, theta})), "free") << theta;
    // Far out on the plate's material, and beyond the plate altogether.
    EXPECT_EQ(to_string(classify(disc, {3.5, 0, theta})), "blocked") << theta;
    EXPECT_EQ(to_string(classify(disc, {8, 0, theta})), "free") << theta;
  }
}

// A case the CGAL oracle once caught answering blocked (with a library build of the same
// day): a heptagon lying flush against a wall of a quadrilateral opening, every other vertex
// well inside. Pushed along the wall's normal it must stay contact inwards and block outwards.
TEST(ClassifyAnalytic, FlushEdgeInsideEnclosure) {
  const json fixed = part_json({json::array({{-3.4383717269740584, -1.3999486305586382},
                                             {1.4113096771049953, -2.9655846978425786},
                                             {3.863837662974458, -0.14418132849222207},
                                             {-2.244893976523376, 3.824600587035328}})},
                               true);
  const json moving = part_json({json::array({{-0.11059555135212039, 1.7338745311072588},
                                              {-1.022457077641716, 1.4364994923332106},
                                              {-1.738878437445595, -0.3439820114598555},
                                              {-0.6536222048687831, -1.210443279517087},
                                              {0.5239045837202356, -0.9022631703051741},
                                              {1.8891447285672403, 0.3040880040791325},
                                              {0.982848880403305, 1.8432058708629997}})});
  const Pair pair = make_pair(moving, fixed, std::nullopt);
  const Pose flush{1.6275098878981353, -1.1574773209109073, 0.13153723126625383};
  // Inward unit normal of the wall from (1.41, -2.97) to (3.86, -0.14), on the opening's side.
  const Vec2 wall =
      Vec2{3.863837662974458, -0.14418132849222207} - Vec2{1.4113096771049953, -2.9655846978425786};
  const Vec2 in = normalized(perp_left(wall));
  const auto shifted = [&](double d) {
    return Pose{flush.x + d * in.x, flush.y + d * in.y, flush.theta};
  };
  const double size = pair.tol.size, tol = pair.tol.contact;
  EXPECT_EQ(to_string(classify(pair, flush)), "contact");
  EXPECT_EQ(to_string(classify(pair, shifted(1e-12 * size))), "contact");
  EXPECT_EQ(to_string(classify(pair, shifted(0.5 * tol))), "contact");
  EXPECT_EQ(to_string(classify(pair, shifted(-1e-6 * size))), "blocked");
}

// ---- Invariances ----------------------------------------------------------------------------

// A moving part with convex and concave arcs and a hole, and a fixed plate with a round and a
// curved hole and an arc on its outline: every kind of feature pair gets exercised.
json curvy_moving() {
  return part_json(
      {json::array({{0, 0, 0.3}, {2, 0, 0}, {2, 1, -0.2}, {0, 1, 0}}), circle_loop(0.6, 0.5, 0.2)});
}
json curvy_fixed() {
  return part_json(
      {json::array({{-5, -4}, {5, -4, 0.25}, {5, 4}, {-5, 4}}), circle_loop(-2, 1, 1.5),
       json::array({{0.5, -2.5, 0}, {1.0, 1.5, -0.4}, {3.5, 1.5, 0}, {3.0, -2.5, 0.3}})});
}

// The part turned half a turn about the origin (which negates coordinates exactly) and then
// shifted; bulges are unchanged by rotation.
json half_turned_and_shifted(json part, Vec2 shift) {
  const auto move = [&](json& xy) {
    xy[0] = -xy[0].get<double>() + shift.x;
    xy[1] = -xy[1].get<double>() + shift.y;
  };
  for (json& loop : part["loops"]) {
    if (loop.is_object()) {
      move(loop["circle"]);
      continue;
    }
    for (json& v : loop) move(v);
  }
  return part;
}

// True when the pose is too close to a threshold for two differently rounded scenes to agree.
bool near_threshold(PlacementTester& tester, const Pose& pose, const Tolerances& tol) {
  const double d = tester.boundary_distance(pose);
  return d < band(tol) || std::fabs(d - tol.contact) < band(tol);
}

TEST(ClassifyAnalytic, RigidMotionOfTheSceneChangesNothing) {
  const Pair pair = make_pair(curvy_moving(), curvy_fixed(), 0.01);
  const Vec2 shift{0.75, -1.5};
  const Pair moved = make_pair(curvy_moving(), half_turned_and_shifted(curvy_fixed(), shift), 0.01);
  PlacementTester a(pair), b(moved);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> ux(-6, 6), uy(-5, 5), ut(-kPi, kPi);
  std::array<int, 3> seen{};
  for (int i = 0; i < 20000; ++i) {
    const Pose p{ux(rng), uy(rng), ut(rng)};
    if (near_threshold(a, p, pair.tol)) continue;
    const Pose q{-p.x + shift.x, -p.y + shift.y, p.theta + kPi};
    const Placement pa = a.classify(p);
    ++seen[static_cast<int>(pa)];
    ASSERT_EQ(to_string(pa), to_string(b.classify(q))) << p.x << "," << p.y << "," << p.theta;
  }
  EXPECT_GT(seen[0], 0);
  EXPECT_GT(seen[1], 0);
  EXPECT_GT(seen[2], 0);
}

TEST(ClassifyAnalytic, SwappingRolesChangesNothing) {
  // The fixed plate is not an enclosure, so it can move too.
  const Pair pair = make_pair(curvy_moving(), curvy_fixed(), 0.01);
  const Pair swapped = make_pair(curvy_fixed(), curvy_moving(), 0.01);
  PlacementTester a(pair), b(swapped);
  std::mt19937_64 rng(10);
  std::uniform_real_distribution<double> ux(-6, 6), uy(-5, 5), ut(-kPi, kPi);
  std::array<int, 3> seen{};
  for (int i = 0; i < 20000; ++i) {
    const Pose p{ux(rng), uy(rng), ut(rng)};
    if (near_threshold(a, p, pair.tol)) continue;
    // The inverse of x -> R(theta) x + t is x -> R(-theta) x - R(-theta) t.
    const Vec2 back = Transform(Pose{0, 0, -p.theta}).rotate({p.x, p.y});
    const Pose inverse{-back.x, -back.y, -p.theta};
    const Placement pa = a.classify(p);
    ++seen[static_cast<int>(pa)];
    ASSERT_EQ(to_string(pa), to_string(b.classify(inverse))) << p.x << "," << p.y << "," << p.theta;
  }
  EXPECT_GT(seen[0], 0);
  EXPECT_GT(seen[1], 0);
  EXPECT_GT(seen[2], 0);
}

TEST(ClassifyAnalytic, FreeFunctionAgreesWithTester) {
  const Pair pair = make_pair(curvy_moving(), curvy_fixed(), 0.01);
  PlacementTester tester(pair);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ux(-6, 6), uy(-5, 5), ut(-kPi, kPi);
  for (int i = 0; i < 2000; ++i) {
    const Pose p{ux(rng), uy(rng), ut(rng)};
    ASSERT_EQ(to_string(classify(pair, p)), to_string(tester.classify(p)));
  }
}

TEST(ClassifyAnalytic, PlacementNames) {
  EXPECT_EQ(to_string(Placement::free), "free");
  EXPECT_EQ(to_string(Placement::contact), "contact");
  EXPECT_EQ(to_string(Placement::blocked), "blocked");
}

}  // namespace
}  // namespace cslice
