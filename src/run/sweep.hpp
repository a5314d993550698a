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
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "run/expect.hpp"
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

// One check of the spec's `expect`, parsed by run --expect's parser
// (run/expect.hpp); `var` is the index of its variable among the reported
// ones (kVariable).
struct Check {
  Expectation e;
  std::size_t var = 0;
};
// Parses `text`; a variable it names joins `vars` when not there yet.
[[nodiscard]] Result<Check> parse_check(const std::string& text, std::vector<VarRef>& vars);

// The ranges of the spec's and the command line's numbers (one place, so
// that a value the command refuses is refused in a spec).
inline constexpr std::int64_t kMaxScenarios = 100'000'000;
inline constexpr std::int64_t kMaxSeed = 9'000'000'000'000'000'000;
inline constexpr int kMaxWorkers = 4096;

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
  // completed, alarm, interrupted; error (could not start); not_run (the
  // sweep was stopped before it took this scenario).
  std::string status;
  int alarm = 0;               // the dialect's alarm number, 0 without one
  std::string alarm_text;      // "file:line:column: alarm CODE (N): message", valid UTF-8
  std::string alarm_code;      // the dialect's code (PS0011) and the alarm's key
  std::string alarm_key;       // (skip_no_feed), for alarm= checks; not in the tables
  std::vector<double> chosen;  // one per vary rule
  std::vector<std::optional<double>> values;  // one per reported variable
  std::vector<bool> checks;                   // one per check
  // All checks hold, and the run completed; a run that alarmed or was
  // interrupted passes only when a status= or alarm= check expects it; an
  // error or a scenario not run never passes.
  bool pass = false;
  double time_s = 0.0;  // simulated
};

// The values scenario `index` takes (pure: seed, index and the rules).
Variation scenario_variation(const SweepPlan& plan, std::int64_t index, std::vector<double>& chosen,
                             std::uint64_t& probe_seed);
ScenarioRow run_scenario(const SweepPlan& plan, std::int64_t index,
                         const std::atomic<bool>* interrupt = nullptr);

// Why a row did not pass, one line each (empty when it passed): each check
// that failed (as `skipnc run --expect` says it), else the alarm or status
// that failed it; an error or a scenario not run, said as such.
std::vector<std::string> row_failures(const SweepPlan& plan, const ScenarioRow& row);

// How a sweep is stopped early: `stop_taking` set, no scenario is started
// any more (the rest are rows with status not_run); `interrupt` set, the
// running ones stop at their next servo period (status interrupted).
struct SweepStop {
  const std::atomic<bool>* stop_taking = nullptr;
  const std::atomic<bool>* interrupt = nullptr;
};
// Receives the rows in index order, each as soon as it and every row before
// it are done; called from one thread at a time.
using RowSink = std::function<void(const ScenarioRow&)>;
// Scenarios [begin, end) on `workers` threads (0: every core). Memory is
// bounded by the number of workers, not of scenarios: a worker does not
// start a scenario more than kSweepWindow rows ahead of the oldest one
// still running.
inline constexpr std::int64_t kSweepWindow = 256;
void run_scenarios(const SweepPlan& plan, std::int64_t begin, std::int64_t end, int workers,
                   const RowSink& sink, SweepStop stop = {});
// The same, the rows kept (the Python module, tests).
std::vector<ScenarioRow> run_scenarios(const SweepPlan& plan, std::int64_t begin, std::int64_t end,
                                       int workers, const std::atomic<bool>* interrupt = nullptr);

// The table, written as the rows come: CSV lines and JSON (a head, one row
// per line, the summary at the end), and the summary's counts and per
// variable figures, kept in constant memory.
class SweepTable {
 public:
  // `scenarios`: the table's announced size (-1: the plan's).
  explicit SweepTable(const SweepPlan& plan, std::int64_t scenarios = -1);
  std::string csv_header() const;
  std::string csv_row(const ScenarioRow& r) const;
  std::string json_head() const;
  // `first`: no comma before it.
  std::string json_row(const ScenarioRow& r, bool first) const;
  // Counts `r` in the summary.
  void add(const ScenarioRow& r);
  std::string json_tail() const;
  std::string summary_text() const;

  std::int64_t rows() const noexcept { return rows_; }
  std::int64_t passed() const noexcept { return passed_; }
  std::int64_t errors() const noexcept { return count("error"); }
  std::int64_t not_run() const noexcept { return count("not_run"); }
  // 0: every scenario ran and passed; 2: none could start (every row an
  // error); else 1.
  int exit_status() const noexcept;

 private:
  struct VarSummary {
    std::int64_t count = 0;
    double min = 0.0, max = 0.0, sum = 0.0;
    std::int64_t min_row = 0, max_row = 0;
    std::optional<std::size_t> check;  // the first check on this variable
    double worst = -1.0;               // largest |value - expected| (with a check)
    std::int64_t worst_row = 0;
    double worst_value = 0.0;
  };
  struct Worst {
    std::int64_t row = 0;
    double value = 0.0, deviation = 0.0;
  };
  Worst worst(const VarSummary& s) const;
  std::int64_t count(const std::string& status) const noexcept;

  const SweepPlan& plan_;
  std::int64_t scenarios_;
  std::int64_t rows_ = 0;
  std::int64_t passed_ = 0;
  std::map<std::string, std::int64_t> statuses_;
  std::vector<VarSummary> vars_;
  std::optional<ScenarioRow> first_failure_;
};

// The whole table at once (the Python module, tests): as SweepTable writes it.
std::string sweep_csv(const SweepPlan& plan, const std::vector<ScenarioRow>& rows);
std::string sweep_json(const SweepPlan& plan, const std::vector<ScenarioRow>& rows);
std::string sweep_summary_text(const SweepPlan& plan, const std::vector<ScenarioRow>& rows);

}  // namespace skipnc::run
