#include "criticals/candidates.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <tuple>

#include "geometry/box_pairs.hpp"
#include "slice/small_sort.hpp"

namespace cslice {

Binning::Binning(int bins) : count(std::max(bins, 1)), width(kTwoPi / std::max(bins, 1)) {}

Binning::Binning(int bins, double from_angle, double span)
    : count(std::max(bins, 1)),
      from(from_angle),
      width(span / std::max(bins, 1)),
      whole_turn(false) {}

int Binning::bin_of(double theta) const {
  if (whole_turn) {
    const int b = int(std::floor((wrap_angle(theta) + kPi) / width));
    return std::clamp(b, 0, count - 1);
  }
  const double d = ccw_turn(from, theta), span = count * width;
  if (d > span) return d - span < kTwoPi - d ? count - 1 : 0;
  return std::clamp(int(std::floor(d / width)), 0, count - 1);
}

namespace {

// Calls visit(bin) for every bin that the family's alive interval can reach (possibly more,
// some twice): those from its start to its end, one more on each side (a closed bin touching
// it at its border counts too), and those it reaches after passing the turn's end back to the
// binning's start. Over the whole turn, the bin before the first is the last.
template <class Visit>
void for_bins_near(const Binning& binning, const ContactFamily& f, Visit&& visit) {
  const auto visit_range = [&](double first, double last) {
    const int lo = std::max(0, int(std::floor(first / binning.width)) - 1);
    const int hi = std::min(binning.count - 1, int(std::floor(last / binning.width)) + 1);
    for (int bin = lo; bin <= hi; ++bin) visit(bin);
  };
  if (f.always_alive()) return visit_range(0.0, binning.count * binning.width);
  const double start = ccw_turn(binning.from, f.alive.lo), end = start + f.alive.span;
  visit_range(start, end);
  if (end + binning.width >= kTwoPi) visit_range(0.0, end - kTwoPi);
  if (binning.whole_turn && start < binning.width) visit(binning.count - 1);
}

}  // namespace

std::vector<std::vector<int>> alive_families_by_bin(const std::vector<ContactFamily>& families,
                                                    const Binning& binning) {
  std::vector<std::vector<int>> alive(binning.count);
  for (size_t i = 0; i < families.size(); ++i) {
    const ContactFamily& f = families[i];
    // Over the whole turn, a family alive nearly all of it is listed in every bin, unasked.
    if (binning.whole_turn && (f.always_alive() || f.alive.span + 2.0 * binning.width >= kTwoPi)) {
      for (int bin = 0; bin < binning.count; ++bin) alive[size_t(bin)].push_back(int(i));
      continue;
    }
    for_bins_near(binning, f, [&](int bin) {
      if (alive_within(f, binning.lower(bin), binning.lower(bin) + binning.width))
        alive[size_t(bin)].push_back(int(i));
    });
  }
  for (auto& bin : alive) {
    std::sort(bin.begin(), bin.end());
    bin.erase(std::unique(bin.begin(), bin.end()), bin.end());
  }
  return alive;
}

namespace {

// A family's cover at the orientation `rotation` turns by, with the margin for orientations
// within half_width of it.
BinEntry entry_at(const ContactFamily& family, int index, const Transform& rotation,
                  double half_width, double tolerance) {
  BinEntry e;
  e.family = index;
  const FamilyCover cover = family_cover_within(family, rotation, half_width);
  e.cover = cover.curve;
  e.margin = cover.drift * half_width + tolerance;
  e.box = bounding_box(e.cover).inflated(e.margin);
  return e;
}

}  // namespace

std::vector<BinEntry> bin_entries(const std::vector<ContactFamily>& families,
                                  const std::vector<int>& alive, const Binning& binning, int bin,
                                  double tolerance) {
  const Transform middle(Pose{0.0, 0.0, binning.lower(bin) + 0.5 * binning.width});
  std::vector<BinEntry> entries;
  entries.reserve(alive.size());
  for (int i : alive)
    entries.push_back(entry_at(families[i], i, middle, 0.5 * binning.width, tolerance));
  std::sort(entries.begin(), entries.end(), [](const BinEntry& x, const BinEntry& y) {
    return x.box.lo.x < y.box.lo.x || (x.box.lo.x == y.box.lo.x && x.family < y.family);
  });
  return entries;
}

namespace {

// A lower bound on the distance between two curves, cheap where the exact one is not (arcs):
// that between their whole circles, or between a segment and the other's circle.
double circle_distance_bound(const Curve& a, const Curve& b) {
  if (a.is_segment() && b.is_segment()) return 0.0;
  if (a.is_arc() && b.is_arc()) {
    const double d = distance(a.center, b.center);
    return std::max({0.0, d - a.radius - b.radius, std::fabs(a.radius - b.radius) - d});
  }
  const Curve& s = a.is_segment() ? a : b;
  const Curve& c = a.is_segment() ? b : a;
  const double nearest = distance_to_curve(s, c.center);
  const double farthest = std::max(distance(s.from, c.center), distance(s.to, c.center));
  return std::max({0.0, nearest - c.radius, c.radius - farthest});
}

// Two families can meet within the bin only if their covers come within their margins. Ends
// that close settle it at once (neighbours along the contact boundary share theirs). Where an
// arc is involved, bounds from the chords settle most pairs before the exact distance: on a
// gear in a ring gear that distance, an atan2 per arc point tried, took 40% of the time of
// the critical orientations.
bool may_meet(const BinEntry& x, const BinEntry& y, double geometric) {
  if (!x.box.overlaps(y.box)) return false;
  const double reach = x.margin + y.margin;
  for (Vec2 p : {x.cover.from, x.cover.to})
    for (Vec2 q : {y.cover.from, y.cover.to})
      if (distance(p, q) <= reach) return true;
  if (x.cover.is_segment() && y.cover.is_segment())
    return distance_segment_segment(x.cover, y.cover) <= reach;
  if (circle_distance_bound(x.cover, y.cover) > reach) return false;
  // Decided by the bounds only with the geometric epsilon to spare, far beyond the round-off
  // of either distance, so that the exact distance would decide alike.
  const DistanceBounds bounds = chord_distance_bounds(x.cover, y.cover);
  if (bounds.hi <= reach - geometric) return true;
  if (bounds.lo > reach + geometric) return false;
  return distance_between(x.cover, y.cover) <= reach;
}

// Along the line of segment c, how far (in units of its length) the whole curve reaches.
double line_reach(const Curve& c, double size) {
  return 4.0 * size / distance(c.from, c.to);
}

bool lines_cross(const Curve& x, const Curve& y, double size, double eps, CurveCrossings& out) {
  const Vec2 d = x.to - x.from, e = y.to - y.from, w = y.from - x.from;
  const double den = cross(d, e), sine = std::fabs(den) / (length(d) * length(e));
  if (!(sine * size > eps)) return false;  // parallel to within eps over the pair
  const double t = cross(w, e) / den, s = cross(w, d) / den;
  const double rx = line_reach(x, size), ry = line_reach(y, size);
  if (t < -rx || t > 1.0 + rx || s < -ry || s > 1.0 + ry) return false;
  out.point[0] = x.from + t * d;
  out.sine[0] = sine;
  out.count = 1;
  return true;
}

// Line x, circle of y: the chord's half-length h off the foot of the centre; the line meets
// the circle's radius at angle acos(h / r), so the curves cross at sine h / r.
bool line_crosses_circle(const Curve& x, const Curve& y, double size, double eps,
                         CurveCrossings& out) {
  const double len = distance(x.from, x.to);
  const Vec2 u = (1.0 / len) * (x.to - x.from), w = y.center - x.from;
  const double along = dot(w, u), off = cross(u, w);
  const double h = std::sqrt(std::max(y.radius * y.radius - off * off, 0.0));
  if (!(h > eps) || !(y.radius > eps)) return false;  // apart, tangent, or a point
  const double reach = line_reach(x, size) * len;
  for (double t : {along - h, along + h}) {
    if (t < -reach || t > len + reach) continue;
    out.point[size_t(out.count)] = x.from + t * u;
    out.sine[size_t(out.count++)] = h / y.radius;
  }
  return out.count > 0;
}

bool circles_cross(const Curve& x, const Curve& y, double eps, CurveCrossings& out) {
  const Vec2 between = y.center - x.center;
  const double d = length(between), r1 = x.radius, r2 = y.radius;
  if (!(r1 > eps) || !(r2 > eps) || !(d > eps)) return false;  // a point, or concentric
  const double a = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
  const double h = std::sqrt(std::max(r1 * r1 - a * a, 0.0));
  if (!(h > eps)) return false;  // apart, or touching
  const Vec2 base = x.center + (a / d) * between, across = (h / d) * perp_left(between);
  for (Vec2 p : {base - across, base + across}) {
    out.point[size_t(out.count)] = p;
    out.sine[size_t(out.count++)] = std::fabs(cross(p - x.center, p - y.center)) / (r1 * r2);
  }
  return true;
}

}  // namespace

bool whole_curves_cross(const Curve& x, const Curve& y, double size, double eps,
                        CurveCrossings& out) {
  const bool x_line = x.is_segment(), y_line = y.is_segment();
  if ((x_line && x.from == x.to) || (y_line && y.from == y.to)) return false;
  if (x_line && y_line) return lines_cross(x, y, size, eps, out);
  if (x_line) return line_crosses_circle(x, y, size, eps, out);
  if (y_line) return line_crosses_circle(y, x, size, eps, out);
  return circles_cross(x, y, eps, out);
}

namespace {

// Where two covers' whole curves cross at an angle phi, a meeting of their contact segments
// within the bin stays within the meeting of two bands as wide as their margins:
// (margin_x + margin_y) / sin(phi) from the crossing (doubled for the curvature of arcs), its
// `reach`. Whole curves that do not cross, or cross nearly tangentially, give no bound. A
// crossing farther than its reach plus a margin from either cover holds no meeting: such
// crossings (the far side of a circle, a line's extension) are dropped.
struct WholeCrossing {
  bool unbounded = false;
  int count = 0;
  std::array<Vec2, 2> point{};
  std::array<double, 2> reach{};
};

bool within(const BinEntry& e, Vec2 p, double reach) {
  const Box& b = e.box;  // already widened by the margin
  if (p.x < b.lo.x - reach || p.x > b.hi.x + reach || p.y < b.lo.y - reach || p.y > b.hi.y + reach)
    return false;
  const double limit = e.margin + reach;
  if (e.cover.is_arc() && std::fabs(distance(p, e.cover.center) - e.cover.radius) > limit)
    return false;
  return distance_to_curve(e.cover, p) <= limit;
}

WholeCrossing whole_crossing(const BinEntry& x, const BinEntry& y, double geometric, double size) {
  CurveCrossings meet;
  WholeCrossing w;
  if (!whole_curves_cross(x.cover, y.cover, size, geometric, meet)) {
    w.unbounded = true;
    return w;
  }
  const double drift = 2.0 * (x.margin + y.margin);
  for (int h = 0; h < meet.count; ++h) {
    const double sine = meet.sine[size_t(h)];
    if (drift >= sine * size) {  // could drift across the whole pair
      w.unbounded = true;
      return w;
    }
    const double reach = drift / sine;
    const Vec2 point = meet.point[size_t(h)];
    if (!within(x, point, reach) || !within(y, point, reach)) continue;
    w.point[w.count] = point;
    w.reach[w.count++] = reach;
  }
  return w;
}

MeetingCandidate ordered(int a, int b, int c, int bin) {
  if (c < 0) return {std::min(a, b), std::max(a, b), -1, bin};
  int f[3] = {a, b, c};
  std::sort(f, f + 3);
  return {f[0], f[1], f[2], bin};
}

// Two families that always share a defining end E (neighbours along the contact boundary: a
// vertex contact and the contact of an adjacent edge, say) cross at E, which a triple point
// may not be (three curves through an end is an endpoint event, and validation rejects it).
// Their curves cross at most once more: never for two lines, at a chord of length 2 r sin(phi)
// from E for a line and a circle of radius r crossing at angle phi, and at least
// 2 r1 r2 sin(phi) / (r1 + r2) for two circles. Bounding phi from below over the bin bounds
// that chord, and so the disc around E where no triple point of the two can lie.
struct Exclusion {
  Vec2 center;
  double radius = 0.0;  // 0: none
};

// How fast (radians per radian of theta) the family's curve turns at its end e: a fixed line
// not at all, a turning line with theta, a circle as the radius to e turns.
double turn_rate(const ContactFamily& f, const MovingPoint& e) {
  if (f.shape == FamilyShape::fixed_line) return 0.0;
  if (f.shape == FamilyShape::turning_line) return 1.0;
  return length(e.q - f.center.q) / f.radius;
}

// rotation = Transform(Pose{0, 0, theta}).
Vec2 direction_at(const ContactFamily& f, const MovingPoint& e, const Transform& rotation) {
  if (f.shape != FamilyShape::circle)
    return normalized(f.ends[1].at(rotation) - f.ends[0].at(rotation));
  return perp_left(normalized(e.at(rotation) - f.center.at(rotation)));
}

const MovingPoint* shared_end(const ContactFamily& x, const ContactFamily& y, double eps,
                              const MovingPoint*& other) {
  for (const MovingPoint& ex : x.ends)
    for (const MovingPoint& ey : y.ends)
      if (distance(ex.p, ey.p) <= eps && distance(ex.q, ey.q) <= eps) {
        other = &ey;
        return &ex;
      }
  return nullptr;
}

// rotation = the rotation to the bin's middle orientation (one per bin).
Exclusion shared_end_exclusion(const ContactFamily& x, const ContactFamily& y,
                               const BinScope& scope, const Transform& rotation) {
  const MovingPoint* ey = nullptr;
  const MovingPoint* ex = shared_end(x, y, scope.geometric, ey);
  if (!ex || x.is_point() || y.is_point()) return {};
  const double half = 0.5 * scope.binning.width;
  const double sine =
      std::fabs(cross(direction_at(x, *ex, rotation), direction_at(y, *ey, rotation)));
  const double phi =
      std::asin(std::min(sine, 1.0)) - (turn_rate(x, *ex) + turn_rate(y, *ey)) * half;
  if (phi <= 0.0) return {};
  // The ends agree to the geometric epsilon only, so the curves cross near E, off it by that
  // over sin(phi): it must stay well inside the tolerance that makes the crossing an end.
  const double s = std::sin(phi);
  if (s * scope.tolerance < 8.0 * scope.geometric) return {};
  double chord = 4.0 * scope.size;  // two lines: no second crossing within the pair's reach
  if (x.shape == FamilyShape::circle && y.shape == FamilyShape::circle)
    chord = 2.0 * x.radius * y.radius * s / (x.radius + y.radius);
  else if (x.shape == FamilyShape::circle || y.shape == FamilyShape::circle)
    chord = 2.0 * (x.shape == FamilyShape::circle ? x.radius : y.radius) * s;
  // E itself moves within the bin.
  const double radius = chord - length(ex->q) * half - scope.tolerance;
  return radius > 0.0 ? Exclusion{ex->at(rotation), radius} : Exclusion{};
}

// Whether the third family can pass through a point where the first two meet within the bin,
// away from the disc `ex` where they cannot make a triple point.
bool may_meet_at(const WholeCrossing& w, const BinEntry& z, const Exclusion& ex) {
  if (w.unbounded) return true;
  for (int h = 0; h < w.count; ++h) {
    if (distance(w.point[h], ex.center) + w.reach[h] < ex.radius) continue;
    if (within(z, w.point[h], w.reach[h])) return true;
  }
  return false;
}

// A neighbour, and the shared end the two have (an index into the shared ends; -1 when none,
// -2 when not looked up yet).
struct Neighbour {
  int index = 0;
  int shared = -2;
};
struct Shared {
  Exclusion exclusion;
  std::optional<WholeCrossing> crossing;  // computed when first needed
};

// Bins with fewer entries are swept. On the paper's examples (about 40 entries a bin) the grid
// took 30% more instructions to meet; on an 8-tooth gear in a ring gear (640 a bin) as many
// as the sweep; on the 16-tooth one (2,270 a bin, 17 times as many box pairs swept as overlap)
// 6% less time for all the critical orientations.
constexpr size_t kMeetOnGridFrom = 1024;

// The lists of one bin, kept per thread from bin to bin with their capacity: a bin's
// neighbour lists were most of the allocations of the meeting pass.
struct MeetingScratch {
  std::vector<std::vector<Neighbour>> near;
  std::vector<Shared> shared;
  BoxGridScratch grid;
  void reset(size_t entries) {
    if (near.size() < entries) near.resize(entries);
    for (size_t i = 0; i < entries; ++i) near[i].clear();
    shared.clear();
  }
};

class BinMeeting {
 public:
  BinMeeting(const std::vector<BinEntry>& entries, const BinScope& scope, MeetingScratch& scratch)
      : entries_(entries),
        scope_(scope),
        middle_(Pose{0.0, 0.0, scope.binning.lower(scope.bin) + 0.5 * scope.binning.width}),
        near_(scratch.near),
        shared_(scratch.shared),
        grid_(scratch.grid) {
    scratch.reset(entries.size());
  }

  void run(std::vector<MeetingCandidate>& pairs, std::vector<MeetingCandidate>& triples) {
    find_pairs(pairs);
    for (size_t i = 0; i < entries_.size(); ++i)
      for (size_t n = 0; n < near_[i].size(); ++n)
        if (near_[i][n].index > int(i)) add_triples(int(i), int(n), triples);
  }

 private:
  // The entries are sorted by the left of their boxes, so a sweep along x finds the boxes
  // that overlap; many of them are better found on a grid (geometry/box_pairs.hpp). Either
  // way the same pairs, and the lists are sorted after.
  void find_pairs(std::vector<MeetingCandidate>& pairs) {
    const auto& e = entries_;
    const auto meet = [&](size_t i, size_t j) {
      if (!may_meet(e[i], e[j], scope_.geometric)) return;
      near_[i].push_back({int(j)});
      near_[j].push_back({int(i)});
      pairs.push_back(ordered(e[i].family, e[j].family, -1, scope_.bin));
    };
    const auto box_of = [&](size_t i) -> const Box& { return e[i].box; };
    if (e.size() < kMeetOnGridFrom ||
        !for_each_overlapping_pair_on_grid(e.size(), box_of, grid_, meet))
      for (size_t i = 0; i < e.size(); ++i)
        for (size_t j = i + 1; j < e.size() && e[j].box.lo.x <= e[i].box.hi.x; ++j) meet(i, j);
    for (size_t i = 0; i < e.size(); ++i)
      std::sort(near_[i].begin(), near_[i].end(),
                [](Neighbour x, Neighbour y) { return x.index < y.index; });
  }

  // The position of k among i's neighbours, or -1.
  int find(int i, int k) const {
    const auto& n = near_[i];
    auto it =
        std::lower_bound(n.begin(), n.end(), k, [](Neighbour x, int v) { return x.index < v; });
    return it != n.end() && it->index == k ? int(it - n.begin()) : -1;
  }

  // The shared end of i and its n-th neighbour with its exclusion, or null; looked up once.
  Shared* shared(int i, int n) {
    Neighbour& x = near_[i][n];
    if (x.shared == -2) {
      const auto& fam = *scope_.families;
      const Exclusion ex = shared_end_exclusion(fam[entries_[i].family],
                                                fam[entries_[x.index].family], scope_, middle_);
      x.shared = -1;
      if (ex.radius > 0.0) {
        x.shared = int(shared_.size());
        shared_.push_back({ex, std::nullopt});
      }
      near_[x.index][find(x.index, i)].shared = x.shared;
    }
    return x.shared >= 0 ? &shared_[x.shared] : nullptr;
  }

  // Every k after j that meets both i and j (i < j, j the n-th neighbour of i).
  void add_triples(int i, int n, std::vector<MeetingCandidate>& triples) {
    const int j = near_[i][n].index;
    std::optional<WholeCrossing> crossing;
    for (size_t m = 0; m < near_[j].size(); ++m) {
      const int k = near_[j][m].index;
      const int ik = k > j ? find(i, k) : -1;
      if (ik < 0) continue;
      const BinEntry &x = entries_[i], &y = entries_[j], &z = entries_[k];
      if (!crossing) crossing = whole_crossing(x, y, scope_.geometric, scope_.size);
      const Shared* xy = shared(i, n);
      if (!may_meet_at(*crossing, z, xy ? xy->exclusion : Exclusion{})) continue;
      // Each pair that shares an end narrows where the triple point can be.
      if (!passes_shared(i, ik, j) || !passes_shared(j, int(m), i)) continue;
      triples.push_back(ordered(x.family, y.family, z.family, scope_.bin));
    }
  }

  // The triple test with x, y = entry a and its n-th neighbour, z = entry c.
  bool passes_shared(int a, int n, int c) {
    Shared* s = shared(a, n);
    if (!s) return true;
    if (!s->crossing)
      s->crossing =
          whole_crossing(entries_[a], entries_[near_[a][n].index], scope_.geometric, scope_.size);
    return may_meet_at(*s->crossing, entries_[c], s->exclusion);
  }

  const std::vector<BinEntry>& entries_;
  const BinScope& scope_;
  const Transform middle_;  // the rotation to the bin's middle, for every shared end there
  std::vector<std::vector<Neighbour>>& near_;  // the first entries_.size() lists
  std::vector<Shared>& shared_;
  BoxGridScratch& grid_;
};

}  // namespace

void meeting_candidates(const std::vector<BinEntry>& entries, const BinScope& scope,
                        std::vector<MeetingCandidate>& pairs,
                        std::vector<MeetingCandidate>& triples) {
  thread_local MeetingScratch scratch;
  BinMeeting(entries, scope, scratch).run(pairs, triples);
}

void MeetingTask::add_run(int first, int last) {
  if (run_count > 0 && runs[run_count - 1][1] + 1 >= first) {
    runs[run_count - 1][1] = std::max(runs[run_count - 1][1], last);
  } else if (run_count < 2) {
    runs[run_count++] = {first, last};
  } else {
    runs[1][1] = last;
  }
}

int MeetingTask::windows(const Binning& binning, double slack,
                         std::array<AngleWindow, 2>& out) const {
  for (int r = 0; r < run_count; ++r) {
    const double span = (runs[r][1] - runs[r][0] + 1) * binning.width;
    out[size_t(r)] = {binning.lower(runs[r][0]) + 0.5 * span, 0.5 * span + 2.0 * slack};
  }
  return run_count;
}

namespace {
bool same_family_set(const MeetingTask& t, const MeetingCandidate& m) {
  return t.a == m.a && t.b == m.b && t.c == m.c;
}
bool task_before(const MeetingTask& x, const MeetingTask& y) {
  return std::tie(x.a, x.b, x.c) < std::tie(y.a, y.b, y.c);
}
}  // namespace

std::vector<MeetingTask> group_candidates(std::vector<MeetingCandidate>& candidates) {
  // Sorted by the first family, then within each: half the comparisons of one sort over all
  // (the order is total, so the same sequence).
  int families = 0;
  for (const MeetingCandidate& m : candidates) families = std::max(families, m.a + 1);
  bucket_sort(
      candidates, size_t(families), [](const MeetingCandidate& m) { return size_t(m.a); },
      std::less<MeetingCandidate>());
  std::vector<MeetingTask> tasks;
  for (const MeetingCandidate& m : candidates) {
    if (tasks.empty() || !same_family_set(tasks.back(), m)) tasks.push_back({m.a, m.b, m.c});
    tasks.back().add_bin(m.bin);
  }
  return tasks;
}

void merge_tasks(std::vector<MeetingTask>& tasks, const std::vector<MeetingTask>& later) {
  std::vector<MeetingTask> out;
  out.reserve(tasks.size() + later.size());
  size_t i = 0, j = 0;
  while (i < tasks.size() || j < later.size()) {
    if (j == later.size() || (i < tasks.size() && task_before(tasks[i], later[j]))) {
      out.push_back(tasks[i++]);
    } else if (i == tasks.size() || task_before(later[j], tasks[i])) {
      out.push_back(later[j++]);
    } else {
      MeetingTask t = tasks[i++];
      for (int r = 0; r < later[j].run_count; ++r)
        t.add_run(later[j].runs[r][0], later[j].runs[r][1]);
      ++j;
      out.push_back(t);
    }
  }
  tasks = std::move(out);
}

}  // namespace cslice
