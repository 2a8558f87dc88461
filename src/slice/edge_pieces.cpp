#include "slice/edge_pieces.hpp"

#include <atomic>

#include "slice/group_by.hpp"
#include "slice/small_sort.hpp"

namespace cslice {
namespace {

std::atomic<bool> g_peeling{true};

// Pieces in the order of their end pairs (lower end, then the other), each group of equal
// ends sorted by piece index: candidates for merging are neighbours.
void order_by_ends(const std::vector<Piece>& pieces, size_t vertices, PieceScratch& s) {
  const size_t count = pieces.size();
  std::vector<std::pair<int, int>>& ends = s.end_pairs;  // compact: read many times
  ends.resize(count);
  for (size_t i = 0; i < count; ++i)
    ends[i] = {std::min(pieces[i].u, pieces[i].v), std::max(pieces[i].u, pieces[i].v)};
  group_by(
      count, vertices, [&](size_t i) { return ends[i].first; }, s.start, s.order, s.fill);
  for (size_t g = 0; g + 1 < s.start.size(); ++g)
    if (s.start[g + 1] - s.start[g] > 1)
      small_sort(s.order.begin() + s.start[g], s.order.begin() + s.start[g + 1],
                 [&](int a, int b) { return ends[a] != ends[b] ? ends[a] < ends[b] : a < b; });
}

// Assigns each piece its edge (edge_of): a new one, or that of an earlier piece with the same
// ends and a midpoint within eps (then listed in `merged`, with whether it runs the same way
// as the edge's first piece).
void assign_edges(const std::vector<Piece>& pieces, double eps,
                  const std::function<Curve(const Piece&)>& curve_of, PieceScratch& s) {
  const size_t count = pieces.size();
  auto ends = [&](int i) { return s.end_pairs[size_t(i)]; };
  s.edge_of.assign(count, -1);
  s.first.clear();
  s.mid.clear();
  s.merged.clear();
  s.same_way.assign(count, 1);
  for (size_t i = 0; i < count; ++i) {
    const int p = s.order[i];
    const bool after_same = i > 0 && ends(s.order[i - 1]) == ends(p);
    const bool before_same = i + 1 < count && ends(s.order[i + 1]) == ends(p);
    if (!after_same && !before_same) {  // the only piece between its ends
      s.edge_of[size_t(p)] = int(s.first.size());
      s.first.push_back(p);
      continue;
    }
    const Piece& e = pieces[size_t(p)];
    const Curve curve = curve_of(e);
    const Vec2 mid = point_at(curve, 0.5);
    int into = -1;
    for (size_t j = i; j-- > 0 && ends(s.order[j]) == ends(p);) {
      if (distance(s.mid[size_t(s.edge_of[size_t(s.order[j])])], mid) <= eps) {
        into = s.edge_of[size_t(s.order[j])];
        break;
      }
    }
    if (into < 0) {
      s.edge_of[size_t(p)] = int(s.first.size());
      s.mid.resize(s.first.size() + 1);
      s.mid.back() = mid;
      s.first.push_back(p);
      continue;
    }
    const Piece& o = pieces[size_t(s.first[size_t(into)])];
    s.edge_of[size_t(p)] = into;
    s.same_way[size_t(p)] =
        o.u == e.u && o.v == e.v && (e.u != e.v || curve_of(o).sweep * curve.sweep > 0);
    s.merged.push_back(p);
  }
}

// Per vertex, from the edges: degree, the xor of their ids (a vertex of degree one names its
// edge), and whether they are simple (one-sided, naming at most two contact segments). A
// loop adds two to its vertex's degree, and so never lets it be a leaf.
void survey(const std::vector<Piece>& pieces, size_t vertices, PieceScratch& s) {
  const size_t edges = s.first.size();
  s.degree.assign(vertices, 0);
  s.edge_xor.assign(vertices, 0);
  s.first_id.assign(vertices, -1);
  s.second_id.assign(vertices, -1);
  s.simple.assign(vertices, 1);
  s.one_sided.assign(edges, 1);
  s.ends_xor.resize(edges);
  auto name = [&](int v, int id) {
    if (s.first_id[size_t(v)] < 0 || s.first_id[size_t(v)] == id)
      s.first_id[size_t(v)] = id;
    else if (s.second_id[size_t(v)] < 0 || s.second_id[size_t(v)] == id)
      s.second_id[size_t(v)] = id;
    else
      s.simple[size_t(v)] = 0;
  };
  for (size_t k = 0; k < edges; ++k) {
    const size_t p = size_t(s.first[k]);
    const auto [u, v] = s.end_pairs[p];
    name(u, pieces[p].segment);
    name(v, pieces[p].segment);
    s.ends_xor[k] = u ^ v;
    if (u == v) {
      s.degree[size_t(u)] += 2;
      continue;
    }
    ++s.degree[size_t(u)];
    ++s.degree[size_t(v)];
    s.edge_xor[size_t(u)] ^= int(k);
    s.edge_xor[size_t(v)] ^= int(k);
  }
  for (const int p : s.merged) {
    const auto [u, v] = s.end_pairs[size_t(p)];
    name(u, pieces[size_t(p)].segment);
    name(v, pieces[size_t(p)].segment);
    if (s.same_way[size_t(p)]) continue;
    s.one_sided[size_t(s.edge_of[size_t(p)])] = 0;
    s.simple[size_t(u)] = s.simple[size_t(v)] = 0;
  }
}

// Whether the edge of inside piece x is that piece alone, one-sided, between simple vertices,
// and its crossing still has degree 4: both its faces are blocked.
bool still_inside(const std::vector<Piece>& pieces, const PieceScratch& s, InsidePiece x) {
  const size_t k = size_t(s.edge_of[size_t(x.piece)]);
  const Piece& p = pieces[size_t(x.piece)];
  return s.first[k] == x.piece && s.one_sided[k] && p.u != p.v && s.degree[size_t(x.vertex)] == 4 &&
         s.simple[size_t(p.u)] && s.simple[size_t(p.v)];
}

// Takes out the edges inside a crossing (decided on the degrees before any goes), then peels
// edges from the simple leaves inward (peeled[k] = 1), as long as they are one-sided and
// lead to a simple vertex.
void peel_dangling(const std::vector<Piece>& pieces, size_t vertices,
                   const std::vector<InsidePiece>& inside, PieceScratch& s) {
  survey(pieces, vertices, s);
  s.peeled.assign(s.first.size(), 0);
  s.going.clear();
  for (const InsidePiece x : inside)
    if (still_inside(pieces, s, x)) s.going.push_back(s.edge_of[size_t(x.piece)]);
  for (const int k : s.going) {
    if (s.peeled[size_t(k)]) continue;  // inside at both its ends
    s.peeled[size_t(k)] = 1;
    const auto [u, v] = s.end_pairs[size_t(s.first[size_t(k)])];
    --s.degree[size_t(u)];
    --s.degree[size_t(v)];
    s.edge_xor[size_t(u)] ^= k;
    s.edge_xor[size_t(v)] ^= k;
  }
  s.leaves.clear();
  for (size_t v = 0; v < vertices; ++v)
    if (s.degree[v] == 1 && s.simple[v]) s.leaves.push_back(int(v));
  while (!s.leaves.empty()) {
    const int v = s.leaves.back();
    s.leaves.pop_back();
    if (s.degree[size_t(v)] != 1) continue;  // its edge went from the other end
    const int k = s.edge_xor[size_t(v)];
    const int w = s.ends_xor[size_t(k)] ^ v;
    if (!s.one_sided[size_t(k)] || !s.simple[size_t(w)]) continue;
    s.peeled[size_t(k)] = 1;
    s.degree[size_t(v)] = 0;
    s.edge_xor[size_t(w)] ^= k;
    if (--s.degree[size_t(w)] == 1) s.leaves.push_back(w);
  }
}

}  // namespace

void set_slice_peeling(bool on) {
  g_peeling.store(on);
}
bool slice_peeling() {
  return g_peeling.load(std::memory_order_relaxed);
}

void edges_from_pieces(const std::vector<Piece>& pieces, size_t vertices, double eps, bool peel,
                       const std::vector<InsidePiece>& inside,
                       const std::function<Curve(const Piece&)>& curve_of,
                       const std::function<void(const Piece&)>& emit, PieceScratch& s,
                       std::vector<ArrangementEdge>& edges) {
  order_by_ends(pieces, vertices, s);
  assign_edges(pieces, eps, curve_of, s);
  if (peel) peel_dangling(pieces, vertices, inside, s);
  const size_t count = s.first.size();
  s.index.resize(count);
  edges.reserve(edges.size() + count);
  for (size_t k = 0; k < count; ++k) {
    if (peel && s.peeled[k]) {
      s.index[k] = -1;
      continue;
    }
    s.index[k] = int(edges.size());
    emit(pieces[size_t(s.first[k])]);
  }
  for (const int p : s.merged) {
    const int k = s.index[size_t(s.edge_of[size_t(p)])];
    if (k >= 0)
      edges[size_t(k)].labels.push_back({pieces[size_t(p)].segment, bool(s.same_way[size_t(p)])});
  }
}

}  // namespace cslice
