// The 3D topology of the sliced space: cells, their joins across critical orientations, and
// the connected components of the 3D free space, on the examples (whose free space is known)
// and on random curved pairs (properties, and an oracle built on `classify`).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <random>
#include <set>

#include "cslice/classify.hpp"
#include "cslice/space.hpp"
#include "support/cli_run.hpp"
#include "support/crossings.hpp"
#include "support/designed_pairs.hpp"
#include "support/examples.hpp"
#include "support/random_parts.hpp"
#include "support/spaces.hpp"

using namespace cslice;
using testkit::space_of;

namespace {

void expect_clean_checks(const SpaceTopology& t, const std::string& name) {
  EXPECT_EQ(t.checks.interval_match_failures, 0) << name;
  EXPECT_EQ(t.checks.boundary_label_mismatches, 0) << name;
  EXPECT_EQ(t.checks.side_slices_not_equivalent, 0) << name;
  EXPECT_EQ(t.checks.orphan_critical_components, 0) << name;
  for (const std::string& p : t.checks.problems) ADD_FAILURE() << name << ": " << p;
}

// The 3D component of the free component of stored slice `s` that holds p, or -1.
int component_at(const SlicedSpace& space, int s, Vec2 p) {
  const int c = space.slices[s].slice.locate(p);
  return c < 0 ? -1 : space.topology.slice_components[s][c];
}

int component_count(const SlicedSpace& space) {
  return static_cast<int>(space.topology.components.size());
}

// The structural promises: cells partitioned by the components, slice maps the right size,
// joins between consecutive intervals only, cells' samples free.
void expect_well_formed(const Pair& pair, const SlicedSpace& space, const std::string& name) {
  const SpaceTopology& t = space.topology;
  const int cells = static_cast<int>(t.cells.size());
  const int intervals = static_cast<int>(std::max<size_t>(1, space.criticals.orientations.size()));
  std::vector<int> seen(cells, 0);
  for (const SpaceComponent& comp : t.components) {
    ASSERT_FALSE(comp.cells.empty()) << name;
    EXPECT_TRUE(std::is_sorted(comp.cells.begin(), comp.cells.end())) << name;
    for (int c : comp.cells) {
      ASSERT_GE(c, 0);
      ASSERT_LT(c, cells);
      seen[c] += 1;
      EXPECT_EQ(t.cells[c].component, comp.id) << name << " cell " << c;
    }
  }
  for (int c = 0; c < cells; ++c) EXPECT_EQ(seen[c], 1) << name << ": cell " << c;
  ASSERT_EQ(t.slice_components.size(), space.slices.size());
  ASSERT_EQ(t.slice_cells.size(), space.slices.size());
  for (size_t s = 0; s < space.slices.size(); ++s) {
    EXPECT_EQ(t.slice_components[s].size(), space.slices[s].slice.free_components.size());
    EXPECT_EQ(t.slice_cells[s].size(), space.slices[s].slice.free_components.size());
    for (size_t c = 0; c < t.slice_cells[s].size(); ++c) {
      const int cell = t.slice_cells[s][c];
      if (space.slices[s].kind == SliceKind::critical) {
        EXPECT_EQ(cell, -1);
        continue;
      }
      ASSERT_GE(cell, 0) << name;
      EXPECT_EQ(t.cells[cell].interval, space.slices[s].interval) << name;
      EXPECT_EQ(t.slice_components[s][c], t.cells[cell].component) << name;
    }
  }
  // Each cell's sample is free; a sliver thinner than the contact tolerance (its area below
  // tol times the pair's size: no point of it is further than tol from its boundary) can
  // only be in contact by classify's definition, never blocked.
  PlacementTester tester(pair);
  for (const SpaceCell& cell : t.cells) {
    EXPECT_LT(cell.theta_from, cell.theta_to);
    const Placement p = tester.classify({cell.sample.x, cell.sample.y, cell.sample_theta});
    const bool sliver = cell.bounded && cell.max_area < pair.tol.contact * pair.tol.size;
    EXPECT_TRUE(p == Placement::free || (sliver && p == Placement::contact))
        << name << ": cell " << cell.id << " sample (" << cell.sample.x << ", " << cell.sample.y
        << ", " << cell.sample_theta << ") is " << to_string(p) << ", area up to " << cell.max_area;
  }
  // The cells' samples are taken in their interval's representative slice.
  for (const SpaceSlice& s : space.slices) {
    if (s.kind != SliceKind::interval) continue;
    for (const SpaceCell& cell : t.cells) {
      if (cell.interval == s.interval) {
        EXPECT_EQ(cell.sample_theta, s.theta) << name;
      }
    }
  }
  ASSERT_EQ(t.transitions.size(), space.criticals.orientations.size());
  for (const CriticalTransition& tr : t.transitions) {
    EXPECT_EQ(tr.interval_after, tr.critical);
    EXPECT_EQ(tr.interval_before, (tr.critical + intervals - 1) % intervals);
    EXPECT_GT(tr.side_before, 0.0);
    EXPECT_GT(tr.side_after, 0.0);
    EXPECT_LE(tr.side_before, side_slice_angle(pair.tol));
    EXPECT_LE(tr.side_after, side_slice_angle(pair.tol));
    for (const auto& [a, b] : tr.joins) {
      EXPECT_EQ(t.cells[a].interval, tr.interval_before) << name;
      EXPECT_EQ(t.cells[b].interval, tr.interval_after) << name;
      EXPECT_EQ((t.cells[a].interval + 1) % intervals, t.cells[b].interval) << name;
      EXPECT_EQ(t.cells[a].component, t.cells[b].component) << name;
    }
  }
}

const SpaceComponent& only_component(const SlicedSpace& space) {
  return space.topology.components.at(0);
}

}  // namespace

// ---- The examples -----------------------------------------------------------------------

// Turning a disc about its centre changes nothing: one cell, the whole turn, one component.
TEST(SpaceTopology, DiscInBoxIsOneComponentSpanningEveryTheta) {
  const Pair pair = testkit::load_example("disc-in-box");
  const SlicedSpace space = space_of(pair);
  expect_clean_checks(space.topology, "disc-in-box");
  expect_well_formed(pair, space, "disc-in-box");
  ASSERT_EQ(component_count(space), 1);
  ASSERT_EQ(space.topology.cells.size(), 1u);
  EXPECT_TRUE(only_component(space).spans_all_theta);
  const SpaceCell& cell = space.topology.cells[0];
  EXPECT_DOUBLE_EQ(cell.theta_from, -kPi);
  EXPECT_DOUBLE_EQ(cell.theta_to, kPi);
  EXPECT_NEAR(cell.min_area, 16.0, 1e-9);
  EXPECT_NEAR(cell.max_area, 16.0, 1e-9);
}

// The peg turns freely in the hole (side 3 > 2 sqrt 2), so the free space inside the hole is
// one component spanning every theta. The plate is closed round the hole, so the space
// outside it is a second, also spanning every theta; the two never meet.
TEST(SpaceTopology, SquarePegTurnsFreelyInItsHole) {
  const Pair pair = testkit::load_example("square-peg-hole");
  const SlicedSpace space = space_of(pair);
  expect_clean_checks(space.topology, "square-peg-hole");
  expect_well_formed(pair, space, "square-peg-hole");
  ASSERT_EQ(component_count(space), 2);
  for (const SpaceComponent& c : space.topology.components) EXPECT_TRUE(c.spans_all_theta);
  // The hole's component: the peg centred in the hole, at every stored slice.
  const int s0 = 0;
  const int inside = component_at(space, s0, {0, 0});
  ASSERT_GE(inside, 0);
  for (int s = 0; s < static_cast<int>(space.slices.size()); ++s)
    EXPECT_EQ(component_at(space, s, {0, 0}), inside) << "slice " << s;
  EXPECT_NE(component_at(space, s0, {20, 0}), inside);
  EXPECT_GE(component_at(space, s0, {20, 0}), 0);
  for (const CriticalTransition& t : space.topology.transitions)
    for (const TransitionEvent& e : t.events) EXPECT_EQ(e.kind, TransitionKind::continues);
}

// The cam turns without interference (paper section 2.2): its 0.2-wide channel is one 3D
// component through every theta, continuing across every critical orientation.
TEST(SpaceTopology, CamIsOneChannelThroughEveryTheta) {
  const Pair pair = testkit::load_example("cam");
  const SlicedSpace space = space_of(pair);
  expect_clean_checks(space.topology, "cam");
  expect_well_formed(pair, space, "cam");
  ASSERT_EQ(component_count(space), 1);
  EXPECT_TRUE(only_component(space).spans_all_theta);
  EXPECT_EQ(space.topology.cells.size(), space.criticals.orientations.size());
  for (const CriticalTransition& t : space.topology.transitions) {
    ASSERT_EQ(t.events.size(), 1u) << t.theta;
    EXPECT_EQ(t.events[0].kind, TransitionKind::continues) << t.theta;
  }
  for (const SpaceCell& cell : space.topology.cells) {
    EXPECT_NEAR(cell.min_area, 0.04, 1e-6);  // the 0.2 x 0.2 square of every slice
    EXPECT_NEAR(cell.max_area, 0.04, 1e-6);
  }
}

// examples/README.md: one free component for theta in (1.2525, 1.8891) and its mirror
// (-1.8891, -1.2525), two otherwise. Inside and outside meet where the pin passes the slot,
// so the 3D free space is one component spanning every theta; turning towards vertical the
// two merge (at +-1.2525 going up from 0, at -+1.8891 going up from -+pi), and split again.
TEST(SpaceTopology, FastenerInsideAndOutsideMeetThroughTheSlot) {
  const Pair pair = testkit::load_example("fastener");
  const SlicedSpace space = space_of(pair);
  expect_clean_checks(space.topology, "fastener");
  expect_well_formed(pair, space, "fastener");
  // The slot moves further than its width between stored slices; its boundary labels are
  // distinct, so they match the slices without halving the gaps (16 extra slices when the
  // halving came first).
  EXPECT_GT(space.topology.checks.label_matches, 0);
  EXPECT_EQ(space.topology.checks.refinement_slices, 0);
  for (const SpaceSlice& s : space.slices) {
    const size_t n = s.slice.free_components.size();
    EXPECT_TRUE(n == 1 || n == 2) << s.theta;
    if (s.kind == SliceKind::critical) continue;
    const double a = std::abs(s.theta);
    if (a > 1.2526 && a < 1.8890) {
      EXPECT_EQ(n, 1u) << s.theta;
    }
    if (a < 1.2524 || a > 1.8892) {
      EXPECT_EQ(n, 2u) << s.theta;
    }
  }
  ASSERT_EQ(component_count(space), 1);
  EXPECT_TRUE(only_component(space).spans_all_theta);
  std::vector<std::pair<double, TransitionKind>> changes;
  for (const CriticalTransition& t : space.topology.transitions)
    for (const TransitionEvent& e : t.events)
      if (e.kind != TransitionKind::continues) changes.emplace_back(t.theta, e.kind);
  ASSERT_EQ(changes.size(), 4u);
  const double lo = 1.25251, hi = 1.88908;
  const std::pair<double, TransitionKind> expected[] = {{-hi, TransitionKind::merge},
                                                        {-lo, TransitionKind::split},
                                                        {lo, TransitionKind::merge},
                                                        {hi, TransitionKind::split}};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(changes[i].first, expected[i].first, 1e-4) << i;
    EXPECT_EQ(changes[i].second, expected[i].second) << i;
  }
  // The pin horizontal in the cavity and vertical above the slot: one component.
  const auto slice_near = [&](double theta) {
    int best = 0;
    for (int s = 0; s < static_cast<int>(space.slices.size()); ++s)
      if (std::abs(space.slices[s].theta - theta) < std::abs(space.slices[best].theta - theta))
        best = s;
    return best;
  };
  const int inside = component_at(space, slice_near(0.0), {0, -3});
  const int above = component_at(space, slice_near(kPi / 2), {0, 6});
  ASSERT_GE(inside, 0);
  EXPECT_EQ(inside, above);
}

// A disc in a hole of its own radius: the hole's free space is a single point at every theta
// (a degenerate contact, no free component), so only the outside is free: one component.
// The disc against a block: one unbounded component.
TEST(SpaceTopology, PinExactFitAndDiscHalfPlane) {
  for (const char* name : {"pin-exact-fit", "disc-half-plane"}) {
    const Pair pair = testkit::load_example(name);
    const SlicedSpace space = space_of(pair);
    expect_clean_checks(space.topology, name);
    expect_well_formed(pair, space, name);
    ASSERT_EQ(component_count(space), 1) << name;
    EXPECT_TRUE(only_component(space).spans_all_theta) << name;
    ASSERT_EQ(space.topology.cells.size(), 1u) << name;
    EXPECT_FALSE(space.topology.cells[0].bounded) << name;
    EXPECT_TRUE(std::isnan(space.topology.cells[0].min_area)) << name;
  }
  const SlicedSpace pin = space_of(testkit::load_example("pin-exact-fit"));
  EXPECT_EQ(component_at(pin, 0, {0, 0}), -1);
}

TEST(SpaceTopology, PaperExamplesAreCleanAndConnected) {
  for (const char* name : {"knee", "fixture"}) {
    const Pair pair = testkit::load_example(name);
    const SlicedSpace space = space_of(pair);
    expect_clean_checks(space.topology, name);
    expect_well_formed(pair, space, name);
    EXPECT_EQ(component_count(space), 1) << name;
  }
}

// The topology part of a space file, without the checks (which count the work done).
nlohmann::json topology_without_checks(const Pair& pair, const SlicedSpace& space) {
  nlohmann::json j = nlohmann::json::parse(space_to_json(pair, space, false)).at("topology");
  j.erase("checks");
  return j;
}

// Where at most one free component lies on either side of a critical orientation the joins
// are taken from the counts, without side slices (compute_topology). The full sample rules,
// with side slices everywhere and each checked against its interval, must give the same
// cells, events, joins and 3D components: on the examples, and on random curved pairs except
// where the full rules leave a sliver of a critical slice (thinner than the contact
// tolerance) an orphan, which the counts join.
TEST(SpaceTopology, JoinsFromComponentCountsAgreeWithTheSampleRules) {
  int compared = 0, by_count = 0, by_clearance = 0, orphans = 0;
  const auto compare = [&](const Pair& pair, const std::string& name) {
    SlicedSpace space = space_of(pair);
    const nlohmann::json counted = topology_without_checks(pair, space);
    by_count += space.topology.checks.joins_by_count;
    by_clearance += space.topology.checks.joins_by_clearance;
    space.topology = compute_topology(pair, space, {2, true});
    EXPECT_EQ(space.topology.checks.joins_by_count, 0) << name;
    EXPECT_EQ(space.topology.checks.joins_by_clearance, 0) << name;
    EXPECT_EQ(space.topology.checks.side_slices_not_equivalent, 0) << name;
    if (space.topology.checks.orphan_critical_components > 0) {
      orphans += 1;
      return;
    }
    expect_clean_checks(space.topology, name);
    const nlohmann::json sampled = topology_without_checks(pair, space);
    EXPECT_TRUE(sampled == counted)
        << name << ": " << nlohmann::json::diff(counted, sampled).dump();
    compared += 1;
  };
  for (const char* name : {"knee", "cam", "fixture", "fastener"})
    compare(testkit::load_example(name), name);
  // The fastener's slot component is thinner than reach times the gap to the nearest stored
  // slice on about half the sides of its 34 critical orientations not joined by count.
  const Pair fastener = testkit::load_example("fastener");
  const TopologyChecks& f = space_of(fastener).topology.checks;
  EXPECT_EQ(f.joins_by_count, 2);
  EXPECT_GE(f.joins_by_clearance, 1);
  EXPECT_LE(f.joins_by_clearance, 48);
  std::mt19937 rng(4711);
  for (int i = 0; i < 24; ++i) {
    const testkit::RandomPair rp = testkit::random_pair(rng, 4 + i % 4, 5 + i % 5, i % 2 == 0);
    SCOPED_TRACE(rp.json);
    compare(rp.pair, "random " + std::to_string(i));
  }
  EXPECT_GE(compared, 24);
  EXPECT_GT(by_count, 100);
  RecordProperty("compared", compared);
  std::printf("compared %d pairs, %d joins by count, %d by clearance, %d left out for orphans\n",
              compared, by_count, by_clearance, orphans);
}

// ---- Random curved pairs ----------------------------------------------------------------

TEST(SpaceTopology, RandomPairsAreWellFormedAndThreadIndependent) {
  std::mt19937 rng(20240505);
  for (int i = 0; i < 20; ++i) {
    const testkit::RandomPair rp = testkit::random_pair(rng, 4 + i % 4, 5 + i % 5, i % 2 == 0);
    const SlicedSpace space = space_of(rp.pair);
    SCOPED_TRACE(rp.json);
    // Random pairs make slivers thinner than the contact tolerance that appear or vanish at
    // a critical orientation; one of those in a critical slice may reach no cell (reported in
    // checks.orphan_critical_components). Anything else is a failure.
    SpaceTopology checked = space.topology;
    for (size_t s = 0; s < space.slices.size(); ++s)
      for (size_t c = 0; c < checked.slice_components[s].size(); ++c) {
        if (checked.slice_components[s][c] >= 0) continue;
        const FreeComponent& comp = space.slices[s].slice.free_components[c];
        EXPECT_TRUE(comp.bounded && comp.area < rp.pair.tol.contact * rp.pair.tol.size)
            << "random " << i << ": orphan component " << c << " of slice " << s;
        checked.checks.orphan_critical_components -= 1;
        std::erase_if(checked.checks.problems, [](const std::string& p) {
          return p.find("reaches no cell") != std::string::npos;
        });
      }
    expect_clean_checks(checked, "random " + std::to_string(i));
    expect_well_formed(rp.pair, space, "random " + std::to_string(i));
    if (i % 5 == 0) {
      const SlicedSpace one = space_of(rp.pair, 1);
      EXPECT_EQ(space_to_json(rp.pair, one, false), space_to_json(rp.pair, space, false));
    }
  }
}

// An oracle built on classify alone: two free configurations of one free component of one
// slice (at a random theta, not a stored one) are joined in 3D. Each is carried at fixed
// (x, y) to a stored slice, one down and one up in theta, through configurations that
// classify as free; where they land, the stored structure must give one 3D component.
TEST(SpaceTopology, ConfigurationsOfOneSliceComponentShareTheir3DComponent) {
  std::mt19937 rng(777);
  int checked = 0;
  for (int i = 0; i < 8; ++i) {
    const testkit::RandomPair rp = testkit::random_pair(rng, 5, 6, i % 2 == 0);
    const SlicedSpace space = space_of(rp.pair);
    PlacementTester tester(rp.pair);
    const int n = static_cast<int>(space.slices.size());
    std::uniform_real_distribution<double> angle(-kPi, kPi), unit(0.0, 1.0);
    // Carries (p, theta) to stored slice s along theta; -1 when the way is not free.
    const auto carry = [&](Vec2 p, double theta, int s) {
      double target = space.slices[s].theta;
      if (std::abs(target - theta) > kPi) target += target < theta ? kTwoPi : -kTwoPi;
      constexpr int kSteps = 200;
      for (int k = 1; k <= kSteps; ++k)
        if (tester.classify({p.x, p.y, theta + (target - theta) * k / kSteps}) != Placement::free)
          return -1;
      return component_at(space, s, p);
    };
    for (int trial = 0; trial < 10; ++trial) {
      const double theta = angle(rng);
      int up = 0;  // the first stored slice above theta, cyclically
      while (up < n && space.slices[up].theta <= theta) ++up;
      up %= n;
      const int down = (up + n - 1) % n;
      const Slice slice = compute_slice(rp.pair, theta);
      for (const FreeComponent& comp : slice.free_components) {
        // Random free points of this component, within its samples' neighbourhood.
        const double r = comp.bounded ? std::sqrt(comp.area) : 3.0;
        std::vector<Vec2> points;
        for (int tries = 0; tries < 200 && points.size() < 2; ++tries) {
          const Vec2 p{comp.sample.x + r * (2 * unit(rng) - 1),
                       comp.sample.y + r * (2 * unit(rng) - 1)};
          if (slice.locate(p) == comp.id && tester.classify({p.x, p.y, theta}) == Placement::free)
            points.push_back(p);
        }
        if (points.size() < 2) continue;
        const int a = carry(points[0], theta, down), b = carry(points[1], theta, up);
        if (a < 0 || b < 0) continue;
        EXPECT_EQ(a, b) << rp.json << "\ntheta " << theta << " points (" << points[0].x << ", "
                        << points[0].y << ") and (" << points[1].x << ", " << points[1].y << ")";
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 20);
}

// Cavity pairs (random parts in random cavities, drawn as in tests/test_mesh.cpp, seeds 164
// and 245 of a 300-pair mesh stress run) where a thin triangle of free space splits off at a
// tangency and vanishes soon after. The stored slice after the tangency was so far away that
// the sliver had moved off its own sample: the triangle was taken to appear from nothing, a
// 3D component of its own (the contact mesh coned it).
const char* const kSliverPairs[] = {
    R"({"name":"cavity","moving":{"loops":[[[0.96029202771539335,0.18641517389015222,0],[-0.482)"
    R"(10087708230198,1.0681984674522478,0.23706233022906598],[-1.2144455955546856,0.6653104272)"
    R"(996192,0.035870401506191738],[-0.64009025593364099,-1.5272709836294105,0],[0.81760396980)"
    R"(57298,-1.4192546452529315,0]]]},"fixed":{"loops":[[[-5,-5,0],[5,-5,0],[5,5,0],[-5,5,0]],)"
    R"([[2.8006192715335705,0.18727748591987653,-0.010433882383144822],[1.0748155083134754,1.96)"
    R"(44744458190784,-0.23802094349808242],[-2.8135927851386042,0.72922823229234268,0],[-1.717)"
    R"(5236968238659,-0.95868666329952235,-0.23676660443420561],[-1.2193049327631864,-2.9878780)"
    R"(517872756,0.061404025167749406],[1.093774798546931,-0.93360749398053833,-0.2293252826592)"
    R"(8678]]]}})",
    R"({"name":"cavity","moving":{"loops":[[[1.0934141855316657,0.77450435148060015,0],[-0.6249)"
    R"(7106883698816,1.417878016775026,0],[-1.1195645630437032,0.51581441892339508,0.0033961062)"
    R"(392989573],[-0.96010637481088557,-1.3006875796045543,-0.29881903514179786],[1.1714982320)"
    R"(847853,-0.61290248295904304,-0.051956875112253172]]]},"fixed":{"loops":[[[-5,-5,0],[5,-5)"
    R"(,0],[5,5,0],[-5,5,0]],[[1.2003114976999965,0.33215491732515401,-0.0968531472767514],[0.5)"
    R"(947065848070906,2.5874088446931895,0],[-2.6243607008953376,2.2953168162661379,-0.1197163)"
    R"(4444433013],[-1.747178142761648,0.45550320375452019,-0.28876114985242923],[-2.0784193037)"
    R"(554708,-1.5527960472995146,0.22853314877857628],[0.40057744427505171,-2.5684194385866932)"
    R"(,0],[3.1118487198520572,-1.1786520496286799,0]]]}})"};
const double kSliverSplits[] = {-1.008745056, -1.285348561};

// The stored slice's index of the critical orientation at theta.
int critical_slice_at(const SlicedSpace& space, double theta) {
  for (int s = 0; s < static_cast<int>(space.slices.size()); ++s)
    if (space.slices[s].kind == SliceKind::critical &&
        std::fabs(space.slices[s].theta - theta) < 1e-6)
      return s;
  return -1;
}

// testkit::expect_crossings_joined at the critical orientation at theta.
int expect_crossings_joined(const Pair& pair, double theta, bool from_after,
                            const std::string& what) {
  const SlicedSpace space = space_of(pair);
  const int at = critical_slice_at(space, theta);
  if (at < 0) {
    ADD_FAILURE() << what << ": no critical orientation at " << theta;
    return 0;
  }
  return testkit::expect_crossings_joined(pair, space, at, from_after, what);
}

// The triangle after the tangency, carried down across it, lands in the component it split
// from.
TEST(SpaceTopology, SliverSplitOffAtATangencyStaysJoined) {
  for (int i = 0; i < 2; ++i) {
    const LoadResult r = parse_pair(kSliverPairs[i], "sliver");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(
        expect_crossings_joined(*r.pair, kSliverSplits[i], true, "sliver " + std::to_string(i)),
        i == 0 ? 3 : 4);
  }
}

// Stress seed 100167 (tests/stress): at theta = 1.182405435 a lobe of area 2e-7 merges through
// a pinch with its neighbour (2.9e-5); 1e-3 rad later its sample was no longer in the merged
// component, and the lobe was taken to vanish: a 3D component of its own.
TEST(SpaceTopology, LobeMergingThroughAPinchStaysJoined) {
  EXPECT_EQ(expect_crossings_joined(testkit::stress_pair(100167).pair, 1.182405435, false,
                                    "stress 100167"),
            3);
}

// Stress seed 100668: a triangle of area 7e-9 changes one side's feature pair at
// theta = 2.147627214 and grows fast after it; its sample had left it 1e-3 rad later, and the
// triangle was taken to vanish and another to appear (no labels in common to match them by).
TEST(SpaceTopology, TriangleChangingASideStaysJoined) {
  EXPECT_EQ(expect_crossings_joined(testkit::stress_pair(100668).pair, 2.147627214, false,
                                    "stress 100668"),
            2);
  EXPECT_EQ(expect_crossings_joined(testkit::stress_pair(100668).pair, 2.147627214, true,
                                    "stress 100668"),
            2);
}

// Stress seed 107007: a triangle of area 3e-13 at theta = -1.930340995 vanishes 6e-6 rad later;
// its sample, carried 1e-3 rad back to the side slice, takes 620 steps of its clearance.
TEST(SpaceTopology, ThinTriangleCarriedFarStaysJoined) {
  const Pair pair = testkit::stress_pair(107007).pair;
  EXPECT_EQ(expect_crossings_joined(pair, -1.930340995, false, "stress 107007"), 2);
  EXPECT_EQ(expect_crossings_joined(pair, -1.930340995, true, "stress 107007"), 2);
}

// The converse of the tests above, for false joins: at every critical orientation of the
// examples, the sliver pairs and twenty stress pairs, the cells the topology joins must be
// joined by components carried across both ways (tests/support/crossings). Stress runs found
// none unconfirmed over 1,500 random, 600 cavity and 90 designed pairs (docs/space-format.md);
// joining two cells the carries keep apart fails it (checked by making that join).
TEST(SpaceTopology, EveryJoinIsWitnessedByACarry) {
  std::vector<std::pair<std::string, Pair>> pairs;
  for (const char* name : {"knee", "cam", "fixture", "fastener", "square-peg-hole"})
    pairs.emplace_back(name, testkit::load_example(name));
  for (int i = 0; i < 2; ++i) pairs.emplace_back("sliver", *parse_pair(kSliverPairs[i], "s").pair);
  for (unsigned seed = 100160; seed < 100180; ++seed)
    pairs.emplace_back("stress " + std::to_string(seed), testkit::stress_pair(seed).pair);
  int joined_events = 0;
  for (const auto& [name, pair] : pairs) {
    const SlicedSpace space = space_of(pair);
    for (int at = 0; at < static_cast<int>(space.slices.size()); ++at)
      if (space.slices[at].kind == SliceKind::critical) {
        EXPECT_EQ(testkit::expect_joins_witnessed(pair, space, at, name), 0);
      }
    for (const CriticalTransition& t : space.topology.transitions)
      for (const TransitionEvent& e : t.events)
        joined_events += e.before.size() + e.after.size() > 1 ? 1 : 0;
  }
  EXPECT_GT(joined_events, 1000) << joined_events;  // the check has joins to confirm
}

// Designed pair 4314 (an L-tromino in an opening of its shape, turned): at theta = 1.5758321
// a free triangle shrinks through a critical orientation and goes on, 4.4e-13 in area, for
// the 2e-4 rad to the next one, where it vanishes. Its sample in the slice after lies within
// the slice's epsilon band, so no carry can start there. Such a cell is left out of the check
// (it failed the stress run before); the join itself is the component counts' (one before,
// one after).
TEST(SpaceTopology, JoinsOfSliversThinnerThanTheBandAreLeftOutOfTheCarryCheck) {
  const Pair pair = testkit::designed_pair(4314).pair;
  const SlicedSpace space = space_of(pair);
  const int at = critical_slice_at(space, 1.5758321472829691);
  ASSERT_GE(at, 0);
  const Slice& after = space.slices[at + 1].slice;
  ASSERT_EQ(after.free_components.size(), 1u);
  EXPECT_LT(after.free_components[0].area, 1e-12);
  EXPECT_EQ(after.locate(after.free_components[0].sample), -1);
  EXPECT_EQ(testkit::expect_joins_witnessed(pair, space, at, "designed 4314"), 0);
}

// ---- The file and the stats column ------------------------------------------------------

class TopologyCli : public testkit::ScratchDirTest {
 protected:
  TopologyCli() : ScratchDirTest("cslice_topology") {}
};

TEST_F(TopologyCli, SpaceFileHasTheTopology) {
  const std::string out = (dir_ / "space.json").string();
  const testkit::RunResult r =
      testkit::run_cli("compute " + testkit::quoted(testkit::example_path("fastener")) + " -o " +
                           testkit::quoted(out),
                       dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(testkit::read_file(out));
  const nlohmann::json& t = j["topology"];
  EXPECT_EQ(t["free_components_3d"], 1);
  EXPECT_EQ(t["components"][0]["spans_all_theta"], true);
  EXPECT_EQ(t["transitions"].size(), j["critical_orientations"].size());
  EXPECT_EQ(t["slice_components"].size(), j["slices"].size());
  for (const char* field :
       {"id", "interval", "theta_range", "component", "bounded", "area_range", "sample"})
    EXPECT_TRUE(t["cells"][0].contains(field)) << field;
  std::multiset<std::string> kinds;
  for (const auto& tr : t["transitions"])
    for (const auto& e : tr["events"]) kinds.insert(e["kind"].get<std::string>());
  EXPECT_EQ(kinds.count("merge"), 2u);
  EXPECT_EQ(kinds.count("split"), 2u);
  EXPECT_EQ(t["checks"]["interval_match_failures"], 0);
}

TEST_F(TopologyCli, StatsHasA3DComponentsColumn) {
  const testkit::RunResult r =
      testkit::run_cli("stats " + testkit::quoted(testkit::example_path("square-peg-hole")), dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("| 3D free components |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| 2 (2 span every θ) |"), std::string::npos) << r.out;
}
