// Critical orientations (paper sections 5, 6.1, 6.2, 6.5 and 9): every orientation where
// the contact graph of the slice can change, solved in closed form for line segments and
// circular arcs. Between two consecutive critical orientations all slices are equivalent.
// The equations are derived in docs/criticals.md.
#pragma once

#include <array>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "cslice/slice.hpp"

namespace cslice {

enum class CriticalCondition {
  segment_end,  // condition 2: a contact segment appears, vanishes, or its end passes from
                // one feature's end to the other's
  endpoint,     // condition 3: an end of one contact segment lies on another
  tangent,      // condition 3: two contact segments touch tangentially
  triple,       // condition 3: three contact segments pass through one point
};
std::string_view to_string(CriticalCondition c);
inline constexpr int kCriticalConditionCount = 4;

// A feature pair, as it labels contact segments.
struct FeaturePairRef {
  int moving_feature = 0;
  int fixed_feature = 0;
  ContactKind kind = ContactKind::vertex_segment;
};

// The feature pairs of one criticality, at most three, kept in place: a set holds thousands
// of criticalities, copied and sorted as images are added and grouped, and a heap block each
// cost 3% of the fixture's instructions. Read like a vector.
class FeaturePairs {
 public:
  static constexpr size_t kCapacity = 3;

  FeaturePairs() = default;
  FeaturePairs(std::initializer_list<FeaturePairRef> pairs) {
    for (const FeaturePairRef& p : pairs) push_back(p);
  }

  // Past the capacity is a programming error: no condition involves more than three.
  void push_back(const FeaturePairRef& p) { items_.at(count_++) = p; }

  size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  const FeaturePairRef& operator[](size_t i) const { return items_[i]; }
  FeaturePairRef& operator[](size_t i) { return items_[i]; }
  const FeaturePairRef& front() const { return items_[0]; }
  const FeaturePairRef* begin() const { return items_.data(); }
  const FeaturePairRef* end() const { return items_.data() + count_; }
  FeaturePairRef* begin() { return items_.data(); }
  FeaturePairRef* end() { return items_.data() + count_; }

 private:
  std::array<FeaturePairRef, kCapacity> items_{};
  size_t count_ = 0;
};

// One solution of one criticality equation.
struct Criticality {
  double theta = 0.0;
  CriticalCondition condition = CriticalCondition::segment_end;
  FeaturePairs pairs;  // 1 (segment_end), 2 (endpoint, tangent) or 3 (triple)
  Vec2 at;             // a configuration (x, y) where it happens, at theta
};

// Criticalities closer together than the critical angle (Tolerances::critical_angle), taken
// as one orientation.
struct CriticalOrientation {
  double theta = 0.0;  // the group's median member's (docs/criticals.md, Grouping)
  std::vector<Criticality> criticalities;
};

struct CriticalOptions {
  // Drop criticalities that happen only in blocked space (the moving part overlapping the
  // fixed one deeper than the criticality tolerance), where a slice's realizable contact
  // cannot change. Off, every solution that survives local overlap filtering is kept.
  bool screen_blocked = true;
  // Threads at once (oneTBB); 0 lets oneTBB choose (every core), and more than the cores
  // are as many as the cores. The result is the same whatever the count.
  int threads = 0;
  // For a pair with symmetries (include/cslice/symmetry.hpp), search only a fundamental
  // domain of theta and add the images of what is found there (docs/symmetry.md); false
  // searches the whole turn (the tests compare the two).
  bool map_symmetric = true;
};

struct CriticalStats {
  int families = 0;             // feature pairs that touch at some orientation
  long long equations = 0;      // criticality equations solved
  long long roots = 0;          // their roots in range
  long long culled = 0;         // roots dropped unvalidated: outside every theta-bin where
                                // their families come close enough to meet
  long long off_segment = 0;    // roots rejected: a family not alive there, the point off
                                // its contact segments, or a triple at a segment's end
  long long blocked = 0;        // dropped by screening
  long long criticalities = 0;  // kept
  long long mapped = 0;         // of those, images of others under the pair's symmetries (the
                                // counts above but this one are of the searched domain)
};

struct CriticalSet {
  std::vector<CriticalOrientation> orientations;  // sorted by theta, in [-pi, pi)
  int counts[kCriticalConditionCount] = {};       // kept criticalities by condition
  CriticalStats stats;
};

CriticalSet critical_orientations(const Pair& pair, const CriticalOptions& options = {});

// The set as JSON text (format "cslice-critical", version 1; docs/criticals.md), ending in a
// newline.
std::string critical_set_to_json(const Pair& pair, const CriticalSet& set);

}  // namespace cslice
