// The JSON report (format "skipnc-report/1", spec/cli.md) and the per-cycle
// CSV trace. Both are written to a temporary file and renamed into place, so
// a reader never sees half a file.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "machine/simulator.hpp"

namespace skipnc::report {

struct ReportInput {
  std::string program;  // as given on the command line
  std::string dialect;
  const config::MachineConfig* machine = nullptr;  // null when the run could not start
  const config::Dialect* dialect_table = nullptr;  // for alarm numbers
  machine::RunResult result;
  std::optional<Error> start_error;  // the run could not start
  std::vector<std::pair<std::string, std::optional<double>>> variables;
};

std::string to_json(const ReportInput& in);

// Writes `text` to `path` atomically ("-": standard output).
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
std::string where(const std::vector<interp::CallContext>& contexts, std::uint32_t context,
                  std::uint32_t line, int n = -1);

// A report number without float noise: rounded to 1e-9 (a nanometre, a
// nanosecond), never -0.
double clean(double v) noexcept;

// CSV trace: one row per servo period. Rows go to "<path>.tmp" and the file
// is renamed when the run ends (complete up to the last period run).
class CsvTrace final : public machine::TraceSink {
 public:
  CsvTrace(std::string path, const config::MachineConfig& m, const machine::Plant* plant_hint);
  ~CsvTrace() override;
  [[nodiscard]] Result<void> open();
  void row(const machine::TraceRow& r) override;
  [[nodiscard]] Result<void> finish();

 private:
  void header(const machine::TraceRow& r);
  std::string path_;
  std::string tmp_;
  const config::MachineConfig& m_;
  std::FILE* f_ = nullptr;
  bool header_done_ = false;
  bool failed_ = false;
  std::string buf_;
  std::vector<char> row_;  // one row's text, sized for the longest row by header()
};

}  // namespace skipnc::report
