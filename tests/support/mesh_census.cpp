#include "support/mesh_census.hpp"

#include <algorithm>
#include <map>

namespace cslice::testkit {

std::vector<int> seam_identified(const ContactMesh& m) {
  std::vector<int> id(m.vertices.size());
  for (size_t v = 0; v < id.size(); ++v) id[v] = static_cast<int>(v);
  for (auto [at_pi, at_mpi] : m.seam) id[at_pi] = at_mpi;
  return id;
}

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
    if (total == 1) c.open.push_back(e);
    if (total == 1) ++c.boundary;
    if (total > 2) ++c.nonmanifold;
    if (total == 2 && n.first != 1) ++c.same_direction;
  }
  return c;
}

}  // namespace cslice::testkit
