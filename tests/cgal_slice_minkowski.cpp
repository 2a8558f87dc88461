// The slice against CGAL's Minkowski sum, for polygonal pairs.
//
// For straight-edged parts, blocked space at theta is the interior of F + (-R(theta) M): the
// fixed polygon plus the moving polygon turned by theta and reflected through its origin.
// CGAL computes that sum exactly (reduced convolution, exact-constructions kernel) from the
// same double coordinates the pair file holds, independently of every cslice routine: the
// rotation is done here in double, the reflection p -> -p is exact, everything after that is
// exact arithmetic. Two numbers are compared:
//   - bounded free components of the slice == holes of the sum (a hole is a pocket of free
//     placements that cannot escape); holes and components of negligible area (below
//     kNegligibleArea times the sum's area: slivers from near-tangencies, which cslice's
//     epsilon may legitimately close) are left out on both sides and counted;
//   - slice.blocked_area == area of the sum (outer boundary minus holes), relative 1e-9.
// CGAL 5.5 (Debian 12) has a known bug in the reduced convolution: it loses holes in rare
// cases (CGAL issue #5830, fixed in 5.6: "Fixed a bug that made holes in the Minkowski sum
// disappear"). So when the slice and the reduced convolution disagree, the full convolution
// (another exact CGAL algorithm, without the faulty hole filter) decides; such cases are
// counted, and one found here is kept as a fixed regression case.
// Pairs come from random star polygons (spiky, non-convex) and from combs whose capped
// teeth leave pockets with narrow mouths, against small stars and rectangles: those give
// sums with holes, and the test insists that enough of them do.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/minkowski_sum_2.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cslice/slice.hpp"
#include "support/random_polygons.hpp"

namespace {

using namespace cslice;
using namespace cslice::testkit;
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

constexpr double kRelativeAreaTolerance = 1e-9;
constexpr double kNegligibleArea = 1e-9;  // of the sum's area

// A counterclockwise simple CGAL polygon from loop vertices mapped by f (bulges must be 0).
template <class F>
Polygon to_cgal(const LoopVertices& loop, F f) {
  Polygon p;
  for (const LoopVertex& v : loop) {
    const Vec2 q = f(Vec2{v.x, v.y});
    p.push_back(Kernel::Point_2(q.x, q.y));
  }
  if (!p.is_simple()) throw std::runtime_error("generator made a non-simple polygon");
  if (p.is_clockwise_oriented()) p.reverse_orientation();
  return p;
}

struct SumFacts {
  double area = 0.0;  // outer boundary minus holes
  int holes = 0;      // of non-negligible area
  int negligible_holes = 0;
};

enum class Method { reduced_convolution, full_convolution };

// F + (-R(theta) M), by CGAL, exactly from the double coordinates.
SumFacts cgal_blocked_space(const LoopVertices& moving, const LoopVertices& fixed, double theta,
                            Method method = Method::reduced_convolution) {
  const double c = std::cos(theta), s = std::sin(theta);
  const Polygon f = to_cgal(fixed, [](Vec2 p) { return p; });
  // Rotate as cslice's Transform does (c x - s y, s x + c y), then reflect (exact).
  const Polygon m = to_cgal(moving, [&](Vec2 p) {
    return Vec2{-(c * p.x - s * p.y), -(s * p.x + c * p.y)};
  });
  const PolygonWithHoles sum = method == Method::reduced_convolution
                                   ? CGAL::minkowski_sum_by_reduced_convolution_2(f, m)
                                   : CGAL::minkowski_sum_by_full_convolution_2(f, m);
  const double outer = CGAL::to_double(sum.outer_boundary().area());
  std::vector<double> holes;
  for (auto h = sum.holes_begin(); h != sum.holes_end(); ++h)
    holes.push_back(std::fabs(CGAL::to_double(h->area())));
  SumFacts facts;
  facts.area = outer;
  for (double a : holes) facts.area -= a;
  for (double a : holes)
    (a <= kNegligibleArea * facts.area ? facts.negligible_holes : facts.holes)++;
  return facts;
}

struct Tally {
  int pairs = 0;
  int pairs_with_holes = 0;
  int holes = 0;
  int negligible_cgal_holes = 0;
  int negligible_components = 0;
  int reduced_convolution_wrong = 0;  // CGAL #5830: settled by the full convolution
  int failures = 0;
  double slice_seconds = 0.0;
  double cgal_seconds = 0.0;

  void print(const char* what) const {
    std::cout << what << ": " << pairs << " pairs, " << pairs_with_holes << " with holes (" << holes
              << " holes); negligible holes skipped: " << negligible_cgal_holes << " (CGAL), "
              << negligible_components
              << " (slice); reduced convolution lost holes (full convolution agreed with the "
                 "slice): "
              << reduced_convolution_wrong << "; time slice " << slice_seconds << " s, CGAL "
              << cgal_seconds << " s\n";
  }
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct SliceFacts {
  double area = 0.0;
  int bounded = 0;  // bounded free components of non-negligible area
  int negligible = 0;
};

SliceFacts slice_facts(const Slice& slice, double sum_area) {
  SliceFacts facts{slice.blocked_area, 0, 0};
  for (const FreeComponent& c : slice.free_components)
    if (c.bounded) (c.area <= kNegligibleArea * sum_area ? facts.negligible : facts.bounded)++;
  return facts;
}

bool agree(const SliceFacts& slice, const SumFacts& sum) {
  return slice.bounded == sum.holes &&
         std::fabs(slice.area - sum.area) <= kRelativeAreaTolerance * std::fabs(sum.area);
}

// Compares one pair at one theta; failures print the pair file and theta to reproduce.
void check_pair(const LoopVertices& moving, const LoopVertices& fixed, double theta, Tally& tally) {
  const std::string json = pair_json("minkowski", {moving}, {fixed});
  const Pair pair = parse_or_throw(json, "minkowski");

  auto t0 = std::chrono::steady_clock::now();
  const Slice slice = compute_slice(pair, theta);
  tally.slice_seconds += seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  SumFacts sum = cgal_blocked_space(moving, fixed, theta);
  tally.cgal_seconds += seconds_since(t0);
  SliceFacts ours = slice_facts(slice, sum.area);
  if (!agree(ours, sum)) {
    const SumFacts full = cgal_blocked_space(moving, fixed, theta, Method::full_convolution);
    ours = slice_facts(slice, full.area);
    if (agree(ours, full)) {
      ++tally.reduced_convolution_wrong;
      std::ostringstream note;  // not std::cout: setprecision would stick to it
      note << "note: CGAL reduced convolution gave " << sum.holes << " holes, area "
           << std::setprecision(17) << sum.area << "; full convolution " << full.holes
           << " holes, area " << full.area << ", as the slice (theta " << theta << "):\n"
           << json << "\n";
      std::cout << note.str();
    }
    sum = full;
  }
  ++tally.pairs;
  tally.holes += sum.holes;
  tally.negligible_cgal_holes += sum.negligible_holes;
  tally.negligible_components += ours.negligible;
  if (sum.holes > 0) ++tally.pairs_with_holes;
  if (agree(ours, sum)) return;
  ++tally.failures;
  if (tally.failures > 5) return;  // enough to debug with; the count says how many more
  ADD_FAILURE() << "theta " << std::setprecision(17) << theta << "\nbounded free components "
                << ours.bounded << ", CGAL holes " << sum.holes << "\nblocked area " << ours.area
                << ", CGAL area " << sum.area << " (relative error "
                << std::fabs(ours.area - sum.area) / std::fabs(sum.area) << ")\npair: " << json;
}

StarOptions rough_star(std::mt19937& rng, int vertices, double radius) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  StarOptions o;
  o.vertices = vertices;
  o.radius = radius;
  o.radial_jitter = 0.15 + 0.5 * u(rng);
  o.angle_jitter = 0.8;
  if (u(rng) < 0.3) {  // some lobed ones: long concave stretches
    o.lobes = 1 + int(3 * u(rng));
    o.lobe_depth = 0.3;
  }
  return o;
}

// Moving parts for the combs: a small rough star or a rectangle around the part size, with
// the body origin somewhere near (not necessarily inside) it.
LoopVertices small_part(std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vec2 origin_offset{size * (u(rng) - 0.5), size * (u(rng) - 0.5)};
  if (u(rng) < 0.5) {
    return rectangle(size * (0.7 + 0.5 * u(rng)), size * (0.6 + 0.5 * u(rng)), origin_offset,
                     kTwoPi * u(rng));
  }
  StarOptions o;
  o.vertices = 3 + int(10 * u(rng));
  o.radius = size * (0.4 + 0.25 * u(rng));
  o.radial_jitter = 0.25;
  o.center = origin_offset;
  return random_star(rng, o);
}

CombOptions comb_options(std::mt19937& rng, int teeth) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  CombOptions o;
  o.teeth = teeth;
  o.part_size = 1.0;
  o.turn = kTwoPi * u(rng);
  o.offset = {4.0 * (u(rng) - 0.5), 4.0 * (u(rng) - 0.5)};
  return o;
}

TEST(SliceMinkowski, RandomStarPairsMatchCgal) {
  std::mt19937 rng(20261121);
  std::uniform_real_distribution<double> u(0.0, 1.0), angle(-kPi, kPi);
  Tally tally;
  for (int i = 0; i < 800; ++i) {
    const int fixed_n = 5 + int(56 * u(rng));   // 5 .. 60
    const int moving_n = 5 + int(26 * u(rng));  // 5 .. 30
    StarOptions fo = rough_star(rng, fixed_n, 3.0);
    StarOptions mo = rough_star(rng, moving_n, 0.5 + u(rng));
    mo.center = {0.6 * (u(rng) - 0.5), 0.6 * (u(rng) - 0.5)};
    const LoopVertices fixed = random_star(rng, fo);
    const LoopVertices moving = random_star(rng, mo);
    check_pair(moving, fixed, angle(rng), tally);
  }
  tally.print("stars");
  EXPECT_EQ(tally.failures, 0);
  EXPECT_EQ(tally.pairs, 800);
}

TEST(SliceMinkowski, CombsCatchingSmallPartsMatchCgalWithHoles) {
  std::mt19937 rng(1121);
  std::uniform_real_distribution<double> u(0.0, 1.0), angle(-kPi, kPi);
  Tally tally;
  for (int i = 0; i < 800; ++i) {
    const int teeth = 1 + i % 7;  // 12 .. 60 vertices
    const LoopVertices comb = random_comb(rng, comb_options(rng, teeth));
    const LoopVertices part = small_part(rng, 1.0);
    check_pair(part, comb, angle(rng), tally);
  }
  tally.print("fixed combs");
  EXPECT_EQ(tally.failures, 0);
  EXPECT_GE(tally.pairs_with_holes, 100);
}

// The comb moves and the small part is fixed: holes again (the small part caught in a
// pocket), now through the reflection of the moving part.
TEST(SliceMinkowski, MovingCombsAroundSmallPartsMatchCgalWithHoles) {
  std::mt19937 rng(2611);
  std::uniform_real_distribution<double> u(0.0, 1.0), angle(-kPi, kPi);
  Tally tally;
  for (int i = 0; i < 500; ++i) {
    const int teeth = 1 + i % 7;
    CombOptions o = comb_options(rng, teeth);
    o.offset = {-2.0 - 2.0 * u(rng), -1.0 - 2.0 * u(rng)};  // origin near the comb's pockets
    const LoopVertices comb = random_comb(rng, o);
    LoopVertices part = small_part(rng, 1.0);
    check_pair(comb, part, angle(rng), tally);
  }
  tally.print("moving combs");
  EXPECT_EQ(tally.failures, 0);
  EXPECT_GE(tally.pairs_with_holes, 100);
}

// Comb against comb: bigger sums, pockets on both sides.
TEST(SliceMinkowski, CombPairsMatchCgal) {
  std::mt19937 rng(5511);
  std::uniform_real_distribution<double> u(0.0, 1.0), angle(-kPi, kPi);
  Tally tally;
  for (int i = 0; i < 200; ++i) {
    const LoopVertices fixed = random_comb(rng, comb_options(rng, 1 + i % 7));
    CombOptions o = comb_options(rng, 1 + i % 3);
    o.part_size = 0.5;
    o.offset = {-1.0 * u(rng), -1.0 * u(rng)};
    const LoopVertices moving = random_comb(rng, o);
    check_pair(moving, fixed, angle(rng), tally);
  }
  tally.print("comb pairs");
  EXPECT_EQ(tally.failures, 0);
}

// Found by MovingCombsAroundSmallPartsMatchCgalWithHoles: a comb moving around a small
// quadrilateral. The slice has two pockets (areas 0.7287 and 0.0075); CGAL 5.5's reduced
// convolution reports only the big one, while its full convolution and its decomposition
// methods report both, with the slice's area to 1e-15. The placed comb at the small pocket's
// sample point does not meet the quadrilateral (checked with CGAL::do_intersect).
TEST(SliceMinkowski, SmallPocketThatCgalReducedConvolutionLoses) {
  const double theta = 2.1942759068779596;
  const std::vector<Vec2> comb{
      {-2.6800157343756625, -2.181580740048389},  {-5.3313955138180305, 10.428317546131765},
      {-6.497503280086518, 10.183129640411428},   {-6.278696002771135, 9.142487506600148},
      {-9.228122867814086, 8.52233573586863},     {-9.354096521245872, 9.12146339341131},
      {-9.553298212669775, 9.079578889295133},    {-9.24899434611524, 7.6323170390327455},
      {-9.049792654691334, 7.6742015431489214},   {-9.138448802132697, 8.095848042208843},
      {-6.189021937089745, 8.71599981294036},     {-6.034462767523017, 7.980920130073198},
      {-8.069939321502655, 7.552937187287268},    {-8.169247443800064, 7.2962487497438175},
      {-8.2196254691594, 7.049848441944439},      {-8.172143300642592, 6.824024393633202},
      {-8.026800938249636, 6.618776604810106},    {-7.8325284789186105, 6.423816945731083},
      {-5.797051924938971, 6.851799888517013},    {-5.5417524269751075, 5.637601633405384},
      {-7.594672518014228, 5.205950981301596},    {-7.650984557799499, 5.473769684410566},
      {-8.018557155128612, 5.39648321231399},     {-7.7165687627591515, 3.960233701432207},
      {-7.34899616543004, 4.037520173528783},     {-7.497381443501676, 4.743236977344578},
      {-5.444461352462556, 5.174887629448367},    {-5.150010802333755, 3.7744879144686916},
      {-8.232343712199482, 3.1263910809133932},   {-8.337363320600264, 2.8968663335304017},
      {-8.393452832062973, 2.677629715891481},    {-8.351682149649537, 2.478969357740703},
      {-8.212051273359958, 2.3008852590780666},   {-8.023490300132305, 2.133089290159501},
      {-4.941157390266579, 2.7811861237147992},   {-4.587072742494968, 1.0971680785756748},
      {-6.992031004466816, 0.591497250668735},    {-7.104970642153696, 1.1286354436774788},
      {-7.467658667633912, 1.0523760103989392},   {-7.174725540826308, -0.340806875861696},
      {-6.812037515346092, -0.26454744258315666}, {-6.86952491039011, 0.008861221789696838},
      {-4.464566648418263, 0.5145320496966366},   {-4.118283249029955, -1.1323834462786806},
      {-7.32845273422648, -1.8073594269304074},   {-7.4103014061932475, -1.4180891170478525},
      {-7.719482187953376, -1.4830980215089933},  {-7.351537851763926, -3.233032410501301},
      {-7.042357070003797, -3.1680235060401603},  {-7.166514715961348, -2.5775327362472495},
      {-3.956345230764824, -1.9025567555955227},  {-3.84612350064415, -2.4267686457687256}};
  const std::vector<Vec2> quad{{0.24207488305340774, -0.12072575055280879},
                               {-0.4251441465138306, 0.340280624632424},
                               {-0.8340476564498981, -0.25152941915831095},
                               {-0.16682862688265976, -0.7125357943435437}};
  auto loop = [](const std::vector<Vec2>& pts) {
    LoopVertices l;
    for (Vec2 p : pts) l.push_back({p.x, p.y, 0.0});
    return l;
  };
  const LoopVertices moving = loop(comb), fixed = loop(quad);
  const Slice slice =
      compute_slice(parse_or_throw(pair_json("pocket", {moving}, {fixed}), "pocket"), theta);
  const SumFacts full = cgal_blocked_space(moving, fixed, theta, Method::full_convolution);
  const SliceFacts ours = slice_facts(slice, full.area);
  EXPECT_EQ(ours.bounded, 2);
  EXPECT_EQ(full.holes, 2);
  EXPECT_NEAR(ours.area, full.area, kRelativeAreaTolerance * full.area);
  const SumFacts reduced = cgal_blocked_space(moving, fixed, theta);
  std::cout << "CGAL reduced convolution: " << reduced.holes
            << " holes (2 when CGAL #5830 is fixed)\n";
}

// Bugs in compute_slice found while benchmarking curved stars (bench_slice, BM_SliceCurved),
// reduced to a few vertices. Two moving arcs whose normal ranges overlap (the vertex
// between them is slightly reflex) rest on one fixed segment: their two contact lines are
// parallel and closer than the geometric epsilon, so they share end vertices, while a third
// contact segment crossing both at a shallow angle cuts them at two distinct vertices (far
// more than epsilon apart). The pieces between are ordered inconsistently around those
// vertices, the face walk leaks from blocked space into the unbounded face, and the slice
// comes out with no free component at all and an infinite blocked area, although the fixed
// part is a solid quadrilateral (any far placement is free).
TEST(SliceMinkowskiBugs, NearlyCoincidentContactLinesCutByATransversal) {
  const struct {
    const char* json;
    double theta;
  } cases[] = {
      {R"({"name": "lens", "moving": {"loops": [[[-0.14986872422785114, -1.1763358321974073,
          0.005056220228118099], [-0.08896289356070611, -1.1564861128624602,
          0.0014878581400887805], [-0.0764877696735646, -1.1522493103209583],
          [0.3572855803751077, -1.0535135385041234], [0.968368348138057, -0.43970081079172807]]]},
          "fixed": {"loops": [[[-3.1572405034347595, 0.2680525474006804], [2.735353511230509,
          -2.5190663806372267], [3.535602490544638, -0.9038554242033245], [3.51225646831321,
          -0.7828680057993694]]]}})",
       -1.7050000000000001},
      {R"({"name": "lens2", "moving": {"loops": [[[-0.05080267842816341, -1.332913557049011,
          0.010171373200039902], [-0.03940787262063675, -1.337864439453149, 0.009462013211743543],
          [0.001945469956737167, -1.354021463322112]]]}, "fixed": {"loops": [[[-0.2132324928033278,
          -2.698785308382419], [0.2698719932724765, -2.652053308566762], [0.39451816220553315,
          -2.637551206749389], [0.48046835241006225, -2.627758071516347]]]}})",
       -2.6350000000000002},
  };
  for (const auto& c : cases) {
    const Pair pair = parse_or_throw(c.json, "lens");
    const Slice slice = compute_slice(pair, c.theta);
    int unbounded = 0;
    for (const FreeComponent& f : slice.free_components) unbounded += f.bounded ? 0 : 1;
    EXPECT_EQ(unbounded, 1) << c.json << "\ntheta " << c.theta;
    EXPECT_TRUE(std::isfinite(slice.blocked_area)) << c.json << "\ntheta " << c.theta;
    const Vec2 far = pair.fixed.box.hi + Vec2{10.0, 10.0};
    EXPECT_GE(slice.locate(far), 0) << c.json << "\ntheta " << c.theta;
  }
}

}  // namespace
