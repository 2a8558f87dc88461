// The slice: arrangement faces labelled free or blocked, realizable pieces, degenerate
// contacts, free components and the contact graph.
//
// Labelling is local wherever the geometry allows it: a face lying on the blocked side of
// any contact segment along its boundary is blocked (the two features overlap just across
// that segment), unless the edge is blocked from both sides by its own labels. Only faces
// with no edge blocking them from one side only, pieces with blocked space on both sides of
// their own labels (a sliding fit, or a sliver thinner than eps), and vertices whose
// every surrounding sector is blocked by segments through the vertex itself (a perfect fit)
// are settled by the direct placement test, at one point each.
#include <algorithm>
#include <optional>

#include "contacts/contact_features.hpp"
#include "cslice/classify.hpp"
#include "cslice/slice.hpp"
#include "slice/arrangement.hpp"
#include "slice/blocked_proof.hpp"
#include "slice/edge_pieces.hpp"
#include "slice/face_sample.hpp"
#include "slice/small_sort.hpp"

namespace cslice {
namespace {

// Sorted, each id once. Mostly the two contact segments meeting at a vertex: those directly.
void sort_unique(std::vector<int>& ids) {
  if (ids.size() == 2) {  // in either order as often: min and max, not a branch
    const int lo = std::min(ids[0], ids[1]), hi = std::max(ids[0], ids[1]);
    ids[0] = lo;
    ids[1] = hi;
    if (lo == hi) ids.pop_back();
    return;
  }
  small_sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

// One half-edge leaving a vertex, as sectors_explained_locally sees it.
struct SectorSide {
  Vec2 dir;
  bool blocks_left, blocks_right, explained;
};

// Buffers of one slice's construction, kept by the Slicer between slices.
struct SliceScratch {
  ArrangementBuilder arrangements;
  std::vector<Curve> curves;
  std::vector<int> ids, vertex_ids;
  std::vector<char> blocked, realizable, is_node;
  std::vector<unsigned char> label_sides;  // per edge: kBlockedLeft | kBlockedRight
  std::vector<int> lowest_label;           // per edge: the lowest contact segment id
  std::vector<Vec2> samples;
  std::vector<SectorSide> sides;
  FaceSampleScratch face_sample;
  BlockedProof proof;
  std::vector<char> proven;     // per contact segment: proven blocked, left out of the arrangement
  size_t segments_hint = 0;     // contact segments of the last slice: the next has about as many
  size_t graph_edges_hint = 0;  // the same for the contact graph's edges
};

class SliceBuilder {
 public:
  SliceBuilder(const Pair& pair, ContactMaker& contacts, std::optional<PlacementTester>& tester,
               std::optional<PairRegions>& regions, SliceScratch& scratch, double theta)
      : pair_(pair),
        contacts_(contacts),
        tester_(tester),
        regions_(regions),
        theta_(principal_angle(theta)),
        blocked_(scratch.blocked),
        samples_(scratch.samples),
        realizable_(scratch.realizable),
        scratch_(scratch) {}

  Slice build() {
    slice_.theta = theta_;
    slice_.epsilon = pair_.tol.geometric;
    slice_.contact_segments.reserve(scratch_.segments_hint);
    contacts_.segments(theta_, slice_.contact_segments);
    scratch_.segments_hint = slice_.contact_segments.size();
    std::vector<Curve>& curves = scratch_.curves;
    std::vector<int>& ids = scratch_.ids;
    curves.clear();
    ids.clear();
    prove_blocked();
    for (const ContactSegment& s : slice_.contact_segments) {
      if (s.is_point || scratch_.proven[size_t(s.id)]) continue;
      curves.push_back(s.curve);
      ids.push_back(s.id);
    }
    arr_ = &scratch_.arrangements.build(curves, ids, pair_.tol, &contacts_.trig(), slice_peeling());
    summarize_labels();
    label_faces();
    find_realizable_edges();
    find_degenerate_vertices();
    find_point_contacts();
    collect_components();
    build_contact_graph();
    return std::move(slice_);
  }

 private:
  // Marks the contact segments proven blocked (slice/blocked_proof.hpp), where that is worth
  // looking for; the pair's material regions are found on first use.
  void prove_blocked() {
    std::vector<char>& proven = scratch_.proven;
    if (!worth_proving(pair_, slice_.contact_segments.size())) {
      proven.assign(slice_.contact_segments.size(), 0);
      return;
    }
    if (!regions_) regions_.emplace(pair_regions(pair_));
    scratch_.proof.find(slice_.contact_segments, *regions_, proof_margin(pair_), proven);
  }

  // The tester is built on first use: many slices settle every face by its labels.
  bool blocked_at(Vec2 p) {
    if (!tester_) tester_.emplace(pair_);
    return tester_->blocked({p.x, p.y, theta_});
  }

  void label_faces() {
    blocked_.assign(arr_->faces.size(), false);
    samples_.assign(arr_->faces.size(), Vec2{});
    for (size_t f = 0; f < arr_->faces.size(); ++f) {
      if (labels_block(int(f))) {
        blocked_[f] = true;
        continue;
      }
      const bool unbounded = !arr_->faces[f].bounded;
      Box box;
      for (int c : arr_->face_cycles(int(f))) box.add(scratch_.arrangements.cycle_box(c));
      // Every edge peeled (dangling in the unbounded face): beyond the curves instead.
      if (unbounded && box.empty())
        for (const Curve& c : scratch_.curves) box.add(bounding_box(c));
      samples_[f] = face_sample(*arr_, int(f), box, pair_.tol, scratch_.face_sample);
      // Blocked space lies inside the box of all contact segments, and the unbounded face's
      // sample lies beyond it: there the parts are apart, inside an enclosure's material when
      // the fixed part is one. Only with no curve in the arrangement (no contact segment, or
      // each proven blocked) is the direct test needed.
      if (unbounded && !scratch_.curves.empty())
        blocked_[f] = pair_.fixed.enclosure;
      else
        blocked_[f] = blocked_at(samples_[f]);
    }
  }

  // Whether a label along face f's boundary puts blocked space in f (and not on the other
  // side too): the first such half-edge settles it.
  bool labels_block(int f) const {
    for (int c : arr_->face_cycles(f))
      for (int h : arr_->half_edges(c))
        if (labels_block_left_only(h)) return true;
    return false;
  }

  // Per edge, from one pass over its labels: on which of its sides they put blocked space,
  // and the lowest contact segment among them (the one its pieces name). Read for each
  // face, vertex and piece beside the edge.
  static constexpr unsigned char kBlockedLeft = 1, kBlockedRight = 2;
  void summarize_labels() {
    std::vector<unsigned char>& sides = scratch_.label_sides;
    std::vector<int>& lowest = scratch_.lowest_label;
    const size_t edges = arr_->edges.size();  // read once: the stores below could alias it
    sides.resize(edges);
    lowest.resize(edges);
    for (size_t e = 0; e < edges; ++e) {
      const EdgeLabels& labels = arr_->edges[e].labels;
      unsigned char side = 0;
      int low = labels.front().segment;
      for (const EdgeLabel& l : labels) {
        side |= l.blocked_left ? kBlockedLeft : kBlockedRight;
        low = std::min(low, l.segment);
      }
      sides[e] = side;
      lowest[e] = low;
    }
  }
  // Whether a label of h's edge puts blocked space on h's left, or on its right.
  bool blocks_left_of(int h) const {
    return scratch_.label_sides[h / 2] & (h % 2 == 0 ? kBlockedLeft : kBlockedRight);
  }
  bool blocks_right_of(int h) const {
    return scratch_.label_sides[h / 2] & (h % 2 == 0 ? kBlockedRight : kBlockedLeft);
  }

  // Whether the labels of h's edge put blocked space on h's left and not on its right. An
  // edge blocked from both sides by its own labels says nothing about the faces beside it:
  // it is a sliding fit (both faces blocked) or a sliver of blocked space thinner than the
  // geometric epsilon, collapsed onto the edge when its sides were snapped together (at a
  // critical orientation, two contact segments leaving a vertex-vertex contact at a shallow
  // angle, one ending within eps of the other), with free space on both sides. Such faces
  // are settled by their other edges or by the direct test.
  bool labels_block_left_only(int h) const { return blocks_left_of(h) && !blocks_right_of(h); }

  void find_realizable_edges() {
    const size_t edges = arr_->edges.size();  // read once: the stores below could alias it
    realizable_.assign(edges, false);
    for (size_t e = 0; e < edges; ++e) {
      const ArrangementEdge& edge = arr_->edges[e];
      if (!blocked_[arr_->face_of(int(2 * e))] || !blocked_[arr_->face_of(int(2 * e + 1))]) {
        realizable_[e] = true;
        continue;
      }
      const bool both = scratch_.label_sides[e] == (kBlockedLeft | kBlockedRight);
      if (!both || blocked_at(point_at(edge.curve, 0.5))) continue;
      realizable_[e] = true;
      DegenerateContact d;
      d.segments = label_ids(int(e));
      d.curve = edge.curve;
      slice_.degenerate.push_back(std::move(d));
    }
  }

  std::vector<int> label_ids(int e) const {
    std::vector<int> ids;
    for (const EdgeLabel& l : arr_->edges[e].labels) ids.push_back(l.segment);
    sort_unique(ids);
    return ids;
  }

  // Whether every sector around v is blocked by contact segments ending at or passing
  // through v: only then can v itself be a contact configuration with no free space near.
  // A label blocks the side of its curve it faces; near v that covers a sector narrower
  // than a half turn beside it, while a wider sector (a dead end's whole neighbourhood)
  // needs blocking from both of its sides. Two labels leaving v in opposite directions with
  // their blocked sides on one side (one contact curve continuing through v, possibly as
  // two segments meeting end to end) block the whole half plane on that side.
  bool sectors_explained_locally(int v) {
    const std::span<const int> out = arr_->outgoing(int(v));
    const int d = int(out.size());
    // A dead end (a contact segment's end that meets nothing, as rough contours have by the
    // hundred) has one sector, the whole turn: blocked from both sides or not explained.
    if (d == 1) return blocks_left_of(out[0]) && blocks_right_of(out[0]);
    // Per half-edge (reused buffer: called for most vertices of big slices): its direction,
    // whether a label of it blocks its left (the sector counterclockwise of it) and its
    // right.
    std::vector<SectorSide>& side = scratch_.sides;
    side.resize(d);
    for (int i = 0; i < d; ++i) {
      SectorSide& x = side[i];
      x.dir = arr_->direction(out[i]);
      x.blocks_left = blocks_left_of(out[i]);
      x.blocks_right = blocks_right_of(out[i]);
    }
    bool all = true;
    for (int i = 0; i < d; ++i) {
      const SectorSide& next = side[i + 1 < d ? i + 1 : 0];
      const bool from_cw_side = side[i].blocks_left;
      const bool from_ccw_side = next.blocks_right;
      const bool narrow = d > 1 && cross(side[i].dir, next.dir) > 0.0;
      side[i].explained =
          narrow ? (from_cw_side || from_ccw_side) : (from_cw_side && from_ccw_side);
      all = all && side[i].explained;
    }
    if (all) return true;  // the half planes below only explain more
    for (int i = 0; i < d; ++i) {
      if (!side[i].blocks_left) continue;
      for (int j = 0; j < d; ++j) {
        if (i == j || !side[j].blocks_right || dot(side[i].dir, side[j].dir) > 0.0 ||
            std::fabs(cross(side[i].dir, side[j].dir)) > pair_.tol.angular)
          continue;
        for (int k = i; k != j; k = k + 1 < d ? k + 1 : 0) side[k].explained = true;
      }
    }
    return std::all_of(side.begin(), side.end(), [](const SectorSide& x) { return x.explained; });
  }

  void find_degenerate_vertices() {
    const size_t vertices = arr_->vertices.size();  // read once: the stores below could alias it
    for (size_t v = 0; v < vertices; ++v) {
      const std::span<const int> out = arr_->outgoing(int(v));
      if (out.empty()) continue;
      // Most vertices fail at their first half-edge: stop there. An edge that is not
      // realizable has blocked faces on both sides (find_realizable_edges), so its own mark
      // says whether the face beside it is blocked.
      const bool all_blocked =
          std::none_of(out.begin(), out.end(), [&](int h) { return realizable_[h / 2]; });
      if (!all_blocked || !sectors_explained_locally(int(v))) continue;
      if (blocked_at(arr_->vertices[v])) continue;
      std::vector<int> ids;
      for (int h : out)
        for (const EdgeLabel& l : arr_->edges[h / 2].labels) ids.push_back(l.segment);
      sort_unique(ids);
      add_degenerate_point(arr_->vertices[v], std::move(ids));
    }
  }

  void add_degenerate_point(Vec2 p, std::vector<int> ids) {
    for (DegenerateContact& d : slice_.degenerate) {
      if (d.is_point && distance(d.curve.from, p) <= pair_.tol.geometric) {
        d.segments.insert(d.segments.end(), ids.begin(), ids.end());
        sort_unique(d.segments);
        return;
      }
    }
    DegenerateContact d;
    d.is_point = true;
    d.curve = make_segment(p, p);
    d.segments = std::move(ids);
    slice_.degenerate.push_back(std::move(d));
  }

  // Perfect fits of equal circles: contact space is one point whatever else happens there.
  void find_point_contacts() {
    for (const ContactSegment& s : slice_.contact_segments)
      if (s.is_point && !blocked_at(s.curve.from)) add_degenerate_point(s.curve.from, {s.id});
  }

  // Appends the piece of half-edge h (built in place: a piece is mostly its curve).
  void add_piece(std::vector<ContactPiece>& pieces, int h) const {
    pieces.emplace_back(scratch_.lowest_label[h / 2], arr_->half_curve(h));
  }

  void collect_components() {
    // Sized once: growing them piece by piece cost several allocations per slice.
    slice_.realizable.reserve(std::count(realizable_.begin(), realizable_.end(), true));
    const size_t edges = arr_->edges.size();  // read once: the stores below could alias it
    for (size_t e = 0; e < edges; ++e)
      if (realizable_[e]) {
        add_piece(slice_.realizable, int(2 * e));
        if (arr_->edges[e].labels.size() > 1) slice_.coincident_pieces = true;
      }
    slice_.free_components.reserve(std::count(blocked_.begin(), blocked_.end(), false));
    for (size_t f = 0; f < arr_->faces.size(); ++f) {
      if (blocked_[f]) {
        slice_.blocked_area += face_area(int(f));
        continue;
      }
      FreeComponent comp;
      comp.id = int(slice_.free_components.size());
      comp.bounded = arr_->faces[f].bounded;
      comp.sample = samples_[f];
      comp.boundary.reserve(arr_->faces[f].count);
      for (int c : arr_->face_cycles(int(f))) {
        std::vector<ContactPiece>& cycle = comp.boundary.emplace_back();
        cycle.reserve(arr_->cycles[c].count);
        for (int h : arr_->half_edges(c)) add_piece(cycle, h);
      }
      comp.area = face_area(int(f));
      slice_.free_components.push_back(std::move(comp));
    }
  }

  // Outer cycle plus (negative) hole cycles; NaN for the unbounded face when free, infinity
  // when blocked.
  double face_area(int f) const {
    if (!arr_->faces[f].bounded)
      return blocked_[f] ? std::numeric_limits<double>::infinity()
                         : std::numeric_limits<double>::quiet_NaN();
    double area = 0.0;
    for (int c : arr_->face_cycles(f)) area += arr_->cycles[c].area;
    return area;
  }

  void build_contact_graph() {
    // The nodes, marked by id (ids are indices of contact segments): read back in order,
    // they are sorted and each once, without sorting a list of them with its repeats.
    std::vector<char>& is_node = scratch_.is_node;
    is_node.assign(slice_.contact_segments.size(), false);
    // With no last slice to go by (one-shot), about one meeting per realizable piece: its
    // end, where the next piece of the free space's boundary starts. (Grown by doubling from
    // nothing, the edges were copied eight times over on a smooth star of 400 features.)
    slice_.contact_graph.edges.reserve(
        std::max(scratch_.graph_edges_hint, slice_.realizable.size()));
    std::vector<int>& ids = scratch_.vertex_ids;
    auto add_meetings = [&](const std::vector<int>& at_ids, Vec2 at) {
      for (size_t i = 0; i < at_ids.size(); ++i)
        for (size_t j = i + 1; j < at_ids.size(); ++j)
          slice_.contact_graph.edges.push_back({at_ids[i], at_ids[j], at});
    };
    const size_t vertices = arr_->vertices.size();  // read once: the stores below could alias it
    for (size_t v = 0; v < vertices; ++v) {
      ids.clear();
      for (int h : arr_->outgoing(int(v)))
        if (realizable_[h / 2])
          for (const EdgeLabel& l : arr_->edges[h / 2].labels) ids.push_back(l.segment);
      if (ids.empty()) continue;
      sort_unique(ids);
      for (int id : ids) is_node[id] = true;
      add_meetings(ids, arr_->vertices[v]);
    }
    for (const DegenerateContact& d : slice_.degenerate) {
      for (int id : d.segments) is_node[id] = true;
      if (d.is_point) add_meetings(d.segments, d.curve.from);
    }
    std::vector<int>& nodes = slice_.contact_graph.nodes;
    nodes.reserve(std::count(is_node.begin(), is_node.end(), true));
    for (size_t id = 0; id < is_node.size(); ++id)
      if (is_node[id]) nodes.push_back(int(id));
    scratch_.graph_edges_hint = slice_.contact_graph.edges.size();
  }

  const Pair& pair_;
  ContactMaker& contacts_;
  std::optional<PlacementTester>& tester_;
  std::optional<PairRegions>& regions_;
  double theta_;
  Slice slice_;
  const Arrangement* arr_ = nullptr;
  std::vector<char>& blocked_;     // per face
  std::vector<Vec2>& samples_;     // per face
  std::vector<char>& realizable_;  // per edge
  SliceScratch& scratch_;
};

}  // namespace

// Ids number the contact segments, so marking beats sorting the many repeats (a segment has
// a piece per edge): one pass, ids in increasing order.
void mark_realizable_segments(const Slice& slice, std::vector<char>& marked) {
  marked.assign(slice.contact_segments.size(), 0);
  for (int id : slice.contact_graph.nodes) marked[size_t(id)] = 1;
  for (const ContactPiece& p : slice.realizable) marked[size_t(p.segment)] = 1;
  for (const DegenerateContact& d : slice.degenerate)
    for (int id : d.segments) marked[size_t(id)] = 1;
}

std::vector<int> realizable_segments(const Slice& slice) {
  std::vector<char> marked;
  mark_realizable_segments(slice, marked);
  std::vector<int> ids;
  for (size_t id = 0; id < marked.size(); ++id)
    if (marked[id]) ids.push_back(int(id));
  return ids;
}

struct Slicer::State {
  explicit State(const Pair& p) : pair(p), contacts(p) {}
  const Pair& pair;
  ContactMaker contacts;
  std::optional<PlacementTester> tester;
  std::optional<PairRegions> regions;
  SliceScratch scratch;
};

Slicer::Slicer(const Pair& pair) : state_(std::make_unique<State>(pair)) {}
Slicer::~Slicer() = default;
Slicer::Slicer(Slicer&&) noexcept = default;
Slicer& Slicer::operator=(Slicer&&) noexcept = default;

Slice Slicer::slice(double theta) {
  State& s = *state_;
  return SliceBuilder(s.pair, s.contacts, s.tester, s.regions, s.scratch, theta).build();
}

// One-shot slices reuse this thread's working buffers and contact maker. Fresh ones for every
// call cost more than the slice itself on pairs of a few thousand features: the allocator
// hands the pages of the last call's buffers back to the system when they are freed, and
// faulting them in again took 0.5 ms of a 0.85 ms slice at 1,200 features (240 page faults a
// call), and 12 ms of a 46 ms slice of 58,000 contact segments. A thread keeps them while
// they hold at most kKeptBytes by kept_bytes' bound, and releases them after a larger slice.
namespace {

constexpr size_t kKeptBytes = size_t(64) << 20;

// At least what the maker and a slice's buffers hold, from their sizes: 160 bytes per
// feature (the maker's feature arrays and index), 450 per contact segment (the curves, the
// proof's slabs and grid) and 2,000 per edge of the arrangement (split points, pieces,
// half-edges, their sorting keys and labels). Measured on smooth, rough and curved stars of
// 200 to 250,000 contact segments and on gears, they held 55 to 100% of it
// (docs/performance.md, twenty-first session).
size_t kept_bytes(size_t features, size_t contact_segments, size_t edges) {
  return 160 * features + 450 * contact_segments + 2000 * edges;
}

}  // namespace

Slice compute_slice(const Pair& pair, double theta) {
  thread_local SliceScratch scratch;
  // The contact maker is made anew for this pair, in the storage of the last call's: its
  // feature arrays alone are 120 bytes a feature, fresh pages at each call otherwise.
  thread_local std::unique_ptr<ContactMaker> maker;
  const size_t features = pair.moving.features.size() + pair.fixed.features.size();
  if (maker)
    maker->reset(pair);
  else
    maker = std::make_unique<ContactMaker>(pair);
  ContactMaker& contacts = *maker;
  std::optional<PlacementTester> tester;
  std::optional<PairRegions> regions;
  // The hints size the returned slice's vectors after the last slice of the same pair; with
  // none, about one contact segment per feature (a smooth pair has half as many, a rough one
  // more), as growing the vector by doubling copied every segment twice over.
  scratch.segments_hint = features;
  scratch.graph_edges_hint = 0;
  Slice slice = SliceBuilder(pair, contacts, tester, regions, scratch, theta).build();
  // realizable: one flag per edge of this slice's arrangement
  if (kept_bytes(features, slice.contact_segments.size(), scratch.realizable.size()) > kKeptBytes) {
    scratch = SliceScratch{};
    maker.reset();
  }
  return slice;
}

}  // namespace cslice
