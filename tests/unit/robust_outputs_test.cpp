// What skipnc writes stays what the user asked for (issue 21): text that is
// not UTF-8 still gives a valid JSON report; outputs that are devices, FIFOs
// or links are written where they are, never replaced by a file, and never
// through a link planted at a temporary name; a replaced report keeps its
// permissions; two outputs, or an output and an input, that are one file are
// refused before the run; an output that cannot be written is an alarm and a
// non-zero exit; [limits] values are range-checked, and the processor-time and
// trace-size limits end a run with their own alarms; a signal still leaves a
// whole report. Every test runs the skipnc binary as a user would.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>

#include "support/endless_programs.hpp"
#include "support/report_run.hpp"

namespace skipnc::test {
namespace {

namespace fs = std::filesystem;

// A short move with a few hundred servo periods: a trace of some rows.
constexpr const char* kShortMove = "G1 X10. F1000.\nM30\n";

// A machine file: the built-in mill3 with `limits` as its [limits] table.
fs::path machine_with_limits(const TempDir& dir, const std::string& limits) {
  return dir.write("machine.toml", "extends = \"mill3\"\n\n[limits]\n" + limits);
}

// Runs skipnc; standard error into `dir`/stderr.txt, returned with the exit.
struct Run {
  ChildExit exit;
  std::string out;
  std::string err;
};
Run run(const TempDir& dir, const std::vector<std::string>& args,
        const std::string& out_file = "") {
  const auto err = dir.path / "stderr.txt";
  const auto out = out_file.empty() ? (dir.path / "stdout.txt").string() : out_file;
  Child c(args, out, err.string());
  Run r;
  r.exit = c.wait(120.0);
  r.err = read_file(err);
  if (out_file.empty()) r.out = read_file(out);
  return r;
}

nlohmann::json parse(const fs::path& p) {
  return nlohmann::json::parse(read_file(p), nullptr, false);
}

// --- Text that is not UTF-8 -------------------------------------------------

TEST(RobustText, LatinOneCommentGivesAValidReport) {
  // "(MSG,CAFÉ)" saved as Latin-1: before, skipnc aborted (exit 134) and
  // wrote no report. The byte is replaced with U+FFFD.
  TempDir dir;
  const auto prog = dir.write("u.nc", "(MSG,CAF\xC9)\nM30\n");
  const auto r = run_with_report(dir, prog);
  ASSERT_TRUE(r.exit.exited) << "ended by signal " << r.exit.signal;
  EXPECT_EQ(r.exit.code, 0) << r.err;
  ASSERT_TRUE(r.report_ok) << read_file(dir.path / "report.json");
  EXPECT_EQ(r.status(), "completed");
  ASSERT_EQ(r.report["messages"].size(), 1U);
  EXPECT_NE(r.report["messages"][0].get<std::string>().find("CAF\xEF\xBF\xBD"), std::string::npos)
      << r.report["messages"].dump();
}

TEST(RobustText, LatinOneProgramNameGivesAValidReport) {
  TempDir dir;
  const auto prog = dir.write("caf\xE9.nc", "M30\n");
  const auto r = run_with_report(dir, prog);
  ASSERT_TRUE(r.exit.exited) << "ended by signal " << r.exit.signal;
  EXPECT_EQ(r.exit.code, 0) << r.err;
  ASSERT_TRUE(r.report_ok);
  EXPECT_NE(r.report.value("program", "").find("caf\xEF\xBF\xBD.nc"), std::string::npos)
      << r.report.value("program", "");
}

// --- Outputs that are not regular files ---------------------------------------

TEST(RobustOutputs, ReportToDevNullLeavesTheDevice) {
  TempDir dir;
  const auto prog = dir.write("m.nc", kShortMove);
  const auto r = run(dir, {"run", prog.string(), "--report", "/dev/null", "-q"});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 0) << r.err;
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(RobustOutputs, TraceToAFifoIsStreamedAndTheFifoStays) {
  TempDir dir;
  const auto prog = dir.write("m.nc", kShortMove);
  const auto fifo = dir.path / "trace.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  // The reader opens without waiting and reads until skipnc has ended and
  // the FIFO is empty.
  const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  ASSERT_GE(fd, 0) << std::strerror(errno);
  std::atomic<bool> ended{false};
  std::string text;
  std::thread reader([&] {
    for (;;) {
      char buf[4096];
      // Looked at before reading: a read after skipnc ended finds all it wrote.
      const bool was_ended = ended.load();
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n > 0) {
        text.append(buf, static_cast<std::size_t>(n));
        continue;
      }
      if (n < 0 && errno != EAGAIN && errno != EINTR) return;
      if (was_ended) return;  // skipnc is gone and nothing is left to read
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  Child c({"run", prog.string(), "--trace", fifo.string(), "-q"}, "/dev/null",
          (dir.path / "stderr.txt").string());
  const ChildExit exit = c.wait(120.0);
  ended.store(true);
  reader.join();
  ::close(fd);
  ASSERT_TRUE(exit.exited);
  EXPECT_EQ(exit.code, 0) << read_file(dir.path / "stderr.txt");
  EXPECT_TRUE(fs::is_fifo(fifo));
  ASSERT_FALSE(text.empty()) << read_file(dir.path / "stderr.txt");
  EXPECT_EQ(text.rfind("time_s,line,", 0), 0U) << text.substr(0, 80);
  EXPECT_EQ(text.back(), '\n');
  // No file was made beside it.
  for (const auto& e : fs::directory_iterator(dir.path)) {
    EXPECT_EQ(e.path().filename().string().find("trace.fifo.tmp"), std::string::npos);
  }
}

TEST(RobustOutputs, LinkAtTheOldTemporaryNameIsNotWrittenThrough) {
  // Before, the report went through "<report>.tmp": a link planted there
  // made skipnc overwrite the file it points at.
  TempDir dir;
  const auto prog = dir.write("m.nc", kShortMove);
  const auto victim = dir.write("victim.txt", "keep me\n");
  fs::create_symlink(victim, dir.path / "report.json.tmp");
  const auto r = run_with_report(dir, prog);
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 0) << r.err;
  EXPECT_TRUE(r.report_ok);
  EXPECT_EQ(read_file(victim), "keep me\n");
  EXPECT_TRUE(fs::is_symlink(dir.path / "report.json.tmp"));
}

TEST(RobustOutputs, ReplacedReportKeepsItsPermissions) {
  TempDir dir;
  const auto prog = dir.write("m.nc", kShortMove);
  const auto report = dir.write("report.json", "old\n");
  fs::permissions(report, fs::perms::owner_read | fs::perms::owner_write);
  const auto r = run(dir, {"run", prog.string(), "--report", report.string(), "-q"});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 0) << r.err;
  EXPECT_FALSE(parse(report).is_discarded());
  EXPECT_EQ(fs::status(report).permissions() & fs::perms::mask,
            fs::perms::owner_read | fs::perms::owner_write);
}

TEST(RobustOutputs, ReportThroughALinkReplacesTheFileAndKeepsTheLink) {
  TempDir dir;
  const auto prog = dir.write("m.nc", kShortMove);
  const auto real = dir.write("real.json", "old\n");
  const auto link = dir.path / "link.json";
  fs::create_symlink(real.filename(), link);
  const auto r = run(dir, {"run", prog.string(), "--report", link.string(), "-q"});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_FALSE(parse(real).is_discarded());
}

// --- Write errors --------------------------------------------------------------

TEST(RobustOutputs, TraceToAFullDeviceIsAnAlarm) {
  // Before, --trace /dev/full exited 0 and the report said "completed".
  TempDir dir;
  const auto prog = dir.write("m.nc", kShortMove);
  const auto r = run_with_report(dir, prog, {"--trace", "/dev/full"});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_NE(r.exit.code, 0);
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.status(), "alarm");
  EXPECT_EQ(r.alarm().value("code", ""), alarm_code(AlarmId::kFileAccess));
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

// `--trace - | head`: the reader goes away after three rows. The write that
// fails (EPIPE) is the alarm file_access and the run stops; the report is
// written whole (was: killed by SIGPIPE, exit 141, no report).
TEST(RobustOutputs, TraceToAPipeClosedEarlyIsAnAlarmWithAReport) {
  TempDir dir;
  const auto prog = dir.write("long.nc", "G1 X100. F1000.\nM30\n");  // 6 s: 6000 rows
  const auto report = dir.path / "r.json";
  const auto status = dir.path / "status.txt";
  const std::string cmd =
      "bash -c " + shell_quote(shell_quote(SKIPNC_BINARY) + " run " + shell_quote(prog.string()) +
                               " --trace - --report " + shell_quote(report.string()) +
                               " 2>/dev/null | head -n 3 >/dev/null; echo "
                               "${PIPESTATUS[0]} >" +
                               shell_quote(status.string()));
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(read_file(status), "1\n");
  const auto j = parse(report);
  ASSERT_FALSE(j.is_discarded()) << read_file(report);
  EXPECT_EQ(j.value("status", ""), "alarm");
  EXPECT_EQ(j["alarm"].value("code", ""), alarm_code(AlarmId::kFileAccess));
  EXPECT_NE(j["alarm"].value("message", "").find("trace"), std::string::npos);
  EXPECT_EQ(j["alarm"].value("line", 0), 1)
      << "the G01 that was running (was 2: the M30 read ahead)";
  // Stopped early: the 100 mm move did not end.
  EXPECT_LT(j["final"]["position"].value("X", 100.0), 99.0);
}

TEST(RobustOutputs, StandardOutputToAFullDeviceIsAnError) {
  TempDir dir;
  const auto prog = dir.write("m.nc", kShortMove);
  const auto canon = run(dir, {"canon", prog.string()}, "/dev/full");
  ASSERT_TRUE(canon.exit.exited);
  EXPECT_NE(canon.exit.code, 0) << canon.err;
  const auto summary = run(dir, {"run", prog.string()}, "/dev/full");
  ASSERT_TRUE(summary.exit.exited);
  EXPECT_NE(summary.exit.code, 0) << summary.err;
}

// --- Outputs that are one file ---------------------------------------------------

TEST(RobustOutputs, ReportAndTraceToOneFileAreRefusedBeforeTheRun) {
  TempDir dir;
  const auto prog = dir.write("m.nc", kShortMove);
  const auto same = dir.path / "out";
  const auto r =
      run(dir, {"run", prog.string(), "--report", same.string(), "--trace", same.string(), "-q"});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 2);
  EXPECT_NE(r.err.find("same file"), std::string::npos) << r.err;
  // No trace rows were written there.
  EXPECT_EQ(read_file(same).find("time_s,"), std::string::npos);
}

TEST(RobustOutputs, AnOutputOverTheProgramIsRefusedAndTheProgramKept) {
  // Before, --trace prog.nc overwrote the program with the trace.
  TempDir dir;
  const auto prog = dir.write("prog.nc", kShortMove);
  for (const char* option : {"--trace", "--report"}) {
    const auto r = run(dir, {"run", prog.string(), option, prog.string(), "-q"});
    ASSERT_TRUE(r.exit.exited) << option;
    EXPECT_EQ(r.exit.code, 2) << option;
    EXPECT_NE(r.err.find("same file"), std::string::npos) << option << ": " << r.err;
    EXPECT_EQ(read_file(prog), kShortMove) << option;
  }
}

// --- [limits] --------------------------------------------------------------------

TEST(LimitsConfig, ValueOutOfRangeIsRefusedWithItsPlace) {
  // Before, max_macro_levels = 1e12 was accepted and cast into an int.
  TempDir dir;
  const auto prog = dir.write("m.nc", kShortMove);
  const auto machine = machine_with_limits(dir, "max_macro_levels = 1e12\n");
  const auto r = run(dir, {"run", prog.string(), "-m", machine.string(), "-q"});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 2);
  EXPECT_NE(r.err.find("machine.toml:4:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("max_macro_levels"), std::string::npos) << r.err;
}

TEST(LimitsConfig, CountsMustBeWholeAndKeysKnown) {
  TempDir dir;
  const auto prog = dir.write("m.nc", kShortMove);
  for (const std::string limits : {"max_subprogram_levels = 4.5\n", "max_cpu_s = 0\n",
                                   "max_trace_bytes = -1\n", "max_memory = 5\n"}) {
    const auto machine = machine_with_limits(dir, limits);
    const auto r = run(dir, {"run", prog.string(), "-m", machine.string(), "-q"});
    ASSERT_TRUE(r.exit.exited) << limits;
    EXPECT_EQ(r.exit.code, 2) << limits;
    EXPECT_NE(r.err.find("machine.toml:4:"), std::string::npos) << limits << r.err;
  }
}

TEST(LimitsConfig, BadMachineFileReportHasTheConfigAlarmNumber) {
  // Before, the report of a machine file that did not load had alarm number
  // 0 and code "config"; cli.md promises 9090 / SN9090.
  TempDir dir;
  const auto prog = dir.write("m.nc", kShortMove);
  const auto machine = dir.write("bad.toml", "name = \n");
  const auto r = run_with_report(dir, prog, {"-m", machine.string()});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 2);
  ASSERT_TRUE(r.report_ok);
  EXPECT_EQ(r.alarm().value("number", 0), 9090);
  EXPECT_EQ(r.alarm().value("code", ""), "SN9090");
}

TEST(LimitsRun, ProcessorTimeLimitEndsAnEndlessLoopWithItsAlarm) {
  TempDir dir;
  const auto prog = dir.write("loop.nc", kEndlessStatements);
  const auto machine = machine_with_limits(dir, "max_cpu_s = 0.5\n");
  const auto r = run_with_report(dir, prog, {"-m", machine.string()}, 120.0);
  ASSERT_TRUE(r.exit.exited) << "ended by signal " << r.exit.signal;
  EXPECT_FALSE(r.exit.timed_out);
  EXPECT_EQ(r.exit.code, 1);
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.status(), "alarm");
  EXPECT_EQ(r.alarm().value("code", ""), alarm_code(AlarmId::kCpuLimit));
}

TEST(LimitsRun, TraceSizeLimitKeepsWholeRowsAndEndsTheRun) {
  TempDir dir;
  const auto prog = dir.write("loop.nc", kEndlessMotion);
  const auto machine = machine_with_limits(dir, "max_trace_bytes = 20000\n");
  const auto trace = dir.path / "trace.csv";
  const auto r =
      run_with_report(dir, prog, {"-m", machine.string(), "--trace", trace.string()}, 120.0);
  ASSERT_TRUE(r.exit.exited) << "ended by signal " << r.exit.signal;
  EXPECT_FALSE(r.exit.timed_out);
  EXPECT_EQ(r.exit.code, 1);
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.alarm().value("code", ""), alarm_code(AlarmId::kTraceLimit));
  const std::string text = read_file(trace);
  ASSERT_FALSE(text.empty());
  EXPECT_LE(text.size(), 20000U);
  EXPECT_EQ(text.back(), '\n');
}

// --- Signals ---------------------------------------------------------------------

TEST(RobustSignal, SigtermAfterProgressLinesLeavesAReportNamingTheSignal) {
  // --progress writes lines to standard error without a terminal; the test
  // waits for the first one, so the run is surely under way, then stops it.
  TempDir dir;
  const auto prog = dir.write("long.nc", kEndlessMotion);
  const auto report = dir.path / "report.json";
  const auto err = dir.path / "stderr.txt";
  Child c({"run", prog.string(), "--report", report.string(), "--trace", "/dev/null", "--progress",
           "-q"},
          "/dev/null", err.string());
  while (read_file(err).find("simulated") == std::string::npos && c.elapsed_s() < 120.0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_NE(read_file(err).find("simulated"), std::string::npos) << "no progress line";
  c.signal(SIGTERM);
  const ChildExit exit = c.wait(120.0);
  ASSERT_TRUE(exit.exited) << "ended by signal " << exit.signal;
  EXPECT_FALSE(exit.timed_out);
  EXPECT_EQ(exit.code, 1);
  const auto j = parse(report);
  ASSERT_FALSE(j.is_discarded()) << read_file(report);
  EXPECT_EQ(j.value("status", ""), "interrupted");
  EXPECT_EQ(j["alarm"].value("code", ""), alarm_code(AlarmId::kInterrupted));
  EXPECT_NE(j["alarm"].value("message", "").find("SIGTERM"), std::string::npos)
      << j["alarm"].dump();
}

}  // namespace
}  // namespace skipnc::test
