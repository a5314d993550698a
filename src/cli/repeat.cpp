#include "cli/repeat.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <iostream>

#include "cli/guard.hpp"
#include "cli/junit.hpp"
#include "cli/outputs.hpp"
#include "report/report.hpp"
#include "run/repeat.hpp"
#include "run/session.hpp"

namespace skipnc::cli {
namespace {

void print_table(std::FILE* f, const RunArgs& a, const run::RepeatOutcome& o) {
  fmt::print(f,
             "{}: {} runs with the probe's scatter (seeds {}..{}) and one without it (nominal)\n",
             a.program, o.runs, o.seed, o.seed + static_cast<std::uint64_t>(o.runs) - 1);
  if (!o.scatter) {
    fmt::print(
        f, "  (the scene's probe has no repeatability scatter: every run is the nominal one)\n");
  }
  fmt::print(f, "  {:<32} {:>13} {:>13} {:>11} {:>13} {:>13} {:>11}\n", "value", "nominal", "mean",
             "std dev", "min", "max", "worst");
  for (const auto& se : o.series) {
    const run::RepeatStats st = run::stats_of(se);
    fmt::print(f, "  {:<32} {:>13} {:>13.6f} {:>11.6f} {:>13.6f} {:>13.6f} {:>11.6f}\n", se.name,
               se.nominal ? fmt::format("{:.6f}", *se.nominal) : std::string("-"), st.mean, st.sd,
               st.min, st.max, st.worst);
  }
  fmt::print(f, "  worst: the largest |value - nominal| over the scattered runs\n");
  if (o.alarms > 0) {
    fmt::print(f, "  {} of {} runs ended in an alarm; {}\n", o.alarms, o.runs, o.first_alarm);
  }
}

}  // namespace

int repeat_command(const RunArgs& a) {
  run::Session s;
  auto o = run::open_session(run::SessionOptions{a.machine, a.dialect, a.scene, a.params}, s);
  // A run that cannot start writes the report with its alarm too, as `run`
  // without --repeat does.
  if (!o) return start_failure(a, o.error(), &s);
  if (auto c = run::check_allow(a.allow); !c) return start_failure(a, c.error(), &s);
  // The same outputs check as a single run: no report over the program.
  if (auto c = check_outputs(a, s); !c) return start_failure(a, c.error(), &s);
  run::RepeatRequest rq;
  rq.program = program_request(a);
  for (const auto& v : a.vars) {
    auto r = run::parse_var_ref(v);
    if (!r) return start_failure(a, r.error(), &s);
    rq.program.vars.push_back(*r);
  }
  rq.dprnt_path = a.dprnt;
  rq.runs = a.repeat;
  if (a.seed >= 0) rq.seed = static_cast<std::uint64_t>(a.seed);
  // SIGTERM / SIGINT end the repetitions: the report keeps the runs that
  // finished, says "interrupted", and the exit status is 1.
  auto out = run::repeat_runs(s, rq, &run_stop().flag);
  if (!out) return start_failure(a, out.error(), &s);
  if (!a.quiet) print_table(a.report == "-" ? stderr : stdout, a, *out);
  if (!a.report.empty()) {
    auto w = report::write_atomic(a.report, run::repeat_json(*out, a.program));
    if (!w) {
      std::cerr << "skipnc: " << w.error().detail << "\n";
      return 1;
    }
  }
  if (!a.junit.empty()) {
    std::vector<JunitCase> cases;  // one per run
    double total = 0.0;
    for (const run::RepeatRun& r : out->log) {
      cases.push_back(JunitCase{
          r.run == 0 ? std::string("nominal run") : fmt::format("run {} (seed {})", r.run, r.seed),
          "skipnc.repeat." + a.program,
          r.time_s,
          r.alarm,
          "alarm",
          r.alarm_text,
          {},
          JunitProblem::kFailure,
          {}});
      total += r.time_s;
    }
    if (auto w = write_junit(a.junit, a.program, total, cases); !w) {
      std::cerr << "skipnc: " << w.error().detail << "\n";
      return 1;
    }
  }
  return out->exit_code();
}

}  // namespace skipnc::cli
