// The one way a run is put together (docs/architecture.md, the run library):
// the interpreter's setup from the machine, dialect and parameters (a
// session's, or the copies a variation changed), the request's program,
// strictness and start values; the simulator on the scene; the outputs it
// feeds while it runs (trace, interrupt, progress, the pictures' capture);
// and what is read from it after it (the report's input, the variables,
// the pictures written, the --expect checks, the exit status). `skipnc run`,
// `plot`, `demo`, `repeat`, sweeps and the Python module make their runs
// with it.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "interpreter/interpreter.hpp"
#include "report/report.hpp"
#include "run/plot.hpp"
#include "run/scenario.hpp"
#include "run/session.hpp"
#include "sim/simulator.hpp"

namespace skipnc::run {

// What a run is made on: the session's machine, dialect, parameters and
// scene, or copies of them a variation changed. They outlive the run.
struct Rig {
  const config::MachineConfig* machine = nullptr;
  const config::Dialect* dialect = nullptr;
  const config::Parameters* params = nullptr;
  const machine::Scene* scene = nullptr;
};
Rig rig_of(const Session& s);

// What a run writes and shows while it goes.
struct RunIO {
  sim::TraceSink* trace = nullptr;  // the trace rows (a CSV file, NumPy columns)
  const std::atomic<bool>* interrupt = nullptr;
  std::function<void(double, std::uint32_t)> progress;  // about every simulated second
  std::string dprnt_path;  // DPRNT file; empty: DPRNT lines go to messages only
  std::string log_dir;     // RS274NGC log files; empty: not written
};

// The interpreter's setup: the rig's machine, dialect and parameters, the
// program of `rq` (setup_program), the warnings that stay warnings under
// --strict (the request's and the scene's, allowed_warnings), the files of
// `io`, and `variables` set before the first block.
interp::Setup make_setup(const Session& s, const Rig& rig, const RunRequest& rq, const RunIO& io,
                         std::vector<std::pair<int, double>> variables = {});

// After the run: what the report, the summary and the exit status are made of.
struct Conclusion {
  report::ReportInput report;  // the result, the request's variables, the checks
  bool output_failed = false;  // an output (trace, picture) could not be written
  int exit_code = 0;           // as `skipnc run` gives it (run::exit_code)
};

// One run: the simulator on the rig, the setup it runs, and (with
// `capture_plot`) the recorder of its pictures.
class ProgramRun {
 public:
  ProgramRun(const Rig& rig, interp::Setup setup, const RunIO& io, bool capture_plot);
  ProgramRun(const ProgramRun&) = delete;
  ProgramRun& operator=(const ProgramRun&) = delete;

  // Runs the program to its end, an alarm or the interrupt. A returned
  // error is a run that could not start.
  [[nodiscard]] Result<sim::RunResult> run() { return sim_.run(setup_, opts_); }
  // The interpreter as the run left it (its variables).
  const interp::Interpreter& interpreter() noexcept { return *sim_.interpreter(); }
  const interp::Setup& setup() const noexcept { return setup_; }
  PlotCapture* plot() noexcept { return plot_.get(); }

  // What follows the run, in this order: the report's input (`shown`
  // names the program), the request's variables as the interpreter holds
  // them, `finish` (the caller's outputs: a trace file to close), the
  // pictures of rq.plot_files, the --expect checks, the exit status. An
  // output that could not be written is the run's alarm (when it had none)
  // and is told to `said`. A returned error: a check that cannot be made.
  [[nodiscard]] Result<Conclusion> conclude(const Session& s, sim::RunResult result,
                                            const RunRequest& rq, std::string shown,
                                            const std::function<Result<void>()>& finish = {},
                                            const std::function<void(const Error&)>& said = {});

 private:
  interp::Setup setup_;
  sim::Simulator sim_;
  sim::RunOptions opts_;
  std::unique_ptr<PlotCapture> plot_;
};

}  // namespace skipnc::run
