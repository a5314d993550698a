#include "run/scenario.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <memory>

#include "config/skip_inputs.hpp"
#include "interpreter/interpreter.hpp"
#include "run/plot.hpp"
#include "run/program_run.hpp"

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

report::ReportInput report_input(const Session& s, std::string program, sim::RunResult result) {
  report::ReportInput in;
  in.program = std::move(program);
  in.dialect = s.dialect.name;
  in.machine = &s.machine;
  in.dialect_table = &s.dialect;
  in.result = std::move(result);
  return in;
}

std::vector<std::pair<std::string, std::optional<double>>> read_variables(
    const interp::Interpreter& in, const std::vector<VarRef>& refs) {
  std::vector<std::pair<std::string, std::optional<double>>> out;
  for (const auto& var : refs) {
    Result<interp::Value> val =
        var.name.empty() ? in.read_variable(var.number) : in.read_named(var.name);
    std::optional<double> x;
    if (val && !val->vacant) x = val->v;
    out.emplace_back(var.key, x);
  }
  return out;
}

Result<std::vector<ExpectResult>> check_outcome(const config::Dialect& d,
                                                const std::vector<Expectation>& expects,
                                                const sim::RunResult& r,
                                                const interp::Interpreter& in) {
  ObservedRun got;
  got.status = report::status_name(r.status);
  if (r.alarm) {
    const report::AlarmView v = report::view_alarm(*r.alarm, &d);
    got.alarm = v.number;
    got.alarm_code = v.code;
    got.alarm_key = std::string(alarm_key(r.alarm->id));
  }
  std::vector<VarRef> refs;
  for (const auto& e : expects) {
    if (e.kind != Expectation::Kind::kVariable) continue;
    auto ref = parse_var_ref("#" + e.var);
    SKIPNC_TRY(ref);
    refs.push_back(*ref);
  }
  got.variables = read_variables(in, refs);
  std::vector<ExpectResult> checks;
  for (const auto& e : expects) checks.push_back(evaluate_expectation(e, got));
  return checks;
}

int exit_code(sim::RunStatus status, bool output_failed, const std::vector<Expectation>& expects,
              const std::vector<ExpectResult>& checks) {
  int rc = status == sim::RunStatus::kCompleted && !output_failed ? 0 : 1;
  if (expects.empty()) return rc;
  bool outcome_expected = false;
  for (const auto& e : expects) outcome_expected |= e.kind != Expectation::Kind::kVariable;
  bool all_held = true;
  for (const auto& c : checks) all_held = all_held && c.pass;
  if (outcome_expected && all_held && !output_failed) rc = 0;
  if (!all_held) rc = 3;
  return rc;
}

namespace {

// The variation's changes to the copies `m` and `params`, checked; the
// starting variables (the persistent file's, then the variation's).
Result<std::vector<std::pair<int, double>>> prepare(const Session& s, const RunRequest& rq,
                                                    const Variation& v, config::MachineConfig& m,
                                                    config::Parameters& params) {
  SKIPNC_TRY(apply_offsets(m, v));
  for (const auto& p : v.params) SKIPNC_TRY(params.apply(p));
  if (!v.params.empty()) SKIPNC_TRY(config::check_skip_addresses(s.dialect, params));
  // alarm=NAME names an alarm of the dialect (as `skipnc run --expect`).
  for (const auto& e : rq.expect) SKIPNC_TRY(check_alarm_name(e, s.dialect));
  SKIPNC_TRY(check_plot_files(rq.plot_files));
  std::vector<std::pair<int, double>> variables;
  SKIPNC_TRY(take_persistent(m, variables));
  variables.insert(variables.end(), v.variables.begin(), v.variables.end());
  return variables;
}

}  // namespace

void setup_program(const RunRequest& rq, interp::Setup& setup) {
  setup.program_path = rq.program_path;
  setup.program_text = rq.program_text;
  setup.program_name = rq.program_name.empty() ? rq.program_path : rq.program_name;
  if (setup.program_name.empty()) setup.program_name = "program";
  setup.include_dirs = rq.include_dirs;
  setup.strict = rq.strict;
  setup.strict_allow = rq.allow;
}

Result<void> take_persistent(config::MachineConfig& m,
                             std::vector<std::pair<int, double>>& variables) {
  if (m.persistent_vars.empty()) return {};
  std::array<interp::Value, 500> kept{};
  if (auto r = interp::load_persistent(m.persistent_vars, kept); !r) return r;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (!kept[i].vacant) variables.emplace_back(static_cast<int>(i) + 500, kept[i].v);
  }
  m.persistent_vars.clear();
  return {};
}

Result<RunOutcome> run_variation(const Session& s, const RunRequest& rq, const Variation& v,
                                 sim::TraceSink* trace, const std::atomic<bool>* interrupt,
                                 bool with_report) {
  config::MachineConfig m = s.machine;
  config::Parameters params = *s.params;
  auto variables = prepare(s, rq, v, m, params);
  SKIPNC_TRY(variables);
  const machine::Scene scene = varied_scene(s.scene, m, v);
  const Rig rig{&m, &s.dialect, &params, &scene};
  RunIO io;
  io.trace = trace;
  io.interrupt = interrupt;
  ProgramRun pr(rig, make_setup(s, rig, rq, io, std::move(*variables)), io, !rq.plot_files.empty());
  auto res = pr.run();
  SKIPNC_TRY(res);
  auto c = pr.conclude(s, std::move(*res), rq, pr.setup().program_name);
  SKIPNC_TRY(c);
  const report::ReportInput& in = c->report;
  RunOutcome out;
  out.output_failed = c->output_failed;
  out.status = in.result.status;
  out.time_s = in.result.time_s;
  if (in.result.alarm) {
    const report::AlarmView view = report::view_alarm(*in.result.alarm, &s.dialect);
    out.alarm = view.number;
    out.alarm_code = view.code;
    out.alarm_key = std::string(alarm_key(in.result.alarm->id));
    out.alarm_text = describe(*in.result.alarm, &s.dialect);
  }
  for (const auto& check : in.expectations) {
    if (!check.pass) out.failed_expectations.push_back(check.message);
  }
  out.exit_code = c->exit_code;
  if (with_report) out.report_json = report::to_json(in);
  out.variables = in.variables;
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
