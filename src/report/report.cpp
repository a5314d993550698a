#include "report/report.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <iostream>
#include <nlohmann/json.hpp>

#include "config/skip_inputs.hpp"
#include "core/decimal.hpp"
#include "core/file.hpp"

namespace skipnc::report {

using nlohmann::ordered_json;

// Trace rows are written in pieces of this size (a system call per 64 KiB).
constexpr std::size_t kTraceBufferBytes = std::size_t{1} << 16;

AlarmView view_alarm(const Error& e, const config::Dialect* d) {
  AlarmView v;
  if (d != nullptr) {
    const config::AlarmText& t = d->alarm(e.id);
    v.number = t.number;
    v.code = t.code;
    v.message = t.message;
  } else {
    v.code = std::string(alarm_key(e.id));
    v.message = std::string(alarm_key(e.id));
  }
  if (e.id == AlarmId::kUserAlarm && e.user_number >= 0) {
    // #3000 = n: the control shows alarm 3000 + n with the program's message.
    v.number = (v.number > 0 ? v.number : 3000) + e.user_number;
    v.code = (v.code.empty() ? std::string("MC") : v.code) + fmt::format("{:04d}", e.user_number);
    v.message = e.detail.empty() ? v.message : e.detail;
    return v;
  }
  if (!e.detail.empty()) v.message += ": " + e.detail;
  return v;
}

double clean(double v) noexcept {
  if (!(std::fabs(v) < 1e6)) return v;
  return std::round(v * 1e9) / 1e9 + 0.0;
}

std::string where(const std::vector<record::CallContext>& contexts, std::uint32_t context,
                  std::uint32_t line, int n) {
  if (context >= contexts.size()) return "line " + std::to_string(line);
  const record::CallContext& here = contexts[context];
  std::string out = here.file + ":" + std::to_string(line);
  if (here.program > 0 || n >= 0) {
    out += " (";
    if (here.program > 0) out += "O" + std::to_string(here.program);
    if (n >= 0) out += std::string(here.program > 0 ? " " : "") + "N" + std::to_string(n);
    out += ")";
  }
  // Each context knows the block that called it, in its parent.
  std::uint32_t c = context;
  for (std::size_t depth = 0; depth < contexts.size(); ++depth) {
    const record::CallContext& callee = contexts[c];
    if (callee.parent >= contexts.size()) break;
    out += " called from " + contexts[callee.parent].file + ":" + std::to_string(callee.call_line) +
           " (" + callee.call + ")";
    c = callee.parent;
  }
  return out;
}

namespace {

ordered_json axes_json(const AxisVec& v, const config::MachineConfig* m) {
  ordered_json o = ordered_json::object();
  if (m == nullptr) return o;
  for (int i = 0; i < m->axis_count(); ++i) {
    o[std::string(1, m->axes[static_cast<std::size_t>(i)].name)] = clean(v[i]);
  }
  return o;
}

// The call stack of a block, innermost first: where each level runs, and
// the call that started it.
ordered_json stack_json(const std::vector<record::CallContext>& cs, std::uint32_t ctx,
                        std::uint32_t line) {
  ordered_json a = ordered_json::array();
  std::uint32_t at = line;
  for (std::size_t depth = 0; ctx < cs.size() && depth < cs.size(); ++depth) {
    const record::CallContext& c = cs[ctx];
    ordered_json o;
    o["file"] = c.file;
    o["line"] = at;
    o["program"] =
        c.program > 0 ? ordered_json("O" + std::to_string(c.program)) : ordered_json(nullptr);
    o["call"] = c.call.empty() ? ordered_json(nullptr) : ordered_json(c.call);
    a.push_back(o);
    at = c.call_line;
    ctx = c.parent;
  }
  return a;
}

ordered_json program_json(const std::vector<record::CallContext>& cs, std::uint32_t ctx) {
  if (ctx >= cs.size() || cs[ctx].program <= 0) return nullptr;
  return "O" + std::to_string(cs[ctx].program);
}

// Where a block is, as skips and warnings give it: line, file, program
// (O number), N number (skips), where ("file:line (O..) called from ...").
void place_json(ordered_json& o, const std::vector<record::CallContext>& cs,
                const std::string& program, std::uint32_t ctx, std::uint32_t line, int n,
                bool with_n) {
  const bool known = ctx < cs.size();
  o["line"] = line;
  o["file"] = known ? ordered_json(cs[ctx].file) : ordered_json(program);
  o["program"] = program_json(cs, ctx);
  if (with_n) o["n"] = n >= 0 ? ordered_json(n) : ordered_json(nullptr);
  o["where"] = known ? where(cs, ctx, line, n) : std::string();
}

// Structured warnings (docs/cli.md): what the run did that is not an alarm
// but may not be what the program meant.
ordered_json warnings_json(const sim::RunResult& r, const std::string& program) {
  ordered_json out = ordered_json::array();
  for (const auto& w : r.warnings) {
    ordered_json o;
    o["code"] = w.code;
    place_json(o, r.contexts, program, w.context, w.line, -1, false);
    o["text"] = w.text;
    o["count"] = w.count;
    out.push_back(o);
  }
  return out;
}

// Per-block timing: the machine's time in each place (file, line), in the
// order the places first ran; a loop's block adds its runs. At most
// kMaxBlockTimes places are listed (a CAM program of 100 000 lines still has
// its cycle time and its first places).
ordered_json block_times_json(const sim::RunResult& r, const std::string& program) {
  constexpr std::size_t kMaxBlockTimes = 10000;
  ordered_json times;
  times["cycle_time"] = clean(r.time_s);
  times["places"] = r.block_times.size();
  const std::size_t listed = std::min(r.block_times.size(), kMaxBlockTimes);
  times["listed"] = listed;
  ordered_json blocks = ordered_json::array();
  for (std::size_t i = 0; i < listed; ++i) {
    const sim::BlockTime& b = r.block_times[i];
    ordered_json o;
    place_json(o, r.contexts, program, b.context, b.line, -1, false);
    o["runs"] = b.runs;
    o["start"] = clean(static_cast<double>(b.first) * r.period_s);
    o["end"] = clean(static_cast<double>(b.last) * r.period_s);
    o["time"] = clean(static_cast<double>(b.ticks) * r.period_s);
    blocks.push_back(o);
  }
  times["blocks"] = blocks;
  return times;
}

const char* ended_by(const record::SkipRecord& s) {
  if (s.ended_by_alarm) return "alarm";
  if (!s.triggered) return "end_point";
  return s.signal == "TORQUE" ? "torque" : "signal";
}

const char* kind_name(canon::SkipKind k) {
  switch (k) {
    case canon::SkipKind::kSkip:
      return "skip";
    case canon::SkipKind::kMultiStep:
      return "multi_step";
    case canon::SkipKind::kTorque:
      return "torque";
    case canon::SkipKind::kProbe:
      return "probe";
  }
  return "skip";
}

// The --expect verdicts: pass, what the run gave, what was expected and the
// tolerance (numbers as numbers, words as strings, null when none).
ordered_json expectations_json(const std::vector<CheckResult>& checks) {
  ordered_json out = ordered_json::array();
  auto either = [](const std::optional<double>& x, const std::string& t) {
    if (x) return ordered_json(clean(*x));
    return t.empty() ? ordered_json(nullptr) : ordered_json(t);
  };
  for (const CheckResult& c : checks) {
    ordered_json o;
    o["expect"] = c.text;
    o["name"] = c.name;
    o["pass"] = c.pass;
    o["value"] = either(c.value, c.value_text);
    o["expected"] = either(c.expected, c.expected_text);
    o["tolerance"] = c.tolerance ? ordered_json(*c.tolerance) : ordered_json(nullptr);
    o["message"] = c.message.empty() ? ordered_json(nullptr) : ordered_json(c.message);
    out.push_back(o);
  }
  return out;
}

}  // namespace

const char* status_name(sim::RunStatus s) noexcept {
  switch (s) {
    case sim::RunStatus::kCompleted:
      return "completed";
    case sim::RunStatus::kAlarm:
      return "alarm";
    case sim::RunStatus::kInterrupted:
      return "interrupted";
  }
  return "alarm";
}

namespace {

// The report's "alarm": the alarm of the run or the error that stopped its
// start (null when neither).
ordered_json alarm_json(const ReportInput& in) {
  const sim::RunResult& r = in.result;
  const Error* err = in.start_error ? &*in.start_error : (r.alarm ? &*r.alarm : nullptr);
  if (err == nullptr) return nullptr;
  const AlarmView v = view_alarm(*err, in.dialect_table);
  ordered_json a;
  a["number"] = v.number;
  a["code"] = v.code;
  a["message"] = v.message;
  a["file"] =
      err->loc.file.empty() ? ordered_json(nullptr) : ordered_json(std::string(err->loc.file));
  a["line"] = err->loc.line == 0 ? ordered_json(nullptr) : ordered_json(err->loc.line);
  a["column"] = err->loc.column == 0 ? ordered_json(nullptr) : ordered_json(err->loc.column);
  a["key"] = std::string(alarm_key(err->id));
  if (!in.start_error && r.alarm_position)
    a["machine_position"] = axes_json(*r.alarm_position, in.machine);
  if (!in.start_error && !r.contexts.empty()) {
    a["program"] = program_json(r.contexts, r.alarm_context);
    a["where"] = where(r.contexts, r.alarm_context, err->loc.line);
    a["call_stack"] = stack_json(r.contexts, r.alarm_context, err->loc.line);
  }
  return a;
}

// The skip in progress when the alarm stopped the run: the latch when the
// input came, where the alarm was raised, and how far past the latch that was.
void crash_json(ordered_json& o, const record::SkipRecord& s, const config::MachineConfig* m) {
  o["crash_machine_position"] =
      s.crash_machine ? axes_json(*s.crash_machine, m) : ordered_json(nullptr);
  if (s.triggered && s.crash_machine && m != nullptr) {
    double d2 = 0.0;
    for (int i = 0; i < m->axis_count(); ++i) {
      const double d = (*s.crash_machine)[i] - s.machine_position[i];
      d2 += d * d;
    }
    o["overtravel_mm"] = clean(std::sqrt(d2));
  } else {
    o["overtravel_mm"] = nullptr;
  }
}

// The report's "skips": one object per skip block run.
ordered_json skips_json(const ReportInput& in) {
  const sim::RunResult& r = in.result;
  ordered_json skips = ordered_json::array();
  for (const auto& s : r.skips) {
    ordered_json o;
    place_json(o, r.contexts, in.program, s.context, s.line, s.n, true);
    o["call_stack"] = stack_json(r.contexts, s.context, s.line);
    o["block"] = s.block;
    o["kind"] = kind_name(s.kind);
    o["p"] = s.p >= 0 ? ordered_json(s.p) : ordered_json(nullptr);
    o["signal"] = s.signal.empty() ? ordered_json(nullptr) : ordered_json(s.signal);
    o["triggered"] = s.triggered;
    // An alarm that cut the block short before any signal latched nothing:
    // no time, no position (spec/cli.md), not a point never visited.
    const bool latched = s.triggered || !s.ended_by_alarm;
    o["time"] = latched ? ordered_json(clean(s.time_s)) : ordered_json(nullptr);
    // The number #5061.. hold (rounded to the least input increment where
    // the dialect's skip_position_increment says the control does).
    o["position"] = latched ? axes_json(s.position, in.machine) : ordered_json(nullptr);
    // What `position` (#5061..) is: the tool reference point (tool offsets
    // in it) or the programmed tip (docs/position-variables.md).
    o["position_point"] = s.position_has_tool_offsets ? "tool_reference" : "tip";
    o["machine_position"] =
        latched ? axes_json(s.machine_position, in.machine) : ordered_json(nullptr);
    o["end_position"] = axes_json(s.end_position, in.machine);
    o["ended_by"] = ended_by(s);
    if (s.ended_by_alarm) crash_json(o, s, in.machine);
    skips.push_back(o);
  }
  return skips;
}

}  // namespace

std::string to_json(const ReportInput& in) {
  ordered_json j;
  j["format"] = "skipnc-report/1";
  j["program"] = in.program;
  j["dialect"] = in.dialect;
  const sim::RunResult& r = in.result;
  j["status"] = in.start_error ? "alarm" : status_name(r.status);
  j["alarm"] = alarm_json(in);
  j["skips"] = skips_json(in);
  ordered_json vars = ordered_json::object();
  for (const auto& [k, v] : in.variables)
    vars[k] = v ? ordered_json(clean(*v)) : ordered_json(nullptr);
  j["variables"] = vars;
  j["expectations"] = expectations_json(in.expectations);
  ordered_json fin;
  fin["position"] = axes_json(r.final_work, in.machine);
  fin["machine_position"] = axes_json(r.final_machine, in.machine);
  fin["time"] = clean(r.time_s);
  j["final"] = fin;
  j["messages"] = r.messages;
  j["warnings"] = warnings_json(r, in.program);
  j["block_times"] = block_times_json(r, in.program);
  if (r.stock) {
    // Only with a [stock] in the scene: what the cutting moves removed.
    ordered_json st;
    st["removed_volume_mm3"] = clean(r.stock->removed_mm3);
    j["stock"] = st;
  }
  if (in.machine != nullptr) j["machine"] = in.machine->name;
  // Units of the numbers above: work positions and stored variables in the
  // program's units (G20/G21 at the end), machine positions in mm, times in s.
  ordered_json units;
  units["program"] = r.program_inch ? "inch" : "mm";
  units["machine"] = "mm";
  units["time"] = "s";
  j["units"] = units;
  // Every text of the report is valid UTF-8: bytes that are not (a Latin-1
  // comment, a file name, a command-line word) are replaced visibly with
  // U+FFFD, one per maximal ill-formed subpart, the rule of utf8::make_valid
  // (core/utf8.hpp); dump() then never throws.
  return j.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

Result<void> write_atomic(const std::string& path, const std::string& text) {
  return write_file_atomic(path, text);
}

CsvTrace::CsvTrace(std::string path, const config::MachineConfig& m, const machine::Plant*)
    : path_(std::move(path)),
      m_(m),
      max_bytes_(static_cast<std::uint64_t>(m.limits.max_trace_bytes)) {}

CsvTrace::~CsvTrace() = default;  // an unfinished trace's temporary file is removed

Result<void> CsvTrace::open() {
  auto f = OutputFile::open(path_);
  if (!f) {
    Error e = f.error();
    e.detail = "trace: " + e.detail;
    return std::unexpected(std::move(e));
  }
  out_ = std::move(*f);
  opened_ = true;
  buf_.reserve(kTraceBufferBytes + 1024);
  return {};
}

void CsvTrace::fail_with(Error e) {
  if (error_) return;
  error_ = std::move(e);
  buf_.clear();
  if (stop_) stop_();
}

void CsvTrace::flush_buffer() {
  if (buf_.empty() || error_) return;
  auto w = out_.write(buf_);
  buf_.clear();
  if (!w) {
    Error e = w.error();
    e.detail = "trace: " + e.detail;
    fail_with(std::move(e));
  }
}

TraceColumns TraceColumns::of(const config::MachineConfig& m, const sim::TraceRow& r) {
  TraceColumns c;
  c.axes = m.axis_count();
  c.names = {"time_s", "line", "file", "feed_mm_min"};
  for (const char* kind : {"cmd", "act", "ferr", "torque"}) {
    for (const auto& a : m.axes) c.names.push_back(std::string(1, a.name) + "_" + kind);
  }
  if (r.plant != nullptr) {
    c.signals = r.plant->signal_count();
    for (std::size_t i = 0; i < c.signals; ++i) {
      c.names.push_back(config::signal_name(r.plant->signal_addr(i)));
    }
  }
  if (r.handshake_names != nullptr) {
    c.handshake = true;
    for (const std::string* name : {&r.handshake_names->active, &r.handshake_names->skip,
                                    &r.handshake_names->recorded, &r.handshake_names->done}) {
      c.names.push_back(*name);
    }
  }
  // The touch probe of the scene: its stylus's deflection (mm) and whether
  // the ball touches a surface (docs/scene.md).
  c.probe = r.plant != nullptr ? r.plant->probing().probe() : nullptr;
  if (c.probe != nullptr) {
    c.names.emplace_back("probe_deflection");
    c.names.emplace_back("probe_contact");
  }
  // The actual position in the running block's work coordinates (as
  // #5041..), and the tip of what is in the spindle along Z (machine) when
  // the scene gives its tools or probe a length.
  c.work = r.work != nullptr;
  if (c.work) {
    for (const auto& a : m.axes) c.names.push_back(std::string(1, a.name) + "_work");
  }
  if (r.plant != nullptr) {
    const auto& spec = r.plant->probing().spec();
    if (spec.probe || !spec.tools.empty()) c.tip_axis = m.axis_index('Z');
  }
  if (c.tip_axis >= 0) {
    c.names.push_back(std::string(1, m.axes[static_cast<std::size_t>(c.tip_axis)].name) + "_tip");
  }
  return c;
}

void TraceColumns::numbers(const sim::TraceRow& r, std::vector<double>& out) const {
  out.clear();
  out.push_back(r.time_s);
  out.push_back(static_cast<double>(r.line));
  out.push_back(r.feed_mm_per_min);
  const AxisVec ferr = *r.commanded - *r.actual;
  for (const AxisVec* v : {r.commanded, r.actual, &ferr, r.torque}) {
    for (int i = 0; i < axes; ++i) out.push_back((*v)[i]);
  }
  for (std::size_t i = 0; i < signals; ++i) out.push_back(r.plant->signal_level(i) ? 1.0 : 0.0);
  if (handshake) {
    for (bool b : {r.handshake.active, r.handshake.skip, r.handshake.recorded, r.handshake.done}) {
      out.push_back(b ? 1.0 : 0.0);
    }
  }
  if (probe != nullptr) {
    out.push_back(probe->deflection());
    out.push_back(probe->touching() ? 1.0 : 0.0);
  }
  if (work) {
    for (int i = 0; i < axes; ++i) out.push_back(r.work != nullptr ? (*r.work)[i] : 0.0);
  }
  if (tip_axis >= 0) {
    out.push_back((*r.actual)[tip_axis] - r.plant->probing().spindle_tool_length());
  }
}

void CsvTrace::header(const sim::TraceRow& r) {
  const TraceColumns c = TraceColumns::of(m_, r);
  for (std::size_t i = 0; i < c.names.size(); ++i) {
    if (i > 0) buf_ += ',';
    buf_ += c.names[i];
  }
  buf_ += '\n';
  probe_ = c.probe;
  work_ = c.work;
  tip_axis_ = c.tip_axis;
  header_done_ = true;
}

namespace {

// Trace numbers are rounded to 6 decimals (1 nm in mm, 1 us in seconds,
// 0.000001 % of torque), trailing zeros dropped: finer than any machine
// measures, and a tenth of the cost of the shortest exact text. Values too
// large for that (or not finite) are written in full.
constexpr std::size_t kNumberRoom = 32;

char* trace_number(char* p, double v) noexcept {
  if (v > -1e12 && v < 1e12) {
    const double scaled = v * 1e6;
    const auto m = static_cast<std::int64_t>(scaled < 0 ? scaled - 0.5 : scaled + 0.5);
    return decimal::write_scaled<6>(p, m);
  }
  return std::to_chars(p, p + kNumberRoom, v).ptr;
}

}  // namespace

void CsvTrace::row(const sim::TraceRow& r) {
  if (!opened_ || error_) return;
  if (every_ > 1 && r.tick % every_ != 0) return;
  write_row(r);
}

// --trace-every larger than the run (or not dividing its length): the header
// and the last period are written all the same (was: an empty file).
void CsvTrace::last(const sim::TraceRow& r) {
  if (!opened_ || error_ || r.tick == last_tick_) return;
  write_row(r);
}

void CsvTrace::write_row(const sim::TraceRow& r) {
  last_tick_ = r.tick;
  if (!header_done_) {
    header(r);
    bytes_ += buf_.size();
  }
  const int n = m_.axis_count();
  const std::size_t signals = r.plant != nullptr ? r.plant->signal_count() : 0;
  const std::size_t room = (6 + 5 * static_cast<std::size_t>(n)) * (kNumberRoom + 1) +
                           2 * (signals + 4) + 1 + 2 * r.file.size() + 3;
  if (row_.size() < room) row_.resize(room);
  char* p = row_.data();
  p = trace_number(p, r.time_s);
  *p++ = ',';
  p = decimal::write_int(p, r.line);
  *p++ = ',';
  // The block's file (CSV-quoted when it holds a comma or a quote).
  if (r.file.find_first_of(",\"") == std::string_view::npos) {
    for (char c : r.file) *p++ = c;
  } else {
    *p++ = '"';
    for (char c : r.file) {
      if (c == '"') *p++ = '"';
      *p++ = c;
    }
    *p++ = '"';
  }
  *p++ = ',';
  p = trace_number(p, r.feed_mm_per_min);
  const AxisVec ferr = *r.commanded - *r.actual;  // following error
  for (const AxisVec* v : {r.commanded, r.actual, &ferr, r.torque}) {
    for (int i = 0; i < n; ++i) {
      *p++ = ',';
      p = trace_number(p, (*v)[i]);
    }
  }
  for (std::size_t i = 0; i < signals; ++i) {
    *p++ = ',';
    *p++ = r.plant->signal_level(i) ? '1' : '0';
  }
  if (r.handshake_names != nullptr) {
    for (bool b : {r.handshake.active, r.handshake.skip, r.handshake.recorded, r.handshake.done}) {
      *p++ = ',';
      *p++ = b ? '1' : '0';
    }
  }
  if (probe_ != nullptr) {
    *p++ = ',';
    p = trace_number(p, probe_->deflection());
    *p++ = ',';
    *p++ = probe_->touching() ? '1' : '0';
  }
  if (work_) {
    for (int i = 0; i < n; ++i) {
      *p++ = ',';
      p = trace_number(p, r.work != nullptr ? (*r.work)[i] : 0.0);
    }
  }
  if (tip_axis_ >= 0) {
    *p++ = ',';
    p = trace_number(p, (*r.actual)[tip_axis_] - r.plant->probing().spindle_tool_length());
  }
  *p++ = '\n';
  const auto len = static_cast<std::uint64_t>(p - row_.data());
  if (bytes_ + len > max_bytes_) {
    // Whole rows up to the limit are kept; the run stops here.
    flush_buffer();
    fail_with(Error{AlarmId::kTraceLimit,
                    "the trace reached limits.max_trace_bytes (" + std::to_string(max_bytes_) +
                        " bytes) at " + std::to_string(r.time_s) + " s",
                    {},
                    -1});
    return;
  }
  bytes_ += len;
  buf_.append(row_.data(), p);
  if (buf_.size() >= kTraceBufferBytes) flush_buffer();
}

Result<void> CsvTrace::finish() {
  if (!opened_) return {};
  opened_ = false;
  flush_buffer();
  if (error_ && error_->id == AlarmId::kFileAccess) {
    out_.discard();
    return std::unexpected(*error_);
  }
  // Past the size limit the rows written so far are a whole trace: kept.
  auto c = out_.commit();
  if (!c) {
    Error e = c.error();
    e.detail = "trace: " + e.detail;
    if (!error_) error_ = e;
    return std::unexpected(std::move(e));
  }
  if (error_) return std::unexpected(*error_);
  return {};
}

}  // namespace skipnc::report
