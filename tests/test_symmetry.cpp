// Symmetries of pairs (include/cslice/symmetry.hpp): found on the examples and on random
// symmetric pairs, refused on a part drawn off its mirror, and the slices that compute_space
// maps across them against the same slices computed from scratch and against classify.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "criticals/symmetric.hpp"
#include "cslice/critical.hpp"
#include "cslice/space.hpp"
#include "cslice/symmetry.hpp"
#include "support/cli_run.hpp"
#include "support/completeness.hpp"
#include "support/examples.hpp"
#include "support/moved_examples.hpp"
#include "support/random_polygons.hpp"
#include "support/slice_oracle.hpp"
#include "support/symmetric_pairs.hpp"

using namespace cslice;

namespace {

// The symmetries' actions on theta, as (quarter turns, reverses theta), sorted.
std::set<std::pair<int, bool>> theta_maps(const Pair& pair) {
  std::set<std::pair<int, bool>> out;
  for (const PairSymmetry& s : pair_symmetries(pair))
    out.insert({s.quarter_turns, s.reverses_theta});
  return out;
}

// Each boundary cycle of each free component closes: every piece starts where the one before
// it ends (a mirrored cycle whose pieces were reversed but not their order would not).
void expect_cycles_chain(const Slice& slice, const std::string& what) {
  for (const FreeComponent& c : slice.free_components)
    for (const std::vector<ContactPiece>& cycle : c.boundary)
      for (size_t i = 0; i < cycle.size(); ++i) {
        const Curve& next = cycle[(i + 1) % cycle.size()].curve;
        EXPECT_LE(distance(cycle[i].curve.to, next.from), slice.epsilon)
            << what << ": component " << c.id << ", piece " << i << " does not meet the next";
      }
}

// What `compute` makes of the pair on two threads, with its options' map_symmetric on, then
// off.
template <class Options, class Result>
std::pair<Result, Result> with_and_without_symmetry(const Pair& pair,
                                                    Result (*compute)(const Pair&,
                                                                      const Options&)) {
  Options options;
  options.threads = 2;
  Result with = compute(pair, options);
  options.map_symmetric = false;
  return {std::move(with), compute(pair, options)};
}

// compute_space's mapped slices (up to `most`, evenly spread) against the slices computed at
// their orientations, beside their boundaries and at random points against classify; the
// space without mapping has the same topology. Returns how many slices were mapped.
int check_mapped_slices(const Pair& pair, const std::string& name, size_t most = 1000) {
  const auto [space, plain] = with_and_without_symmetry(pair, compute_space);
  EXPECT_EQ(space.slices.size(), plain.slices.size()) << name;
  EXPECT_EQ(space.topology.components.size(), plain.topology.components.size()) << name;
  EXPECT_EQ(space.topology.cells.size(), plain.topology.cells.size()) << name;
  EXPECT_EQ(space.topology.slice_components, plain.topology.slice_components) << name;
  std::vector<const SpaceSlice*> mapped;
  for (const SpaceSlice& s : space.slices)
    if (s.mapped) mapped.push_back(&s);
  std::mt19937 rng(17);
  for (size_t i = 0; i < mapped.size(); i += std::max<size_t>(1, mapped.size() / most)) {
    const Slice& s = mapped[i]->slice;
    const std::string what = name + " at theta " + std::to_string(s.theta);
    const Slice computed = compute_slice(pair, s.theta);
    testkit::expect_same_slice(pair, s, computed, what);
    // Each component's boundary by the same labels: where pieces lie along coincident contact
    // segments, naming them is the computed slice's rule, so such slices are not mapped.
    for (const FreeComponent& c : s.free_components) {
      const int match = computed.locate(c.sample);
      if (match >= 0) {
        EXPECT_EQ(boundary_labels(s, c), boundary_labels(computed, computed.free_components[match]))
            << what << ": component " << c.id;
      }
    }
    testkit::expect_boundary_sides_agree_with_classify(pair, s, what);
    testkit::check_slice_against_classify(pair, s, 100, rng, what, false);
    expect_cycles_chain(s, what);
  }
  return static_cast<int>(mapped.size());
}

// A criticality's condition and feature pairs (in order for an endpoint, whose first pair owns
// the end; as a set otherwise).
std::vector<int> identity(const Criticality& c) {
  std::vector<std::array<int, 3>> pairs;
  for (const FeaturePairRef& p : c.pairs)
    pairs.push_back({p.moving_feature, p.fixed_feature, int(p.kind)});
  if (c.condition != CriticalCondition::endpoint) std::sort(pairs.begin(), pairs.end());
  std::vector<int> id{int(c.condition)};
  for (const auto& p : pairs) id.insert(id.end(), p.begin(), p.end());
  return id;
}

// At the orientations of the domain's two ends, the search within the domain finds every
// criticality that the search of the whole turn finds there, as often: families that appear
// exactly at an end are met only by bins reaching past it.
void expect_domain_ends_complete(const Pair& pair, const CriticalSet& set, const CriticalSet& whole,
                                 const std::string& name) {
  const std::optional<AngleInterval> domain = fundamental_domain(pair_symmetries(pair));
  if (!domain) return;
  const auto at_an_end = [&](double theta) {
    return std::fabs(wrap_angle(theta - domain->lo)) <= pair.tol.critical_angle ||
           std::fabs(wrap_angle(theta - domain->lo - domain->span)) <= pair.tol.critical_angle;
  };
  for (size_t i = 0; i < whole.orientations.size() && i < set.orientations.size(); ++i) {
    if (!at_an_end(whole.orientations[i].theta)) continue;
    std::multiset<std::vector<int>> found;
    for (const Criticality& c : set.orientations[i].criticalities) found.insert(identity(c));
    for (const Criticality& c : whole.orientations[i].criticalities) {
      const auto it = found.find(identity(c));
      EXPECT_TRUE(it != found.end())
          << name << ": a " << to_string(c.condition) << " criticality at the domain's end "
          << c.theta << " is missing";
      if (it != found.end()) found.erase(it);
    }
  }
}

// The critical orientations found in the symmetries' fundamental domain and mapped: the same
// orientations as searching the whole turn, each the exact image of another under every
// symmetry, every criticality's image among the criticalities, and complete (no change of
// the slices between two of them, none missed). Returns how many criticalities were mapped.
long check_symmetric_criticals(const Pair& pair, const std::string& name) {
  const auto [set, whole] = with_and_without_symmetry(pair, critical_orientations);
  EXPECT_EQ(set.orientations.size(), whole.orientations.size()) << name;
  for (size_t i = 0; i < set.orientations.size() && i < whole.orientations.size(); ++i)
    EXPECT_NEAR(set.orientations[i].theta, whole.orientations[i].theta, pair.tol.critical_angle)
        << name << ": orientation " << i;
  expect_domain_ends_complete(pair, set, whole, name);
  std::vector<double> thetas;
  std::vector<const Criticality*> all;
  for (const CriticalOrientation& o : set.orientations) {
    thetas.push_back(o.theta);
    for (const Criticality& c : o.criticalities) all.push_back(&c);
  }
  for (const PairSymmetry& s : pair_symmetries(pair)) {
    // To round-off of composing the maps: the slices at them are each other's images.
    for (double theta : thetas)
      EXPECT_EQ(std::count_if(thetas.begin(), thetas.end(),
                              [&](double t) {
                                return std::fabs(wrap_angle(t - s.image_theta(theta))) <=
                                       64 * kTwoPi * std::numeric_limits<double>::epsilon();
                              }),
                1)
          << name << ": no orientation at the image of " << theta;
    for (const Criticality* c : all) {
      const double theta = s.image_theta(c->theta);
      const Vec2 at = s.plane.apply(c->at);
      const bool found = std::any_of(all.begin(), all.end(), [&](const Criticality* d) {
        return d->condition == c->condition && d->pairs.size() == c->pairs.size() &&
               std::fabs(wrap_angle(d->theta - theta)) <= pair.tol.critical_angle &&
               (c->condition == CriticalCondition::segment_end ||
                distance(d->at, at) <= pair.tol.criticality);
      });
      EXPECT_TRUE(found) << name << ": no image of the criticality at " << c->theta;
    }
  }
  testkit::CompletenessOptions few;
  few.samples_per_interval = 8;
  few.dense_samples = 240;
  const testkit::CompletenessReport report = testkit::check_completeness(pair, set, few);
  for (const std::string& f : report.interval_failures) ADD_FAILURE() << name << ": " << f;
  for (const std::string& m : report.missed) ADD_FAILURE() << name << ": " << m;
  return set.stats.mapped;
}

}  // namespace

TEST(Symmetry, ThePaperExamplesSymmetriesAreFound) {
  using Maps = std::set<std::pair<int, bool>>;
  // The knee's femur and tibia are not symmetric.
  EXPECT_EQ(theta_maps(testkit::load_example("knee")), Maps{});
  // The fixture's gripper is symmetric under both mirrors about its origin; its fixture under
  // the mirror x -> 4.2 - x: theta -> -theta, pi - theta and theta + pi.
  const Maps halves = {{0, true}, {2, false}, {2, true}};
  EXPECT_EQ(theta_maps(testkit::load_example("fixture")), halves);
  EXPECT_EQ(theta_maps(testkit::load_example("fastener")), halves);
  // The cam: every quarter turn and mirror.
  EXPECT_EQ(theta_maps(testkit::load_example("cam")),
            (Maps{{1, false}, {2, false}, {3, false}, {0, true}, {1, true}, {2, true}, {3, true}}));
  // Turned a quarter turn as a whole, the fixture keeps them.
  EXPECT_EQ(theta_maps(testkit::moved_example("fixture", 1.0, kPi / 2, {0.0, 0.0})), halves);
}

TEST(Symmetry, APartDrawnOffItsMirrorIsNotSymmetric) {
  std::ifstream in(testkit::example_path("fixture"));
  nlohmann::json j = nlohmann::json::parse(in);
  const Pair original = testkit::parse_or_throw(j.dump(), "fixture");
  // One vertex of the fixed part moved by a geometric epsilon: the mirror is lost, the
  // moving part's own symmetry (theta -> theta + pi) stays.
  j["fixed"]["loops"][0][1][0] =
      j["fixed"]["loops"][0][1][0].get<double>() + original.tol.geometric * 1.0;
  const Pair moved = testkit::parse_or_throw(j.dump(), "fixture, one vertex moved");
  EXPECT_EQ(theta_maps(moved), (std::set<std::pair<int, bool>>{{2, false}}));
  // The symmetry's feature map is a permutation that keeps kinds.
  for (const PairSymmetry& s : pair_symmetries(original)) {
    std::vector<int> sorted = s.plane.feature_map;
    std::sort(sorted.begin(), sorted.end());
    for (size_t i = 0; i < sorted.size(); ++i) EXPECT_EQ(sorted[i], static_cast<int>(i));
    for (size_t i = 0; i < s.plane.feature_map.size(); ++i)
      EXPECT_EQ(original.fixed.features[i].kind,
                original.fixed.features[s.plane.feature_map[i]].kind);
  }
}

TEST(Symmetry, MappedSlicesOfTheExamplesAreTheSlicesAtTheirOrientations) {
  // The last three have no critical orientation or few: a disc, a pin in its hole, a peg.
  for (const char* name :
       {"cam", "fixture", "fastener", "disc-in-box", "pin-exact-fit", "square-peg-hole"})
    EXPECT_GT(check_mapped_slices(testkit::load_example(name), name), 0) << name;
  std::ifstream in(testkit::example_path("fixture"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const Pair moved = testkit::moved_pair(text, "fixture moved", 1.0, 0.0, {}, {30.0, -15.0});
  EXPECT_GT(check_mapped_slices(moved, "fixture moved"), 0);
  EXPECT_GT(check_mapped_slices(testkit::mirrored_example("fastener"), "fastener mirrored"), 0);
}

TEST(Symmetry, MappedSlicesOfRandomSymmetricPairsAreTheSlicesAtTheirOrientations) {
  // Mirror-symmetric moving stars around fixed stars symmetric under quarter turns (theta ->
  // theta + pi / 2, pi, 3 pi / 2) or a mirror (theta -> pi - theta), or inside such openings.
  using Maps = std::set<std::pair<int, bool>>;
  for (unsigned seed = 0; seed < 8; ++seed) {
    const testkit::RandomPair p = testkit::symmetric_pair(seed);
    const Maps expected =
        seed % 2 == 0 ? Maps{{1, false}, {2, false}, {3, false}} : Maps{{2, true}};
    EXPECT_EQ(theta_maps(p.pair), expected) << p.json;
    EXPECT_GT(check_mapped_slices(p.pair, "symmetric pair " + std::to_string(seed), 8), 0);
  }
}

TEST(Symmetry, CriticalOrientationsFromTheFundamentalDomainAreThoseOfTheWholeTurn) {
  for (const char* name : {"cam", "fixture", "fastener"})
    EXPECT_GT(check_symmetric_criticals(testkit::load_example(name), name), 0) << name;
  EXPECT_EQ(check_symmetric_criticals(testkit::load_example("knee"), "knee"), 0);
  EXPECT_GT(check_symmetric_criticals(testkit::mirrored_example("fixture"), "fixture mirrored"), 0);
  for (unsigned seed = 8; seed < 14; ++seed)
    check_symmetric_criticals(testkit::symmetric_pair(seed).pair,
                              "symmetric pair " + std::to_string(seed));
}

class SymmetryCli : public testkit::ScratchDirTest {
 protected:
  SymmetryCli() : ScratchDirTest("cslice_symmetry") {}
};

// `cslice info` names what each symmetry does to theta; `cslice critical --whole-turn` finds
// the same orientations without them.
TEST_F(SymmetryCli, InfoNamesTheSymmetriesAndCriticalCanSearchTheWholeTurn) {
  const std::string fixture = testkit::quoted(testkit::example_path("fixture"));
  const testkit::RunResult info = testkit::run_cli("info --json " + fixture, dir_);
  ASSERT_EQ(info.status, 0) << info.err;
  EXPECT_EQ(nlohmann::json::parse(info.out)["symmetries"],
            nlohmann::json({"theta + pi", "pi - theta", "-theta"}));
  const testkit::RunResult knee =
      testkit::run_cli("info " + testkit::quoted(testkit::example_path("knee")), dir_);
  EXPECT_NE(knee.out.find("symmetry   none"), std::string::npos) << knee.out;
  for (const char* how : {"", " --whole-turn"}) {
    const testkit::RunResult r = testkit::run_cli("critical --json - " + fixture + how, dir_);
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["counts"]["orientations"], 76) << how;
    EXPECT_EQ(j["stats"]["mapped"].get<int>() > 0, std::string(how).empty()) << how;
  }
}
