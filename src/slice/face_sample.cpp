#include "slice/face_sample.hpp"

#include <algorithm>

#include "parts/loop_queries.hpp"

namespace cslice {
namespace {

// x of every crossing of the line y = const with the curve, half-open at segment ends so a
// line through a shared vertex counts it once.
void scan_crossings(const Curve& c, double y, std::vector<double>& xs) {
  if (c.is_segment()) {
    if ((c.from.y > y) == (c.to.y > y)) return;
    xs.push_back(c.from.x + (y - c.from.y) * (c.to.x - c.from.x) / (c.to.y - c.from.y));
    return;
  }
  const double dy = y - c.center.y;
  if (std::fabs(dy) >= c.radius) return;
  const double dx = std::sqrt(c.radius * c.radius - dy * dy);
  for (double x : {c.center.x - dx, c.center.x + dx}) {
    const double t = arc_parameter_of_angle(c, std::atan2(dy, x - c.center.x));
    if (t >= 0.0 && t < 1.0) xs.push_back(x);
  }
}

}  // namespace

Vec2 sample_beyond(const Box& box, const Tolerances& tol) {
  if (box.empty()) return {0.0, 0.0};
  const double reach = std::max(box.diagonal(), tol.size);
  return {box.hi.x + reach, 0.5 * (box.lo.y + box.hi.y)};
}

Vec2 sample_inside(std::span<const Curve> curves, const Box& box, std::vector<double>& xs) {
  // Scan lines at irrational fractions of the height, so they avoid vertices of designed
  // (round-numbered) input.
  constexpr int kLines = 7;
  constexpr double kGolden = 0.6180339887498949;
  Vec2 best = 0.5 * (box.lo + box.hi);
  double best_clearance = -1.0;
  for (int k = 0; k < kLines; ++k) {
    const double frac = std::fmod(0.5 + k * kGolden, 1.0);
    const double y = box.lo.y + frac * (box.hi.y - box.lo.y);
    xs.clear();
    for (const Curve& c : curves) scan_crossings(c, y, xs);
    std::sort(xs.begin(), xs.end());
    for (size_t i = 0; i + 1 < xs.size(); i += 2) {
      const Vec2 p{0.5 * (xs[i] + xs[i + 1]), y};
      const double clearance = std::min(0.5 * (xs[i + 1] - xs[i]), distance_to_curves(curves, p));
      if (clearance > best_clearance) {
        best_clearance = clearance;
        best = p;
      }
    }
  }
  return best;
}

Vec2 face_sample(const Arrangement& arr, int face, const Box& box, const Tolerances& tol,
                 FaceSampleScratch& scratch) {
  if (!arr.faces[face].bounded) return sample_beyond(box, tol);
  std::vector<Curve>& curves = scratch.curves;
  curves.clear();
  for (int c : arr.face_cycles(face))
    for (int h : arr.half_edges(c)) curves.push_back(arr.half_curve(h));
  return sample_inside(curves, box, scratch.xs);
}

}  // namespace cslice
