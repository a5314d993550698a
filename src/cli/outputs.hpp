// What a command writes besides its summary: the report, and how a run that
// could not start, failed inside skipnc, or was stopped early is reported.
// Every path here ends with a whole report when one was asked for.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/commands.hpp"
#include "cli/guard.hpp"
#include "interpreter/interpreter.hpp"
#include "report/report.hpp"
#include "run/scenario.hpp"
#include "run/session.hpp"
#include "sim/simulator.hpp"

namespace skipnc::cli {

// The dialect whose numbers a report uses: the session's; before the session
// has one (a bad machine file), the -d dialect, else fanuc. Every dialect
// numbers skipnc's own alarms alike (config: 9090, SN9090; base.toml).
const config::Dialect* report_dialect(const RunArgs& a, const run::Session* s);

// The program of a run as the run library takes it: its file, or (program
// "-") the text read from standard input, named "<stdin>" in errors and the
// report; the include folders, --strict and --allow.
run::RunRequest program_request(const RunArgs& a);
// Reads standard input whole into a.program_text when the program is "-";
// an error names standard input.
[[nodiscard]] Result<void> read_stdin_program(RunArgs& a);

// Writes the report (`a.report`; nothing when none was asked for). Errors go
// to standard error and make the returned value false.
bool write_report(const RunArgs& a, const std::string& json);
// True once a report was written whole by this process.
bool report_written() noexcept;

// The run could not start: the message on standard error, the report (when
// asked for and not itself the cause), exit status 2.
int start_failure(const RunArgs& a, const Error& e, const run::Session* s);

// The last resort of main(): an exception reached the top. The report (when
// asked for and not written yet) has the internal-error alarm (SN9000); exit 1.
// `a` must outlive the exception (main()'s frame, not the command's). The
// memory reserve_emergency_memory() set aside is given back first.
int internal_failure(const RunArgs* a, std::string_view what) noexcept;
void reserve_emergency_memory() noexcept;

// One collision check for every command: no output may be a file the run
// reads, nor another output. `what` names the file in the message
// ("--report", "the program", "--csv", ...).
struct NamedFile {
  std::string what;
  std::string name;
};
// kUsage naming both files when an output is an input or another output
// (*output_is_input set in the first case). Nothing is written.
[[nodiscard]] Result<void> refuse_collisions(const std::vector<NamedFile>& outputs,
                                             const std::vector<NamedFile>& inputs,
                                             bool* output_is_input = nullptr);
// The files a session read: the machine file and its `extends` chain, the
// scene file and its STL meshes.
std::vector<NamedFile> session_inputs(const run::Session& s);
// The files directly in -I folders (a subprogram may be any of them).
std::vector<NamedFile> include_inputs(const std::vector<std::string>& folders);

// Refuses, before anything runs, two outputs (report, trace, plots, DPRNT
// file, persistent variables) that are one file, or an output that is one of
// the inputs (program, machine file, scene file): kUsage naming both. A
// refused report is not written at all when it is an input.
[[nodiscard]] Result<void> check_outputs(const RunArgs& a, const run::Session& s);

// A run that the simulator ended as interrupted because skipnc asked it to
// (run_stop()): the alarm that says why. The processor-time limit is
// cpu_limit, an output that failed is its own error (file_access,
// trace_limit), a signal stays `interrupted` and names the signal.
void explain_stop(sim::RunResult& r, const report::CsvTrace* trace, const config::MachineConfig& m);

// Flushes standard output; an error when anything written to it was lost
// (a full disk, a closed pipe).
[[nodiscard]] Result<void> finish_stdout();

}  // namespace skipnc::cli
