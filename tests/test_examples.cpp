// The example pairs in examples/: they load, have the feature counts the paper reports, and
// the configurations examples/README.md names classify as it says. Guards the examples
// against edits that would quietly break the documentation built on them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cslice/classify.hpp"
#include "cslice/pair.hpp"
#include "support/examples.hpp"

namespace cslice {
namespace {

Pair example(const std::string& name) {
  return testkit::load_example(name);
}

int features(const Pair& p) {
  return p.moving.feature_count() + p.fixed.feature_count();
}

// Figure 8 of the paper: knee 22, mechanism 16, fixture 36, fastener 32.
TEST(Examples, PaperFeatureCounts) {
  EXPECT_EQ(features(example("knee")), 22);
  EXPECT_EQ(features(example("cam")), 16);
  EXPECT_EQ(features(example("fixture")), 36);
  EXPECT_EQ(features(example("fastener")), 32);
}

TEST(Examples, AnalyticCasesLoad) {
  EXPECT_EQ(features(example("disc-in-box")), 1 + 8);
  EXPECT_EQ(features(example("square-peg-hole")), 8 + 16);
  EXPECT_EQ(features(example("disc-half-plane")), 1 + 8);
  EXPECT_EQ(features(example("pin-exact-fit")), 1 + 9);
}

// Figure 1: the femur at (5, -3, 0.5) is free, about 1.65 mm above the tibial plateau.
TEST(Examples, KneeFigureOneConfigurationIsFree) {
  const Pair knee = example("knee");
  PlacementTester tester(knee);
  EXPECT_EQ(tester.classify({5, -3, 0.5}), Placement::free);
  EXPECT_NEAR(tester.boundary_distance({5, -3, 0.5}), 1.646, 0.01);
  EXPECT_EQ(tester.classify({5, -4.7, 0.5}), Placement::blocked);
}

// The engaging configuration is contact, and pushing further up blocks: it is the top of
// the well, upright and upside down alike.
TEST(Examples, FixtureEngagingConfigurationIsContact) {
  const Pair fixture = example("fixture");
  PlacementTester tester(fixture);
  for (double theta : {0.0, kPi}) {
    EXPECT_EQ(tester.classify({2.1, -0.7, theta}), Placement::contact) << theta;
    EXPECT_EQ(tester.classify({2.1, -0.69, theta}), Placement::blocked) << theta;
    EXPECT_EQ(tester.classify({2.1, -0.75, theta}), Placement::free) << theta;
    // Sideways at the same height the part runs into the notch: a strict local maximum.
    EXPECT_EQ(tester.classify({2.2, -0.7, theta}), Placement::blocked) << theta;
    EXPECT_EQ(tester.classify({2.0, -0.7, theta}), Placement::blocked) << theta;
  }
}

// The backlash: at every orientation the cam has a 0.2 x 0.2 square of free positions.
// At theta = 0 it is centred at (0, -1.25); its corners are contact.
TEST(Examples, CamBacklashSquare) {
  const Pair cam = example("cam");
  PlacementTester tester(cam);
  EXPECT_EQ(tester.classify({0, -1.25, 0}), Placement::free);
  EXPECT_EQ(tester.classify({0.1, -1.15, 0}), Placement::contact);
  EXPECT_EQ(tester.classify({0.11, -1.25, 0}), Placement::blocked);
  EXPECT_EQ(tester.classify({0, -1.36, 0}), Placement::blocked);
  EXPECT_EQ(tester.classify({0.885, -1.25, 0.3}), Placement::free);
  EXPECT_EQ(tester.classify({0, 0, 0.3}), Placement::blocked);
}

// The pin passes the slot when vertical, and lies free inside the cavity when horizontal.
TEST(Examples, FastenerPinPassesTheSlotOnlyNearVertical) {
  const Pair fastener = example("fastener");
  PlacementTester tester(fastener);
  EXPECT_EQ(tester.classify({0, 6, kPi / 2}), Placement::free);
  EXPECT_EQ(tester.classify({0, 0.75, kPi / 2}), Placement::free);  // halfway through
  EXPECT_EQ(tester.classify({0, 0.75, 0}), Placement::blocked);
  EXPECT_EQ(tester.classify({0, -3, 0}), Placement::free);  // locked in the cavity
}

}  // namespace
}  // namespace cslice
