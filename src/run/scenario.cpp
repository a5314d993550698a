#include "run/scenario.hpp"

#include <array>
#include <cstdio>
#include <fstream>

#include "config/skip_inputs.hpp"
#include "interpreter/variables.hpp"

namespace skipnc::run {
namespace {

// The scene with the parts, triggers and stops moved and the probe's scatter
// changed.
machine::Scene varied_scene(const machine::Scene& base, const config::MachineConfig& m,
                            const Variation& v) {
  machine::Scene sc = base;
  const machine::geo::Vec3 d{v.part_shift[0], v.part_shift[1], v.part_shift[2]};
  if (d != machine::geo::Vec3{}) {
    // A part's shapes are in its own frame (docs/scene.md, frames): moving
    // the part in machine coordinates moves the frame's origin.
    // On a rotary table the part moves on the table: by d at the table's zero.
    for (auto& part : sc.probing.parts) {
      part.place.origin = part.place.origin + d;
      auto& r = part.rotary;
      if (r.turns()) r.inner.origin = r.inner.origin + r.table.unturn(d);
    }
    auto along = [&](int axis) {
      const char name = m.axes[static_cast<std::size_t>(axis)].name;
      return name == 'X' ? d.x : name == 'Y' ? d.y : name == 'Z' ? d.z : 0.0;
    };
    for (auto& t : sc.triggers) t.at += along(t.axis);
    for (auto& st : sc.stops) st.at += along(st.axis);
  }
  if (sc.probing.probe) {
    if (v.probe_seed) sc.probing.probe->seed = *v.probe_seed;
    if (v.probe_repeatability) sc.probing.probe->repeatability = *v.probe_repeatability;
  }
  return sc;
}

Result<void> apply_offsets(config::MachineConfig& m, const Variation& v) {
  for (const auto& w : v.work_offsets) {
    if (w.set < 0 || w.set >= static_cast<int>(m.work_offsets.size()) || w.axis < 0 ||
        w.axis >= m.axis_count()) {
      return fail(AlarmId::kUsage, "work offset set " + std::to_string(w.set) + " axis " +
                                       std::to_string(w.axis) + " does not exist");
    }
    m.work_offsets[static_cast<std::size_t>(w.set)][w.axis] = w.value;
  }
  for (const auto& t : v.tool_offsets) {
    if (t.number < 1 || t.number > m.tool_offset_count) {
      return fail(AlarmId::kUsage, "tool offset " + std::to_string(t.number) +
                                       " does not exist (1-" + std::to_string(m.tool_offset_count) +
                                       ")");
    }
    config::ToolOffset& o = m.tool_offsets[t.number];
    switch (t.which) {
      case ToolValue::kLengthGeometry:
        o.length_geometry = t.value;
        break;
      case ToolValue::kLengthWear:
        o.length_wear = t.value;
        break;
      case ToolValue::kRadiusGeometry:
        o.radius_geometry = t.value;
        break;
      case ToolValue::kRadiusWear:
        o.radius_wear = t.value;
        break;
    }
  }
  return {};
}

}  // namespace

Result<RunOutcome> run_variation(const Session& s, const RunRequest& rq, const Variation& v,
                                 sim::TraceSink* trace, const std::atomic<bool>* interrupt) {
  config::MachineConfig m = s.machine;
  if (auto r = apply_offsets(m, v); !r) return std::unexpected(r.error());
  config::Parameters params = *s.params;
  for (const auto& p : v.params) {
    if (auto r = params.apply(p); !r) return std::unexpected(r.error());
  }
  if (!v.params.empty()) {
    if (auto r = config::check_skip_addresses(s.dialect, params); !r) {
      return std::unexpected(r.error());
    }
  }
  interp::Setup setup;
  // #500-#999 from the machine's file are read, never written back: runs in
  // parallel must not write one file.
  if (!m.persistent_vars.empty()) {
    std::array<interp::Value, 500> kept{};
    if (auto r = interp::load_persistent(m.persistent_vars, kept); !r) {
      return std::unexpected(r.error());
    }
    for (std::size_t i = 0; i < kept.size(); ++i) {
      if (!kept[i].vacant) setup.variables.emplace_back(static_cast<int>(i) + 500, kept[i].v);
    }
    m.persistent_vars.clear();
  }
  setup.variables.insert(setup.variables.end(), v.variables.begin(), v.variables.end());
  const machine::Scene scene = varied_scene(s.scene, m, v);
  setup.machine = &m;
  setup.dialect = &s.dialect;
  setup.params = &params;
  setup.program_path = rq.program_path;
  setup.program_text = rq.program_text;
  setup.program_name = rq.program_name.empty() ? rq.program_path : rq.program_name;
  if (setup.program_name.empty()) setup.program_name = "program";
  setup.include_dirs = rq.include_dirs;

  sim::Simulator sim(m, s.dialect, params, scene);
  sim::RunOptions opts;
  opts.trace = trace;
  opts.interrupt = interrupt;
  auto res = sim.run(setup, opts);
  if (!res) return std::unexpected(res.error());
  report::ReportInput in;
  in.program = setup.program_name;
  in.dialect = s.dialect.name;
  in.machine = &s.machine;
  in.dialect_table = &s.dialect;
  in.result = std::move(*res);
  for (const auto& var : rq.vars) {
    Result<interp::Value> val = var.name.empty() ? sim.interpreter()->read_variable(var.number)
                                                 : sim.interpreter()->read_named(var.name);
    std::optional<double> x;
    if (val && !val->vacant) x = val->v;
    in.variables.emplace_back(var.key, x);
  }
  RunOutcome out;
  out.report_json = report::to_json(in);
  out.status = in.result.status;
  out.time_s = in.result.time_s;
  if (in.result.alarm) {
    out.alarm = report::view_alarm(*in.result.alarm, &s.dialect).number;
    out.alarm_text = describe(*in.result.alarm, &s.dialect);
  }
  out.variables = std::move(in.variables);
  out.exit_code = in.result.status == sim::RunStatus::kCompleted ? 0 : 1;
  return out;
}

Result<std::vector<std::pair<int, double>>> load_variable_file(const std::string& path) {
  std::ifstream f(path);
  if (!f) return fail(AlarmId::kConfig, "cannot read variable file '" + path + "'");
  std::vector<std::pair<int, double>> out;
  std::string line;
  std::uint32_t lineno = 0;
  while (std::getline(f, line)) {
    ++lineno;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == ';') continue;
    int n = 0;
    double x = 0.0;
    char tail = 0;
    if (std::sscanf(line.c_str() + first, "#%d = %lf %c", &n, &x, &tail) != 2 ||
        !(interp::VariableStore::is_local(n) || interp::VariableStore::is_common(n) ||
          interp::VariableStore::is_persistent(n))) {
      return fail(AlarmId::kConfig,
                  "line is not '#<n> = <number>' with n in 1-33, 100-199, 500-999",
                  SourceLoc{path, lineno, 1});
    }
    out.emplace_back(n, x);
  }
  return out;
}

}  // namespace skipnc::run
