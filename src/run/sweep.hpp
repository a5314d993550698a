// `skipnc sweep SPEC.toml`: one program run in N scenarios, each with its own
// part position, offsets, parameters, macro variables (feeds) and probe
// scatter, checked against expectations and written as one table (CSV and
// JSON) with a summary (docs/cli.md#skipnc-sweep-spectoml).
//
// A scenario's values depend only on the sweep's seed and the scenario's
// index, so the table is the same whatever the number of workers, and any
// range of scenarios can be run anywhere (threads here, Dask through the
// Python module) and merged.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "run/scenario.hpp"
#include "run/session.hpp"

namespace skipnc::run {

// What one [[vary]] changes, and how its value is drawn.
struct VaryRule {
  enum class Target : std::uint8_t {
    kPart,
    kVariable,
    kParam,
    kWorkOffset,
    kToolOffset,
    kProbeRepeatability
  };
  enum class Draw : std::uint8_t { kValues, kUniform, kNormal, kSteps };
  std::string name;  // as written: "part.Z", "#101", "param.6200#7", "G54.X", "H1", ...
  Target target = Target::kVariable;
  int number = 0;  // variable, parameter, set (work offset) or offset number
  int bit = -1;    // parameter bit
  int axis = 0;    // part axis (0 X, 1 Y, 2 Z) or work offset axis
  ToolValue tool_value = ToolValue::kLengthGeometry;
  Draw draw = Draw::kValues;
  std::vector<double> values;  // kValues: cycled; otherwise [a, b]
};

// One --expect-style check: "#140=-0.05+-0.001", "status=completed",
// "alarm=9061".
struct Check {
  std::string text;
  enum class Kind : std::uint8_t { kVariable, kStatus, kAlarm } kind = Kind::kVariable;
  std::size_t var = 0;  // index into the sweep's reported variables
  double value = 0.0;
  double tolerance = 0.0;
  std::string status;
};
[[nodiscard]] Result<Check> parse_check(const std::string& text, std::vector<VarRef>& vars);

struct SweepPlan {
  std::string spec_path;
  Session session;
  RunRequest request;
  std::vector<VaryRule> vary;
  std::vector<Check> checks;
  std::int64_t scenarios = 1;
  std::uint64_t seed = 1;
  int workers = 0;  // 0: every core
};

// Overrides from the command line (unset: the spec's).
struct SweepOverrides {
  std::optional<std::int64_t> scenarios;
  std::optional<std::uint64_t> seed;
};

// Loads the spec and everything it names (paths relative to the spec's
// folder). Errors name the spec, line and column.
[[nodiscard]] Result<void> load_sweep(const std::string& spec_path, const SweepOverrides& o,
                                      SweepPlan& plan);

// One row of the table.
struct ScenarioRow {
  std::int64_t index = 0;
  std::uint64_t probe_seed = 0;
  std::string status;          // completed, alarm, interrupted, error (could not start)
  int alarm = 0;               // the dialect's alarm number, 0 without one
  std::string alarm_text;      // "file:line:column: alarm CODE (N): message"
  std::vector<double> chosen;  // one per vary rule
  std::vector<std::optional<double>> values;  // one per reported variable
  std::vector<bool> checks;                   // one per check
  bool pass = true;
  double time_s = 0.0;  // simulated
};

// The values scenario `index` takes (pure: seed, index and the rules).
Variation scenario_variation(const SweepPlan& plan, std::int64_t index, std::vector<double>& chosen,
                             std::uint64_t& probe_seed);
ScenarioRow run_scenario(const SweepPlan& plan, std::int64_t index,
                         const std::atomic<bool>* interrupt = nullptr);
// Scenarios [begin, end) on `workers` threads (0: every core), in index order.
std::vector<ScenarioRow> run_scenarios(const SweepPlan& plan, std::int64_t begin, std::int64_t end,
                                       int workers, const std::atomic<bool>* interrupt = nullptr);

// The table and its summary.
std::string sweep_csv(const SweepPlan& plan, const std::vector<ScenarioRow>& rows);
std::string sweep_json(const SweepPlan& plan, const std::vector<ScenarioRow>& rows);
std::string sweep_summary_text(const SweepPlan& plan, const std::vector<ScenarioRow>& rows);

}  // namespace skipnc::run
