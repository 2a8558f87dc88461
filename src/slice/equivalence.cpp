// Label-preserving isomorphism of contact graphs.
//
// Contact graphs are small and their labels (feature pairs) nearly unique, so colour
// refinement usually leaves classes of one node and the search below is linear; classes
// of several nodes (a feature pair with two contact segments, symmetric parts) are
// resolved by backtracking, which keeps the answer exact.
#include "cslice/equivalence.hpp"

#include <algorithm>
#include <map>
#include <sstream>

namespace cslice {
namespace {

using Label = std::pair<int, int>;  // (moving feature, fixed feature)

struct LabelledGraph {
  std::vector<Label> labels;                // per node
  std::map<std::pair<int, int>, int> mult;  // (u, v) with u < v -> number of meeting points
  std::vector<std::vector<int>> neighbours;
  int edges = 0;
};

LabelledGraph graph_of(const Slice& s) {
  LabelledGraph g;
  std::map<int, int> index;  // segment id -> node
  for (int id : s.contact_graph.nodes) {
    index[id] = int(g.labels.size());
    const ContactSegment& c = s.contact_segments[id];
    g.labels.push_back({c.moving_feature, c.fixed_feature});
  }
  g.neighbours.resize(g.labels.size());
  for (const ContactGraphEdge& e : s.contact_graph.edges) {
    const int u = index.at(e.a), v = index.at(e.b);
    if (g.mult[{std::min(u, v), std::max(u, v)}]++ == 0) {
      g.neighbours[u].push_back(v);
      g.neighbours[v].push_back(u);
    }
    ++g.edges;
  }
  return g;
}

int multiplicity(const LabelledGraph& g, int u, int v) {
  auto it = g.mult.find({std::min(u, v), std::max(u, v)});
  return it == g.mult.end() ? 0 : it->second;
}

std::string label_text(Label l) {
  std::ostringstream out;
  out << "(moving feature " << l.first << ", fixed feature " << l.second << ")";
  return out.str();
}

// One round of refinement on both graphs with a shared dictionary, so colours compare.
std::vector<std::vector<int>> refine(const std::vector<const LabelledGraph*>& graphs,
                                     const std::vector<std::vector<int>>& colours) {
  std::map<std::vector<int>, int> dictionary;
  std::vector<std::vector<int>> next(graphs.size());
  for (size_t k = 0; k < graphs.size(); ++k) {
    const LabelledGraph& g = *graphs[k];
    next[k].resize(g.labels.size());
    for (size_t u = 0; u < g.labels.size(); ++u) {
      std::vector<int> signature{colours[k][u]};
      std::vector<std::pair<int, int>> around;
      for (int v : g.neighbours[u]) around.push_back({colours[k][v], multiplicity(g, int(u), v)});
      std::sort(around.begin(), around.end());
      for (auto [c, m] : around) signature.insert(signature.end(), {c, m});
      next[k][u] = dictionary.emplace(signature, int(dictionary.size())).first->second;
    }
  }
  return next;
}

std::map<int, int> histogram(const std::vector<int>& colours) {
  std::map<int, int> h;
  for (int c : colours) ++h[c];
  return h;
}

class Matcher {
 public:
  Matcher(const LabelledGraph& a, const LabelledGraph& b, const std::vector<int>& ca,
          const std::vector<int>& cb)
      : a_(a), b_(b), ca_(ca), cb_(cb), map_(a.labels.size(), -1), preimage_(b.labels.size(), -1) {
    order_.resize(a.labels.size());
    for (size_t i = 0; i < order_.size(); ++i) order_[i] = int(i);
    // Nodes of rare colours first, then by colour, so neighbours constrain early.
    const std::map<int, int> sizes = histogram(ca);
    std::sort(order_.begin(), order_.end(), [&](int x, int y) {
      const int sx = sizes.at(ca[x]), sy = sizes.at(ca[y]);
      return sx != sy ? sx < sy : (ca[x] != ca[y] ? ca[x] < ca[y] : x < y);
    });
  }
  bool run() { return extend(0); }

 private:
  bool consistent(int u, int w) const {
    for (int v : a_.neighbours[u])
      if (map_[v] >= 0 && multiplicity(a_, u, v) != multiplicity(b_, w, map_[v])) return false;
    // A neighbour of w already used as an image must be the image of a neighbour of u.
    for (int x : b_.neighbours[w])
      if (preimage_[x] >= 0 && multiplicity(a_, u, preimage_[x]) == 0) return false;
    return true;
  }
  bool extend(size_t k) {
    if (k == order_.size()) return true;
    const int u = order_[k];
    for (size_t w = 0; w < b_.labels.size(); ++w) {
      if (preimage_[w] >= 0 || cb_[w] != ca_[u] || !consistent(u, int(w))) continue;
      map_[u] = int(w);
      preimage_[w] = u;
      if (extend(k + 1)) return true;
      map_[u] = -1;
      preimage_[w] = -1;
    }
    return false;
  }

  const LabelledGraph &a_, &b_;
  const std::vector<int>&ca_, &cb_;
  std::vector<int> map_;       // node of a -> node of b
  std::vector<int> preimage_;  // node of b -> node of a
  std::vector<int> order_;
};

EquivalenceResult differ(const std::string& why) {
  return {false, why};
}

// Compares the label multisets; empty when they agree.
std::string label_difference(const LabelledGraph& a, const LabelledGraph& b) {
  std::map<Label, std::pair<int, int>> counts;
  for (Label l : a.labels) ++counts[l].first;
  for (Label l : b.labels) ++counts[l].second;
  for (const auto& [label, n] : counts) {
    if (n.first == n.second) continue;
    std::ostringstream out;
    out << "contact segments of " << label_text(label) << ": " << n.first << " in the first slice, "
        << n.second << " in the second";
    return out.str();
  }
  return {};
}

}  // namespace

EquivalenceResult slices_equivalent(const Slice& sa, const Slice& sb) {
  const LabelledGraph a = graph_of(sa), b = graph_of(sb);
  if (std::string why = label_difference(a, b); !why.empty()) return differ(why);
  if (a.edges != b.edges) {
    std::ostringstream out;
    out << "meeting points of realizable contact segments: " << a.edges << " in the first slice, "
        << b.edges << " in the second";
    return differ(out.str());
  }
  // Initial colours: the labels, numbered in one shared order.
  std::map<Label, int> label_colour;
  for (Label l : a.labels) label_colour.emplace(l, int(label_colour.size()));
  std::vector<std::vector<int>> colours(2);
  for (Label l : a.labels) colours[0].push_back(label_colour.at(l));
  for (Label l : b.labels) colours[1].push_back(label_colour.at(l));
  size_t classes = label_colour.size();
  for (;;) {
    colours = refine({&a, &b}, colours);
    if (histogram(colours[0]) != histogram(colours[1])) {
      // Find a node whose neighbourhood has no counterpart, to name it.
      const std::map<int, int> ha = histogram(colours[0]), hb = histogram(colours[1]);
      for (size_t u = 0; u < a.labels.size(); ++u) {
        const int c = colours[0][u];
        if (!hb.count(c) || hb.at(c) != ha.at(c))
          return differ("the contact segment of " + label_text(a.labels[u]) +
                        " meets different contact segments in the two slices");
      }
      return differ("the contact segments meet differently in the two slices");
    }
    const size_t now = histogram(colours[0]).size();
    if (now == classes) break;
    classes = now;
  }
  if (!Matcher(a, b, colours[0], colours[1]).run())
    return differ("no label-preserving isomorphism between the contact graphs");
  return {true, {}};
}

}  // namespace cslice
