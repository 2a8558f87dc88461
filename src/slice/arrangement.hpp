// The planar arrangement of contact segments: vertices where they meet, edges (pieces of
// contact segments between vertices, coincident pieces merged and carrying every label),
// and faces traced from a half-edge structure, holes attached to the faces around them.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "cslice/geometry.hpp"
#include "cslice/tolerance.hpp"

namespace cslice {

// A contact segment running along an edge; its blocked side is on the edge's left when
// blocked_left, else on its right.
struct EdgeLabel {
  int segment = 0;
  bool blocked_left = true;
};

// The labels of one edge: nearly always one or two, so those live in place and only more
// go to the heap (an edge is built per piece, and one allocation each dominated).
class EdgeLabels {
 public:
  EdgeLabels() = default;
  explicit EdgeLabels(EdgeLabel l) : size_(1), local_{l, EdgeLabel{}} {}
  EdgeLabels(const EdgeLabels& o) { *this = o; }
  EdgeLabels& operator=(const EdgeLabels& o) {
    if (this != &o) {
      size_ = 0;
      more_.clear();
      for (const EdgeLabel& l : o) push_back(l);
    }
    return *this;
  }
  // Member by member (not default-construct, then assign: every edge is moved twice, once
  // into its piece and once into the arrangement).
  EdgeLabels(EdgeLabels&& o) noexcept
      : size_(o.size_), local_(o.local_), more_(std::move(o.more_)) {
    o.size_ = 0;
  }
  EdgeLabels& operator=(EdgeLabels&& o) noexcept {
    size_ = o.size_;
    local_ = o.local_;
    more_ = std::move(o.more_);
    o.size_ = 0;
    return *this;
  }
  void push_back(EdgeLabel l) {
    if (size_ < kLocal) {
      local_[size_] = l;
    } else {
      if (size_ == kLocal) more_.assign(local_.begin(), local_.end());
      more_.push_back(l);
    }
    ++size_;
  }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const EdgeLabel* begin() const { return size_ <= kLocal ? local_.data() : more_.data(); }
  const EdgeLabel* end() const { return begin() + size_; }
  const EdgeLabel& front() const { return *begin(); }

 private:
  static constexpr size_t kLocal = 2;
  size_t size_ = 0;
  std::array<EdgeLabel, kLocal> local_{};
  std::vector<EdgeLabel> more_;  // all of them, once there are more than kLocal
};

struct ArrangementEdge {
  int u = 0, v = 0;  // vertex ids; the curve runs from u to v
  Curve curve;
  EdgeLabels labels;
  int source = -1;  // index of the curve this piece was cut from (the first, when merged)
  // Unit tangents of the unsnapped contact segment at u and at v (both along the curve):
  // snapping ends to merged vertices would tilt a short piece by up to eps / length.
  Vec2 tangent_u, tangent_v;
  // Where the piece really starts and ends on that contact segment, before snapping to the
  // vertices moved them by up to about eps: orders pieces that leave a vertex side by side.
  Vec2 point_u, point_v;
};

// A closed walk of half-edges with its face on the left. Its half-edges are
// Arrangement::half_edges(cycle): one flat list for all cycles, so that a rebuilt
// arrangement reuses its storage. Its box is ArrangementBuilder::cycle_box(cycle), found
// when asked: most slices need only the free faces' boxes.
struct ArrangementCycle {
  int first = 0, count = 0;  // its half-edges in Arrangement::cycle_half_edges
  double area = 0.0;         // signed: counterclockwise (> 0) around a bounded face
  int face = -1;
  int component = -1;  // connected component of the graph
};

// A face's cycles are Arrangement::face_cycles(face), the outer one first when bounded.
struct ArrangementFace {
  bool bounded = false;
  int first = 0, count = 0;  // its cycles in Arrangement::face_cycle_list
};

// Half-edge h runs along edge h / 2, forward (u to v) when h is even.
struct Arrangement {
  std::vector<Vec2> vertices;
  // Half-edges leaving each vertex, counterclockwise: those of vertex v are
  // outgoing_edges[outgoing_start[v] .. outgoing_start[v + 1]).
  std::vector<int> outgoing_start, outgoing_edges;
  std::span<const int> outgoing(int v) const {
    return {outgoing_edges.data() + outgoing_start[v],
            outgoing_edges.data() + outgoing_start[v + 1]};
  }
  std::vector<ArrangementEdge> edges;
  std::vector<int> next;      // per half-edge: the next one around its face
  std::vector<int> cycle_of;  // per half-edge
  std::vector<ArrangementCycle> cycles;
  std::vector<int> cycle_half_edges;
  std::vector<ArrangementFace> faces;  // faces[0] is the unbounded face
  std::vector<int> face_cycle_list;
  std::span<const int> half_edges(int cycle) const {
    const ArrangementCycle& c = cycles[cycle];
    return {cycle_half_edges.data() + c.first, size_t(c.count)};
  }
  std::span<const int> face_cycles(int face) const {
    const ArrangementFace& f = faces[face];
    return {face_cycle_list.data() + f.first, size_t(f.count)};
  }

  int origin(int h) const { return h % 2 == 0 ? edges[h / 2].u : edges[h / 2].v; }
  int target(int h) const { return h % 2 == 0 ? edges[h / 2].v : edges[h / 2].u; }
  int face_of(int h) const { return cycles[cycle_of[h]].face; }
  // The edge's curve oriented along h (inline: every realizable piece is made from one).
  Curve half_curve(int h) const {
    const Curve& c = edges[h / 2].curve;
    return h % 2 == 0 ? c : reversed(c);
  }
  // Unit tangent of h where it leaves its origin.
  Vec2 direction(int h) const {
    const ArrangementEdge& e = edges[h / 2];
    return h % 2 == 0 ? e.tangent_u : -e.tangent_v;
  }
};

class TrigMemo;  // slice/trig_memo.hpp

// Builds arrangements one after another in the same buffers (its own and the arrangement's):
// a slice of a small pair makes a few dozen edges, and allocating every working array per
// slice cost more than the geometry. Not thread-safe: one per thread.
class ArrangementBuilder {
 public:
  ArrangementBuilder();
  ~ArrangementBuilder();
  ArrangementBuilder(ArrangementBuilder&&) noexcept;
  ArrangementBuilder& operator=(ArrangementBuilder&&) noexcept;
  // The arrangement of `curves` (each oriented with its blocked side on the left); label ids
  // are the curves' indices in `segment_ids`. Valid until the next build. `trig`, when
  // given, holds the sines, cosines and tangents the curves' maker took at their ends.
  // With peel_dangling_edges, edges dangling into blocked faces are left out
  // (slice/edge_pieces.hpp); their vertices stay, some with nothing leaving them: a slice's
  // arrangement, whose blocked faces need not be told apart.
  const Arrangement& build(const std::vector<Curve>& curves, const std::vector<int>& segment_ids,
                           const Tolerances& tol, TrigMemo* trig = nullptr,
                           bool peel_dangling_edges = false);
  // The box of a cycle of the last build: the union of its edges' boxes, in the cycle's
  // order. Found when first asked.
  const Box& cycle_box(int cycle);

  struct Scratch;  // arrangement.cpp

 private:
  std::unique_ptr<Scratch> scratch_;
  Arrangement arr_;
};

}  // namespace cslice
