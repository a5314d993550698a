#include "cli/outputs.hpp"

#include <signal.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <new>
#include <utility>
#include <vector>

#include "core/file.hpp"
#include "interpreter/interpreter.hpp"

namespace skipnc::cli {
namespace {

namespace fs = std::filesystem;

std::atomic<bool> g_report_written{false};

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

namespace {

// A report written after an error never replaces a file the run reads: the
// program, the machine and scene files, meshes, -I files, the persistent
// file (whatever the error, even one found before the outputs were checked).
bool report_may_be_written(const RunArgs& a, const run::Session* s) {
  std::vector<NamedFile> inputs{{"the scene file", a.scene}};
  if (a.program != "-") inputs.push_back({"the program", a.program});  // "-": standard input
  if (a.machine.find('/') != std::string::npos || a.machine.ends_with(".toml"))
    inputs.push_back({"the machine file", a.machine});
  if (s != nullptr) {
    for (auto& f : session_inputs(*s)) inputs.push_back(std::move(f));
    inputs.push_back({"the persistent-variable file", s->machine.persistent_vars});
  }
  for (auto& f : include_inputs(a.include)) inputs.push_back(std::move(f));
  std::erase_if(inputs, [](const NamedFile& f) { return f.name.empty(); });
  auto r = refuse_collisions({{"--report", a.report}}, inputs);
  if (r) return true;
  std::cerr << "skipnc: " << r.error().detail << "\n";
  return false;
}

}  // namespace

int start_failure(const RunArgs& a, const Error& e, const run::Session* s) {
  const config::Dialect* d = report_dialect(a, s);
  std::cerr << "skipnc: " << run::describe(e, d) << "\n";
  if (!a.report.empty() && !g_report_is_input.load() && report_may_be_written(a, s)) {
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

namespace {
// Memory set aside at the start and given back by the last resort, so that
// the report of a run that ran out of memory (std::bad_alloc) can be built.
constexpr std::size_t kEmergencyBytes = 4u << 20;
char* g_emergency = nullptr;
}  // namespace

void reserve_emergency_memory() noexcept {
  if (g_emergency == nullptr) g_emergency = new (std::nothrow) char[kEmergencyBytes];
}

int internal_failure(const RunArgs* a, std::string_view what) noexcept {
  delete[] std::exchange(g_emergency, nullptr);
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

std::vector<NamedFile> session_inputs(const run::Session& s) {
  std::vector<NamedFile> in;
  if (s.machine_file.find('/') != std::string::npos || s.machine_file.ends_with(".toml"))
    in.push_back({"the machine file", s.machine_file});
  for (const auto& f : s.machine.extends_files) in.push_back({"a machine file it extends", f});
  if (!s.scene_file.empty()) in.push_back({"the scene file", s.scene_file});
  for (const auto& f : s.scene.probing.mesh_files) in.push_back({"an STL mesh", f});
  return in;
}

std::vector<NamedFile> include_inputs(const std::vector<std::string>& folders) {
  // The files directly in each -I folder: a subprogram the run may call.
  // At most this many per folder are looked at (a huge folder is not read
  // whole for this check).
  constexpr int kMaxListed = 10000;
  std::vector<NamedFile> in;
  for (const auto& dir : folders) {
    std::error_code ec;
    int listed = 0;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end && listed < kMaxListed;
         it.increment(ec), ++listed) {
      if (it->is_regular_file(ec)) in.push_back({"a file of -I " + dir, it->path().string()});
    }
  }
  return in;
}

Result<void> refuse_collisions(const std::vector<NamedFile>& outputs,
                               const std::vector<NamedFile>& inputs, bool* output_is_input) {
  auto resolve = [](const std::vector<NamedFile>& list,
                    std::vector<OutputTarget>& out) -> Result<void> {
    for (const auto& f : list) {
      auto t = resolve_output(f.name);
      SKIPNC_TRY(t);
      out.push_back(std::move(*t));
    }
    return {};
  };
  std::vector<OutputTarget> to, ti;
  if (auto r = resolve(outputs, to); !r) return r;
  if (auto r = resolve(inputs, ti); !r) return r;
  auto refuse = [&](const NamedFile& o, const NamedFile& other, bool input) {
    if (input && output_is_input != nullptr) *output_is_input = true;
    return fail(AlarmId::kUsage,
                o.what + " " + o.name + " is the same file as " + other.what +
                    (other.what.starts_with("--") ? " " + other.name : " (" + other.name + ")") +
                    ": nothing was run, nothing written over");
  };
  for (std::size_t i = 0; i < to.size(); ++i) {
    for (std::size_t k = 0; k < ti.size(); ++k) {
      if (same_file(to[i], ti[k])) return refuse(outputs[i], inputs[k], true);
    }
    for (std::size_t j = i + 1; j < to.size(); ++j) {
      if (same_file(to[i], to[j])) return refuse(outputs[j], outputs[i], false);
    }
  }
  return {};
}

Result<void> check_outputs(const RunArgs& a, const run::Session& s) {
  std::vector<NamedFile> outputs;
  for (const auto& [what, name] : {std::pair<std::string, std::string>{"--report", a.report},
                                   {"--trace", a.trace},
                                   {"--dprnt", a.dprnt},
                                   {"the persistent-variable file", s.machine.persistent_vars}}) {
    if (!name.empty()) outputs.push_back({what, name});
  }
  for (const auto& p : a.plot) outputs.push_back({"--plot", p});
  // Inputs that are files. The persistent-variable file is read and written
  // by design; it is only checked against the other outputs.
  std::vector<NamedFile> inputs;
  if (!a.program.empty() && a.program != "-") inputs.push_back({"the program", a.program});
  for (auto& f : session_inputs(s)) inputs.push_back(std::move(f));
  for (auto& f : include_inputs(a.include)) inputs.push_back(std::move(f));
  bool report_is_input = false;
  auto r = refuse_collisions(outputs, inputs, &report_is_input);
  if (!r && report_is_input && r.error().detail.starts_with("--report ")) {
    g_report_is_input.store(true);
  }
  return r;
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

run::RunRequest program_request(const RunArgs& a) {
  run::RunRequest rq;
  if (a.program == "-") {
    rq.program_text = a.program_text;
    rq.program_name = "<stdin>";
  } else {
    rq.program_path = a.program;
    rq.program_name = a.program;
  }
  rq.include_dirs = a.include;
  rq.strict = a.strict;
  rq.allow = a.allow;
  return rq;
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
