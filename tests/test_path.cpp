// Paths (PathPlanner, include/cslice/path.hpp) checked against the direct placement test: on
// the bundled examples and random curved pairs, random free start and goal configurations
// that the point query puts in one 3D free component get a path; every configuration of it
// is free by `classify`, the clearance certificate holds for every step (recomputed here),
// and the straight motion of every step is free by `classify` at 50 samples. Ends in
// different components, or not free, get the status that says so.
#include "cslice/path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cslice/classify.hpp"
#include "cslice/query.hpp"
#include "cslice/space.hpp"
#include "path/certify.hpp"
#include "support/examples.hpp"
#include "support/free_poses.hpp"
#include "support/random_parts.hpp"
#include "support/spaces.hpp"

using namespace cslice;
using testkit::space_of;

namespace {

// Interpolation as the path's reader does it: x and y linearly, theta the short way round.
Pose between(const Pose& a, const Pose& b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y),
          a.theta + t * wrap_angle(b.theta - a.theta)};
}

bool same_pose(const Pose& a, const Pose& b) {
  return std::fabs(a.x - b.x) < 1e-12 && std::fabs(a.y - b.y) < 1e-12 &&
         std::fabs(wrap_angle(a.theta - b.theta)) < 1e-12;
}

struct Checked {
  int paths = 0, steps = 0, samples = 0;
  int crossed = 0;  // paths that crossed a critical orientation through the topology
  int not_found = 0;
  int no_free_pose = 0;  // queries skipped: random_free_pose found no end
};

constexpr int kSamplesPerStep = 50;

// Everything a found path promises, checked independently of the planner.
void expect_valid_path(const Pair& pair, const PathResult& r, const Pose& from, const Pose& to,
                       const std::string& name, Checked& checked) {
  ASSERT_EQ(r.status, PathStatus::found) << name << ": " << r.problem;
  ASSERT_GE(r.poses.size(), 2u) << name;
  ASSERT_EQ(r.poses.size(), r.clearance.size()) << name;
  EXPECT_TRUE(same_pose(r.poses.front(), from)) << name;
  EXPECT_TRUE(same_pose(r.poses.back(), to)) << name;
  EXPECT_NEAR(r.reach, moving_reach(pair.moving), 1e-12) << name;
  PlacementTester tester(pair);
  const double c = pair.tol.contact;
  int bad_poses = 0, bad_certificates = 0, bad_samples = 0;
  for (size_t i = 0; i < r.poses.size(); ++i) {
    const Pose& p = r.poses[i];
    ASSERT_GE(p.theta, -kPi) << name;
    ASSERT_LT(p.theta, kPi) << name;
    if (tester.classify(p) != Placement::free && ++bad_poses <= 3)
      ADD_FAILURE() << name << ": pose " << i << " (" << p.x << ", " << p.y << ", " << p.theta
                    << ") is not free";
    // The reported clearance is the true one (up to round-off of the end's exact theta).
    EXPECT_NEAR(r.clearance[i], tester.boundary_distance(p), 1e-9 * pair.tol.size) << name;
    if (i == 0) continue;
    const Pose& q = r.poses[i - 1];
    const double sweep = step_sweep(moving_reach(pair.moving), q, p);
    if (!(r.clearance[i - 1] + r.clearance[i] - sweep > 2.0 * c) && ++bad_certificates <= 3)
      ADD_FAILURE() << name << ": step " << i << " is not certified: clearances "
                    << r.clearance[i - 1] << " + " << r.clearance[i] << ", sweep " << sweep;
    for (int k = 1; k < kSamplesPerStep; ++k) {
      const Pose s = between(q, p, static_cast<double>(k) / kSamplesPerStep);
      ++checked.samples;
      if (tester.classify(s) != Placement::free && ++bad_samples <= 3)
        ADD_FAILURE() << name << ": step " << i << " passes (" << s.x << ", " << s.y << ", "
                      << s.theta << "), not free";
    }
  }
  EXPECT_EQ(bad_poses, 0) << name;
  EXPECT_EQ(bad_certificates, 0) << name;
  EXPECT_EQ(bad_samples, 0) << name;
  checked.paths += 1;
  checked.steps += static_cast<int>(r.poses.size()) - 1;
  checked.crossed += r.stats.critical_crossings > 0 ? 1 : 0;
}

// Random queries: a path whenever the point query puts both ends in one component, the
// status different_components otherwise.
Checked random_queries(const Pair& pair, const SlicedSpace& space, int queries, unsigned seed,
                       const std::string& name, bool must_find = true) {
  std::mt19937 rng(seed);
  SpaceQuery query(pair, space);
  PathPlanner planner(pair, space);
  Checked checked;
  int different = 0;
  for (int i = 0; i < queries; ++i) {
    const std::optional<Pose> pa = testkit::random_free_pose(pair, rng),
                              pb = testkit::random_free_pose(pair, rng);
    if (!pa || !pb) {
      ++checked.no_free_pose;
      continue;
    }
    const Pose a = *pa, b = *pb;
    const QueryAnswer qa = query.query(a), qb = query.query(b);
    if (qa.placement != Placement::free || qb.placement != Placement::free) continue;
    const PathResult r = planner.plan(a, b);
    const std::string what = name + " query " + std::to_string(i) + " from (" +
                             std::to_string(a.x) + ", " + std::to_string(a.y) + ", " +
                             std::to_string(a.theta) + ") to (" + std::to_string(b.x) + ", " +
                             std::to_string(b.y) + ", " + std::to_string(b.theta) + ")";
    if (qa.component != qb.component) {
      EXPECT_EQ(r.status, PathStatus::different_components) << what;
      EXPECT_EQ(r.start.component, qa.component) << what;
      EXPECT_EQ(r.goal.component, qb.component) << what;
      ++different;
      continue;
    }
    if (!must_find && r.status == PathStatus::not_found) {
      ++checked.not_found;
      continue;
    }
    expect_valid_path(pair, r, a, b, what, checked);
    EXPECT_EQ(r.component, qa.component) << what;
  }
  std::cout << name << ": " << checked.paths << " paths (" << checked.crossed
            << " through critical orientations), " << checked.steps << " steps, " << checked.samples
            << " motion samples checked; " << different << " in different components; "
            << checked.not_found << " not found; " << checked.no_free_pose
            << " without a free pose\n";
  return checked;
}

}  // namespace

TEST(PathCertificate, SweepBoundsEveryPointsMotion) {
  // The bound |dp| + R |dtheta| against the true largest displacement of the moving part's
  // vertices and arc points along random straight motions.
  const Pair pair = testkit::load_example("knee");
  const double reach = moving_reach(pair.moving);
  EXPECT_GT(reach, 0.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const Pose a{u(rng), u(rng), 3 * u(rng)}, b{u(rng), u(rng), 3 * u(rng)};
    const double sweep = step_sweep(reach, a, b);
    for (const Loop& loop : pair.moving.loops)
      for (const Curve& c : loop.edges)
        for (double s : {0.0, 0.3, 0.7}) {
          const Vec2 q = point_at(c, s);
          EXPECT_LE(length(q), reach + 1e-12);
          const Vec2 start = Transform(a).apply(q);
          for (double t : {0.25, 0.5, 1.0})
            EXPECT_LE(distance(Transform(between(a, b, t)).apply(q), start), sweep + 1e-9);
        }
  }
}

TEST(PathCertificate, FarthestDistanceOfRandomArcsAndSegments) {
  // Against dense sampling: never below a sampled point, and no further above the farthest
  // sample than the sampling's spacing allows.
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-2.0, 2.0), sweep(-6.2, 6.2);
  for (int i = 0; i < 300; ++i) {
    const Curve c = i % 3 == 0
                        ? make_segment({u(rng), u(rng)}, {u(rng), u(rng)})
                        : make_arc({u(rng), u(rng)}, 0.1 + std::fabs(u(rng)), u(rng), sweep(rng));
    const Vec2 p{u(rng), u(rng)};
    const double far = farthest_distance(c, p);
    double sampled = 0.0;
    for (int k = 0; k <= 2000; ++k)
      sampled = std::max(sampled, distance(p, point_at(c, k / 2000.0)));
    EXPECT_GE(far, sampled - 1e-12);
    EXPECT_LE(far, sampled + curve_length(c) / 2000.0 + 1e-12);
  }
}

TEST(PathCertificate, ReachIsTheFarthestPoint) {
  // The cam's farthest point from its shaft is the top arc's (radius 6.25 about the origin).
  EXPECT_NEAR(moving_reach(testkit::load_example("cam").moving), 6.25, 1e-12);
  // The disc (radius 1 about its origin).
  EXPECT_NEAR(moving_reach(testkit::load_example("disc-in-box").moving), 1.0, 1e-12);
}

TEST(Path, CamFollowsTheSpiralChannel) {
  // The cam's free space is one 0.2-wide square per slice, turning with the cam: the path
  // has to follow the channel a long way round.
  const Pair pair = testkit::load_example("cam");
  const SlicedSpace space = space_of(pair);
  Checked checked;
  const Pose from{0.0, -1.25, 0.0}, to{1.25, -1.2335, 1.0};
  expect_valid_path(pair, find_path(pair, space, from, to), from, to, "cam 0 to 1", checked);
  // The channel's centre at theta = -3: the sample of the slice's one free component.
  const Slice at_minus_3 = compute_slice(pair, -3.0);
  ASSERT_EQ(at_minus_3.free_components.size(), 1u);
  const Vec2 centre = at_minus_3.free_components[0].sample;
  const Pose back{centre.x, centre.y, -3.0};
  expect_valid_path(pair, find_path(pair, space, to, back), to, back, "cam 1 to -3", checked);
}

TEST(Path, FastenerPinGoesInThroughTheSlot) {
  // Outside, pin horizontal, to inside the cavity, pin horizontal: the two are one
  // component only through the slot, with the pin near vertical.
  const Pair pair = testkit::load_example("fastener");
  const SlicedSpace space = space_of(pair);
  Checked checked;
  const Pose out{0.0, 6.0, 0.0}, in{0.0, -3.0, 0.0};
  const PathResult r = find_path(pair, space, out, in);
  expect_valid_path(pair, r, out, in, "fastener out to in", checked);
  EXPECT_GT(r.stats.critical_crossings, 0);
  // Halfway down the slot the pin is near vertical.
  bool vertical_in_slot = false;
  for (const Pose& p : r.poses)
    if (std::fabs(p.y - 0.75) < 0.5 && std::fabs(std::fabs(p.theta) - kPi / 2) < 0.4)
      vertical_in_slot = true;
  EXPECT_TRUE(vertical_in_slot);
}

// The path's ends are the configurations asked for, bit for bit: wrapping 0.3 into [-pi, pi)
// by way of pi gave 0.2999999999999998.
TEST(Path, EndsAreTheConfigurationsAskedFor) {
  const Pair pair = testkit::load_example("fastener");
  const SlicedSpace space = space_of(pair);
  const Pose out{0.1, 6.0, 0.3}, in{0.0, -3.0, -0.1};
  const PathResult r = find_path(pair, space, out, in);
  ASSERT_EQ(r.status, PathStatus::found) << r.problem;
  EXPECT_EQ(r.poses.front().theta, out.theta);
  EXPECT_EQ(r.poses.back().theta, in.theta);
  EXPECT_EQ(r.poses.back().x, in.x);
  for (const Pose& p : r.poses) {
    EXPECT_GE(p.theta, -kPi);
    EXPECT_LT(p.theta, kPi);
  }
}

// A start at a far orientation is the same placement as its principal angle, and gets the path
// planned from there: the carries add their steps to the start's theta, and at 1e15 rad
// those sums were rounded to an eighth of a radian (no path was found).
TEST(Path, AFarStartOrientationPlansFromItsPrincipalAngle) {
  const Pair pair = testkit::load_example("fastener");
  const SlicedSpace space = space_of(pair);
  PathPlanner planner(pair, space);
  const double far = 1e15, wrapped = std::atan2(std::sin(far), std::cos(far));
  const Pose out{0.0, 6.0, wrapped}, in{0.0, -3.0, 0.0};
  const PathResult r = planner.plan({out.x, out.y, far}, in);
  Checked checked;
  expect_valid_path(pair, r, out, in, "fastener from 1e15 rad", checked);
  EXPECT_EQ(r.poses.size(), planner.plan(out, in).poses.size());
}

// A step's certificate allows for the round-off of the magnitudes in play. From a start at
// x = 1e300 the clearance and the sweep to a goal behind the fastener's wall are the same
// double, and the bare test certified the straight motion through the wall; the planner
// returned that one step as the path.
TEST(PathCertificate, AStepFromFarOutIsNotCertifiedThroughAWall) {
  const Pair pair = testkit::load_example("fastener");
  path_detail::Certifier cert(pair, 1000);
  const Pose far_out{1e300, -3.0, 0.0}, in{0.0, -3.0, 0.0};
  const std::optional<path_detail::Waypoint> a = cert.evaluate(far_out), b = cert.evaluate(in);
  ASSERT_TRUE(a && b);
  EXPECT_FALSE(cert.step_ok(*a, *b));
  const PathResult r = find_path(pair, space_of(pair), far_out, in);
  EXPECT_TRUE(r.status != PathStatus::found || r.poses.size() > 2) << r.poses.size();
}

TEST(Path, SquarePegInsideAndOutsideAreDifferentComponents) {
  const Pair pair = testkit::load_example("square-peg-hole");
  const SlicedSpace space = space_of(pair);
  ASSERT_EQ(space.topology.components.size(), 2u);
  PathPlanner planner(pair, space);
  const PathResult r = planner.plan({0.0, 0.0, 0.0}, {8.0, 0.0, 0.0});
  EXPECT_EQ(r.status, PathStatus::different_components);
  EXPECT_NE(r.start.component, r.goal.component);
  EXPECT_GE(r.start.component, 0);
  EXPECT_GE(r.goal.component, 0);
  EXPECT_TRUE(r.poses.empty());
  // Inside the hole the peg turns a quarter turn (the free square shrinks to side 0.17).
  Checked checked;
  const Pose a{0.2, 0.1, 0.0}, b{0.0, 0.0, kPi / 4};
  expect_valid_path(pair, planner.plan(a, b), a, b, "peg turns in the hole", checked);
}

TEST(Path, EndsNotFreeSayWhich) {
  const Pair pair = testkit::load_example("square-peg-hole");
  const SlicedSpace space = space_of(pair);
  PathPlanner planner(pair, space);
  // The peg across the hole's edge: blocked.
  const PathResult blocked = planner.plan({1.5, 0.0, 0.0}, {0.0, 0.0, 0.0});
  EXPECT_EQ(blocked.status, PathStatus::start_not_free);
  EXPECT_EQ(blocked.start.placement, Placement::blocked);
  EXPECT_GE(blocked.start.contact.moving_feature, 0);
  // The peg's right side on the hole's right side: contact.
  const PathResult contact = planner.plan({0.0, 0.0, 0.0}, {0.5, 0.0, 0.0});
  EXPECT_EQ(contact.status, PathStatus::goal_not_free);
  EXPECT_EQ(contact.goal.placement, Placement::contact);
  EXPECT_GE(contact.goal.contact.moving_feature, 0);
  EXPECT_GE(contact.goal.contact.fixed_feature, 0);
  EXPECT_EQ(contact.start.placement, Placement::free);
}

TEST(Path, RandomQueriesOnTheExamples) {
  Checked all;
  for (const auto& [name, queries] :
       std::vector<std::pair<const char*, int>>{{"cam", 12},
                                                {"fastener", 24},
                                                {"fixture", 20},
                                                {"knee", 20},
                                                {"square-peg-hole", 20},
                                                {"disc-in-box", 6},
                                                {"disc-half-plane", 6},
                                                {"pin-exact-fit", 6}}) {
    const Pair pair = testkit::load_example(name);
    const SlicedSpace space = space_of(pair);
    const Checked c = random_queries(pair, space, queries, 11, name);
    all.paths += c.paths;
    all.crossed += c.crossed;
  }
  EXPECT_GT(all.paths, 80);
  EXPECT_GT(all.crossed, 20);  // the topology's route, not only straight motions
}

TEST(Path, RandomQueriesOnRandomCurvedPairs) {
  std::mt19937 rng(77);
  Checked all;
  for (int i = 0; i < 12; ++i) {
    const testkit::RandomPair rp = testkit::random_pair(rng, 4 + i % 3, 5 + i % 4, i % 2 == 0);
    const SlicedSpace space = space_of(rp.pair);
    const Checked c =
        random_queries(rp.pair, space, 10, 300 + i, "random pair " + std::to_string(i));
    all.paths += c.paths;
    all.crossed += c.crossed;
  }
  EXPECT_GT(all.paths, 100);
  EXPECT_GT(all.crossed, 20);
}

// A square in a square opening 0.001 wider: free space everywhere thinner than twice the
// contact tolerance, so no random end can be drawn. The helper gives up (it used to loop
// for ever on such a tight pair, as random seed 4711 of the tight fits above draws one).
TEST(Path, RandomFreePoseGivesUpOnATightFit) {
  const LoadResult r = parse_pair(
      R"({"name":"snug","moving":{"loops":[[[-0.5,-0.5],[0.5,-0.5],[0.5,0.5],[-0.5,0.5]]]},)"
      R"("fixed":{"enclosure":true,"loops":[[[-0.5005,-0.5005],[0.5005,-0.5005],)"
      R"([0.5005,0.5005],[-0.5005,0.5005]]]}})",
      "snug");
  ASSERT_TRUE(r.ok());
  const Slice at_zero = compute_slice(*r.pair, 0.0);
  ASSERT_EQ(at_zero.free_components.size(), 1u);  // free, but thin
  std::mt19937 rng(1);
  EXPECT_FALSE(testkit::random_free_pose(*r.pair, rng).has_value());
}

// Random tight fits (testkit::tight_pair): a moving part in an opening or a hole it barely fits,
// like the cam in its follower: free space in narrow, turning channels, split into components and
// pinched at critical orientations. A pinch narrower than twice the contact tolerance has no free
// path through it although the point query joins both sides (status not_found), so here only most
// queries must find a path, and every path found must be valid.
TEST(Path, RandomTightFits) {
  std::mt19937 rng(5);
  Checked all;
  for (int k = 0; k < 10; ++k) {
    const Pair pair = testkit::tight_pair(rng, k);
    const SlicedSpace space = space_of(pair);
    const Checked c =
        random_queries(pair, space, 10, 500 + k, "tight pair " + std::to_string(k), false);
    all.paths += c.paths;
    all.crossed += c.crossed;
    all.not_found += c.not_found;
  }
  EXPECT_GT(all.paths, 40);
  EXPECT_GT(all.crossed, 10);
  EXPECT_LE(all.not_found * 20, all.paths);  // at most 5%
}
