// Label-preserving isomorphism of contact graphs.
//
// Contact graphs are small and their labels (feature pairs) nearly unique. When every label
// is used once the map is forced and one sorted comparison decides. Otherwise colour
// refinement usually leaves classes of one node and the search below is linear; classes
// of several nodes (a feature pair with two contact segments, symmetric parts) are
// resolved by backtracking, which keeps the answer exact.
#include "cslice/equivalence.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <stdexcept>

namespace cslice {
namespace {

using Label = std::pair<int, int>;  // (moving feature, fixed feature)

struct Neighbour {
  int node = 0;
  int meetings = 0;  // meeting points of the two contact segments
};

struct Meeting {
  int u = 0, v = 0;  // u < v
  int count = 0;
  auto operator<=>(const Meeting&) const = default;
};

struct LabelledGraph {
  std::vector<Label> labels;      // per node
  std::vector<Meeting> meetings;  // sorted, one per pair of nodes that meet
  std::vector<std::vector<Neighbour>> neighbours;
  int edges = 0;  // meeting points in all
};

// Meetings listed once per meeting point, pairs ordered, made distinct with their counts.
std::vector<Meeting> count_meetings(std::vector<Meeting> raw) {
  std::sort(raw.begin(), raw.end());
  std::vector<Meeting> out;
  for (const Meeting& m : raw) {
    if (!out.empty() && out.back().u == m.u && out.back().v == m.v)
      out.back().count += m.count;
    else
      out.push_back(m);
  }
  return out;
}

LabelledGraph graph_of(const Slice& s) {
  LabelledGraph g;
  std::vector<int> index(s.contact_segments.size(), -1);  // segment id -> node
  for (int id : s.contact_graph.nodes) {
    index.at(id) = int(g.labels.size());
    const ContactSegment& c = s.contact_segments[id];
    g.labels.push_back({c.moving_feature, c.fixed_feature});
  }
  std::vector<Meeting> raw;
  for (const ContactGraphEdge& e : s.contact_graph.edges) {
    const int u = index.at(e.a), v = index.at(e.b);
    if (u < 0 || v < 0) throw std::out_of_range("contact graph edge between non-nodes");
    raw.push_back({std::min(u, v), std::max(u, v), 1});
  }
  g.edges = int(raw.size());
  g.meetings = count_meetings(std::move(raw));
  g.neighbours.resize(g.labels.size());
  for (const Meeting& m : g.meetings) {
    g.neighbours[m.u].push_back({m.v, m.count});
    g.neighbours[m.v].push_back({m.u, m.count});
  }
  return g;
}

int multiplicity(const LabelledGraph& g, int u, int v) {
  for (const Neighbour& n : g.neighbours[u])
    if (n.node == v) return n.meetings;
  return 0;
}

std::string label_text(Label l) {
  std::ostringstream out;
  out << "(moving feature " << l.first << ", fixed feature " << l.second << ")";
  return out.str();
}

// One round of refinement on both graphs at once: each node's new colour numbers its
// signature (its colour, then its neighbours' colours and meeting counts, sorted) in the
// sorted order of all signatures of both graphs, so colours compare across the graphs.
std::vector<std::vector<int>> refine(const std::vector<const LabelledGraph*>& graphs,
                                     const std::vector<std::vector<int>>& colours) {
  std::vector<std::vector<int>> signatures;
  std::vector<std::pair<int, int>> around;
  for (size_t k = 0; k < graphs.size(); ++k) {
    const LabelledGraph& g = *graphs[k];
    for (size_t u = 0; u < g.labels.size(); ++u) {
      around.clear();
      for (const Neighbour& n : g.neighbours[u]) around.push_back({colours[k][n.node], n.meetings});
      std::sort(around.begin(), around.end());
      std::vector<int> signature{colours[k][u]};
      for (auto [c, m] : around) signature.insert(signature.end(), {c, m});
      signatures.push_back(std::move(signature));
    }
  }
  std::vector<int> order(signatures.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::sort(order.begin(), order.end(),
            [&](int x, int y) { return signatures[x] < signatures[y]; });
  std::vector<int> colour(signatures.size());
  int next = -1;
  for (size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || signatures[order[i]] != signatures[order[i - 1]]) ++next;
    colour[order[i]] = next;
  }
  std::vector<std::vector<int>> out(graphs.size());
  size_t at = 0;
  for (size_t k = 0; k < graphs.size(); ++k)
    for (size_t u = 0; u < graphs[k]->labels.size(); ++u) out[k].push_back(colour[at++]);
  return out;
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
    for (const Neighbour& n : a_.neighbours[u])
      if (map_[n.node] >= 0 && n.meetings != multiplicity(b_, w, map_[n.node])) return false;
    // A neighbour of w already used as an image must be the image of a neighbour of u.
    for (const Neighbour& x : b_.neighbours[w])
      if (preimage_[x.node] >= 0 && multiplicity(a_, u, preimage_[x.node]) == 0) return false;
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
  std::vector<Label> la = a.labels, lb = b.labels;
  std::sort(la.begin(), la.end());
  std::sort(lb.begin(), lb.end());
  if (la == lb) return {};
  const auto [ia, ib] = std::mismatch(la.begin(), la.end(), lb.begin(), lb.end());
  const Label label = ib == lb.end() || (ia != la.end() && *ia < *ib) ? *ia : *ib;
  std::ostringstream out;
  out << "contact segments of " << label_text(label) << ": "
      << std::count(la.begin(), la.end(), label) << " in the first slice, "
      << std::count(lb.begin(), lb.end(), label) << " in the second";
  return out.str();
}

bool labels_distinct(const LabelledGraph& g) {
  std::vector<Label> sorted = g.labels;
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

// With every label used once (the common case: a feature pair rarely makes two contact
// segments), the only label-preserving map is by label, so the graphs are isomorphic
// exactly when b's meetings, renamed by it, are a's.
EquivalenceResult compare_by_labels(const LabelledGraph& a, const LabelledGraph& b) {
  std::vector<std::pair<Label, int>> by_label;
  for (size_t u = 0; u < a.labels.size(); ++u) by_label.push_back({a.labels[u], int(u)});
  std::sort(by_label.begin(), by_label.end());
  const auto node_in_a = [&](Label l) {
    return std::lower_bound(by_label.begin(), by_label.end(), std::pair{l, -1})->second;
  };
  std::vector<Meeting> renamed;
  for (const Meeting& m : b.meetings) {
    const int u = node_in_a(b.labels[m.u]), v = node_in_a(b.labels[m.v]);
    renamed.push_back({std::min(u, v), std::max(u, v), m.count});
  }
  std::sort(renamed.begin(), renamed.end());
  if (renamed == a.meetings) return {true, {}};
  const auto [ma, mb] =
      std::mismatch(a.meetings.begin(), a.meetings.end(), renamed.begin(), renamed.end());
  const int u = ma != a.meetings.end() ? ma->u : mb->u;
  return differ("the contact segment of " + label_text(a.labels[u]) +
                " meets different contact segments in the two slices");
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
  if (labels_distinct(a)) return compare_by_labels(a, b);
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
