#include "run/sweep.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <condition_variable>
#include <filesystem>
#include <limits>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <numbers>
#include <thread>

#include "config/toml_util.hpp"
#include "core/file.hpp"
#include "core/utf8.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/variables.hpp"

namespace skipnc::run {
namespace {

namespace fs = std::filesystem;

// The targets a [[vary]] can name, by prefix of its `what`.
struct WorkSetName {
  std::string_view name;
  int set;
};
constexpr WorkSetName kWorkSets[] = {{"EXT", 0}, {"G54", 1}, {"G55", 2}, {"G56", 3},
                                     {"G57", 4}, {"G58", 5}, {"G59", 6}};
constexpr std::string_view kPartAxes = "XYZ";

// splitmix64 finaliser (Steele, Lea, Flood 2014): a scenario's draws are a
// function of (seed, index, rule) only, never of the order of the runs.
constexpr std::uint64_t mix(std::uint64_t z) noexcept {
  z += 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

std::uint64_t draw_bits(std::uint64_t seed, std::int64_t index, std::uint64_t stream) noexcept {
  return mix(seed ^ mix(static_cast<std::uint64_t>(index) * 0x100000001B3ULL + stream));
}

// (0, 1]
double unit(std::uint64_t bits) noexcept {
  return static_cast<double>((bits >> 11) + 1) * 0x1.0p-53;
}

Error spec_error(const std::string& path, const toml::source_region& where, std::string detail) {
  return Error{AlarmId::kConfig, std::move(detail),
               SourceLoc{path, where.begin.line, where.begin.column}, -1};
}

// "part.Z", "#101", "param.6200#7", "G54.X", "H1", "H1.wear", "D2", "D2.wear",
// "probe.repeatability".
Result<VaryRule> parse_target(std::string_view what, const config::MachineConfig& m) {
  VaryRule r;
  r.name = std::string(what);
  auto bad = [&](std::string why) {
    return fail(AlarmId::kConfig, "[[vary]] what = \"" + std::string(what) + "\": " + why);
  };
  auto to_int = [](std::string_view t, int& out) {
    auto res = std::from_chars(t.data(), t.data() + t.size(), out);
    return res.ec == std::errc{} && res.ptr == t.data() + t.size();
  };
  if (what.starts_with("part.") && what.size() == 6) {
    const auto at = kPartAxes.find(what[5]);
    if (at == std::string_view::npos) return bad("the part moves along X, Y or Z");
    r.target = VaryRule::Target::kPart;
    r.axis = static_cast<int>(at);
    return r;
  }
  if (what == "probe.repeatability") {
    r.target = VaryRule::Target::kProbeRepeatability;
    return r;
  }
  if (what.starts_with("#")) {
    if (!to_int(what.substr(1), r.number) ||
        !(interp::VariableStore::is_local(r.number) || interp::VariableStore::is_common(r.number) ||
          interp::VariableStore::is_persistent(r.number))) {
      return bad("a macro variable #1-#33, #100-#199 or #500-#999");
    }
    r.target = VaryRule::Target::kVariable;
    return r;
  }
  if (what.starts_with("param.")) {
    auto s = config::Parameters::parse_setting(std::string(what.substr(6)) + "=0");
    if (!s) return bad("param.N or param.N#B");
    r.target = VaryRule::Target::kParam;
    r.number = s->number;
    r.bit = s->bit;
    return r;
  }
  for (const auto& ws : kWorkSets) {
    if (what.size() == ws.name.size() + 2 && what.starts_with(ws.name) &&
        what[ws.name.size()] == '.') {
      r.axis = m.axis_index(what.back());
      if (r.axis < 0) return bad("the machine has no axis " + std::string(1, what.back()));
      r.target = VaryRule::Target::kWorkOffset;
      r.number = ws.set;
      return r;
    }
  }
  if (what.starts_with("H") || what.starts_with("D")) {
    const bool wear = what.ends_with(".wear");
    const auto digits = what.substr(1, what.size() - 1 - (wear ? 5 : 0));
    if (!to_int(digits, r.number) || r.number < 1 || r.number > m.tool_offset_count) {
      return bad(
          fmt::format("a tool offset H1-H{0}, D1-D{0}, optionally .wear", m.tool_offset_count));
    }
    r.target = VaryRule::Target::kToolOffset;
    r.tool_value = what[0] == 'H' ? (wear ? ToolValue::kLengthWear : ToolValue::kLengthGeometry)
                                  : (wear ? ToolValue::kRadiusWear : ToolValue::kRadiusGeometry);
    return r;
  }
  return bad(
      "expected part.X|Y|Z, #N, param.N[#B], EXT|G54..G59.<axis>, H<n>[.wear], "
      "D<n>[.wear] or probe.repeatability");
}

// The draw of a [[vary]]: exactly one of values, uniform, normal, steps.
Result<void> parse_draw(const toml::table& t, const std::string& path, VaryRule& r) {
  struct DrawKey {
    std::string_view key;
    VaryRule::Draw draw;
  };
  constexpr DrawKey kDraws[] = {{"values", VaryRule::Draw::kValues},
                                {"uniform", VaryRule::Draw::kUniform},
                                {"normal", VaryRule::Draw::kNormal},
                                {"steps", VaryRule::Draw::kSteps}};
  int found = 0;
  for (const auto& d : kDraws) {
    const toml::node* n = t.get(d.key);
    if (n == nullptr) continue;
    ++found;
    const toml::array* arr = n->as_array();
    if (arr == nullptr)
      return std::unexpected(
          spec_error(path, n->source(), std::string(d.key) + ": expected an array of numbers"));
    r.values.clear();
    for (const auto& e : *arr) {
      auto v = e.value<double>();
      if (!v || !std::isfinite(*v)) {
        return std::unexpected(
            spec_error(path, e.source(), std::string(d.key) + ": expected a number"));
      }
      r.values.push_back(*v);
    }
    r.draw = d.draw;
    const bool pair = d.draw != VaryRule::Draw::kValues;
    if (pair ? r.values.size() != 2 : r.values.empty()) {
      return std::unexpected(spec_error(
          path, n->source(),
          std::string(d.key) + (pair ? ": expected [a, b]" : ": expected at least one value")));
    }
    if (d.draw == VaryRule::Draw::kNormal && r.values[1] < 0.0) {
      return std::unexpected(spec_error(path, n->source(), "normal = [mean, sd]: sd must be >= 0"));
    }
  }
  if (found != 1) {
    return std::unexpected(spec_error(
        path, t.source(), "[[vary]] needs exactly one of values, uniform, normal, steps"));
  }
  return {};
}

Result<std::vector<std::string>> string_array(const toml::table& root, std::string_view key,
                                              const std::string& path) {
  std::vector<std::string> out;
  const toml::node* n = root.get(key);
  if (n == nullptr) return out;
  const toml::array* arr = n->as_array();
  if (arr == nullptr)
    return std::unexpected(
        spec_error(path, n->source(), std::string(key) + ": expected an array of strings"));
  for (const auto& e : *arr) {
    auto s = e.value<std::string>();
    if (!s)
      return std::unexpected(
          spec_error(path, e.source(), std::string(key) + ": expected a string"));
    out.push_back(*s);
  }
  return out;
}

std::string relative_to(const fs::path& dir, const std::string& p) {
  if (p.empty() || fs::path(p).is_absolute()) return p;
  return (dir / p).lexically_normal().string();
}

double draw_value(const VaryRule& r, std::uint64_t seed, std::int64_t index, std::size_t k,
                  std::int64_t count) {
  const auto& v = r.values;
  switch (r.draw) {
    case VaryRule::Draw::kValues:
      return v[static_cast<std::size_t>(index % static_cast<std::int64_t>(v.size()))];
    case VaryRule::Draw::kSteps:
      return count <= 1 ? v[0]
                        : v[0] + (v[1] - v[0]) * static_cast<double>(index) /
                                     static_cast<double>(count - 1);
    case VaryRule::Draw::kUniform:
      return v[0] + (v[1] - v[0]) * (1.0 - unit(draw_bits(seed, index, 2 * k + 1)));
    case VaryRule::Draw::kNormal: {
      // Box-Muller: two uniform draws give one normal deviate.
      const double u1 = unit(draw_bits(seed, index, 2 * k + 1));
      const double u2 = unit(draw_bits(seed, index, 2 * k + 2));
      return v[0] + v[1] * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }
  }
  return v[0];
}

// A parameter's drawn values are refused as `-p N=V` refuses them: every
// listed value, and both ends of a range (a normal draw is checked per
// scenario: a value out of range makes that row an error).
Result<void> check_param_values(const VaryRule& r, const config::Parameters& base) {
  if (r.target != VaryRule::Target::kParam || r.draw == VaryRule::Draw::kNormal) return {};
  config::Parameters p = base;
  for (double x : r.values) {
    if (auto a = p.apply(config::ParamSetting{r.number, r.bit, x, {}}); !a) {
      return fail(AlarmId::kConfig,
                  "[[vary]] " + r.name + " = " + fmt::format("{}", x) + ": " + a.error().detail);
    }
  }
  return {};
}

}  // namespace

Result<Check> parse_check(const std::string& text, std::vector<VarRef>& vars) {
  auto e = parse_expectation(text);
  SKIPNC_TRY(e);
  Check c{std::move(*e), 0};
  if (c.e.kind != Expectation::Kind::kVariable) return c;
  auto ref = parse_var_ref("#" + c.e.var);
  SKIPNC_TRY(ref);
  const auto it =
      std::find_if(vars.begin(), vars.end(), [&](const VarRef& v) { return v.key == ref->key; });
  c.var = static_cast<std::size_t>(it - vars.begin());
  if (it == vars.end()) vars.push_back(*ref);
  // The report and the checks key a variable alike (#<name> or N).
  c.e.var = ref->key;
  return c;
}

namespace {

// The spec as a table; its keys are the known ones. The same checked parser
// as machine and scene files (toml++ asserts on some malformed input that the
// precheck refuses).
Result<toml::table> read_spec(const std::string& path) {
  auto spec_text = read_input_file(path, kSweepSpecInput);
  if (!spec_text) return fail(AlarmId::kConfig, spec_text.error().detail);
  auto parsed = config::parse_toml(*spec_text, path);
  SKIPNC_TRY(parsed);
  static constexpr std::string_view kKeys[] = {"program", "machine", "scene",     "dialect",
                                               "include", "params",  "scenarios", "seed",
                                               "workers", "vars",    "expect",    "vary"};
  for (const auto& [k, node] : *parsed) {
    if (std::find(std::begin(kKeys), std::end(kKeys), k.str()) == std::end(kKeys)) {
      return std::unexpected(
          spec_error(path, k.source(), "unknown key '" + std::string(k.str()) + "'"));
    }
  }
  return parsed;
}

// A string key of the spec ("" when absent).
Result<std::string> spec_string(const toml::table& root, std::string_view key,
                                const std::string& path) {
  const toml::node* n = root.get(key);
  if (n == nullptr) return std::string();
  auto s = n->value<std::string>();
  if (!s)
    return std::unexpected(spec_error(path, n->source(), std::string(key) + ": expected a string"));
  return *s;
}

// An integer key of the spec within [lo, hi] (`def` when absent).
Result<std::int64_t> spec_integer(const toml::table& root, std::string_view key, std::int64_t lo,
                                  std::int64_t hi, std::int64_t def, const std::string& path) {
  const toml::node* n = root.get(key);
  if (n == nullptr) return def;
  auto v = n->value<std::int64_t>();
  if (!v || *v < lo || *v > hi) {
    return std::unexpected(
        spec_error(path, n->source(), fmt::format("{}: expected an integer {}-{}", key, lo, hi)));
  }
  return *v;
}

// The spec's string keys and string arrays, read before anything is opened.
struct SpecStrings {
  std::string program, machine, scene, dialect;
  std::vector<std::string> include, params, vars, expect;
};

Result<SpecStrings> read_strings(const toml::table& root, const std::string& path) {
  SpecStrings out;
  auto program = spec_string(root, "program", path);
  SKIPNC_TRY(program);
  if (program->empty())
    return std::unexpected(spec_error(path, root.source(), "program: required"));
  out.program = *program;
  for (auto [key, to] : {std::pair{"machine", &out.machine}, std::pair{"scene", &out.scene},
                         std::pair{"dialect", &out.dialect}}) {
    auto r = spec_string(root, key, path);
    SKIPNC_TRY(r);
    *to = *r;
  }
  for (auto [key, to] : {std::pair{"include", &out.include}, std::pair{"params", &out.params},
                         std::pair{"vars", &out.vars}, std::pair{"expect", &out.expect}}) {
    auto r = string_array(root, key, path);
    SKIPNC_TRY(r);
    *to = *r;
  }
  return out;
}

// Scenarios, seed and workers: the command line's ranges (-n, --seed, -j), a
// value run refuses is refused here; the command line's values win.
Result<void> read_counts(const toml::table& root, const std::string& path, const SweepOverrides& o,
                         SweepPlan& plan) {
  auto scenarios = spec_integer(root, "scenarios", 1, kMaxScenarios, 1, path);
  auto seed = spec_integer(root, "seed", 0, kMaxSeed, 1, path);
  auto workers = spec_integer(root, "workers", 0, kMaxWorkers, 0, path);
  for (auto* r : {&scenarios, &seed, &workers}) {
    SKIPNC_TRY(*r);
  }
  plan.scenarios = o.scenarios.value_or(*scenarios);
  plan.seed = o.seed.value_or(static_cast<std::uint64_t>(*seed));
  plan.workers = static_cast<int>(*workers);
  return {};
}

// The program, include folders, reported variables and checks of every run.
Result<void> read_request(const toml::table& root, const std::string& path, const SpecStrings& sp,
                          SweepPlan& plan) {
  const fs::path dir = fs::path(path).parent_path();
  RunRequest& rq = plan.request;
  rq.program_path = relative_to(dir, sp.program);
  rq.program_name = rq.program_path;
  // A program that cannot be read stops the sweep before any scenario (was:
  // every row an error).
  if (auto p = check_input_file(rq.program_path,
                                InputKind{"program", std::numeric_limits<std::uint64_t>::max()});
      !p) {
    return std::unexpected(spec_error(path, root.get("program")->source(), p.error().detail));
  }
  for (const auto& inc : sp.include) rq.include_dirs.push_back(relative_to(dir, inc));
  for (const auto& v : sp.vars) {
    auto ref = parse_var_ref(v);
    SKIPNC_TRY(ref);
    rq.vars.push_back(*ref);
  }
  for (const auto& e : sp.expect) {
    auto c = parse_check(e, rq.vars);
    SKIPNC_TRY(c);
    // alarm=NAME names an alarm of the session's dialect (as run --expect).
    if (auto n = check_alarm_name(c->e, plan.session.dialect); !n) {
      return std::unexpected(spec_error(path, root.get("expect")->source(), n.error().detail));
    }
    plan.checks.push_back(*c);
  }
  return {};
}

// One [[vary]] table: what changes and how it is drawn.
Result<VaryRule> read_vary(const toml::table& t, const std::string& path, const SweepPlan& plan) {
  static constexpr std::string_view kVaryKeys[] = {"what", "values", "uniform", "normal", "steps"};
  for (const auto& [k, node] : t) {
    if (std::find(std::begin(kVaryKeys), std::end(kVaryKeys), k.str()) == std::end(kVaryKeys)) {
      return std::unexpected(
          spec_error(path, k.source(), "[[vary]]: unknown key '" + std::string(k.str()) + "'"));
    }
  }
  auto what = t["what"].value<std::string>();
  if (!what)
    return std::unexpected(spec_error(path, t.source(), "[[vary]]: what = \"...\" required"));
  auto rule = parse_target(*what, plan.session.machine);
  if (!rule) return std::unexpected(spec_error(path, t.get("what")->source(), rule.error().detail));
  SKIPNC_TRY(parse_draw(t, path, *rule));
  if (auto c = check_param_values(*rule, *plan.session.params); !c) {
    return std::unexpected(spec_error(path, t.source(), c.error().detail));
  }
  return rule;
}

}  // namespace

Result<void> load_sweep(const std::string& spec_path, const SweepOverrides& o, SweepPlan& plan) {
  plan.spec_path = spec_path;
  const std::string& path = plan.spec_path;
  auto root = read_spec(path);
  SKIPNC_TRY(root);
  auto sp = read_strings(*root, path);
  SKIPNC_TRY(sp);
  if (auto c = read_counts(*root, path, o, plan); !c) return c;
  const fs::path dir = fs::path(path).parent_path();
  std::string mname = sp->machine.empty() ? "mill3" : sp->machine;
  if (mname.find('/') != std::string::npos || mname.ends_with(".toml"))
    mname = relative_to(dir, mname);
  auto opened = open_session(
      SessionOptions{mname, sp->dialect, relative_to(dir, sp->scene), sp->params}, plan.session);
  if (!opened) return opened;
  if (auto r = read_request(*root, path, *sp, plan); !r) return r;
  const toml::node* n = root->get("vary");
  if (n == nullptr) return {};
  const toml::array* arr = n->as_array();
  if (arr == nullptr || !arr->is_array_of_tables()) {
    return std::unexpected(spec_error(path, n->source(), "vary: expected [[vary]] tables"));
  }
  for (const auto& e : *arr) {
    auto rule = read_vary(*e.as_table(), path, plan);
    SKIPNC_TRY(rule);
    plan.vary.push_back(std::move(*rule));
  }
  return {};
}

Variation scenario_variation(const SweepPlan& plan, std::int64_t index, std::vector<double>& chosen,
                             std::uint64_t& probe_seed) {
  Variation v;
  chosen.clear();
  // The probe's scatter: a seed of its own per scenario (53 bits: exact in JSON).
  probe_seed = draw_bits(plan.seed, index, 0) >> 11;
  v.probe_seed = probe_seed;
  for (std::size_t k = 0; k < plan.vary.size(); ++k) {
    const VaryRule& r = plan.vary[k];
    const double x = draw_value(r, plan.seed, index, k, plan.scenarios);
    chosen.push_back(x);
    switch (r.target) {
      case VaryRule::Target::kPart:
        v.part_shift[r.axis] += x;
        break;
      case VaryRule::Target::kVariable:
        v.variables.emplace_back(r.number, x);
        break;
      case VaryRule::Target::kParam:
        v.params.push_back(config::ParamSetting{r.number, r.bit, x, {}});
        break;
      case VaryRule::Target::kWorkOffset:
        v.work_offsets.push_back({r.number, r.axis, x});
        break;
      case VaryRule::Target::kToolOffset:
        v.tool_offsets.push_back({r.number, r.tool_value, x});
        break;
      case VaryRule::Target::kProbeRepeatability:
        v.probe_repeatability = std::max(0.0, x);
        break;
    }
  }
  return v;
}

namespace {

// Whether the checks expect a run that did not complete (status= other than
// completed, or alarm=): only then may such a run pass.
bool expects_an_end(const SweepPlan& plan) {
  for (const Check& c : plan.checks) {
    if (c.e.kind == Expectation::Kind::kAlarm) return true;
    if (c.e.kind == Expectation::Kind::kStatus && c.e.status != "completed") return true;
  }
  return false;
}

// What the checks see of a row.
ObservedRun observed(const SweepPlan& plan, const ScenarioRow& row) {
  ObservedRun o;
  o.status = row.status;
  o.alarm = row.alarm;
  o.alarm_code = row.alarm_code;
  o.alarm_key = row.alarm_key;
  for (std::size_t i = 0; i < plan.request.vars.size(); ++i)
    o.variables.emplace_back(plan.request.vars[i].key, row.values[i]);
  return o;
}

void check_row(const SweepPlan& plan, ScenarioRow& row) {
  const ObservedRun o = observed(plan, row);
  bool all = true;
  for (const Check& c : plan.checks) {
    const bool ok = check_expectation(c.e, o).empty();
    row.checks.push_back(ok);
    all = all && ok;
  }
  const bool ran =
      row.status == "completed" || row.status == "alarm" || row.status == "interrupted";
  row.pass = all && ran && (row.status == "completed" || expects_an_end(plan));
}

// A scenario the sweep did not take: its values, no run.
ScenarioRow not_run_row(const SweepPlan& plan, std::int64_t index) {
  ScenarioRow row;
  row.index = index;
  (void)scenario_variation(plan, index, row.chosen, row.probe_seed);
  row.values.assign(plan.request.vars.size(), std::nullopt);
  row.status = "not_run";
  row.checks.assign(plan.checks.size(), false);
  row.pass = false;
  return row;
}

}  // namespace

ScenarioRow run_scenario(const SweepPlan& plan, std::int64_t index,
                         const std::atomic<bool>* interrupt) {
  ScenarioRow row;
  row.index = index;
  const Variation v = scenario_variation(plan, index, row.chosen, row.probe_seed);
  row.values.assign(plan.request.vars.size(), std::nullopt);
  auto res = run_variation(plan.session, plan.request, v, nullptr, interrupt,
                           /*with_report=*/false);
  if (!res) {
    row.status = "error";
    const report::AlarmView view = report::view_alarm(res.error(), &plan.session.dialect);
    row.alarm = view.number;
    row.alarm_code = view.code;
    row.alarm_key = std::string(alarm_key(res.error().id));
    row.alarm_text = describe(res.error(), &plan.session.dialect);
  } else {
    row.status = report::status_name(res->status);
    row.time_s = res->time_s;
    row.alarm = res->alarm;
    row.alarm_code = res->alarm_code;
    row.alarm_key = res->alarm_key;
    row.alarm_text = res->alarm_text;
    for (std::size_t i = 0; i < row.values.size(); ++i) row.values[i] = res->variables[i].second;
  }
  // A message or a file name in the alarm may hold any bytes: the table is
  // UTF-8, as the run report is (core/utf8.hpp).
  row.alarm_text = utf8::make_valid(row.alarm_text);
  check_row(plan, row);
  return row;
}

std::vector<std::string> row_failures(const SweepPlan& plan, const ScenarioRow& row) {
  if (row.status == "not_run") return {"not run: the sweep was stopped before this scenario"};
  if (row.status == "error") return {"could not start: " + row.alarm_text};
  std::vector<std::string> out;
  const ObservedRun o = observed(plan, row);
  for (std::size_t k = 0; k < plan.checks.size() && k < row.checks.size(); ++k) {
    if (!row.checks[k]) out.push_back(evaluate_expectation(plan.checks[k].e, o).message);
  }
  if (!row.pass && out.empty()) {
    out.push_back(row.status == "alarm" ? "the scenario ended in an alarm: " + row.alarm_text
                                        : "the scenario ended " + row.status);
  }
  return out;
}

void run_scenarios(const SweepPlan& plan, std::int64_t begin, std::int64_t end, int workers,
                   const RowSink& sink, SweepStop stop) {
  const std::int64_t n = std::max<std::int64_t>(0, end - begin);
  if (workers <= 0) workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  workers = static_cast<int>(std::min<std::int64_t>(workers, std::max<std::int64_t>(n, 1)));
  std::mutex m;
  std::condition_variable cv;
  std::map<std::int64_t, ScenarioRow> done;  // finished, waiting for an earlier row
  std::int64_t next_take = 0, next_emit = 0;
  auto stopped = [&] { return stop.stop_taking != nullptr && stop.stop_taking->load(); };
  auto work = [&] {
    for (;;) {
      std::int64_t i = 0;
      {
        std::unique_lock lock(m);
        cv.wait(lock, [&] { return next_take >= n || next_take < next_emit + kSweepWindow; });
        if (next_take >= n) return;
        i = next_take++;
      }
      ScenarioRow row =
          stopped() ? not_run_row(plan, begin + i) : run_scenario(plan, begin + i, stop.interrupt);
      {
        std::lock_guard lock(m);
        done.emplace(i, std::move(row));
        // Each row leaves as soon as every row before it has.
        for (auto it = done.begin(); it != done.end() && it->first == next_emit;
             it = done.erase(it), ++next_emit) {
          sink(it->second);
        }
      }
      cv.notify_all();
    }
  };
  std::vector<std::jthread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
}

std::vector<ScenarioRow> run_scenarios(const SweepPlan& plan, std::int64_t begin, std::int64_t end,
                                       int workers, const std::atomic<bool>* interrupt) {
  std::vector<ScenarioRow> rows;
  rows.reserve(static_cast<std::size_t>(std::max<std::int64_t>(0, end - begin)));
  run_scenarios(
      plan, begin, end, workers, [&](const ScenarioRow& r) { rows.push_back(r); },
      SweepStop{nullptr, interrupt});
  return rows;
}

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string number(double v) {
  return std::isfinite(v) ? fmt::format("{}", v) : std::string();
}

// `text` (a dump of a JSON value) indented by `by` more spaces after its
// first line.
std::string indented(const std::string& text, std::string_view by) {
  std::string out;
  for (char c : text) {
    out += c;
    if (c == '\n') out += by;
  }
  return out;
}

}  // namespace

SweepTable::SweepTable(const SweepPlan& plan, std::int64_t scenarios)
    : plan_(plan),
      scenarios_(scenarios < 0 ? plan.scenarios : scenarios),
      vars_(plan.request.vars.size()) {
  for (std::size_t c = 0; c < plan.checks.size(); ++c) {
    const Check& ch = plan.checks[c];
    if (ch.e.kind == Expectation::Kind::kVariable && !ch.e.vacant && !vars_[ch.var].check)
      vars_[ch.var].check = c;
  }
}

std::string SweepTable::csv_header() const {
  std::string out = "scenario,probe_seed,status,alarm";
  for (const auto& r : plan_.vary) out += "," + csv_field(r.name);
  for (const auto& v : plan_.request.vars) out += ",#" + csv_field(v.key);
  for (const auto& c : plan_.checks) out += "," + csv_field(c.e.text);
  return out + ",pass,time_s\n";
}

std::string SweepTable::csv_row(const ScenarioRow& r) const {
  std::string out = fmt::format("{},{},{},{}", r.index, r.probe_seed, r.status,
                                r.alarm != 0 ? std::to_string(r.alarm) : std::string());
  for (double x : r.chosen) out += "," + number(x);
  for (const auto& x : r.values) out += "," + (x ? number(*x) : std::string());
  for (bool ok : r.checks) out += ok ? ",pass" : ",fail";
  out += r.pass ? ",pass," : ",fail,";
  return out + number(r.time_s) + "\n";
}

std::string SweepTable::json_head() const {
  using nlohmann::ordered_json;
  ordered_json j;
  j["format"] = "skipnc-sweep/1";
  j["spec"] = utf8::make_valid(plan_.spec_path);
  j["program"] = utf8::make_valid(plan_.request.program_name);
  j["machine"] = utf8::make_valid(plan_.session.machine.name);
  j["dialect"] = plan_.session.dialect.name;
  j["seed"] = plan_.seed;
  j["scenarios"] = scenarios_;
  ordered_json vary = ordered_json::array();
  for (const auto& r : plan_.vary) vary.push_back(utf8::make_valid(r.name));
  j["vary"] = vary;
  ordered_json vars = ordered_json::array();
  for (const auto& v : plan_.request.vars) vars.push_back(utf8::make_valid(v.key));
  j["variables"] = vars;
  ordered_json checks = ordered_json::array();
  for (const auto& c : plan_.checks) checks.push_back(utf8::make_valid(c.e.text));
  j["expect"] = checks;
  std::string out = j.dump(2);
  out.resize(out.size() - 2);  // "\n}"
  return out + ",\n  \"rows\": [";
}

std::string SweepTable::json_row(const ScenarioRow& r, bool first) const {
  using nlohmann::ordered_json;
  ordered_json o;
  o["scenario"] = r.index;
  o["probe_seed"] = r.probe_seed;
  o["status"] = r.status;
  o["alarm"] = r.alarm != 0 ? ordered_json(r.alarm) : ordered_json(nullptr);
  if (!r.alarm_text.empty()) o["alarm_text"] = utf8::make_valid(r.alarm_text);
  ordered_json chosen = ordered_json::object();
  for (std::size_t k = 0; k < plan_.vary.size(); ++k)
    chosen[utf8::make_valid(plan_.vary[k].name)] = r.chosen[k];
  o["chosen"] = chosen;
  ordered_json values = ordered_json::object();
  for (std::size_t k = 0; k < plan_.request.vars.size(); ++k) {
    values[utf8::make_valid(plan_.request.vars[k].key)] =
        r.values[k] ? ordered_json(*r.values[k]) : ordered_json(nullptr);
  }
  o["variables"] = values;
  ordered_json ch = ordered_json::object();
  for (std::size_t k = 0; k < plan_.checks.size(); ++k)
    ch[utf8::make_valid(plan_.checks[k].e.text)] = bool(r.checks[k]);
  o["checks"] = ch;
  o["pass"] = r.pass;
  o["time"] = r.time_s;
  // One row per line: a table cut short keeps its finished rows readable.
  return (first ? "\n    " : ",\n    ") + o.dump();
}

void SweepTable::add(const ScenarioRow& r) {
  ++rows_;
  passed_ += r.pass ? 1 : 0;
  ++statuses_[r.status];
  if (!r.pass && !first_failure_ && r.status != "not_run") first_failure_ = r;
  for (std::size_t v = 0; v < vars_.size(); ++v) {
    if (!r.values[v]) continue;
    VarSummary& s = vars_[v];
    const double x = *r.values[v];
    if (s.count == 0 || x < s.min) s.min = x, s.min_row = r.index;
    if (s.count == 0 || x > s.max) s.max = x, s.max_row = r.index;
    s.sum += x;
    ++s.count;
    if (s.check) {
      const double d = std::fabs(x - plan_.checks[*s.check].e.value);
      if (d > s.worst) s.worst = d, s.worst_row = r.index, s.worst_value = x;
    }
  }
}

// The worst case: the largest deviation from the expected value when a check
// names the variable, else from the mean (then the minimum or the maximum).
SweepTable::Worst SweepTable::worst(const VarSummary& s) const {
  if (s.check) return {s.worst_row, s.worst_value, s.worst};
  const double mean = s.sum / static_cast<double>(s.count);
  if (s.max - mean > mean - s.min) return {s.max_row, s.max, s.max - mean};
  return {s.min_row, s.min, mean - s.min};
}

std::int64_t SweepTable::count(const std::string& status) const noexcept {
  const auto it = statuses_.find(status);
  return it == statuses_.end() ? 0 : it->second;
}

int SweepTable::exit_status() const noexcept {
  if (rows_ > 0 && errors() == rows_) return 2;
  return passed_ == rows_ ? 0 : 1;
}

std::string SweepTable::json_tail() const {
  using nlohmann::ordered_json;
  ordered_json sum;
  sum["passed"] = passed_;
  sum["failed"] = rows_ - passed_ - errors() - not_run();
  sum["errors"] = errors();
  sum["not_run"] = not_run();
  ordered_json st = ordered_json::object();
  for (const auto& [k, n] : statuses_) st[k] = n;
  sum["statuses"] = st;
  ordered_json vs = ordered_json::object();
  for (std::size_t v = 0; v < vars_.size(); ++v) {
    const VarSummary& s = vars_[v];
    ordered_json o;
    o["count"] = s.count;
    if (s.count > 0) {
      o["min"] = s.min;
      o["max"] = s.max;
      o["mean"] = s.sum / static_cast<double>(s.count);
      o["reference"] = s.check ? "expect" : "mean";
      const Worst w = worst(s);
      o["worst"] = {{"scenario", w.row}, {"value", w.value}, {"deviation", w.deviation}};
    }
    vs[utf8::make_valid(plan_.request.vars[v].key)] = std::move(o);
  }
  sum["variables"] = std::move(vs);
  return std::string(rows_ > 0 ? "\n  ]" : "]") +
         ",\n  \"summary\": " + indented(sum.dump(2), "  ") + "\n}\n";
}

std::string SweepTable::summary_text() const {
  std::string out = fmt::format("{}: {} scenarios (seed {}): {} passed, {} failed", plan_.spec_path,
                                rows_, plan_.seed, passed_, rows_ - passed_ - errors() - not_run());
  if (errors() > 0) out += fmt::format(", {} could not start (error)", errors());
  if (not_run() > 0) out += fmt::format(", {} not run (stopped)", not_run());
  out += "\n";
  if (!vars_.empty()) {
    out += fmt::format("  {:<24} {:>7} {:>14} {:>14} {:>14} {:>12} {:>9}\n", "variable", "count",
                       "min", "max", "mean", "worst", "scenario");
  }
  for (std::size_t v = 0; v < vars_.size(); ++v) {
    const VarSummary& s = vars_[v];
    if (s.count == 0) {
      out += fmt::format("  {:<24} {:>7}\n", "#" + plan_.request.vars[v].key, 0);
      continue;
    }
    const Worst w = worst(s);
    out += fmt::format("  {:<24} {:>7} {:>14.6f} {:>14.6f} {:>14.6f} {:>12.6f} {:>9}\n",
                       "#" + plan_.request.vars[v].key, s.count, s.min, s.max,
                       s.sum / static_cast<double>(s.count), w.deviation, w.row);
  }
  if (!vars_.empty())
    out += "  worst: the largest |value - expected| (|value - mean| without an expect)\n";
  if (first_failure_) {
    const ScenarioRow& r = *first_failure_;
    out += fmt::format("  first failure: scenario {} ({}{}{})\n", r.index, r.status,
                       r.alarm_text.empty() ? "" : ": ", r.alarm_text);
  }
  return out;
}

std::string sweep_csv(const SweepPlan& plan, const std::vector<ScenarioRow>& rows) {
  const SweepTable t(plan);
  std::string out = t.csv_header();
  for (const auto& r : rows) out += t.csv_row(r);
  return out;
}

std::string sweep_json(const SweepPlan& plan, const std::vector<ScenarioRow>& rows) {
  SweepTable t(plan, static_cast<std::int64_t>(rows.size()));
  std::string out = t.json_head();
  for (const auto& r : rows) {
    out += t.json_row(r, t.rows() == 0);
    t.add(r);
  }
  return out + t.json_tail();
}

std::string sweep_summary_text(const SweepPlan& plan, const std::vector<ScenarioRow>& rows) {
  SweepTable t(plan);
  for (const auto& r : rows) t.add(r);
  return t.summary_text();
}

}  // namespace skipnc::run
