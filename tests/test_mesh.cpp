// The contact-surface mesh (src/mesh): well-formed triangles, closed surfaces where the free
// space is one channel around every theta, the seam at theta = pi = -pi, the enclosed volume
// against the integral of the slices' free areas, partial reconstruction, and the writers.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "cslice/mesh.hpp"
#include "support/examples.hpp"

using namespace cslice;

namespace {

const char* const kExamples[] = {"disc-in-box",     "cam",          "knee",
                                 "fixture",         "fastener",     "square-peg-hole",
                                 "disc-half-plane", "pin-exact-fit"};
// Pairs whose free space is one channel around every theta: a closed contact surface.
const char* const kClosed[] = {"disc-in-box", "cam"};

struct Computed {
  Pair pair;
  SlicedSpace space;
  ContactMesh mesh;
};

// Each example's space and mesh, computed once for the whole test program.
const Computed& computed(const std::string& name) {
  static std::map<std::string, Computed> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    Computed c{testkit::load_example(name), {}, {}};
    c.space = compute_space(c.pair);
    c.mesh = contact_mesh(c.pair, c.space);
    it = cache.emplace(name, std::move(c)).first;
  }
  return it->second;
}

double triangle_area(const ContactMesh& m, const std::array<int, 3>& t) {
  const MeshVertex &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
  const double ux = b.x - a.x, uy = b.y - a.y, ut = b.theta - a.theta;
  const double wx = c.x - a.x, wy = c.y - a.y, wt = c.theta - a.theta;
  const double nx = uy * wt - ut * wy, ny = ut * wx - ux * wt, nt = ux * wy - uy * wx;
  return 0.5 * std::sqrt(nx * nx + ny * ny + nt * nt);
}

// Vertex ids with each seam vertex at theta = pi replaced by its partner at -pi: the closed
// surface's vertices.
std::vector<int> seam_identified(const ContactMesh& m) {
  std::vector<int> id(m.vertices.size());
  for (size_t v = 0; v < id.size(); ++v) id[v] = static_cast<int>(v);
  for (auto [at_pi, at_mpi] : m.seam) id[at_pi] = at_mpi;
  return id;
}

struct EdgeCensus {
  int edges = 0, boundary = 0, nonmanifold = 0, same_direction = 0;
};

// Directed edge counts after identifying the seam: a closed, consistently oriented surface has
// every undirected edge used twice, once in each direction.
EdgeCensus census(const ContactMesh& m) {
  const std::vector<int> id = seam_identified(m);
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{id[t[k]], id[t[(k + 1) % 3]]}];
  std::map<std::pair<int, int>, std::pair<int, int>> undirected;  // (forward, backward)
  for (auto [e, n] : directed) {
    auto& u = undirected[std::minmax(e.first, e.second)];
    (e.first < e.second ? u.first : u.second) += n;
  }
  EdgeCensus c;
  for (auto [e, n] : undirected) {
    ++c.edges;
    const int total = n.first + n.second;
    if (total == 1) ++c.boundary;
    if (total > 2) ++c.nonmanifold;
    if (total == 2 && n.first != 1) ++c.same_direction;
  }
  return c;
}

// Free area of a slice (bounded components) and the length of their boundaries.
double free_area(const Slice& s) {
  double a = 0.0;
  for (const FreeComponent& c : s.free_components) a += c.bounded ? c.area : 0.0;
  return a;
}
// Signed area inside the free space's boundary cycles: a bounded component counts its area, the
// unbounded one minus the blocked islands it surrounds. What the mesh's volume integrates.
double signed_boundary_area(const Slice& s) {
  double a = 0.0;
  for (const FreeComponent& c : s.free_components)
    for (const auto& cycle : c.boundary)
      for (const ContactPiece& p : cycle) a += signed_area_contribution(p.curve);
  return a;
}
double free_perimeter(const Slice& s) {
  double l = 0.0;
  for (const FreeComponent& c : s.free_components)
    for (const auto& cycle : c.boundary)
      for (const ContactPiece& p : cycle) l += curve_length(p.curve);
  return l;
}

// The trapezoid rule over the stored slices, cyclically (the last to the first + 2 pi), of
// f(slice).
template <class F>
double trapezoid(const SlicedSpace& space, F f) {
  double sum = 0.0;
  const size_t n = space.slices.size();
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    const double step = space.slices[j].theta - space.slices[i].theta + (j == 0 ? kTwoPi : 0.0);
    sum += 0.5 * step * (f(space.slices[i].slice) + f(space.slices[j].slice));
  }
  return sum;
}

int count_lines(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0 ? 1 : 0;
  return n;
}

}  // namespace

TEST(Mesh, NoDegenerateTriangles) {
  for (const char* name : kExamples) {
    const Computed& c = computed(name);
    // A triangle spans a chord of a slice (at least the geometric epsilon long) and a step in
    // theta, or lies in one plane only at a cone; a millionth of the geometric epsilon times
    // the pair's size is far below either.
    const double tiny = 1e-6 * c.pair.tol.geometric * c.pair.tol.size;
    double smallest = INFINITY;
    for (const auto& t : c.mesh.triangles) smallest = std::min(smallest, triangle_area(c.mesh, t));
    const MeshStats& s = c.mesh.stats;
    std::printf(
        "%-16s %7zu triangles %7zu vertices, min area %.3g; cycles %d matched, %d coned, %d "
        "unanchored; pieces %d matched, %d unmatched\n",
        name, c.mesh.triangles.size(), c.mesh.vertices.size(), smallest, s.matched_cycles,
        s.coned_cycles, s.unanchored_cycles, s.matched_pieces, s.unmatched_pieces);
    EXPECT_FALSE(c.mesh.triangles.empty()) << name;
    EXPECT_GT(smallest, tiny) << name;
  }
}

TEST(Mesh, ClosedWhereTheFreeSpaceIsOneChannel) {
  for (const char* name : kExamples) {
    const EdgeCensus e = census(computed(name).mesh);
    std::printf("%-16s %7d edges: %d boundary, %d non-manifold, %d inconsistently oriented\n", name,
                e.edges, e.boundary, e.nonmanifold, e.same_direction);
  }
  for (const char* name : kClosed) {
    const Computed& c = computed(name);
    EXPECT_EQ(c.space.topology.components.size(), 1u) << name;
    EXPECT_EQ(c.mesh.stats.coned_cycles, 0) << name;
    const EdgeCensus e = census(c.mesh);
    EXPECT_GT(e.edges, 0) << name;
    EXPECT_EQ(e.boundary, 0) << name;
    EXPECT_EQ(e.nonmanifold, 0) << name;
    EXPECT_EQ(e.same_direction, 0) << name;
  }
}

TEST(Mesh, ThetaMinusPiAndPiMeet) {
  for (const char* name : kExamples) {
    const ContactMesh& m = computed(name).mesh;
    EXPECT_FALSE(m.seam.empty()) << name;
    for (auto [at_pi, at_mpi] : m.seam) {
      const MeshVertex &a = m.vertices[at_pi], &b = m.vertices[at_mpi];
      EXPECT_EQ(a.theta, kPi) << name;
      // The first slice's own vertices when it lies at -pi (up to its rounding).
      EXPECT_NEAR(b.theta, -kPi, 1e-12) << name;
      EXPECT_EQ(a.x, b.x) << name;
      EXPECT_EQ(a.y, b.y) << name;
    }
    // Nothing lies beyond the seam, and every vertex on it has its partner.
    std::set<int> on_seam;
    for (auto [at_pi, at_mpi] : m.seam) on_seam.insert({at_pi, at_mpi});
    for (size_t v = 0; v < m.vertices.size(); ++v) {
      EXPECT_LE(std::fabs(m.vertices[v].theta), kPi) << name;
      if (m.vertices[v].theta == kPi) {
        EXPECT_TRUE(on_seam.count(static_cast<int>(v))) << name;
      }
    }
  }
}

// The mesh's cross-section at a stored slice is the slice's free region with arcs replaced by
// chords, each within the chord tolerance tol of its arc, so the areas differ by at most
// perimeter * tol there; between slices the surface is within tol of the true one (the
// interpolation step, docs/space-format.md), so again by at most perimeter * tol; the
// trapezoid rule's own error is of the same order (dtheta^2 / 12 * A'', with dtheta^2 =
// 8 tol / reach and A'' ~ perimeter * reach). Integrated over theta:
// |V_mesh - V_trapezoid| <= 2 tol * integral of the perimeter. The volume is that of the
// signed area inside the boundary cycles (free area, minus blocked islands in unbounded free
// space).
//
// The interpolation step bounds the motion of the contact curves' defining points, not of the
// corners where two curves cross, which move faster where the curves are nearly parallel
// (docs/space-format.md); and branchings are closed by cones. Of the pairs with such corners,
// knee, fastener and square-peg-hole exceed the bound by up to about 2x (fixture stays
// within): for these four the test is a regression guard at 3x, not a derived tolerance.
TEST(Mesh, EnclosedVolumeMatchesTheIntegralOfFreeArea) {
  const std::set<std::string> derived = {"disc-in-box", "cam", "disc-half-plane", "pin-exact-fit"};
  for (const char* name : kExamples) {
    const Computed& c = computed(name);
    const double volume = enclosed_volume(c.mesh);
    const double integral = trapezoid(c.space, signed_boundary_area);
    const double bound = 2.0 * c.mesh.chord_tolerance * trapezoid(c.space, free_perimeter);
    std::printf("%-16s volume %.9g, integral of signed area %.9g, difference %.3g, bound %.3g\n",
                name, volume, integral, volume - integral, bound);
    EXPECT_NEAR(volume, integral, derived.count(name) ? bound : 3.0 * bound) << name;
  }
  for (const char* name : kClosed) {
    const Computed& c = computed(name);
    EXPECT_NEAR(trapezoid(c.space, signed_boundary_area), trapezoid(c.space, free_area),
                1e-9 * trapezoid(c.space, free_area))
        << name;
  }
  // Disc in box: the free space is [-2, 2]^2 at every theta; cam: a 0.2 x 0.2 square.
  EXPECT_NEAR(enclosed_volume(computed("disc-in-box").mesh), 16.0 * kTwoPi, 1e-9);
  EXPECT_NEAR(enclosed_volume(computed("cam").mesh), 0.04 * kTwoPi, 1e-9);
}

TEST(Mesh, PartialReconstructionKeepsOnlyWhatIsInside) {
  for (const char* name : {"cam", "knee", "fastener"}) {
    const Computed& c = computed(name);
    MeshOptions o;
    o.theta_from = -0.5;
    o.theta_to = 1.0;
    Box all;
    for (const MeshVertex& v : c.mesh.vertices) all.add(Vec2{v.x, v.y});
    o.box.lo = all.lo;
    o.box.hi = 0.5 * (all.lo + all.hi);
    const ContactMesh part = contact_mesh(c.pair, c.space, o);
    EXPECT_FALSE(part.triangles.empty()) << name;
    EXPECT_LT(part.triangles.size(), c.mesh.triangles.size()) << name;
    for (const MeshVertex& v : part.vertices) {
      EXPECT_GE(v.theta, o.theta_from) << name;
      EXPECT_LE(v.theta, o.theta_to) << name;
      EXPECT_GE(v.x, o.box.lo.x) << name;
      EXPECT_LE(v.x, o.box.hi.x) << name;
      EXPECT_GE(v.y, o.box.lo.y) << name;
      EXPECT_LE(v.y, o.box.hi.y) << name;
    }
    // Exactly the full mesh's triangles inside: partial reconstruction loses nothing.
    const auto inside = [&](const MeshVertex& v) {
      return v.theta >= o.theta_from && v.theta <= o.theta_to && v.x >= o.box.lo.x &&
             v.x <= o.box.hi.x && v.y >= o.box.lo.y && v.y <= o.box.hi.y;
    };
    size_t expected = 0;
    for (const auto& t : c.mesh.triangles)
      expected += inside(c.mesh.vertices[t[0]]) && inside(c.mesh.vertices[t[1]]) &&
                  inside(c.mesh.vertices[t[2]]);
    EXPECT_EQ(part.triangles.size(), expected) << name;
    std::printf("%-16s partial: %zu of %zu triangles\n", name, part.triangles.size(),
                c.mesh.triangles.size());
  }
  // A range wrapping through pi keeps both ends and the seam.
  const Computed& c = computed("cam");
  MeshOptions o;
  o.theta_from = 3.0;
  o.theta_to = -3.0;
  const ContactMesh part = contact_mesh(c.pair, c.space, o);
  EXPECT_FALSE(part.triangles.empty());
  EXPECT_FALSE(part.seam.empty());
  for (const MeshVertex& v : part.vertices) EXPECT_TRUE(v.theta >= 3.0 || v.theta <= -3.0);
}

TEST(Mesh, ChordToleranceDefaultsToTheContactTolerance) {
  const Computed& c = computed("cam");
  EXPECT_EQ(c.mesh.chord_tolerance, c.pair.tol.contact);
  // Recovered from the interpolation step when the pair is not given.
  EXPECT_NEAR(contact_mesh(c.space).chord_tolerance, c.pair.tol.contact, 1e-9 * c.pair.tol.contact);
  // A finer tolerance samples arcs (the disc's rounded corners) more densely.
  const Computed& d = computed("disc-half-plane");
  MeshOptions fine;
  fine.chord_tolerance = d.pair.tol.contact / 100;
  EXPECT_GT(contact_mesh(d.space, fine).triangles.size(), d.mesh.triangles.size());
}

TEST(Mesh, LabelsAreFeaturePairsOfTheSlices) {
  const Computed& c = computed("cam");
  std::set<SegmentLabel> labels;
  for (const SpaceSlice& s : c.space.slices)
    for (const SegmentLabel& l : realizable_labels(s.slice)) labels.insert(l);
  for (const MeshVertex& v : c.mesh.vertices)
    EXPECT_TRUE(labels.count(v.label)) << v.label.moving_feature << "," << v.label.fixed_feature;
}

TEST(Mesh, WritersParseBackToTheSameCounts) {
  const ContactMesh& m = computed("cam").mesh;
  const int nv = static_cast<int>(m.vertices.size()), nt = static_cast<int>(m.triangles.size());

  const std::string obj = mesh_to_obj(m);
  EXPECT_EQ(count_lines(obj, "v "), nv);
  EXPECT_EQ(count_lines(obj, "f "), nt);

  const std::string ply = mesh_to_ply(m);
  std::istringstream in(ply);
  std::string line;
  int declared_v = -1, declared_f = -1;
  while (std::getline(in, line) && line != "end_header") {
    std::sscanf(line.c_str(), "element vertex %d", &declared_v);
    std::sscanf(line.c_str(), "element face %d", &declared_f);
  }
  EXPECT_EQ(declared_v, nv);
  EXPECT_EQ(declared_f, nt);
  int vertex_lines = 0, face_lines = 0;
  for (int k = 0; k < nv && std::getline(in, line); ++k) {
    std::istringstream fields(line);
    double x, y, z;
    int mf, ff;
    vertex_lines += static_cast<bool>(fields >> x >> y >> z >> mf >> ff) &&
                    mf == m.vertices[k].label.moving_feature &&
                    ff == m.vertices[k].label.fixed_feature && x == m.vertices[k].x;
  }
  for (int k = 0; k < nt && std::getline(in, line); ++k) {
    std::istringstream fields(line);
    int three, a, b, c;
    face_lines += static_cast<bool>(fields >> three >> a >> b >> c) && three == 3 &&
                  a == m.triangles[k][0] && c == m.triangles[k][2];
  }
  EXPECT_EQ(vertex_lines, nv);
  EXPECT_EQ(face_lines, nt);
  EXPECT_FALSE(std::getline(in, line));

  const std::string stl = mesh_to_stl(m);
  EXPECT_EQ(count_lines(stl, "solid cslice"), 1);
  EXPECT_EQ(count_lines(stl, "  facet normal "), nt);
  EXPECT_EQ(count_lines(stl, "      vertex "), 3 * nt);
  EXPECT_EQ(count_lines(stl, "endsolid cslice"), 1);
}
