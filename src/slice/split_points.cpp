// Split points of the arrangement's curves (see arrangement.cpp for the rules).
#include "slice/split_points.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace cslice {

void SplitsByCurve::build(const std::vector<SplitPoint>& splits, size_t first, size_t curves) {
  start.assign(curves + 1, 0);
  index.resize(splits.size() - first);
  for (size_t k = first; k < splits.size(); ++k) ++start[splits[k].curve + 1];
  for (size_t c = 0; c < curves; ++c) start[c + 1] += start[c];
  fill.assign(start.begin(), start.end() - 1);
  for (size_t k = first; k < splits.size(); ++k) index[fill[splits[k].curve]++] = int(k);
}

namespace {

// Every pair of curves whose boxes overlap, found by sweeping boxes sorted by their left x.
void candidate_pairs(SplitScratch& s) {
  const std::vector<Box>& boxes = s.boxes;
  s.order.resize(boxes.size());
  std::iota(s.order.begin(), s.order.end(), 0);
  std::sort(s.order.begin(), s.order.end(),
            [&](int a, int b) { return boxes[a].lo.x < boxes[b].lo.x; });
  s.sorted.resize(boxes.size());  // contiguous for the sweep
  for (size_t i = 0; i < s.order.size(); ++i) s.sorted[i] = boxes[s.order[i]];
  s.pairs.clear();
  for (size_t i = 0; i < s.sorted.size(); ++i) {
    const Box& a = s.sorted[i];
    for (size_t j = i + 1; j < s.sorted.size() && s.sorted[j].lo.x <= a.hi.x; ++j) {
      const Box& b = s.sorted[j];  // Box::overlaps, knowing b.lo.x <= a.hi.x
      if (!(b.hi.x < a.lo.x || b.lo.y > a.hi.y || b.hi.y < a.lo.y))
        s.pairs.emplace_back(s.order[i], s.order[j]);
    }
  }
}

// Curves within eps of each other along a stretch must be cut at the same vertices there, or
// their pieces would not coincide and a third curve would cross them in an order that
// round-off decides: two lines closer than eps crossed by a third at a shallow angle get
// their crossings at points farther apart than eps. The same holds for curves that only meet
// at points, next to those points: arcs the intersection step calls tangent (a lens thinner
// than eps) and curves crossing at a shallow angle stay within eps of each other for up to
// sqrt(eps / curvature) or eps / angle. So every split point of one curve inside a shared
// piece, or within eps of a curve it meets, is copied to the other, at the same point; the
// pieces between them then merge into one edge. Two passes carry points along chains.
void share_split_points(const std::vector<Curve>& curves, SplitScratch& s,
                        std::vector<SplitPoint>& splits, double eps) {
  if (s.shared.empty()) return;
  size_t first_new = 0;
  for (int pass = 0; pass < 2; ++pass) {
    SplitsByCurve& fresh = s.fresh;
    fresh.build(splits, first_new, curves.size());
    if (first_new != 0) s.all.build(splits, 0, curves.size());
    const SplitsByCurve& all = first_new == 0 ? fresh : s.all;
    s.grouped = first_new == 0 ? SplitScratch::Grouped::fresh : SplitScratch::Grouped::all;
    // The fresh points in curve order, compact, each with where it is on its own curve.
    std::vector<FreshSplit>& points = s.points;
    points.resize(fresh.index.size());
    for (size_t i = 0; i < points.size(); ++i) {
      const SplitPoint& sp = splits[fresh.index[i]];
      points[i] = {sp.t, sp.met, sp.curve, sp.p, {}, false};
    }
    // Where a point is on its own curve costs a sine and cosine on an arc: found when asked.
    auto on_curve = [&](FreshSplit& p) {
      if (!p.located) p.on_curve = point_at(curves[p.curve], p.t);
      p.located = true;
      return p.on_curve;
    };
    // A point within eps of one the curve already has would join that one's vertex anyway.
    auto has_point_near = [&](int c, Vec2 p) {
      for (int k : all.of(c))
        if (length_squared(splits[k].p - p) <= eps * eps) return true;
      return false;
    };
    std::vector<SplitPoint>& added = s.added;
    added.clear();
    for (const SharedPiece& sp : s.shared) {
      for (const auto& [from, to, lo, hi] :
           {std::tuple{sp.a, sp.b, sp.a_lo, sp.a_hi}, std::tuple{sp.b, sp.a, sp.b_lo, sp.b_hi}}) {
        for (int i = fresh.start[from]; i < fresh.start[from + 1]; ++i) {
          FreshSplit& p = points[i];
          if (p.t < lo || p.t > hi) continue;
          if (sp.near) {
            if (p.met == to) continue;  // where the two meet: already on both
            // Measured from the curve's own point, so that a vertex carried onto a curve
            // passes on to the curves that one runs beside. Outside the other's box grown by
            // eps is farther than eps from it.
            const Vec2 q = on_curve(p);
            const Box& box = s.boxes[to];
            if (q.x < box.lo.x || q.x > box.hi.x || q.y < box.lo.y || q.y > box.hi.y) continue;
            if (has_point_near(to, p.p) || distance_to_curve(curves[to], q) > eps) continue;
          }
          added.push_back({to, closest_parameter(curves[to], p.p), p.p});
        }
      }
    }
    if (added.empty()) return;
    first_new = splits.size();
    splits.insert(splits.end(), added.begin(), added.end());
    s.grouped = SplitScratch::Grouped::none;  // the points just added are in neither
  }
}

}  // namespace

void split_points(const std::vector<Curve>& curves, double eps, SplitScratch& s,
                  std::vector<SplitPoint>& splits) {
  splits.clear();
  s.shared.clear();
  s.boxes.clear();
  s.grouped = SplitScratch::Grouped::none;
  for (size_t i = 0; i < curves.size(); ++i) {
    splits.push_back({int(i), 0.0, curves[i].from});
    splits.push_back({int(i), 1.0, curves[i].to});
    s.boxes.push_back(bounding_box(curves[i]).inflated(eps));
  }
  candidate_pairs(s);
  for (auto [i, j] : s.pairs) {
    const Intersection x = intersect(curves[i], curves[j], eps);
    bool piece = false;
    for (int k = 0; k < x.count; ++k) {
      const IntersectionHit& h = x.hits[k];
      // A point hit inside both curves, not a tangency, is a crossing; at an end of either
      // curve it is a touch (that curve ends there).
      const Meeting how = h.is_piece     ? Meeting::other
                          : h.is_tangent ? Meeting::tangent
                          : (h.ta0 > 0.0 && h.ta0 < 1.0 && h.tb0 > 0.0 && h.tb0 < 1.0)
                              ? Meeting::crossing
                              : Meeting::other;
      splits.push_back({i, h.ta0, h.point, j, how});
      splits.push_back({j, h.tb0, h.point, i, how});
      if (h.is_piece) {
        piece = true;
        splits.push_back({i, h.ta1, h.point_end});
        splits.push_back({j, h.tb1, h.point_end});
        s.shared.push_back({i, j, std::min(h.ta0, h.ta1), std::max(h.ta0, h.ta1),
                            std::min(h.tb0, h.tb1), std::max(h.tb0, h.tb1)});
      }
    }
    if (x.count > 0 && !piece) s.shared.push_back({i, j, 0.0, 1.0, 0.0, 1.0, true});
  }
  share_split_points(curves, s, splits, eps);
}

}  // namespace cslice
