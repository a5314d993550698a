#include "cli/outputs.hpp"

#include <signal.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <vector>

#include "core/file.hpp"
#include "interpreter/interpreter.hpp"

namespace skipnc::cli {
namespace {

std::atomic<bool> g_report_written{false};

struct Named {
  std::string what;  // "--report", "the program", ...
  std::string name;
  OutputTarget target;
};

// The report's refusal stays unwritten when the report is an input.
std::atomic<bool> g_report_is_input{false};

std::string signal_name(int sig) {
  switch (sig) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "signal " + std::to_string(sig);
  }
}

}  // namespace

const config::Dialect* report_dialect(const RunArgs& a, const run::Session* s) {
  if (s != nullptr && !s->dialect.name.empty()) return &s->dialect;
  static const std::optional<config::Dialect> fallback = [&]() -> std::optional<config::Dialect> {
    if (!a.dialect.empty()) {
      if (auto d = config::builtin_dialect(a.dialect)) return std::move(*d);
    }
    if (auto d = config::builtin_dialect("fanuc")) return std::move(*d);
    return std::nullopt;
  }();
  return fallback ? &*fallback : nullptr;
}

bool report_written() noexcept {
  return g_report_written.load();
}

bool write_report(const RunArgs& a, const std::string& json) {
  if (a.report.empty()) return true;
  auto w = report::write_atomic(a.report, json);
  if (!w) {
    std::cerr << "skipnc: " << w.error().detail << "\n";
    return false;
  }
  g_report_written.store(true);
  return true;
}

int start_failure(const RunArgs& a, const Error& e, const run::Session* s) {
  const config::Dialect* d = report_dialect(a, s);
  std::cerr << "skipnc: " << run::describe(e, d) << "\n";
  if (!a.report.empty() && !g_report_is_input.load()) {
    report::ReportInput in;
    in.program = a.program;
    in.dialect = s && !s->dialect.name.empty() ? s->dialect.name : a.dialect;
    in.machine = s && !s->machine.axes.empty() ? &s->machine : nullptr;
    in.dialect_table = d;
    in.start_error = e;
    (void)write_report(a, report::to_json(in));
  }
  return 2;
}

int internal_failure(const RunArgs* a, std::string_view what) noexcept {
  try {
    const Error e{AlarmId::kInternal, "uncaught exception: " + std::string(what), {}, -1};
    std::cerr << "skipnc: internal error: " << what << "\n";
    if (a != nullptr && !a->report.empty() && !report_written() && !g_report_is_input.load()) {
      report::ReportInput in;
      in.program = a->program;
      in.dialect = a->dialect;
      in.dialect_table = report_dialect(*a, nullptr);
      in.result.status = sim::RunStatus::kAlarm;
      in.result.alarm = e;
      (void)write_report(*a, report::to_json(in));
    }
  } catch (...) {
    // Nothing more can be done: the exit status still says it.
  }
  return 1;
}

Result<void> check_outputs(const RunArgs& a, const run::Session& s) {
  std::vector<Named> outputs;
  std::vector<Named> inputs;
  auto add = [](std::vector<Named>& list, std::string what,
                const std::string& name) -> Result<void> {
    if (name.empty()) return {};
    auto t = resolve_output(name);
    if (!t) return std::unexpected(t.error());
    list.push_back(Named{std::move(what), name, std::move(*t)});
    return {};
  };
  for (auto r : {add(outputs, "--report", a.report), add(outputs, "--trace", a.trace),
                 add(outputs, "--dprnt", a.dprnt),
                 add(outputs, "the persistent-variable file", s.machine.persistent_vars)}) {
    if (!r) return r;
  }
  for (const auto& p : a.plot) {
    if (auto r = add(outputs, "--plot", p); !r) return r;
  }
  // Inputs that are files. The persistent-variable file is read and written
  // by design; it is only checked against the other outputs.
  if (!a.program.empty() && a.program != "-") {
    if (auto r = add(inputs, "the program", a.program); !r) return r;
  }
  if (s.machine_file.find('/') != std::string::npos || s.machine_file.ends_with(".toml")) {
    if (auto r = add(inputs, "the machine file", s.machine_file); !r) return r;
  }
  if (auto r = add(inputs, "the scene file", s.scene_file); !r) return r;

  auto refuse = [&](const Named& o, const Named& other, bool input) {
    if (input && o.what == "--report") g_report_is_input.store(true);
    return fail(AlarmId::kUsage,
                o.what + " " + o.name + " is the same file as " + other.what +
                    (other.what.starts_with("--") ? " " + other.name : " (" + other.name + ")") +
                    ": nothing was run, nothing written over");
  };
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (const auto& in : inputs) {
      if (same_file(outputs[i].target, in.target)) return refuse(outputs[i], in, true);
    }
    for (std::size_t j = i + 1; j < outputs.size(); ++j) {
      if (same_file(outputs[i].target, outputs[j].target))
        return refuse(outputs[j], outputs[i], false);
    }
  }
  return {};
}

void explain_stop(sim::RunResult& r, const report::CsvTrace* trace,
                  const config::MachineConfig& m) {
  if (r.status != sim::RunStatus::kInterrupted || !r.alarm) return;
  const RunStop& stop = run_stop();
  switch (stop.why()) {
    case StopReason::kCpuLimit:
      r.status = sim::RunStatus::kAlarm;
      r.alarm->id = AlarmId::kCpuLimit;
      r.alarm->detail = "the run used more than limits.max_cpu_s (" +
                        std::to_string(m.limits.max_cpu_s) + " s) of processor time";
      break;
    case StopReason::kOutput:
      if (trace != nullptr && trace->error()) {
        r.status = sim::RunStatus::kAlarm;
        const SourceLoc where = r.alarm->loc;
        r.alarm = *trace->error();
        r.alarm->loc = where;
      }
      break;
    case StopReason::kSignal:
      r.alarm->detail = "stopped by " + signal_name(stop.signal.load());
      break;
    case StopReason::kNone:
      break;
  }
}

Result<void> finish_stdout() {
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    const int e = errno;
    std::clearerr(stdout);
    return fail(AlarmId::kFileAccess, std::string("cannot write standard output: ") +
                                          (e != 0 ? std::strerror(e) : "write error"));
  }
  return {};
}

void set_program(const RunArgs& a, interp::Setup& setup) {
  if (a.program == "-") {
    setup.program_path.clear();
    setup.program_text = a.program_text;
    setup.program_name = "<stdin>";
    return;
  }
  setup.program_path = a.program;
  setup.program_name = a.program;
}

Result<void> read_stdin_program(RunArgs& a) {
  if (a.program != "-") return {};
  std::string text;
  char buf[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, stdin)) > 0) text.append(buf, n);
  if (std::ferror(stdin)) {
    return std::unexpected(Error{AlarmId::kFileAccess,
                                 "cannot read the program from standard input",
                                 SourceLoc{"<stdin>", 0, 0}, -1});
  }
  a.program_text = std::move(text);
  return {};
}

}  // namespace skipnc::cli
