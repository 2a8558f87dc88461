// cslice_stress: a bug hunt over many pairs, beyond what the test suite can afford to run.
//
//   cslice_stress --seeds FIRST LAST    random curved pairs FIRST..LAST-1 (testkit::stress_pair)
//   cslice_stress --designed FIRST LAST designed pairs FIRST..LAST-1 (testkit::designed_pair:
//                                       unit grids, perfect fits, symmetric parts)
//   cslice_stress --symmetric FIRST LAST random pairs with symmetries (testkit::symmetric_pair:
//                                       quarter turns and mirrors, docs/symmetry.md)
//   cslice_stress --stars N FIRST LAST  random lobed star pairs of N vertices per part, half the
//                                       edges arcs (BM_CriticalCurved's kind; radii jittered
//                                       10%, 30% on odd seeds): pairs of a few hundred
//                                       features, where the small random pairs never reach
//                                       (a 200-feature one showed a missed triple point)
//   cslice_stress PAIR.json ...         pair files (designed fits, imported parts)
//   --scale K                           every random and designed pair drawn K times larger
//                                       first (points, radii and tolerance): the same pair in
//                                       other units, whose round-off differs
//   --offset X                          the fixed part of every random and designed pair
//                                       moved by (X, -X / 2): a drawing far from its origin
//   --prove-blocked always|never        slices leave out contact segments proven blocked
//                                       always, or never (slice/blocked_proof.hpp), instead
//                                       of only where segments outnumber features (worth_proving)
//
// Each pair goes through the checks the tests make on a few: the completeness of its
// critical orientations (tests/support/completeness.hpp), its slices at random and at critical
// orientations against `classify`, point queries on its computed space against `classify`
// outside the contact tolerance band, its contact mesh closed (every edge shared by two
// triangles once each way, nothing coned or joined straight), and the 3D topology's joins at
// every critical orientation against components carried across it, both ways: no join
// missed, none unconfirmed (tests/support/crossings); slices evaluated from their interval's
// structure, and slices mapped across a symmetry of the pair, against the same computed from
// scratch and classify. A
// failing pair is printed (its file, or its JSON for a seed) and the exit status is 1. Not run by
// ctest: a few hundred pairs take minutes.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "cslice/mesh.hpp"
#include "cslice/query.hpp"
#include "cslice/space.hpp"
#include "slice/blocked_proof.hpp"
#include "support/band.hpp"
#include "support/completeness.hpp"
#include "support/crossings.hpp"
#include "support/designed_pairs.hpp"
#include "support/failures.hpp"
#include "support/mesh_census.hpp"
#include "support/moved_examples.hpp"
#include "support/random_parts.hpp"
#include "support/random_polygons.hpp"
#include "support/slice_oracle.hpp"
#include "support/symmetric_pairs.hpp"

using namespace cslice;

namespace {

std::vector<std::string> g_files;
unsigned g_first = 0, g_last = 0;
unsigned g_designed_first = 0, g_designed_last = 0;
unsigned g_symmetric_first = 0, g_symmetric_last = 0;
unsigned g_stars_first = 0, g_stars_last = 0;
int g_star_vertices = 0;
double g_scale = 1.0, g_offset = 0.0;

// Closed and consistently oriented once the seam at theta = pi is identified, as
// tests/test_mesh.cpp requires of its cases.
void check_mesh(const Pair& pair, const SlicedSpace& space, const std::string& name) {
  const ContactMesh m = contact_mesh(pair, space);
  EXPECT_EQ(testkit::census(m).bad(), 0)
      << name << ": mesh edges not shared by two triangles once each way";
  EXPECT_EQ(m.stats.coned_cycles + m.stats.straight_joins + m.stats.unanchored_cycles, 0)
      << name << ": mesh cycles coned " << m.stats.coned_cycles << ", joined straight "
      << m.stats.straight_joins << ", unanchored " << m.stats.unanchored_cycles;
}

// Queries anywhere and near realizable contact, as tests/test_query.cpp makes them.
void check_queries(const Pair& pair, const SlicedSpace& space, unsigned seed,
                   const std::string& name) {
  SpaceQuery q(pair, space);
  testkit::compare_queries_with_classify(pair, space, q, 600, seed, name);
}

// Returns whether the pair passed every check.
bool check_pair(const Pair& pair, unsigned seed, const std::string& name) {
  const int before = testkit::failures_so_far();
  SpaceOptions options;
  options.threads = 1;
  const SlicedSpace space = compute_space(pair, options);
  const CriticalSet& set = space.criticals;  // as critical_orientations(pair) finds them
  const testkit::CompletenessReport report = testkit::check_completeness(pair, set);
  for (const std::string& f : report.interval_failures) ADD_FAILURE() << name << ": " << f;
  for (const std::string& m : report.missed) ADD_FAILURE() << name << ": " << m;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (int k = 0; k < 3; ++k)
    testkit::check_slice_against_classify(pair, angle(rng), 200, rng, name, false);
  // At most 40 critical orientations, evenly spread: the slices most likely to go wrong.
  const size_t n = set.orientations.size(), step = std::max<size_t>(1, n / 40);
  for (size_t i = 0; i < n; i += step)
    testkit::check_slice_against_classify(pair, set.orientations[i].theta, 40, rng, name, false);
  // Up to 20 slices evaluated from their interval's structure and 20 mapped across a
  // symmetry of the pair, evenly spread, against the same slices computed from scratch and
  // beside their boundaries against classify.
  for (const bool mapped : {false, true}) {
    std::vector<const SpaceSlice*> made;
    for (const SpaceSlice& s : space.slices)
      if (mapped ? s.mapped : s.evaluated) made.push_back(&s);
    for (size_t i = 0; i < made.size(); i += std::max<size_t>(1, made.size() / 20)) {
      const Slice& s = made[i]->slice;
      testkit::expect_same_slice(pair, s, compute_slice(pair, s.theta), name);
      testkit::expect_boundary_sides_agree_with_classify(pair, s, name);
    }
  }
  check_queries(pair, space, seed, name);
  check_mesh(pair, space, name);
  for (int at = 0; at < static_cast<int>(space.slices.size()); ++at)
    if (space.slices[at].kind == SliceKind::critical)
      testkit::expect_joins_witnessed(pair, space, at, name);
  return testkit::failures_so_far() == before;
}

// The --stars pair of a seed: the first of its draws (seed, seed + 1,000,003, ...) that the
// reader accepts.
testkit::RandomPair star_pair(unsigned seed) {
  testkit::AcceptedStarPair p = testkit::accepted_star_pair(g_star_vertices, seed % 2 ? 0.3 : 0.1,
                                                            0.5, seed, 1000003u, 100, "star");
  return {std::move(p.pair), std::move(p.json)};
}

// Checks the pairs make(seed) for seeds in [first, last), named "<kind> <seed>"; counts them.
void check_seeds(unsigned first, unsigned last, testkit::RandomPair (*make)(unsigned),
                 const std::string& kind, int& checked, int& failed) {
  for (unsigned seed = first; seed < last; ++seed) {
    const testkit::RandomPair p = make(seed);
    const std::string name = kind + " " + std::to_string(seed);
    ++checked;
    const bool moved = g_scale != 1.0 || g_offset != 0.0;
    const Pair pair =
        moved ? testkit::moved_pair(p.json, name, g_scale, 0, {}, {g_offset, -0.5 * g_offset})
              : p.pair;
    if (!check_pair(pair, seed, name)) {
      ++failed;
      std::cout << "FAILED " << kind << " " << seed
                << (g_scale == 1.0 ? "" : " scaled by " + std::to_string(g_scale))
                << (g_offset == 0.0 ? "" : " fixed part moved by " + std::to_string(g_offset))
                << ": " << p.json << "\n";
    }
  }
}

TEST(Stress, Pairs) {
  int checked = 0, failed = 0;
  check_seeds(g_first, g_last, testkit::stress_pair, "seed", checked, failed);
  check_seeds(g_designed_first, g_designed_last, testkit::designed_pair, "designed", checked,
              failed);
  check_seeds(g_symmetric_first, g_symmetric_last, testkit::symmetric_pair, "symmetric", checked,
              failed);
  check_seeds(g_stars_first, g_stars_last, star_pair,
              "star of " + std::to_string(g_star_vertices) + " vertices, seed", checked, failed);
  for (const std::string& file : g_files) {
    LoadResult r = load_pair(file);
    if (!r.ok()) {
      std::cout << "skipped " << r.error->message() << "\n";
      continue;
    }
    ++checked;
    if (!check_pair(*r.pair, 1, file)) {
      ++failed;
      std::cout << "FAILED " << file << "\n";
    }
  }
  std::cout << checked << " pairs checked, " << failed << " failed\n";
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--seeds" && i + 2 < argc) {
      g_first = unsigned(std::stoul(argv[i + 1]));
      g_last = unsigned(std::stoul(argv[i + 2]));
      i += 2;
    } else if (arg == "--scale" && i + 1 < argc) {
      g_scale = std::stod(argv[++i]);
    } else if (arg == "--offset" && i + 1 < argc) {
      g_offset = std::stod(argv[++i]);
    } else if (arg == "--prove-blocked" && i + 1 < argc) {
      const std::string mode = argv[++i];
      if (mode != "always" && mode != "never") {
        std::cerr << "--prove-blocked takes always or never\n";
        return 2;
      }
      cslice::set_blocked_proof_mode(mode == "always" ? cslice::BlockedProofMode::always
                                                      : cslice::BlockedProofMode::never);
    } else if (arg == "--designed" && i + 2 < argc) {
      g_designed_first = unsigned(std::stoul(argv[i + 1]));
      g_designed_last = unsigned(std::stoul(argv[i + 2]));
      i += 2;
    } else if (arg == "--stars" && i + 3 < argc) {
      g_star_vertices = std::stoi(argv[i + 1]);
      g_stars_first = unsigned(std::stoul(argv[i + 2]));
      g_stars_last = unsigned(std::stoul(argv[i + 3]));
      i += 3;
      if (g_star_vertices < 3) {
        std::cerr << "--stars takes at least 3 vertices per part\n";
        return 2;
      }
    } else if (arg == "--symmetric" && i + 2 < argc) {
      g_symmetric_first = unsigned(std::stoul(argv[i + 1]));
      g_symmetric_last = unsigned(std::stoul(argv[i + 2]));
      i += 2;
    } else {
      g_files.push_back(arg);
    }
  }
  if (g_files.empty() && g_first >= g_last && g_designed_first >= g_designed_last &&
      g_symmetric_first >= g_symmetric_last && g_stars_first >= g_stars_last) {
    std::cerr << "usage: cslice_stress [--scale K] [--offset X] [--prove-blocked always|never] "
                 "--seeds FIRST LAST | --designed FIRST LAST | --symmetric FIRST LAST | "
                 "--stars N FIRST LAST | PAIR.json ...\n";
    return 2;
  }
  return RUN_ALL_TESTS();
}
