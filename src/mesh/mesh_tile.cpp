// Tiling one band between two slices (the classic contour tiling): n + m triangles between
// polylines of n and m chords, advancing along whichever side is behind. "Behind" is by
// material coordinate when both sides carry one (vertices of the same feature point are then
// joined, docs/mesh.md), otherwise by arc-length fraction, so two sides sampled differently
// (a piece shrinking towards a critical slice) still tile.
#include <map>

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
int cancel_opposite_triangles(std::vector<Triangle>& triangles, size_t first) {
  // Each triangle by its rotation starting at its least corner; its reverse keeps that corner
  // first and swaps the other two.
  const auto canonical = [](const Triangle& t) {
    const int k = t[0] < t[1] ? (t[0] < t[2] ? 0 : 2) : (t[1] < t[2] ? 1 : 2);
    return Triangle{t[k], t[(k + 1) % 3], t[(k + 2) % 3]};
  };
  std::map<Triangle, size_t> open;  // canonical corners -> index of a triangle not yet paired
  std::vector<char> gone(triangles.size(), 0);
  int pairs = 0;
  for (size_t i = first; i < triangles.size(); ++i) {
    const Triangle t = canonical(triangles[i]);
    const auto reverse = open.find(Triangle{t[0], t[2], t[1]});
    if (reverse != open.end()) {
      gone[i] = gone[reverse->second] = 1;
      open.erase(reverse);
      ++pairs;
    } else {
      open.emplace(t, i);
    }
  }
  if (pairs == 0) return 0;
  size_t kept = first;
  for (size_t i = first; i < triangles.size(); ++i)
    if (!gone[i]) triangles[kept++] = triangles[i];
  triangles.resize(kept);
  return pairs;
}

}  // namespace cslice::mesh_detail
