// System variables of Custom Macro B (Fanuc numbering): which numbers exist,
// who may write them and which wait for motion is the table in
// sysvar_table.hpp; this file is what each one reads and writes (the table
// of docs/macro.md). Positions are in the program's units (G20: inch).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <ctime>

#include "interpreter/impl.hpp"
#include "interpreter/offset_units.hpp"
#include "interpreter/sysvar_table.hpp"

namespace skipnc::interp {
namespace {

// The G code reported for a modal group this interpreter does not model:
// the group's power-on state of a Fanuc M-series control. Nothing: no such
// group.
std::optional<GCode> default_g_of_group(int group) {
  switch (group) {
    case 4:
      return GCode(22);  // G22 stored stroke check on
    case 11:
      return GCode(50);  // G50 scaling off
    case 13:
      return GCode(97);  // G97 constant surface speed off
    case 16:
      return GCode(69);  // G69 rotation off
    case 17:
      return GCode(15);  // G15 polar coordinates off
    case 18:
      return GCode(50, 1);  // G50.1 programmable mirror image off
    case 19:
      return GCode(40, 1);  // G40.1 normal direction control off
    case 21:
      return GCode(13, 1);  // G13.1 polar coordinate interpolation off
    default:
      return std::nullopt;
  }
}

// A work-offset variable (a range of that kind and the number in it): which
// set (0 EXT, 1-6 G54-G59, 7.. G54.1 P1..) and which axis.
void work_offset_var(const sysvar::Range& r, int n, int& set, int& axis) {
  switch (r.id) {
    case sysvar::Id::kWorkOffsetOld:  // rows of 100 per axis, a set per unit
      set = n % 100;
      axis = (n - sysvar::kWorkOffsetOldAxis1) / 100;
      return;
    case sysvar::Id::kWorkOffset:
      set = (n - r.first) / 20;
      axis = (n - r.first) % 20;
      return;
    default:  // G54.1 P1..: kWorkOffsetP48, kWorkOffsetP300
      set = 7 + (n - r.first) / 20;
      axis = (n - r.first) % 20;
      return;
  }
}

// The machine axis a work offset's slot (0-based) names under the
// dialect's numbering (offset_variables_by); -1: none.
int offset_axis(const Interpreter::Impl& im, int slot) {
  return sysvar::offset_slot_axis(
      im.dialect.sw.offset_variables_by == config::OffsetVariables::kLetter, im.axis_count, slot,
      [&im](char letter) { return im.axis_of_letter[static_cast<std::size_t>(letter - 'A')]; });
}

// The alarm's text for a write to a work-offset variable naming no axis.
std::string no_offset_axis(const Interpreter::Impl& im, int n, int slot) {
  const std::string var = "#" + std::to_string(n);
  if (im.dialect.sw.offset_variables_by != config::OffsetVariables::kLetter) {
    return var + ": the machine has no axis " + std::to_string(slot + 1);
  }
  if (slot < static_cast<int>(sysvar::kOffsetSlotLetters.size())) {
    return var + ": the machine has no " +
           std::string(1, sysvar::kOffsetSlotLetters[static_cast<std::size_t>(slot)]) +
           " axis (the offsets are numbered by letter: X Y Z A B C)";
  }
  return var + ": offset " + std::to_string(slot + 1) +
         " names no axis (the offsets are numbered by letter: X Y Z A B C)";
}

bool is_tool(const sysvar::Range& r) {
  return r.id == sysvar::Id::kHWearShort || r.id == sysvar::Id::kHGeomShort ||
         r.id == sysvar::Id::kHWear || r.id == sysvar::Id::kHGeom || r.id == sysvar::Id::kDWear ||
         r.id == sysvar::Id::kDGeom;
}

bool is_work_offset(sysvar::Id id) {
  return id == sysvar::Id::kWorkOffsetOld || id == sysvar::Id::kWorkOffset ||
         id == sysvar::Id::kWorkOffsetP48 || id == sysvar::Id::kWorkOffsetP300;
}

// Number of the system variable `name` ("_ABSKP[3]"), 0 when it is not one,
// -1 when the name is known but the index is not valid.
int system_number(std::string_view name) {
  const std::size_t open = name.find('[');
  const std::string_view base = name.substr(0, open);
  for (const sysvar::Name& s : sysvar::kNames) {
    if (s.name != base) continue;
    if (s.count == 0) return open == std::string_view::npos ? s.number : -1;
    if (open == std::string_view::npos || name.back() != ']') return -1;
    int i = 0;
    for (std::size_t k = open + 1; k + 1 < name.size(); ++k) {
      if (name[k] < '0' || name[k] > '9' || i > 1000) return -1;
      i = i * 10 + (name[k] - '0');
    }
    return i >= 1 && i <= s.count ? s.number + i : -1;
  }
  return 0;
}

}  // namespace

namespace sysvar {

const Range* find(int n, int& number) noexcept {
  const auto in = [](int k) -> const Range* {
    const Range* r = std::upper_bound(std::begin(kRanges), std::end(kRanges), k,
                                      [](int v, const Range& x) { return v < x.first; });
    if (r == std::begin(kRanges)) return nullptr;
    --r;
    return k <= r->last ? r : nullptr;
  };
  if (const Range* r = in(n)) {
    number = n;
    return r;
  }
  // An alias: #4201.. for #4001.. (each alias is below the smallest first
  // number it could be confused with: 200 for the modal block).
  constexpr int kModalAlias = 200;
  if (const Range* r = in(n - kModalAlias); r != nullptr && r->alias == kModalAlias) {
    number = n - kModalAlias;
    return r;
  }
  return nullptr;
}

}  // namespace sysvar

namespace {

// Haas's tool offset numbers (haas_tool_offset_vars) as the long forms of
// memory C: #2001-#2200 length -> #11001.., #2201-#2400 length wear ->
// #10001.., #2401-#2600 diameter/radius -> #13001.., #2601-#2800 its wear ->
// #12001...
int haas_tool_var(int n) noexcept {
  if (n < 2001 || n > 2800) return n;
  static constexpr int kLongForm[] = {11001, 10001, 13001, 12001};
  const int block = (n - 2001) / 200;
  return kLongForm[block] + (n - 2001) % 200;
}

}  // namespace

Flow<Value> Interpreter::Impl::read_var(int n, SourceLoc where) {
  return lang->read_param(*this, n, where);  // RS274NGC's: ngc_params.cpp
}

Flow<Value> Interpreter::Impl::read_macro_var(int n, SourceLoc where) {
  if (dialect.sw.haas_tool_offset_vars) n = haas_tool_var(n);
  if (n == 0) return Value::null();
  if (n < 0) return fail(AlarmId::kIllegalVariable, "#" + std::to_string(n), where);
  if (VariableStore::is_local(n) || VariableStore::is_common(n) ||
      VariableStore::is_persistent(n)) {
    return vars.get(n);
  }
  int k = 0;
  const sysvar::Range* r = sysvar::find(n, k);
  double* tool = r != nullptr && is_tool(*r) ? tool_field(*r, k) : nullptr;
  if (r == nullptr || !(r->access & sysvar::kRead) || (is_tool(*r) && tool == nullptr)) {
    return fail(AlarmId::kIllegalVariable,
                "#" + std::to_string(n) + " is not a variable of this control", where);
  }
  // Buffer stop: the value is the one after the queued motion has ended.
  if (r->live && motion_since_sync) return need_sync();
  if (is_work_offset(r->id)) {
    int set = 0, axis = 0;
    work_offset_var(*r, k, set, axis);
    axis = offset_axis(*this, axis);
    if (axis < 0) return Value::null();
    return Value::of(work_offsets[static_cast<std::size_t>(set)][axis] * offset_unit_mm(*this) /
                         unit_mm() +
                     0.0);
  }
  if (tool != nullptr) return Value::of(*tool * offset_unit_mm(*this) / unit_mm() + 0.0);
  if (r->id == sysvar::Id::kSettingError) return setting_error_data[std::size_t(k - r->first)];
  if (k >= 5000) return read_position(*r, k - r->first, where);
  if (k >= 4000) return read_modal(*r, k - r->first);
  return read_control(*r, k);
}

namespace {

// Whether a block's text compares values (EQ NE GT LT GE LE as words) or
// reads the end point #5001-#5008 (compared with the skip position, a miss
// shows as equality).
bool block_checks_skip(std::string_view text) {
  // A letter next to the operator makes it part of a word (WHILE, ENDIF);
  // a digit or a bracket does not: IF[#1GT0] compares as IF [#1 GT 0] does.
  auto word_char = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
  for (std::size_t i = 0; i + 1 < text.size(); ++i) {
    const char a = static_cast<char>(std::toupper(static_cast<unsigned char>(text[i])));
    const char b = static_cast<char>(std::toupper(static_cast<unsigned char>(text[i + 1])));
    const bool op = (a == 'E' && b == 'Q') || (a == 'N' && b == 'E') ||
                    ((a == 'G' || a == 'L') && (b == 'T' || b == 'E'));
    if (op && (i == 0 || !word_char(text[i - 1])) &&
        (i + 2 >= text.size() || !word_char(text[i + 2])))
      return true;
    if (text[i] == '#' && text.substr(i + 1, 3) == "500" && i + 4 < text.size() &&
        text[i + 4] >= '1' && text[i + 4] <= '8' &&
        (i + 5 >= text.size() || std::isdigit(static_cast<unsigned char>(text[i + 5])) == 0))
      return true;
  }
  return false;
}

}  // namespace

// #5001.. - #5108: one value per axis, vacant for an axis the machine does
// not have. Lengths in program values (an X axis in diameter reads in
// diameter); tool offsets in or out per dialect (docs/position-variables.md).
Flow<Value> Interpreter::Impl::read_position(const sysvar::Range& r, int i, SourceLoc where) {
  if (i >= axis_count) return Value::null();
  const auto& sw = dialect.sw;
  const double scale = axis_scale[static_cast<std::size_t>(i)];
  // #5021.. and #5041.. are where the tool is: under cutter compensation
  // the programmed point plus the offset vector (docs/cutter-compensation.md).
  const double tool = pos[i] + comp.vector()[i];
  double v = 0.0;
  switch (r.id) {
    case sysvar::Id::kBlockEnd:
      v = position_var(i, pos[i], sw.block_end_tool_offsets);
      break;
    case sysvar::Id::kMachinePos: {
      // Machine lock and Z-axis cancel: the machine does not move, and its
      // machine coordinates stay where it is (the work position follows
      // the program).
      const bool lock = sw.machine_lock_param != 0 && params.get(sw.machine_lock_param) != 0.0;
      const bool z_cancel = sw.z_cancel_param != 0 && params.get(sw.z_cancel_param) != 0.0;
      const bool held = lock || (z_cancel && axis_letter[static_cast<std::size_t>(i)] == 'Z');
      v = (held ? last_sync.actual_position[i] : tool) * scale / unit_mm();
      break;
    }
    case sysvar::Id::kWorkPos:
      v = position_var(i, tool, sw.current_tool_offsets);
      break;
    case sysvar::Id::kSkipPos: {
      // A block that tests the value (IF/WHILE with a comparison, or
      // against the end point #5001..) is the program checking for a miss,
      // the protected-move idiom: no warning, and later reads are after
      // the check.
      if (skip_state.missed_unread && where.line != 0 && block_checks_skip(raw.text)) {
        skip_state.missed_unread = false;
      }
      if (skip_state.missed_unread && where.line != 0) {
        skip_state.missed_unread = false;
        auto w = warn("skip_missed_read",
                      "#" + std::to_string(r.first + i) + " read after the skip of line " +
                          std::to_string(skip_missed_line) +
                          " ran to its end point without a signal: it holds that end point, "
                          "not a touch",
                      where);
        SKIPNC_TRY(w);
      }
      v = skip_result.work_or_zero(i);
      break;
    }
    case sysvar::Id::kLengthOffset:
      v = i == length_axis ? length_offset / unit_mm() : 0.0;
      break;
    case sysvar::Id::kServoError:
      v = (last_sync.machine_position[i] - last_sync.actual_position[i]) * scale / unit_mm();
      break;
    default:
      return fail(AlarmId::kInternal, "system variable table: no reader", where);
  }
  return Value::of(v + 0.0);
}

// #4001.. (and #4201..): the modal state. `i` is the number within the
// range (the group for #4001-#4022).
Value Interpreter::Impl::read_modal(const sysvar::Range& r, int i) const {
  switch (r.id) {
    case sysvar::Id::kModalG: {
      const int group = i + 1;
      if (group == 14 && modal.work > 6) return Value::of(54.1);
      std::optional<GCode> code = g_code_of_group(modal, group);
      if (!code) code = default_g_of_group(group);
      if (!code) return Value::null();
      return Value::of(code->value());
    }
    case sysvar::Id::kModalB:
      return Value::of(0.0);
    case sysvar::Id::kModalD:
      return Value::of(modal.d);
    case sysvar::Id::kModalE:
      return Value::of(modal.e);
    case sysvar::Id::kModalF:
      return Value::of(modal.feed);
    case sysvar::Id::kModalH:
      return Value::of(modal.h);
    case sysvar::Id::kModalM:
      return Value::of(modal.last_m);
    case sysvar::Id::kModalN:
      return Value::of(modal.seq);
    case sysvar::Id::kModalO:
      return Value::of(
          static_cast<double>(programs.frames.empty() ? 0 : programs.frames.back().program));
    case sysvar::Id::kModalS:
      return Value::of(modal.spindle);
    case sysvar::Id::kModalT:
      return Value::of(modal.tool);
    default:  // kModalP
      return Value::of(modal.work > 6 ? modal.work - 6 : 0);
  }
}

// #3000-#3999: alarms, timers, control and part counts.
Value Interpreter::Impl::read_control(const sysvar::Range& r, int n) const {
  switch (r.id) {
    case sysvar::Id::kClockMs:
      return control_vars.timer_ms(last_sync.time_s);
    case sysvar::Id::kClockHours:
      return control_vars.timer_h(last_sync.time_s);
    case sysvar::Id::kControl:
      return control_vars.at(n - r.first);
    case sysvar::Id::kMirror:
      return Value::of(0.0);
    case sysvar::Id::kDate:
    case sysvar::Id::kTime: {
      // The host's local date (YYYYMMDD) and time (HHMMSS), as the control's clock.
      const std::time_t now = std::time(nullptr);
      std::tm tm{};
      localtime_r(&now, &tm);
      return Value::of(r.id == sysvar::Id::kDate
                           ? (tm.tm_year + 1900) * 10000.0 + (tm.tm_mon + 1) * 100.0 + tm.tm_mday
                           : tm.tm_hour * 10000.0 + tm.tm_min * 100.0 + tm.tm_sec);
    }
    case sysvar::Id::kPartsDone:
      return Value::of(static_cast<double>(parts_count));
    case sysvar::Id::kPartsRequired:
      return Value::of(static_cast<double>(parts_required));
    default:  // kAlarm, kMessageStop: written, read vacant
      return Value::null();
  }
}

// The tool offset number `k` of a tool-offset range names (memory C),
// nullptr when the machine has no such offset.
double* Interpreter::Impl::tool_field(const sysvar::Range& r, int k) noexcept {
  const int count = mc.tool_offset_count;
  const int slot = k - r.first + 1;
  if (slot > count) return nullptr;
  const bool short_table = r.id == sysvar::Id::kHWearShort || r.id == sysvar::Id::kHGeomShort;
  if (short_table && count > 200) return nullptr;
  config::ToolOffset& t = tools.write(static_cast<std::size_t>(slot));
  switch (r.id) {
    case sysvar::Id::kHWearShort:
    case sysvar::Id::kHWear:
      return &t.length_wear;
    case sysvar::Id::kHGeomShort:
    case sysvar::Id::kHGeom:
      return &t.length_geometry;
    case sysvar::Id::kDWear:
      return &t.radius_wear;
    default:  // kDGeom
      return &t.radius_geometry;
  }
}

Flow<void> Interpreter::Impl::write_var(int n, Value v, SourceLoc where) {
  return lang->write_param(*this, n, v, where);
}

Flow<void> Interpreter::Impl::write_macro_var(int n, Value v, SourceLoc where) {
  if (dialect.sw.haas_tool_offset_vars) n = haas_tool_var(n);
  if (VariableStore::is_local(n) || VariableStore::is_common(n) ||
      VariableStore::is_persistent(n)) {
    vars.set(n, v);
    return {};
  }
  if (n == 0) {
    return fail(AlarmId::kWriteProtected, "#0 is always vacant and cannot be written", where);
  }
  int k = 0;
  const sysvar::Range* r = sysvar::find(n, k);
  if (r != nullptr && (r->access & sysvar::kWrite)) {
    if (is_work_offset(r->id)) {
      int set = 0, axis = 0;
      work_offset_var(*r, k, set, axis);
      const int slot = axis;
      axis = offset_axis(*this, slot);
      if (axis < 0) return fail(AlarmId::kIllegalVariable, no_offset_axis(*this, n, slot), where);
      auto ok = check_offset(v.num() * unit_mm(), "#" + std::to_string(n), where);
      if (!ok) return ok;
      work_offsets.write(static_cast<std::size_t>(set))[axis] =
          v.num() * unit_mm() / offset_unit_mm(*this);
      return {};
    }
    if (r->id == sysvar::Id::kSettingError) {
      setting_error_data.write(std::size_t(k - r->first)) = v;  // G54.4 (conversion_3d.cpp)
      return {};
    }
    if (!is_tool(*r)) return write_control(*r, k, v, where);
    if (double* f = tool_field(*r, k)) {
      auto ok = check_offset(v.num() * unit_mm(), "#" + std::to_string(n), where);
      if (!ok) return ok;
      *f = v.num() * unit_mm() / offset_unit_mm(*this);
      return {};
    }
  }
  if (sysvar::is_protected(n)) {
    return fail(AlarmId::kWriteProtected, "#" + std::to_string(n) + " cannot be written", where);
  }
  return fail(AlarmId::kIllegalVariable,
              "#" + std::to_string(n) + " is not a variable of this control", where);
}

// #3000-#3999 that may be written.
Flow<void> Interpreter::Impl::write_control(const sysvar::Range& r, int n, Value v,
                                            SourceLoc where) {
  const auto comment = [&]() -> std::string {
    return blk.comments.empty() ? std::string()
                                : blk.names[static_cast<std::size_t>(blk.comments.front().text)];
  };
  switch (r.id) {
    case sysvar::Id::kAlarm: {
      // #3000 = n (MESSAGE): the program stops with alarm 3000 + n and the
      // block's comment as the message.
      const double a = std::round(v.num());
      if (a < 0 || a > 9999) {
        return fail(AlarmId::kIllegalArgument,
                    "#3000 = " + std::to_string(v.num()) + ": the alarm number is 0-9999", where);
      }
      return std::unexpected(Error{AlarmId::kUserAlarm, comment(), where, static_cast<int>(a)});
    }
    case sysvar::Id::kMessageStop: {
      // #3006 = n (MESSAGE): the control stops and shows the message until
      // cycle start; the simulation records the message and goes on.
      const std::string text = comment();
      add_message(text.empty() ? "#3006 = " + std::to_string(std::lround(v.num())) : text);
      return {};
    }
    case sysvar::Id::kClockMs:
      control_vars.set_timer_ms(last_sync.time_s, v.num());
      return {};
    case sysvar::Id::kClockHours:
      control_vars.set_timer_h(last_sync.time_s, v.num());
      return {};
    case sysvar::Id::kControl:
      // Single block / FIN wait (#3003), feed hold / override / exact stop
      // (#3004), settings (#3005): kept for reading back; the simulation
      // has no operator panel for them to act on.
      control_vars.at(n - r.first) = v;
      return {};
    case sysvar::Id::kPartsDone:
      parts_count = std::llround(v.num());
      return {};
    case sysvar::Id::kPartsRequired:
      parts_required = std::llround(v.num());
      return {};
    default:
      return fail(AlarmId::kInternal, "system variable table: no writer", where);
  }
}

Flow<Value> Interpreter::Impl::read_named_var(const std::string& name, SourceLoc where) {
  return lang->read_named(*this, name, where);
}

Flow<Value> Interpreter::Impl::read_macro_named(const std::string& name, SourceLoc where) {
  if (!name.empty() && name.front() == '_') {
    const int n = system_number(name);
    if (n > 0) return read_var(n, where);
    if (n < 0) return fail(AlarmId::kIllegalVariable, "#" + name + ": bad index", where);
  }
  return vars.get_named(name);
}

Flow<void> Interpreter::Impl::write_named_var(const std::string& name, Value v, SourceLoc where) {
  return lang->write_named(*this, name, v, where);
}

Flow<void> Interpreter::Impl::write_macro_named(const std::string& name, Value v, SourceLoc where) {
  if (!name.empty() && name.front() == '_') {
    const int n = system_number(name);
    if (n > 0) return write_var(n, v, where);
    if (n < 0) return fail(AlarmId::kIllegalVariable, "#" + name + ": bad index", where);
  }
  const auto& sv = dialect.skip_vars;
  if ((!sv.named_machine.empty() && name.starts_with(sv.named_machine)) ||
      (!sv.named_local.empty() && name.starts_with(sv.named_local))) {
    return fail(AlarmId::kWriteProtected, "#<" + name + "> is set by the skip function", where);
  }
  if (!vars.has_named(name) &&
      static_cast<std::int64_t>(vars.named_count()) >= mc.limits.max_named_variables) {
    return fail(AlarmId::kNamedVariableLimit,
                "#<" + name + ">: more than limits.max_named_variables = " +
                    std::to_string(mc.limits.max_named_variables) + " named variables",
                where);
  }
  vars.set_named(name, v);
  return {};
}

}  // namespace skipnc::interp
