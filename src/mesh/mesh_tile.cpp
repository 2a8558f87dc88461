// Tiling one band between two slices (the classic contour tiling): n + m triangles between
// polylines of n and m chords, advancing along whichever side is behind. "Behind" is by
// material coordinate when both sides carry one (vertices of the same feature point are then
// joined, docs/mesh.md), otherwise by arc-length fraction, so two sides sampled differently
// (a piece shrinking towards a critical slice) still tile.
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

}  // namespace cslice::mesh_detail
