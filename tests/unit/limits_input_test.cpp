// Bad input, one test per case of issue 7: a very long line, deep brackets,
// a 400-digit number, NaN and infinity from expressions, SQRT of a negative,
// division by zero, a binary file, an empty file. Each is run through the
// skipnc binary as a user would; each must end in a clear alarm with
// file:line:column in the report (exit status 1), never in a crash or a
// hang. docs/bad-input.md lists them.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <random>
#include <string>

#include "gcode/ast.hpp"
#include "support/report_run.hpp"

namespace skipnc::test {
namespace {

// What a user must see for a program that ends in an alarm.
void expect_alarm(const ReportRun& r, AlarmId id, std::uint32_t line, std::uint32_t column,
                  const std::string& file) {
  ASSERT_TRUE(r.exit.exited) << "ended by signal " << r.exit.signal;
  EXPECT_FALSE(r.exit.timed_out);
  EXPECT_EQ(r.exit.code, 1) << r.err;
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.status(), "alarm");
  const auto& a = r.alarm();
  ASSERT_TRUE(a.is_object()) << r.report.dump();
  EXPECT_EQ(a.value("code", ""), alarm_code(id)) << a.dump();
  EXPECT_EQ(a.value("file", ""), file) << a.dump();
  EXPECT_EQ(a.value("line", 0u), line) << a.dump();
  EXPECT_EQ(a.value("column", 0u), column) << a.dump();
  // The same place on standard error, for a user without a report.
  EXPECT_NE(r.err.find(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ":"),
            std::string::npos)
      << r.err;
}

ReportRun run_text(const TempDir& dir, const std::string& text,
                   std::vector<std::string> args = {}) {
  const auto p = dir.write("prog.nc", text);
  return run_with_report(dir, p, std::move(args));
}

TEST(LimitsInput, MegabyteLineIsBlockTooLong) {
  TempDir dir;
  std::string text = "G0 X1\nG1 X";
  text.append(1 << 20, '1');
  text += " F100\nM30\n";
  const auto r = run_text(dir, text);
  expect_alarm(r, AlarmId::kBlockTooLong, 2, 1, (dir.path / "prog.nc").string());
  EXPECT_LT(r.exit.wall_s, 10.0);
}

TEST(LimitsInput, MegabyteCommentIsBlockTooLong) {
  TempDir dir;
  std::string text = "(";
  text.append(1 << 20, 'a');
  text += ")\nM30\n";
  const auto r = run_text(dir, text);
  expect_alarm(r, AlarmId::kBlockTooLong, 1, 1, (dir.path / "prog.nc").string());
}

TEST(LimitsInput, ThousandDeepBracketsAreTooManyBrackets) {
  TempDir dir;
  const std::string text = "#1=" + std::string(1000, '[') + "1" + std::string(1000, ']') + "\n";
  const auto r = run_text(dir, text);
  // Fanuc allows five levels: the sixth '[' (column 4 + 5) is refused.
  auto d = config::builtin_dialect("fanuc");
  ASSERT_TRUE(d);
  const auto col = static_cast<std::uint32_t>(4 + d->sw.macro_bracket_depth);
  expect_alarm(r, AlarmId::kBracketNesting, 1, col, (dir.path / "prog.nc").string());
}

TEST(LimitsInput, ThousandDeepFunctionCallsAreTooManyBrackets) {
  TempDir dir;
  std::string e = "1";
  for (int i = 0; i < 1000; ++i) e = "ABS[" + e + "]";
  const auto r = run_text(dir, "G0 X0\n#1=" + e + "\n");
  auto d = config::builtin_dialect("fanuc");
  ASSERT_TRUE(d);
  const auto col = static_cast<std::uint32_t>(4 + 4 * d->sw.macro_bracket_depth + 3);
  expect_alarm(r, AlarmId::kBracketNesting, 2, col, (dir.path / "prog.nc").string());
}

// 30000 operators or signs in one block: no bracket, but a syntax tree
// 30000 levels deep. Evaluating it recursed once per level and overflowed
// the stack (found by fuzz_expr); the parser now refuses trees deeper than
// gcode::kMaxExprDepth, at the expression's first character.
TEST(LimitsInput, LongOperatorChainIsRefusedNotACrash) {
  TempDir dir;
  std::string sum = "#1=1";
  for (int i = 0; i < 30000; ++i) sum += "+1";
  const auto r = run_text(dir, "G0 X0\n" + sum + "\n");
  expect_alarm(r, AlarmId::kMacroFormat, 2, 4, (dir.path / "prog.nc").string());
}

TEST(LimitsInput, LongSignChainIsRefusedNotACrash) {
  TempDir dir;
  const auto r = run_text(dir, "G0 X0\n#2=" + std::string(30000, '-') + "#1\n");
  expect_alarm(r, AlarmId::kMacroFormat, 2, 4, (dir.path / "prog.nc").string());
}

TEST(LimitsInput, ChainWithinTheDepthBoundIsEvaluated) {
  TempDir dir;
  std::string sum = "#100=1";
  for (int i = 1; i < gcode::kMaxExprDepth - 2; ++i) sum += "+1";
  const auto r = run_text(dir, sum + "\nM30\n", {"--var", "100"});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 0) << r.err;
  ASSERT_TRUE(r.report_ok);
  EXPECT_EQ(r.report["variables"]["100"].get<double>(), gcode::kMaxExprDepth - 2);
}

TEST(LimitsInput, FourHundredDigitNumberIsTooManyDigits) {
  TempDir dir;
  const auto r = run_text(dir, "G0 X0\nG1 X" + std::string(400, '9') + ". F100\n");
  expect_alarm(r, AlarmId::kTooManyDigits, 2, 5, (dir.path / "prog.nc").string());
  const auto m = run_text(dir, "#1=0." + std::string(400, '3') + "\n");
  expect_alarm(m, AlarmId::kTooManyDigits, 1, 4, (dir.path / "prog.nc").string());
}

TEST(LimitsInput, FourHundredLeadingZerosAreOneNumber) {
  TempDir dir;
  const auto r = run_text(
      dir, "#100=" + std::string(400, '0') + "12.5\n#101=0." + std::string(400, '0') + "1\nM30\n",
      {"--var", "100", "--var", "101"});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 0) << r.err;
  ASSERT_TRUE(r.report_ok);
  EXPECT_EQ(r.report["variables"]["100"].get<double>(), 12.5);
  // 1e-401 is below the smallest double: it reads as 0.
  EXPECT_EQ(r.report["variables"]["101"].get<double>(), 0.0);
}

struct ExprCase {
  const char* name;
  const char* program;
  AlarmId id;
  std::uint32_t line;
  std::uint32_t column;
};

class LimitsExpr : public ::testing::TestWithParam<ExprCase> {};

TEST_P(LimitsExpr, EndsInItsAlarmAtItsPlace) {
  TempDir dir;
  const ExprCase& c = GetParam();
  const auto r = run_text(dir, c.program);
  expect_alarm(r, c.id, c.line, c.column, (dir.path / "prog.nc").string());
}

INSTANTIATE_TEST_SUITE_P(
    Cases, LimitsExpr,
    ::testing::Values(
        ExprCase{"DivisionByZero", "#1=1\n#2=0\n#3=#1/#2\n", AlarmId::kDivisionByZero, 3, 4},
        ExprCase{"DivisionByVacant", "#3=5/#7\n", AlarmId::kDivisionByZero, 1, 4},
        ExprCase{"ModByZero", "#3=5 MOD 0\n", AlarmId::kDivisionByZero, 1, 4},
        ExprCase{"DivisionByZeroInAWord", "G0 X[1/0]\n", AlarmId::kDivisionByZero, 1, 6},
        ExprCase{"SqrtOfNegative", "#1=-4\n#2=SQRT[#1]\n", AlarmId::kIllegalArgument, 2, 4},
        ExprCase{"AcosOutOfRange", "#2=ACOS[2]\n", AlarmId::kIllegalArgument, 1, 4},
        ExprCase{"LnOfZero", "#2=LN[0]\n", AlarmId::kIllegalArgument, 1, 4},
        ExprCase{"InfinityFromExp", "#1=EXP[1000]\n", AlarmId::kOverflow, 1, 4},
        ExprCase{"InfinityFromPow", "#1=POW[10,400]\n", AlarmId::kOverflow, 1, 4},
        ExprCase{"InfinityFromProduct",
                 "#1=999999999999999\n#1=#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*"
                 "#1*#1*#1\n",
                 AlarmId::kOverflow, 2, 4},
        ExprCase{"InfinityInAnAxisWord", "G0 X0\nG1 X[EXP[710]] F100\n", AlarmId::kOverflow, 2, 6},
        ExprCase{"NanFromInfinityMinusInfinity", "#1=EXP[710]-EXP[710]\n", AlarmId::kOverflow, 1,
                 4},
        ExprCase{"TanOfNinety", "#1=TAN[90]\n", AlarmId::kDivisionByZero, 1, 4}),
    [](const ::testing::TestParamInfo<ExprCase>& i) { return std::string(i.param.name); });

TEST(LimitsInput, BinaryFileIsAnIllegalCharacter) {
  // The skipnc executable itself, given as a program.
  TempDir dir;
  const auto r = run_with_report(dir, SKIPNC_BINARY);
  // An ELF file starts with byte 0x7F.
  expect_alarm(r, AlarmId::kIllegalChar, 1, 1, SKIPNC_BINARY);
}

TEST(LimitsInput, RandomBytesEndInAnAlarmWithAPlace) {
  TempDir dir;
  std::mt19937 rng(7);
  for (int k = 0; k < 8; ++k) {
    std::string bytes(4096, '\0');
    for (auto& c : bytes) c = static_cast<char>(rng() & 0xff);
    const auto r = run_text(dir, bytes);
    ASSERT_TRUE(r.exit.exited) << "case " << k << ": signal " << r.exit.signal;
    ASSERT_TRUE(r.report_ok) << "case " << k;
    EXPECT_EQ(r.exit.code, 1) << "case " << k << ": " << r.err;
    EXPECT_EQ(r.status(), "alarm");
    EXPECT_GE(r.alarm().value("line", 0), 1);
    EXPECT_GE(r.alarm().value("column", 0), 1);
  }
}

TEST(LimitsInput, NulByteInABlockIsAnIllegalCharacter) {
  TempDir dir;
  const auto r = run_text(dir, std::string("G0 X0\nG1 X1", 11) + '\0' + " F100\n");
  expect_alarm(r, AlarmId::kIllegalChar, 2, 6, (dir.path / "prog.nc").string());
}

TEST(LimitsInput, EmptyFileCompletesWithoutMotion) {
  // Decision: an empty program is a program with no blocks. It completes,
  // moves nothing and takes no time; the report says so.
  TempDir dir;
  for (const std::string text : {"", "\n\n\n", "%\n%\n", "   \t\n"}) {
    const auto r = run_text(dir, text);
    ASSERT_TRUE(r.exit.exited);
    EXPECT_EQ(r.exit.code, 0) << r.err;
    ASSERT_TRUE(r.report_ok);
    EXPECT_EQ(r.status(), "completed");
    EXPECT_LE(r.report["final"]["time"].get<double>(), 0.001);  // one servo period
    EXPECT_EQ(r.report["final"]["position"]["X"].get<double>(), 0.0);
    EXPECT_TRUE(r.report["skips"].empty());
  }
}

TEST(LimitsInput, MissingOrUnreadableProgramCannotStart) {
  TempDir dir;
  // A FIFO that no one writes once made the run wait for ever on open().
  const auto fifo = dir.path / "fifo.nc";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const auto& p : {dir.path / "nothing.nc", dir.path, fifo}) {
    const auto r = run_with_report(dir, p);
    ASSERT_TRUE(r.exit.exited);
    EXPECT_EQ(r.exit.code, 2) << p;
    ASSERT_TRUE(r.report_ok) << p;
    EXPECT_EQ(r.status(), "alarm");
    EXPECT_EQ(r.alarm().value("code", ""), alarm_code(AlarmId::kFileAccess)) << p;
    EXPECT_LT(r.exit.wall_s, 10.0) << p;
  }
}

}  // namespace
}  // namespace skipnc::test
