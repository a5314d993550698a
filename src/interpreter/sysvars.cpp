// System variables of Custom Macro B, Fanuc numbering (docs/macro.md has
// the table with what each one gives here):
//   #3000 alarm (write), #3001 ms timer, #3002 hour timer, #3003/#3004
//   execution control (kept, no effect), #3005 settings (kept), #3006 stop
//   with message, #3007 mirror image (0), #3011/#3012 date and time,
//   #3901/#3902 parts, #4001-#4022 modal G of each group, #4102-#4130
//   B D E F H M N O S T P (also #4201-#4330), #5001.. block end point,
//   #5021.. machine position, #5041.. work position, #5061.. skip position,
//   #5081.. tool length offset, #5101.. following error, #5201-#5340 work
//   offsets (EXT, then G54-G59 every 20), #2500-#2806 the older numbering of
//   the same, #7001-#7960 G54.1 P1-P48 and #14001-#19980 G54.1 P1-P300,
//   tool offsets memory C: #10001.. H wear, #11001.. H geometry, #12001.. D
//   wear, #13001.. D geometry, and #2001-#2200 / #2201-#2400 for H wear /
//   geometry when the machine has 200 offsets or fewer.
// Positions are in the program's units (G20: inch).
#include <cmath>
#include <ctime>

#include "interpreter/impl.hpp"

namespace skipnc::interp {
namespace {

// Values that change while the axes move: reading one after a move waits
// for the move to end (buffer stop).
bool is_live(int n) {
  return (n >= 5021 && n <= 5028) || (n >= 5041 && n <= 5048) || (n >= 5101 && n <= 5108) ||
         n == 3001 || n == 3002;
}

// The G code reported for a modal group this interpreter does not model:
// the group's power-on state of a Fanuc M-series control. 0: no such group.
int default_g_of_group(int group) {
  switch (group) {
    case 4:
      return 220;  // G22 stored stroke check on
    case 11:
      return 500;  // G50 scaling off
    case 13:
      return 970;  // G97 constant surface speed off
    case 16:
      return 690;  // G69 rotation off
    case 17:
      return 150;  // G15 polar coordinates off
    case 18:
      return 501;  // G50.1 programmable mirror image off
    case 19:
      return 401;  // G40.1 normal direction control off
    case 21:
      return 131;  // G13.1 polar coordinate interpolation off
    default:
      return 0;
  }
}

// A work-offset variable: which set (0 EXT, 1-6 G54-G59, 7.. G54.1 P1..)
// and which axis; false when `n` is not one.
bool work_offset_var(int n, int& set, int& axis) {
  if (n >= 5201 && n <= 5340) {
    set = (n - 5201) / 20;
    axis = (n - 5201) % 20;
    return true;
  }
  if (n >= 2500 && n <= 2806 && (n % 100) <= 6) {
    set = n % 100;
    axis = n / 100 - 25;
    return true;
  }
  if (n >= 7001 && n <= 7960) {
    set = 7 + (n - 7001) / 20;
    axis = (n - 7001) % 20;
    return true;
  }
  if (n >= 14001 && n <= 19980) {
    set = 7 + (n - 14001) / 20;
    axis = (n - 14001) % 20;
    return true;
  }
  return false;
}

// Fanuc 30i system variable names (#_NAME, #_NAME[i]) and their numbers.
struct SysName {
  std::string_view name;
  int number;  // the variable, or the base of [i] (number + i)
  int count;   // 0: no index; else i = 1..count
};

constexpr SysName kSysNames[] = {
    {"_ALM", 3000, 0},    {"_CLOCK1", 3001, 0}, {"_CLOCK2", 3002, 0}, {"_MSGSTP", 3006, 0},
    {"_DATE", 3011, 0},   {"_TIME", 3012, 0},   {"_PRTSA", 3901, 0},  {"_PRTSN", 3902, 0},
    {"_ABSIO", 5000, 8},  {"_ABSMT", 5020, 8},  {"_ABSOT", 5040, 8},  {"_ABSKP", 5060, 8},
    {"_TOFSWZ", 5080, 8}, {"_SRVO", 5100, 8},   {"_WZCMN", 5200, 20}, {"_WZG54", 5220, 20},
    {"_WZG55", 5240, 20}, {"_WZG56", 5260, 20}, {"_WZG57", 5280, 20}, {"_WZG58", 5300, 20},
    {"_WZG59", 5320, 20},
};

// Number of the system variable `name` ("_ABSKP[3]"), 0 when it is not one,
// -1 when the name is known but the index is not valid.
int system_number(std::string_view name) {
  const std::size_t open = name.find('[');
  const std::string_view base = name.substr(0, open);
  for (const SysName& s : kSysNames) {
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

Flow<Value> Interpreter::Impl::read_var(int n, SourceLoc where) {
  if (n == 0) return Value::null();
  if (n < 0) return fail(AlarmId::kIllegalVariable, "#" + std::to_string(n), where);
  if (VariableStore::is_local(n) || VariableStore::is_common(n) ||
      VariableStore::is_persistent(n)) {
    return vars.get(n);
  }
  if (is_live(n) && motion_since_sync) {
    // Buffer stop: the value is the one after the queued motion has ended.
    return need_sync();
  }
  const auto axis_value = [&](int base, auto&& f) -> Value {
    const int i = n - base;
    if (i >= axis_count) return Value::null();
    return Value::of(f(i) + 0.0);
  };
  // Tool offsets in or out of each, per dialect (docs/position-variables.md).
  const auto& sw = dialect.sw;
  if (n >= 5001 && n <= 5008) {
    return axis_value(5001,
                      [&](int i) { return position_var(i, pos[i], sw.block_end_tool_offsets); });
  }
  // Lengths in program values: an X axis in diameter reads in diameter.
  const auto scale = [&](int i) { return axis_scale[static_cast<std::size_t>(i)]; };
  // #5021.. and #5041.. are where the tool is: under cutter compensation
  // the programmed point plus the offset vector (docs/cutter-compensation.md).
  const auto tool = [&](int i) { return pos[i] + comp.vector()[i]; };
  if (n >= 5021 && n <= 5028) {
    // Machine lock and Z-axis cancel: the machine does not move, and its
    // machine coordinates stay where it is (the work position follows the
    // program).
    const bool lock =
        dialect.sw.machine_lock_param != 0 && params.get(dialect.sw.machine_lock_param) != 0.0;
    const bool z_cancel =
        dialect.sw.z_cancel_param != 0 && params.get(dialect.sw.z_cancel_param) != 0.0;
    return axis_value(5021, [&](int i) {
      const bool held = lock || (z_cancel && axis_letter[static_cast<std::size_t>(i)] == 'Z');
      return (held ? last_sync.actual_position[i] : tool(i)) * scale(i) / unit_mm();
    });
  }
  if (n >= 5041 && n <= 5048) {
    return axis_value(5041,
                      [&](int i) { return position_var(i, tool(i), sw.current_tool_offsets); });
  }
  if (n >= 5061 && n <= 5068) {
    if (skip_missed_unread && where.line != 0) {
      skip_missed_unread = false;
      auto w = warn("skip_missed_read",
                    "#" + std::to_string(n) + " read after the skip of line " +
                        std::to_string(skip_missed_line) +
                        " ran to its end point without a signal: it holds that end point, not "
                        "a touch",
                    where);
      if (!w) return std::unexpected(w.error());
    }
    return axis_value(5061, [&](int i) { return have_skip ? skip_work[i] : 0.0; });
  }
  if (n >= 5081 && n <= 5088) {
    return axis_value(5081,
                      [&](int i) { return i == length_axis ? length_offset / unit_mm() : 0.0; });
  }
  if (n >= 5101 && n <= 5108) {
    return axis_value(5101, [&](int i) {
      return (last_sync.machine_position[i] - last_sync.actual_position[i]) * scale(i) / unit_mm();
    });
  }
  if (int set = 0, axis = 0; work_offset_var(n, set, axis)) {
    if (axis >= axis_count) return Value::null();
    return Value::of(work_offsets[static_cast<std::size_t>(set)][axis] / unit_mm() + 0.0);
  }
  // Modal information: #4001-#4130 (blocks read so far) and #4201-#4330
  // (the block executing) are the same here: blocks run one at a time.
  const int m = n >= 4201 && n <= 4330 ? n - 200 : n;
  if (m >= 4001 && m <= 4022) {
    const int group = m - 4000;
    if (group == 14 && modal.work > 6) return Value::of(54.1);
    int code = g_code_of_group(modal, group);
    if (code == 0 && group != 1) code = default_g_of_group(group);
    if (code == 0 && group != 1) return Value::null();
    return Value::of(code / 10.0);
  }
  switch (m) {
    case 4102:
      return Value::of(0.0);
    case 4107:
      return Value::of(modal.d);
    case 4108:
      return Value::of(last_e);
    case 4109:
      return Value::of(modal.feed);
    case 4111:
      return Value::of(modal.h);
    case 4113:
      return Value::of(modal.last_m);
    case 4114:
      return Value::of(modal.seq);
    case 4115:
      return Value::of(static_cast<double>(frames.empty() ? 0 : frames.back().program));
    case 4119:
      return Value::of(modal.spindle);
    case 4120:
      return Value::of(modal.tool);
    case 4130:
      return Value::of(modal.work > 6 ? modal.work - 6 : 0);
    default:
      break;
  }
  switch (n) {
    case 3000:
    case 3006:
      return Value::null();
    case 3001:
      return Value::of(std::floor(last_sync.time_s * 1000.0 - timer_ms_base) + 0.0);
    case 3002:
      return Value::of(last_sync.time_s / 3600.0 - timer_h_base + 0.0);
    case 3003:
    case 3004:
    case 3005:
      return control_vars[static_cast<std::size_t>(n - 3003)];
    case 3007:
      return Value::of(0.0);
    case 3011:
    case 3012: {
      // The host's local date (YYYYMMDD) and time (HHMMSS), as the control's clock.
      const std::time_t now = std::time(nullptr);
      std::tm tm{};
      localtime_r(&now, &tm);
      return Value::of(n == 3011
                           ? (tm.tm_year + 1900) * 10000.0 + (tm.tm_mon + 1) * 100.0 + tm.tm_mday
                           : tm.tm_hour * 10000.0 + tm.tm_min * 100.0 + tm.tm_sec);
    }
    case 3901:
      return Value::of(static_cast<double>(parts_count));
    case 3902:
      return Value::of(static_cast<double>(parts_required));
    default:
      break;
  }
  if (double* f = tool_field(n)) return Value::of(*f / unit_mm() + 0.0);
  return fail(AlarmId::kIllegalVariable,
              "#" + std::to_string(n) + " is not a variable of this control", where);
}

// The tool offset a variable names (memory C), nullptr when none.
double* Interpreter::Impl::tool_field(int n) noexcept {
  const int count = mc.tool_offset_count;
  auto slot = [&](int base, int limit) -> int {
    return (n > base && n <= base + limit && n - base <= count) ? n - base : 0;
  };
  auto at = [&](int k) -> config::ToolOffset& { return tools[static_cast<std::size_t>(k)]; };
  if (count <= 200) {
    if (int k = slot(2000, 200)) return &at(k).length_wear;
    if (int k = slot(2200, 200)) return &at(k).length_geometry;
  }
  if (int k = slot(10000, 999)) return &at(k).length_wear;
  if (int k = slot(11000, 999)) return &at(k).length_geometry;
  if (int k = slot(12000, 999)) return &at(k).radius_wear;
  if (int k = slot(13000, 999)) return &at(k).radius_geometry;
  return nullptr;
}

Flow<void> Interpreter::Impl::write_var(int n, Value v, SourceLoc where) {
  if (VariableStore::is_local(n) || VariableStore::is_common(n) ||
      VariableStore::is_persistent(n)) {
    vars.set(n, v);
    return {};
  }
  const auto comment = [&]() -> std::string {
    return blk.comments.empty() ? std::string()
                                : blk.names[static_cast<std::size_t>(blk.comments.front().text)];
  };
  switch (n) {
    case 0:
      return fail(AlarmId::kWriteProtected, "#0 is always vacant and cannot be written", where);
    case 3000: {
      // #3000 = n (MESSAGE): the program stops with alarm 3000 + n and the
      // block's comment as the message.
      const double a = std::round(v.num());
      if (a < 0 || a > 9999) {
        return fail(AlarmId::kIllegalArgument,
                    "#3000 = " + std::to_string(v.num()) + ": the alarm number is 0-9999", where);
      }
      return std::unexpected(Error{AlarmId::kUserAlarm, comment(), where, static_cast<int>(a)});
    }
    case 3006: {
      // #3006 = n (MESSAGE): the control stops and shows the message until
      // cycle start; the simulation records the message and goes on.
      const std::string text = comment();
      add_message(text.empty() ? "#3006 = " + std::to_string(std::lround(v.num())) : text);
      return {};
    }
    case 3001:
      timer_ms_base = last_sync.time_s * 1000.0 - v.num();
      return {};
    case 3002:
      timer_h_base = last_sync.time_s / 3600.0 - v.num();
      return {};
    case 3003:
    case 3004:
    case 3005:
      // Single block / FIN wait (#3003), feed hold / override / exact stop
      // (#3004), settings (#3005): kept for reading back; the simulation
      // has no operator panel for them to act on.
      control_vars[static_cast<std::size_t>(n - 3003)] = v;
      return {};
    case 3901:
      parts_count = std::llround(v.num());
      return {};
    case 3902:
      parts_required = std::llround(v.num());
      return {};
    default:
      break;
  }
  if (int set = 0, axis = 0; work_offset_var(n, set, axis)) {
    if (axis >= axis_count) {
      return fail(AlarmId::kIllegalVariable,
                  "#" + std::to_string(n) + ": the machine has no axis " + std::to_string(axis + 1),
                  where);
    }
    work_offsets[static_cast<std::size_t>(set)][axis] = v.num() * unit_mm();
    return {};
  }
  if (double* f = tool_field(n)) {
    *f = v.num() * unit_mm();
    return {};
  }
  if ((n >= 4001 && n <= 4330) || (n >= 5001 && n <= 5108) || (n >= 3000 && n < 4000)) {
    return fail(AlarmId::kWriteProtected, "#" + std::to_string(n) + " cannot be written", where);
  }
  return fail(AlarmId::kIllegalVariable,
              "#" + std::to_string(n) + " is not a variable of this control", where);
}

Flow<Value> Interpreter::Impl::read_named_var(const std::string& name, SourceLoc where) {
  if (!name.empty() && name.front() == '_') {
    const int n = system_number(name);
    if (n > 0) return read_var(n, where);
    if (n < 0) return fail(AlarmId::kIllegalVariable, "#" + name + ": bad index", where);
  }
  return vars.get_named(name);
}

Flow<void> Interpreter::Impl::write_named_var(const std::string& name, Value v, SourceLoc where) {
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
