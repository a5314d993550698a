// Limits of a run, one test per case of issue 7: a program far larger than
// memory streams through in bounded memory; a billion-iteration WHILE ends at
// limits.max_macro_statements of the machine file; runaway recursion (M98 or
// G65 calling itself) ends in the nesting alarm; a move that would take hours
// ends at limits.max_time_s. Each through the skipnc binary, as a user runs it.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/report_run.hpp"
#include "support/sanitizer.hpp"

namespace skipnc::test {
namespace {

// The built-in mill3 with a [limits] table.
std::string machine_with_limits(const std::string& limits) {
  std::string m = "name = \"limited\"\ndialect = \"fanuc\"\n";
  for (const char* a : {"X", "Y", "Z"}) m += std::string("[[axis]]\nname = \"") + a + "\"\n";
  return m + "[limits]\n" + limits + "\n";
}

void expect_alarm_on(const ReportRun& r, AlarmId id, std::uint32_t line) {
  ASSERT_TRUE(r.exit.exited) << "ended by signal " << r.exit.signal;
  EXPECT_FALSE(r.exit.timed_out);
  EXPECT_EQ(r.exit.code, 1) << r.err;
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.status(), "alarm");
  EXPECT_EQ(r.alarm().value("code", ""), alarm_code(id)) << r.report.dump();
  EXPECT_EQ(r.alarm().value("line", 0u), line) << r.report.dump();
  EXPECT_GE(r.alarm().value("column", 0), 1);
}

TEST(LimitsRun, BillionIterationWhileEndsAtTheStatementLimit) {
  TempDir dir;
  const auto m = dir.write("m.toml", machine_with_limits("max_macro_statements = 200000"));
  const auto p = dir.write("loop.nc",
                           "#1=0\n"
                           "WHILE [#1 LT 1000000000] DO1\n"
                           "#1=#1+1\n"
                           "END1\n"
                           "M30\n");
  const auto r = run_with_report(dir, p, {"-m", m.string(), "--var", "1"});
  // Blocks 1..200000 run: #1=0, then WHILE / #1=#1+1 / END in turn; block
  // 200001 is the limit. 200000 = 1 + 3 * 66666 + 1: the last block run is
  // the WHILE of round 66667, so block 200001 is the increment on line 3.
  expect_alarm_on(r, AlarmId::kLoopLimit, 3);
  ASSERT_TRUE(r.report_ok);
  EXPECT_EQ(r.report["variables"]["1"].get<double>(), 66666.0);
  EXPECT_LT(r.exit.wall_s, 20.0);
}

TEST(LimitsRun, EndlessGotoEndsAtTheStatementLimit) {
  TempDir dir;
  const auto m = dir.write("m.toml", machine_with_limits("max_macro_statements = 100000"));
  const auto p = dir.write("goto.nc", "N1 GOTO 1\n");
  const auto r = run_with_report(dir, p, {"-m", m.string()});
  expect_alarm_on(r, AlarmId::kLoopLimit, 1);
}

TEST(LimitsRun, M98CallingItselfIsASubprogramNestingAlarm) {
  TempDir dir;
  const auto p = dir.write("O1234.nc",
                           "O1234\n"
                           "G0 X1.\n"
                           "M98 P1234\n"
                           "M99\n");
  const auto r = run_with_report(dir, p);
  expect_alarm_on(r, AlarmId::kSubprogramNesting, 3);
}

TEST(LimitsRun, G65CallingItselfIsAMacroNestingAlarm) {
  TempDir dir;
  const auto p = dir.write("main.nc",
                           "G65 P9001 A1.\n"
                           "M30\n"
                           "O9001\n"
                           "#100=#1\n"
                           "G65 P9001 A[#1+1]\n"
                           "M99\n");
  const auto r = run_with_report(dir, p, {"--var", "100"});
  expect_alarm_on(r, AlarmId::kMacroNesting, 5);
  ASSERT_TRUE(r.report_ok);
  // Fanuc: four levels of macro calls; the fifth call is refused.
  EXPECT_EQ(r.report["variables"]["100"].get<double>(), 4.0);
}

TEST(LimitsRun, HoursOfMotionEndAtTheTimeLimit) {
  TempDir dir;
  const auto m = dir.write("m.toml", machine_with_limits("max_time_s = 5"));
  const auto p = dir.write("slow.nc", "G1 X500. F1.\nM30\n");
  const auto r = run_with_report(dir, p, {"-m", m.string()});
  expect_alarm_on(r, AlarmId::kTimeLimit, 1);
  ASSERT_TRUE(r.report_ok);
  EXPECT_NEAR(r.report["final"]["time"].get<double>(), 5.0, 0.01);
}

// A program far larger than the read window streams through: memory does
// not grow with it. 200 MB of comments and statements (a 1 GB program works
// the same way; 200 MB keeps the test quick), against the same program at
// 2 MB.
TEST(LimitsRun, LargeProgramStreamsInBoundedMemory) {
  TempDir dir;
  auto make = [&](const std::string& name, std::size_t bytes) {
    const auto path = dir.path / name;
    std::FILE* f = std::fopen(path.c_str(), "wb");
    EXPECT_NE(f, nullptr);
    std::string chunk;
    std::size_t lines = 0;
    std::size_t counted = 0;
    while (chunk.size() < (1 << 20)) {
      if (++lines % 1000 == 0) {
        chunk += "#100=#100+1\n";
        ++counted;
      } else {
        chunk += "(a comment line that the reader skips, seventy bytes long ........)\n";
      }
    }
    std::size_t written = 0;
    std::size_t total = 0;
    while (written + chunk.size() <= bytes) {
      std::fwrite(chunk.data(), 1, chunk.size(), f);
      written += chunk.size();
      total += counted;
    }
    std::fputs("G0 X1.\nM30\n", f);
    std::fclose(f);
    return std::make_pair(path, total);
  };
  // In a sanitizer build the allocator keeps freed blocks aside (quarantine,
  // 256 MB by default), which would show as memory use: bound it.
  const char* asan_env = std::getenv("ASAN_OPTIONS");
  const bool had_asan = asan_env != nullptr;
  const std::string asan = had_asan ? asan_env : "";
  ::setenv("ASAN_OPTIONS", (asan + (had_asan ? ":" : "") + "quarantine_size_mb=4").c_str(), 1);
  const auto [small, small_count] = make("small.nc", 2u << 20);
  const auto [big, big_count] = make("big.nc", 200u << 20);
  const auto rs = run_with_report(dir, small, {"--var", "100"});
  const auto rb = run_with_report(dir, big, {"--var", "100"}, 120.0);
  for (const auto* r : {&rs, &rb}) {
    ASSERT_TRUE(r->exit.exited);
    EXPECT_EQ(r->exit.code, 0) << r->err;
    ASSERT_TRUE(r->report_ok);
  }
  // Every block was read: the counter saw all of them.
  EXPECT_EQ(rs.report["variables"]["100"].get<double>(), static_cast<double>(small_count));
  EXPECT_EQ(rb.report["variables"]["100"].get<double>(), static_cast<double>(big_count));
  std::fprintf(stderr, "peak RSS: %ld kB for 2 MB, %ld kB for 200 MB (%.2f s)\n",
               rs.exit.max_rss_kb, rb.exit.max_rss_kb, rb.exit.wall_s);
  // 100 times the text, the same memory within 8 MB, and far below the file.
  EXPECT_LT(rb.exit.max_rss_kb, rs.exit.max_rss_kb + 8 * 1024);
#if SKIPNC_TEST_ASAN
  // ASan's shadow memory and allocator come on top, and the Debug ASan
  // binary (~120 MB) counts with the pages of it that run: its baseline was
  // 159 MB with a 2 MB program, 1 MB under the old bound of 160 MB, and
  // grows with the code. The flat check above is the one that matters.
  constexpr long kFlatKb = 200 * 1024;
#else
  constexpr long kFlatKb = 100 * 1024;
#endif
  EXPECT_LT(rb.exit.max_rss_kb, kFlatKb);
  if (had_asan) {
    ::setenv("ASAN_OPTIONS", asan.c_str(), 1);
  } else {
    ::unsetenv("ASAN_OPTIONS");
  }
}

// A GOTO in a program with more N labels than limits.max_label_index: the
// jump index keeps only the number asked for (a scan per number), so memory
// does not grow with the program (issue 21: a 1 GB program with one GOTO held
// every label, 1.58 GB). Here 1 000 000 labels (44 MB) against 4 000 (0.2 MB),
// both past a cap of 1 000: the same memory within 8 MB; the GOTO lands on
// the right label (the counter shows how many blocks ran after it).
TEST(LimitsRun, GotoInAProgramWithManyLabelsStaysInBoundedMemory) {
  TempDir dir;
  const auto m = dir.write("m.toml", machine_with_limits("max_label_index = 1000"));
  // Labels N1-N50000 over and over (N is at most 99999), then N99990 and
  // five more counted blocks. Written line by line: the test process stays
  // small (a spawned child's peak memory counts the parent's until exec).
  auto make = [&](const std::string& name, int labels) {
    const auto path = dir.path / name;
    std::FILE* f = std::fopen(path.c_str(), "wb");
    EXPECT_NE(f, nullptr);
    std::fputs("#100=0\nGOTO 99990\n", f);
    for (int i = 0; i < labels; ++i) {
      std::fprintf(f, "N%d #101=#101+1 (label line, forty bytes)\n", 1 + i % 50000);
    }
    std::fputs("N99990 #100=#100+1\n", f);
    for (int i = 1; i <= 5; ++i) std::fprintf(f, "N%d #100=#100+1\n", i);
    std::fputs("M30\n", f);
    std::fclose(f);
    return path;
  };
  const auto small = make("small.nc", 4000);
  const auto big = make("big.nc", 1000000);
  // In a sanitizer build freed blocks wait in a quarantine (256 MB by
  // default), which would show as memory use: bound it, as above.
  const char* asan_env = std::getenv("ASAN_OPTIONS");
  const std::string asan = asan_env != nullptr ? asan_env : "";
  ::setenv("ASAN_OPTIONS", (asan + (asan.empty() ? "" : ":") + "quarantine_size_mb=4").c_str(), 1);
  const auto rs = run_with_report(dir, small, {"-m", m.string(), "--var", "100"});
  const auto rb = run_with_report(dir, big, {"-m", m.string(), "--var", "100"}, 120.0);
  if (asan_env != nullptr) {
    ::setenv("ASAN_OPTIONS", asan.c_str(), 1);
  } else {
    ::unsetenv("ASAN_OPTIONS");
  }
  for (const auto* r : {&rs, &rb}) {
    ASSERT_TRUE(r->exit.exited);
    EXPECT_EQ(r->exit.code, 0) << r->err;
    ASSERT_TRUE(r->report_ok);
    // From N99990 to the end: 6 blocks counted.
    EXPECT_EQ(r->report["variables"]["100"].get<double>(), 6.0);
  }
  std::fprintf(stderr, "peak RSS: %ld kB for 4000 labels, %ld kB for 1000000\n", rs.exit.max_rss_kb,
               rb.exit.max_rss_kb);
#if SKIPNC_TEST_ASAN
  // ASan's allocator and shadow pages come on top even with the quarantine
  // bounded: 38.9 MB against 49.0 MB measured (the Release binary: 7.2 MB
  // against 8.1 MB, the bound that matters).
  constexpr long kMoreKb = 16 * 1024;
#else
  constexpr long kMoreKb = 8 * 1024;
#endif
  EXPECT_LT(rb.exit.max_rss_kb, rs.exit.max_rss_kb + kMoreKb);
}

}  // namespace
}  // namespace skipnc::test
