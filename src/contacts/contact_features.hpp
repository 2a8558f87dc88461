// Features as contact makers: each arc or vertex is a disc boundary with a signed radius,
// each segment a straight edge, and each carries the interval of outward normals along
// which it can touch another part.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "cslice/slice.hpp"

namespace cslice {

// Counterclockwise angle interval [lo, lo + span], span in [0, 2pi] (a segment: span 0).
struct AngleInterval {
  double lo = 0.0;
  double span = 0.0;
};

// Whether the interval grown by angular_eps at both ends holds angle.
inline bool interval_contains(const AngleInterval& a, double angle, double angular_eps) {
  if (a.span >= kTwoPi) return true;
  const double d = ccw_turn(a.lo, angle);
  return d <= a.span + angular_eps || d >= kTwoPi - angular_eps;
}

struct ContactFeature {
  int feature = 0;  // index into Part::features
  FeatureKind kind = FeatureKind::segment;
  bool can_touch = true;  // false for reflex and smooth vertices
  Vec2 center;            // arcs: circle centre; vertices: the vertex
  double rho = 0.0;       // +r convex arc, -r concave arc, 0 vertex
  Vec2 from, to;          // segments and arcs: the edge's ends (all the contacts read of it)
  AngleInterval normals;  // outward normals the feature can touch along
};

// One per feature of the part, in feature order (element i describes feature i). Without
// all_normals, a vertex that cannot touch (reflex or smooth) is left without its normals
// (two angles each, and such a vertex touches nothing): for callers that never read them.
std::vector<ContactFeature> contact_features(const Part& part, bool all_normals = true);
// The same into `out`, whose storage is reused.
void contact_features(const Part& part, bool all_normals, std::vector<ContactFeature>& out);

// Whether a feature pair can touch at some orientation (local overlap filtering by
// convexity; the normal sets decide at which orientations): reflex vertices, segment pairs,
// concave pairs, vertex pairs and convex features too big for a concave one never touch.
bool pair_can_touch(const ContactFeature& m, const ContactFeature& f, double eps);
ContactKind contact_kind(const ContactFeature& m, const ContactFeature& f);

class NormalIndex;  // contacts.cpp
class TrigMemo;     // slice/trig_memo.hpp

// The contact segments of one pair at many orientations: the features as contact makers
// and the index of fixed normals are built once. Not thread-safe (it keeps scratch state):
// one per thread.
class ContactMaker {
 public:
  explicit ContactMaker(const Pair& pair);
  ~ContactMaker();
  // Makes this the maker of `pair`, as if newly constructed, reusing the storage (the
  // trigonometry memo is kept: it only repeats what the functions give).
  void reset(const Pair& pair);
  ContactMaker(const ContactMaker&) = delete;
  ContactMaker& operator=(const ContactMaker&) = delete;
  // Replaces out with the contact segments at theta, as contact_segments(pair, theta).
  void segments(double theta, std::vector<ContactSegment>& out);
  // The sines, cosines and tangents of the contact arcs' end angles made so far: the
  // arrangement evaluates the arcs there again.
  TrigMemo& trig() { return *trig_; }

 private:
  const Pair* pair_ = nullptr;
  std::vector<ContactFeature> moving_, fixed_;
  std::unique_ptr<NormalIndex> index_;
  std::unique_ptr<TrigMemo> trig_;
  std::vector<int> candidates_;  // reused scratch
  // Per moving feature, the fixed ones it can touch (pair_can_touch) as bits, when there are
  // few enough fixed features for NormalIndex to list candidates from bits; else empty.
  std::vector<uint64_t> touching_;
};

// Appends the contact segments of one feature pair at theta (none when the pair cannot
// touch there), by the rules contact_segments applies to every pair; ids continue from
// out.size().
void add_pair_contacts(const Pair& pair, const ContactFeature& m, const ContactFeature& f,
                       double theta, std::vector<ContactSegment>& out);
// The same with the rotation given: turn = Transform(Pose{0, 0, theta}), for callers that
// rebuild several pairs at one orientation (a query) and so turn once.
void add_pair_contacts(const Pair& pair, const ContactFeature& m, const ContactFeature& f,
                       const Transform& turn, std::vector<ContactSegment>& out);

}  // namespace cslice
