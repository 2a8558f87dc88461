#include "slice/arrangement_steps.hpp"

namespace cslice {

// A counting sort, one edge at a time: its two half-edges leave from u and v, read once
// instead of choosing by parity per half-edge.
void group_by_origin(Arrangement& arr, std::vector<int>& fill) {
  std::vector<int>& start = arr.outgoing_start;
  const size_t keys = arr.vertices.size();
  start.assign(keys + 1, 0);
  for (const ArrangementEdge& e : arr.edges) {
    ++start[e.u + 1];
    ++start[e.v + 1];
  }
  for (size_t g = 0; g < keys; ++g) start[g + 1] += start[g];
  arr.outgoing_edges.resize(2 * arr.edges.size());
  fill.assign(start.begin(), start.end() - 1);
  int* order = arr.outgoing_edges.data();
  const int edges = int(arr.edges.size());  // read once: the stores below could alias it
  for (int e = 0; e < edges; ++e) {
    order[fill[arr.edges[e].u]++] = 2 * e;
    order[fill[arr.edges[e].v]++] = 2 * e + 1;
  }
}

}  // namespace cslice
