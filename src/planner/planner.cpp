// Lookahead planner and closed-form segment evaluation (see planner.hpp).
//
// Design notes
// - Geometry is built once, at push time, in machine coordinates (mm).
// - Every segment has one path acceleration `accel` used for both its
//   acceleration and its deceleration phase, and a trapezoid (or triangle)
//   from v_entry to v_exit with a cruise speed of at most v_max.
// - Arcs: the plane axes' acceleration A_p = min(A_a0, A_a1) is shared
//   between the centripetal acceleration at the arc's top speed (at most
//   kCentripetalShare * A_p) and the tangential acceleration, so that the
//   vector sum stays within A_p on each plane axis.
// - Arcs whose end radius differs from the start radius (within the
//   interpreter's tolerance) are spirals: the radius changes linearly with
//   the swept angle, so the arc ends exactly on its end point.
// - Junctions: the spec rule |v * (u_out_i - u_in_i)| <= A_i * T, tightened
//   by the tangential acceleration the two neighbours may have on that axis
//   at the junction (see kJunctionAccelShare and junction_speed()).
// - A feed move with a non-positive feed (the interpreter alarms on F0, so
//   this is only a guard) runs at limits.max_feed_mm_s.
#include "planner/planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace skipnc::planner {
namespace {

using Kind = Move::Kind;

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Share of the plane acceleration an arc may use as centripetal acceleration
// at its top speed; the rest (at least sqrt(1 - 0.8^2) = 0.6) is left for the
// tangential acceleration.
constexpr double kCentripetalShare = 0.8;
// At a junction the velocity step of axis i is limited to
// (A_i - share * max(p_i, q_i)) * T, where p_i and q_i bound the tangential
// acceleration of axis i at the end of the incoming and the start of the
// outgoing segment (the spec rule is share = 0). The sampled second
// difference around a junction is a weighted mix of the step and of p_i and
// q_i:
// - an axis that reverses can have all three pointing the same way; it gets
//   share = 1, which keeps the sample within A_i;
// - otherwise (share = kJunctionAccelShare = 0.5) the sample stays within
//   1.125 * A_i when the step and one neighbour act the same way (the usual
//   case: decelerate in, accelerate out; the random programs of the property
//   test never exceed it), and within 1.5 * A_i in any case (both neighbours
//   accelerating, or both decelerating, the same way as the step).
// share = 1 everywhere would make the bound exact, but then a polyline whose
// segments use their full acceleration would stop at every vertex.
constexpr double kJunctionAccelShare = 0.5;
// Direction changes per axis below this are rounding, not corners.
constexpr double kDirEpsilon = 1e-9;
// Radii and limits below this are treated as degenerate.
constexpr double kTiny = 1e-12;
// An arc whose end is this close to its start (mm, in the plane) is a full turn.
constexpr double kFullTurnChord = 1e-9;

bool valid_axis(int i) noexcept {
  return i >= 0 && i < kMaxAxes;
}
double positive(double x) noexcept {
  return x > kTiny ? x : kTiny;
}
double sq(double x) noexcept {
  return x * x;
}

// Closed-form trapezoid from v0 to v1 over `length` with cruise <= v_max.
// Rounding-level infeasibility (|v1^2 - v0^2| slightly above 2 a L) is
// absorbed by raising the acceleration to exactly what the change needs.
void make_profile(Segment& s, double v0, double v1) noexcept {
  const double len = s.length;
  double a = s.accel;
  s.v_entry = v0;
  s.v_exit = v1;
  const double need = std::abs(sq(v1) - sq(v0)) / (2.0 * len);
  if (need > a) a = need;
  s.accel = a;
  double vc = std::sqrt((2.0 * a * len + sq(v0) + sq(v1)) * 0.5);
  vc = std::min(vc, s.v_max);
  vc = std::max({vc, v0, v1});
  s.v_cruise = vc;
  s.t_acc = (vc - v0) / a;
  s.d_acc = (sq(vc) - sq(v0)) / (2.0 * a);
  s.t_dec = (vc - v1) / a;
  const double d_dec = (sq(vc) - sq(v1)) / (2.0 * a);
  const double d_cruise = std::max(0.0, len - s.d_acc - d_dec);
  s.t_cruise = vc > 0.0 ? d_cruise / vc : 0.0;
  s.duration = s.t_acc + s.t_cruise + s.t_dec;
}

// Per-axis trapezoid of a non-linear rapid: travel d (>= 0) at time t.
double axis_travel(double d, double v, double a, double t_acc, double t_total, double t) noexcept {
  if (t <= 0.0) return 0.0;
  if (t >= t_total) return d;
  if (t < t_acc) return 0.5 * a * t * t;
  if (t <= t_total - t_acc) return 0.5 * a * t_acc * t_acc + v * (t - t_acc);
  const double tau = t_total - t;
  return std::clamp(d - 0.5 * a * tau * tau, 0.0, d);
}

double axis_speed(double v, double a, double t_acc, double t_total, double t) noexcept {
  if (t <= 0.0 || t >= t_total) return 0.0;
  if (t < t_acc) return a * t;
  if (t <= t_total - t_acc) return v;
  return a * (t_total - t);
}

// Arc: the position at `dist` mm along the path.
AxisVec arc_point(const Segment& s, double dist) noexcept {
  const double f = dist / s.length;
  const double th = s.start_angle + s.sweep * f;
  const double r = s.radius + (s.radius_end - s.radius) * f;
  AxisVec p = s.start;
  for (int j = 0; j < kMaxAxes; ++j) p[j] += s.linear_per_mm[j] * dist;
  p[s.plane.a0] = s.center0 + r * std::cos(th);
  p[s.plane.a1] = s.center1 + r * std::sin(th);
  if (valid_axis(s.plane.normal)) {
    p[s.plane.normal] = s.start[s.plane.normal] + s.helix_per_rad * s.sweep * f;
  }
  return p;
}

// Arc: d(position)/d(path length) at fraction f.
AxisVec arc_direction(const Segment& s, double f) noexcept {
  const double th = s.start_angle + s.sweep * f;
  const double r = s.radius + (s.radius_end - s.radius) * f;
  const double dth = s.sweep / s.length;
  const double dr = (s.radius_end - s.radius) / s.length;
  const double c = std::cos(th);
  const double sn = std::sin(th);
  AxisVec d = s.linear_per_mm;
  d[s.plane.a0] = dr * c - r * sn * dth;
  d[s.plane.a1] = dr * sn + r * c * dth;
  if (valid_axis(s.plane.normal)) d[s.plane.normal] = s.helix_per_rad * dth;
  return d;
}

// Direction of motion per mm at the start (f = 0) or end (f = 1).
AxisVec direction_at_fraction(const Segment& s, double f) noexcept {
  if (s.kind == Kind::kArc) return arc_direction(s, f);
  return s.unit;
}

// Arcs whose radius changes along the sweep (a spiral r = r0 + rho * angle)
// have two extra acceleration terms in the plane, 2 rho angle'^2 and
// rho angle''; both stay within 2 * rho / r_min of the circle's acceleration.
double spiral_factor(double r0, double r1, double sweep) noexcept {
  const double rho = std::abs(r1 - r0) / std::abs(sweep);
  return 1.0 + 2.0 * rho / std::min(r0, r1);
}

// Upper bound of |acceleration| per axis at the start (f = 0) or end (f = 1).
AxisVec accel_bound(const Segment& s, double f) noexcept {
  AxisVec b;
  const AxisVec d = direction_at_fraction(s, f);
  for (int i = 0; i < kMaxAxes; ++i) b[i] = s.accel * std::abs(d[i]);
  if (s.kind == Kind::kArc) {
    const double th = s.start_angle + s.sweep * f;
    const double k = spiral_factor(s.radius, s.radius_end, s.sweep);
    b[s.plane.a0] = k * (b[s.plane.a0] + s.centripetal * std::abs(std::cos(th)));
    b[s.plane.a1] = k * (b[s.plane.a1] + s.centripetal * std::abs(std::sin(th)));
  }
  return b;
}

// Straight segments: line (feed) and linear rapid.
void build_linear(Segment& s, const Move& m, const Limits& lim) noexcept {
  const AxisVec delta = s.end - s.start;
  s.length = norm(delta, kMaxAxes);
  s.unit = delta * (1.0 / s.length);
  const bool rapid = s.kind == Kind::kRapid;
  double v = kInf;
  if (!rapid) {
    const double feed = m.feed_mm_s > 0.0 ? m.feed_mm_s : lim.max_feed_mm_s;
    v = std::min(feed, lim.max_feed_mm_s);
  }
  double a = kInf;
  for (int i = 0; i < kMaxAxes; ++i) {
    const double u = std::abs(s.unit[i]);
    if (u == 0.0) continue;
    const AxisLimits& al = lim.axes[static_cast<std::size_t>(i)];
    v = std::min(v, positive(rapid ? al.rapid_mm_s : al.max_velocity_mm_s) / u);
    a = std::min(a, positive(al.max_accel_mm_s2) / u);
  }
  s.v_max = v;
  s.accel = a;
}

void build_rapid_nonlinear(Segment& s, const Limits& lim) noexcept {
  double longest = 0.0;
  double vsq = 0.0;
  for (int i = 0; i < kMaxAxes; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double delta = s.end[i] - s.start[i];
    const double d = std::abs(delta);
    s.unit[i] = delta > 0.0 ? 1.0 : (delta < 0.0 ? -1.0 : 0.0);
    if (d == 0.0) continue;
    const AxisLimits& al = lim.axes[k];
    const double v = positive(al.rapid_mm_s);
    const double a = positive(al.max_accel_mm_s2);
    if (d * a >= v * v) {
      s.axis_t_acc[k] = v / a;
      s.axis_t_total[k] = d / v + v / a;
      s.axis_v[k] = v;
    } else {
      s.axis_t_acc[k] = std::sqrt(d / a);
      s.axis_t_total[k] = 2.0 * s.axis_t_acc[k];
      s.axis_v[k] = a * s.axis_t_acc[k];
    }
    s.axis_a[k] = a;
    vsq += sq(s.axis_v[k]);
    if (s.axis_t_total[k] > longest) {
      longest = s.axis_t_total[k];
      s.basis_axis = i;
    }
  }
  s.duration = longest;
  s.length = std::abs(s.end[s.basis_axis] - s.start[s.basis_axis]);
  s.v_max = std::sqrt(vsq);
  s.v_cruise = s.axis_v[static_cast<std::size_t>(s.basis_axis)];
}

// Arcs; returns false when the geometry is degenerate (then it is a line).
bool build_arc(Segment& s, const Move& m, const Limits& lim) noexcept {
  const canon::Plane pl = m.plane;
  if (!valid_axis(pl.a0) || !valid_axis(pl.a1) || pl.a0 == pl.a1) return false;
  if (pl.normal == pl.a0 || pl.normal == pl.a1) return false;
  const double x0 = s.start[pl.a0] - m.center0;
  const double y0 = s.start[pl.a1] - m.center1;
  const double x1 = s.end[pl.a0] - m.center0;
  const double y1 = s.end[pl.a1] - m.center1;
  const double r0 = std::hypot(x0, y0);
  const double r1 = std::hypot(x1, y1);
  if (!(r0 > 1e-9) || !(r1 > 1e-9)) return false;
  const double th0 = std::atan2(y0, x0);
  const double th1 = std::atan2(y1, x1);
  double d = std::fmod(m.ccw ? th1 - th0 : th0 - th1, kTwoPi);
  if (d < 0.0) d += kTwoPi;
  const double chord = std::hypot(x1 - x0, y1 - y0);
  // Sweep in (0, 2 pi]: coincident start and end make a full turn.
  if (d <= 0.0 || (chord <= kFullTurnChord && d < std::numbers::pi)) d += kTwoPi;
  d += kTwoPi * static_cast<double>(std::max(0, m.extra_turns));

  s.plane = pl;
  s.center0 = m.center0;
  s.center1 = m.center1;
  s.radius = r0;
  s.radius_end = r1;
  s.start_angle = th0;
  s.sweep = m.ccw ? d : -d;
  const bool has_normal = valid_axis(pl.normal);
  const double dn = has_normal ? s.end[pl.normal] - s.start[pl.normal] : 0.0;
  s.helix_per_rad = dn / s.sweep;
  double others_sq = 0.0;
  for (int j = 0; j < kMaxAxes; ++j) {
    if (j == pl.a0 || j == pl.a1 || j == pl.normal) continue;
    others_sq += sq(s.end[j] - s.start[j]);
  }
  const double dr = r1 - r0;
  s.length = std::sqrt(sq(0.5 * (r0 + r1) * d) + sq(dr) + sq(dn) + others_sq);
  for (int j = 0; j < kMaxAxes; ++j) {
    if (j == pl.a0 || j == pl.a1 || j == pl.normal) continue;
    s.linear_per_mm[j] = (s.end[j] - s.start[j]) / s.length;
  }

  // Speed and acceleration limits. kp bounds the plane speed per unit of
  // path speed; the other axes move in fixed proportion to the path.
  const auto ax = [&](int i) -> const AxisLimits& { return lim.axes[static_cast<std::size_t>(i)]; };
  const double r_max = std::max(r0, r1);
  const double r_min = std::min(r0, r1);
  const double kp = std::sqrt(sq(r_max * d) + sq(dr)) / s.length;
  const double feed = m.feed_mm_s > 0.0 ? m.feed_mm_s : lim.max_feed_mm_s;
  double v = std::min(feed, lim.max_feed_mm_s);
  v = std::min(v, positive(ax(pl.a0).max_velocity_mm_s) / kp);
  v = std::min(v, positive(ax(pl.a1).max_velocity_mm_s) / kp);
  const double a_plane =
      std::min(positive(ax(pl.a0).max_accel_mm_s2), positive(ax(pl.a1).max_accel_mm_s2)) /
      spiral_factor(r0, r1, d);
  v = std::min(v, std::sqrt(kCentripetalShare * a_plane * r_min) / kp);
  double a = kInf;
  for (int j = 0; j < kMaxAxes; ++j) {
    if (j == pl.a0 || j == pl.a1) continue;
    const double k = std::abs(j == pl.normal ? dn : s.end[j] - s.start[j]) / s.length;
    if (k == 0.0) continue;
    v = std::min(v, positive(ax(j).max_velocity_mm_s) / k);
    a = std::min(a, positive(ax(j).max_accel_mm_s2) / k);
  }
  s.v_max = v;
  s.centripetal = sq(v * kp) / r_min;
  const double a_tan_plane = std::sqrt(std::max(0.0, sq(a_plane) - sq(s.centripetal)));
  s.accel = std::min(a, positive(a_tan_plane) / kp);
  return true;
}

// The highest speed at which `in` may hand over to `out`.
double junction_speed(const Segment& in, const Segment& out, const Limits& lim) noexcept {
  if (in.exact_stop || in.no_accel || out.no_accel || in.in_position || out.wait_in_position) {
    return 0.0;
  }
  if (in.kind == Kind::kRapid || in.kind == Kind::kRapidNonLinear || in.kind == Kind::kDwell) {
    return 0.0;
  }
  if (out.kind == Kind::kRapid || out.kind == Kind::kRapidNonLinear || out.kind == Kind::kDwell) {
    return 0.0;
  }
  double v = std::min(in.v_max, out.v_max);
  const AxisVec u_in = direction_at_fraction(in, 1.0);
  const AxisVec u_out = direction_at_fraction(out, 0.0);
  const AxisVec p = accel_bound(in, 1.0);
  const AxisVec q = accel_bound(out, 0.0);
  for (int i = 0; i < kMaxAxes; ++i) {
    const double du = std::abs(u_out[i] - u_in[i]);
    if (du <= kDirEpsilon) continue;
    const double a = positive(lim.axes[static_cast<std::size_t>(i)].max_accel_mm_s2);
    // An axis that reverses can have the step and both neighbours'
    // accelerations pointing the same way: it gets the full share.
    const double share = u_in[i] * u_out[i] < 0.0 ? 1.0 : kJunctionAccelShare;
    const double budget = a - share * std::max(p[i], q[i]);
    if (budget <= 0.0) return 0.0;
    v = std::min(v, budget * lim.period_s / du);
  }
  return v;
}

}  // namespace

// ---------------------------------------------------------------------------
// Segment evaluation

double Segment::distance_at(double t) const noexcept {
  if (kind == Kind::kDwell) return 0.0;
  if (kind == Kind::kRapidNonLinear) {
    const auto k = static_cast<std::size_t>(basis_axis);
    return axis_travel(length, axis_v[k], axis_a[k], axis_t_acc[k], axis_t_total[k], t);
  }
  if (!(t > 0.0)) return 0.0;
  if (t >= duration) return length;
  double s = 0.0;
  if (t < t_acc) {
    s = (v_entry + 0.5 * accel * t) * t;
  } else if (t < t_acc + t_cruise) {
    s = d_acc + v_cruise * (t - t_acc);
  } else {
    const double tau = duration - t;
    s = length - (v_exit + 0.5 * accel * tau) * tau;
  }
  return std::clamp(s, 0.0, length);
}

double Segment::speed_at(double t) const noexcept {
  if (kind == Kind::kDwell) return 0.0;
  if (kind == Kind::kRapidNonLinear) return norm(velocity_at(t), kMaxAxes);
  if (!(t > 0.0)) return v_entry;
  if (t >= duration) return v_exit;
  if (t < t_acc) return v_entry + accel * t;
  if (t < t_acc + t_cruise) return v_cruise;
  return v_exit + accel * (duration - t);
}

AxisVec Segment::position_at(double t) const noexcept {
  if (t >= duration) return end;
  if (kind == Kind::kDwell) return start;
  if (kind == Kind::kRapidNonLinear) {
    AxisVec p = start;
    for (int i = 0; i < kMaxAxes; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (unit[i] == 0.0) continue;
      if (t >= axis_t_total[k]) {
        p[i] = end[i];
        continue;
      }
      const double d = std::abs(end[i] - start[i]);
      p[i] = start[i] +
             unit[i] * axis_travel(d, axis_v[k], axis_a[k], axis_t_acc[k], axis_t_total[k], t);
    }
    return p;
  }
  const double s = distance_at(t);
  if (kind == Kind::kArc) return arc_point(*this, s);
  AxisVec p = start;
  for (int i = 0; i < kMaxAxes; ++i) p[i] += unit[i] * s;
  return p;
}

AxisVec Segment::tangent_at(double t) const noexcept {
  switch (kind) {
    case Kind::kDwell:
      return AxisVec{};
    case Kind::kArc: {
      const double tc = std::clamp(t, 0.0, duration);
      return arc_direction(*this, distance_at(tc) / length);
    }
    case Kind::kRapidNonLinear: {
      const AxisVec v = velocity_at(t);
      const double n = norm(v, kMaxAxes);
      if (n > 0.0) return v * (1.0 / n);
      const AxisVec d = end - start;
      const double len = norm(d, kMaxAxes);
      return len > 0.0 ? d * (1.0 / len) : AxisVec{};
    }
    case Kind::kLine:
    case Kind::kRapid:
      break;
  }
  return unit;
}

AxisVec Segment::velocity_at(double t) const noexcept {
  if (kind == Kind::kRapidNonLinear) {
    AxisVec v;
    for (int i = 0; i < kMaxAxes; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (unit[i] == 0.0) continue;
      v[i] = unit[i] * axis_speed(axis_v[k], axis_a[k], axis_t_acc[k], axis_t_total[k], t);
    }
    return v;
  }
  return tangent_at(t) * speed_at(t);
}

namespace {

// sample() outside a line, rapid or arc's inside (a dwell, a non-linear
// rapid, the ends): not inlined, so that the common path keeps its
// registers.
[[gnu::noinline]] void sample_apart(const Segment& seg, double t, AxisVec& position,
                                    AxisVec& velocity, double& speed) noexcept {
  position = seg.position_at(t);
  velocity = seg.velocity_at(t);
  speed = seg.speed_at(t);
}

}  // namespace

void Segment::sample(double t, int axis_count, AxisVec& position, AxisVec& velocity,
                     double& speed) const noexcept {
  if (kind == Kind::kDwell || kind == Kind::kRapidNonLinear || !(t > 0.0) || t >= duration) {
    sample_apart(*this, t, position, velocity, speed);
    return;
  }
  // Inside a line, rapid or arc: distance and speed from one phase of the profile.
  double s = 0.0, v = 0.0;
  if (t < t_acc) {
    s = (v_entry + 0.5 * accel * t) * t;
    v = v_entry + accel * t;
  } else if (t < t_acc + t_cruise) {
    s = d_acc + v_cruise * (t - t_acc);
    v = v_cruise;
  } else {
    const double tau = duration - t;
    s = length - (v_exit + 0.5 * accel * tau) * tau;
    v = v_exit + accel * tau;
  }
  s = std::clamp(s, 0.0, length);
  speed = v;
  if (kind == Kind::kArc) {
    position = arc_point(*this, s);
    velocity = arc_direction(*this, s / length) * v;
    return;
  }
  for (int i = 0; i < axis_count; ++i) {
    position[i] = start[i] + unit[i] * s;
    velocity[i] = unit[i] * v;
  }
}

// ---------------------------------------------------------------------------
// SegmentQueue

SegmentQueue::SegmentQueue(const Limits& limits, std::size_t capacity)
    : limits_(limits), ring_(std::max<std::size_t>(capacity, 1)) {}

void SegmentQueue::reset(const AxisVec& position) noexcept {
  head_ = 0;
  count_ = 0;
  tail_ = position;
  front_entry_ = 0.0;
}

void SegmentQueue::pop_front() noexcept {
  if (count_ == 0) return;
  const Segment& s = ring_[head_];
  front_entry_ = s.no_accel ? 0.0 : s.v_exit;
  head_ = (head_ + 1) % ring_.size();
  --count_;
  if (count_ == 0) front_entry_ = 0.0;
}

bool SegmentQueue::push(const Move& move) {
  if (full()) return false;
  Segment s;
  s.kind = move.kind;
  s.start = tail_;
  s.end = move.target;
  s.line = move.line;
  s.source = move.source;
  s.tag = move.tag;
  s.exact_stop = move.exact_stop;
  s.no_accel = move.no_accel && (move.kind == Kind::kLine || move.kind == Kind::kArc);
  s.in_position = move.in_position;
  s.wait_in_position = move.wait_in_position;

  switch (move.kind) {
    case Kind::kDwell:
      // A dwell of no time (G04 X0) is a segment too: the axes come to rest
      // and in position as for any dwell, and the block is counted as run
      // (the interpolator says it passed it: its row in the block times).
      if (!(move.dwell_s >= 0.0)) return true;
      s.end = tail_;
      s.exact_stop = true;
      s.no_accel = false;
      s.duration = move.dwell_s;
      s.t_cruise = move.dwell_s;
      break;
    case Kind::kRapidNonLinear:
      if (s.end == s.start) return true;
      s.exact_stop = true;
      build_rapid_nonlinear(s, limits_);
      break;
    case Kind::kRapid:
      if (s.end == s.start) return true;
      s.exact_stop = true;
      build_linear(s, move, limits_);
      break;
    case Kind::kArc:
      if (build_arc(s, move, limits_)) break;
      s.kind = Kind::kLine;
      [[fallthrough]];
    case Kind::kLine:
      if (s.end == s.start) return true;
      build_linear(s, move, limits_);
      break;
  }

  if (s.no_accel) {
    s.accel = kInf;
    s.v_entry = s.v_exit = s.v_cruise = s.v_max;
    s.t_acc = s.t_dec = 0.0;
    s.d_acc = 0.0;
    s.t_cruise = s.length / s.v_max;
    s.duration = s.t_cruise;
  }

  s.v_entry_max = count_ > 0 ? junction_speed(at(count_ - 1), s, limits_) : 0.0;
  ring_[(head_ + count_) % ring_.size()] = s;
  ++count_;
  tail_ = s.end;
  replan();
  return true;
}

void SegmentQueue::replan() noexcept {
  const std::size_t n = count_;
  std::size_t first = 0;
  while (first < n && at(first).started) ++first;
  if (first == n) return;

  // Backward pass: the exit of each segment is limited by what the rest of
  // the queue can still absorb (the newest segment ends at rest). Only the
  // newest segment is new since the last replan: once an older segment's exit
  // comes out as it was, or one that is always entered from rest is met,
  // every segment before it would be planned exactly as it is (exits and
  // profiles), so both passes stop there.
  double next_entry = 0.0;
  std::size_t from = first;  // the first segment whose profile may change
  for (std::size_t k = n; k-- > first;) {
    Segment& s = at(k);
    const bool newest = k + 1 == n;
    if (s.kind == Kind::kDwell || s.kind == Kind::kRapidNonLinear || s.no_accel) {
      // Its predecessor ends at rest (a no_accel segment's v_entry_max is 0).
      if (!newest) {
        from = k + 1;
        break;
      }
      next_entry = 0.0;
      continue;
    }
    const double v_exit = s.exact_stop || newest ? 0.0 : next_entry;
    if (!newest && v_exit == s.v_exit) {
      from = k + 1;
      break;
    }
    s.v_exit = v_exit;
    next_entry =
        std::min({s.v_entry_max, s.v_max, std::sqrt(sq(s.v_exit) + 2.0 * s.accel * s.length)});
  }

  // Forward pass: each entry is the previous exit; the exit is what can be
  // reached from there; then the closed-form profile.
  for (std::size_t k = from; k < n; ++k) {
    Segment& s = at(k);
    if (s.kind == Kind::kDwell || s.kind == Kind::kRapidNonLinear || s.no_accel) continue;
    double v0 = front_entry_;
    if (k > 0) {
      const Segment& prev = at(k - 1);
      v0 = prev.no_accel ? 0.0 : prev.v_exit;
    }
    const double v1 = std::min(s.v_exit, std::sqrt(sq(v0) + 2.0 * s.accel * s.length));
    make_profile(s, v0, v1);
  }
}

}  // namespace skipnc::planner
