// Tiling one band between two slices (the classic contour tiling): n + m triangles between
// polylines of n and m chords, advancing along whichever side is behind. "Behind" is by
// material coordinate when both sides carry one (vertices of the same feature point are then
// joined, docs/mesh.md), otherwise by arc-length fraction, so two sides sampled differently
// (a piece shrinking towards a critical slice) still tile.
#include <algorithm>
#include <cstdint>

#include "mesh/mesh_internal.hpp"

namespace cslice::mesh_detail {

namespace {

std::vector<double> fractions(const std::vector<int>& line, const VertexStore& store) {
  std::vector<double> f(line.size(), 0.0);
  for (size_t k = 1; k < line.size(); ++k)
    f[k] = f[k - 1] + distance(store.xy(line[k - 1]), store.xy(line[k]));
  const double total = f.empty() ? 0.0 : f.back();
  for (size_t k = 0; k < f.size(); ++k)
    f[k] = total > 0.0 ? f[k] / total : double(k) / double(std::max<size_t>(1, f.size() - 1));
  return f;
}

void emit(const Triangle& t, std::vector<Triangle>& out) {
  // A repeated vertex: the polyline has shrunk to a point there, and the triangle with it.
  if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return;
  out.push_back(t);
}

}  // namespace

void tile_band(const Band& band, const VertexStore& store, std::vector<Triangle>& out) {
  const std::vector<int>&p = band.lower, &q = band.upper;
  if (p.empty() || q.empty()) return;
  const bool by_coord = band.lower_coord.size() == p.size() && band.upper_coord.size() == q.size();
  const std::vector<double> fp = by_coord ? band.lower_coord : fractions(p, store);
  const std::vector<double> fq = by_coord ? band.upper_coord : fractions(q, store);
  size_t a = 0, b = 0;
  while (a + 1 < p.size() || b + 1 < q.size()) {
    const bool advance_p = b + 1 >= q.size() || (a + 1 < p.size() && fp[a + 1] <= fq[b + 1]);
    if (advance_p) {
      emit({p[a], p[a + 1], q[b]}, out);
      ++a;
    } else {
      emit({p[a], q[b + 1], q[b]}, out);
      ++b;
    }
  }
}

// A fin: where a part fits an opening exactly at one orientation only, the free space there
// is the fit's curve, and the small free region beside it on either side closes onto it from
// one corner. The bands along the fit's two darts then tile the same triangles from that corner,
// once each way: a sheet of zero thickness whose edges the rest of the strip uses too (edges
// used four times). The two copies bound nothing, so both go; the fit stays a curve of the
// slices, not of the surface.
int cancel_opposite_triangles(std::vector<Triangle>& triangles,
                              const std::vector<size_t>& candidates) {
  // Each triangle by its corners sorted, and which way round it runs: turned to start at its
  // least corner, forward when the next corner is the smaller of the other two.
  struct Key {
    Triangle corners;
    bool forward;
    size_t index;
  };
  std::vector<Key> keys;
  keys.reserve(candidates.size());
  for (size_t i : candidates) {
    const Triangle& t = triangles[i];
    const int k = t[0] < t[1] ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
    const int b = t[(k + 1) % 3], c = t[(k + 2) % 3];
    keys.push_back({{t[k], std::min(b, c), std::max(b, c)}, b < c, i});
  }
  std::sort(keys.begin(), keys.end(), [](const Key& x, const Key& y) {
    return x.corners != y.corners ? x.corners < y.corners : x.index < y.index;
  });
  std::vector<size_t> gone;
  for (size_t g0 = 0, g1 = 0; g0 < keys.size(); g0 = g1) {
    while (g1 < keys.size() && keys[g1].corners == keys[g0].corners) ++g1;
    if (g1 - g0 < 2) continue;
    // Within one set of corners, the first of each way pair off, in the order of the list.
    std::vector<size_t> ways[2];
    for (size_t k = g0; k < g1; ++k) ways[keys[k].forward].push_back(keys[k].index);
    for (size_t k = 0; k < std::min(ways[0].size(), ways[1].size()); ++k)
      gone.insert(gone.end(), {ways[0][k], ways[1][k]});
  }
  if (gone.empty()) return 0;
  std::sort(gone.begin(), gone.end());
  size_t kept = gone.front();
  for (size_t i = gone.front(), g = 0; i < triangles.size(); ++i) {
    if (g < gone.size() && gone[g] == i) {
      ++g;
      continue;
    }
    triangles[kept++] = triangles[i];
  }
  triangles.resize(kept);
  return static_cast<int>(gone.size() / 2);
}

// A sheet's triangles each have an edge in the critical slice that the strip also runs the
// other way (a fit's two darts); any other edge of that slice bounds the strip, used once.
std::vector<size_t> triangles_on_two_way_edges(const std::vector<Triangle>& triangles,
                                               const VertexStore& store, double theta) {
  const auto in_slice = [&](int v) {
    return store.vertices[static_cast<size_t>(v)].theta == theta;
  };
  const auto key = [](int u, int v) {
    return (static_cast<uint64_t>(static_cast<uint32_t>(u)) << 32) | static_cast<uint32_t>(v);
  };
  std::vector<uint64_t> edges;
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k)
      if (in_slice(t[k]) && in_slice(t[(k + 1) % 3])) edges.push_back(key(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  const auto two_way = [&](int u, int v) {
    return std::binary_search(edges.begin(), edges.end(), key(v, u));
  };
  std::vector<size_t> out;
  for (size_t i = 0; i < triangles.size(); ++i) {
    const Triangle& t = triangles[i];
    for (int k = 0; k < 3; ++k)
      if (in_slice(t[k]) && in_slice(t[(k + 1) % 3]) && two_way(t[k], t[(k + 1) % 3])) {
        out.push_back(i);
        break;
      }
  }
  return out;
}

}  // namespace cslice::mesh_detail
