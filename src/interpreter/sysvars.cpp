// System variables of Custom Macro B (Fanuc numbering; other dialects map
// their names onto the same state):
//   #3000 alarm (write), #3001 ms timer, #3002 hour timer, #3006 stop with message,
//   #3901/#3902 parts, #4001-#4022 modal G of each group, #4102-#4120 B D F H M N O S T,
//   #5001.. block end point, #5021.. machine position, #5041.. work position,
//   #5061.. skip position, #5081.. tool length offset, #5101.. following error,
//   #5201.. work offsets (EXT, then G54-G59 every 20),
//   #2001-#2200 H wear, #2201-#2400 H geometry (200 offsets or fewer),
//   #10001.. H wear, #11001.. H geometry, #12001.. D wear, #13001.. D geometry.
#include <cmath>

#include "interpreter/impl.hpp"

namespace skipnc::interp {
namespace {

bool is_position_var(int n) {
  return (n >= 5021 && n <= 5028) || (n >= 5041 && n <= 5048) || (n >= 5101 && n <= 5108) ||
         n == 3001 || n == 3002;
}

}  // namespace

Result<Value> Interpreter::Impl::read_var(int n, SourceLoc where) {
  if (n == 0) return Value::null();
  if (n < 0) return fail(AlarmId::kIllegalVariable, "#" + std::to_string(n), where);
  if (VariableStore::is_local(n) || VariableStore::is_common(n) ||
      VariableStore::is_persistent(n)) {
    return vars.get(n);
  }
  if (is_position_var(n) && motion_since_sync) {
    // Buffer stop: the value is the one after the queued motion has ended.
    need_sync = true;
    return fail(AlarmId::kInternal, "sync");
  }
  const auto axis_in = [&](int base) { return n - base; };
  if (n >= 5001 && n <= 5008) {
    const int i = axis_in(5001);
    if (i >= axis_count) return Value::null();
    return Value::of(work_of(i, pos[i]));
  }
  if (n >= 5021 && n <= 5028) {
    const int i = axis_in(5021);
    if (i >= axis_count) return Value::null();
    return Value::of(pos[i] / unit_mm());
  }
  if (n >= 5041 && n <= 5048) {
    const int i = axis_in(5041);
    if (i >= axis_count) return Value::null();
    return Value::of(work_of(i, pos[i]));
  }
  if (n >= 5061 && n <= 5068) {
    const int i = axis_in(5061);
    if (i >= axis_count) return Value::null();
    if (!have_skip) return Value::of(0.0);
    return Value::of(skip_work[i]);
  }
  if (n >= 5081 && n <= 5088) {
    const int i = axis_in(5081);
    if (i >= axis_count) return Value::null();
    return Value::of(i == length_axis ? length_offset / unit_mm() : 0.0);
  }
  if (n >= 5101 && n <= 5108) {
    const int i = axis_in(5101);
    if (i >= axis_count) return Value::null();
    return Value::of((last_sync.machine_position[i] - last_sync.actual_position[i]) / unit_mm());
  }
  if (n >= 5201 && n <= 5328) {
    const int set = (n - 5201) / 20;
    const int i = (n - 5201) % 20;
    if (i >= axis_count) return Value::null();
    return Value::of(work_offsets[static_cast<std::size_t>(set)][i] / unit_mm());
  }
  if (n >= 4001 && n <= 4022) return Value::of(g_code_of_group(modal, n - 4000) / 10.0);
  switch (n) {
    case 3000:
    case 3006:
      return Value::null();
    case 3001:
      return Value::of(std::floor(last_sync.time_s * 1000.0 - timer_ms_base));
    case 3002:
      return Value::of(last_sync.time_s / 3600.0 - timer_h_base);
    case 3901:
      return Value::of(static_cast<double>(parts_count));
    case 3902:
      return Value::of(static_cast<double>(parts_required));
    case 4107:
      return Value::of(modal.d);
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
    default:
      break;
  }
  const int count = mc.tool_offset_count;
  auto tool_var = [&](int base, int limit) -> int {
    return (n >= base + 1 && n <= base + limit) ? n - base : 0;
  };
  if (count <= 200) {
    if (int k = tool_var(2000, 200); k > 0 && k <= count) return Value::of(tools[static_cast<std::size_t>(k)].length_wear / unit_mm());
    if (int k = tool_var(2200, 200); k > 0 && k <= count) return Value::of(tools[static_cast<std::size_t>(k)].length_geometry / unit_mm());
  }
  if (int k = tool_var(10000, 999); k > 0 && k <= count) return Value::of(tools[static_cast<std::size_t>(k)].length_wear / unit_mm());
  if (int k = tool_var(11000, 999); k > 0 && k <= count) return Value::of(tools[static_cast<std::size_t>(k)].length_geometry / unit_mm());
  if (int k = tool_var(12000, 999); k > 0 && k <= count) return Value::of(tools[static_cast<std::size_t>(k)].radius_wear / unit_mm());
  if (int k = tool_var(13000, 999); k > 0 && k <= count) return Value::of(tools[static_cast<std::size_t>(k)].radius_geometry / unit_mm());
  return fail(AlarmId::kIllegalVariable, "#" + std::to_string(n) + " is not a variable of this control",
              where);
}

Result<void> Interpreter::Impl::write_var(int n, Value v, SourceLoc where) {
  if (VariableStore::is_local(n) || VariableStore::is_common(n) ||
      VariableStore::is_persistent(n)) {
    vars.set(n, v);
    return {};
  }
  if (n == 3000) {
    Error e{AlarmId::kUserAlarm, "", where, static_cast<int>(std::lround(v.num()))};
    // The message is the comment of the block: #3000 = 1 (PROBE OPEN)
    if (!blk.comments.empty()) e.detail = blk.names[static_cast<std::size_t>(blk.comments.front().text)];
    return std::unexpected(e);
  }
  if (n == 3006) {
    std::string text = "#3006";
    if (!blk.comments.empty()) text = blk.names[static_cast<std::size_t>(blk.comments.front().text)];
    messages.push_back(text);
    return {};
  }
  if (n == 3001) {
    timer_ms_base = last_sync.time_s * 1000.0 - v.num();
    return {};
  }
  if (n == 3002) {
    timer_h_base = last_sync.time_s / 3600.0 - v.num();
    return {};
  }
  if (n == 3901) {
    parts_count = std::llround(v.num());
    return {};
  }
  if (n == 3902) {
    parts_required = std::llround(v.num());
    return {};
  }
  if (n >= 5201 && n <= 5328) {
    const int set = (n - 5201) / 20;
    const int i = (n - 5201) % 20;
    if (i >= axis_count) return fail(AlarmId::kIllegalVariable, "#" + std::to_string(n), where);
    work_offsets[static_cast<std::size_t>(set)][i] = v.num() * unit_mm();
    return {};
  }
  const int count = mc.tool_offset_count;
  auto tool_slot = [&](int base, int limit) -> int {
    return (n >= base + 1 && n <= base + limit && n - base <= count) ? n - base : 0;
  };
  double* field = nullptr;
  if (count <= 200) {
    if (int k = tool_slot(2000, 200)) field = &tools[static_cast<std::size_t>(k)].length_wear;
    else if (int k2 = tool_slot(2200, 200)) field = &tools[static_cast<std::size_t>(k2)].length_geometry;
  }
  if (field == nullptr) {
    if (int k = tool_slot(10000, 999)) field = &tools[static_cast<std::size_t>(k)].length_wear;
    else if (int k2 = tool_slot(11000, 999)) field = &tools[static_cast<std::size_t>(k2)].length_geometry;
    else if (int k3 = tool_slot(12000, 999)) field = &tools[static_cast<std::size_t>(k3)].radius_wear;
    else if (int k4 = tool_slot(13000, 999)) field = &tools[static_cast<std::size_t>(k4)].radius_geometry;
  }
  if (field != nullptr) {
    *field = v.num() * unit_mm();
    return {};
  }
  if ((n >= 4001 && n <= 4130) || (n >= 5001 && n <= 5108) || (n >= 3000 && n < 4000)) {
    return fail(AlarmId::kWriteProtected, "#" + std::to_string(n) + " cannot be written", where);
  }
  return fail(AlarmId::kIllegalVariable, "#" + std::to_string(n) + " is not a variable of this control",
              where);
}

Result<Value> Interpreter::Impl::read_named_var(const std::string& name, SourceLoc where) {
  (void)where;
  return vars.get_named(name);
}

Result<void> Interpreter::Impl::write_named_var(const std::string& name, Value v, SourceLoc where) {
  const auto& sv = dialect.skip_vars;
  if ((!sv.named_machine.empty() && name.starts_with(sv.named_machine)) ||
      (!sv.named_local.empty() && name.starts_with(sv.named_local))) {
    return fail(AlarmId::kWriteProtected, "#<" + name + "> is set by the skip function", where);
  }
  vars.set_named(name, v);
  return {};
}

}  // namespace skipnc::interp
