// Sampling one slice for the contact mesh: each boundary piece (and each degenerate contact
// curve, as two darts) becomes a polyline of mesh vertices with material coordinates.
//
// Where the vertices go. A piece's corners are its ends; corners of the slice closer than its
// epsilon are one vertex, so cycles that touch at a critical slice (a pinch) share it. In a
// regular slice only consecutive pieces' corners are: cycles that touch there (or a cycle
// that touches itself) touch at every orientation of the interval (two free components
// meeting at a point, where a pin passes from a channel's corner into a channel of exactly
// its width), and the strips of both passes would put four triangles on every edge along
// that line. Inside
// a piece the vertices sit on a grid fixed to the features, not to the piece: an arc at the
// multiples of one angle (world angle about the contact circle's centre, which translates
// with theta), a line that turns with theta (a moving segment's contact) at the multiples of
// one length along its contact segment, measured from the segment's end (a point of the
// feature). So a vertex of one slice and the vertex with the same coordinate in the next are
// one point of the feature, whose path between them is within the interpolation tolerance;
// and a chord of a turning line is short enough that its twist between slices is too
// (docs/mesh.md derives both). Grid points nearer than a quarter step to a corner are left out,
// so no chord is much shorter than the step.
#include <algorithm>
#include <cmath>

#include "mesh/mesh_internal.hpp"

namespace cslice::mesh_detail {

namespace {

// Largest turn of one chord of a sampled arc (radians), whatever the tolerance: a quarter
// turn, so that even a coarse tolerance keeps a full circle a square, not a segment.
constexpr double kMaxChordTurn = kPi / 2;
// Cap on the grid steps of one piece, against absurd tolerances.
constexpr double kMaxSteps = 100000;
// Grid points closer than this many steps to a corner are dropped; the chords next to a corner
// are then up to 1 + kCornerGap steps long, which the step sizes allow for.
constexpr double kCornerGap = 0.25;

bool turns_with_theta(ContactKind k) {
  return k == ContactKind::segment_vertex || k == ContactKind::segment_arc;
}

class Sampler {
 public:
  Sampler(const Slice& slice, double theta, const SamplingOptions& options, VertexStore& store)
      : slice_(slice), theta_(theta), options_(options), store_(store) {
    out_.theta = theta;
    out_.slice = &slice;
  }

  SampledSlice run() {
    for (const FreeComponent& comp : slice_.free_components) {
      out_.cycles.emplace_back();
      for (const auto& cycle : comp.boundary) {
        if (!options_.weld_across_cycles) corners_.clear();
        std::vector<int> ids;
        for (const ContactPiece& p : cycle) {
          ids.push_back(static_cast<int>(out_.pieces.size()));
          out_.pieces.push_back(sample(p.curve, p.segment));
          // Only the cycle's first corner and this piece's end can be the next piece's start
          // (a cycle that touches itself there passes twice, on vertices of its own).
          if (!options_.weld_across_cycles && corners_.size() > 2)
            corners_.erase(corners_.begin() + 1, corners_.end() - 1);
        }
        drop_spikes(ids);
        out_.cycles.back().push_back(std::move(ids));
      }
    }
    out_.boundary_pieces = static_cast<int>(out_.pieces.size());
    for (const DegenerateContact& d : slice_.degenerate) add_degenerate(d);
    return std::move(out_);
  }

 private:
  const Slice& slice_;
  double theta_;
  const SamplingOptions& options_;
  VertexStore& store_;
  SampledSlice out_;
  std::vector<std::pair<Vec2, int>> corners_;

  // Piece b walks piece a back to where it started, and both are short enough to be round-off
  // (kMeshSpikePerGeometric).
  bool is_spike(int a, int b) const {
    const Piece &x = out_.pieces[a], &y = out_.pieces[b];
    const double limit = kMeshSpikePerGeometric * slice_.epsilon;
    return x.first() != x.last() && y.first() == x.last() && y.last() == x.first() &&
           x.length() <= limit && y.length() <= limit;
  }

  // Leaves round-off spikes out of a boundary cycle (see kMeshSpikePerGeometric), innermost
  // first; a cycle that is nothing but a spike stays as it is.
  void drop_spikes(std::vector<int>& cycle) const {
    for (size_t k = 0; cycle.size() > 2 && k < cycle.size();) {
      const size_t next = (k + 1) % cycle.size();
      if (!is_spike(cycle[k], cycle[next])) {
        ++k;
        continue;
      }
      cycle.erase(cycle.begin() + std::max(k, next));
      cycle.erase(cycle.begin() + std::min(k, next));
      k = k > 0 ? k - 1 : 0;  // the pieces now side by side may form an outer spike
    }
  }

  // The corner vertex at p: an existing one within the slice's epsilon, or a new one.
  int corner(Vec2 p, SegmentLabel label) {
    for (const auto& [q, v] : corners_)
      if (distance(p, q) <= slice_.epsilon) return v;
    const int v = store_.add(p, theta_, label);
    corners_.push_back({p, v});
    return v;
  }

  SegmentLabel label_of(int segment) const {
    const ContactSegment& s = slice_.contact_segments.at(segment);
    return {s.moving_feature, s.fixed_feature};
  }

  Piece sample(const Curve& curve, int segment) {
    Piece piece;
    piece.label = label_of(segment);
    piece.curve = curve;
    const int from = corner(curve.from, piece.label);
    piece.verts.push_back(from);
    piece.offset.push_back(0.0);
    set_frame(piece, slice_.contact_segments.at(segment));
    if (curve_length(curve) > slice_.epsilon) {
      if (curve.is_segment())
        sample_line(piece, slice_.contact_segments.at(segment));
      else
        sample_arc(piece);
    }
    const int to = corner(curve.to, piece.label);
    piece.verts.push_back(to);
    piece.offset.push_back(curve_length(curve));
    if (store_.end_label[to].moving_feature < 0) store_.end_label[to] = piece.label;
    return piece;
  }

  // The material coordinate of the piece's start: for a line, along its contact segment from
  // the segment's `from` end (a point of the feature), signed to grow along the piece; for an
  // arc, r times its world angle, in the direction of travel.
  static void set_frame(Piece& piece, const ContactSegment& seg) {
    const Curve& c = piece.curve;
    if (c.is_arc()) {
      const double sign = c.sweep > 0.0 ? 1.0 : -1.0;
      piece.start = sign * c.radius * c.start_angle;
      piece.period = kTwoPi * c.radius;
      return;
    }
    const Vec2 dir = normalized(c.to - c.from);
    const Vec2 axis =
        seg.curve.to == seg.curve.from ? dir : normalized(seg.curve.to - seg.curve.from);
    const double sign = dot(dir, axis) >= 0.0 ? 1.0 : -1.0;
    piece.start = sign * dot(c.from - seg.curve.from, axis);
  }

  // Inside a line that turns with theta: the multiples of the twist chord.
  void sample_line(Piece& piece, const ContactSegment& seg) {
    const Curve& c = piece.curve;
    const double len = curve_length(c);
    const double step = options_.twist_chord;
    if (!turns_with_theta(seg.kind) || !(step > 0.0) || len / step > kMaxSteps) return;
    const Vec2 dir = (1.0 / len) * (c.to - c.from);
    const double end = piece.start + len;
    for (double k = std::ceil((piece.start + kCornerGap * step) / step);
         k * step < end - kCornerGap * step; ++k) {
      const double t = k * step - piece.start;
      piece.verts.push_back(store_.add(c.from + t * dir, theta_, piece.label));
      piece.offset.push_back(t);
    }
  }

  // Inside an arc: the multiples of one angle, whose chords up to (1 + kCornerGap) steps long
  // keep their sagitta r (1 - cos(a / 2)) within the tolerance.
  void sample_arc(Piece& piece) {
    const Curve& c = piece.curve;
    const double sign = c.sweep > 0.0 ? 1.0 : -1.0;
    const double widest = 1.0 + kCornerGap;
    double turn = kMaxChordTurn;
    const double tol = options_.chord_tolerance / (widest * widest);
    if (tol < c.radius) turn = std::min(turn, 2.0 * std::acos(1.0 - tol / c.radius));
    turn /= widest;
    const double steps = std::min(std::ceil(kTwoPi / turn), kMaxSteps);
    const double grid = kTwoPi / steps;
    const double s0 = sign * c.start_angle, sweep = std::fabs(c.sweep);
    for (double k = std::ceil((s0 + kCornerGap * grid) / grid);
         k * grid - s0 < sweep - kCornerGap * grid; ++k) {
      const double t = k * grid - s0;
      const Vec2 p = c.center + c.radius * unit_vector(c.start_angle + sign * t);
      piece.verts.push_back(store_.add(p, theta_, piece.label));
      piece.offset.push_back(c.radius * t);
    }
    // A short arc with no grid point inside still bulges: its middle, so that an arc and the
    // chord that closes a lens are never one edge twice.
    if (piece.verts.size() == 1 && curve_length(c) > 2.0 * slice_.epsilon) {
      piece.verts.push_back(store_.add(point_at(c, 0.5), theta_, piece.label));
      piece.offset.push_back(0.5 * curve_length(c));
    }
  }

  // A sliding fit (a curve of contact with blocked space on both sides) is a boundary walked
  // both ways once free space opens along it: two darts, each labelled by a contact segment
  // running against it, as a boundary piece runs against its segment.
  void add_degenerate(const DegenerateContact& d) {
    if (d.segments.empty()) return;
    if (d.is_point || curve_length(d.curve) <= slice_.epsilon) {
      DegeneratePoint p;
      p.vertex = corner(d.curve.from, label_of(d.segments.front()));
      for (int s : d.segments) p.labels.push_back(label_of(s));
      out_.points.push_back(std::move(p));
      return;
    }
    // Sampled once, so both darts share their vertices; each in the frame of its own label.
    int labels[2] = {-1, -1};
    const Curve darts[2] = {d.curve, reversed(d.curve)};
    for (int k = 0; k < 2; ++k) {
      const Vec2 along = tangent_at(darts[k], 0.5);
      for (int s : d.segments) {
        const Curve& sc = slice_.contact_segments.at(s).curve;
        if (dot(tangent_at(sc, closest_parameter(sc, point_at(darts[k], 0.5))), along) < 0.0) {
          labels[k] = s;
          break;
        }
      }
      if (labels[k] < 0) labels[k] = d.segments.front();
    }
    const Piece forward = sample(darts[0], labels[0]);
    Piece backward;
    backward.label = label_of(labels[1]);
    backward.curve = darts[1];
    backward.verts.assign(forward.verts.rbegin(), forward.verts.rend());
    for (auto it = forward.offset.rbegin(); it != forward.offset.rend(); ++it)
      backward.offset.push_back(forward.length() - *it);
    set_frame(backward, slice_.contact_segments.at(labels[1]));
    out_.pieces.push_back(forward);
    out_.pieces.push_back(std::move(backward));
  }
};

}  // namespace

SampledSlice sample_slice(const Slice& slice, double theta, const SamplingOptions& options,
                          VertexStore& store) {
  return Sampler(slice, theta, options, store).run();
}

void find_coinciding_labels(SampledSlice& s) {
  s.coinciding.assign(s.pieces.size(), {});
  for (size_t k = 0; k < s.pieces.size(); ++k) {
    const Piece& piece = s.pieces[k];
    const Vec2 probes[] = {piece.curve.from, point_at(piece.curve, 0.5), piece.curve.to};
    for (const ContactSegment& seg : s.slice->contact_segments) {
      if (seg.is_point || SegmentLabel{seg.moving_feature, seg.fixed_feature} == piece.label)
        continue;
      if (std::all_of(std::begin(probes), std::end(probes),
                      [&](Vec2 p) { return distance_to_curve(seg.curve, p) <= s.slice->epsilon; }))
        s.coinciding[k].push_back({seg.moving_feature, seg.fixed_feature});
    }
  }
}

}  // namespace cslice::mesh_detail
