// One run of a loaded session with changes of its own: parameters, macro
// variables, work and tool offsets, the parts moved, the probe's scatter
// seed. Shared by `skipnc sweep` (run/sweep.hpp) and the Python module
// (python/): the session is read only, so runs in several threads may share
// one (each run copies what it changes; nothing is written to files).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "interpreter/interpreter.hpp"
#include "report/report.hpp"
#include "run/expect.hpp"
#include "run/session.hpp"
#include "sim/simulator.hpp"

namespace skipnc::run {

// A tool offset a run sets: offset number and which value.
enum class ToolValue : std::uint8_t { kLengthGeometry, kLengthWear, kRadiusGeometry, kRadiusWear };

struct Variation {
  std::vector<config::ParamSetting> params;       // applied over the session's
  std::vector<std::pair<int, double>> variables;  // #1-#33, #100-#199, #500-#999 at the start
  // Work offsets: (set, axis) = value in mm; set 0 is EXT, 1-6 G54-G59.
  struct WorkOffset {
    int set = 1;
    int axis = 0;
    double value = 0.0;
  };
  std::vector<WorkOffset> work_offsets;
  struct ToolOffset {
    int number = 1;
    ToolValue which = ToolValue::kLengthGeometry;
    double value = 0.0;
  };
  std::vector<ToolOffset> tool_offsets;
  // Moves every part of the scene, and every trigger and stop along its
  // axis, by this vector (machine X, Y, Z; mm).
  double part_shift[3] = {0.0, 0.0, 0.0};
  std::optional<std::uint64_t> probe_seed;    // the scene probe's scatter seed
  std::optional<double> probe_repeatability;  // its 1-sigma scatter, mm
};

struct RunRequest {
  std::string program_path;  // the program file; empty: program_text
  std::string program_text;
  std::string program_name;  // in errors and the report
  std::vector<std::string> include_dirs;
  std::vector<VarRef> vars;        // reported after the run
  bool strict = false;             // --strict: a warning is an alarm (strict_warning)
  std::vector<std::string> allow;  // --allow CODE: warnings that stay warnings under --strict
  // --expect: checked on the run's outcome (run/expect.hpp), as `skipnc run`.
  std::vector<Expectation> expect;
  // --plot: pictures of the run (.svg, .html), written after it (run/plot.hpp).
  std::vector<std::string> plot_files;
};

// The run, made while its simulator exists: an alarm's location points into
// the simulator's program store, so everything that shows it is written here.
struct RunOutcome {
  std::string report_json;  // report::to_json, as `skipnc run --report` (with_report)
  sim::RunStatus status = sim::RunStatus::kCompleted;
  int alarm = 0;           // the dialect's number, 0 without an alarm
  std::string alarm_text;  // describe(): "file:line:column: alarm CODE (N): message"
  std::string alarm_code;  // the dialect's code (PS0011), empty without an alarm
  std::string alarm_key;   // the alarm's key (skip_no_feed), empty without an alarm
  double time_s = 0.0;     // simulated
  std::vector<std::pair<std::string, std::optional<double>>> variables;  // rq.vars, in order
  // The expectations that failed, one line each ("expectation failed: ...").
  std::vector<std::string> failed_expectations;
  bool output_failed = false;  // a picture (plot_files) could not be written
  // As `skipnc run`: 0 completed, 1 alarm or interrupted (or a plot that could
  // not be written), 3 an expectation failed; an expected outcome that held
  // is 0 (an expected alarm passes).
  int exit_code = 0;
};

// Runs once. A returned error is a run that could not start (a bad change,
// an unreadable program): exit status 2 for the CLI. Never writes files
// (no persistent variables, no DPRNT file). Without `with_report` the
// report's JSON is not made (a sweep's row takes what it needs from the
// outcome's other fields).
[[nodiscard]] Result<RunOutcome> run_variation(const Session& s, const RunRequest& rq,
                                               const Variation& v, sim::TraceSink* trace = nullptr,
                                               const std::atomic<bool>* interrupt = nullptr,
                                               bool with_report = true);

// What the report of a finished run of session `s` is made from: the
// program's name, the dialect, the machine and the result (variables and
// expectations are the caller's to add).
report::ReportInput report_input(const Session& s, std::string program, sim::RunResult result);

// The variables `refs` names as the interpreter holds them after a run, keyed
// as VarRef::key (vacant: no value).
std::vector<std::pair<std::string, std::optional<double>>> read_variables(
    const interp::Interpreter& in, const std::vector<VarRef>& refs);

// The --expect checks on a finished run, each with its verdict (the report's
// "expectations", one JUnit case each): how the run ended, its alarm (the
// dialect's number, its code, its key) and the variables the checks name, as
// the interpreter holds them after the run. An error: a check names a
// variable that cannot be read as one (parse_var_ref).
[[nodiscard]] Result<std::vector<ExpectResult>> check_outcome(
    const config::Dialect& d, const std::vector<Expectation>& expects, const sim::RunResult& r,
    const interp::Interpreter& in);

// The exit status as `skipnc run` gives it: 0 completed, 1 alarm or
// interrupted (or an output that could not be written), 3 a check failed; a
// run whose expected outcome (status=, alarm=) held is 0, an expected alarm
// too, unless an output could not be written.
int exit_code(sim::RunStatus status, bool output_failed, const std::vector<Expectation>& expects,
              const std::vector<ExpectResult>& checks);

// The program part of an interpreter setup: file or text, name, include
// folders, strict.
void setup_program(const RunRequest& rq, interp::Setup& setup);

// The machine's #500-#999 (its persistent-variable file) added to the
// starting `variables`, and the file dropped from `m`: runs from the library
// read it, never write it (runs in parallel must not write one file).
[[nodiscard]] Result<void> take_persistent(config::MachineConfig& m,
                                           std::vector<std::pair<int, double>>& variables);

// Reads a variable file: one "#<n> = <value>" per line, ';' comments (the
// persistent-variable file's format, any settable variable).
[[nodiscard]] Result<std::vector<std::pair<int, double>>> load_variable_file(
    const std::string& path);

}  // namespace skipnc::run
