// The criticality equations against the geometry they describe: the closed forms of the pair
// equations (an end on a curve, two curves tangent) evaluated at many orientations against the
// contact curves rebuilt there, and roots sought only within windows of orientations against
// the roots over the whole turn. Also the crossings of whole curves that bound where triples
// can meet, against the general intersection of the same curves.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "criticals/candidates.hpp"
#include "criticals/events.hpp"
#include "criticals/families.hpp"
#include "criticals/trig.hpp"
#include "support/random_parts.hpp"

using namespace cslice;

namespace {

// A family's curve at theta, rebuilt from its moving points (not from its equation).
struct CurveAt {
  bool circle = false;
  Vec2 point, normal;  // lines
  Vec2 centre;         // circles
  double radius = 0.0;
};
CurveAt curve_at(const ContactFamily& f, double theta) {
  CurveAt c;
  if (f.shape == FamilyShape::circle) {
    c.circle = true;
    c.centre = f.center.at(theta);
    c.radius = f.radius;
    return c;
  }
  c.point = f.ends[0].at(theta);
  c.normal = normalized(perp_left(f.ends[1].at(theta) - c.point));
  return c;
}

// |x - C|^2 - r^2 on a circle, n . (x - p) on a line.
double on_curve(const CurveAt& c, Vec2 x) {
  return c.circle ? length_squared(x - c.centre) - c.radius * c.radius : dot(c.normal, x - c.point);
}

std::vector<Pair> random_pairs(int count) {
  std::vector<Pair> out;
  for (int seed = 0; seed < count; ++seed) {
    std::mt19937 rng(500 + seed);
    out.push_back(testkit::random_pair(rng, 3 + seed % 5, 4 + seed % 7, seed % 2 == 0).pair);
  }
  return out;
}

}  // namespace

TEST(CriticalEquations, PairEquationsMatchTheContactCurvesAtEveryOrientation) {
  int checked = 0;
  for (const Pair& pair : random_pairs(12)) {
    const std::vector<ContactFamily> families = contact_families(pair);
    std::vector<FamilyEquation> equations;
    for (const ContactFamily& f : families) equations.push_back(family_equation(f));
    for (size_t a = 0; a < families.size(); ++a)
      for (size_t b = 0; b < families.size(); ++b) {
        std::array<EventEquation, 2> tangents;
        const int n = tangent_equations(equations[a], equations[b], tangents);
        for (double theta = -3.1; theta < 3.1; theta += 0.37) {
          const CurveAt ca = curve_at(families[a], theta), cb = curve_at(families[b], theta);
          for (const MovingPoint& end : families[a].ends) {
            const EventEquation e = endpoint_equation(end, equations[b]);
            EXPECT_NEAR(e.f(theta), on_curve(cb, end.at(theta)), 1e-12 * e.magnitude);
            ++checked;
          }
          if (n == 0) continue;
          // Tangency: the signed distance of a centre from a line is +-r, or two centres are
          // r1 + r2 or |r1 - r2| apart.
          double expected[2];
          if (ca.circle && cb.circle) {
            const double d2 = length_squared(ca.centre - cb.centre);
            expected[0] = d2 - (ca.radius + cb.radius) * (ca.radius + cb.radius);
            expected[1] = d2 - (ca.radius - cb.radius) * (ca.radius - cb.radius);
          } else {
            const CurveAt& line = ca.circle ? cb : ca;
            const CurveAt& circle = ca.circle ? ca : cb;
            const double reach = on_curve(line, circle.centre);
            expected[0] = reach - circle.radius;
            expected[1] = reach + circle.radius;
          }
          ASSERT_EQ(n, 2);
          for (int k = 0; k < 2; ++k)
            EXPECT_NEAR(tangents[size_t(k)].f(theta), expected[k],
                        1e-12 * tangents[size_t(k)].magnitude);
        }
      }
  }
  EXPECT_GT(checked, 10000);
}

TEST(CriticalEquations, RootsWithinWindowsAreTheRootsThere) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0), angle(-kPi, kPi), width(0.01, 0.8);
  int compared = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Trig f;
    f.top = 2 + trial % 2;
    for (int j = 0; j <= f.top; ++j) {
      f.a[size_t(j)] = u(rng);
      if (j > 0) f.b[size_t(j)] = u(rng);
    }
    const std::array<AngleWindow, 2> windows{{{angle(rng), width(rng)}, {angle(rng), width(rng)}}};
    const int count = 1 + trial % 2;
    const TrigRoots all = trig_roots(f, 0.0, 1e-9, 1e-9);
    const TrigRoots within = trig_roots_within(f, 0.0, 1e-9, 1e-9, windows.data(), count);
    // Every root inside a window (clear of its edges, where the two may differ by round-off)
    // is found, at the same orientation.
    for (double root : all.roots) {
      bool inside = false;
      for (int w = 0; w < count; ++w)
        inside |=
            std::fabs(wrap_angle(root - windows[size_t(w)].mid)) < windows[size_t(w)].half - 1e-6;
      if (!inside) continue;
      double best = kPi;
      for (double r : within.roots) best = std::min(best, std::fabs(wrap_angle(r - root)));
      EXPECT_LE(best, 1e-9) << "trial " << trial << " root " << root;
      ++compared;
    }
  }
  EXPECT_GT(compared, 500);
}

TEST(CriticalEquations, AWindowReachingAChartBorderFindsTheRootOnIt) {
  // cos(theta) (1 + sin(theta) / 2) = cos + sin(2 theta) / 4 vanishes at -pi/2 and pi/2,
  // the borders between the two charts; tan(pi / 4) rounds below 1.
  Trig f;
  f.top = 2;
  f.a[1] = 1.0;
  f.b[2] = 0.25;
  for (double border : {-0.5 * kPi, 0.5 * kPi})
    for (double offset : {-0.03, 0.0, 0.03}) {
      const AngleWindow window{border + offset, 0.05};
      const TrigRoots r = trig_roots_within(f, 0.0, 1e-9, 1e-9, &window, 1);
      double best = kPi;
      for (double root : r.roots) best = std::min(best, std::fabs(wrap_angle(root - border)));
      EXPECT_LE(best, 1e-12) << "border " << border << " offset " << offset;
    }
}

TEST(CriticalEquations, WholeCurvesCrossWhereTheirIntersectionSays) {
  // Lines through random segments, circles of random arcs; the general intersection of the
  // same whole curves (lines drawn 4 sizes past their ends, full circles) is the reference.
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0), radius(0.05, 1.5);
  const double size = 4.0, eps = 1e-9 * size;
  auto random_cover = [&](bool arc) {
    if (arc) return make_arc({u(rng), u(rng)}, radius(rng), kPi * u(rng), 2.0 * u(rng));
    return make_segment({u(rng), u(rng)}, {u(rng), u(rng)});
  };
  auto whole = [&](const Curve& c) {
    if (c.is_arc()) return make_circle(c.center, c.radius);
    const Vec2 reach = (4.0 * size / distance(c.from, c.to)) * (c.to - c.from);
    return make_segment(c.from - reach, c.to + reach);
  };
  int crossings = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Curve x = random_cover(trial % 2 == 1), y = random_cover(trial % 4 >= 2);
    CurveCrossings mine;
    const bool crossed = whole_curves_cross(x, y, size, eps, mine);
    const Curve wx = whole(x), wy = whole(y);
    const Intersection ref = intersect(wx, wy, eps);
    if (ref.kind == IntersectionKind::none || ref.kind == IntersectionKind::overlapping ||
        ref.kind == IntersectionKind::tangent) {
      EXPECT_FALSE(crossed && ref.kind == IntersectionKind::overlapping) << trial;
      continue;
    }
    ASSERT_TRUE(crossed) << "trial " << trial;
    ASSERT_EQ(mine.count, ref.count) << "trial " << trial;
    for (int h = 0; h < ref.count; ++h) {
      const IntersectionHit& hit = ref.hits[size_t(h)];
      const double sine = std::fabs(cross(tangent_at(wx, hit.ta0), tangent_at(wy, hit.tb0)));
      int k = distance(mine.point[0], hit.point) <= distance(mine.point[1], hit.point) ? 0 : 1;
      if (mine.count == 1) k = 0;
      EXPECT_LE(distance(mine.point[size_t(k)], hit.point), 1e-9) << "trial " << trial;
      EXPECT_NEAR(mine.sine[size_t(k)], sine, 1e-9) << "trial " << trial;
      ++crossings;
    }
  }
  EXPECT_GT(crossings, 2000);
}

TEST(CriticalBins, EveryBinListsTheFamiliesAliveInIt) {
  // The families listed alive in each bin, found from each family's alive interval, over the
  // whole turn and over arcs starting anywhere (across the turn's seam too), as a symmetric
  // pair's fundamental domain gets them: a random pair's families against orientations
  // sampled across the bin, and, with them, families that start or end exactly where the bins
  // start or end against the rule itself (a closed bin touching the interval counts), which
  // the samples cannot settle to round-off.
  int listed = 0, arcs = 0;
  for (unsigned seed = 0; seed < 16; ++seed) {
    const std::vector<ContactFamily> drawn = contact_families(testkit::stress_pair(seed).pair);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> from(-kPi, kPi), span(0.05, 0.99 * kTwoPi);
    for (int trial = 0; trial < 6; ++trial) {
      const int bins = 1 + int(rng() % 40);
      const Binning binning = trial == 0 ? Binning(bins) : Binning(bins, from(rng), span(rng));
      arcs += binning.whole_turn ? 0 : 1;
      std::vector<ContactFamily> families = drawn;
      for (double end : {binning.from, binning.from + binning.count * binning.width})
        for (double lo : {end, end - 0.3}) {
          families.emplace_back();
          families.back().alive = {wrap_angle(lo), 0.3};
        }
      const std::vector<std::vector<int>> alive = alive_families_by_bin(families, binning);
      ASSERT_EQ(alive.size(), size_t(binning.count));
      for (int b = 0; b < binning.count; ++b) {
        const std::vector<int>& in_bin = alive[size_t(b)];
        listed += int(in_bin.size());
        ASSERT_TRUE(std::is_sorted(in_bin.begin(), in_bin.end()));
        // bin_of puts the bin's middle in it.
        EXPECT_EQ(binning.bin_of(binning.lower(b) + 0.5 * binning.width), b);
        const auto where = [&](size_t i) {
          return "seed " + std::to_string(seed) + " trial " + std::to_string(trial) + " bin " +
                 std::to_string(b) + " family " + std::to_string(i);
        };
        for (size_t i = 0; i < families.size(); ++i) {
          const bool is_listed = std::binary_search(in_bin.begin(), in_bin.end(), int(i));
          if (i >= drawn.size()) {
            EXPECT_EQ(is_listed,
                      alive_within(families[i], binning.lower(b), binning.lower(b) + binning.width))
                << where(i);
            continue;
          }
          for (int k = 0; k <= 8; ++k) {
            const double theta = binning.lower(b) + binning.width * k / 8.0;
            if (!alive_at(families[i], theta, 0.0)) continue;
            EXPECT_TRUE(is_listed) << where(i) << " alive at " << theta;
            break;
          }
        }
      }
      if (binning.whole_turn) continue;
      // Off the arc, the bin at its nearer end.
      const double end = binning.from + binning.count * binning.width;
      const double gap = kTwoPi - binning.count * binning.width;
      EXPECT_EQ(binning.bin_of(end + 0.25 * gap), binning.count - 1);
      EXPECT_EQ(binning.bin_of(binning.from - 0.25 * gap), 0);
    }
  }
  EXPECT_EQ(arcs, 16 * 5);
  EXPECT_GT(listed, 10000);
}
