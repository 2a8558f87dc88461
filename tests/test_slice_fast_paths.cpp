// The slice's shortcuts against the plain computations they replace: the index of fixed
// normals (and the per-slice rotations it shares) against every feature pair tried in turn,
// the arrangement's merge of exactly equal points against clusters of near ones, and the
// split points left out where segments meet end to end; and the buffers one-shot slices keep.
#include <gtest/gtest.h>
#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "contacts/contact_features.hpp"
#include "cslice/slice.hpp"
#include "slice/arrangement.hpp"
#include "slice/edge_pieces.hpp"
#include "slice/small_sort.hpp"
#include "slice/split_points.hpp"
#include "support/designed_pairs.hpp"
#include "support/random_parts.hpp"
#include "support/random_polygons.hpp"

using namespace cslice;

namespace {

// Curve i as contact segment i, for arrangements built from curves alone.
std::vector<int> own_ids(const std::vector<Curve>& curves) {
  std::vector<int> ids(curves.size());
  std::iota(ids.begin(), ids.end(), 0);
  return ids;
}

Tolerances with_geometric(double eps) {
  Tolerances tol;
  tol.geometric = eps;
  return tol;
}

// Every moving feature against every fixed one, in feature order: what ContactMaker finds
// through its index, pair by pair, with nothing precomputed.
std::vector<ContactSegment> every_pair(const Pair& pair, double theta) {
  const std::vector<ContactFeature> moving = contact_features(pair.moving);
  const std::vector<ContactFeature> fixed = contact_features(pair.fixed);
  std::vector<ContactSegment> out;
  for (const ContactFeature& m : moving)
    for (const ContactFeature& f : fixed) add_pair_contacts(pair, m, f, theta, out);
  return out;
}

bool same_bits(const Curve& a, const Curve& b) {
  return a.from == b.from && a.to == b.to && a.center == b.center && a.radius == b.radius &&
         a.start_angle == b.start_angle && a.sweep == b.sweep &&
         (a.bulge == b.bulge || (std::isinf(a.bulge) && a.bulge == b.bulge));
}

void expect_same_contacts(ContactMaker& maker, const Pair& pair, const std::string& what) {
  std::vector<ContactSegment> found;
  for (int k = 0; k < 16; ++k) {
    const double theta = -kPi + (k + 0.3) * kTwoPi / 16;
    maker.segments(theta, found);
    const std::vector<ContactSegment> all = every_pair(pair, theta);
    ASSERT_EQ(found.size(), all.size()) << what << " theta " << theta;
    for (size_t i = 0; i < all.size(); ++i) {
      EXPECT_EQ(found[i].moving_feature, all[i].moving_feature) << what << " segment " << i;
      EXPECT_EQ(found[i].fixed_feature, all[i].fixed_feature) << what << " segment " << i;
      EXPECT_EQ(found[i].kind, all[i].kind) << what << " segment " << i;
      EXPECT_EQ(found[i].is_point, all[i].is_point) << what << " segment " << i;
      EXPECT_TRUE(same_bits(found[i].curve, all[i].curve)) << what << " segment " << i;
    }
  }
}

}  // namespace

// Few fixed features (at most 64: the index's bitmask per bucket) and many (its lists per
// bucket, read back through a bitmap): both must find every pair that touches, in feature
// order, with the same curves to the bit.
TEST(SliceFastPaths, ContactIndexFindsEveryTouchingPair) {
  std::mt19937 rng(77);
  for (int i = 0; i < 8; ++i) {
    const testkit::RandomPair rp = testkit::random_pair(rng, 4 + i, 5 + i, i % 2 == 0);
    ASSERT_LE(rp.pair.fixed.feature_count(), 64);
    ContactMaker maker(rp.pair);
    expect_same_contacts(maker, rp.pair, "random pair " + std::to_string(i));
  }
  for (const double jitter : {0.0, 0.3 * kTwoPi / 60}) {
    const testkit::StarPairLoops loops = testkit::lobed_star_pair(rng, 60, jitter, 0.3);
    const Pair pair =
        testkit::parse_or_throw(testkit::pair_json("star", {loops.moving}, {loops.fixed}), "star");
    ASSERT_GT(pair.fixed.feature_count(), 64);
    ContactMaker maker(pair);
    expect_same_contacts(maker, pair, "star");
  }
}

// One maker reset from pair to pair (as compute_slice keeps one per thread) is a new maker
// each time: from few fixed features to many and back, with and without arcs, and from a
// rough pair (whose vertices' normals make the index's long runs) to smooth ones.
TEST(SliceFastPaths, AResetContactMakerIsANewOne) {
  std::mt19937 rng(78);
  std::vector<Pair> pairs;
  for (int i = 0; i < 3; ++i) {
    pairs.push_back(testkit::random_pair(rng, 5 + i, 6 + i, i == 1).pair);
    const testkit::StarPairLoops loops =
        testkit::lobed_star_pair(rng, 40 + 10 * i, i * 0.01, i == 2 ? 0.0 : 0.4);
    pairs.push_back(
        testkit::parse_or_throw(testkit::pair_json("star", {loops.moving}, {loops.fixed}), "star"));
    if (i < 2)
      pairs.push_back(testkit::accepted_star_pair(60, 0.3 * kTwoPi / 60, i * 0.4, 90 + unsigned(i),
                                                  1, 76, "rough")
                          .pair);
  }
  ContactMaker maker(pairs.back());
  for (size_t i = 0; i < pairs.size(); ++i) {
    maker.reset(pairs[i]);
    expect_same_contacts(maker, pairs[i], "pair " + std::to_string(i) + " after a reset");
  }
}

// Rays from one point O, so that many split points coincide there exactly, and two more
// segments starting near O: P within eps of O, Q within eps of P only. Exactly equal points
// are joined before the sweep, which then compares one of them for all: P must still join
// O's vertex, and Q through P.
TEST(SliceFastPaths, EqualPointsStillJoinNearOnes) {
  Tolerances tol;
  tol.geometric = 1e-6;
  tol.angular = 1e-7;
  const Vec2 o{1.0, 2.0};
  std::vector<Curve> curves;
  for (const double degrees : {100.0, 160.0, 200.0, 250.0, 300.0, 340.0})
    curves.push_back(make_segment(o, o + 3.0 * unit_vector(degrees * kPi / 180.0)));
  const Vec2 p = o + Vec2{0.5e-6, 0.0}, q = o + Vec2{1.3e-6, 0.0};
  curves.push_back(make_segment(p, {1.5, 5.0}));
  curves.push_back(make_segment(q, {4.0, 2.5}));
  std::vector<int> ids = own_ids(curves);
  ArrangementBuilder builder;
  const Arrangement& arr = builder.build(curves, ids, tol);
  int near_o = 0;
  for (const Vec2& v : arr.vertices) {
    if (distance(v, o) > 10 * tol.geometric) continue;
    ++near_o;
    EXPECT_TRUE(v == o);  // the cluster's first split point: the first ray's start
  }
  EXPECT_EQ(near_o, 1);
  EXPECT_EQ(arr.vertices.size(), curves.size() + 1);
  EXPECT_EQ(arr.edges.size(), curves.size());
  EXPECT_EQ(arr.outgoing(0).size(), curves.size());
}

// Segments meeting end to end share their ends bit for bit, and a touch there repeats the end
// points every curve starts with: no split point is added for it. A crossing inside both
// still adds its two, and the arrangement is the same closed chain with the crossing cut in.
TEST(SliceFastPaths, EndToEndTouchesAddNoSplitPoints) {
  const double eps = 1e-9;
  const std::vector<Vec2> corners{{0.1, 0.3}, {4.7, 0.9}, {3.3, 3.1}, {0.9, 2.7}};
  std::vector<Curve> chain;
  for (size_t i = 0; i < corners.size(); ++i)
    chain.push_back(make_segment(corners[i], corners[(i + 1) % corners.size()]));
  SplitScratch scratch;
  std::vector<SplitPoint> splits;
  split_points(chain, eps, scratch, splits);
  EXPECT_EQ(splits.size(), 2 * chain.size());  // the ends only

  chain.push_back(make_segment({2.0, -1.0}, {2.5, 1.5}));  // crosses the first edge
  split_points(chain, eps, scratch, splits);
  ASSERT_EQ(splits.size(), 2 * chain.size() + 2);
  EXPECT_EQ(splits[2 * chain.size()].met, 4);
  EXPECT_EQ(splits[2 * chain.size() + 1].met, 0);

  std::vector<int> ids = own_ids(chain);
  const Tolerances tol = with_geometric(eps);
  ArrangementBuilder builder;
  const Arrangement& arr = builder.build(chain, ids, tol);
  EXPECT_EQ(arr.vertices.size(), 7u);  // 4 corners, the crossing, the stick's 2 ends
  EXPECT_EQ(arr.edges.size(), 7u);
  EXPECT_EQ(arr.faces.size(), 2u);
}

// A hairpin: a and b meet end to end at P and run back side by side, 1e-4 rad apart (not
// collinear within eps). Alone, each has only its ends, and nothing is copied between them
// (the sharing step skips such curves). A segment c crossing a at X, within eps of b there,
// crosses b at X' 2.5e-3 away: X has no point of b near it, so it must still be copied onto
// b, as X' onto a. (Along a, and along c too: a sharing step that skipped a would not fail
// here, one that skipped every pair meeting at points would.)
TEST(SliceFastPaths, EndToEndNeighboursStillShareTheirOtherPoints) {
  const double eps = 1e-6;
  const Vec2 p{0.0, 0.0};
  const Curve a = make_segment({-1.0, 0.0}, p), b = make_segment(p, {-1.0, 1e-4});
  SplitScratch scratch;
  std::vector<SplitPoint> splits;
  split_points({a, b}, eps, scratch, splits);
  EXPECT_EQ(splits.size(), 4u);  // the ends only

  const double slope = 1e-4;  // c: y = slope (x + 5e-3), through X = (-5e-3, 0)
  const Curve c = make_segment({-0.1, slope * (-0.1 + 5e-3)}, {-0.001, slope * (-0.001 + 5e-3)});
  split_points({a, b, c}, eps, scratch, splits);
  const SplitPoint* x = nullptr;
  const SplitPoint* x_on_b = nullptr;
  for (const SplitPoint& s : splits) {
    if (s.met != 2 || s.how != Meeting::crossing) continue;  // (c's end touches both too)
    if (s.curve == 0) x = &s;
    if (s.curve == 1) x_on_b = &s;
  }
  ASSERT_NE(x, nullptr);
  ASSERT_NE(x_on_b, nullptr);
  EXPECT_NEAR(x->p.x, -5e-3, 1e-9);
  EXPECT_NEAR(x_on_b->p.x, -2.5e-3, 1e-9);
  bool x_copied_onto_b = false, x_on_b_copied_onto_a = false;
  for (const SplitPoint& s : splits) {
    x_copied_onto_b |= s.curve == 1 && s.p == x->p;
    x_on_b_copied_onto_a |= s.curve == 0 && s.p == x_on_b->p;
  }
  EXPECT_TRUE(x_copied_onto_b);
  EXPECT_TRUE(x_on_b_copied_onto_a);
}

// A slice's arrangement peels off edges dangling into blocked faces (slice/edge_pieces.hpp):
// a chain of one-sided segments meeting nothing else, and two segments crossing, go whole;
// a loop stays, as do the arms of three segments meeting at one point (a possible perfect
// fit) and a sliding fit (two coincident segments, blocked on both sides).
TEST(SliceFastPaths, DanglingEdgesArePeeledOffTheSlicesArrangement) {
  std::vector<Curve> curves;
  auto chain = [&](const std::vector<Vec2>& points, bool closed) {
    for (size_t i = 0; i + 1 < points.size(); ++i)
      curves.push_back(make_segment(points[i], points[i + 1]));
    if (closed) curves.push_back(make_segment(points.back(), points.front()));
  };
  chain({{0, 0}, {0, 10}, {10, 10}, {10, 0}}, true);           // the box around: 4 edges
  chain({{2, 2}, {3, 2.5}, {4, 2}, {5, 3}}, false);            // 3 edges, peeled
  chain({{2, 7}, {3, 7}, {2.5, 8}}, true);                     // a loop: 3 edges
  for (const Vec2 arm : {Vec2{8, 7}, Vec2{7, 8}, Vec2{6, 6}})  // a star: 3 edges
    curves.push_back(make_segment({7, 7}, arm));
  curves.push_back(make_segment({6, 2}, {8, 4}));  // a cross: 4 edges, peeled
  curves.push_back(make_segment({6, 4}, {8, 2}));
  curves.push_back(make_segment({12, 0}, {13, 0}));  // a sliding fit: 1 edge
  curves.push_back(make_segment({13, 0}, {12, 0}));
  std::vector<int> ids = own_ids(curves);
  const Tolerances tol = with_geometric(1e-9);
  ArrangementBuilder builder;
  const Arrangement& all = builder.build(curves, ids, tol);
  EXPECT_EQ(all.edges.size(), 18u);
  const size_t vertices = all.vertices.size(), faces = all.faces.size();
  EXPECT_EQ(faces, 3u);  // unbounded, the box's inside, the loop's inside
  const Arrangement& slice = builder.build(curves, ids, tol, nullptr, true);
  EXPECT_EQ(slice.edges.size(), 11u);
  EXPECT_EQ(slice.vertices.size(), vertices);
  EXPECT_EQ(slice.faces.size(), faces);
  for (const ArrangementEdge& e : slice.edges)
    for (const EdgeLabel& l : e.labels)
      EXPECT_TRUE(l.segment < 4 || (l.segment > 6 && l.segment < 13) || l.segment > 14)
          << l.segment;
  // A chain touching the loop: peeled too, having split the loop's edge.
  curves.push_back(make_segment({5, 3}, {2.5, 7.0 - 0.5e-9}));
  ids.push_back(int(ids.size()));
  EXPECT_EQ(builder.build(curves, ids, tol, nullptr, true).edges.size(), 12u);
  EXPECT_EQ(builder.build(curves, ids, tol).edges.size(), 20u);
}

// Where two one-sided segments cross at a point nothing else passes through, the piece of
// each that leaves the crossing into the other's blocked side (its left) has blocked faces
// on both hands, and a slice's arrangement leaves it out (slice/edge_pieces.hpp): here a,
// running right along y = 5, and b, running up along x = 5, inside a box they end on, lose
// a's piece left of x = 5 and b's piece above y = 5. A third segment through their crossing
// makes it no simple crossing, and every piece stays.
TEST(SliceFastPaths, PiecesInsideASimpleCrossingAreLeftOut) {
  std::vector<Curve> curves;
  const std::vector<Vec2> box{{0, 0}, {0, 10}, {10, 10}, {10, 0}};
  for (size_t i = 0; i < box.size(); ++i)
    curves.push_back(make_segment(box[i], box[(i + 1) % box.size()]));
  curves.push_back(make_segment({0, 5}, {10, 5}));  // a
  curves.push_back(make_segment({5, 0}, {5, 10}));  // b
  std::vector<int> ids = own_ids(curves);
  const Tolerances tol = with_geometric(1e-9);
  ArrangementBuilder builder;
  const Arrangement& all = builder.build(curves, ids, tol);
  EXPECT_EQ(all.edges.size(), 12u);  // the box's 4 edges cut in two, a and b in two each
  EXPECT_EQ(all.faces.size(), 5u);
  const Arrangement& slice = builder.build(curves, ids, tol, nullptr, true);
  ASSERT_EQ(slice.edges.size(), 10u);
  EXPECT_EQ(slice.faces.size(), 3u);  // unbounded, the quarter right of b below a, the rest
  for (const ArrangementEdge& e : slice.edges) {
    const Vec2 mid = point_at(e.curve, 0.5);
    const int segment = e.labels.front().segment;
    EXPECT_TRUE(segment != 4 || mid.x > 5.0);  // a's right half stays
    EXPECT_TRUE(segment != 5 || mid.y < 5.0);  // b's lower half stays
  }
  curves.push_back(make_segment({0, 0}, {10, 10}));  // through the crossing
  ids.push_back(int(ids.size()));
  EXPECT_EQ(builder.build(curves, ids, tol).edges.size(), 14u);
  EXPECT_EQ(builder.build(curves, ids, tol, nullptr, true).edges.size(), 14u);
}

// Slices with dangling edges (and the pieces inside simple crossings) peeled and kept are the
// same bit for bit, but for the blocked area's last bits (each dangling edge adds and takes
// back its area term, and merged faces sum theirs in another order): contact segments,
// realizable pieces, free components with their samples and boundaries, the contact graph and
// degenerate contacts. On rough stars (a third of their edges dangle), random curved pairs,
// designed pairs (perfect fits and sliding fits: vertices the peeling must stop at) and gears.
TEST(SliceFastPaths, PeelingDanglingEdgesChangesNoSlice) {
  struct PeelingGuard {
    ~PeelingGuard() { set_slice_peeling(true); }
  } guard;
  std::vector<Pair> pairs;
  for (int n : {20, 60, 120})
    pairs.push_back(
        testkit::accepted_star_pair(n, 0.3 * kTwoPi / n, 0.0, 500 + unsigned(n), 1, 76, "rough")
            .pair);
  pairs.push_back(testkit::curved_star_pair(40));
  std::mt19937 rng(23);
  for (int i = 0; i < 20; ++i)
    pairs.push_back(testkit::random_pair(rng, 4 + i % 6, 5 + i % 7, i % 3 == 0).pair);
  for (unsigned seed = 1; seed <= 80; ++seed) pairs.push_back(testkit::designed_pair(seed).pair);
  pairs.push_back(testkit::gear_pair(8));
  auto same_curve = [](const Curve& a, const Curve& b) {
    return a.from == b.from && a.to == b.to && a.center == b.center && a.radius == b.radius &&
           a.sweep == b.sweep;
  };
  int buried = 0;
  for (size_t p = 0; p < pairs.size(); ++p) {
    for (const double theta : {0.3, 1.1, 2.6, -2.0}) {
      set_slice_peeling(false);
      const Slice kept = compute_slice(pairs[p], theta);
      set_slice_peeling(true);
      const Slice peeled = compute_slice(pairs[p], theta);
      const std::string where = "pair " + std::to_string(p) + " theta " + std::to_string(theta);
      ASSERT_EQ(kept.contact_segments.size(), peeled.contact_segments.size()) << where;
      ASSERT_EQ(kept.realizable.size(), peeled.realizable.size()) << where;
      for (size_t i = 0; i < kept.realizable.size(); ++i) {
        EXPECT_EQ(kept.realizable[i].segment, peeled.realizable[i].segment) << where;
        EXPECT_TRUE(same_curve(kept.realizable[i].curve, peeled.realizable[i].curve)) << where;
      }
      ASSERT_EQ(kept.free_components.size(), peeled.free_components.size()) << where;
      for (size_t c = 0; c < kept.free_components.size(); ++c) {
        const FreeComponent &a = kept.free_components[c], &b = peeled.free_components[c];
        EXPECT_EQ(a.bounded, b.bounded) << where;
        EXPECT_TRUE(a.area == b.area || (std::isnan(a.area) && std::isnan(b.area))) << where;
        EXPECT_EQ(a.sample, b.sample) << where;
        ASSERT_EQ(a.boundary.size(), b.boundary.size()) << where;
        for (size_t k = 0; k < a.boundary.size(); ++k) {
          ASSERT_EQ(a.boundary[k].size(), b.boundary[k].size()) << where;
          for (size_t i = 0; i < a.boundary[k].size(); ++i)
            EXPECT_TRUE(same_curve(a.boundary[k][i].curve, b.boundary[k][i].curve)) << where;
        }
      }
      EXPECT_EQ(kept.contact_graph.nodes, peeled.contact_graph.nodes) << where;
      ASSERT_EQ(kept.contact_graph.edges.size(), peeled.contact_graph.edges.size()) << where;
      for (size_t i = 0; i < kept.contact_graph.edges.size(); ++i) {
        EXPECT_EQ(kept.contact_graph.edges[i].a, peeled.contact_graph.edges[i].a) << where;
        EXPECT_EQ(kept.contact_graph.edges[i].b, peeled.contact_graph.edges[i].b) << where;
        EXPECT_EQ(kept.contact_graph.edges[i].at, peeled.contact_graph.edges[i].at) << where;
      }
      ASSERT_EQ(kept.degenerate.size(), peeled.degenerate.size()) << where;
      for (size_t i = 0; i < kept.degenerate.size(); ++i)
        EXPECT_EQ(kept.degenerate[i].segments, peeled.degenerate[i].segments) << where;
      if (std::isinf(kept.blocked_area))
        EXPECT_EQ(kept.blocked_area, peeled.blocked_area) << where;
      else
        EXPECT_NEAR(kept.blocked_area, peeled.blocked_area,
                    1e-12 * std::max(1.0, std::fabs(kept.blocked_area)))
            << where;
      // Contact segments wholly in blocked space, where edges dangle: enough to matter.
      buried += int(kept.contact_segments.size() - realizable_segments(kept).size());
    }
  }
  EXPECT_GT(buried, 2000);
}

// compute_slice keeps its buffers on the thread between calls, up to about 64 MB: those of a
// rough star pair of 4,000 features (58,000 contact segments, bounded at 57 MB) are kept, a
// rough pair of 8,000 features (250,000 segments) lets them go. Measured as the heap in use
// with the slice itself gone (glibc's count; each test runs in a process of its own).
TEST(SliceFastPaths, OneShotSlicesKeepAtMost64MBOfBuffers) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the address sanitizer's allocator keeps its own heap, which glibc's count "
                  "does not see";
#endif
  auto heap_in_use = [] {
    const struct mallinfo2 m = mallinfo2();
    return double(m.uordblks + m.hblkhd) / double(1 << 20);
  };
  auto rough_star = [](int n) {
    return testkit::accepted_star_pair(n, 0.3 * kTwoPi / n, 0.0, 2026 + unsigned(n), 1, 76, "star")
        .pair;
  };
  const Pair kept = rough_star(1000), released = rough_star(2000);
  const double start = heap_in_use();
  ASSERT_GT(compute_slice(kept, 0.7).contact_segments.size(), 50000u);
  const double after_kept = heap_in_use() - start;
  EXPECT_GT(after_kept, 16.0) << "the buffers were released, or never grew";
  EXPECT_LE(after_kept, 64.0) << "kept_bytes in slice.cpp no longer bounds what is kept";
  ASSERT_GT(compute_slice(released, 0.7).contact_segments.size(), 200000u);
  EXPECT_LT(heap_in_use() - start, 8.0) << "a slice over the budget kept its buffers";
}

// The slice's sorts pick std::sort for keys in long runs and the branch-free pdqsort for
// short ones: both kinds of key order are told apart, and sorted either way.
TEST(SliceFastPaths, SortByRunsTellsRunLengthsAndSortsBoth) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> step(0.1, 1.0);
  // Runs of 8 rising and falling in turn (a smooth contour's keys), and shuffled keys.
  std::vector<double> runs;
  double x = 0.0;
  for (int run = 0; run < 40; ++run)
    for (int k = 0; k < 8; ++k) runs.push_back(x += (run % 2 == 0 ? 1.0 : -0.9) * step(rng));
  std::vector<double> shuffled = runs;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  const std::less<double> less;
  EXPECT_FALSE(has_short_runs(runs.begin(), runs.end(), less));
  EXPECT_TRUE(has_short_runs(shuffled.begin(), shuffled.end(), less));
  for (std::vector<double>* keys : {&runs, &shuffled}) {
    std::vector<double> expected = *keys;
    std::sort(expected.begin(), expected.end());
    sort_by_runs(keys->begin(), keys->end(), less);
    EXPECT_EQ(*keys, expected);
  }
}

// sort_by_coordinate sorts whatever the keys' spread: uniform, bunched into a few values far
// apart (most buckets empty, a few full), repeated exactly, one or none; with an infinite
// or NaN key it leaves the buckets to sort_by_runs. The items are indices, sorted by keys
// looked up, as the slice's boxes and points are.
TEST(SliceFastPaths, SortByCoordinateSortsEverySpread) {
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::vector<double>> cases;
  cases.emplace_back();
  for (int i = 0; i < 500; ++i) cases.back().push_back(100.0 * unit(rng));
  cases.emplace_back();
  for (int i = 0; i < 500; ++i) cases.back().push_back(1e6 * (i % 4) + 1e-9 * unit(rng));
  cases.emplace_back(300, 2.5);
  cases.push_back({7.0});
  cases.emplace_back();
  cases.push_back(cases[0]);
  cases.back()[17] = std::numeric_limits<double>::infinity();
  cases.back()[18] = -std::numeric_limits<double>::infinity();
  BucketSortBuffers<int> buffers;
  for (const std::vector<double>& keys : cases) {
    std::vector<int> order(keys.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    sort_by_coordinate(
        order, [&](int i) { return keys[size_t(i)]; }, buffers);
    std::vector<int> sorted_ids = order;
    std::sort(sorted_ids.begin(), sorted_ids.end());
    for (size_t i = 0; i < sorted_ids.size(); ++i) ASSERT_EQ(sorted_ids[i], int(i));
    for (size_t i = 1; i < order.size(); ++i)
      ASSERT_LE(keys[size_t(order[i - 1])], keys[size_t(order[i])]) << i;
  }
  std::vector<double> with_nan = cases[0];
  with_nan[3] = std::nan("");
  std::vector<int> order(with_nan.size());
  std::iota(order.begin(), order.end(), 0);
  sort_by_coordinate(
      order, [&](int i) { return with_nan[size_t(i)]; }, buffers);
  EXPECT_EQ(order.size(), with_nan.size());  // sorted as sort_by_runs sorts a NaN: no crash
}
