// Bad input on the surfaces added after plain `run` (issue 31, and the sweep
// bullet of issue 30): the last-resort report, sweeps, every file a run
// reads, the collision check, the LinuxCNC parameter file, locks, limits.
// Each test runs the skipnc binary as a user would and checks what the user
// sees: the exit status, the files left, the message.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/child_process.hpp"
#include "support/report_run.hpp"
#include "support/run_cli.hpp"
#include "support/sanitizer.hpp"

namespace skipnc::test {
namespace {

namespace fs = std::filesystem;

// mill3 in the linuxcnc dialect with its parameter file m.var beside it.
fs::path linuxcnc_machine_with_parameter_file(const TempDir& dir) {
  return dir.write("m.toml",
                   "extends = \"mill3\"\ndialect = \"linuxcnc\"\n"
                   "persistent_variables = \"m.var\"\n");
}

int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n' ? 1 : 0;
  return n;
}

// ---- 1. The last resort -------------------------------------------------

// An exception that leaves the command (out of memory, a bug) still writes
// the report the user asked for, whole, with the internal alarm; the
// handler once read the arguments of the frame the exception unwound.
TEST(SurfacesLastResort, AnyExceptionWritesTheInternalReportWhole) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G0 X1.\nM30\n");
  for (const char* kind : {"bad_alloc", "runtime_error", "int"}) {
    ::setenv("SKIPNC_TEST_THROW", kind, 1);
    const auto r = run_with_report(dir, prog);
    ::unsetenv("SKIPNC_TEST_THROW");
    ASSERT_TRUE(r.exit.exited) << kind << ": ended by signal " << r.exit.signal;
    EXPECT_EQ(r.exit.code, 1) << kind;
    ASSERT_TRUE(r.report_ok) << kind << ": " << r.err;
    EXPECT_EQ(r.report.value("status", ""), "alarm") << kind;
    EXPECT_EQ(r.alarm().value("code", ""), alarm_code(AlarmId::kInternal)) << kind;
    EXPECT_NE(r.err.find("internal error"), std::string::npos) << kind;
  }
}

// ---- 2. Sweeps ------------------------------------------------------------

struct Sweep {
  TempDir dir;
  fs::path spec;
  fs::path csv() const { return dir.path / "s.sweep.csv"; }
  fs::path json() const { return dir.path / "s.sweep.json"; }

  Sweep(const std::string& program, const std::string& spec_tail) {
    if (!program.empty()) dir.write("p.nc", program);
    spec = dir.write("s.sweep.toml", "program = \"p.nc\"\n" + spec_tail);
  }
  CliResult run(std::vector<std::string> extra = {}) const {
    std::vector<std::string> args{"sweep", spec.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli(args, (dir.path / "err.txt").string());
  }
  std::string err() const { return read_file(dir.path / "err.txt"); }
  nlohmann::json table() const { return nlohmann::json::parse(read_file(json()), nullptr, false); }
};

TEST(SurfacesSweep, MissingProgramExitsTwoAndWritesNothing) {
  Sweep s("", "scenarios = 3\n");
  const auto r = s.run();
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(s.err().find("p.nc"), std::string::npos) << s.err();
  EXPECT_FALSE(fs::exists(s.csv()));
  EXPECT_FALSE(fs::exists(s.json()));
}

// Every scenario could not start (a parameter bit drawn as 5): nothing ran,
// exit 2, and the rows count as errors, never as passed.
TEST(SurfacesSweep, EveryRowAnErrorExitsTwoAndCountsErrorsApart) {
  Sweep s("G0 X1.\nM30\n",
          "scenarios = 4\n[[vary]]\nwhat = \"param.6200#7\"\nnormal = [5.0, 0.0]\n");
  const auto r = s.run({"-q"});
  EXPECT_EQ(r.exit_code, 2) << s.err();
  const auto j = s.table();
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["summary"]["passed"], 0);
  EXPECT_EQ(j["summary"]["errors"], 4);
  EXPECT_EQ(j["summary"]["failed"], 0);
  for (const auto& row : j["rows"]) {
    EXPECT_EQ(row["status"], "error");
    EXPECT_FALSE(row["pass"].get<bool>());
  }
}

// A listed value out of range is refused when the spec is read, as `-p`
// refuses it.
TEST(SurfacesSweep, OutOfRangeParameterValueIsRefusedAtLoad) {
  Sweep s("G0 X1.\nM30\n", "[[vary]]\nwhat = \"param.6200#7\"\nvalues = [0, 5]\n");
  const auto r = s.run({"-q"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(s.err().find("s.sweep.toml:"), std::string::npos) << s.err();
  EXPECT_FALSE(fs::exists(s.csv()));
}

// A run that alarms is not a pass without a check that expects it; with
// alarm=N it is. The alarm text is valid UTF-8 in the JSON whatever bytes
// the message held.
TEST(SurfacesSweep, AlarmsFailUnlessExpectedAndTextsAreUtf8) {
  const std::string prog = "#3000=1(BAD \xe9 BYTE)\nM30\n";
  Sweep plain(prog, "scenarios = 2\n");
  EXPECT_EQ(plain.run({"-q"}).exit_code, 1);
  const auto j = plain.table();
  ASSERT_FALSE(j.is_discarded()) << read_file(plain.json());
  EXPECT_EQ(j["summary"]["failed"], 2);
  EXPECT_EQ(j["rows"][0]["status"], "alarm");
  EXPECT_NE(j["rows"][0]["alarm_text"].get<std::string>().find("\xef\xbf\xbd"), std::string::npos);

  Sweep expected(prog, "scenarios = 2\nexpect = [\"alarm=3001\"]\n");
  EXPECT_EQ(expected.run({"-q"}).exit_code, 0) << read_file(expected.csv());
}

// The spec's expect is read by run --expect's parser: its forms (vacant)
// work, and its refusals are the same.
TEST(SurfacesSweep, ExpectUsesTheRunParser) {
  Sweep ok("#101=1\nM30\n", "scenarios = 1\nexpect = [\"#102=vacant\", \"#101=1\"]\n");
  EXPECT_EQ(ok.run({"-q"}).exit_code, 0) << ok.err();
  Sweep bad("M30\n", "expect = [\"status=finished\"]\n");
  EXPECT_EQ(bad.run({"-q"}).exit_code, 2);
  EXPECT_NE(bad.err().find("unknown status 'finished'"), std::string::npos) << bad.err();
}

// No table over an input: the spec, the program, each other. Nothing runs,
// every file stays as it was.
TEST(SurfacesSweep, TablesNeverReplaceAnInput) {
  Sweep s("G0 X1.\nM30\n", "scenarios = 2\n");
  const std::string program = read_file(s.dir.path / "p.nc");
  const std::string spec = read_file(s.spec);
  for (const auto& extra : std::vector<std::vector<std::string>>{
           {"--csv", (s.dir.path / "p.nc").string()},
           {"--json", s.spec.string()},
           {"--csv", (s.dir.path / "t").string(), "--json", (s.dir.path / "t").string()}}) {
    EXPECT_EQ(s.run(extra).exit_code, 2) << extra[1];
    EXPECT_NE(s.err().find("same file"), std::string::npos) << s.err();
  }
  EXPECT_EQ(read_file(s.dir.path / "p.nc"), program);
  EXPECT_EQ(read_file(s.spec), spec);
  EXPECT_FALSE(fs::exists(s.dir.path / "t"));
}

// The tables go beside the spec by default, not into the current folder.
TEST(SurfacesSweep, DefaultTablesGoBesideTheSpec) {
  Sweep s("G0 X1.\nM30\n", "scenarios = 2\n");
  ASSERT_EQ(s.run({"-q"}).exit_code, 0) << s.err();
  EXPECT_EQ(count_lines(read_file(s.csv())), 3);
  EXPECT_FALSE(fs::exists(fs::current_path() / "s.sweep.csv"));
}

// A long sweep stopped by `sig` once some rows are done: exit 1, and the
// JSON table (whole: the .partial file renamed into place).
nlohmann::json stopped_sweep(const Sweep& s, int sig) {
  Child c({"sweep", s.spec.string(), "-q"}, "/dev/null", (s.dir.path / "err.txt").string());
  // Some rows finished: the .partial file has more than its header.
  const fs::path partial = s.csv().string() + ".partial";
  for (int i = 0; i < 400 && count_lines(read_file(partial)) < 3; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  c.signal(sig);
  const auto e = c.wait(60.0);
  EXPECT_TRUE(e.exited) << "ended by signal " << e.signal;
  EXPECT_EQ(e.code, 1);
  EXPECT_FALSE(fs::exists(partial));
  return s.table();
}

// SIGTERM stops taking scenarios: the table is whole, with every finished
// row and the rest not_run; exit 1.
TEST(SurfacesSweep, SigtermKeepsFinishedRowsAndMarksTheRestNotRun) {
  Sweep s("G04 X0.3\nM30\n", "scenarios = 100000\nworkers = 1\n");
  const auto j = stopped_sweep(s, SIGTERM);
  ASSERT_FALSE(j.is_discarded());
  const auto& sum = j["summary"];
  EXPECT_GT(sum["passed"].get<int>(), 0);
  EXPECT_GT(sum["not_run"].get<int>(), 0);
  EXPECT_EQ(sum["passed"].get<int>() + sum["not_run"].get<int>() +
                sum["statuses"].value("interrupted", 0),
            100000);
  EXPECT_EQ(count_lines(read_file(s.csv())), 100001);
}

// Ctrl-C (SIGINT) stops taking scenarios as SIGTERM does: the scenarios
// not taken are not_run, never counted as failed; the table is whole.
TEST(SurfacesSweep, CtrlCLeavesUnrunScenariosNotRunNotFailed) {
  Sweep s("G04 X0.3\nM30\n", "scenarios = 100000\nworkers = 1\n");
  const auto j = stopped_sweep(s, SIGINT);
  ASSERT_FALSE(j.is_discarded());
  const auto& sum = j["summary"];
  EXPECT_GT(sum["passed"].get<int>(), 0);
  EXPECT_GT(sum["not_run"].get<int>(), 0);
  EXPECT_EQ(sum["failed"].get<int>(), sum["statuses"].value("interrupted", 0));
  EXPECT_EQ(sum["errors"].get<int>(), 0);
  int not_run = 0;
  for (const auto& row : j["rows"]) {
    if (row["status"] != "not_run") continue;
    ++not_run;
    EXPECT_FALSE(row["pass"].get<bool>());
  }
  EXPECT_EQ(not_run, sum["not_run"].get<int>());
}

// alarm= by code or key holds in a sweep as in `skipnc run` (the rows keep
// the alarm's code and key, not only its number).
TEST(SurfacesSweep, AlarmNamesInExpectMatchAsInRun) {
  const std::string prog = "#3000=1(BAD)\nM30\n";
  for (const char* name : {"alarm=MC0001", "alarm=user_alarm", "alarm=3001"}) {
    Sweep s(prog, std::string("scenarios = 2\nexpect = [\"") + name + "\"]\n");
    EXPECT_EQ(s.run({"-q"}).exit_code, 0) << name << ": " << read_file(s.csv());
  }
  Sweep other(prog, "scenarios = 1\nexpect = [\"alarm=probe_crash\"]\n");
  EXPECT_EQ(other.run({"-q"}).exit_code, 1);
  Sweep typo(prog, "scenarios = 1\nexpect = [\"alarm=probe_crsh\"]\n");
  EXPECT_EQ(typo.run({"-q"}).exit_code, 2);
  EXPECT_NE(typo.err().find("s.sweep.toml:"), std::string::npos) << typo.err();
  EXPECT_NE(typo.err().find("probe_crsh"), std::string::npos) << typo.err();
}

// --junit is an output like the tables: never over an input or a table.
TEST(SurfacesSweep, JunitFileNeverReplacesAnInput) {
  Sweep s("G0 X1.\nM30\n", "scenarios = 2\n");
  const std::string program = read_file(s.dir.path / "p.nc");
  for (const auto& extra : std::vector<std::vector<std::string>>{
           {"--junit", (s.dir.path / "p.nc").string()}, {"--junit", s.csv().string()}}) {
    EXPECT_EQ(s.run(extra).exit_code, 2) << extra[1];
    EXPECT_NE(s.err().find("same file"), std::string::npos) << s.err();
  }
  EXPECT_EQ(read_file(s.dir.path / "p.nc"), program);
  EXPECT_FALSE(fs::exists(s.csv()));
}

// SIGTERM at any moment of a sweep: the table is whole and readable, each
// finished row in it, the rest not_run, whatever the instant. Two workers.
// The first milliseconds too (0 to 50 ms: before main(), while the spec
// loads, before the first scenario): skipnc is started with SIGINT and
// SIGTERM blocked, as a caller does that must be able to stop it from its
// first instant, and unblocks them once its handlers are set. Before, a
// SIGTERM in those milliseconds was lost (the sweep ran to its end) or, before
// main(), ended skipnc without a table.
// The sweep is long enough that the signal comes before its end: 200,000
// scenarios (about 14,000 a second in a Release build), 20,000 under
// AddressSanitizer (about 20 times slower), where most of the test's time was
// spent writing and reading the 200,000 rows of the table.
constexpr int kSigtermScenarios = SKIPNC_TEST_ASAN ? 20000 : 200000;

void sigterm_leaves_a_readable_table(int wait_ms, bool blocked_at_start) {
  Sweep s("G91 G1 X0.1 F600\nG04 X0.3\nM30\n",
          "scenarios = " + std::to_string(kSigtermScenarios) + "\nworkers = 2\n");
  Child c({"sweep", s.spec.string(), "-q"}, "/dev/null", (s.dir.path / "err.txt").string(),
          blocked_at_start);
  std::this_thread::sleep_for(std::chrono::milliseconds(wait_ms));
  c.signal(SIGTERM);
  const auto e = c.wait(120.0);
  ASSERT_TRUE(e.exited) << wait_ms << " ms: ended by signal " << e.signal;
  const auto j = s.table();
  ASSERT_FALSE(j.is_discarded()) << wait_ms << " ms";
  const auto& sum = j["summary"];
  const int done = sum["passed"].get<int>() + sum["failed"].get<int>();
  EXPECT_EQ(done + sum["not_run"].get<int>() + sum["statuses"].value("interrupted", 0),
            kSigtermScenarios)
      << wait_ms << " ms";
  EXPECT_GT(sum["not_run"].get<int>(), 0) << wait_ms << " ms: the signal was not heard";
  EXPECT_EQ(count_lines(read_file(s.csv())), kSigtermScenarios + 1) << wait_ms << " ms";
  int finished = 0;
  for (const auto& row : j["rows"]) finished += row.value("status", "") == "completed" ? 1 : 0;
  EXPECT_EQ(finished, done) << wait_ms << " ms";
  EXPECT_EQ(e.code, 1) << wait_ms << " ms";
}

TEST(SurfacesSweep, SigtermAtAnyMomentLeavesAReadableTable) {
  for (const int ms : {0, 2, 5, 10, 25, 50}) sigterm_leaves_a_readable_table(ms, true);
  std::mt19937 rng(31);
  std::uniform_int_distribution<int> ms(50, 1500);
  for (int k = 0; k < 5; ++k) sigterm_leaves_a_readable_table(ms(rng), false);
}

// ---- 3. Every file the run reads is checked --------------------------------

TEST(SurfacesInputs, DevicesAndFifosAreRefusedByName) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G0 X1.\nM30\n");
  const auto fifo = dir.path / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto extends = dir.write("m.toml", "extends = \"/dev/zero\"\n");
  const auto stl_scene = dir.write("s.toml", "[[mesh]]\nfile = \"fifo\"\n");
  const auto pv =
      dir.write("pv.toml", "extends = \"mill3\"\npersistent_variables = \"/dev/null\"\n");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"-m", "/dev/zero"}, "/dev/zero"},   {{"-m", fifo.string()}, "fifo"},
      {{"-s", fifo.string()}, "fifo"},      {{"-m", extends.string()}, "/dev/zero"},
      {{"-s", stl_scene.string()}, "fifo"}, {{"-m", pv.string()}, "/dev/null"},
  };
  for (const auto& [opts, name] : cases) {
    std::vector<std::string> args{"run", prog.string(), "-q"};
    args.insert(args.end(), opts.begin(), opts.end());
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = run_cli(args, (dir.path / "err.txt").string());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::string err = read_file(dir.path / "err.txt");
    EXPECT_EQ(r.exit_code, 2) << opts[1] << ": " << err;
    EXPECT_NE(err.find(name), std::string::npos) << err;
    EXPECT_NE(err.find("not a regular file"), std::string::npos) << err;
    EXPECT_LT(s, 10.0) << opts[1];
  }
  EXPECT_FALSE(fs::exists("/dev/null.lock"));
  Sweep sw("G0 X1.\nM30\n", "");
  const auto r = run_cli({"sweep", "/dev/zero", "-q"}, (sw.dir.path / "err.txt").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(sw.err().find("not a regular file"), std::string::npos) << sw.err();
}

// ---- 4. One collision check for every command and mode ---------------------

TEST(SurfacesCollisions, RepeatNeverReplacesTheProgram) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G0 X1.\nM30\n");
  const auto r = run_cli({"run", prog.string(), "--repeat", "3", "--report", prog.string(), "-q"},
                         (dir.path / "err.txt").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_file(prog), "G0 X1.\nM30\n");
  EXPECT_NE(read_file(dir.path / "err.txt").find("same file"), std::string::npos);
}

// A usage error found before the outputs are checked (a bad --var) does not
// write its report over the persistent file, nor over the scene.
TEST(SurfacesCollisions, UsageErrorReportNeverReplacesAnInput) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G0 X1.\nM30\n");
  const auto vars = dir.write("kept.vars", "#500 = 1\n");
  const auto m = dir.write("m.toml", "extends = \"mill3\"\npersistent_variables = \"kept.vars\"\n");
  const auto r = run_cli(
      {"run", prog.string(), "-m", m.string(), "--var", "#x", "--report", vars.string(), "-q"},
      (dir.path / "err.txt").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_file(vars), "#500 = 1\n");
}

// ---- 5. The LinuxCNC parameter file -----------------------------------------

TEST(SurfacesNgcParams, HugeValuesAreWrittenWholeAndReadBack) {
  TempDir dir;
  const auto m = linuxcnc_machine_with_parameter_file(dir);
  // #5000 is kept because the file lists it (an offset, #5221, is
  // range-checked on assignment instead: SurfacesOffsets).
  dir.write("m.var", "5000\t0\n");
  const auto prog = dir.write("p.ngc", "#5000 = [10 ** 60]\nM2\n");
  auto r = run_cli({"run", prog.string(), "-m", m.string(), "-q"}, (dir.path / "e1").string());
  EXPECT_EQ(r.exit_code, 0) << read_file(dir.path / "e1");
  const std::string text = read_file(dir.path / "m.var");
  // Written whole, as LinuxCNC writes it ("%f": every digit of the double).
  const auto at = text.find("5000\t");
  ASSERT_NE(at, std::string::npos) << text;
  EXPECT_DOUBLE_EQ(std::stod(text.substr(at + 5, text.find('\n', at + 1) - at - 5)), 1e60) << text;
  // The next run starts from it.
  const auto prog2 = dir.write("q.ngc", "#1 = #5000\nM2\n");
  r = run_cli({"run", prog2.string(), "-m", m.string(), "-q"}, (dir.path / "e2").string());
  EXPECT_EQ(r.exit_code, 0) << read_file(dir.path / "e2");
}

TEST(SurfacesNgcParams, DamagedFilesAreRefusedWithTheirLine) {
  TempDir dir;
  const auto m = linuxcnc_machine_with_parameter_file(dir);
  const auto prog = dir.write("p.ngc", "M2\n");
  for (const std::string bad :
       {"5221 1\n5221 2\n", "5221 0x10\n", "4294972517 1\n", "-5221 1\n", "5221 1e999\n"}) {
    dir.write("m.var", bad);
    const auto r =
        run_cli({"run", prog.string(), "-m", m.string(), "-q"}, (dir.path / "err.txt").string());
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(read_file(dir.path / "err.txt").find("m.var:"), std::string::npos)
        << bad << read_file(dir.path / "err.txt");
  }
}

// The persistent file's path is relative to the machine file, not to the
// folder the command runs in.
TEST(SurfacesNgcParams, PersistentPathResolvesAgainstTheMachineFile) {
  TempDir dir;
  fs::create_directory(dir.path / "cfg");
  const auto m =
      dir.write("cfg/m.toml", "extends = \"mill3\"\npersistent_variables = \"k.vars\"\n");
  const auto prog = dir.write("p.nc", "#500 = 7\nM30\n");
  const auto r = run_cli({"run", prog.string(), "-m", m.string(), "-q"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(read_file(dir.path / "cfg" / "k.vars").find("#500 = 7"), std::string::npos);
  EXPECT_FALSE(fs::exists(fs::current_path() / "k.vars"));
}

// ---- 6. Locks ---------------------------------------------------------------

// Eight runs at once in a shared folder (mode 1777), each adding 1 to #500:
// no update is lost. As root the runs are another user's (65534), and the
// lock file is root's, read-only to them: the lock is held through a
// descriptor open for reading.
TEST(SurfacesLocks, ParallelRunsAsAnotherUserLoseNoUpdate) {
  TempDir dir;
  ::chmod(dir.path.c_str(), 01777);
  const auto m = dir.write("m.toml", "extends = \"mill3\"\npersistent_variables = \"k.vars\"\n");
  const auto prog = dir.write("p.nc", "IF[#500NE#0]GOTO1\n#500=0\nN1 #500=#500+1\nM30\n");
  const auto lock = dir.write("k.vars.lock", "");
  ::chmod(lock.c_str(), 0444);
  for (const auto& f : {m, prog}) ::chmod(f.c_str(), 0644);
  const std::string as_other =
      ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
  constexpr int kRuns = 8;
  std::string cmd;
  for (int i = 0; i < kRuns; ++i) {
    cmd += "(" + as_other + shell_quote(SKIPNC_BINARY) + " run " + shell_quote(prog.string()) +
           " -m " + shell_quote(m.string()) + " -q 2>/dev/null; echo $? >" +
           shell_quote((dir.path / ("rc" + std::to_string(i))).string()) + ") & ";
  }
  cmd += "wait";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  for (int i = 0; i < kRuns; ++i)
    EXPECT_EQ(read_file(dir.path / ("rc" + std::to_string(i))), "0\n");
  EXPECT_NE(read_file(dir.path / "k.vars").find("#500 = " + std::to_string(kRuns)),
            std::string::npos)
      << read_file(dir.path / "k.vars");
}

// ---- 7. Limits --------------------------------------------------------------

// A trace larger than `ulimit -f` allows: an alarm and a report, not SIGXFSZ.
TEST(SurfacesLimits, FileSizeLimitIsAnAlarmWithAReport) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G04 X5.\nM30\n");
  const auto report = dir.path / "r.json";
  const std::string cmd = "ulimit -f 64; " + shell_quote(SKIPNC_BINARY) + " run " +
                          shell_quote(prog.string()) + " --trace " +
                          shell_quote((dir.path / "t.csv").string()) + " --report " +
                          shell_quote(report.string()) + " -q 2>/dev/null";
  const int st = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(st)) << "ended by a signal";
  EXPECT_EQ(WEXITSTATUS(st), 1);
  const auto j = nlohmann::json::parse(read_file(report), nullptr, false);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j.value("status", ""), "alarm");
}

// ---- 8. Words and outputs ---------------------------------------------------

// A replaced output keeps its permissions, never the set-user-ID or
// set-group-ID bit.
TEST(SurfacesOutputs, ReplacedOutputLosesSetuidBits) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G0 X1.\nM30\n");
  const auto report = dir.write("r.json", "old");
  ASSERT_EQ(::chmod(report.c_str(), 06755), 0);
  const auto r = run_cli({"run", prog.string(), "--report", report.string(), "-q"});
  EXPECT_EQ(r.exit_code, 0);
  struct stat st {};
  ASSERT_EQ(::stat(report.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0755u);
}

// ---- Words the language does not have ----------------------------------

// `G1 X1e-05` is X1 and an E word. LinuxCNC's rs274 refuses the E ("E word
// with no G70, G76, M66, M67 or M68 to use it"), grbl any letter it does not
// read (error:20); skipnc once moved 1 mm.
TEST(SurfacesWords, ExponentIsAnEWordAndRefused) {
  TempDir dir;
  const auto prog = dir.write("p.ngc", "G21 G90\nG1 X1e-05 F100\nM2\n");
  for (const std::string d : {"linuxcnc", "grblhal"}) {
    const auto r = run_with_report(dir, prog, {"-d", d});
    ASSERT_TRUE(r.report_ok) << d << r.err;
    EXPECT_EQ(r.exit.code, 1) << d;
    EXPECT_EQ(r.alarm().value("code", ""), alarm_code(AlarmId::kIllegalAddress, d)) << d;
    EXPECT_EQ(r.alarm().value("line", 0), 2) << d;
    EXPECT_EQ(r.alarm().value("column", 0), 6) << d;  // the E of X1e-05
    EXPECT_DOUBLE_EQ(r.report.at("final").at("machine_position").value("X", -1.0), 0.0) << d;
  }
  // grbl: error:20 for every letter it does not read.
  for (const std::string block : {"G0 X1 D1", "G0 X1 H1", "G0 X1 Q1", "G0 X1 E1"}) {
    const auto p2 = dir.write("q.nc", block + "\nM2\n");
    const auto r = run_with_report(dir, p2, {"-d", "grblhal"});
    ASSERT_TRUE(r.report_ok) << block;
    EXPECT_EQ(r.alarm().value("code", ""), "error:20") << block;
  }
  // LinuxCNC's E beside M67 (an analog output) is a word of that code.
  const auto p3 = dir.write("r.ngc", "M67 E0 Q2.5\nM2\n");
  EXPECT_EQ(run_with_report(dir, p3, {"-d", "linuxcnc"}).exit.code, 0);
}

// grbl has no subprograms: M98 is error:20 (grbl 1.1 gcode.c: "Unsupported
// M command").
TEST(SurfacesWords, GrblRefusesM98) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G0 X1\nM98 P100\nM2\n");
  const auto r = run_with_report(dir, prog, {"-d", "grblhal"});
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.exit.code, 1);
  EXPECT_EQ(r.alarm().value("code", ""), "error:20");
  EXPECT_EQ(r.alarm().value("line", 0), 2);
}

// An o<name> sub without its endsub is an alarm, whether it is passed over
// or called.
TEST(SurfacesWords, SubWithoutEndsubIsAnAlarm) {
  TempDir dir;
  for (const std::string text : {"o<s> sub\nG0 X1\nM2\n", "o<s> call\nM2\no<s> sub\nG0 X1\n"}) {
    const auto prog = dir.write("p.ngc", text);
    const auto r = run_with_report(dir, prog, {"-d", "linuxcnc"});
    ASSERT_TRUE(r.report_ok) << text << r.err;
    EXPECT_EQ(r.exit.code, 1) << text;
    EXPECT_EQ(r.alarm().value("code", ""), alarm_code(AlarmId::kOwordFlow, "linuxcnc")) << text;
  }
}

// --trace-every larger than the run: the header and the run's last period
// (was: an empty file).
TEST(SurfacesWords, TraceEveryLargerThanTheRunKeepsHeaderAndLastRow) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G91 G1 X1. F600\nM30\n");
  const auto trace = dir.path / "t.csv";
  const auto r =
      run_with_report(dir, prog, {"--trace", trace.string(), "--trace-every", "1000000"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  const std::string text = read_file(trace);
  ASSERT_EQ(count_lines(text), 2) << text;
  EXPECT_EQ(text.rfind("time_s,", 0), 0u) << text;
  const std::string row = text.substr(text.find('\n') + 1);
  const double t = std::stod(row.substr(0, row.find(',')));
  EXPECT_NEAR(t, r.report.at("final").value("time", 0.0), 1e-9) << text;
}

// ---- Offsets and stored positions are range-checked -----------------------

// An offset or a stored position beyond 999999.999 mm is the dialect's
// illegal_offset_value where it is assigned (Fanuc PS0029), in every
// dialect: nothing of the block is kept, no parameter file holds it.
TEST(SurfacesOffsets, OutOfRangeOffsetsAreRefusedWhereAssigned) {
  TempDir dir;
  struct Case {
    std::string dialect, text;
    int line;
  };
  const std::vector<Case> cases = {
      {"fanuc", "G10 L2 P1 X1000000.\nM30\n", 1},
      {"fanuc", "#5221 = 10000000.\nM30\n", 1},
      {"fanuc", "#2001 = 2000000.\nM30\n", 1},
      {"fanuc", "G10 L10 P1 R-1000000000.\nM30\n", 1},
      {"fanuc", "G0 X0\nG92 X-1000000.\nM30\n", 2},
      {"fanuc", "G52 Z1000000000000.\nM30\n", 1},
      {"nct", "#5221 = 10000000.\nM30\n", 1},
      {"mitsubishi", "G10 L2 P1 Y100000000.\nM30\n", 1},
      {"compass", "#5221 = 10000000.\nM30\n", 1},
      {"linuxcnc", "#5221 = [10 ** 60]\nM2\n", 1},
      {"linuxcnc", "G10 L2 P1 X1000000\nM2\n", 1},
      {"linuxcnc", "G10 L20 P2 Z-2000000\nM2\n", 1},
      {"linuxcnc", "G92 X1000000\nM2\n", 1},
      {"linuxcnc", "G10 L1 P1 Z1000000\nM2\n", 1},
      {"grblhal", "G10 L2 P1 X1000000\nM2\n", 1},
      {"grblhal", "G92 Y-1000000\nM2\n", 1},
  };
  for (const auto& c : cases) {
    const auto prog = dir.write("p.nc", c.text);
    const auto r = run_with_report(dir, prog, {"-d", c.dialect});
    ASSERT_TRUE(r.report_ok) << c.dialect << " " << c.text << r.err;
    EXPECT_EQ(r.exit.code, 1) << c.dialect << " " << c.text;
    EXPECT_EQ(r.alarm().value("code", ""), alarm_code(AlarmId::kIllegalOffsetValue, c.dialect))
        << c.dialect << " " << c.text << r.err;
    EXPECT_EQ(r.alarm().value("line", 0), c.line) << c.dialect << " " << c.text;
  }
  // At the bound, accepted.
  const auto ok = dir.write("ok.nc", "G10 L2 P1 X999999.999\n#5222 = -999999.999\nM30\n");
  EXPECT_EQ(run_with_report(dir, ok).exit.code, 0);
}

// A refused value never reaches the parameter file; the file keeps the run's
// earlier values and the next run starts.
TEST(SurfacesOffsets, RefusedOffsetNeverReachesTheParameterFile) {
  TempDir dir;
  const auto m = linuxcnc_machine_with_parameter_file(dir);
  const auto prog = dir.write("p.ngc", "#5221 = 12.5\nG10 L2 P1 X3 Y1000000000\nM2\n");
  auto r = run_cli({"run", prog.string(), "-m", m.string(), "-q"}, (dir.path / "e1").string());
  EXPECT_EQ(r.exit_code, 1) << read_file(dir.path / "e1");
  const std::string text = read_file(dir.path / "m.var");
  const auto at = text.find("\n5221\t");
  ASSERT_NE(at, std::string::npos) << text;
  EXPECT_DOUBLE_EQ(std::stod(text.substr(at + 6)), 12.5) << text;  // X3 not kept either
  EXPECT_EQ(text.find("1000000000"), std::string::npos) << text;
  const auto prog2 = dir.write("q.ngc", "M2\n");
  r = run_cli({"run", prog2.string(), "-m", m.string(), "-q"}, (dir.path / "e2").string());
  EXPECT_EQ(r.exit_code, 0) << read_file(dir.path / "e2");
}

// ---- Time: what changes costs, not the simulated periods -----------------

// G04 X1e9 (31 years) runs to limits.max_time_s (1000 h) with its alarm; the
// periods in which nothing changes are passed in one step (it took 191 s of
// processor time, period by period). The bound here is the wait's, 60 s.
TEST(SurfacesTime, HugeDwellEndsAtTheTimeLimitInLittleProcessorTime) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G0 X1.\nG04 X1000000000.\nM30\n");
  const auto r = run_with_report(dir, prog, {}, 60.0);
  ASSERT_TRUE(r.exit.exited) << "not ended within 60 s";
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.alarm().value("code", ""), alarm_code(AlarmId::kTimeLimit));
  EXPECT_EQ(r.alarm().value("line", 0), 2);
  EXPECT_DOUBLE_EQ(r.report.at("final").value("time", 0.0), 3600000.0);
  EXPECT_DOUBLE_EQ(r.report.at("final").at("machine_position").value("X", 0.0), 1.0);
}

// Issue 30: a dwell's block has its own time (G04 X5. is 5.000 s, was
// 4.999 s: its last period went to the next block), every dwell has a row
// (G04 X0 too, for no time), and the trace labels each period with the
// block that ran it. With --trace-every the rows are those of every N-th
// period and the last, whether or not the periods between were passed in one
// step.
TEST(SurfacesTime, DwellBlocksHaveTheirTimeAndQuietPeriodsKeepTheTraceRows) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G0 X1.\nG04 X5.\nG04 X0\nG1 X2. F600\nG04 X0.5\nM30\n");
  const auto trace = dir.path / "t.csv";
  auto r = run_with_report(dir, prog, {"--trace", trace.string()});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  std::map<int, double> time_of;
  std::map<int, int> runs_of;
  for (const auto& b : r.report.at("block_times").at("blocks")) {
    time_of[b.value("line", 0)] = b.value("time", -1.0);
    runs_of[b.value("line", 0)] = b.value("runs", 0);
  }
  EXPECT_DOUBLE_EQ(time_of[2], 5.0);
  ASSERT_EQ(runs_of.count(3), 1u) << r.report.at("block_times").dump();
  EXPECT_DOUBLE_EQ(time_of[3], 0.0);
  EXPECT_EQ(runs_of[3], 1);
  EXPECT_DOUBLE_EQ(time_of[5], 0.5);
  const double total = r.report.at("final").value("time", 0.0);
  // Every period in the trace, labelled: 5000 periods of line 2, then line 4.
  const std::string text = read_file(trace);
  std::istringstream in(text);
  std::string row;
  std::getline(in, row);
  int rows = 0, dwell_rows = 0, after_dwell_line = 0, prev_line = 0;
  while (std::getline(in, row)) {
    ++rows;
    const auto c1 = row.find(','), c2 = row.find(',', c1 + 1);
    const int line = std::stoi(row.substr(c1 + 1, c2 - c1 - 1));
    if (line == 2) ++dwell_rows;
    if (prev_line == 2 && line != 2) after_dwell_line = line;
    prev_line = line;
  }
  EXPECT_EQ(rows, static_cast<int>(std::lround(total * 1000)));
  EXPECT_EQ(dwell_rows, 5000);
  EXPECT_EQ(after_dwell_line, 4);
  // --trace-every 250: the rows of periods 250, 500, ... and the last.
  r = run_with_report(dir, prog, {"--trace", trace.string(), "--trace-every", "250"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  std::istringstream in2(read_file(trace));
  std::getline(in2, row);
  std::vector<double> times;
  while (std::getline(in2, row)) times.push_back(std::stod(row.substr(0, row.find(','))));
  const auto periods = static_cast<long>(std::lround(total * 1000));
  ASSERT_EQ(static_cast<long>(times.size()), periods / 250 + (periods % 250 != 0 ? 1 : 0));
  for (std::size_t i = 0; i + 1 < times.size(); ++i)
    EXPECT_NEAR(times[i], 0.25 * static_cast<double>(i + 1), 1e-9);
  EXPECT_NEAR(times.back(), total, 1e-9);
}

// Issue 31: a very slow feed costs processor time in proportion to what
// changes. G1 X1. F0.0001 is 600,000 s of motion, 600 million periods (about
// 19 s of processor time period by period, more than the 5 s limits.max_cpu_s
// allows here): its cruise is passed in a few steps, and the run ends with the
// axis at X1.
TEST(SurfacesTime, VerySlowFeedEndsInLittleProcessorTime) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G1 X1. F0.0001\nM30\n");
  const auto machine = dir.write("m.toml", "extends = \"mill3\"\n[limits]\nmax_cpu_s = 5\n");
  const auto r = run_with_report(dir, prog, {"-m", machine.string()}, 120.0);
  ASSERT_TRUE(r.exit.exited) << "not ended within 120 s";
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.exit.code, 0) << r.report.dump(1);
  EXPECT_NEAR(r.report.at("final").value("time", 0.0), 600000.0, 0.01);
  EXPECT_DOUBLE_EQ(r.report.at("final").at("machine_position").value("X", 0.0), 1.0);
}

// A passed cruise gives the report of the period-by-period run: the same
// program with a trace (which has every period run one by one, its rows
// digit for digit) and without one (its cruises passed in closed form) gives
// the same report, byte for byte. Three slow feeds on three axes, 102 s, on
// mill3 (kp 30/s, feedforward 0.95) and on mill3_lowgain.
TEST(SurfacesTime, VerySlowFeedGivesThePeriodByPeriodReport) {
  TempDir dir;
  const auto prog =
      dir.write("p.nc", "G91 G1 X0.1 Y0.05 F0.3\nG1 Z-0.02 F0.03\nG1 X-0.1 F0.15\nM30\n");
  const auto trace = dir.path / "t.csv";
  for (const char* machine : {"mill3", "mill3_lowgain"}) {
    const auto one_by_one = run_with_report(dir, prog, {"-m", machine, "--trace", trace.string()});
    ASSERT_EQ(one_by_one.exit.code, 0) << one_by_one.err;
    EXPECT_GT(count_lines(read_file(trace)), 102000) << machine;
    const auto passed = run_with_report(dir, prog, {"-m", machine});
    ASSERT_EQ(passed.exit.code, 0) << passed.err;
    EXPECT_EQ(passed.report.dump(1), one_by_one.report.dump(1)) << machine;
    EXPECT_NEAR(passed.report.at("final").value("time", 0.0), 102.361, 0.01) << machine;
  }
}

}  // namespace
}  // namespace skipnc::test
