#include "criticals/candidates.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

namespace cslice {

Binning::Binning(int bins) : count(std::max(bins, 1)), width(kTwoPi / std::max(bins, 1)) {}

int Binning::bin_of(double theta) const {
  const int b = int(std::floor((wrap_angle(theta) + kPi) / width));
  return std::clamp(b, 0, count - 1);
}

std::vector<std::vector<int>> alive_families_by_bin(const std::vector<ContactFamily>& families,
                                                    const Binning& binning) {
  std::vector<std::vector<int>> alive(binning.count);
  for (size_t i = 0; i < families.size(); ++i) {
    const ContactFamily& f = families[i];
    if (f.always_alive() || f.alive.span + 2.0 * binning.width >= kTwoPi) {
      for (auto& bin : alive) bin.push_back(int(i));
      continue;
    }
    // The bins from the one holding the interval's start to the one holding its end, and
    // one more on each side: a closed bin touching the interval at its border counts too.
    const int first = binning.bin_of(f.alive.lo) - 1;
    const int last = binning.bin_of(f.alive.lo) + int(f.alive.span / binning.width) + 2;
    for (int b = first; b <= last; ++b) {
      const int bin = (b % binning.count + binning.count) % binning.count;
      if (alive_within(f, binning.lower(bin), binning.lower(bin) + binning.width))
        alive[bin].push_back(int(i));
    }
  }
  for (auto& bin : alive) {
    std::sort(bin.begin(), bin.end());
    bin.erase(std::unique(bin.begin(), bin.end()), bin.end());
  }
  return alive;
}

std::vector<BinEntry> bin_entries(const std::vector<ContactFamily>& families,
                                  const std::vector<int>& alive, const Binning& binning, int bin,
                                  double tolerance) {
  const double mid = binning.lower(bin) + 0.5 * binning.width;
  std::vector<BinEntry> entries;
  entries.reserve(alive.size());
  for (int i : alive) {
    BinEntry e;
    e.family = i;
    e.cover = family_cover(families[i], mid);
    e.margin = family_drift(families[i]) * 0.5 * binning.width + tolerance;
    e.box = bounding_box(e.cover).inflated(e.margin);
    entries.push_back(e);
  }
  std::sort(entries.begin(), entries.end(), [](const BinEntry& x, const BinEntry& y) {
    return x.box.lo.x < y.box.lo.x || (x.box.lo.x == y.box.lo.x && x.family < y.family);
  });
  return entries;
}

namespace {

// Two families can meet within the bin only if their covers come within their margins.
bool may_meet(const BinEntry& x, const BinEntry& y) {
  return x.box.overlaps(y.box) && distance_between(x.cover, y.cover) <= x.margin + y.margin;
}

// The whole curve a cover lies on, as far as the pair reaches: the full circle of an arc,
// the line of a segment extended well past the pair's size each way. Covers drift within the
// bin, so two of them can come to cross anywhere their whole curves cross, not only where the
// covers themselves cross at the bin's middle.
Curve whole_curve(const Curve& c, double size) {
  if (c.is_arc()) return make_circle(c.center, c.radius);
  const double length = distance(c.from, c.to);
  if (length == 0.0) return c;
  const Vec2 reach = (4.0 * size / length) * (c.to - c.from);
  return make_segment(c.from - reach, c.to + reach);
}

// Whether the third family can pass through a point where the first two meet within the
// bin. Where the whole curves of covers x and y cross at an angle phi, a meeting of their
// contact segments stays within the meeting of two bands as wide as their margins:
// (margin_x + margin_y) / sin(phi) from the crossing (doubled for the curvature of arcs).
// Whole curves that do not cross, or cross nearly tangentially, give no bound.
struct WholeCrossing {
  Curve wx, wy;
  Intersection meet;
};

WholeCrossing whole_crossing(const BinEntry& x, const BinEntry& y, double geometric, double size) {
  WholeCrossing w{whole_curve(x.cover, size), whole_curve(y.cover, size), {}};
  w.meet = intersect(w.wx, w.wy, geometric);
  return w;
}

bool may_meet_at(const BinEntry& x, const BinEntry& y, const WholeCrossing& w, const BinEntry& z,
                 double size) {
  const Intersection& meet = w.meet;
  if (meet.kind == IntersectionKind::none || meet.kind == IntersectionKind::overlapping)
    return true;
  for (int h = 0; h < meet.count; ++h) {
    const IntersectionHit& hit = meet.hits[h];
    const double sine = std::fabs(cross(tangent_at(w.wx, hit.ta0), tangent_at(w.wy, hit.tb0)));
    const double drift = 2.0 * (x.margin + y.margin);
    if (drift >= sine * size) return true;  // could drift across the whole pair
    if (distance_to_curve(z.cover, hit.point) <= z.margin + drift / sine) return true;
  }
  return false;
}

MeetingCandidate ordered(int a, int b, int c, int bin) {
  if (c < 0) return {std::min(a, b), std::max(a, b), -1, bin};
  int f[3] = {a, b, c};
  std::sort(f, f + 3);
  return {f[0], f[1], f[2], bin};
}

}  // namespace

void meeting_candidates(const std::vector<BinEntry>& entries, int bin, double geometric,
                        double size, std::vector<MeetingCandidate>& pairs,
                        std::vector<MeetingCandidate>& triples) {
  std::vector<std::vector<int>> neighbours(entries.size());
  for (size_t i = 0; i < entries.size(); ++i)
    for (size_t j = i + 1; j < entries.size() && entries[j].box.lo.x <= entries[i].box.hi.x; ++j)
      if (may_meet(entries[i], entries[j])) {
        neighbours[i].push_back(int(j));
        neighbours[j].push_back(int(i));
        pairs.push_back(ordered(entries[i].family, entries[j].family, -1, bin));
      }
  for (auto& n : neighbours) std::sort(n.begin(), n.end());
  for (size_t i = 0; i < entries.size(); ++i)
    for (int j : neighbours[i]) {
      if (j <= int(i)) continue;
      std::optional<WholeCrossing> crossing;  // computed when a third family needs it
      for (int k : neighbours[j]) {
        if (k <= j || !std::binary_search(neighbours[i].begin(), neighbours[i].end(), k)) continue;
        if (!crossing) crossing = whole_crossing(entries[i], entries[j], geometric, size);
        if (may_meet_at(entries[i], entries[j], *crossing, entries[k], size))
          triples.push_back(ordered(entries[i].family, entries[j].family, entries[k].family, bin));
      }
    }
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

bool MeetingTask::near(const Binning& binning, double theta, double slack) const {
  for (int r = 0; r < run_count; ++r) {
    double d = std::fmod(theta - binning.lower(runs[r][0]), kTwoPi);
    if (d < 0.0) d += kTwoPi;
    const double span = (runs[r][1] - runs[r][0] + 1) * binning.width;
    if (d <= span + slack || d >= kTwoPi - slack) return true;
  }
  return false;
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
  std::sort(candidates.begin(), candidates.end());
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
