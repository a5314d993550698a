#include "run/program_run.hpp"

namespace skipnc::run {

Rig rig_of(const Session& s) {
  return Rig{&s.machine, &s.dialect, s.params.get(), &s.scene};
}

interp::Setup make_setup(const Session& s, const Rig& rig, const RunRequest& rq, const RunIO& io,
                         std::vector<std::pair<int, double>> variables) {
  interp::Setup setup;
  setup.machine = rig.machine;
  setup.dialect = rig.dialect;
  setup.params = rig.params;
  setup.variables = std::move(variables);
  setup_program(rq, setup);
  setup.strict_allow = allowed_warnings(s, rq.allow);
  setup.dprnt_path = io.dprnt_path;
  setup.log_dir = io.log_dir;
  return setup;
}

ProgramRun::ProgramRun(const Rig& rig, interp::Setup setup, const RunIO& io, bool capture_plot)
    : setup_(std::move(setup)), sim_(*rig.machine, *rig.dialect, *rig.params, *rig.scene) {
  opts_.trace = io.trace;
  opts_.interrupt = io.interrupt;
  opts_.progress = io.progress;
  if (capture_plot) plot_ = std::make_unique<PlotCapture>(*rig.machine, opts_);
}

Result<Conclusion> ProgramRun::conclude(const Session& s, sim::RunResult result,
                                        const RunRequest& rq, std::string shown,
                                        const std::function<Result<void>()>& finish,
                                        const std::function<void(const Error&)>& said) {
  Conclusion c;
  c.report = report_input(s, shown, std::move(result));
  c.report.variables = read_variables(interpreter(), rq.vars);
  // An output that could not be written is an alarm of the run, in the
  // report too (a full disk does not leave "completed").
  auto output_error = [&](const Error& e) {
    if (said) said(e);
    c.output_failed = true;
    if (c.report.result.status == sim::RunStatus::kCompleted) {
      c.report.result.status = sim::RunStatus::kAlarm;
      c.report.result.alarm = e;
    }
  };
  if (finish) {
    if (auto f = finish(); !f) output_error(f.error());
  }
  if (plot_) {
    const std::string text =
        setup_.program_path.empty() ? setup_.program_text : read_program_text(setup_.program_path);
    if (auto w = plot_->write(rq.plot_files, s, c.report.result, {shown, text, c.report.variables});
        !w) {
      output_error(w.error());
    }
  }
  // --expect: checked on the run's outcome; variables as the control holds them.
  if (!rq.expect.empty()) {
    auto checks = check_outcome(s.dialect, rq.expect, c.report.result, interpreter());
    SKIPNC_TRY(checks);
    c.report.expectations = std::move(*checks);
  }
  c.exit_code =
      exit_code(c.report.result.status, c.output_failed, rq.expect, c.report.expectations);
  return c;
}

}  // namespace skipnc::run
