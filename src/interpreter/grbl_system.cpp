// grbl's '$' system lines (docs/languages.md, "grbl's $ lines"), after
// grbl 1.1's "Grbl v1.1 Commands", "Grbl v1.1 Jogging" and "Grbl v1.1
// Configuration" (gnea/grbl doc/markdown/commands.md, jogging.md,
// settings.md) and its system.c: what each line answers goes to the run's
// messages, one line each, as grbl prints them (the `ok` that follows every
// accepted line is not repeated there). A line grbl runs only at rest
// (everything but `$`, `$G`) waits for the motion queued before it, as a
// sender waits for Idle before it sends one (grbl itself answers error:8 to
// `$H`, `$#`, `$n=` while a cycle runs).
//   $        the help line            $$   the settings, `$n=value`
//   $#       [G54:..]..[PRB:..:1]     $G   [GC:...] the parser's modes
//   $I       [VER:..] [OPT:..]        $N   the startup lines (kept, not run)
//   $X       unlock ($22 = 1 starts the run in alarm)
//   $H       homing: Z, then X and Y, to the switch at the axis's top end and
//            back by $27 (grbl's default: machine position -$27 at the end)
//   $J=...   a G1 in the jog's own modes; the program's modes stay
//   $n=v     a setting: $6 probe invert, $13 inches in reports, $22 homing,
//            $24/$25/$27 homing, $110-$112 rate and $120-$122 acceleration of
//            the axis from the next move on; the others are kept and listed
// $C (check mode), $SLP (sleep) and $RST= are refused by name (not simulated).
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <string>

#include "interpreter/impl.hpp"

namespace skipnc::interp {

namespace {

bool whole(double v) {
  return v == std::trunc(v) && std::fabs(v) < 1e9;
}

std::string setting_text(double v, bool integer) {
  return integer && whole(v) ? fmt::format("{}", static_cast<long long>(v))
                             : fmt::format("{:.3f}", v + 0.0);
}

const config::ParamDef* def_of(const config::Dialect& d, int n) {
  for (const auto& p : d.params) {
    if (p.number == n) return &p;
  }
  return nullptr;
}

}  // namespace

// The settings grbl starts with: the dialect's table (the machine file's
// [parameters] applied), and the axes' rate, acceleration and travel.
void Interpreter::Impl::grbl_start() {
  for (const auto& p : dialect.params) {
    if (p.number < 1000) grbl_system().settings[p.number] = params.get(p.number);
  }
  for (int i = 0; i < axis_count && i < 10; ++i) {
    const auto& a = mc.axes[static_cast<std::size_t>(i)];
    grbl_system().settings[110 + i] = a.rapid_mm_min;
    grbl_system().settings[120 + i] = a.accel_mm_s2;
    grbl_system().settings[130 + i] = a.max_mm - a.min_mm;
  }
  grbl_system().locked = grbl_setting(22) != 0.0;
  if (grbl_system().locked) add_message("[MSG:'$H'|'$X' to unlock]");
}

double Interpreter::Impl::grbl_setting(int n) const noexcept {
  const auto it = grbl_system().settings.find(n);
  return it != grbl_system().settings.end() ? it->second : 0.0;
}

bool Interpreter::Impl::probe_inverted() const noexcept {
  const int n = dialect.sw.probe_invert_param;
  if (n == 0) return false;
  return lang->probe_inverted(*this, n);  // a parameter bit, or grbl's $6
}

// Machine (or offset) values as grbl prints them: mm with 3 decimals, or
// inches with 4 with $13 = 1 ("report in inches"; grbl's internal unit is mm).
std::string Interpreter::Impl::grbl_coords(const AxisVec& mm) const {
  const bool inch = (static_cast<long long>(grbl_setting(13)) & 1) != 0;
  std::string s;
  for (int i = 0; i < axis_count; ++i) {
    if (i > 0) s += ',';
    s += inch ? fmt::format("{:.4f}", mm[i] / 25.4 + 0.0) : fmt::format("{:.3f}", mm[i] + 0.0);
  }
  return s;
}

Flow<Step> Interpreter::Impl::execute_grbl_system(CommandSink& out) {
  const std::string& text = blk.names[static_cast<std::size_t>(blk.stmt.label)];
  if (blk.stmt.kind == gcode::StmtKind::kGrblJog) {
    if (motion_since_sync) return need_sync();
    return grbl_jog(out);
  }
  if (text.empty()) {
    add_message("[HLP:$$ $# $G $I $N $x=val $Nx=line $J=line $SLP $C $X $H ~ ! ? ctrl-x]");
    return Step::kContinue;
  }
  if (text == "G") {
    grbl_modal_line();
    return Step::kContinue;
  }
  if (motion_since_sync) return need_sync();  // grbl: at rest (Idle) only
  if (text == "X") {
    if (grbl_system().locked) add_message("[MSG:Caution: Unlocked]");
    grbl_system().locked = false;  // not in alarm: no effect
    return Step::kContinue;
  }
  if (text == "H") return grbl_home(out);
  if (text == "C" || text == "SLP" || text.starts_with("RST=")) {
    return fail(AlarmId::kNotSimulated,
                "$" + text +
                    (text == "C"     ? " (check mode)"
                     : text == "SLP" ? " (sleep)"
                                     : "") +
                    " is not simulated",
                loc(blk.stmt.column));
  }
  if (!text.empty() && (text[0] >= '0' && text[0] <= '9')) return grbl_store_setting(text, out);
  return grbl_report(text);
}

// The lines that print: $$, $#, $I, $N, and storing $I= and $Nx=.
Flow<Step> Interpreter::Impl::grbl_report(const std::string& text) {
  if (text == "$") {
    grbl_list_settings();
  } else if (text == "#") {
    grbl_list_offsets();
  } else if (text == "I") {
    add_message("[VER:1.1h.20190825:" + grbl_system().build_info + "]");
    add_message("[OPT:V,15,128]");
  } else if (text.starts_with("I=")) {
    grbl_system().build_info = text.substr(2);
  } else if (text == "N") {
    for (std::size_t i = 0; i < grbl_system().startup.size(); ++i) {
      add_message(fmt::format("$N{}={}", i, grbl_system().startup[i]));
    }
  } else if (text.size() >= 3 && text[0] == 'N' && (text[1] == '0' || text[1] == '1') &&
             text[2] == '=') {
    grbl_system().startup[static_cast<std::size_t>(text[1] - '0')] = text.substr(3);
  } else {
    return fail(AlarmId::kGrblStatement, "$" + text + " is not a grbl system command",
                loc(blk.stmt.column));
  }
  return Step::kContinue;
}

void Interpreter::Impl::grbl_list_settings() {
  for (const auto& [n, v] : grbl_system().settings) {
    const config::ParamDef* d = def_of(dialect, n);
    const bool integer = d != nullptr ? d->kind != config::ParamKind::kReal : false;
    add_message(fmt::format("${}={}", n, setting_text(v, integer)));
  }
}

// $#: the work offsets G54-G59, the G28 and G30 positions (#5161.., #5181..,
// kept in mm), G92, the tool length offset and the last probe.
void Interpreter::Impl::grbl_list_offsets() {
  for (int set = 1; set <= 6; ++set) {
    add_message(fmt::format("[G{}:{}]", 53 + set,
                            grbl_coords(work_offsets[static_cast<std::size_t>(set)])));
  }
  for (const int base : {5161, 5181}) {
    AxisVec p;
    for (int i = 0; i < axis_count; ++i) {
      const int j = ngc_axis_index(axis_letter[static_cast<std::size_t>(i)]);
      p[i] = j < 0 ? 0.0 : vars.ngc_param(base + j) * stored_mm();
    }
    add_message(fmt::format("[G{}:{}]", base == 5161 ? 28 : 30, grbl_coords(p)));
  }
  add_message("[G92:" + grbl_coords(shifts.get().g92_shift) + "]");
  const bool inch = (static_cast<long long>(grbl_setting(13)) & 1) != 0;
  add_message(inch ? fmt::format("[TLO:{:.4f}]", length_offset / 25.4 + 0.0)
                   : fmt::format("[TLO:{:.3f}]", length_offset + 0.0));
  add_message("[PRB:" + grbl_coords(grbl_system().prb) + (grbl_system().prb_ok ? ":1]" : ":0]"));
}

// $G: "[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]" (grbl 1.1's
// report_gcode_modes; F in mm/min, or inch/min with $13 = 1).
void Interpreter::Impl::grbl_modal_line() {
  std::string motion = "G0";
  switch (modal.motion) {
    case Motion::kLinear:
      motion = "G1";
      break;
    case Motion::kCwArc:
      motion = "G2";
      break;
    case Motion::kCcwArc:
      motion = "G3";
      break;
    case Motion::kProbe:
      motion = code_name(modal.probe);
      break;
    default:
      break;
  }
  const char* plane = modal.plane == PlaneSel::kXY   ? "G17"
                      : modal.plane == PlaneSel::kZX ? "G18"
                                                     : "G19";
  const bool inch = (static_cast<long long>(grbl_setting(13)) & 1) != 0;
  const double f_mm = modal.feed * unit_mm();
  add_message(fmt::format("[GC:{} G{} {} {} {} G94 {} M9 T{} F{} S{}]", motion, 53 + modal.work,
                          plane, modal.units == Units::kInch ? "G20" : "G21",
                          modal.distance == Distance::kIncremental ? "G91" : "G90",
                          modal.spindle_dir > 0   ? "M3"
                          : modal.spindle_dir < 0 ? "M4"
                                                  : "M5",
                          modal.tool,
                          inch ? fmt::format("{:.1f}", f_mm / 25.4) : fmt::format("{:.0f}", f_mm),
                          fmt::format("{:.0f}", modal.spindle)));
}

// $n=value (grbl's settings_store_global_setting): a whole number, '=', a
// number; negative values are error:4. The dialect's table gives the range
// of the settings it lists; a number it does not list is kept as given.
Flow<Step> Interpreter::Impl::grbl_store_setting(const std::string& text, CommandSink& out) {
  const SourceLoc at = loc(blk.stmt.column);
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) {
    return fail(AlarmId::kGrblStatement, "$" + text + ": a setting needs '=value'", at);
  }
  int n = 0;
  double v = 0.0;
  const char* vb = text.data() + eq + 1;
  const char* ve = text.data() + text.size();
  const auto rn = std::from_chars(text.data(), text.data() + eq, n);
  const auto rv = std::from_chars(vb, ve, v);
  if (rn.ec != std::errc{} || rn.ptr != text.data() + eq || rv.ec != std::errc{} || rv.ptr != ve ||
      vb == ve) {
    return fail(AlarmId::kNoValue, "$" + text + ": bad number format", at);
  }
  if (v < 0.0) return fail(AlarmId::kGrblNegativeValue, fmt::format("${} = {}", n, v), at);
  if (const config::ParamDef* d = def_of(dialect, n); d != nullptr && (v < d->min || v > d->max)) {
    return fail(AlarmId::kBadValue,
                fmt::format("${} = {} is outside {}..{} ({})", n, v, d->min, d->max, d->name), at);
  }
  const int axis = n % 10;
  if ((n / 10 == 11 || n / 10 == 12 || n / 10 == 13) && axis >= axis_count) {
    return fail(AlarmId::kGrblStatement, fmt::format("${}: the machine has no axis {}", n, axis),
                at);
  }
  if ((n / 10 == 11 || n / 10 == 12) && v == 0.0) {
    return fail(AlarmId::kBadValue, fmt::format("${} = 0: a rate or acceleration above 0", n), at);
  }
  grbl_system().settings[n] = v;
  if (n / 10 == 11) emit(out, canon::AxisRate{axis, v, 0.0});
  if (n / 10 == 12) emit(out, canon::AxisRate{axis, 0.0, v});
  return Step::kContinue;
}

// $H (grbl's limits_go_home, default build): Z first, then X and Y
// together, each at $25 to its switch (the top end of its travel, machine 0
// on a grbl machine) and back by $27 at $24. The locate touch grbl repeats
// at $24 ends where the search did, so it is not moved twice here.
Flow<Step> Interpreter::Impl::grbl_home(CommandSink& out) {
  if (grbl_setting(22) == 0.0) {
    return fail(AlarmId::kGrblSettingDisabled, "$H with $22 = 0 (homing not enabled)",
                loc(blk.stmt.column));
  }
  const double pull = grbl_setting(27);
  auto cycle = [&](std::initializer_list<int> axes) {
    AxisVec at = pos;
    bool any = false;
    for (const int a : axes) {
      if (a >= axis_count) continue;
      at[a] = mc.axes[static_cast<std::size_t>(a)].max_mm;
      any = true;
    }
    if (!any) return;
    emit(out, canon::Feed{at, grbl_setting(25), true});
    for (const int a : axes) {
      if (a < axis_count) at[a] -= pull;
    }
    emit(out, canon::Feed{at, grbl_setting(24), true});
    pos = at;
  };
  cycle({2});
  cycle({0, 1});
  motion_since_sync = true;
  grbl_system().locked = false;
  return Step::kContinue;
}

// $J=...: a G1 to the words given, in the program's G20/G21 and G90/G91
// unless the jog gives its own, F required (units/min, never modal), G53
// for machine coordinates; no other word. The program's modes stay as
// they were ("Jogging commands do not alter the g-code parser state").
Flow<Step> Interpreter::Impl::grbl_jog(CommandSink& out) {
  const SourceLoc at = loc(blk.stmt.column);
  if (grbl_system().locked) return fail(AlarmId::kGrblNotIdle, "$J while grbl is in alarm", at);
  cur_words.clear();
  auto w = collect_words(cur_words);
  SKIPNC_TRY(w);
  bool axis = false;
  for (const gcode::Word& word : blk.words) {
    const char c = word.letter;
    if (axis_of_letter[static_cast<std::size_t>(c - 'A')] >= 0) {
      axis = true;
    } else if (c != 'G' && c != 'F' && c != 'N') {
      return fail(AlarmId::kGrblJogInvalid, std::string("$J with ") + c, loc(word.column));
    }
  }
  for (int i = 0; i < cur_words.g_count; ++i) {
    const GCode g = cur_words.g[static_cast<std::size_t>(i)];
    if (g != GCode(20) && g != GCode(21) && g != GCode(90) && g != GCode(91) && g != GCode(53)) {
      return fail(AlarmId::kGrblJogInvalid, "$J with " + code_name(g),
                  loc(cur_words.g_col[static_cast<std::size_t>(i)]));
    }
  }
  if (!cur_words.has('F')) return fail(AlarmId::kNoFeed, "$J without F", at);
  if (!axis) return fail(AlarmId::kGrblJogInvalid, "$J without an axis word", at);
  if (cur_words.g_count == static_cast<int>(cur_words.g.size())) {
    return fail(AlarmId::kGrblJogInvalid, "$J with too many G codes", at);
  }
  cur_words.g[static_cast<std::size_t>(cur_words.g_count)] = GCode(1);  // the jog is a G1
  cur_words.g_col[static_cast<std::size_t>(cur_words.g_count++)] = blk.stmt.column;
  const ModalState kept = modal;
  const double kept_cut_feed = last_cut_feed;
  auto r = execute_nc(cur_words, out);
  modal = kept;
  last_cut_feed = kept_cut_feed;
  return r;
}

}  // namespace skipnc::interp
