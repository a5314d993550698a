#include "cli/commands.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>

#include "canon/print.hpp"
#include "cli/junit.hpp"
#include "cli/outputs.hpp"
#include "config/skip_inputs.hpp"
#include "core/embedded.hpp"
#include "interpreter/interpreter.hpp"
#include "report/report.hpp"
#include "run/expect.hpp"
#include "run/plot.hpp"
#include "run/program_run.hpp"
#include "run/scenario.hpp"
#include "run/session.hpp"
#include "sim/simulator.hpp"

namespace skipnc::cli {
namespace {

// The --expect parser and checks are the run library's: `sweep` specs and
// the Python module use the same ones.
using run::Expectation;
using run::parse_expectation;

// Outputs that go to standard output move the summary to standard error.
bool is_stdout(const std::string& name) {
  return name == "-" || name == "/dev/stdout" || name == "/dev/fd/1" || name == "/proc/self/fd/1";
}

// A value to 0.1 um; one that rounds to zero is "0.0000" whatever its sign
// (a centre computed as -1e-15 is not "-0.0000").
std::string fixed4(double v) {
  std::string s = fmt::format("{:.4f}", v);
  if (s == "-0.0000") s.erase(0, 1);
  return s;
}

std::string fmt_axes(const AxisVec& v, const config::MachineConfig& m) {
  std::string out;
  for (int i = 0; i < m.axis_count(); ++i) {
    out += fmt::format("{}{}{}", out.empty() ? "" : " ", m.axes[static_cast<std::size_t>(i)].name,
                       fixed4(v[i]));
  }
  return out;
}

// At most `width` characters: a longer text ends in an ellipsis.
std::string shorten(const std::string& text, std::size_t width) {
  if (text.size() <= width) return text;
  return text.substr(0, width - 3) + "...";
}

// One line per warning: `warning (code): file:line: text`.
void print_warnings(std::FILE* f, const sim::RunResult& r) {
  for (const auto& w : r.warnings) {
    fmt::print(f, "  warning ({}): {}: {}{}\n", w.code,
               report::where(r.contexts, w.context, w.line), w.text,
               w.count > 1 ? fmt::format(" ({} times)", w.count) : std::string());
  }
}

void print_summary(std::FILE* f, const sim::RunResult& r, const run::Session& s,
                   const std::string& program) {
  const auto& m = s.machine;
  fmt::print(f, "{} on {} ({}): ", program, m.name, s.dialect.name);
  switch (r.status) {
    case sim::RunStatus::kCompleted:
      fmt::print(f, "completed");
      break;
    case sim::RunStatus::kAlarm:
      fmt::print(f, "ALARM");
      break;
    case sim::RunStatus::kInterrupted:
      fmt::print(f, "interrupted");
      break;
  }
  fmt::print(f, " after {:.3f} s of machine time\n", r.time_s);
  print_warnings(f, r);  // before the alarm: one of them may be why it came
  if (r.alarm) {
    fmt::print(f, "  {}\n", run::describe(*r.alarm, &s.dialect));
    if (r.alarm_context != 0 && !r.contexts.empty())
      fmt::print(f, "  at {}\n", report::where(r.contexts, r.alarm_context, r.alarm->loc.line));
  }
  for (const auto& sk : r.skips) {
    fmt::print(f, "  {}\n    {:<28} ", report::where(r.contexts, sk.context, sk.line, sk.n),
               shorten(sk.block, 28));
    if (sk.ended_by_alarm) {
      fmt::print(f, "cut short by the alarm{}\n",
                 sk.triggered ? fmt::format(" after {} at {:.4f} s, stored {}",
                                            sk.signal.empty() ? "signal" : sk.signal, sk.time_s,
                                            fmt_axes(sk.position, m))
                              : std::string(" before any signal"));
    } else if (sk.triggered) {
      fmt::print(f, "{} at {:.4f} s  stored {}  stopped {}\n",
                 sk.signal.empty() ? "signal" : sk.signal, sk.time_s, fmt_axes(sk.position, m),
                 fmt_axes(sk.end_position, m));
    } else {
      // The tip's end point in work coordinates (#5001..), not #5061.. (the
      // tool reference point on Fanuc-class dialects).
      fmt::print(f, "no signal: ran to its end point {}\n", fmt_axes(sk.end_position, m));
    }
  }
  for (const auto& msg : r.messages) fmt::print(f, "  message: {}\n", msg);
  // The --var values, as the report has them (vacant: no value).
  for (const auto& [key, v] : r.variables) {
    if (v) {
      fmt::print(f, "  #{} = {}\n", key, fixed4(*v));
    } else {
      fmt::print(f, "  #{} = vacant\n", key);
    }
  }
  fmt::print(f, "  final position {}\n", fmt_axes(r.final_work, m));
}

// The JUnit test cases of a run: one per --expect; without any, one that
// passes when the run completed.
std::vector<JunitCase> run_cases(const RunArgs& a, const report::ReportInput& in,
                                 const config::Dialect& d) {
  std::vector<JunitCase> cases;
  const std::string cls = "skipnc.run." + a.program;
  for (const auto& c : in.expectations) {
    cases.push_back(JunitCase{
        c.text, cls, 0.0, !c.pass, "expectation", c.message, {}, JunitProblem::kFailure, {}});
  }
  if (cases.empty()) {
    JunitCase c{"completes", cls, in.result.time_s, false, {}, {}, {}, JunitProblem::kFailure, {}};
    if (in.result.status != sim::RunStatus::kCompleted) {
      c.failed = true;
      c.failure_type = in.result.alarm ? "alarm" : "interrupted";
      c.failure_message =
          in.result.alarm ? run::describe(*in.result.alarm, &d) : std::string("interrupted");
    }
    cases.push_back(std::move(c));
  }
  return cases;
}

// The run as the run library takes it: the program, and the --var,
// --expect and --plot arguments, read before the run (a bad one stops the
// start).
Result<run::RunRequest> read_request(const RunArgs& a, const run::Session& s) {
  run::RunRequest rq = program_request(a);
  for (const auto& v : a.vars) {
    auto r = run::parse_var_ref(v);
    SKIPNC_TRY(r);
    rq.vars.push_back(*r);
  }
  for (const auto& text : a.expect) {
    auto e = run::parse_expectation(text);
    SKIPNC_TRY(e);
    SKIPNC_TRY(run::check_alarm_name(*e, s.dialect));
    if (e->kind == run::Expectation::Kind::kVariable) {
      // Read after the run by run::check_outcome.
      SKIPNC_TRY(run::parse_var_ref("#" + e->var));
    }
    rq.expect.push_back(*e);
  }
  rq.plot_files = a.plot;
  return rq;
}

// The files the interpreter writes (--dprnt, --log-dir) and the stop flag
// (signals, the processor-time limit, an output that cannot go on).
run::RunIO run_io(const RunArgs& a) {
  run::RunIO io;
  io.interrupt = &run_stop().flag;
  io.dprnt_path = a.dprnt;
  io.log_dir = a.log_dir;
  return io;
}

// The --trace file, open (none without --trace). A trace that cannot go on
// (a full disk, a closed pipe, its size limit) stops the run.
Result<std::unique_ptr<report::CsvTrace>> open_trace(const RunArgs& a, const run::Session& s) {
  if (a.trace.empty()) return nullptr;
  auto trace = std::make_unique<report::CsvTrace>(a.trace, s.machine, nullptr);
  trace->every(a.trace_every);
  SKIPNC_TRY(trace->open());
  trace->on_stop([] { run_stop().request(StopReason::kOutput); });
  return trace;
}

// After the run and its checks: the JUnit file, the report, the summary and
// the failed checks. Returns the exit code (`rc`, or 1 for an output that
// could not be written).
int conclude(const RunArgs& a, const run::Session& s, report::ReportInput& in, std::size_t expects,
             int rc, bool explain) {
  if (!a.junit.empty()) {
    auto j = write_junit(a.junit, a.program, in.result.time_s, run_cases(a, in, s.dialect));
    if (!j) {
      std::cerr << "skipnc: " << j.error().detail << "\n";
      rc = rc == 0 ? 1 : rc;
    }
  }
  // The report is made only when asked for (it costs more than the run's
  // motion on a program of many short moves).
  if (!a.report.empty() && !write_report(a, report::to_json(in))) rc = rc == 0 ? 1 : rc;
  if (explain) return rc;
  std::FILE* out = is_stdout(a.report) || is_stdout(a.trace) ? stderr : stdout;
  if (in.result.alarm)
    std::cerr << "skipnc: " << run::describe(*in.result.alarm, &s.dialect) << "\n";
  in.result.variables = in.variables;  // the summary prints them too
  if (!a.quiet) print_summary(out, in.result, s, a.program);
  bool held = true;
  for (const auto& c : in.expectations) {
    if (!c.pass) std::cerr << "skipnc: " << c.message << "\n";
    held = held && c.pass;
  }
  if (expects > 0 && held && !a.quiet) {
    fmt::print(out, "  {} expectation{} held\n", expects, expects == 1 ? "" : "s");
  }
  return rc;
}

// Runs a loaded session; writes report and trace. Returns the exit code.
int execute(const RunArgs& a, run::Session& s, bool explain) {
  auto rq = read_request(a, s);
  if (!rq) return start_failure(a, rq.error(), &s);
  if (auto c = run::check_plot_files(a.plot); !c) return start_failure(a, c.error(), &s);
  if (auto c = check_outputs(a, s); !c) return start_failure(a, c.error(), &s);
  auto trace = open_trace(a, s);
  if (!trace) return start_failure(a, trace.error(), &s);
  run::RunIO io = run_io(a);
  io.trace = trace->get();
  std::optional<Watchdog> watchdog;
  io.progress = [&](double t, std::uint32_t line) { watchdog->update(t, line); };
  const run::Rig rig = run::rig_of(s);
  run::ProgramRun pr(rig, run::make_setup(s, rig, *rq, io), io, !a.plot.empty());
  watchdog.emplace(Watchdog::Options{s.machine.limits.max_cpu_s, a.progress,
                                     ::isatty(STDERR_FILENO) != 0 && !a.quiet && !explain});
  auto res = pr.run();
  watchdog.reset();
  if (!res) return start_failure(a, res.error(), &s);
  report::CsvTrace* t = trace->get();
  explain_stop(*res, t, s.machine);
  // The end of the trace, then the pictures: one that could not be written
  // is an alarm of the run.
  std::function<Result<void>()> finish;
  if (t != nullptr) finish = [t] { return t->finish(); };
  auto c = pr.conclude(s, std::move(*res), *rq, a.program, finish,
                       [](const Error& e) { std::cerr << "skipnc: " << e.detail << "\n"; });
  if (!c) return start_failure(a, c.error(), &s);
  return conclude(a, s, c->report, rq->expect.size(), c->exit_code, explain);
}

canon::AxisNames axis_names(const config::MachineConfig& m) {
  canon::AxisNames a;
  a.count = m.axis_count();
  for (int i = 0; i < a.count; ++i) a.names[i] = m.axes[static_cast<std::size_t>(i)].name;
  return a;
}

class PrintSink final : public canon::CommandSink {
 public:
  explicit PrintSink(const config::MachineConfig& m) : text_(axis_names(m)) {
    buf_.reserve(1 << 17);
  }
  ~PrintSink() override { flush(); }
  // The interpreter whose call contexts name the files (set once it exists).
  void set_interpreter(const interp::Interpreter* in) { in_ = in; }
  void emit(const canon::Stamped& c) override {
    if (c.source != source_ && in_ != nullptr) {
      // A FILE line where the commands start coming from another file or
      // program: "FILE O9023.nc O9023 called from bore.nc:9 (G65 P9023)".
      source_ = c.source;
      const auto& cs = in_->contexts();
      if (c.source < cs.size()) {
        const interp::CallContext& cc = cs[c.source];
        fmt::format_to(fmt::appender(buf_), "FILE {}", cc.file);
        if (cc.program > 0) fmt::format_to(fmt::appender(buf_), " O{}", cc.program);
        for (std::uint32_t k = c.source, depth = 0; k < cs.size() && depth < cs.size(); ++depth) {
          const interp::CallContext& callee = cs[k];
          if (callee.parent >= cs.size()) break;
          fmt::format_to(fmt::appender(buf_), " called from {}:{} ({})", cs[callee.parent].file,
                         callee.call_line, callee.call);
          k = callee.parent;
        }
        buf_.push_back('\n');
      }
    }
    text_.append(buf_, c);
    if (buf_.size() > (1 << 16)) flush();
  }
  void flush() {
    if (std::fwrite(buf_.data(), 1, buf_.size(), stdout) != buf_.size()) failed_ = true;
    buf_.clear();
  }
  // Standard output refused the text (a full disk, a closed pipe).
  bool failed() const noexcept { return failed_; }

 private:
  canon::TextWriter text_;
  fmt::memory_buffer buf_;
  bool failed_ = false;
  const interp::Interpreter* in_ = nullptr;
  std::uint32_t source_ = 0;
};

}  // namespace

int run_command(const RunArgs& a) {
  run::Session s;
  auto o = run::open_session(run::SessionOptions{a.machine, a.dialect, a.scene, a.params}, s);
  if (!o) return start_failure(a, o.error(), &s);
  if (auto c = run::check_allow(a.allow); !c) return start_failure(a, c.error(), &s);
  return execute(a, s, false);
}

int canon_command(const RunArgs& a) {
  run::Session s;
  auto o = run::open_session(run::SessionOptions{a.machine, a.dialect, "", a.params}, s);
  if (!o) return start_failure(a, o.error(), &s);
  if (auto c = run::check_allow(a.allow); !c) return start_failure(a, c.error(), &s);
  auto in = interp::Interpreter::create(
      run::make_setup(s, run::rig_of(s), program_request(a), run_io(a)), AxisVec{});
  if (!in) return start_failure(a, in.error(), &s);
  PrintSink sink(s.machine);
  Watchdog watchdog(Watchdog::Options{s.machine.limits.max_cpu_s, false, false});
  sink.set_interpreter(in->get());
  for (;;) {
    // Stopped by a signal or the processor-time limit; output that cannot
    // be written ends the command too.
    if (run_stop().flag.load(std::memory_order_relaxed) || sink.failed()) {
      sink.flush();
      const Error e =
          sink.failed() ? Error{AlarmId::kFileAccess, "cannot write standard output", {}, -1}
          : run_stop().why() == StopReason::kCpuLimit
              ? Error{AlarmId::kCpuLimit, "more than limits.max_cpu_s of processor time",
                      SourceLoc{a.program, (*in)->line(), 1}, -1}
              : Error{AlarmId::kInterrupted, "stopped by a signal",
                      SourceLoc{a.program, (*in)->line(), 1}, -1};
      std::cerr << "skipnc: " << run::describe(e, &s.dialect) << "\n";
      return 1;
    }
    auto st = (*in)->step(sink);
    if (!st) {
      sink.flush();
      std::cerr << "skipnc: " << run::describe(st.error(), &s.dialect) << "\n";
      return 1;
    }
    if (*st == interp::Step::kEnd) break;
    if (*st == interp::Step::kSync) {
      // Without a machine a skip block reaches its end point.
      interp::SyncState sync;
      sync.machine_position = (*in)->position();
      sync.actual_position = sync.machine_position;
      sync.skip_done = true;
      sync.no_machine = true;
      sync.latch_machine = sync.machine_position;
      auto r = (*in)->sync(sync);
      if (!r && r.error().id != AlarmId::kSkipMiss && r.error().id != AlarmId::kProbeNoContact &&
          r.error().id != AlarmId::kProbeNoBreak) {
        sink.flush();
        std::cerr << "skipnc: " << run::describe(r.error(), &s.dialect) << "\n";
        return 1;
      }
    }
  }
  sink.flush();
  // Warnings go to standard error: standard output is the command stream.
  for (const auto& w : (*in)->warnings()) {
    std::cerr << fmt::format("skipnc: warning ({}): {}: {}\n", w.code,
                             report::where((*in)->contexts(), w.context, w.line), w.text);
  }
  return sink.failed() ? 1 : 0;
}

namespace {

// The probing features of a dialect that probes with G38.2-G38.5.
template <class AlarmText>
void print_g38_dialect(const config::Dialect& d, const std::string& inputs,
                       const AlarmText& alarm) {
  const config::Switches& sw = d.sw;
  fmt::print(
      "  command     G38.2 toward, G38.3 toward (no error), G38.4 away, G38.5 away "
      "(no error); modal group 01\n");
  fmt::print("  inputs      {} (the probe){}\n", inputs,
             sw.probe_invert_param != 0 ? fmt::format("; ${} = 1 inverts it", sw.probe_invert_param)
                                        : std::string());
  fmt::print("  detection   level; away from the part: the input going inactive\n");
  auto pair = [&](AlarmId a, AlarmId b) {
    const std::string x = alarm(a), y = alarm(b);
    return x == y ? x : x + " / " + y;
  };
  fmt::print("  at start    already in the target state: {}; no motion\n",
             pair(AlarmId::kProbeTrippedAtStart, AlarmId::kProbeClearAtStart));
  fmt::print("  feed        F, else modal F (F is modal); override and acc/dec as G01\n");
  fmt::print("  stop        linear deceleration\n");
  fmt::print("  latch       {}, {} position\n",
             sw.probe_latch_sampled ? "the first servo sample that sees the input"
                                    : "the instant of the edge",
             sw.probe_latch_actual ? "feedback (actual)" : "commanded (step count)");
  fmt::print("  miss        G38.2, G38.4: {}; G38.3, G38.5 complete normally\n",
             pair(AlarmId::kProbeNoContact, AlarmId::kProbeNoBreak));
  fmt::print("  results     {}\n",
             sw.probe_report_line
                 ? std::string("[PRB:x,y,z:1|0] in machine coordinates (messages, console)")
                 : fmt::format("#{}-#{} in work coordinates, tool offset {}; #{} = 1 on contact",
                               d.skip_vars.work_base, d.skip_vars.work_base + 8,
                               sw.skip_tool_offsets ? "in" : "out", d.skip_vars.success_flag));
  fmt::print("  alarms      radius comp {}; no feed {}; no axis {}; end = start {}{}\n",
             alarm(AlarmId::kProbeInCutterComp), alarm(AlarmId::kProbeZeroFeed),
             alarm(AlarmId::kProbeNoAxis), alarm(AlarmId::kProbeTooShort),
             sw.probe_same_point_all ? " (every G38)" : " (G38.2, G38.4)");
}

// A parameter as `dialects` names it: "6240 skip feed" ("?" when the
// dialect has none of that number).
std::string param_text(const config::Dialect& d, int n) {
  const config::ParamDef* p = d.param(n);
  return p == nullptr ? std::string("?") : fmt::format("{} {}", n, p->name);
}

// How a G31 dialect selects and detects its skip signal.
void print_skip_signal(const config::Dialect& d, const std::string& inputs) {
  using config::SkipPMode;
  const auto& sw = d.sw;
  const int last = sw.skip_p_first + sw.skip_p_count - 1;
  fmt::print("  P word      {}\n",
             sw.skip_p_mode == SkipPMode::kMultiStep
                 ? fmt::format("multi-step skip P{}-P{}", sw.skip_p_first, last)
             : sw.skip_p_mode == SkipPMode::kSelect
                 ? fmt::format("selects skip input P{}-P{} (no P: input 1)", sw.skip_p_first, last)
             : sw.skip_p_mode == SkipPMode::kBitmask
                 ? fmt::format("bit mask of inputs 1-{}: P1-P{}", sw.skip_p_count,
                               (1 << sw.skip_p_count) - 1)
                 : std::string("none"));
  fmt::print("  inputs      {}{}\n", inputs,
             d.param(config::param::kSkipAddressing) != nullptr
                 ? " (fixed; 3008#2 = 1: parameters 3012, 3020-3025)"
                 : "");
  fmt::print("  detection   {}\n",
             sw.skip_edge_rising_only ? std::string("rising edge only")
             : sw.skip_signal_param != 0
                 ? fmt::format("parameter {} (#0 level/edge, #1 polarity)", sw.skip_signal_param)
                 : std::string("level, active high"));
  fmt::print("  at start    {}\n", sw.skip_edge_rising_only ? "waits for a new edge"
                                   : sw.skip_active_at_start_ends
                                       ? "ends the block at once (level detection)"
                                       : "waits for a new edge");
}

// How a G31 dialect's skip block moves, stops and misses.
void print_skip_motion(const config::Dialect& d) {
  using config::SkipAccel;
  using config::SkipFeedRule;
  using config::SkipOverride;
  const auto& sw = d.sw;
  fmt::print("  feed        {}\n",
             sw.skip_feed == SkipFeedRule::kModal ? std::string("F, else modal F")
             : sw.skip_feed == SkipFeedRule::kBlockOrParam && sw.skip_feed_param == 0
                 ? std::string("F in the block (required); modal F not updated")
             : sw.skip_feed == SkipFeedRule::kBlockOrParam
                 ? "F, else " + param_text(d, sw.skip_feed_param) + "; modal F not updated"
             : sw.skip_feed == SkipFeedRule::kParamSwitch
                 ? param_text(d, sw.skip_feed_switch_param) +
                       " = 0: F or modal F; 1: " + param_text(d, sw.skip_feed_param)
                 : std::string("F, else the last non-rapid feed"));
  fmt::print("  override    {}; acc/dec {}\n",
             sw.skip_override == SkipOverride::kSkfParam ? "SKF (6200#7)"
             : sw.skip_override == SkipOverride::kFixed  ? "fixed 100 % (0 % stops), no dry run"
                                                         : "as G01",
             sw.skip_accel == SkipAccel::kSkfParam ? "SKF (6200#7)"
             : sw.skip_accel == SkipAccel::kNever  ? "none"
                                                   : "as G01");
  fmt::print("  stop        {}\n",
             sw.skip_stop == canon::SkipStop::kImmediate ? "immediate" : "linear deceleration");
  fmt::print("  miss        {}\n",
             sw.skip_k_word ? "K1 alarm, K0 none; K omitted: " + param_text(d, sw.skip_miss_param)
                            : std::string("completes normally"));
  fmt::print("  torque skip {}\n", sw.torque_skip
                                       ? "P98/P99, Q or " + param_text(d, sw.torque_q_param) +
                                             ", delay " + param_text(d, sw.torque_delay_param)
                                       : std::string("no"));
}

// A G31 dialect's other skip rules, its result variables and its alarms.
template <class AlarmText>
void print_skip_rest(const config::Dialect& d, const AlarmText& alarm) {
  const auto& sw = d.sw;
  std::string other;
  for (const auto& [on, text] :
       {std::pair{sw.skip_g53_allowed, "G31 G53: target in machine coordinates"},
        std::pair{sw.skip_ignored_when_locked, "skip ignored in machine lock / Z-axis cancel"},
        std::pair{!sw.skip_ignored_when_locked && !sw.skip_locked_stores_command,
                  "a skip in machine lock stores where the machine stands"},
        std::pair{sw.tool_position_offset, "G45-G48 tool offsets enter #5061.."},
        std::pair{sw.skip_requires_axis, "G31 without an axis word is a format error"},
        std::pair{!d.handshake.empty(), "PLC handshake in the trace"},
        std::pair{sw.local_sub_call_m97, "M97 local subprogram call"},
        std::pair{sw.block_lookahead_g103, "G103 P0-P15 look-ahead limit (accepted)"},
        std::pair{sw.m99_p_jumps_in_subprogram, "M99 Pn in a subprogram branches within it"},
        std::pair{sw.haas_tool_offset_vars, "#2001-#2800 tool offsets as Haas numbers them"},
        std::pair{sw.offset_variables_by == config::OffsetVariables::kLetter,
                  "work offsets #5201.. by axis letter (X Y Z A B C)"}}) {
    if (on) other += (other.empty() ? "" : "; ") + std::string(text);
  }
  fmt::print("  other       {}\n", other.empty() ? "-" : other);
  fmt::print("  results     {}{}\n",
             d.skip_vars.work_base != 0 ? fmt::format("#{}.. ", d.skip_vars.work_base) : "",
             d.skip_vars.named_local.empty()
                 ? std::string()
                 : "#<" + d.skip_vars.named_machine + "X> #<" + d.skip_vars.named_local + "X>");
  fmt::print("  alarms      radius comp {}; no feed {}; P {}; format {}\n",
             alarm(AlarmId::kSkipInCutterComp), alarm(AlarmId::kSkipNoFeed),
             alarm(AlarmId::kSkipBadP), alarm(AlarmId::kSkipSyntax));
}

}  // namespace

// One line per skip feature that differs between the dialects.
int dialects_command() {
  for (const auto& name : config::builtin_dialect_names()) {
    auto d = config::builtin_dialect(name);
    if (!d) {
      fmt::print("{:<11} (cannot load: {})\n", name, d.error().detail);
      continue;
    }
    const auto& sw = d->sw;
    auto alarm = [&](AlarmId id) {
      const config::AlarmText& a = d->alarm(id);
      return fmt::format("{} {}", a.code, a.message);
    };
    std::string inputs;
    for (const auto& a : d->fixed_skip_inputs) {
      inputs += (inputs.empty() ? "" : " ") + config::signal_name(a);
    }
    fmt::print("{:<11} {}\n", d->name, d->title);
    fmt::print("  language    {}\n",
               sw.language == config::Language::kRs274ngc
                   ? "RS274NGC: O-word subroutines and flow, numbered and named parameters"
               : sw.language == config::Language::kGrbl
                   ? "G code only: no parameters, expressions or subprograms"
                   : "Custom Macro B: #1-#33 locals, IF/GOTO/WHILE, G65/G66, M98/M99");
    if (sw.probe_g38 && !sw.skip_g31) {
      print_g38_dialect(*d, inputs, alarm);
      continue;
    }
    print_skip_signal(*d, inputs);
    print_skip_motion(*d);
    print_skip_rest(*d, alarm);
  }
  return 0;
}

namespace {

// The demo's program, numbered, as the user reads it.
void print_demo_program(std::string_view program) {
  std::cout
      << "skipnc demo: a touch probe finds the top of a part on the built-in mill3 (fanuc).\n"
      << "The scene puts the part's top face at Z-23.8 (machine); the probe is wired to X0.4.\n\n"
      << "Program:\n";
  for (std::size_t i = 0, line = 1; i < program.size(); ++line) {
    const auto nl = program.find('\n', i);
    const auto text =
        program.substr(i, nl == std::string_view::npos ? std::string_view::npos : nl - i);
    fmt::print("  {:>3}  {}\n", line, text);
    if (nl == std::string_view::npos) break;
    i = nl + 1;
  }
}

// What happened, in the user's terms: each touch, the stored values, the end.
void print_demo_outcome(const sim::RunResult& r, const run::Session& s,
                        const std::function<double(int)>& var) {
  std::cout << "\nWhat happened:\n";
  for (const auto& sk : r.skips) {
    const double over = sk.position[2] - sk.end_position[2];
    fmt::print(
        "  line {:>2}  {:<22}  {} at t = {:.4f} s: Z stored in #5063 = {:.4f}; "
        "the axis stopped at Z{:.4f} ({:.4f} mm past the touch)\n",
        sk.line, sk.block, sk.triggered ? "probe signal " + sk.signal : std::string("no signal"),
        sk.time_s, sk.position[2], sk.end_position[2], over);
  }
  fmt::print(
      "\n  first touch  #100 = {:.4f}\n  second touch #101 = {:.4f}  (slower, so it stops closer)\n"
      "  G54 Z offset #5223 = {:.4f}  (written by G10 L2 P1)\n",
      var(100), var(101), var(5223));
  print_warnings(stdout, r);
  for (const auto& m : r.messages) fmt::print("  message: {}\n", m);
  fmt::print("\n{} after {:.3f} s of machine time; final position {}\n",
             r.status == sim::RunStatus::kCompleted ? "Completed" : "Stopped by an alarm", r.time_s,
             fmt_axes(r.final_work, s.machine));
  if (r.alarm) std::cout << "  " << run::describe(*r.alarm, &s.dialect) << "\n";
}

constexpr int kDemoVariables[] = {100, 101, 102, 5223};

// The report and pictures the user asked for; false when one could not be written.
bool write_demo_outputs(const RunArgs& a, const run::Session& s, const sim::RunResult& r,
                        run::PlotCapture* plot, std::string_view program,
                        const std::function<double(int)>& var) {
  bool ok = true;
  if (!a.report.empty()) {
    report::ReportInput in = run::report_input(s, a.program, r);
    for (int n : kDemoVariables) in.variables.emplace_back(std::to_string(n), var(n));
    ok &= write_report(a, report::to_json(in));
  }
  if (plot != nullptr) {
    std::vector<std::pair<std::string, std::optional<double>>> vars;
    for (int n : kDemoVariables) vars.emplace_back(std::to_string(n), var(n));
    auto w = plot->write(a.plot, s, r, {a.program, program, vars});
    if (!w) {
      std::cerr << "skipnc: " << w.error().detail << "\n";
      ok = false;
    }
  }
  return ok;
}

}  // namespace

// `skipnc demo`: the built-in probing program on mill3, explained (-q: only
// the outputs asked for, and the exit status).
int demo_command(const RunArgs& args) {
  RunArgs a = args;
  a.program = "probe_demo.nc";
  run::Session s;
  auto o = run::open_session(run::SessionOptions{"mill3", "", "", {}}, s);
  if (!o) return start_failure(a, o.error(), &s);
  const EmbeddedFile* prog = embedded_entry("demo/probe_demo.nc");
  const EmbeddedFile* scene = embedded_entry("demo/probe_demo.toml");
  if (prog == nullptr || scene == nullptr) {
    return start_failure(a, Error{AlarmId::kInternal, "demo files missing from the build", {}, -1},
                         &s);
  }
  auto sc = machine::parse_scene(scene->content, scene->path, s.machine, s.dialect, *s.params);
  if (!sc) return start_failure(a, sc.error(), &s);
  s.scene = std::move(*sc);
  if (!a.quiet) print_demo_program(prog->content);
  if (auto c = run::check_plot_files(a.plot); !c) return start_failure(a, c.error(), &s);
  if (auto c = check_outputs(a, s); !c) return start_failure(a, c.error(), &s);
  auto trace = open_trace(a, s);
  if (!trace) return start_failure(a, trace.error(), &s);
  run::RunRequest rq = program_request(a);
  rq.program_path.clear();  // the embedded text, named probe_demo.nc
  rq.program_text = std::string(prog->content);
  run::RunIO io = run_io(a);
  io.trace = trace->get();
  const run::Rig rig = run::rig_of(s);
  run::ProgramRun pr(rig, run::make_setup(s, rig, rq, io), io, !a.plot.empty());
  auto res = pr.run();
  if (!res) return start_failure(a, res.error(), &s);
  explain_stop(*res, trace->get(), s.machine);
  bool output_failed = false;
  if (*trace) {
    if (auto f = (*trace)->finish(); !f) {
      std::cerr << "skipnc: " << f.error().detail << "\n";
      output_failed = true;
    }
  }
  const auto var = [&](int n) {
    auto v = pr.interpreter().read_variable(n);
    return v && !v->vacant ? v->v : 0.0;
  };
  if (!a.quiet) print_demo_outcome(*res, s, var);
  output_failed |= !write_demo_outputs(a, s, *res, pr.plot(), prog->content, var);
  if (!a.quiet) {
    std::cout
        << "\nTry it yourself: skipnc run PROGRAM --scene SCENE --report report.json --var 5063\n";
  }
  return res->status == sim::RunStatus::kCompleted && !output_failed ? 0 : 1;
}

int plot_command(RunArgs a) {
  if (a.plot.empty()) {
    const std::string stem = std::filesystem::path(a.program).stem().string();
    a.plot = {stem + ".html", stem + ".svg"};
  }
  const int rc = run_command(a);
  if (rc != 2 && !a.quiet) {
    for (const auto& f : a.plot) {
      std::error_code ec;
      if (std::filesystem::is_regular_file(f, ec)) fmt::print("wrote {}\n", f);
    }
  }
  return rc;
}

}  // namespace skipnc::cli
