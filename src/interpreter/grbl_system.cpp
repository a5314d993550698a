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
void Grbl::start(Impl& im) {
  start_params(im);  // ngc_params.cpp: G28, G30, G92 and the offsets in #5161..
  for (const auto& p : im.dialect.params) {
    if (p.number < 1000) system.settings[p.number] = im.params.get(p.number);
  }
  for (int i = 0; i < im.axis_count && i < 10; ++i) {
    const auto& a = im.mc.axes[static_cast<std::size_t>(i)];
    system.settings[110 + i] = a.rapid_mm_min;
    system.settings[120 + i] = a.accel_mm_s2;
    system.settings[130 + i] = a.max_mm - a.min_mm;
  }
  system.locked = setting(22) != 0.0;
  if (system.locked) im.add_message("[MSG:'$H'|'$X' to unlock]");
}

double Grbl::setting(int n) const noexcept {
  const auto it = system.settings.find(n);
  return it != system.settings.end() ? it->second : 0.0;
}

// After a G38: the success flag, then, where the dialect reports it, grbl's
// "[PRB:x,y,z:1]" (machine coordinates in mm, 3 decimals; inches, 4
// decimals, with $13 = 1), kept for `$#`.
void Grbl::store_probe(Impl& im, const AxisVec& latch, bool triggered) {
  Language::store_probe(im, latch, triggered);
  if (!im.dialect.sw.probe_report_line) return;
  system.prb = latch;
  system.prb_ok = triggered;
  im.add_message("[PRB:" + coords(im, latch) + (triggered ? ":1]" : ":0]"));
}

// Machine (or offset) values as grbl prints them: mm with 3 decimals, or
// inches with 4 with $13 = 1 ("report in inches"; grbl's internal unit is mm).
std::string Grbl::coords(const Impl& im, const AxisVec& mm) const {
  const bool inch = (static_cast<long long>(setting(13)) & 1) != 0;
  std::string s;
  for (int i = 0; i < im.axis_count; ++i) {
    if (i > 0) s += ',';
    s += inch ? fmt::format("{:.4f}", mm[i] / 25.4 + 0.0) : fmt::format("{:.3f}", mm[i] + 0.0);
  }
  return s;
}

Flow<Step> Grbl::system_line(Impl& im, CommandSink& out) {
  const std::string& text = im.blk.names[static_cast<std::size_t>(im.blk.stmt.label)];
  if (im.blk.stmt.kind == gcode::StmtKind::kGrblJog) {
    if (im.motion_since_sync) return need_sync();
    return jog(im, out);
  }
  if (text.empty()) {
    im.add_message("[HLP:$$ $# $G $I $N $x=val $Nx=line $J=line $SLP $C $X $H ~ ! ? ctrl-x]");
    return Step::kContinue;
  }
  if (text == "G") {
    modal_line(im);
    return Step::kContinue;
  }
  if (im.motion_since_sync) return need_sync();  // grbl: at rest (Idle) only
  if (text == "X") {
    if (system.locked) im.add_message("[MSG:Caution: Unlocked]");
    system.locked = false;  // not in alarm: no effect
    return Step::kContinue;
  }
  if (text == "H") return home(im, out);
  if (text == "C" || text == "SLP" || text.starts_with("RST=")) {
    return fail(AlarmId::kNotSimulated,
                "$" + text +
                    (text == "C"     ? " (check mode)"
                     : text == "SLP" ? " (sleep)"
                                     : "") +
                    " is not simulated",
                im.loc(im.blk.stmt.column));
  }
  if (!text.empty() && (text[0] >= '0' && text[0] <= '9')) return store_setting(im, text, out);
  return report(im, text);
}

// The lines that print: $$, $#, $I, $N, and storing $I= and $Nx=.
Flow<Step> Grbl::report(Impl& im, const std::string& text) {
  if (text == "$") {
    list_settings(im);
  } else if (text == "#") {
    list_offsets(im);
  } else if (text == "I") {
    im.add_message("[VER:1.1h.20190825:" + system.build_info + "]");
    im.add_message("[OPT:V,15,128]");
  } else if (text.starts_with("I=")) {
    system.build_info = text.substr(2);
  } else if (text == "N") {
    for (std::size_t i = 0; i < system.startup.size(); ++i) {
      im.add_message(fmt::format("$N{}={}", i, system.startup[i]));
    }
  } else if (text.size() >= 3 && text[0] == 'N' && (text[1] == '0' || text[1] == '1') &&
             text[2] == '=') {
    system.startup[static_cast<std::size_t>(text[1] - '0')] = text.substr(3);
  } else {
    return fail(AlarmId::kGrblStatement, "$" + text + " is not a grbl system command",
                im.loc(im.blk.stmt.column));
  }
  return Step::kContinue;
}

void Grbl::list_settings(Impl& im) {
  for (const auto& [n, v] : system.settings) {
    const config::ParamDef* d = def_of(im.dialect, n);
    const bool integer = d != nullptr ? d->kind != config::ParamKind::kReal : false;
    im.add_message(fmt::format("${}={}", n, setting_text(v, integer)));
  }
}

// $#: the work offsets G54-G59, the G28 and G30 positions (#5161.., #5181..,
// kept in mm), G92, the tool length offset and the last probe.
void Grbl::list_offsets(Impl& im) {
  for (int set = 1; set <= 6; ++set) {
    im.add_message(fmt::format("[G{}:{}]", 53 + set,
                               coords(im, im.work_offsets[static_cast<std::size_t>(set)])));
  }
  for (const int base : {5161, 5181}) {
    AxisVec p;
    for (int i = 0; i < im.axis_count; ++i) {
      const int j = ngc_axis_index(im.axis_letter[static_cast<std::size_t>(i)]);
      p[i] = j < 0 ? 0.0 : im.vars.ngc_param(base + j) * im.stored_mm();
    }
    im.add_message(fmt::format("[G{}:{}]", base == 5161 ? 28 : 30, coords(im, p)));
  }
  im.add_message("[G92:" + coords(im, im.shifts.get().g92_shift) + "]");
  const bool inch = (static_cast<long long>(setting(13)) & 1) != 0;
  im.add_message(inch ? fmt::format("[TLO:{:.4f}]", im.length_offset / 25.4 + 0.0)
                      : fmt::format("[TLO:{:.3f}]", im.length_offset + 0.0));
  im.add_message("[PRB:" + coords(im, system.prb) + (system.prb_ok ? ":1]" : ":0]"));
}

// $G: "[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]" (grbl 1.1's
// report_gcode_modes; F in mm/min, or inch/min with $13 = 1).
void Grbl::modal_line(Impl& im) {
  std::string motion = "G0";
  switch (im.modal.motion) {
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
      motion = code_name(im.modal.probe);
      break;
    default:
      break;
  }
  const char* plane = im.modal.plane == PlaneSel::kXY   ? "G17"
                      : im.modal.plane == PlaneSel::kZX ? "G18"
                                                        : "G19";
  const bool inch = (static_cast<long long>(setting(13)) & 1) != 0;
  const double f_mm = im.modal.feed * im.unit_mm();
  im.add_message(fmt::format(
      "[GC:{} G{} {} {} {} G94 {} M9 T{} F{} S{}]", motion, 53 + im.modal.work, plane,
      im.modal.units == Units::kInch ? "G20" : "G21",
      im.modal.distance == Distance::kIncremental ? "G91" : "G90",
      im.modal.spindle_dir > 0   ? "M3"
      : im.modal.spindle_dir < 0 ? "M4"
                                 : "M5",
      im.modal.tool, inch ? fmt::format("{:.1f}", f_mm / 25.4) : fmt::format("{:.0f}", f_mm),
      fmt::format("{:.0f}", im.modal.spindle)));
}

// $n=value (grbl's settings_store_global_setting): a whole number, '=', a
// number; negative values are error:4. The dialect's table gives the range
// of the settings it lists; a number it does not list is kept as given.
Flow<Step> Grbl::store_setting(Impl& im, const std::string& text, CommandSink& out) {
  const SourceLoc at = im.loc(im.blk.stmt.column);
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
  if (const config::ParamDef* d = def_of(im.dialect, n);
      d != nullptr && (v < d->min || v > d->max)) {
    return fail(AlarmId::kBadValue,
                fmt::format("${} = {} is outside {}..{} ({})", n, v, d->min, d->max, d->name), at);
  }
  const int axis = n % 10;
  if ((n / 10 == 11 || n / 10 == 12 || n / 10 == 13) && axis >= im.axis_count) {
    return fail(AlarmId::kGrblStatement, fmt::format("${}: the machine has no axis {}", n, axis),
                at);
  }
  if ((n / 10 == 11 || n / 10 == 12) && v == 0.0) {
    return fail(AlarmId::kBadValue, fmt::format("${} = 0: a rate or acceleration above 0", n), at);
  }
  system.settings[n] = v;
  if (n / 10 == 11) im.emit(out, canon::AxisRate{axis, v, 0.0});
  if (n / 10 == 12) im.emit(out, canon::AxisRate{axis, 0.0, v});
  return Step::kContinue;
}

// $H (grbl's limits_go_home, default build): Z first, then X and Y
// together, each at $25 to its switch (the top end of its travel, machine 0
// on a grbl machine) and back by $27 at $24. The locate touch grbl repeats
// at $24 ends where the search did, so it is not moved twice here.
Flow<Step> Grbl::home(Impl& im, CommandSink& out) {
  if (setting(22) == 0.0) {
    return fail(AlarmId::kGrblSettingDisabled, "$H with $22 = 0 (homing not enabled)",
                im.loc(im.blk.stmt.column));
  }
  const double pull = setting(27);
  auto cycle = [&](std::initializer_list<int> axes) {
    AxisVec at = im.pos;
    bool any = false;
    for (const int a : axes) {
      if (a >= im.axis_count) continue;
      at[a] = im.mc.axes[static_cast<std::size_t>(a)].max_mm;
      any = true;
    }
    if (!any) return;
    im.emit(out, canon::Feed{at, setting(25), true});
    for (const int a : axes) {
      if (a < im.axis_count) at[a] -= pull;
    }
    im.emit(out, canon::Feed{at, setting(24), true});
    im.pos = at;
  };
  cycle({2});
  cycle({0, 1});
  im.motion_since_sync = true;
  system.locked = false;
  return Step::kContinue;
}

// $J=...: a G1 to the words given, in the program's G20/G21 and G90/G91
// unless the jog gives its own, F required (units/min, never modal), G53
// for machine coordinates; no other word. The program's modes stay as
// they were ("Jogging commands do not alter the g-code parser state").
Flow<Step> Grbl::jog(Impl& im, CommandSink& out) {
  const SourceLoc at = im.loc(im.blk.stmt.column);
  if (system.locked) return fail(AlarmId::kGrblNotIdle, "$J while grbl is in alarm", at);
  im.cur_words.clear();
  auto w = im.collect_words(im.cur_words);
  SKIPNC_TRY(w);
  bool axis = false;
  for (const gcode::Word& word : im.blk.words) {
    const char c = word.letter;
    if (im.axis_of_letter[static_cast<std::size_t>(c - 'A')] >= 0) {
      axis = true;
    } else if (c != 'G' && c != 'F' && c != 'N') {
      return fail(AlarmId::kGrblJogInvalid, std::string("$J with ") + c, im.loc(word.column));
    }
  }
  for (int i = 0; i < im.cur_words.g_count; ++i) {
    const GCode g = im.cur_words.g[static_cast<std::size_t>(i)];
    if (g != GCode(20) && g != GCode(21) && g != GCode(90) && g != GCode(91) && g != GCode(53)) {
      return fail(AlarmId::kGrblJogInvalid, "$J with " + code_name(g),
                  im.loc(im.cur_words.g_col[static_cast<std::size_t>(i)]));
    }
  }
  if (!im.cur_words.has('F')) return fail(AlarmId::kNoFeed, "$J without F", at);
  if (!axis) return fail(AlarmId::kGrblJogInvalid, "$J without an axis word", at);
  if (im.cur_words.g_count == static_cast<int>(im.cur_words.g.size())) {
    return fail(AlarmId::kGrblJogInvalid, "$J with too many G codes", at);
  }
  im.cur_words.g[static_cast<std::size_t>(im.cur_words.g_count)] = GCode(1);  // the jog is a G1
  im.cur_words.g_col[static_cast<std::size_t>(im.cur_words.g_count++)] = im.blk.stmt.column;
  const ModalState kept = im.modal;
  const double kept_cut_feed = im.skip_state.last_cut_feed;
  auto r = im.execute_nc(im.cur_words, out);
  im.modal = kept;
  im.skip_state.last_cut_feed = kept_cut_feed;
  return r;
}

}  // namespace skipnc::interp
