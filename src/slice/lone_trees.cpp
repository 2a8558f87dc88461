#include "slice/lone_trees.hpp"

namespace cslice {

void find_lone_trees(const std::vector<Curve>& curves, const std::vector<SharedPiece>& shared,
                     LoneTreeScratch& s, std::vector<char>& left_out) {
  const size_t n = curves.size();
  s.curves.reset(n);
  s.met_otherwise.assign(n, 0);
  s.links.assign(n, 0);
  for (const SharedPiece& p : shared) {
    if (p.end_to_end) {
      s.curves.unite(p.a, p.b);
      ++s.links[size_t(p.a)];
    } else {
      s.met_otherwise[size_t(p.a)] = s.met_otherwise[size_t(p.b)] = 1;
    }
  }
  // Per class, at its smallest curve (the root): curves less links, and whether any meets
  // another way. A curve's own counts are read before its root's are added to (c >= root).
  s.excess.assign(n, 0);
  for (size_t c = 0; c < n; ++c) {
    const size_t root = size_t(s.curves.find(int(c)));
    s.excess[root] += 1 - s.links[c];
    if (s.met_otherwise[c] || !curves[c].is_segment()) s.met_otherwise[root] = 1;
  }
  left_out.resize(n);
  for (size_t c = 0; c < n; ++c) {
    const size_t root = size_t(s.curves.find(int(c)));
    left_out[c] = !s.met_otherwise[root] && s.excess[root] == 1;
  }
}

}  // namespace cslice
