// The JSON report (format "skipnc-report/1", spec/cli.md) and the per-cycle
// CSV trace. Both are written to a temporary file and renamed into place, so
// a reader never sees half a file.
#pragma once

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "core/file.hpp"
#include "sim/simulator.hpp"

namespace skipnc::report {

// One --expect check's verdict (the report's "expectations").
struct CheckResult {
  std::string text;  // the --expect text
  std::string name;  // "#140", "status", "alarm"
  bool pass = false;
  // What the run gave and what was expected: a number (variables, alarm
  // numbers) or a word (status, alarm code, "vacant"); nullopt/empty when
  // there was none.
  std::optional<double> value;
  std::string value_text;
  std::optional<double> expected;
  std::string expected_text;
  std::optional<double> tolerance;  // variables with a value
  std::string message;              // why it failed, empty when it passed
};

struct ReportInput {
  std::string program;  // as given on the command line
  std::string dialect;
  const config::MachineConfig* machine = nullptr;  // null when the run could not start
  const config::Dialect* dialect_table = nullptr;  // for alarm numbers
  sim::RunResult result;
  std::optional<Error> start_error;  // the run could not start
  std::vector<std::pair<std::string, std::optional<double>>> variables;
  std::vector<CheckResult> expectations;  // --expect, in the order given
};

std::string to_json(const ReportInput& in);

// How a run ended, as the report's "status", a sweep row, --expect status=
// and the plot name it: "completed", "alarm" or "interrupted".
const char* status_name(sim::RunStatus s) noexcept;

// Writes `text` to `path` atomically ("-": standard output; a device or a
// FIFO in place): write_file_atomic (core/file.hpp).
[[nodiscard]] Result<void> write_atomic(const std::string& path, const std::string& text);

// The alarm as the user sees it: number, code, message.
struct AlarmView {
  int number = 0;
  std::string code;
  std::string message;
};
AlarmView view_alarm(const Error& e, const config::Dialect* d);

// Where a block is, for people: "O9023.nc:38 (O9023 N30) called from
// bore.nc:9 (G65 P9023)". `n` < 0: the block has no N number.
std::string where(const std::vector<record::CallContext>& contexts, std::uint32_t context,
                  std::uint32_t line, int n = -1);

// A report number without float noise: rounded to 1e-9 (a nanometre, a
// nanosecond), never -0.
double clean(double v) noexcept;

// The trace's columns (--trace), decided by its first row: the names in the
// CSV header's order, and each row's numbers in the same order. The CSV
// trace and the Python module's trace both take them from here.
struct TraceColumns {
  std::vector<std::string> names;  // "time_s", "line", "file", "feed_mm_min", "X_cmd", ...
  int axes = 0;
  std::size_t signals = 0;                     // one 0/1 column per scene signal
  bool handshake = false;                      // the skip handshake's four 0/1 columns
  const machine::TouchProbe* probe = nullptr;  // probe_deflection, probe_contact
  bool work = false;                           // <axis>_work columns
  int tip_axis = -1;                           // the <Z>_tip column's axis, -1: none
  static constexpr std::size_t kFile = 2;      // the one column that is text
  static TraceColumns of(const config::MachineConfig& m, const sim::TraceRow& first);
  // The row's value of every column but `file`, in order (names.size() - 1).
  void numbers(const sim::TraceRow& r, std::vector<double>& out) const;
};

// CSV trace: one row per servo period, written as the run goes (an
// OutputFile: a regular file through a unique temporary renamed when the run
// ends, complete up to the last period run; a device, a FIFO or standard
// output in place). A write error (a full disk, a closed pipe) or passing
// `limits.max_trace_bytes` ends the trace: no more rows are written, the
// stop callback is called once (the run should stop), and finish() returns
// the error (kFileAccess, or kTraceLimit with the rows up to the limit kept).
class CsvTrace final : public sim::TraceSink {
 public:
  CsvTrace(std::string path, const config::MachineConfig& m, const machine::Plant* plant_hint);
  ~CsvTrace() override;
  [[nodiscard]] Result<void> open();
  void row(const sim::TraceRow& r) override;
  void last(const sim::TraceRow& r) override;
  std::int64_t stride() const noexcept override { return every_; }
  [[nodiscard]] Result<void> finish();
  void on_stop(std::function<void()> stop) { stop_ = std::move(stop); }
  // --trace-every N: one row for every N servo periods (the periods whose
  // tick is a multiple of N) and the run's last period, 1: every period.
  void every(std::int64_t n) noexcept { every_ = n < 1 ? 1 : n; }
  // The error that ended the trace early, if any.
  const std::optional<Error>& error() const noexcept { return error_; }

 private:
  void header(const sim::TraceRow& r);
  void write_row(const sim::TraceRow& r);
  void flush_buffer();
  void fail_with(Error e);
  std::string path_;
  const config::MachineConfig& m_;
  OutputFile out_;
  bool opened_ = false;
  std::uint64_t max_bytes_ = 0;
  std::uint64_t bytes_ = 0;  // rows accepted (written or buffered)
  std::int64_t every_ = 1;
  std::int64_t last_tick_ = -1;                 // the tick of the last row written
  const machine::TouchProbe* probe_ = nullptr;  // the scene's probe (trace columns), if any
  bool work_ = false;                           // <axis>_work columns
  int tip_axis_ = -1;                           // the <Z>_tip column's axis, -1: none
  bool header_done_ = false;
  std::optional<Error> error_;
  std::function<void()> stop_;
  std::string buf_;
  std::vector<char> row_;  // one row's text, sized for the longest row by header()
};

}  // namespace skipnc::report
