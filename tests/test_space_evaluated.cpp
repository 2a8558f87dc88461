// Intermediate slices evaluated from their interval's boundary model
// (src/slice/boundary_model.cpp) against the same slices computed from scratch, and against
// the direct placement test.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "cslice/classify.hpp"
#include "cslice/slice_io.hpp"
#include "cslice/space.hpp"
#include "slice/boundary_model.hpp"
#include "support/examples.hpp"
#include "support/random_parts.hpp"
#include "support/random_polygons.hpp"
#include "support/slice_oracle.hpp"

using namespace cslice;

namespace {

const char* const kPaperExamples[] = {"knee", "cam", "fixture", "fastener"};

SlicedSpace space_of(const Pair& pair, bool evaluate) {
  SpaceOptions options;
  options.threads = 2;
  options.evaluate_slices = evaluate;
  options.map_symmetric = false;  // every intermediate slice evaluated, none mapped
  return compute_space(pair, options);
}

// Every evaluated slice of `pair` against its twin computed from scratch; returns how many
// intermediate slices were evaluated, out of `intermediates`.
int compare_spaces(const Pair& pair, const std::string& name, const SlicedSpace& fast,
                   const SlicedSpace& slow, int& intermediates) {
  EXPECT_EQ(fast.slices.size(), slow.slices.size()) << name;
  EXPECT_EQ(fast.topology.components.size(), slow.topology.components.size()) << name;
  EXPECT_EQ(fast.topology.cells.size(), slow.topology.cells.size()) << name;
  EXPECT_EQ(fast.topology.slice_components, slow.topology.slice_components) << name;
  // The whole 3D topology as written to the file, but for the checks' counts and the
  // round-off in the cells' area ranges.
  nlohmann::json tf = nlohmann::json::parse(space_to_json(pair, fast, false))["topology"];
  nlohmann::json ts = nlohmann::json::parse(space_to_json(pair, slow, false))["topology"];
  for (const char* key : {"transitions", "components", "slice_components"})
    EXPECT_EQ(tf[key], ts[key]) << name << ": topology " << key;
  const double area_slack = pair.tol.geometric * pair.tol.size;
  EXPECT_EQ(tf["cells"].size(), ts["cells"].size()) << name;
  for (size_t c = 0; c < tf["cells"].size() && c < ts["cells"].size(); ++c) {
    nlohmann::json& a = tf["cells"][c];
    nlohmann::json& b = ts["cells"][c];
    for (int end : {0, 1}) {
      const nlohmann::json &x = a["area_range"][end], &y = b["area_range"][end];
      EXPECT_EQ(x.is_null(), y.is_null()) << name << ": cell " << c;
      if (x.is_number() && y.is_number()) {
        EXPECT_NEAR(x.get<double>(), y.get<double>(), area_slack) << name << ": cell " << c;
      }
    }
    a.erase("area_range");
    b.erase("area_range");
    EXPECT_EQ(a, b) << name << ": cell " << c;
  }
  EXPECT_EQ(slow.topology.checks.side_slices_evaluated, 0) << name;
  for (const SlicedSpace* s : {&fast, &slow}) {
    EXPECT_TRUE(s->topology.checks.problems.empty()) << name;
    EXPECT_EQ(s->topology.checks.side_slices_not_equivalent, 0) << name;
  }
  int evaluated = 0;
  intermediates = 0;
  for (size_t i = 0; i < fast.slices.size() && i < slow.slices.size(); ++i) {
    const SpaceSlice& s = fast.slices[i];
    EXPECT_FALSE(slow.slices[i].evaluated) << name;
    intermediates += s.kind == SliceKind::intermediate ? 1 : 0;
    if (!s.evaluated) continue;
    EXPECT_EQ(s.kind, SliceKind::intermediate) << name << ": slice " << i;
    ++evaluated;
    testkit::expect_same_slice(pair, s.slice, slow.slices[i].slice,
                               name + " slice " + std::to_string(i));
  }
  return evaluated;
}
int compare_spaces(const Pair& pair, const std::string& name, int& intermediates) {
  return compare_spaces(pair, name, space_of(pair, true), space_of(pair, false), intermediates);
}

}  // namespace

// On the paper's examples every interval's model holds: all intermediate slices are
// evaluated, and each is the slice computed from scratch.
TEST(EvaluatedSlices, PaperExamplesMatchSlicesComputedFromScratch) {
  for (const char* name : kPaperExamples) {
    const Pair pair = testkit::load_example(name);
    int intermediates = 0;
    const int evaluated = compare_spaces(pair, name, intermediates);
    EXPECT_GT(intermediates, 0) << name;
    EXPECT_EQ(evaluated, intermediates) << name;
  }
  // The fastener's joins need side slices (its slot): evaluated too.
  const SlicedSpace fastener = space_of(testkit::load_example("fastener"), true);
  EXPECT_GT(fastener.topology.checks.side_slices_evaluated, 0);
}

// Random curved pairs: where a model holds, the evaluated slice is the computed one; most
// intermediate slices are evaluated.
TEST(EvaluatedSlices, RandomCurvedPairsMatchSlicesComputedFromScratch) {
  int evaluated = 0, intermediates = 0;
  for (unsigned seed = 100240; seed < 100280; ++seed) {
    const testkit::RandomPair p = testkit::stress_pair(seed);
    int n = 0;
    evaluated += compare_spaces(p.pair, "random pair " + std::to_string(seed), n);
    intermediates += n;
  }
  EXPECT_GT(evaluated, intermediates * 3 / 4) << evaluated << " of " << intermediates;
}

// Tight fits (a part in an opening it barely fits): thin, pinched free space, corners close
// together, and intervals with no free space at all. Every intermediate slice is evaluated
// and is the computed one.
TEST(EvaluatedSlices, TightFitsMatchSlicesComputedFromScratch) {
  std::mt19937 rng(5);
  int evaluated = 0, intermediates = 0;
  for (int k = 0; k < 10; ++k) {
    const Pair pair = testkit::tight_pair(rng, k);
    int n = 0;
    evaluated += compare_spaces(pair, "tight pair " + std::to_string(k), n);
    intermediates += n;
  }
  EXPECT_GT(intermediates, 0);
  EXPECT_EQ(evaluated, intermediates);
}

// The evaluated slices pass the slice tests' own oracle (samples free, membership as classify
// says at random points) and classify finds their boundary pieces where contact is.
TEST(EvaluatedSlices, AgreeWithClassify) {
  std::mt19937 rng(2026);
  for (const char* name : kPaperExamples) {
    const Pair pair = testkit::load_example(name);
    const SlicedSpace space = space_of(pair, true);
    int checked = 0;
    for (const SpaceSlice& s : space.slices) {
      if (!s.evaluated) continue;
      ++checked;
      testkit::check_slice_against_classify(pair, s.slice, 200, rng, name);
      EXPECT_GT(testkit::expect_boundary_sides_agree_with_classify(pair, s.slice, name), 0) << name;
    }
    EXPECT_GT(checked, 0) << name;
  }
}

// A pin in a hole of its own radius is a perfect fit at every theta: no model (degenerate
// contacts), every slice computed from scratch.
TEST(EvaluatedSlices, PerfectFitIsComputedFromScratch) {
  const Pair pair = testkit::load_example("pin-exact-fit");
  const SlicedSpace space = space_of(pair, true);
  for (const SpaceSlice& s : space.slices) {
    EXPECT_FALSE(s.evaluated);
    EXPECT_FALSE(model_boundary(s.slice, pair.tol).has_value()) << s.theta;
  }
}

// The check that accepts a model: its own slice passes; a slice whose contact graph has a
// node or edge the model lacks (what coinciding contact segments or an extra split give the
// arrangement) or more pieces fails.
TEST(EvaluatedSlices, ModelMustReproduceItsSlice) {
  const Pair pair = testkit::load_example("fixture");
  const Slice slice = compute_slice(pair, 0.3);
  const std::optional<BoundaryModel> model = model_boundary(slice, pair.tol);
  ASSERT_TRUE(model.has_value());
  EXPECT_TRUE(model_reproduces(*model, slice));
  Slice extra_edge = slice;
  extra_edge.contact_graph.edges.push_back(extra_edge.contact_graph.edges.front());
  EXPECT_FALSE(model_reproduces(*model, extra_edge));
  Slice extra_piece = slice;
  extra_piece.realizable.push_back(extra_piece.realizable.front());
  EXPECT_FALSE(model_reproduces(*model, extra_piece));
  Slice extra_node = slice;
  for (const ContactSegment& s : slice.contact_segments)
    if (!std::binary_search(slice.contact_graph.nodes.begin(), slice.contact_graph.nodes.end(),
                            s.id)) {
      extra_node.contact_graph.nodes.push_back(s.id);
      std::sort(extra_node.contact_graph.nodes.begin(), extra_node.contact_graph.nodes.end());
      break;
    }
  if (extra_node.contact_graph.nodes != slice.contact_graph.nodes) {
    EXPECT_FALSE(model_reproduces(*model, extra_node));
  }
}

// A gear of 4 teeth in a ring gear of 9: the teeth lock in pockets, thin free components that
// join across critical orientations only by carrying their samples (joins_by_carrying). The
// carries' steps lie inside an interval, so they are evaluated from its model, as side slices
// are; the topology is the one computed from scratch.
TEST(EvaluatedSlices, CarriesStepThroughEvaluatedSlices) {
  const std::string json = testkit::gear_in_ring_json(4, 3.0, 0.75, 9, 3.5, 5.75);
  const LoadResult loaded = parse_pair(json, "gear in ring");
  ASSERT_TRUE(loaded.ok()) << loaded.error->message();
  const SlicedSpace fast = space_of(*loaded.pair, true), slow = space_of(*loaded.pair, false);
  int intermediates = 0;
  compare_spaces(*loaded.pair, "gear in ring", fast, slow, intermediates);
  EXPECT_GT(fast.topology.checks.joins_by_carrying, 0);
  EXPECT_EQ(fast.topology.checks.joins_by_carrying, slow.topology.checks.joins_by_carrying);
  EXPECT_GT(fast.topology.checks.carry_slices, 0);
  EXPECT_EQ(fast.topology.checks.carry_slices_evaluated, fast.topology.checks.carry_slices);
  EXPECT_EQ(slow.topology.checks.carry_slices_evaluated, 0);
}
