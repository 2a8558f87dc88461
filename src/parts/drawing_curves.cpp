// Curves of a DXF drawing that are not lines or circular arcs (SPLINE, ELLIPSE), as circular
// arcs within a tolerance: the parts cslice works with are bounded by segments and arcs.
#include <algorithm>
#include <array>
#include <cmath>

#include "cslice/tolerance.hpp"
#include "parts/drawing_internal.hpp"
#include "parts/validate.hpp"

namespace cslice::drawing {

namespace {

// The signed bulge of the arc from a through m to b, or 0 when the three are collinear (the
// arc is then the segment). The arc's sweep is twice the supplement of the angle at m.
double bulge_through(Vec2 a, Vec2 m, Vec2 b) {
  const Vec2 u = a - m, v = b - m;
  const double c = cross(u, v), d = dot(u, v);
  if (std::fabs(c) <= 1e-14 * (length_squared(u) + length_squared(v))) return 0.0;
  const double angle = std::atan2(std::fabs(c), d);  // at m, in (0, pi)
  const double magnitude = std::tan((kPi - angle) / 2.0);
  // m right of the travel from a to b: the arc turns counterclockwise (positive bulge).
  return cross(b - a, m - a) < 0.0 ? magnitude : -magnitude;
}

// How far p lies from the arc (or segment) from a to b of the given bulge.
double distance_to_piece(Vec2 p, Vec2 a, Vec2 b, double bulge) {
  if (bulge == 0.0) return distance_to_curve(make_segment(a, b), p);
  return distance_to_curve(make_bulge_arc(a, b, bulge), p);
}

struct Fitter {
  const std::function<Vec2(double)>& curve;
  double tolerance;
  size_t max_pieces;
  std::vector<ArcVertex>& out;

  // Appends pieces for [u0, u1] (its ends' points given); false when they would be too many.
  bool fit(double u0, double u1, Vec2 p0, Vec2 p1, int depth) {
    const double um = 0.5 * (u0 + u1);
    const Vec2 pm = curve(um);
    const double bulge = bulge_through(p0, pm, p1);
    bool close = depth >= 2 && distance(p0, p1) > 0.0;  // at least four pieces per span
    for (int k = 1; close && k < 8; ++k) {
      if (k == 4) continue;
      close = distance_to_piece(curve(u0 + (u1 - u0) * k / 8.0), p0, p1, bulge) <= tolerance;
    }
    if (close || depth >= 40) {
      if (out.size() >= max_pieces) return false;
      out.push_back({p0, bulge});
      return true;
    }
    return fit(u0, um, p0, pm, depth + 1) && fit(um, u1, pm, p1, depth + 1);
  }
};

}  // namespace

bool arcs_along(const std::function<Vec2(double)>& curve, const std::vector<double>& breaks,
                double tolerance, size_t max_pieces, std::vector<ArcVertex>& out, Vec2& end) {
  Fitter fitter{curve, tolerance, max_pieces, out};
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    if (!(breaks[k + 1] > breaks[k])) continue;
    if (!fitter.fit(breaks[k], breaks[k + 1], curve(breaks[k]), curve(breaks[k + 1]), 0))
      return false;
  }
  end = curve(breaks.back());
  return true;
}

std::string follow_curve(const std::function<Vec2(double)>& curve,
                         const std::vector<double>& breaks, const Box& box,
                         std::optional<double> tolerance, const Origin& origin,
                         std::vector<Piece>& out) {
  const double within =
      kDxfCurveFitPerTolerance * tolerance.value_or(kDefaultRelativeTolerance * box.diagonal());
  std::vector<ArcVertex> chain;
  Vec2 end;
  if (!(within > 0.0 && std::isfinite(within)) ||
      !arcs_along(curve, breaks, within, kMaxCurvePieces, chain, end))
    return "more than " + std::to_string(kMaxCurvePieces) +
           " arcs would be needed to follow it within " + detail::format_number(within);
  for (size_t i = 0; i < chain.size(); ++i) {
    const Vec2 to = i + 1 < chain.size() ? chain[i + 1].p : end;
    if (chain[i].p == to) continue;  // a cusp's repeated point: nothing to draw
    if (!(is_finite(chain[i].p) && is_finite(to) && std::isfinite(chain[i].bulge)))
      return "its points are beyond the range of numbers";
    out.push_back({chain[i].p, to, chain[i].bulge, origin});
  }
  return "";
}

std::string check_nurbs(const Nurbs& n) {
  const size_t count = n.points.size();
  if (n.degree < 1 || n.degree > 10)
    return "degree " + std::to_string(n.degree) + " is not 1 to 10";
  if (count < static_cast<size_t>(n.degree) + 1)
    return std::to_string(count) + " control points are too few for degree " +
           std::to_string(n.degree);
  if (n.knots.size() != count + n.degree + 1)
    return std::to_string(n.knots.size()) + " knots, where " + std::to_string(count) +
           " control points of degree " + std::to_string(n.degree) + " need " +
           std::to_string(count + n.degree + 1);
  for (size_t k = 1; k < n.knots.size(); ++k)
    if (!(n.knots[k] >= n.knots[k - 1])) return "its knots decrease";
  if (!(n.knots[count] > n.knots[n.degree])) return "its knots span nothing";
  if (!n.weights.empty() && n.weights.size() != count)
    return std::to_string(n.weights.size()) + " weights for " + std::to_string(count) +
           " control points";
  for (double w : n.weights)
    if (!(w > 0.0)) return "a weight is not positive";
  return "";
}

// de Boor's algorithm in homogeneous coordinates (x w, y w, w).
Vec2 nurbs_point(const Nurbs& n, double u) {
  const int p = n.degree;
  const size_t count = n.points.size();
  u = std::clamp(u, n.knots[p], n.knots[count]);
  // The span k with knots[k] <= u < knots[k + 1], the last one at the domain's end.
  size_t k = static_cast<size_t>(p);
  while (k + 1 < count && n.knots[k + 1] <= u) ++k;
  struct H {
    double x, y, w;
  };
  std::array<H, 11> d;  // degree <= 10 (check_nurbs): no allocation per point
  for (int j = 0; j <= p; ++j) {
    const size_t i = k - p + j;
    const double w = n.weights.empty() ? 1.0 : n.weights[i];
    d[j] = {n.points[i].x * w, n.points[i].y * w, w};
  }
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const size_t i = k - p + j;
      const double span = n.knots[i + p - r + 1] - n.knots[i];
      const double a = span > 0.0 ? (u - n.knots[i]) / span : 0.0;
      d[j] = {(1 - a) * d[j - 1].x + a * d[j].x, (1 - a) * d[j - 1].y + a * d[j].y,
              (1 - a) * d[j - 1].w + a * d[j].w};
    }
  return {d[p].x / d[p].w, d[p].y / d[p].w};
}

}  // namespace cslice::drawing
