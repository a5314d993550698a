// Motion blocks: rapid, linear, circular, dwell, reference return. Targets
// are computed in the block's modes and emitted in machine coordinates. The
// skip family (G31) is in skip.cpp.
#include <cmath>
#include <string>

#include "interpreter/impl.hpp"

namespace skipnc::interp {

Flow<void> Interpreter::Impl::dwell(const Words& words, CommandSink& out) {
  double seconds = 0.0;
  if (lang->rules.dwell_p_seconds && words.has('P')) {
    seconds = words.at('P').value;  // LinuxCNC and grbl: P in seconds
  } else if (words.has('P')) {
    const WordVal& p = words.at('P');
    if (p.has_point) {
      return fail(AlarmId::kBadDecimalPoint, "G04 P is in milliseconds, without decimal point",
                  loc(p.column));
    }
    seconds = p.value / 1000.0;
  } else if (words.has('X')) {
    seconds = word_length(words.at('X'));
  } else if (words.has('U')) {
    seconds = word_length(words.at('U'));
  }
  if (seconds < 0) return fail(AlarmId::kBadValue, "negative dwell", loc(cur_col));
  if (modal.feed_mode == FeedMode::kPerRev && params.bit(config::param::kDwellRevolutions)) {
    // 3405#1 DWL: in feed per revolution the dwell counts spindle
    // revolutions (X1. = 1 revolution, P1000 = 1 revolution).
    auto s = need_spindle_for_feed(cur_col);
    if (!s) return s;
    seconds = seconds * 60.0 / spindle_rpm_at(pos);
  }
  emit(out, canon::Dwell{seconds});
  motion_since_sync = true;
  return {};
}

Flow<void> Interpreter::Impl::reference_return(const Words& words, int g, CommandSink& out) {
  return lang->reference_return(*this, words, g, out);
}

// The Fanuc family's G28 / G30.
Flow<void> Interpreter::Impl::reference_return_fanuc(const Words& words, int g, CommandSink& out) {
  // G30: P2-P4 choose the 2nd-4th reference point (P omitted: the 2nd), from
  // the machine file's [reference_points]; G28: the reference position,
  // machine zero.
  const AxisVec* point = nullptr;
  if (g == 30) {
    int p = 2;
    if (words.has('P')) {
      const double v = words.at('P').value;
      if (v != 2.0 && v != 3.0 && v != 4.0) {
        return fail(AlarmId::kBadValue, "G30 P must be 2, 3 or 4 (2nd-4th reference point)",
                    loc(words.at('P').column));
      }
      p = static_cast<int>(v);
    }
    point = &mc.reference_points[static_cast<std::size_t>(p - 2)];
  }
  // Through the intermediate point (X/Z absolute, U/W incremental).
  AxisVec mid;
  AxisMask moved;
  auto t = axis_targets(words, false, mid, moved);
  if (!t) return t;
  if (moved.empty()) return {};
  AxisVec ref = pos;
  for (int i = 0; i < axis_count; ++i) {
    if (moved.has(i)) ref[i] = point != nullptr ? (*point)[i] : 0.0;
  }
  const bool linear = block_params.linear_rapid;
  emit(out, canon::Rapid{mid, linear});
  emit(out, canon::Rapid{ref, linear});
  pos = ref;
  motion_since_sync = true;
  return {};
}

Flow<Step> Interpreter::Impl::motion(const Words& words, CommandSink& out, bool skip, bool g53) {
  AxisVec target;
  AxisMask moved;
  auto t = axis_targets(words, g53, target, moved);
  SKIPNC_TRY(t);
  // LinuxCNC and grbl move in machine coordinates only with G0 or G1: G53
  // with G38.n or an arc is refused (LinuxCNC rs274ngc check_g_codes,
  // "Must use G0 or G1 with G53"; grbl gcode.c, error 30).
  if (g53 && lang->rules.g53_g0_g1_only &&
      (skip || (modal.motion != Motion::kRapid && modal.motion != Motion::kLinear))) {
    return fail(AlarmId::kG53Motion,
                skip ? "G53 with a probe move (G38.n): G53 moves only with G0 or G1"
                     : "G53 with an arc (G02/G03 modal): G53 moves only with G0 or G1",
                loc(cur_col));
  }
  // G53 G01 is a feed in machine coordinates on LinuxCNC and grbl.
  if (g53 && !skip && !(lang->rules.g53_g0_g1_only && modal.motion == Motion::kLinear)) {
    // G53 positions at rapid traverse whatever the modal motion (B-63944EN
    // "Machine coordinate system"); in G91 it is an incremental rapid.
    emit(out, canon::Rapid{target, block_params.linear_rapid});
    pos = target;
    motion_since_sync = true;
    return Step::kContinue;
  }
  if (skip || modal.motion != Motion::kRapid) {
    auto s = need_spindle_for_feed(cur_col);
    SKIPNC_TRY(s);
  }
  if (skip) return skip_block(words, target, moved, out);
  if (modal.motion != Motion::kRapid) skip_state.last_cut_feed = modal.feed;
  const bool exact = modal.path == PathMode::kExactStop || words.has_g(GCode(9));
  switch (modal.motion) {
    case Motion::kRapid:
      emit(out, canon::Rapid{target, block_params.linear_rapid});
      break;
    case Motion::kLinear:
      if (feed_mm_per_min() <= 0.0) {
        return fail(AlarmId::kNoFeed, "G01 without a feed (F)", loc(cur_col));
      }
      emit(out, canon::Feed{target, feed_mm_per_min(), exact});
      break;
    case Motion::kCwArc:
    case Motion::kCcwArc: {
      auto r = arc(words, target, out);
      SKIPNC_TRY(r);
      break;
    }
    case Motion::kTurningCycle: {
      auto r = turning_cycle(words, target, moved, out);
      SKIPNC_TRY(r);
      break;
    }
    case Motion::kProbe:
      return fail(AlarmId::kInternal, "a G38 block reached the motion of a G01", loc(cur_col));
  }
  pos = target;
  motion_since_sync = true;
  return Step::kContinue;
}

namespace {

// The arc's plane (its two axes and the normal) and the words of its centre
// offset (I J, K I or J K).
struct ArcPlane {
  canon::Plane pl;
  char ci = 'I', cj = 'J';
};

ArcPlane arc_plane(const Interpreter::Impl& im) noexcept {
  auto idx = [&](char c) { return im.axis_of_letter[static_cast<std::size_t>(c - 'A')]; };
  switch (im.modal.plane) {
    case PlaneSel::kZX:
      return {{idx('Z'), idx('X'), idx('Y')}, 'K', 'I'};
    case PlaneSel::kYZ:
      return {{idx('Y'), idx('Z'), idx('X')}, 'J', 'K'};
    case PlaneSel::kXY:
      break;
  }
  return {{idx('X'), idx('Y'), idx('Z')}, 'I', 'J'};
}

// What the centre is found from: the start and end in the plane (machine
// mm), the direction, the frame (G51 / G51.1 / G68 in the XY plane) and
// the radius tolerance.
struct ArcGeometry {
  double sx, sy, ex, ey;
  bool ccw, framed;
  double tol;
};

// The centre of an arc given by its radius R (R < 0: the long way). (The
// helpers of arc are inlined: one call per arc block.)
[[gnu::always_inline]] inline Flow<void> arc_center_r(const Interpreter::Impl& im,
                                                      const Words& words, const ArcGeometry& g,
                                                      SourceLoc at, double& cx, double& cy) {
  const SourceLoc r_at = im.loc(words.at('R').column);
  const double r = im.word_length(words.at('R')) * im.unit_mm() *
                   (g.framed ? std::fabs(im.frame().scale[0]) : 1.0);
  const double dx = g.ex - g.sx, dy = g.ey - g.sy;
  const double d = std::hypot(dx, dy);
  if (d < 1e-9) {
    return fail(AlarmId::kArcBadCenter, "a full circle cannot be programmed with R; use I, J or K",
                at);
  }
  if (r == 0.0) return fail(AlarmId::kArcBadCenter, "R0", r_at);
  const double half = d / 2.0;
  if (half > std::fabs(r) + g.tol) {
    return fail(AlarmId::kArcRadiusMismatch,
                "R" + std::to_string(std::fabs(r)) + " is smaller than half the chord " +
                    std::to_string(half),
                r_at);
  }
  const double h = std::sqrt(std::max(0.0, r * r - half * half));
  // Left of the chord for a short ccw arc; right for cw; R < 0 takes the long way.
  double side = g.ccw ? 1.0 : -1.0;
  if (r < 0) side = -side;
  cx = g.sx + dx / 2.0 - side * h * dy / d;
  cy = g.sy + dy / 2.0 + side * h * dx / d;
  return {};
}

// LinuxCNC's tolerance (interp_arc.cc): 2 * 0.01 mm * sqrt(2), 2 * 0.001
// inch * sqrt(2) in G20.
[[gnu::always_inline]] inline double linuxcnc_arc_tolerance(const Interpreter::Impl& im) noexcept {
  return (im.modal.units == Units::kInch ? 0.001 * 25.4 : 0.01) * 2.0 * std::sqrt(2.0);
}

// Whether the start and end radii differ too much, under the language's rule.
[[gnu::always_inline]] inline bool radius_error(const Interpreter::Impl& im, double r0, double r1,
                                                double tol) noexcept {
  if (!im.lang->rules.arc_radius_linuxcnc) return std::fabs(r1 - r0) > tol;
  // LinuxCNC (interp_arc.cc): refused when the radii differ by more than
  // 100 times the tolerance, or by more than the tolerance and 0.1 %.
  const double abs_tol = linuxcnc_arc_tolerance(im);
  const double err = std::fabs(r1 - r0);
  return err > 100.0 * abs_tol || (err / std::max(r0, r1) > 0.001 && err > abs_tol);
}

// Whether the radii of an arc (start and end to the centre) are surely
// accepted: their difference, from sqrt(x * x + y * y), is below the
// tolerance by far more than the few units in the last place between that
// and std::hypot (no square overflows below 1e150; none underflows to
// matter above 2e-9). Where this is not sure the radii come from std::hypot.
[[gnu::always_inline]] inline bool radii_surely_accepted(const Interpreter::Impl& im,
                                                         const ArcGeometry& g, double cx,
                                                         double cy) noexcept {
  const double a = g.sx - cx, b = g.sy - cy, c = g.ex - cx, d = g.ey - cy;
  const double q0 = std::sqrt(a * a + b * b), q1 = std::sqrt(c * c + d * d);
  // Under LinuxCNC's rule a difference below its tolerance is never refused.
  const double limit = im.lang->rules.arc_radius_linuxcnc ? linuxcnc_arc_tolerance(im) : g.tol;
  return q0 > 2e-9 && q0 < 1e150 && q1 < 1e150 &&
         std::fabs(q1 - q0) + 1e-12 * std::max(q0, q1) < limit;
}

// The centre of an arc given by I, J, K (G90.1: absolute in work coordinates).
[[gnu::always_inline]] inline Flow<void> arc_center_ijk(const Interpreter::Impl& im,
                                                        const Words& words, const ArcPlane& ap,
                                                        const ArcGeometry& g, SourceLoc at,
                                                        double& cx, double& cy) {
  const char ci = ap.ci, cj = ap.cj;
  double oi = words.has(ci) ? im.word_length(words.at(ci)) * im.unit_mm() : 0.0;
  double oj = words.has(cj) ? im.word_length(words.at(cj)) * im.unit_mm() : 0.0;
  if (im.modal.arc_ijk_absolute) {
    // G90.1: I J K are the centre in work coordinates.
    oi = words.has(ci) ? im.machine_of(ap.pl.a0, oi / im.unit_mm()) - g.sx : 0.0;
    oj = words.has(cj) ? im.machine_of(ap.pl.a1, oj / im.unit_mm()) - g.sy : 0.0;
  }
  if (g.framed) {
    const xform::Point v = xform::vector_to_work(im.frame(), {oi, oj, 0.0});
    oi = v[0];
    oj = v[1];
  }
  cx = g.sx + oi;
  cy = g.sy + oj;
  if (radii_surely_accepted(im, g, cx, cy)) return {};
  const double r0 = std::hypot(g.sx - cx, g.sy - cy);
  const double r1 = std::hypot(g.ex - cx, g.ey - cy);
  if (r0 < 1e-9) return fail(AlarmId::kArcBadCenter, "the arc's centre is its start point", at);
  if (radius_error(im, r0, r1, g.tol)) {
    return fail(AlarmId::kArcRadiusMismatch,
                "start radius " + std::to_string(r0 / im.unit_mm()) + ", end radius " +
                    std::to_string(r1 / im.unit_mm()),
                at);
  }
  return {};
}

}  // namespace

Flow<void> Interpreter::Impl::arc(const Words& words, const AxisVec& target, CommandSink& out) {
  canon::Arc a;
  SKIPNC_TRY(arc_move(words, target, a));
  emit(out, a);
  return {};
}

// The arc command of a block into `a`, or its alarm; nothing changes.
Flow<void> Interpreter::Impl::arc_move(const Words& words, const AxisVec& target,
                                       canon::Arc& a) const {
  const ArcPlane ap = arc_plane(*this);
  const canon::Plane& pl = ap.pl;
  const SourceLoc at = loc(cur_col);
  if (pl.a0 < 0 || pl.a1 < 0) {
    return fail(AlarmId::kIllegalPlaneAxis, "the selected plane's axes are not on this machine",
                at);
  }
  if (feed_mm_per_min() <= 0.0) return fail(AlarmId::kNoFeed, "G02/G03 without a feed (F)", at);
  // Under G51 / G51.1 / G68 (XY plane) the centre offset turns and scales with
  // the frame, and an odd number of mirrored axes reverses the direction.
  const bool framed = !mc.lathe() && frame().active() && modal.plane == PlaneSel::kXY;
  if (!mc.lathe() && frame().spatial != nullptr && (frame().tilted() || !framed)) {
    // The program's arc plane is tilted out of the machine's planes.
    return fail(AlarmId::kNotSimulated,
                "an arc under a G68 I J K or G54.4 that turns other than about Z (or outside "
                "G17) is not simulated by skipnc",
                at);
  }
  const bool flipped = framed && ((frame().mirror[0] != (frame().scale[0] < 0.0)) !=
                                  (frame().mirror[1] != (frame().scale[1] < 0.0)));
  const double tol = block_params.arc_tolerance;
  const ArcGeometry g{pos[pl.a0],
                      pos[pl.a1],
                      target[pl.a0],
                      target[pl.a1],
                      (modal.motion == Motion::kCcwArc) != flipped,
                      framed,
                      tol};
  double cx = 0, cy = 0;
  if (words.has('R')) {
    SKIPNC_TRY(arc_center_r(*this, words, g, at, cx, cy));
  } else if (lang->rules.arc_turns_p && words.has('P') && words.at('P').value != 1.0) {
    return fail(AlarmId::kNotSimulated,
                "G02/G03 P (an arc of more than one turn) is not simulated by skipnc",
                loc(words.at('P').column));
  } else if (words.has(ap.ci) || words.has(ap.cj)) {
    SKIPNC_TRY(arc_center_ijk(*this, words, ap, g, at, cx, cy));
  } else {
    return fail(AlarmId::kArcBadCenter, "G02/G03 needs R or the centre (I, J, K)", at);
  }
  if (&a.target != &target) a.target = target;
  a.center0 = cx;
  a.center1 = cy;
  a.plane = pl;
  a.ccw = g.ccw;
  a.feed_mm_per_min = feed_mm_per_min();
  a.exact_stop = modal.path == PathMode::kExactStop || words.has_g(GCode(9));
  return {};
}

}  // namespace skipnc::interp
