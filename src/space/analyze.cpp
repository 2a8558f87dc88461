// What a computed space says about its pair (docs/space-format.md, "Analysis"): coverage of
// the 3D components, transitions, per-slice free space and channel width, and the checks of
// the paper's applications (section 2) for the pairs that model them.
#include "cslice/analyze.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>

#include "cslice/classify.hpp"

namespace cslice {

namespace {

using json = nlohmann::ordered_json;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Smallest and largest of dot(p, u) over the curve's points.
std::pair<double, double> support(const Curve& c, Vec2 u) {
  double lo = std::min(dot(c.from, u), dot(c.to, u));
  double hi = std::max(dot(c.from, u), dot(c.to, u));
  if (c.is_arc()) {
    // The arc's extreme points along u lie in directions u and -u from its centre, when the
    // arc passes through them.
    for (const double sign : {1.0, -1.0}) {
      const Vec2 d = sign * u;
      const double t = arc_parameter_of_angle(c, std::atan2(d.y, d.x));
      if (c.is_full_circle() || (t >= 0.0 && t <= 1.0)) {
        const double v = dot(c.center + c.radius * d, u);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
  }
  return {lo, hi};
}

// Length of the projection of a set of curves on the unit direction u.
double extent(const std::vector<const Curve*>& curves, Vec2 u) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Curve* c : curves) {
    const auto [a, b] = support(*c, u);
    lo = std::min(lo, a);
    hi = std::max(hi, b);
  }
  return hi - lo;
}

// The least extent over directions: a grid of directions over a half turn, then a golden
// section search around the best one. The extent is continuous in the direction and, for the
// boundaries here (segments and arcs), has one minimum per grid cell at this resolution; an
// axis-aligned or polygonal minimum is hit exactly when it lies on the grid.
double min_extent(const std::vector<const Curve*>& curves) {
  if (curves.empty()) return 0.0;
  constexpr int kDirections = 360;
  const double step = kPi / kDirections;
  const auto width = [&](double a) { return extent(curves, unit_vector(a)); };
  int best = 0;
  double best_width = width(0.0);
  for (int i = 1; i < kDirections; ++i) {
    const double w = width(i * step);
    if (w < best_width) {
      best_width = w;
      best = i;
    }
  }
  const double phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = (best - 1) * step, b = (best + 1) * step;
  double x1 = b - phi * (b - a), x2 = a + phi * (b - a);
  double f1 = width(x1), f2 = width(x2);
  for (int k = 0; k < 80 && b - a > 1e-13; ++k) {
    if (f1 < f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - phi * (b - a);
      f1 = width(x1);
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + phi * (b - a);
      f2 = width(x2);
    }
  }
  return std::min({best_width, f1, f2});
}

std::vector<const Curve*> boundary_curves(const FreeComponent& c) {
  std::vector<const Curve*> out;
  for (const auto& cycle : c.boundary)
    for (const ContactPiece& piece : cycle) out.push_back(&piece.curve);
  return out;
}

Box boundary_box(const FreeComponent& c) {
  Box box;
  for (const Curve* curve : boundary_curves(c)) box.add(bounding_box(*curve));
  return box;
}

bool contains_angle(const std::pair<double, double>& range, double theta) {
  // Ranges may pass pi; theta is compared in every turn that can fall in them.
  for (const double t : {theta - kTwoPi, theta, theta + kTwoPi})
    if (t > range.first && t < range.second) return true;
  return false;
}

std::string ranges_text(const std::vector<std::pair<double, double>>& ranges) {
  std::string out;
  for (const auto& [a, b] : ranges) {
    // Appended piecewise: GCC 12 -Wrestrict false alarm on chained concatenation.
    if (!out.empty()) out += ", ";
    out += "(";
    out += num(a);
    out += ", ";
    out += num(b);
    out += ")";
  }
  return out.empty() ? "none" : out;
}

// Intervals as topology.cpp numbers them: interval i starts at critical orientation i (or at
// -pi when there is none) and ends at the next (the last wraps past pi).
struct Intervals {
  std::vector<double> starts, ends;
  explicit Intervals(const CriticalSet& criticals) {
    for (const CriticalOrientation& o : criticals.orientations) starts.push_back(o.theta);
    if (starts.empty()) starts.push_back(-kPi);
    const size_t n = starts.size();
    for (size_t i = 0; i < n; ++i) ends.push_back(i + 1 < n ? starts[i + 1] : starts[0] + kTwoPi);
  }
  int size() const { return static_cast<int>(starts.size()); }
  // The interval holding theta (theta itself not critical).
  int of(double theta) const {
    for (int i = 0; i < size(); ++i)
      if (contains_angle({starts[i], ends[i]}, theta)) return i;
    return 0;
  }
};

// The 3D component of the free component of `slice` (computed at any theta) holding p: the
// component's sample located in the stored slices of its interval, nearest first.
int component_3d(const SlicedSpace& space, const Slice& slice, Vec2 p) {
  const int c = slice.locate(p);
  if (c < 0) return -1;
  const Vec2 sample = slice.free_components[c].sample;
  const int interval = Intervals(space.criticals).of(slice.theta);
  std::vector<int> candidates;
  for (int s = 0; s < static_cast<int>(space.slices.size()); ++s)
    if (space.slices[s].kind != SliceKind::critical && space.slices[s].interval == interval)
      candidates.push_back(s);
  const auto gap = [&](int s) { return std::abs(wrap_angle(space.slices[s].theta - slice.theta)); };
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](int a, int b) { return gap(a) < gap(b); });
  for (int s : candidates) {
    for (const Vec2 q : {p, sample}) {
      const int d = space.slices[s].slice.locate(q);
      if (d >= 0) return space.topology.slice_components[s][d];
    }
  }
  return -1;
}

// ---- The applications -----------------------------------------------------------------

// The cam turns without interference: one component through every theta, and the channel's
// width (the backlash) is the follower clearance: for a convex part in a rectangular opening
// the slice's free space is a rectangle, the opening's width and height less the part's
// extent along x and y at that theta, so its smallest extent is the smaller of the two.
void cam_checks(const Pair& pair, const SpaceAnalysis& a, SpaceAnalysis& out) {
  const bool one = a.components.size() == 1 && a.components[0].spans_all_theta;
  out.checks.push_back({"one component spanning every theta", one,
                        std::to_string(a.components.size()) + " 3D component(s), covering " +
                            (a.components.empty() ? std::string("nothing")
                                                  : ranges_text(a.components[0].theta_ranges))});
  CamAnalysis cam;
  std::vector<const Curve*> moving;
  for (const Loop& loop : pair.moving.loops)
    for (const Curve& c : loop.edges) moving.push_back(&c);
  const Box opening = pair.fixed.box;
  cam.min_clearance = std::numeric_limits<double>::infinity();
  cam.max_clearance = -cam.min_clearance;
  bool all_widths = pair.fixed.enclosure;
  for (const SliceSummary& s : a.slices) {
    // The part turned by theta has extent along x that the unturned part has along R(-theta) x.
    const double cx = (opening.hi.x - opening.lo.x) - extent(moving, unit_vector(-s.theta));
    const double cy =
        (opening.hi.y - opening.lo.y) - extent(moving, unit_vector(kPi / 2 - s.theta));
    const double clearance = std::min(cx, cy);
    cam.min_clearance = std::min(cam.min_clearance, clearance);
    cam.max_clearance = std::max(cam.max_clearance, clearance);
    if (!s.channel_width) {
      all_widths = false;
      continue;
    }
    cam.max_width_error = std::max(cam.max_width_error, std::abs(*s.channel_width - clearance));
  }
  const bool width_ok =
      all_widths && a.channel.is_channel && cam.max_width_error <= pair.tol.contact;
  out.checks.push_back(
      {"channel width equals the follower clearance", width_ok,
       a.channel.is_channel
           ? "width (backlash) " + num(a.channel.min_width) + " to " + num(a.channel.max_width) +
                 ", clearance " + num(cam.min_clearance) + " to " + num(cam.max_clearance) +
                 ", largest difference " + num(cam.max_width_error) + " (tolerance " +
                 num(pair.tol.contact) + ")"
           : std::string("the free space is not a single bounded channel") +
                 (pair.fixed.enclosure ? "" : " (the fixed part is not an enclosure)")});
  out.cam = cam;
}

// The fastener: one free component with the pin near vertical (theta = +-pi/2), two
// otherwise, the two meeting at critical orientations.
void fastener_checks(const Pair& pair, const SlicedSpace& space, const SpaceAnalysis& a,
                     SpaceAnalysis& out) {
  FastenerAnalysis f;
  const double critical_angle = pair.tol.critical_angle;
  const Intervals iv(space.criticals);
  std::vector<int> cells(iv.size(), 0);
  for (const SpaceCell& c : space.topology.cells) cells[c.interval] += 1;
  bool one_or_two = true;
  for (const SliceSummary& s : a.slices)
    one_or_two = one_or_two && (s.free_components == 1 || s.free_components == 2);
  out.checks.push_back({"every slice has one or two free components", one_or_two, ""});
  // Runs of consecutive one-component intervals, cyclically.
  const int n = iv.size();
  const auto one = [&](int i) { return cells[(i + n) % n] == 1; };
  bool all_one = true;
  for (int i = 0; i < n; ++i) all_one = all_one && one(i);
  for (int i = 0; i < n && !all_one; ++i) {
    if (!one(i) || one(i - 1)) continue;
    int j = i;
    while (one(j + 1)) ++j;
    const double from = iv.starts[i];
    const double to = iv.ends[j % n] + (j >= n ? kTwoPi : 0.0);
    f.one_component_ranges.emplace_back(from, to);
  }
  for (const TransitionSummary& t : a.transitions)
    for (const TransitionEvent& e : t.events)
      if (e.kind == TransitionKind::merge || e.kind == TransitionKind::split ||
          e.kind == TransitionKind::merge_split) {
        f.meeting_thetas.push_back(t.theta);
        break;
      }
  const auto holds = [&](double theta) {
    return std::count_if(f.one_component_ranges.begin(), f.one_component_ranges.end(),
                         [&](const auto& r) { return contains_angle(r, theta); });
  };
  const bool vertical = f.one_component_ranges.size() == 2 && holds(kPi / 2) == 1 &&
                        holds(-kPi / 2) == 1 && holds(0.0) == 0 && holds(kPi) == 0;
  out.checks.push_back({"one free component near the vertical pin, two otherwise", vertical,
                        "one component for theta in " + ranges_text(f.one_component_ranges)});
  bool ends_meet = !f.one_component_ranges.empty();
  std::string ends;
  for (const auto& [from, to] : f.one_component_ranges)
    for (const double end : {from, wrap_angle(to)}) {
      const bool meets =
          std::any_of(f.meeting_thetas.begin(), f.meeting_thetas.end(),
                      [&](double t) { return std::abs(wrap_angle(t - end)) <= critical_angle; });
      ends_meet = ends_meet && meets;
      ends += (ends.empty() ? "" : ", ") + num(end);
    }
  out.checks.push_back(
      {"the components meet at the critical orientations ending those ranges", ends_meet,
       "range ends " + (ends.empty() ? std::string("none") : ends) + "; merges or splits at " +
           std::to_string(f.meeting_thetas.size()) + " critical orientation(s)"});
  out.fastener = f;
}

// The fixture's engaging configuration (2.1, -0.7, 0) is a local maximum of the theta = 0
// slice's contact space. The test, local to a disc of `radius` about it (100 contact
// tolerances, 0.1 mm for the example):
//   1. classify says contact;
//   2. the point radius/2 straight below it is free, in free component C;
//   3. no boundary point of C inside the disc is higher than it (up to the criticality
//      tolerance): boundary pieces sampled at 257 parameters each, plus each arc's top point;
//   4. no point of the disc's upper half circle (181 samples) is in C.
// Then no point of C in the disc is higher: moving straight up from such a point would leave C
// through its boundary inside the disc (3) or reach the upper half circle inside C (4).
// `drop`, how far C's boundary stays below the point between radius/2 and radius from it,
// tells a strict maximum (positive) from a plateau.
void fixture_checks(const Pair& pair, SpaceAnalysis& out) {
  FixtureAnalysis f;
  const Vec2 p{f.engaging.x, f.engaging.y};
  const Placement placement = classify(pair, f.engaging);
  f.placement = std::string(to_string(placement));
  out.checks.push_back({"the engaging configuration (2.1, -0.7, 0) is contact",
                        placement == Placement::contact, "classify: " + f.placement});
  const Slice slice = compute_slice(pair, f.engaging.theta);
  f.radius = 100.0 * pair.tol.contact;
  f.component = slice.locate(p - Vec2{0.0, f.radius / 2});
  f.highest_boundary_y = -std::numeric_limits<double>::infinity();
  double ring_high = -std::numeric_limits<double>::infinity();
  if (f.component >= 0) {
    const FreeComponent& c = slice.free_components[f.component];
    const auto visit = [&](Vec2 q) {
      const double d = distance(q, p);
      if (d > f.radius) return;
      f.highest_boundary_y = std::max(f.highest_boundary_y, q.y);
      if (d >= f.radius / 2) ring_high = std::max(ring_high, q.y);
    };
    for (const Curve* curve : boundary_curves(c)) {
      constexpr int kSamples = 256;
      for (int k = 0; k <= kSamples; ++k)
        visit(point_at(*curve, static_cast<double>(k) / kSamples));
      if (curve->is_arc()) {
        const double t = arc_parameter_of_angle(*curve, kPi / 2);
        if (curve->is_full_circle() || (t >= 0.0 && t <= 1.0))
          visit(curve->center + Vec2{0.0, curve->radius});
      }
    }
    constexpr int kCircle = 180;
    for (int k = 0; k <= kCircle; ++k) {
      const Vec2 q = p + f.radius * unit_vector(kPi * k / kCircle);
      if (slice.locate(q) == f.component) f.upper_circle_points_free += 1;
    }
  }
  f.drop = p.y - ring_high;
  const bool below_free = f.component >= 0;
  const bool highest = below_free && f.highest_boundary_y <= p.y + pair.tol.criticality;
  const bool local_max = highest && f.upper_circle_points_free == 0;
  out.checks.push_back(
      {"it is a local maximum of its theta = 0 slice", local_max,
       below_free ? "within " + num(f.radius) + " of it the free component below it reaches y = " +
                        num(f.highest_boundary_y) + " at most (it is at y = " + num(p.y) +
                        "), dropping by " + num(f.drop) + " from radius/2 on; " +
                        std::to_string(f.upper_circle_points_free) +
                        " point(s) of the upper half circle free in it"
                  : std::string("no free space just below it")});
  out.fixture = f;
}

// The knee's range of motion: the theta ranges of the 3D component holding the paper's
// Figure 1 configuration (5, -3, 0.5).
void knee_checks(const Pair& pair, const SlicedSpace& space, const SpaceAnalysis& a,
                 SpaceAnalysis& out) {
  KneeAnalysis k;
  const Placement placement = classify(pair, k.start);
  const Slice slice = compute_slice(pair, k.start.theta);
  k.component =
      placement == Placement::free ? component_3d(space, slice, {k.start.x, k.start.y}) : -1;
  out.checks.push_back(
      {"the configuration of Figure 1, (5, -3, 0.5), is free", k.component >= 0,
       "classify: " + std::string(to_string(placement)) +
           (k.component >= 0 ? ", 3D component " + std::to_string(k.component) : std::string())});
  if (k.component >= 0) {
    const ComponentCoverage& c = a.components.at(k.component);
    k.range_of_motion = c.theta_ranges;
    k.coverage = c.theta_coverage;
  }
  out.checks.push_back({"range of motion from it", k.component >= 0 && k.coverage > 0.0,
                        "theta in " + ranges_text(k.range_of_motion) + ", " + num(k.coverage) +
                            " rad" + (k.coverage >= kTwoPi - 1e-12 ? " (every orientation)" : "")});
  out.knee = k;
}

json ranges_json(const std::vector<std::pair<double, double>>& ranges) {
  json out = json::array();
  for (const auto& [a, b] : ranges) out.push_back(json::array({a, b}));
  return out;
}

json number_or_null(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

}  // namespace

double component_min_width(const FreeComponent& component) {
  return min_extent(boundary_curves(component));
}

bool SpaceAnalysis::all_checks_passed() const {
  return std::all_of(checks.begin(), checks.end(), [](const auto& c) { return c.passed; });
}

SpaceAnalysis analyze_space(const Pair& pair, const SlicedSpace& space) {
  SpaceAnalysis a;
  a.pair = pair.name;
  const SpaceTopology& topo = space.topology;
  for (const SpaceComponent& c : topo.components) {
    ComponentCoverage cov;
    cov.id = c.id;
    cov.cells = static_cast<int>(c.cells.size());
    cov.spans_all_theta = c.spans_all_theta;
    cov.theta_ranges = c.theta_ranges;
    for (const auto& [from, to] : c.theta_ranges) cov.theta_coverage += to - from;
    a.components.push_back(std::move(cov));
  }
  std::vector<int> cells_in(std::max<size_t>(1, space.criticals.orientations.size()), 0);
  for (const SpaceCell& c : topo.cells) cells_in.at(c.interval) += 1;
  for (const CriticalTransition& t : topo.transitions) {
    TransitionSummary s;
    s.critical = t.critical;
    s.theta = t.theta;
    for (const Criticality& k : space.criticals.orientations.at(t.critical).criticalities) {
      s.criticalities += 1;
      s.counts[static_cast<int>(k.condition)] += 1;
    }
    s.components_before = cells_in.at(t.interval_before);
    s.components_after = cells_in.at(t.interval_after);
    for (const SpaceSlice& slice : space.slices)
      if (slice.kind == SliceKind::critical && slice.interval == t.critical)
        s.critical_components = static_cast<int>(slice.slice.free_components.size());
    s.events = t.events;
    a.transitions.push_back(std::move(s));
  }
  bool channel = a.components.size() == 1 && a.components[0].spans_all_theta;
  a.channel.min_width = std::numeric_limits<double>::infinity();
  a.channel.max_width = -a.channel.min_width;
  for (const SpaceSlice& s : space.slices) {
    SliceSummary sum;
    sum.theta = s.theta;
    sum.kind = s.kind;
    sum.interval = s.interval;
    sum.free_components = static_cast<int>(s.slice.free_components.size());
    for (const FreeComponent& c : s.slice.free_components) {
      if (c.bounded && std::isfinite(c.area)) {
        sum.bounded_free_components += 1;
        sum.free_area += c.area;
      } else {
        sum.unbounded_free_space = true;
      }
    }
    if (sum.free_components == 1 && sum.bounded_free_components == 1) {
      const FreeComponent& c = s.slice.free_components[0];
      sum.channel_width = component_min_width(c);
      const Box box = boundary_box(c);
      sum.channel_box = Vec2{box.hi.x - box.lo.x, box.hi.y - box.lo.y};
      a.channel.min_width = std::min(a.channel.min_width, *sum.channel_width);
      a.channel.max_width = std::max(a.channel.max_width, *sum.channel_width);
    } else {
      channel = false;
    }
    a.slices.push_back(std::move(sum));
  }
  a.channel.is_channel = channel && !a.slices.empty();
  if (!a.channel.is_channel) a.channel.min_width = a.channel.max_width = 0.0;

  a.application =
      pair.name == "cam" || pair.name == "fastener" || pair.name == "fixture" || pair.name == "knee"
          ? pair.name
          : "";
  if (a.application == "cam") cam_checks(pair, a, a);
  if (a.application == "fastener") fastener_checks(pair, space, a, a);
  if (a.application == "fixture") fixture_checks(pair, a);
  if (a.application == "knee") knee_checks(pair, space, a, a);
  return a;
}

std::string analysis_to_json(const SpaceAnalysis& a) {
  json components = json::array();
  for (const ComponentCoverage& c : a.components)
    components.push_back({{"id", c.id},
                          {"cells", c.cells},
                          {"spans_all_theta", c.spans_all_theta},
                          {"theta_ranges", ranges_json(c.theta_ranges)},
                          {"theta_coverage", c.theta_coverage}});
  json transitions = json::array();
  for (const TransitionSummary& t : a.transitions) {
    json counts = json::object();
    for (int k = 0; k < kCriticalConditionCount; ++k)
      counts[std::string(to_string(static_cast<CriticalCondition>(k)))] = t.counts[k];
    json events = json::array();
    for (const TransitionEvent& e : t.events)
      events.push_back({{"kind", to_string(e.kind)},
                        {"before", e.before},
                        {"after", e.after},
                        {"critical_components", e.critical_components}});
    transitions.push_back({{"critical", t.critical},
                           {"theta", t.theta},
                           {"criticalities", t.criticalities},
                           {"conditions", std::move(counts)},
                           {"components_before", t.components_before},
                           {"critical_components", t.critical_components},
                           {"components_after", t.components_after},
                           {"events", std::move(events)}});
  }
  json slices = json::array();
  for (const SliceSummary& s : a.slices)
    slices.push_back(
        {{"theta", s.theta},
         {"kind", to_string(s.kind)},
         {"interval", s.interval},
         {"free_components", s.free_components},
         {"bounded_free_components", s.bounded_free_components},
         {"free_area", s.free_area},
         {"unbounded_free_space", s.unbounded_free_space},
         {"channel_width", s.channel_width ? json(*s.channel_width) : json(nullptr)},
         {"channel_box",
          s.channel_box ? json::array({s.channel_box->x, s.channel_box->y}) : json(nullptr)}});
  json checks = json::array();
  for (const ApplicationCheck& c : a.checks)
    checks.push_back({{"name", c.name}, {"passed", c.passed}, {"detail", c.detail}});
  json out = {{"format", "cslice-analysis"},
              {"version", 1},
              {"pair", a.pair},
              {"free_components_3d", a.components.size()},
              {"components", std::move(components)},
              {"transitions", std::move(transitions)},
              {"slices", std::move(slices)},
              {"channel",
               {{"is_channel", a.channel.is_channel},
                {"min_width", a.channel.is_channel ? json(a.channel.min_width) : json(nullptr)},
                {"max_width", a.channel.is_channel ? json(a.channel.max_width) : json(nullptr)}}},
              {"application", a.application.empty() ? json(nullptr) : json(a.application)},
              {"checks", std::move(checks)},
              {"all_checks_passed", a.all_checks_passed()}};
  json details = json::object();
  if (a.cam)
    details = {{"min_clearance", a.cam->min_clearance},
               {"max_clearance", a.cam->max_clearance},
               {"max_width_error", a.cam->max_width_error}};
  if (a.fastener)
    details = {{"one_component_ranges", ranges_json(a.fastener->one_component_ranges)},
               {"meeting_thetas", a.fastener->meeting_thetas}};
  if (a.fixture)
    details = {{"engaging", json::array({a.fixture->engaging.x, a.fixture->engaging.y,
                                         a.fixture->engaging.theta})},
               {"placement", a.fixture->placement},
               {"radius", a.fixture->radius},
               {"component", a.fixture->component},
               {"highest_boundary_y", number_or_null(a.fixture->highest_boundary_y)},
               {"drop", number_or_null(a.fixture->drop)},
               {"upper_circle_points_free", a.fixture->upper_circle_points_free}};
  if (a.knee)
    details = {{"start", json::array({a.knee->start.x, a.knee->start.y, a.knee->start.theta})},
               {"component", a.knee->component},
               {"range_of_motion", ranges_json(a.knee->range_of_motion)},
               {"coverage", a.knee->coverage}};
  out["application_details"] = details.empty() ? json(nullptr) : details;
  return out.dump(2) + "\n";
}

}  // namespace cslice
