// The mill's codes beside the core G-code table of ncblock.cpp: canned
// cycles (group 09), coordinate rotation G68/G69, scaling G50/G51,
// programmable mirror G50.1/G51.1, polar coordinates G15/G16, the codes that
// change nothing in a simulation, and the codes skipnc does not simulate
// (an alarm that says so, distinct from an improper G code).
//
// Sources: Fanuc Series 30i/31i/32i-MODEL A operator's manual (machining
// centre), B-63944EN: 5.1 canned cycles, 6.x scaling, coordinate system
// rotation and mirror image; Fanuc 0i-A connection manual B-63503EN-1
// (parameters 5400#0 RIN, 5410).
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <variant>

#include "config/skip_inputs.hpp"
#include "interpreter/codes.hpp"
#include "interpreter/impl.hpp"
#include "interpreter/offset_units.hpp"

namespace skipnc::interp {
namespace {

// G37 (B-63944EN "Automatic tool length measurement"): parameters 6241 the
// measurement feed, 6251 gamma (the rapid approach ends gamma before the
// measuring position), 6254 epsilon (the signal must come within epsilon of
// it); the measuring position reached signals XAE, YAE, ZAE of the machining
// centre are X4.0, X4.1, X4.2 (Fanuc connection manual, signal list).
constexpr int kG37FeedParam = config::param::kG37Feed;
constexpr int kG37GammaParam = config::param::kG37Gamma;
struct MeasureSignal {
  char axis;
  canon::SignalAddr addr;
};
constexpr MeasureSignal kMeasureSignals[] = {
    {'X', {'X', 4, 0}}, {'Y', {'X', 4, 1}}, {'Z', {'X', 4, 2}}};

// Most pecks of one G73/G83 hole (see canned_cycle).
constexpr double kMaxPecks = 10000;

// As the manuals write them: G05.1, G08, G12.1.
std::string name(GCode code) {
  return code_name(code, CodeStyle::kManual);
}

// A value without decimal point in an address that is not a length: in
// `increment` units (G68 R: 0.001 degree; G51 P: 0.001 or 0.00001).
double scaled_word(const WordVal& w, double increment, bool calculator) {
  return w.is_expr || w.has_point || calculator ? w.value : w.value * increment;
}

}  // namespace

// A code of the mill beyond the modal groups and one-shot actions (its
// handler kind in the code table). Returns false when the code is not a
// code of this control after all (the caller raises the improper G code
// alarm).
Flow<bool> Interpreter::Impl::mill_code(const CodeDef& def, SourceLoc at, MillRequest& req) const {
  const GCode code = def.code;
  switch (def.handler) {
    case Handler::kSkipStep:
      if (dialect.param(kSkipStepParam) == nullptr) break;
      // Multi-step skip function 1: the dialect has its parameters
      // (mitsubishi.toml); a G31 whose signals and feed come from them.
      req.skip_step = code.decimal();
      return true;
    case Handler::kG37_1:
      // Mitsubishi's G37.1 (M700V/M70V manual 15.1): only where the dialect
      // defines its TLM parameter 8004 (mitsubishi.toml); elsewhere no code.
      if (dialect.param(ToolMeasurement::kG37_1SpeedParam) == nullptr) return false;
      break;
    case Handler::kG37:
      if (dialect.param(ToolMeasurement::kEpsilonParam) == nullptr) break;
      req.g37 = true;  // the dialect has G37's parameters (fanuc.toml)
      return true;
    case Handler::kCycle:
      req.cycle = def.cycle;
      return true;
    case Handler::kFrame:
      if (def.frame == FrameCode::kSettingError && dialect.param(kSettingErrorParam) == nullptr) {
        return false;
      }
      if (def.frame == FrameCode::kPolar || def.frame == FrameCode::kPolarCancel) {
        // Group 17: changes only how X and Y are read, from this block on.
        req.polar = def.frame == FrameCode::kPolar;
        return true;
      }
      if (req.frame != nullptr) {
        return fail(AlarmId::kGCodeConflict, name(req.frame->code) + " and " + name(code), at);
      }
      req.frame = &def;
      req.frame_at = at;
      return true;
    case Handler::kNoEffect:
      req.no_effect = name(code) + " " + def.summary;
      return true;
    case Handler::kLookahead:
      req.lookahead = true;
      return true;
    default:
      break;
  }
  // kNotSimulated, and the dialect-dependent codes where the dialect has
  // not their parameters.
  return fail(AlarmId::kNotSimulated,
              name(code) + " " + def.summary + " is not simulated by skipnc", at);
}

// G103 Pn (Haas "G103 Limit Block Buffering"): look-ahead limited to n
// blocks, 0-15; G103 alone or P0: no limit. Sent to the planner
// (canon::LookAhead: the motion may know n moves beyond the one running);
// nothing else reads it (#4xxx have no place for it), so it is not kept.
// What it changes for a probing macro (the expressions evaluated in step
// with the motion), skipnc does at every block.
Flow<int> Interpreter::Impl::lookahead_limit(const Words& words) const {
  if (!words.has('P')) return 0;
  const WordVal& p = words.at('P');
  if (p.value != std::trunc(p.value) || p.value < 0 || p.value > 15) {
    return fail(AlarmId::kBadValue,
                "G103 P" + fmt::format("{}", p.value) + ": the look-ahead limit is 0 to 15 blocks",
                loc(p.column));
  }
  return static_cast<int>(p.value);
}

namespace {

// Where the block's frame codes start from: the present position in the
// work system and in the program frame, and the block's X Y Z words.
struct FrameWords {
  const Interpreter::Impl& in;
  const Words& words;
  std::array<int, 3> xyz;
  xform::Point here_work, here;
  FrameWords(const Interpreter::Impl& impl, const Words& w)
      : in(impl),
        words(w),
        xyz{impl.axis_of_letter['X' - 'A'], impl.axis_of_letter['Y' - 'A'],
            impl.axis_of_letter['Z' - 'A']} {
    for (std::size_t i = 0; i < 3; ++i) {
      here_work[i] = xyz[i] >= 0 ? impl.work_of(xyz[i], impl.pos[xyz[i]]) : 0.0;
    }
    here = xform::to_program(impl.frame(), here_work);
  }
  // The word of X, Y or Z (i = 0..2), else `fallback`.
  double word(int i, double fallback) const {
    if (xyz[static_cast<std::size_t>(i)] < 0) return fallback;
    const char c = "XYZ"[i];
    return words.has(c) ? in.word_length(words.at(c)) : fallback;
  }
};

// G68: rotation about X Y (or the present position) by R.
Flow<void> frame_rotation(Interpreter::Impl& in, const FrameWords& fw, const MillRequest& req,
                          xform::Transform& next) {
  const Words& words = fw.words;
  if (in.frame().setting_error()) {
    return fail(AlarmId::kNotSimulated, "G68 without I J K under G54.4 is not simulated by skipnc",
                req.frame_at);
  }
  if (in.modal.plane != PlaneSel::kXY) {
    return fail(AlarmId::kNotSimulated,
                "G68 in the G18/G19 plane is not simulated by skipnc (G17 only)", req.frame_at);
  }
  // The centre: X Y (always absolute), else the present position; in
  // G51 mode it is scaled too (B-63944EN "Scaling and coordinate system
  // rotation").
  xform::Transform before_rotation = in.frame();
  before_rotation.rotating = false;
  const xform::Point c =
      words.has('X') || words.has('Y')
          ? xform::to_work(before_rotation, {fw.word(0, fw.here[0]), fw.word(1, fw.here[1]), 0})
          : fw.here_work;
  double angle = in.params.get(config::param::kRotationAngle) * 0.001;
  if (words.has('R')) {
    angle = scaled_word(words.at('R'), 0.001, in.params.bit(config::param::kCalculatorDecimal));
    if (in.params.bit(config::param::kRotationIncremental) &&
        in.modal.distance == Distance::kIncremental) {
      angle += in.frame().rotating ? in.frame_codes.rotation_angle : 0.0;
    }
  }
  next.rotating = true;
  next.angle_deg = angle;
  next.rotation_center = {c[0], c[1]};
  in.frame_codes.rotation_angle = angle;
  return {};
}

// G51: magnification P (or I J K per axis) about X Y Z.
Flow<void> frame_scaling(const Interpreter::Impl& in, const FrameWords& fw, const MillRequest& req,
                         xform::Transform& next) {
  const Words& words = fw.words;
  if (in.frame().conversions() > 0) {
    return fail(AlarmId::kNotSimulated, "G51 under G68 I J K is not simulated by skipnc",
                req.frame_at);
  }
  const double inc = in.params.bit(config::param::kScalingFine) ? 0.00001 : 0.001;
  const bool calc = in.params.bit(config::param::kCalculatorDecimal);
  double all = in.params.get(config::param::kMagnification) * inc;
  if (words.has('P')) all = scaled_word(words.at('P'), inc, calc);
  std::array<double, 3> f{all, all, all};
  for (int i = 0; i < 3; ++i) {
    const char c = "IJK"[i];
    if (words.has(c)) f[static_cast<std::size_t>(i)] = scaled_word(words.at(c), inc, calc);
  }
  for (double v : f) {
    if (v == 0.0 || !std::isfinite(v)) {
      return fail(AlarmId::kBadValue, "G51 magnification 0", req.frame_at);
    }
  }
  next.scale = f;
  next.scale_center = {fw.word(0, fw.here[0]), fw.word(1, fw.here[1]), fw.word(2, fw.here[2])};
  return {};
}

}  // namespace

// G68 G69 G50 G51 G50.1 G51.1, after the block's modes are committed.
// Returns true when the block's axis words were the mode's data (no move).
Flow<bool> Interpreter::Impl::apply_frame_code(const Words& words, const MillRequest& req) {
  const FrameWords fw(*this, words);
  xform::Transform next = frame();
  bool consumed = false;
  switch (req.frame != nullptr ? req.frame->frame : FrameCode::kNone) {
    case FrameCode::kSettingError: {
      auto s = setting_error(words, req);  // conversion_3d.cpp
      SKIPNC_TRY(s);
      program_frame.write() = *s;
      return true;
    }
    case FrameCode::kRotationCancel:
      next.rotating = false;
      if (frame().spatial) {  // G69 ends both 3-D conversions too, not G54.4
        xform::Spatial s = *frame().spatial;
        s.conversions = 0;
        next = xform::with_spatial(next, s);
      }
      break;
    case FrameCode::kRotation:
      if (words.has('I') || words.has('J') || words.has('K') || frame().conversions() > 0) {
        auto k = conversion_3d(words, req, fw.here);  // conversion_3d.cpp
        SKIPNC_TRY(k);
        program_frame.write() = *k;
        return true;
      }
      SKIPNC_TRY(frame_rotation(*this, fw, req, next));
      consumed = true;
      break;
    case FrameCode::kScalingCancel:
      next.scale = {1.0, 1.0, 1.0};
      break;
    case FrameCode::kScaling:
      SKIPNC_TRY(frame_scaling(*this, fw, req, next));
      consumed = true;
      break;
    case FrameCode::kMirror:
    case FrameCode::kMirrorCancel:
      if (req.frame->frame == FrameCode::kMirror && frame().conversions() > 0) {
        return fail(AlarmId::kNotSimulated, "G51.1 under G68 I J K is not simulated by skipnc",
                    req.frame_at);
      }
      for (int i = 0; i < 3; ++i) {
        if (fw.xyz[static_cast<std::size_t>(i)] < 0 || !words.has("XYZ"[i])) continue;
        next.mirror[static_cast<std::size_t>(i)] = req.frame->frame == FrameCode::kMirror;
        next.mirror_center[static_cast<std::size_t>(i)] = fw.word(i, 0.0);
      }
      consumed = true;
      break;
    default:
      return false;
  }
  program_frame.write() = next;
  return consumed;
}

// Targets of X Y Z through polar coordinates and the frame (the other axes
// are left to axis_targets). Under rotation a move of X alone moves Y too.
Flow<void> Interpreter::Impl::frame_targets(const Words& words, AxisVec& target, AxisMask& moved) {
  const std::array<int, 3> xyz{axis_of_letter['X' - 'A'], axis_of_letter['Y' - 'A'],
                               axis_of_letter['Z' - 'A']};
  xform::Point here_work{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (xyz[i] >= 0) here_work[i] = work_of(xyz[i], pos[xyz[i]]);
  }
  const xform::Point here = xform::to_program(frame(), here_work);
  xform::Point p = here;
  const bool inc = modal.distance == Distance::kIncremental;
  std::array<bool, 3> named{};
  for (std::size_t i = 0; i < 3; ++i) {
    named[i] = xyz[i] >= 0 && words.has("XYZ"[i]);
  }
  if (frame_codes.polar && modal.plane == PlaneSel::kXY && (named[0] || named[1])) {
    // G16 (B-63944EN "Polar coordinate command"): X is the radius, Y the
    // angle. In G90 the centre is the work origin; in G91 the present
    // position, with the angle added to the last one.
    const std::array<double, 2> centre =
        inc ? std::array<double, 2>{here[0], here[1]} : std::array<double, 2>{0.0, 0.0};
    const double r0 = inc ? 0.0 : std::hypot(here[0], here[1]);
    const double radius = named[0] ? word_length(words.at('X')) : r0;
    const double a = named[1] ? word_length(words.at('Y')) : (inc ? 0.0 : frame_codes.polar_angle);
    const auto xy = xform::polar_to_xy(centre, radius, frame_codes.next_polar_angle(a, inc));
    p[0] = xy[0];
    p[1] = xy[1];
    named[0] = named[1] = true;
  } else {
    for (std::size_t i = 0; i < 2; ++i) {
      if (named[i]) {
        const double v = word_length(words.at("XYZ"[i]));
        p[i] = inc ? p[i] + v : v;
      }
    }
  }
  if (named[2]) {
    const double v = word_length(words.at('Z'));
    p[2] = inc ? p[2] + v : v;
  }
  if ((frame().rotating || frame().conversions() > 0) && (named[0] || named[1])) {
    named[0] = named[1] = true;
  }
  if (frame().tilted() && (named[0] || named[1] || named[2])) named = {true, true, true};
  const xform::Point w = xform::to_work(frame(), p);
  for (std::size_t i = 0; i < 3; ++i) {
    if (!named[i] || xyz[i] < 0) continue;
    target[xyz[i]] = machine_of(xyz[i], w[i]);
    moved.set(xyz[i]);
  }
  return {};
}

// Cutter radius compensation C on a mill (cutter_comp.hpp). The radius is
// the D offset (geometry + wear); D0 or an empty offset moves on the
// programmed path, as on the control.
Flow<crc::BlockMode> Interpreter::Impl::comp_mode(const BlockPlan& plan) const {
  crc::BlockMode m;
  m.side = modal.cutter == CutterComp::kLeft ? 1 : modal.cutter == CutterComp::kRight ? -1 : 0;
  if (modal.d > 0) {
    const auto& t = tools[static_cast<std::size_t>(modal.d)];
    m.radius = (t.radius_geometry + t.radius_wear) * offset_unit_mm(*this);
  }
  auto idx = [&](char c) { return axis_of_letter[static_cast<std::size_t>(c - 'A')]; };
  switch (modal.plane) {
    case PlaneSel::kXY:
      m.a0 = idx('X');
      m.a1 = idx('Y');
      break;
    case PlaneSel::kZX:
      m.a0 = idx('Z');
      m.a1 = idx('X');
      break;
    case PlaneSel::kYZ:
      m.a0 = idx('Y');
      m.a1 = idx('Z');
      break;
  }
  if (m.a0 < 0 || m.a1 < 0) {
    return fail(AlarmId::kIllegalPlaneAxis,
                "cutter compensation in a plane whose axes are not on this machine", loc(cur_col));
  }
  // 5003#0 SUP: start-up and cancel of type A (0) or B (1), FANUC parameter
  // manual (cutter compensation C).
  m.type_b = params.bit(config::param::kCompStartTypeB);
  // G28/G30 and G53 in offset mode: the vector is cancelled for the block's
  // moves and built again at the next move (FANUC operator's manual, cutter
  // compensation C, "reference position return / G53 in offset mode").
  m.suspend =
      plan.action == Action::kRefReturn || plan.action == Action::kRefReturn2 || plan.machine_coord;
  return m;
}

// A programmed feed the machine cannot give along a straight move (more than
// an axis's max_feed for its share of the move): the planner runs the move
// at the machine's limit, as a control clamps to its feed upper limit; the
// warning says to what. Arcs are not checked (their limit changes along them).
Flow<void> Interpreter::Impl::check_feeds(const AxisVec& start) {
  // A feed no axis's max_feed is below cannot be clamped: most blocks stop
  // here (this runs for every block).
  const double slowest = plain.slowest_feed;
  const AxisVec* from = &start;
  for (const canon::Stamped& c : block_buffer.cmds) {
    const AxisVec* to = nullptr;
    double f = 0.0;
    if (const auto* fd = std::get_if<canon::Feed>(&c.cmd)) {
      to = &fd->target;
      f = fd->feed_mm_per_min;
    } else if (const auto* sk = std::get_if<canon::Skip>(&c.cmd)) {
      to = &sk->target;
      f = sk->feed_mm_per_min;
    } else if (const auto* r = std::get_if<canon::Rapid>(&c.cmd)) {
      from = &r->target;
      continue;
    } else if (const auto* a = std::get_if<canon::Arc>(&c.cmd)) {
      from = &a->target;
      continue;
    } else {
      continue;
    }
    const AxisVec* prev = std::exchange(from, to);
    if (f <= slowest) continue;
    const AxisVec d = *to - *prev;
    const double len = norm(d, axis_count);
    if (!(len > 0.0) || !(f > 0.0)) continue;
    double limit = f;
    char axis = 0;
    for (int i = 0; i < axis_count; ++i) {
      const double u = std::fabs(d[i]) / len;
      if (u == 0.0) continue;
      const double l = mc.axes[static_cast<std::size_t>(i)].max_feed_mm_min / u;
      if (l < limit) {
        limit = l;
        axis = axis_letter[static_cast<std::size_t>(i)];
      }
    }
    if (axis == 0 || limit >= f * (1.0 - 1e-9)) continue;
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "F%g mm/min on this move is more than the %c axis's max_feed allows along it: "
                  "it runs at %.1f mm/min",
                  f, axis, limit);
    auto w = warn("feed_clamped", buf, loc(cur_col));
    if (!w) return w;
  }
  return {};
}

Flow<void> Interpreter::Impl::pass_block(const BlockPlan& plan, const AxisVec& start,
                                         CommandSink& out) {
  if (auto f = check_feeds(start); !f) return f;
  if (mc.lathe() || (modal.cutter == CutterComp::kOff && comp.idle())) {
    for (const canon::Stamped& c : block_buffer.cmds) out.emit(c);
    return {};
  }
  auto mode = comp_mode(plan);
  SKIPNC_TRY(mode);
  if (comp.idle()) comp.state.begin(start);
  // The block is a transaction: the compensator is changed only when the
  // whole block has gone through it.
  crc::Compensator next = comp.state;
  comp.out.clear();
  auto r = next.block(block_buffer.cmds, *mode, comp.out);
  if (!r) {
    Error e = r.error();
    if (e.loc.line == 0) e.loc = loc(cur_col);
    return std::unexpected(std::move(e));
  }
  if (const std::uint32_t broken = next.broke_lookahead(); broken != 0) {
    auto w = warn("comp_lookahead",
                  "cutter compensation: two or more blocks without a move in the offset plane "
                  "after line " +
                      std::to_string(broken) +
                      ": that move ends perpendicular to its end point, as on the control, and "
                      "the next move may overcut",
                  loc(cur_col));
    if (!w) return w;
  }
  comp.state = std::move(next);
  for (const canon::Stamped& c : comp.out) out.emit(c);
  return {};
}

// At a point where the interpreter waits for the machine (or at the end):
// what the compensator holds goes out, the held move ending perpendicular.
std::uint32_t Interpreter::Impl::flush_comp(CommandSink& out) {
  if (comp.idle()) return 0;
  return comp.flush(out);
}

Flow<void> Interpreter::Impl::refuse_under_comp(const char* what, SourceLoc where) const {
  if (mc.lathe() || modal.cutter == CutterComp::kOff) return {};
  return fail(AlarmId::kNotSimulated,
              std::string(what) + " with cutter radius compensation (" +
                  (modal.cutter == CutterComp::kLeft ? "G41" : "G42") +
                  ") active is not simulated by skipnc; cancel it with G40 first",
              where);
}

// Tool nose radius compensation (G41/G42 on a lathe, with the imaginary tool
// nose) is not simulated: a move under it with a nose radius other than 0 is
// refused in words instead of running on the programmed path.
Flow<void> Interpreter::Impl::check_nose_radius_comp(SourceLoc where) const {
  if (!mc.lathe() || modal.cutter == CutterComp::kOff) return {};
  const auto& t = tools[static_cast<std::size_t>(lathe_state.wear_offset())];
  const double r = t.radius_geometry + t.radius_wear;
  if (r == 0.0) return {};
  return fail(AlarmId::kNotSimulated,
              std::string(modal.cutter == CutterComp::kLeft ? "G41" : "G42") +
                  " tool nose radius compensation with a nose radius of " + std::to_string(r) +
                  " mm (offset " + std::to_string(lathe_state.wear_offset()) +
                  ") is not simulated by skipnc",
              where);
}

// G37 X_ / Y_ / Z_: rapid to gamma before the measuring position, then at the
// measurement feed until the measuring position reached signal of the axis,
// at most epsilon past it. finish_g37 checks the range and corrects the
// active H.
Flow<Step> Interpreter::Impl::g37_block(const Words& words, CommandSink& out) {
  const SourceLoc at = loc(cur_col);
  SKIPNC_TRY(refuse_under_comp("G37 automatic tool length measurement", at));
  if (words.has('H')) {
    return fail(AlarmId::kG37HCode, "H in a G37 block", loc(words.at('H').column));
  }
  int axis = -1;
  canon::SignalAddr signal{};
  for (const MeasureSignal& m : kMeasureSignals) {
    if (!words.has(m.axis) || axis_of_letter[static_cast<std::size_t>(m.axis - 'A')] < 0) continue;
    if (axis >= 0) return fail(AlarmId::kG37Axis, "G37 measures one axis only", at);
    axis = axis_of_letter[static_cast<std::size_t>(m.axis - 'A')];
    signal = m.addr;
  }
  if (axis < 0) {
    return fail(AlarmId::kG37Axis, "G37 needs one of X, Y, Z (the measuring position)", at);
  }
  for (int i = 0; i < axis_count; ++i) {
    const char c = axis_letter[static_cast<std::size_t>(i)];
    if (i != axis && words.has(c)) return fail(AlarmId::kG37Axis, "G37 measures one axis only", at);
  }
  if (modal.h == 0 || modal.length == LengthComp::kOff) {
    return fail(AlarmId::kG37NoOffset, "G37 without an active tool length offset (G43 H..)", at);
  }
  AxisVec target;
  AxisMask moved;
  auto t = axis_targets(words, false, target, moved);
  SKIPNC_TRY(t);
  const double dir = target[axis] > pos[axis] ? 1.0 : -1.0;
  if (target[axis] == pos[axis]) {
    return fail(AlarmId::kG37Axis, "G37 from the measuring position itself", at);
  }
  const double gamma = params.get(kG37GammaParam);
  const double epsilon = params.get(ToolMeasurement::kEpsilonParam);
  const double feed = params.get(kG37FeedParam);
  if (!(feed > 0.0)) return fail(AlarmId::kNoFeed, "G37 feed (parameter 6241) is 0", at);
  AxisVec approach = pos;
  approach[axis] = target[axis] - dir * gamma;
  if (dir * (approach[axis] - pos[axis]) > 0.0) {
    emit(out, canon::Rapid{approach, block_params.linear_rapid});
    pos = approach;
  }
  canon::Skip sk;
  sk.target = pos;
  sk.target[axis] = target[axis] + dir * epsilon;
  sk.feed_mm_per_min = feed;
  canon::SkipSpec& spec = sk.spec;
  spec.kind = canon::SkipKind::kSkip;
  spec.inputs[0] = signal;
  spec.input_count = 1;
  spec.stop = canon::SkipStop::kImmediate;
  spec.latch = mc.latch;
  spec.latch_delay_s = mc.latch_delay_s;
  spec.servo_delay_comp = mc.servo_delay_comp;
  pending_skip = PendingSkip{};
  pending_skip.input_names[0] = config::signal_name(signal);
  SkipRecord& rec = pending_skip.record;
  rec.line = cur_line;
  std::string_view text = raw.text;
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
    text.remove_suffix(1);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) {
    text.remove_prefix(1);
  }
  rec.block = std::string(text);
  rec.code = "G37";
  rec.kind = spec.kind;
  pending_skip.target = sk.target;
  pending_skip.loc = at;
  g37.arm(axis, target[axis], epsilon, at);
  emit(out, sk);
  pos = sk.target;
  motion_since_sync = true;
  pending = Pending::kSkip;
  return Step::kSync;
}

// The signal must have come within epsilon of the measuring position.
Flow<double> ToolMeasurement::deviation(bool triggered, double latch_mm) const {
  if (!triggered) {
    return fail(AlarmId::kG37Signal,
                "the measuring position reached signal did not come within " +
                    std::to_string(epsilon_mm_) + " mm of the measuring position",
                at_);
  }
  const double diff_mm = latch_mm - target_mm_;
  if (std::fabs(diff_mm) > epsilon_mm_ + 1e-9) {
    return fail(AlarmId::kG37Signal,
                "the measuring position reached signal came " + std::to_string(std::fabs(diff_mm)) +
                    " mm before the measuring position (allowed: " + std::to_string(epsilon_mm_) +
                    " mm)",
                at_);
  }
  return diff_mm;
}

// The difference between where the signal came and the measuring position
// is added to the active H (its wear: the geometry stays as set), and the
// offset is applied again.
Flow<void> Interpreter::Impl::finish_g37(const SyncState& s) {
  const ToolMeasurement m = std::exchange(g37, ToolMeasurement{});
  auto dev = m.deviation(s.triggered, s.latch_machine[m.axis()]);
  SKIPNC_TRY(dev);
  const double diff_mm = *dev;
  auto& t = tools.write(static_cast<std::size_t>(modal.h));
  const double diff = diff_mm / offset_unit_mm(*this);  // stored numbers (offset_units.hpp)
  t.length_wear += modal.length == LengthComp::kMinus ? -diff : diff;
  Words none;
  return set_tool_length(none, modal.length);
}

namespace {

// The hole data of a canned cycle block (R Z Q P) into `d`; returns the
// repeats (K or L, else 1).
Flow<int> read_hole_data(const Interpreter::Impl& in, const Words& words, cycles::Data& d) {
  if (words.has('R')) {
    d.r = in.word_length(words.at('R'));
    d.have_r = true;
  }
  if (words.has('Z')) {
    d.z = in.word_length(words.at('Z'));
    d.have_z = true;
  }
  if (words.has('Q')) d.q = std::fabs(in.word_length(words.at('Q')));
  if (words.has('P')) {
    const WordVal& p = words.at('P');
    if (in.lang->rules.dwell_p_seconds) {
      d.p_ms = p.value * 1000.0;  // LinuxCNC: the dwell P is in seconds
    } else if (p.has_point) {
      // As G04 P: milliseconds, written without a decimal point (PS0007).
      return fail(AlarmId::kBadDecimalPoint,
                  "the dwell P of a canned cycle is in milliseconds, without decimal point",
                  in.loc(p.column));
    } else {
      d.p_ms = p.value;
    }
  }
  int repeats = 1;
  const char kw = words.has('K') ? 'K' : words.has('L') ? 'L' : 0;
  if (kw != 0) {
    const double k = words.at(kw).value;
    if (k != std::trunc(k) || k < 0 || k > 9999) {
      return fail(AlarmId::kBadValue,
                  std::string(1, kw) + std::to_string(k) + ": repeats are 0-9999",
                  in.loc(words.at(kw).column));
    }
    repeats = static_cast<int>(k);
  }
  return repeats;
}

// The moves of one hole, through the frame, as commands.
void emit_hole(Interpreter::Impl& in, const cycles::Hole& h, const AxisVec& base,
               CommandSink& out) {
  const int x = in.axis_of_letter['X' - 'A'], y = in.axis_of_letter['Y' - 'A'],
            z = in.axis_of_letter['Z' - 'A'];
  const bool linear = in.block_params.linear_rapid;
  const double feed = in.feed_mm_per_min();
  for (const cycles::Move& m : cycles::hole_moves(h)) {
    const xform::Point w = xform::to_work(in.frame(), m.to);
    AxisVec mp = base;
    if (x >= 0) mp[x] = in.machine_of(x, w[0]);
    if (y >= 0) mp[y] = in.machine_of(y, w[1]);
    mp[z] = in.machine_of(z, w[2]);
    switch (m.kind) {
      case cycles::MoveKind::kRapid:
        in.emit(out, canon::Rapid{mp, linear});
        in.pos = mp;
        break;
      case cycles::MoveKind::kFeed:
        in.emit(out, canon::Feed{mp, feed, false});
        in.pos = mp;
        break;
      case cycles::MoveKind::kDwell:
        in.emit(out, canon::Dwell{m.seconds});
        break;
      case cycles::MoveKind::kSpindle:
        in.emit(out, canon::Spindle{in.modal.spindle, m.spindle_dir});
        break;
      case cycles::MoveKind::kOrient:
        in.emit(out, canon::MCode{19});
        break;
    }
  }
  in.motion_since_sync = true;
}

// The hole of the block's position `target`, from the present position.
Flow<cycles::Hole> make_hole(const Interpreter::Impl& in, const Words& words,
                             const AxisVec& target) {
  const int x = in.axis_of_letter['X' - 'A'], y = in.axis_of_letter['Y' - 'A'],
            z = in.axis_of_letter['Z' - 'A'];
  auto program_point = [&](const AxisVec& m) {
    xform::Point w{x >= 0 ? in.work_of(x, m[x]) : 0.0, y >= 0 ? in.work_of(y, m[y]) : 0.0,
                   in.work_of(z, m[z])};
    return xform::to_program(in.frame(), w);
  };
  const cycles::Data& d = in.cycle_data;
  const ModalState& modal = in.modal;
  cycles::Hole h;
  h.kind = modal.cycle;
  h.ret = modal.ret;
  h.from = program_point(in.pos);
  const xform::Point hole = program_point(target);
  h.at = {hole[0], hole[1]};
  const cycles::Levels lv = cycles::resolve_levels(d, modal.distance == Distance::kIncremental);
  if (cycles::pecks(modal.cycle) && std::fabs(lv.bottom - lv.r) / d.q > kMaxPecks) {
    // A bound of skipnc's (the control has none): a Q far smaller than the
    // depth would make millions of moves from one block.
    return fail(AlarmId::kBadValue,
                "Q" + std::to_string(d.q) + " makes more than " +
                    std::to_string(static_cast<int>(kMaxPecks)) + " pecks in one hole",
                words.has('Q') ? in.loc(words.at('Q').column) : in.loc(in.cur_col));
  }
  h.initial = d.initial;
  h.r = lv.r;
  h.bottom = lv.bottom;
  h.q = d.q;
  h.dwell_s = cycles::uses_p(modal.cycle) ? d.p_ms / 1000.0 : 0.0;
  h.peck_clearance = in.params.get(modal.cycle == Cycle::kG73 ? 5114 : 5115) / in.unit_mm();
  h.shift_dir =
      cycles::shift_direction(static_cast<int>(in.params.get(config::param::kShiftDirection)) >> 4);
  h.spindle_dir = modal.spindle_dir != 0 ? modal.spindle_dir : 1;
  // LinuxCNC's levels (cycles.hpp): rise to the clearance level first,
  // G98 to the higher of R and the start, taps feeding out to it.
  h.linuxcnc_levels = in.lang->rules.cycle_levels_linuxcnc;
  return h;
}

}  // namespace

// One block in canned cycle mode: the hole data are updated from the block
// and each hole (K repeats) is drilled. The moves are made in the program
// frame and go through the frame (G68, G51, G51.1) like any move.
Flow<Step> Interpreter::Impl::canned_cycle(const Words& words, CommandSink& out) {
  const SourceLoc at = loc(cur_col);
  const int z = axis_of_letter['Z' - 'A'];
  if (z < 0) return fail(AlarmId::kIllegalPlaneAxis, "a canned cycle needs a Z axis", at);
  if (modal.plane != PlaneSel::kXY) {
    // The drilling axis is the plane's normal (Y in G18, X in G19); skipnc
    // drills along Z only, so it says so rather than drill the wrong way.
    return fail(AlarmId::kNotSimulated,
                "a canned cycle in the G18/G19 plane (drilling along Y or X) is not simulated "
                "by skipnc: G17 only",
                at);
  }
  cycles::Data& d = cycle_data;
  auto repeats = read_hole_data(*this, words, d);
  SKIPNC_TRY(repeats);
  if (cycles::pecks(modal.cycle) && !(d.q > 0.0)) {
    return fail(AlarmId::kCycleNoQ, "G73/G83 without a peck depth Q", at);
  }
  if (!d.have_z) return fail(AlarmId::kBadValue, "a canned cycle needs Z (point Z)", at);
  if (feed_mm_per_min() <= 0.0)
    return fail(AlarmId::kNoFeed, "canned cycle without a feed (F)", at);
  auto c = refuse_under_comp("a canned cycle", at);
  SKIPNC_TRY(c);
  // The hole's position: the block's axis words but Z (the hole data).
  Words position = words;
  position.erase('Z');
  for (int k = 0; k < *repeats; ++k) {
    AxisVec target;
    AxisMask moved;
    auto t = axis_targets(position, false, target, moved);
    SKIPNC_TRY(t);
    auto h = make_hole(*this, words, target);
    SKIPNC_TRY(h);
    // Other axes of the block (A, B, ...) are positioned with X and Y.
    emit_hole(*this, *h, target, out);
  }
  skip_state.last_cut_feed = modal.feed;
  return Step::kContinue;
}

}  // namespace skipnc::interp
