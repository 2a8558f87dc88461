// Whether a contact mesh is a closed, consistently oriented surface: the edge census the mesh
// tests and the stress driver take.
#pragma once

#include <utility>
#include <vector>

#include "cslice/mesh.hpp"

namespace cslice::testkit {

// Vertex ids with each seam vertex at theta = pi replaced by its partner at -pi: the closed
// surface's vertices.
std::vector<int> seam_identified(const ContactMesh& m);

struct EdgeCensus {
  int edges = 0, boundary = 0, nonmanifold = 0, same_direction = 0;
  std::vector<std::pair<int, int>> open;  // edges used once
  // Edges not used exactly twice, once each way.
  int bad() const { return boundary + nonmanifold + same_direction; }
};

// Directed edge counts after identifying the seam: a closed, consistently oriented surface has
// every undirected edge used twice, once in each direction.
EdgeCensus census(const ContactMesh& m);

}  // namespace cslice::testkit
