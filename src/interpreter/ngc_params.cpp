// LinuxCNC's parameters (RS274NGC dialects; docs/languages.md), after the
// "Parameters" section of LinuxCNC's G-code overview:
//   #1-#30        local to a call level; `o.. call [a] [b]` sets #1, #2 ...
//   #31-#5000     global, 0 until set (there is no vacant value)
//   #5061-#5069   the last G38 probe position, in the work coordinates
//                 of the G38 block, X Y Z A B C U V W
//   #5070         1 when the last G38 tripped the probe, else 0
//   #5161-#5169   G28 position, #5181-#5189 G30 position (stored values)
//   #5210         1 while a G92 offset applies; #5211-#5219 the G92 offset
//                 (kept by G92.2, applied again by G92.3)
//   #5220         the coordinate system, 1 = G54 .. 9 = G59.3
//   #5221-#5230   G54 X Y Z A B C U V W R, then 20 per system to G59.3;
//                 the active system reads them when it is selected
//   #5400         tool number; #5401-#5409 tool offsets; #5410 diameter
//   #5420-#5428   the current position in work coordinates
// Named parameters: #<name> is local to its call level, #<_name> global;
// reading one never set is an error. Predefined read-only names (#<_x>,
// #<_abs_x>, #<_line>, #<_value> ...) are computed from the state.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "interpreter/impl.hpp"

namespace skipnc::interp {
namespace {

constexpr const char* kNgcAxes = "XYZABCUVW";

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

int ngc_axis_index(char letter) noexcept {
  for (int i = 0; i < 9; ++i) {
    if (kNgcAxes[i] == letter) return i;
  }
  return -1;
}

Flow<Value> LinuxcncFamily::read_numbered(Impl& im, int n, SourceLoc where) {
  if (n < 0 || n >= VariableStore::kNgcParams) {
    return fail(AlarmId::kIllegalVariable,
                "#" + std::to_string(n) + ": parameters are #0 to #" +
                    std::to_string(VariableStore::kNgcParams - 1),
                where);
  }
  if (n >= 1 && n <= 30) return Value::of(im.vars.get(n).num());
  // A machine axis of LinuxCNC's axis slot j (X Y Z A B C U V W), -1 if none.
  auto axis = [&](int j) { return im.axis_of_letter[static_cast<std::size_t>(kNgcAxes[j] - 'A')]; };
  if (n == 5220) return Value::of(im.modal.work >= 1 && im.modal.work <= 9 ? im.modal.work : 1.0);
  if (n == 5400) return Value::of(im.modal.tool);
  if (n >= 5401 && n <= 5409) {
    const int a = axis(n - 5401);
    return Value::of(a >= 0 && a == im.length_axis ? im.length_offset / im.unit_mm() + 0.0 : 0.0);
  }
  if (n >= 5410 && n <= 5413) {
    if (n == 5410 && im.modal.tool > 0 && im.modal.tool < static_cast<int>(im.tools.size())) {
      const auto& t = im.tools[static_cast<std::size_t>(im.modal.tool)];
      return Value::of(2.0 * (t.radius_geometry + t.radius_wear) / im.unit_mm());
    }
    return Value::of(0.0);
  }
  if (n >= 5420 && n <= 5428) {
    if (im.motion_since_sync) return need_sync();
    const int a = axis(n - 5420);
    if (a < 0) return Value::of(0.0);
    return Value::of(
        im.position_var(a, im.pos[a] + im.comp.vector()[a], im.dialect.sw.current_tool_offsets));
  }
  return Value::of(im.vars.ngc_param(n));
}

Flow<void> LinuxcncFamily::write_numbered(Impl& im, int n, Value v, SourceLoc where) {
  if (n < 0 || n >= VariableStore::kNgcParams) {
    return fail(AlarmId::kIllegalVariable,
                "#" + std::to_string(n) + ": parameters are #0 to #" +
                    std::to_string(VariableStore::kNgcParams - 1),
                where);
  }
  if (n >= 1 && n <= 30) {
    im.vars.set(n, Value::of(v.num()));
    return {};
  }
  if ((n >= 5061 && n <= 5070) || n == 5220 || (n >= 5400 && n <= 5428)) {
    return fail(AlarmId::kWriteProtected, "#" + std::to_string(n) + " is read-only", where);
  }
  // #5161-#5390: the stored G28/G30 positions, the G92 offsets (#5211..)
  // and the work offsets (#5221..), each within kMaxOffsetMm.
  if (n >= 5161 && n <= 5390 && n != 5210 && (n - 5221) % 20 != 9 && n != 5220) {
    auto ok = im.check_offset(v.num() * im.stored_mm(), "#" + std::to_string(n), where);
    if (!ok) return ok;
  }
  // #5221-#5390 are the stored work offsets: the active system keeps what
  // it loaded until another one is selected (select_work), as LinuxCNC.
  im.vars.set_ngc_param(n, v.num());
  return {};
}

// The work offsets of system `set` (1-9) from #5221.. (LinuxCNC loads them
// when a block selects a system other than the active one, and at start).
void LinuxcncFamily::select_work(Impl& im, int set) {
  for (int i = 0; i < im.axis_count; ++i) {
    const int j = ngc_axis_index(im.axis_letter[static_cast<std::size_t>(i)]);
    if (j < 0) continue;
    im.work_offsets.write(static_cast<std::size_t>(set))[i] =
        im.vars.ngc_param(5221 + 20 * (set - 1) + j) * im.stored_mm();
  }
}

// The predefined named parameters (LinuxCNC "Predefined Named Parameters"):
// nullopt when `name` is not one of them.
std::optional<Flow<Value>> LinuxcncFamily::predefined(Impl& im, const std::string& name,
                                                      SourceLoc where) {
  const std::string n = lower(name);
  if (n.size() < 2 || n[0] != '_') return std::nullopt;
  if (auto r = ini_hal(im, n, where)) return r;
  auto of = [](double x) -> std::optional<Flow<Value>> { return Flow<Value>(Value::of(x + 0.0)); };
  // Positions: #<_x> .. #<_w> in work coordinates (as #5420..), #<_abs_x> ..
  // in machine coordinates.
  const bool abs = n.starts_with("_abs_") && n.size() == 6;
  if ((n.size() == 2 || abs) && ngc_axis_index(static_cast<char>(std::toupper(n.back()))) >= 0) {
    const int j = ngc_axis_index(static_cast<char>(std::toupper(n.back())));
    const int a = im.axis_of_letter[static_cast<std::size_t>(kNgcAxes[j] - 'A')];
    if (im.motion_since_sync) return Flow<Value>(need_sync());
    if (a < 0) return of(0.0);
    const double tool = im.pos[a] + im.comp.vector()[a];
    return of(abs ? tool / im.unit_mm()
                  : im.position_var(a, tool, im.dialect.sw.current_tool_offsets));
  }
  if (n == "_line") return of(im.cur_line);
  if (n == "_value") return of(state.value.num());
  if (n == "_value_returned") return of(state.value_returned ? 1.0 : 0.0);
  if (n == "_call_level") return of(static_cast<double>(im.programs.frames.size() - 1));
  if (n == "_task") return of(1.0);
  if (n == "_metric") return of(im.modal.units == Units::kMetric ? 1.0 : 0.0);
  if (n == "_imperial") return of(im.modal.units == Units::kInch ? 1.0 : 0.0);
  if (n == "_absolute") return of(im.modal.distance == Distance::kAbsolute ? 1.0 : 0.0);
  if (n == "_incremental") return of(im.modal.distance == Distance::kIncremental ? 1.0 : 0.0);
  if (n == "_units_per_minute") return of(im.modal.feed_mode == FeedMode::kPerMinute ? 1.0 : 0.0);
  if (n == "_units_per_rev") return of(im.modal.feed_mode == FeedMode::kPerRev ? 1.0 : 0.0);
  if (n == "_inverse_time") return of(0.0);
  if (n == "_feed") return of(im.modal.feed);
  if (n == "_rpm") return of(im.modal.spindle);
  if (n == "_current_tool" || n == "_selected_tool") return of(im.modal.tool);
  if (n == "_spindle_on") return of(im.modal.spindle_dir != 0 ? 1.0 : 0.0);
  if (n == "_spindle_cw") return of(im.modal.spindle_dir == 1 ? 1.0 : 0.0);
  if (n == "_tool_offset") return of(im.modal.length != LengthComp::kOff ? 1.0 : 0.0);
  if (n == "_coord_system") {
    return of(im.modal.work > 6 ? 584.0 + im.modal.work : 530.0 + 10.0 * im.modal.work);
  }
  if (n == "_plane") {
    return of(im.modal.plane == PlaneSel::kXY   ? 170.0
              : im.modal.plane == PlaneSel::kZX ? 180.0
                                                : 190.0);
  }
  if (n == "_ccomp") {
    return of(im.modal.cutter == CutterComp::kOff    ? 400.0
              : im.modal.cutter == CutterComp::kLeft ? 410.0
                                                     : 420.0);
  }
  if (n == "_motion_mode") {
    switch (im.modal.motion) {
      case Motion::kRapid:
        return of(0.0);
      case Motion::kLinear:
        return of(10.0);
      case Motion::kCwArc:
        return of(20.0);
      case Motion::kCcwArc:
        return of(30.0);
      case Motion::kProbe:
        return of(static_cast<double>(im.modal.probe.tenths()));  // 382: G38.2
      default:
        return of(0.0);
    }
  }
  return std::nullopt;
}

bool LinuxcncFamily::named_exists(Impl& im, const std::string& name) {
  if (!name.empty() && name.front() == '_') {
    return im.vars.has_named(name) || predefined(im, name, im.loc(im.cur_col)).has_value();
  }
  return im.vars.local_named(name) != nullptr;
}

Flow<Value> LinuxcncFamily::read_name(Impl& im, const std::string& name, SourceLoc where) {
  if (!name.empty() && name.front() == '_') {
    if (auto p = predefined(im, name, where)) return std::move(*p);
    if (im.vars.has_named(name)) return im.vars.get_named(name);
  } else if (const Value* v = im.vars.local_named(name)) {
    return *v;
  }
  return fail(AlarmId::kNamedUndefined, "#<" + lower(name) + "> was never set", where);
}

Flow<void> LinuxcncFamily::write_name(Impl& im, const std::string& name, Value v, SourceLoc where) {
  const bool global = !name.empty() && name.front() == '_';
  if (global && predefined(im, name, where).has_value()) {
    return fail(AlarmId::kWriteProtected, "#<" + lower(name) + "> is a predefined parameter",
                where);
  }
  const bool have = global ? im.vars.has_named(name) : im.vars.local_named(name) != nullptr;
  if (!have && static_cast<std::int64_t>(im.vars.named_count() + im.vars.local_named_count()) >=
                   im.mc.limits.max_named_variables) {
    return fail(AlarmId::kNamedVariableLimit,
                "#<" + lower(name) + ">: more than limits.max_named_variables = " +
                    std::to_string(im.mc.limits.max_named_variables) + " named parameters",
                where);
  }
  if (global) {
    im.vars.set_named(name, Value::of(v.num()));
  } else {
    im.vars.set_local_named(name, Value::of(v.num()));
  }
  return {};
}

// A message's text with #n and #<name> replaced by their values ("%f", as
// LinuxCNC prints them; a named parameter never set prints "######").
Flow<std::string> LinuxcncFamily::message_text(Impl& im, std::string_view text, SourceLoc where) {
  std::string out;
  std::size_t i = 0;
  char buf[64];
  while (i < text.size()) {
    if (text[i] != '#') {
      out += text[i++];
      continue;
    }
    if (i + 1 < text.size() && text[i + 1] == '<') {
      const std::size_t close = text.find('>', i + 2);
      if (close == std::string_view::npos) {
        out += text.substr(i);
        break;
      }
      std::string name;
      for (std::size_t k = i + 2; k < close; ++k) {
        if (text[k] != ' ' && text[k] != '\t') {
          name += static_cast<char>(std::toupper(static_cast<unsigned char>(text[k])));
        }
      }
      i = close + 1;
      const bool exists = named_exists(im, name);
      if (!exists) {
        out += "######";
        continue;
      }
      auto v = read_name(im, name, where);
      SKIPNC_TRY(v);
      std::snprintf(buf, sizeof buf, "%f", v->num());
      out += buf;
      continue;
    }
    std::size_t k = i + 1;
    int n = 0;
    while (k < text.size() && text[k] >= '0' && text[k] <= '9' && n < VariableStore::kNgcParams) {
      n = n * 10 + (text[k] - '0');
      ++k;
    }
    if (k == i + 1 || n >= VariableStore::kNgcParams) {
      out += text[i++];
      continue;
    }
    auto v = read_numbered(im, n, where);
    SKIPNC_TRY(v);
    std::snprintf(buf, sizeof buf, "%f", v->num());
    out += buf;
    i = k;
  }
  return out;
}

// The comments of an RS274NGC line that speak: (msg,..) is shown as
// written, (debug,..) with parameters replaced; (print,..) goes to the
// messages the same way (LinuxCNC prints it on its standard output).
Flow<void> LinuxcncFamily::comments(Impl& im) {
  for (const auto& c : im.blk.comments) {
    const std::string& t = im.blk.names[static_cast<std::size_t>(c.text)];
    std::size_t i = 0;
    while (i < t.size() && (t[i] == ' ' || t[i] == '\t')) ++i;
    const std::string head = lower(t.substr(i, 6));
    if (head.starts_with("msg,")) {
      im.add_message(t.substr(i + 4));
    } else if (head.starts_with("debug,") || head.starts_with("print,")) {
      auto m = message_text(im, std::string_view(t).substr(i + 6), im.loc(c.column));
      SKIPNC_TRY(m);
      im.add_message(*m);
    } else if (head.starts_with("abort,")) {
      // LinuxCNC "(ABORT, ...)": the run ends with the text (parameters
      // replaced as in DEBUG) as its error ("Comments" in the G-code overview).
      auto m = message_text(im, std::string_view(t).substr(i + 6), im.loc(c.column));
      SKIPNC_TRY(m);
      const std::size_t text = std::min(m->find_first_not_of(" \t"), m->size());
      return fail(AlarmId::kUserAlarm, "(abort) " + m->substr(text), im.loc(c.column));
    } else {
      auto r = log_comment(im, std::string_view(t).substr(i), im.loc(c.column));
      if (!r) return r;
    }
  }
  return {};
}

// After a G38: #5061-#5069 (the latch, or the end point without contact,
// in the work coordinates of the block) and #5070.
void LinuxcncFamily::store_probe_params(Impl& im, const AxisVec& latch_work, bool triggered) {
  for (int j = 0; j < 9; ++j) {
    const int a = im.axis_of_letter[static_cast<std::size_t>(kNgcAxes[j] - 'A')];
    im.vars.set_ngc_param(5061 + j, a < 0 ? 0.0 : latch_work[a]);
  }
  im.vars.set_ngc_param(5070, triggered ? 1.0 : 0.0);
}

// At the start: the parameter store, and #5221.. holding the machine file's
// work offsets (grbl keeps G28, G30, G92 and the offsets in the same numbers).
void LinuxcncFamily::start_params(Impl& im) {
  im.vars.enable_ngc_params();
  for (int set = 1; set <= 9; ++set) {
    for (int i = 0; i < im.axis_count; ++i) {
      const int j = ngc_axis_index(im.axis_letter[static_cast<std::size_t>(i)]);
      if (j >= 0) {
        im.vars.set_ngc_param(5221 + 20 * (set - 1) + j,
                              im.work_offsets[static_cast<std::size_t>(set)][i] / im.stored_mm());
      }
    }
  }
}

// LinuxCNC's parameter file (the machine's persistent_variables): the
// parameters it lists, and always #5161-#5390 (G28, G30, G92 and the work
// offsets); the run starts in the system of #5220 with the G92 of
// #5210-#5219, as LinuxCNC does.
Flow<void> Rs274ngc::load_persistent(Impl& im) {
  std::vector<int>& numbers = state.var_file_numbers;
  std::vector<double> values;
  auto r = load_var_file(im.mc.persistent_vars, numbers, values);
  SKIPNC_TRY(r);
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    const int n = numbers[i];
    if (n == 5220) {  // the coordinate system LinuxCNC starts in
      const double w = std::round(values[i]);
      if (w >= 1 && w <= 9) im.modal.work = static_cast<int>(w);
      continue;
    }
    if (n >= 5210 && n <= 5219) {  // G92: on and its offsets
      im.vars.set_ngc_param(n, values[i]);
      continue;
    }
    if (!write_numbered(im, n, Value::of(values[i]), SourceLoc{})) {
      return fail(AlarmId::kConfig, "parameter file '" + im.mc.persistent_vars + "': #" +
                                        std::to_string(n) + " cannot be set");
    }
  }
  for (int set = 1; set <= 9; ++set) select_work(im, set);
  if (im.vars.ngc_param(5210) != 0.0) {
    for (int i = 0; i < im.axis_count; ++i) {
      const int j = ngc_axis_index(im.axis_letter[static_cast<std::size_t>(i)]);
      if (j >= 0) im.shifts.write().g92_shift[i] = im.vars.ngc_param(5211 + j) * im.stored_mm();
    }
  }
  for (int n = 5161; n <= 5390; ++n) numbers.push_back(n);
  std::sort(numbers.begin(), numbers.end());
  numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
  return {};
}

}  // namespace skipnc::interp
