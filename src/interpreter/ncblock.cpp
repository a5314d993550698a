// Address words and modal groups. Order of execution inside one block
// (Fanuc): messages; G65 call; F S T; modal G codes (units first); data
// setting and coordinate shifts (G10 G52 G92); dwell; motion; M codes.
#include <algorithm>
#include <bit>
#include <cmath>

#include "interpreter/impl.hpp"

namespace skipnc::interp {
namespace {

enum class Group : std::uint8_t {
  kNone,
  k00,
  k01,
  k02,
  k03,
  k05,
  k06,
  k07,
  k08,
  k09,
  k10,
  k12,
  k14,
  k15
};

struct GDef {
  int code;  // x10
  Group group;
};

// The G codes this interpreter executes. Anything else is an improper G code.
constexpr GDef kGCodes[] = {
    {0, Group::k01},   {10, Group::k01},  {20, Group::k01},  {30, Group::k01},  {40, Group::k00},
    {90, Group::k00},  {100, Group::k00}, {170, Group::k02}, {180, Group::k02}, {190, Group::k02},
    {200, Group::k06}, {210, Group::k06}, {280, Group::k00}, {300, Group::k00}, {310, Group::k00},
    {400, Group::k07}, {410, Group::k07}, {420, Group::k07}, {430, Group::k08}, {440, Group::k08},
    {450, Group::k00}, {460, Group::k00}, {470, Group::k00}, {480, Group::k00}, {490, Group::k08},
    {520, Group::k00}, {530, Group::k00}, {540, Group::k14}, {550, Group::k14}, {560, Group::k14},
    {570, Group::k14}, {580, Group::k14}, {590, Group::k14}, {541, Group::k14}, {610, Group::k15},
    {640, Group::k15}, {650, Group::k00}, {660, Group::k12}, {670, Group::k12}, {800, Group::k09},
    {900, Group::k03}, {910, Group::k03}, {920, Group::k00}, {940, Group::k05}, {950, Group::k05},
    {980, Group::k10}, {990, Group::k10}, {500, Group::k00}, {960, Group::k02}, {970, Group::k02},
};

// G codes that G-code system A (a lathe) gives another meaning or does not
// have, with what to write instead. The turning cycles are not modelled.
const char* lathe_refusal(int code) {
  switch (code) {
    case 910:
      return " is not a code of G-code system A: U and W are the incremental X and Z";
    case 920:
      return " is the thread cutting cycle in G-code system A (not supported); G50 sets the "
             "coordinate system";
    case 940:
      return " is the end-face cutting cycle in G-code system A (not supported); G98 is feed per "
             "minute";
    case 950:
      return " is not a code of G-code system A: G99 is feed per revolution";
    case 430:
    case 440:
    case 490:
      return " is not a code of a lathe: the T code offsets the tool";
    case 450:
    case 460:
    case 470:
    case 480:
      return " is not a code of a lathe";
    default:
      return nullptr;
  }
}

Group group_of(int code) {
  for (const auto& d : kGCodes) {
    if (d.code == code) return d.group;
  }
  return Group::kNone;
}

std::string g_name(int code) {
  return "G" + std::to_string(code / 10) + (code % 10 ? "." + std::to_string(code % 10) : "");
}

}  // namespace

double Interpreter::Impl::word_length(const WordVal& w, bool rotary) const noexcept {
  (void)rotary;
  if (w.is_expr || w.has_point || params.bit(3401, 0)) return w.value;
  // Without a decimal point a length is in least input increments.
  const double increment = modal.units == Units::kInch ? 0.0001 : 0.001;
  return w.value * increment;
}

double Interpreter::Impl::offset_total(int axis) const noexcept {
  double o = work_offsets[0][axis] + work_offsets[static_cast<std::size_t>(modal.work)][axis] +
             local_shift[axis] + g92_shift[axis] + tool_pos_offset[axis] + lathe_tool_offset[axis];
  if (axis == length_axis) o += length_offset;
  return o;
}

double Interpreter::Impl::work_of(int axis, double machine_mm) const noexcept {
  return (machine_mm * axis_scale[static_cast<std::size_t>(axis)] - offset_total(axis)) / unit_mm();
}

double Interpreter::Impl::machine_of(int axis, double work_units) const noexcept {
  return (work_units * unit_mm() + offset_total(axis)) / axis_scale[static_cast<std::size_t>(axis)];
}

// Evaluates the words of an NC block. In a G65/G66 block every address but
// G, P and L is a macro argument (see collect_argument); elsewhere an
// address may appear once.
Result<void> Interpreter::Impl::collect_words(Words& words) {
  call_block = false;
  for (const gcode::Word& w : blk.words) {
    if (w.letter == 'G' && !w.is_expr && (w.value == 65.0 || w.value == 66.0)) {
      call_block = true;
      call_args.fill(Value::null());
      break;
    }
  }
  int ijk_set = -1, ijk_last = -1;
  for (const gcode::Word& w : blk.words) {
    WordVal v;
    v.column = w.column;
    v.has_point = w.has_point;
    v.is_expr = w.is_expr;
    if (w.is_expr) {
      // ROUND in an address rounds to the address's least input increment
      // (lengths: 0.001 mm, 0.0001 inch); elsewhere to a whole number.
      const bool length = axis_of_letter[static_cast<std::size_t>(w.letter - 'A')] >= 0 ||
                          (mc.lathe() && (w.letter == 'U' || w.letter == 'W')) || w.letter == 'I' ||
                          w.letter == 'J' || w.letter == 'K' || w.letter == 'R' || w.letter == 'Q';
      const double word_inc = modal.units == Units::kInch ? 0.0001 : 0.001;
      word_round_increment = length ? word_inc : 0.0;
      auto e = eval(w.expr);
      word_round_increment = 0.0;
      if (!e) return std::unexpected(e.error());
      if (e->vacant) continue;  // a vacant variable in a word: the word is omitted
      if (!std::isfinite(e->v)) {
        return fail(AlarmId::kOverflow, std::string("value of ") + w.letter + " is not finite",
                    loc(w.column));
      }
      v.value = e->v;
      // A computed length is rounded to the address's least input increment,
      // as the control does (#1 = 12.3456, X#1 -> X12.346); macro arguments
      // keep their value.
      if (length && !call_block) {
        v.value = std::round(v.value / word_inc) * word_inc + 0.0;
      }
    } else {
      v.value = w.value;
    }
    if (call_block && w.letter != 'G' && w.letter != 'P' && w.letter != 'L') {
      auto a = collect_argument(w, v, ijk_set, ijk_last);
      if (!a) return a;
      continue;
    }
    if (w.letter == 'G') {
      if (words.g_count == static_cast<int>(words.g.size())) {
        return fail(AlarmId::kGCodeConflict, "too many G codes in one block", loc(w.column));
      }
      const double code10 = std::round(v.value * 10.0);
      if (std::fabs(v.value * 10.0 - code10) > 1e-6 || code10 < 0 || code10 > 9999) {
        return fail(AlarmId::kUnknownGCode, "G" + std::to_string(v.value), loc(w.column));
      }
      words.g[static_cast<std::size_t>(words.g_count)] = static_cast<int>(code10);
      words.g_col[static_cast<std::size_t>(words.g_count++)] = w.column;
      continue;
    }
    if (w.letter == 'M') {
      if (words.m_count == 3) {
        return fail(AlarmId::kTooManyMCodes, "more than 3 M codes in one block", loc(w.column));
      }
      // A value in brackets is rounded (M[3.5] is M4); a literal must be whole.
      const double m = w.is_expr ? std::round(v.value) : v.value;
      if (m != std::trunc(m) || m < 0 || m > 99999999) {
        return fail(AlarmId::kUnknownMCode, "M" + std::to_string(v.value), loc(w.column));
      }
      words.m[static_cast<std::size_t>(words.m_count++)] = static_cast<int>(m);
      continue;
    }
    auto& slot = words.slot(w.letter);
    if (slot) {
      return fail(AlarmId::kWordRepeated,
                  std::string("address ") + w.letter + " twice in one block", loc(w.column));
    }
    slot = v;
    words.letters |= 1u << (w.letter - 'A');
  }
  return {};
}

Result<void> Interpreter::Impl::set_tool_length(const Words& words, LengthComp mode) {
  if (mode == LengthComp::kOff) {
    length_offset = 0.0;
    modal.h = 0;
    return {};
  }
  int h = modal.h;
  if (words.has('H')) {
    const double v = words.at('H').value;
    if (v != std::trunc(v) || v < 0 || v > mc.tool_offset_count) {
      return fail(AlarmId::kIllegalOffsetNumber, "H" + std::to_string(v),
                  loc(words.at('H').column));
    }
    h = static_cast<int>(v);
  }
  modal.h = h;
  const auto& t = tools[static_cast<std::size_t>(h)];
  const double len = h == 0 ? 0.0 : t.length_geometry + t.length_wear;
  length_offset = mode == LengthComp::kPlus ? len : -len;
  return {};
}

// G10: programmable data input. L2 Pn: work offset n (0 = EXT, 1-6 = G54-G59);
// L20 Pn: G54.1 Pn (1-300); L10/L11: H geometry/wear; L12/L13: D
// geometry/wear; L1: H wear (memory A). G90 sets, G91 adds.
Result<void> Interpreter::Impl::data_setting(const Words& words, SourceLoc where) {
  if (mc.lathe() && !words.has('L')) return lathe_offset_setting(words, where);
  if (!words.has('L')) return fail(AlarmId::kBadValue, "G10 needs L", where);
  const int l = static_cast<int>(words.at('L').value);
  const bool inc = modal.distance == Distance::kIncremental;
  if (!words.has('P')) return fail(AlarmId::kBadValue, "G10 needs P", where);
  const double pv = words.at('P').value;
  if (l == 2 || l == 20) {
    const double lo = l == 2 ? 0 : 1;
    const double hi = l == 2 ? 6 : kExtraWorkSystems;
    if (pv != std::trunc(pv) || pv < lo || pv > hi) {
      return fail(AlarmId::kIllegalOffsetNumber,
                  "G10 L" + std::to_string(l) + " P" + std::to_string(pv) +
                      (l == 2 ? ": work offsets are P0 (EXT) and P1-P6 (G54-G59)"
                              : ": G54.1 work offsets are P1-P300"),
                  loc(words.at('P').column));
    }
    const int set = static_cast<int>(pv) + (l == 20 ? 6 : 0);
    AxisVec& o = work_offsets[static_cast<std::size_t>(set)];
    for (int i = 0; i < axis_count; ++i) {
      const char c = axis_letter[static_cast<std::size_t>(i)];
      if (!words.has(c)) continue;
      const double mm = word_length(words.at(c), false) * unit_mm();
      o[i] = inc ? o[i] + mm : mm;
    }
    return {};
  }
  if (l == 1 || (l >= 10 && l <= 13)) {
    if (pv != std::trunc(pv) || pv < 1 || pv > mc.tool_offset_count) {
      return fail(AlarmId::kIllegalOffsetNumber, "G10 P" + std::to_string(pv),
                  loc(words.at('P').column));
    }
    if (!words.has('R'))
      return fail(AlarmId::kBadValue, "G10 L" + std::to_string(l) + " needs R", where);
    auto& t = tools[static_cast<std::size_t>(pv)];
    double* f = l == 10             ? &t.length_geometry
                : l == 11 || l == 1 ? &t.length_wear
                : l == 12           ? &t.radius_geometry
                                    : &t.radius_wear;
    const double mm = word_length(words.at('R'), false) * unit_mm();
    *f = inc ? *f + mm : mm;
    return {};
  }
  return fail(AlarmId::kBadValue, "G10 L" + std::to_string(l) + " is not supported", where);
}

Result<Step> Interpreter::Impl::execute_nc(const Words& words, CommandSink& out) {
  for (const auto& c : blk.comments) {
    const std::string& t = blk.names[static_cast<std::size_t>(c.text)];
    if (t.size() >= 4 && t.compare(0, 4, "MSG,") == 0) messages.push_back(t.substr(4));
  }
  if (blk.has_n) modal.seq = static_cast<int>(blk.n % 100000000);

  // Classify the G codes.
  bool g65 = false, g31 = false, g53 = false, g04 = false, g10 = false, g28 = false, g52 = false,
       g92 = false, g50 = false;
  int g45 = 0;
  ModalState next = modal;
  std::optional<Motion> motion_code;
  MillRequest mill;  // mill_codes.cpp: cycles, frames, codes without effect
  for (int i = 0; i < words.g_count; ++i) {
    const int code = words.g[static_cast<std::size_t>(i)];
    const Group grp = group_of(code);
    const SourceLoc at = loc(words.g_col[static_cast<std::size_t>(i)]);
    if (grp == Group::kNone) {
      auto known = mill_code(code, at, mill);
      if (!known) return std::unexpected(known.error());
      if (!*known) return fail(AlarmId::kUnknownGCode, g_name(code), at);
      continue;
    }
    if (mc.lathe()) {
      if (const char* why = lathe_refusal(code))
        return fail(AlarmId::kUnknownGCode, g_name(code) + why, at);
      if (code == 900) {
        motion_code = Motion::kTurningCycle;  // system A: G90 is a cycle, not absolute mode
        continue;
      }
      if (code == 980 || code == 990) {
        next.feed_mode = code == 980 ? FeedMode::kPerMinute : FeedMode::kPerRev;
        continue;
      }
    } else if (code == 500) {
      auto known = mill_code(code, at, mill);  // G50 of the mill: scaling cancel
      if (!known) return std::unexpected(known.error());
      continue;
    } else if (code == 960 || code == 970) {
      return fail(AlarmId::kUnknownGCode,
                  g_name(code) + " is a code of the lathe (G-code system A) only", at);
    }
    switch (code) {
      case 0:
        motion_code = Motion::kRapid;
        break;
      case 10:
        motion_code = Motion::kLinear;
        break;
      case 20:
        motion_code = Motion::kCwArc;
        break;
      case 30:
        motion_code = Motion::kCcwArc;
        break;
      case 40:
        g04 = true;
        break;
      case 90:  // G09: exact stop for this block only, read by motion() (motion.cpp)
        break;
      case 100:
        g10 = true;
        break;
      case 170:
        next.plane = PlaneSel::kXY;
        break;
      case 180:
        next.plane = PlaneSel::kZX;
        break;
      case 190:
        next.plane = PlaneSel::kYZ;
        break;
      case 200:
        next.units = Units::kInch;
        break;
      case 210:
        next.units = Units::kMetric;
        break;
      case 280:
        g28 = true;
        break;
      case 300:
        g28 = true;
        break;
      case 310:
        g31 = true;
        break;
      case 400:
        next.cutter = CutterComp::kOff;
        break;
      case 410:
        next.cutter = CutterComp::kLeft;
        break;
      case 420:
        next.cutter = CutterComp::kRight;
        break;
      case 430:
        next.length = LengthComp::kPlus;
        break;
      case 440:
        next.length = LengthComp::kMinus;
        break;
      case 490:
        next.length = LengthComp::kOff;
        break;
      case 450:
      case 460:
      case 470:
      case 480:
        if (!dialect.sw.tool_position_offset) {
          return fail(AlarmId::kUnknownGCode,
                      g_name(code) + " (tool position offset) is not a code of this control", at);
        }
        g45 = code / 10;
        break;
      case 500:
        g50 = true;
        break;
      case 520:
        g52 = true;
        break;
      case 530:
        g53 = true;
        break;
      case 540:
      case 550:
      case 560:
      case 570:
      case 580:
      case 590:
        next.work = (code - 530) / 10;
        break;
      case 541: {
        // G54.1 Pn: additional work coordinate system n (1-300), after EXT
        // and G54-G59 in work_offsets. P omitted: P1.
        const double pn = words.has('P') ? words.at('P').value : 1.0;
        if (pn != std::trunc(pn) || pn < 1 || pn > kExtraWorkSystems) {
          return fail(AlarmId::kIllegalOffsetNumber, "G54.1 P" + std::to_string(pn) + ": P1-P300",
                      words.has('P') ? loc(words.at('P').column) : at);
        }
        next.work = 6 + static_cast<int>(pn);
        break;
      }
      case 610:
        next.path = PathMode::kExactStop;
        break;
      case 640:
        next.path = PathMode::kContinuous;
        break;
      case 650:
        g65 = true;
        break;
      case 660:
        next.modal_macro = true;
        break;
      case 670:
        next.modal_macro = false;
        break;
      case 800:
        next.cycle = Cycle::kNone;
        break;
      case 900:
        next.distance = Distance::kAbsolute;
        break;
      case 910:
        next.distance = Distance::kIncremental;
        break;
      case 920:
        g92 = true;
        break;
      case 960:
        next.spindle_mode = SpindleMode::kSurfaceSpeed;
        break;
      case 970:
        next.spindle_mode = SpindleMode::kRpm;
        break;
      case 940:
        next.feed_mode = FeedMode::kPerMinute;
        break;
      case 950:
        next.feed_mode = FeedMode::kPerRev;
        break;
      case 980:
        next.ret = ReturnLevel::kInitial;
        break;
      case 990:
        next.ret = ReturnLevel::kR;
        break;
      default:
        return fail(AlarmId::kUnknownGCode, g_name(code), at);
    }
  }
  skip_step = mill.skip_step;  // G31.1-G31.3: a G31 (skip.cpp)
  if (skip_step != 0) g31 = true;
  const SourceLoc block_loc = loc(cur_col);

  // G65 / G66: every other word is an argument (collected in block order by
  // collect_words); G66 runs the macro after each later block that moves,
  // until G67. A second G66 replaces the first (nested modal calls are not
  // modelled).
  const bool g66 = words.has_g(660);
  if (g65 || g66) {
    if (!call_block) {
      return fail(AlarmId::kMacroFormat, "G65/G66 must be written as a number (G65, not G#i)",
                  block_loc);
    }
    if (words.g_count > 1) {
      for (int i = 0; i < words.g_count; ++i) {
        const int code = words.g[static_cast<std::size_t>(i)];
        if (code != 650 && code != 660) {
          return fail(AlarmId::kIllegalArgumentAddress,
                      g_name(code) + " in a G65/G66 block: G cannot be an argument",
                      loc(words.g_col[static_cast<std::size_t>(i)]));
        }
      }
    }
    if (!words.has('P')) {
      return fail(AlarmId::kProgramNotFound,
                  g65 ? "G65 needs P (program number)" : "G66 needs P (program number)", block_loc);
    }
    const double p = words.at('P').value;
    double l = 1.0;
    if (words.has('L')) l = words.at('L').value;
    if (p != std::trunc(p) || p < 1 || p > 99999999) {
      return fail(AlarmId::kProgramNotFound, "P" + std::to_string(p) + " is not a program number",
                  loc(words.at('P').column));
    }
    if (l != std::trunc(l) || l < 0 || l > 9999) {
      return fail(AlarmId::kBadValue, "L" + std::to_string(l) + ": repetitions are 0-9999",
                  loc(words.at('L').column));
    }
    const auto repeats = static_cast<int>(l);
    if (g65) {
      if (repeats == 0) return Step::kContinue;
      auto c = macro_call(static_cast<std::int64_t>(p), repeats, false, block_loc);
      if (!c) return std::unexpected(c.error());
      return Step::kContinue;
    }
    modal_macro_program = static_cast<std::int64_t>(p);
    modal_macro_args = call_args;
    modal.modal_macro = true;
    return Step::kContinue;
  }

  // Addresses that mean nothing here are refused, so a typo is not ignored.
  for (std::uint32_t rest = words.letters & ~axis_letters; rest != 0; rest &= rest - 1) {
    const char letter = static_cast<char>('A' + std::countr_zero(rest));
    if (mc.lathe() && (letter == 'U' || letter == 'W')) continue;
    if (mc.lathe() && letter == 'H' && axis_of_letter['C' - 'A'] < 0) {
      // H is the incremental C of system A; a lathe has no tool length offset.
      return fail(AlarmId::kIllegalAddress, "address H (incremental C) on a lathe without a C axis",
                  loc(words.at(letter).column));
    }
    if (std::string_view("FSTHDPQRKLIJE").find(letter) != std::string_view::npos) continue;
    return fail(AlarmId::kIllegalAddress,
                std::string("address ") + letter + " is not an address of this machine",
                loc(words.at(letter).column));
  }

  // F S T
  if (words.has('E')) last_e = words.at('E').value;
  if (words.has('F')) {
    const double f = words.at('F').value;
    if (f < 0) return fail(AlarmId::kBadValue, "negative F", loc(words.at('F').column));
    if (!(g31 && dialect.sw.skip_feed == config::SkipFeedRule::kBlockOrParam)) next.feed = f;
  }
  bool spindle_changed = next.spindle_mode != modal.spindle_mode;
  if (words.has('S')) {
    const WordVal& sw = words.at('S');
    if (mc.lathe()) {
      if (sw.value < 0) return fail(AlarmId::kBadValue, "negative S", loc(sw.column));
      if (g50) {
        next.spindle_clamp_rpm = sw.value;  // G50 S: the G96 speed limit
      } else {
        next.spindle = sw.value;
        spindle_changed = true;
      }
    } else {
      next.spindle = sw.value;
      emit(out, canon::Spindle{next.spindle, 0});
    }
  }
  if (words.has('T') && !mc.lathe()) {
    next.tool = static_cast<int>(words.at('T').value);
    emit(out, canon::ToolSelect{next.tool});
  }
  if (words.has('D')) {
    const double d = words.at('D').value;
    if (d != std::trunc(d) || d < 0 || d > mc.tool_offset_count) {
      return fail(AlarmId::kIllegalOffsetNumber, "D" + std::to_string(d),
                  loc(words.at('D').column));
    }
    next.d = static_cast<int>(d);
  }
  if (next.plane != modal.plane && modal.cutter != CutterComp::kOff) {
    return fail(AlarmId::kPlaneChangeInComp, "plane change with G41/G42 active", block_loc);
  }
  if (motion_code) next.motion = *motion_code;
  // Group 09: a cycle code sets it; G80 and any group-01 code end it.
  if (motion_code && !mc.lathe()) next.cycle = Cycle::kNone;
  if (mill.cycle) next.cycle = *mill.cycle;

  // Commit the modal part of the block: from here on the block's words are
  // interpreted in its own modes (G20/G21, G90/G91, G54...).
  const ModalState before = modal;
  modal = next;
  auto undo = [&](Error e) -> Result<Step> {
    modal = before;
    return std::unexpected(std::move(e));
  };
  if (modal.length != before.length || (words.has('H') && modal.length != LengthComp::kOff)) {
    auto r = set_tool_length(words, modal.length);
    if (!r) return undo(r.error());
  }
  if (words.has('T') && mc.lathe()) {
    auto r = lathe_tool(words, modal);
    if (!r) return undo(r.error());
    emit(out, canon::ToolSelect{modal.tool / 100});
  }
  for (int i = 0; i < words.m_count; ++i) {
    const int m = words.m[static_cast<std::size_t>(i)];
    if (m != 3 && m != 4 && m != 5) continue;
    modal.spindle_dir = m == 3 ? 1 : m == 4 ? -1 : 0;
    if (mc.lathe()) {
      spindle_changed = true;
    } else {
      emit(out, canon::Spindle{modal.spindle, modal.spindle_dir});
    }
  }
  if (spindle_changed) emit_spindle(out);

  if (modal.cycle != Cycle::kNone && before.cycle == Cycle::kNone) {
    // A new cycle mode: the initial level is the present Z (B-63944EN 5.1).
    cycle_data = cycles::Data{};
    const int z = axis_of_letter['Z' - 'A'];
    if (z >= 0) {
      const int x = axis_of_letter['X' - 'A'], y = axis_of_letter['Y' - 'A'];
      cycle_data.initial =
          xform::to_program(frame, {x >= 0 ? work_of(x, pos[x]) : 0.0,
                                    y >= 0 ? work_of(y, pos[y]) : 0.0, work_of(z, pos[z])})[2];
    }
  }
  bool frame_block = false;  // G68 G51 G51.1: the axis words are the mode's data
  if (mill.frame_code != 0) {
    auto r = apply_frame_code(words, mill);
    if (!r) return undo(r.error());
    frame_block = *r;
  }
  bool moved = false;
  if (frame_block) {
    // G68 X Y R, G51 X Y Z P, G51.1 X Y: centres and factors, no move.
  } else if (mill.g37) {
    auto m = g37_block(words, out);  // mill_codes.cpp
    if (!m) return undo(m.error());
    return *m;
  } else if (g10) {
    auto r = data_setting(words, block_loc);
    if (!r) return undo(r.error());
  } else if (g50) {
    auto r = lathe_coordinate_setting(words);
    if (!r) return undo(r.error());
  } else if (g52 || g92) {
    for (int i = 0; i < axis_count; ++i) {
      const char c = axis_letter[static_cast<std::size_t>(i)];
      if (!words.has(c)) continue;
      const double v = word_length(words.at(c), false) * unit_mm();
      if (g52) {
        local_shift[i] = v;
      } else {
        // G92: the current position becomes v in the work system.
        g92_shift[i] = 0.0;
        g92_shift[i] = pos[i] * axis_scale[static_cast<std::size_t>(i)] - v - offset_total(i);
      }
    }
  } else if (g04) {
    auto r = dwell(words, out);
    if (!r) return undo(r.error());
  } else if (g28) {
    auto r = reference_return(words, 28, out);
    if (!r) return undo(r.error());
    moved = true;
  } else {
    const bool any_axis = has_axis_word(words);
    const bool arc_words =
        modal.motion == Motion::kCwArc || modal.motion == Motion::kCcwArc
            ? (words.has('I') || words.has('J') || words.has('K') || words.has('R'))
            : false;
    if (modal.cycle != Cycle::kNone && !g31 && (any_axis || words.has('R'))) {
      auto m = canned_cycle(words, out);
      if (!m) return undo(m.error());
      moved = true;
    } else if (g31 || any_axis || arc_words || g45 != 0) {
      if (g45 != 0) {
        // G45-G48: the move is extended (G45, G47) or shortened (G46, G48)
        // by the D offset; G47/G48 by twice the offset. The direction is
        // that of the programmed move (from the previous programmed point in
        // G90; a zero move counts as positive). The shift stays with the
        // axis: later positions and #5061.. are in programmed coordinates.
        const auto& t = tools[static_cast<std::size_t>(modal.d)];
        const double r = modal.d == 0 ? 0.0 : t.radius_geometry + t.radius_wear;
        const double k = (g45 == 45 ? 1.0 : g45 == 46 ? -1.0 : g45 == 47 ? 2.0 : -2.0) * r;
        const bool inc = modal.distance == Distance::kIncremental;
        for (int i = 0; i < axis_count; ++i) {
          const char c = axis_letter[static_cast<std::size_t>(i)];
          if (!words.has(c)) continue;
          const double v = word_length(words.at(c), false);
          const double dist = inc ? v : v - work_of(i, pos[i]);
          const double shift = (dist < 0.0 ? -1.0 : 1.0) * k;
          tool_pos_offset[i] += shift;
          if (inc) g45_delta[i] = shift;
        }
      }
      if (!g31) {
        auto c = check_cutter_comp(block_loc);
        if (!c) return undo(c.error());
      }
      auto m = motion(words, out, g31, g53);
      if (!m) return undo(m.error());
      if (*m == Step::kSync) return Step::kSync;
      moved = true;
    }
  }
  // M codes after the motion.
  for (int i = 0; i < words.m_count; ++i) {
    const int m = words.m[static_cast<std::size_t>(i)];
    modal.last_m = m;
    switch (m) {
      case 0:
        emit(out, canon::Stop{canon::StopKind::kProgramStop});
        break;
      case 1:
        emit(out, canon::Stop{canon::StopKind::kOptionalStop});
        break;
      case 2:
      case 30:
        emit(out, canon::Stop{m == 2 ? canon::StopKind::kProgramEnd : canon::StopKind::kRewindEnd});
        ++parts_count;
        ended = true;
        return Step::kEnd;
      case 98: {
        if (!words.has('P')) return fail(AlarmId::kProgramNotFound, "M98 needs P", block_loc);
        const double p = words.at('P').value;
        if (p != std::trunc(p) || p < 1 || p > 99999999) {
          return fail(AlarmId::kProgramNotFound, "M98 P" + std::to_string(p),
                      loc(words.at('P').column));
        }
        auto program = static_cast<std::int64_t>(p);
        int repeats = 1;
        if (words.has('L')) {
          repeats = static_cast<int>(words.at('L').value);
        } else if (program > 9999) {
          // M98 Pxxxxyyyy: the first digits repeat, the last four name the program.
          repeats = static_cast<int>(program / 10000);
          program %= 10000;
        }
        if (repeats < 1) return Step::kContinue;
        auto c = call(program, repeats, false, block_loc);
        if (!c) return std::unexpected(c.error());
        return Step::kContinue;
      }
      case 99: {
        std::optional<std::int64_t> label;
        if (words.has('P')) {
          const double pv = std::round(words.at('P').value);
          if (pv < 1 || pv > 99999) {
            return fail(
                AlarmId::kIllegalSequenceNumber,
                "M99 P" + std::to_string(words.at('P').value) + ": sequence numbers are 1 to 99999",
                loc(words.at('P').column));
          }
          label = static_cast<std::int64_t>(pv);
        }
        return return_from_sub(label, block_loc);
      }
      case 3:
      case 4:
      case 5:
        break;
      default:
        emit(out, canon::MCode{m});
        break;
    }
  }

  // G66: the modal macro runs after each block that moved, but not for the
  // moves of the macro it calls (nor of what that macro calls).
  if (moved && modal.modal_macro && modal_macro_program != 0 && !in_modal_call()) {
    auto c = macro_call(modal_macro_program, 1, true, block_loc);
    if (!c) return std::unexpected(c.error());
  }
  return Step::kContinue;
}

void Interpreter::Impl::emit(CommandSink& out, canon::Command cmd) {
  out.emit(canon::Stamped{std::move(cmd), cur_line});
}

}  // namespace skipnc::interp
