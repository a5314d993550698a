// Issue "real probing programs run as their authors wrote them", Haas part:
// each test is named after a construct of Haas programs (docs/compatibility.md,
// docs/skip-dialects.md#haas) and asserts what the user sees in the report.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/report_run.hpp"
#include "support/run_cli.hpp"

namespace skipnc::test {
namespace {

// A Haas mill: the built-in mill3 (X Y Z, mm) under the haas dialect, or
// under another dialect to show the difference.
std::filesystem::path mill(TempDir& dir, const std::string& dialect = "haas",
                           const std::string& extra = "") {
  return dir.write("m_" + dialect + ".toml",
                   "extends = \"mill3\"\nname = \"m\"\ndialect = \"" + dialect + "\"\n" + extra);
}

// A switch that closes while machine Z is below -100.
std::filesystem::path z_plane(TempDir& dir) {
  return dir.write("s.toml",
                   "[[trigger]]\nsignal = \"X0.4\"\naxis = \"Z\"\nat = -100.0\n"
                   "direction = \"decreasing\"\n");
}

ReportRun run(TempDir& dir, const std::string& text, const std::string& dialect = "haas",
              std::vector<std::string> extra = {}) {
  const auto p = dir.write("p.nc", text);
  std::vector<std::string> args = {"-m", mill(dir, dialect).string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_with_report(dir, p, args);
}

double var(const ReportRun& r, int n) {
  return r.report["variables"][std::to_string(n)];
}

TEST(CompatHaas, M97CallsALocalSubprogramLTimes) {
  TempDir dir;
  const std::string prog =
      "#100 = 0\nG90 G0 X0\nM97 P100 L3\n#101 = #5041\nM30\n"
      "N100 #100 = #100 + 1\nG91 G0 X10.\nG90\nM99\n";
  const auto r = run(dir, prog, "haas", {"--var", "100", "--var", "101"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  EXPECT_EQ(var(r, 100), 3.0);
  EXPECT_DOUBLE_EQ(var(r, 101), 30.0);
  // On a Fanuc control M97 is a machine M code: nothing is called.
  TempDir dir2;
  const auto f = run(dir2, prog, "fanuc", {"--var", "100"});
  ASSERT_EQ(f.exit.code, 0) << f.err;
  EXPECT_EQ(var(f, 100), 0.0);
}

TEST(CompatHaas, M97WithoutItsSequenceNumberIsAnAlarmNamingIt) {
  TempDir dir;
  const auto r = run(dir, "G0 X1.\nM97 P200\nM30\nN100 M99\n");
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.exit.code, 1);
  EXPECT_EQ(r.alarm()["code"], alarm_code(AlarmId::kSequenceNotFound, "haas"));
  EXPECT_EQ(r.alarm()["line"], 2);
  EXPECT_NE(r.alarm()["message"].get<std::string>().find("N200"), std::string::npos)
      << r.alarm().dump();
}

TEST(CompatHaas, M97InsideAMacroCallsTheMacrosOwnLabel) {
  TempDir dir;
  dir.write("O9100.nc", "O9100\n#100 = #1\nM97 P10\nM99\nN10 #101 = #1 * 2\nM99\n");
  const auto r = run(dir, "G65 P9100 A4.\n#102 = 1\nM30\nN10 #102 = 99\nM99\n", "haas",
                     {"-I", dir.path.string(), "--var", "100", "--var", "101", "--var", "102"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  EXPECT_EQ(var(r, 100), 4.0);
  EXPECT_EQ(var(r, 101), 8.0);
  EXPECT_EQ(var(r, 102), 1.0);
}

TEST(CompatHaas, G103LookaheadLimitAcceptsP0ToP15) {
  TempDir dir;
  const auto r = run(dir, "G103 P1\nG0 X1.\nG103\nG103 P15\nG103 P0\nM30\n");
  ASSERT_EQ(r.exit.code, 0) << r.err;
  TempDir dir2;
  const auto bad = run(dir2, "G103 P16\nM30\n");
  ASSERT_TRUE(bad.report_ok) << bad.err;
  EXPECT_EQ(bad.exit.code, 1);
  EXPECT_EQ(bad.alarm()["code"], alarm_code(AlarmId::kBadValue, "haas"));
  EXPECT_EQ(bad.alarm()["column"], 6);
  // Fanuc has no G103: refused as an improper G code.
  TempDir dir3;
  const auto f = run(dir3, "G103 P1\nM30\n", "fanuc");
  EXPECT_EQ(f.exit.code, 1);
  EXPECT_EQ(f.alarm()["code"], "PS0010");
}

TEST(CompatHaas, G103P1LeavesTheProbedValuesAsWithout) {
  TempDir dir;
  const auto s = z_plane(dir);
  const std::string touch = "G90 G0 Z-90.\nG31 Z-120. F300.\n#100 = #5063\n#101 = #5023\nM30\n";
  const auto a = run(dir, touch, "haas", {"-s", s.string(), "--var", "100", "--var", "101"});
  const auto b =
      run(dir, "G103 P1\n" + touch, "haas", {"-s", s.string(), "--var", "100", "--var", "101"});
  ASSERT_EQ(a.exit.code, 0) << a.err;
  ASSERT_EQ(b.exit.code, 0) << b.err;
  EXPECT_NEAR(var(a, 100), -100.0, 1e-6);
  EXPECT_EQ(var(a, 100), var(b, 100));
  EXPECT_EQ(var(a, 101), var(b, 101));
}

// G103 Pn limits the motion's look-ahead to n blocks: 50 collinear moves of
// 0.2 mm at F6000 (100 mm/s) on the mill3 axes (2000 mm/s^2). Under G103 P1
// a move starts knowing one more, so the axis must be able to stop within
// 2 x 0.2 mm: v <= sqrt(2 x 2000 x 0.4) = 40 mm/s, and the 10 mm take at
// least 0.25 s. Without a limit the machine goes faster than 40 mm/s, so it
// ends sooner (0.15 s of motion at 100 mm/s plus its ramps and settling);
// P2 (0.6 mm known: 49 mm/s) lies between. Under P15 (3.2 mm known: 113
// mm/s would be allowed) the time is that of no limit; P0 lifts the limit.
double short_moves_time(TempDir& dir, const std::string& head) {
  std::string prog = head + "G90 G1 X0. F6000.\n";
  for (int i = 1; i <= 50; ++i) prog += "X" + std::to_string(i * 0.2).substr(0, 5) + "\n";
  const auto r = run(dir, prog + "M30\n");
  EXPECT_EQ(r.exit.code, 0) << r.err;
  EXPECT_NEAR(r.report["final"]["position"]["X"].get<double>(), 10.0, 1e-9);
  return r.report["final"]["time"].get<double>();
}

TEST(CompatHaas, G103LimitsTheMotionLookAheadToPBlocks) {
  TempDir dir;
  const double free = short_moves_time(dir, "");
  const double p1 = short_moves_time(dir, "G103 P1\n");
  const double p2 = short_moves_time(dir, "G103 P2\n");
  const double p15 = short_moves_time(dir, "G103 P15\n");
  const double p0 = short_moves_time(dir, "G103 P1\nG103 P0\n");
  EXPECT_GE(p1, 0.25);
  EXPECT_LT(free, 0.25);
  EXPECT_GT(p1, p2);
  EXPECT_GT(p2, free);
  EXPECT_NEAR(p15, free, 0.002);
  EXPECT_EQ(p0, free);
}

TEST(CompatHaas, G103IsSentToTheMotionAsALookAheadCommand) {
  TempDir dir;
  const auto p = dir.write("p.nc", "G103 P2\nG1 X1. F100.\nG103\nM30\n");
  const auto out = run_cli({"canon", "-m", mill(dir).string(), p.string()});
  ASSERT_EQ(out.exit_code, 0);
  EXPECT_NE(out.out.find("LOOKAHEAD 2\n"), std::string::npos) << out.out;
  EXPECT_NE(out.out.find("LOOKAHEAD 0\n"), std::string::npos) << out.out;
}

// Haas 96-8000, Macros: `N50 [#100 LT 10] M99 P10` branches to N10 only
// while #100 < 10. The loop below adds 1 to #100 from 0: it branches back
// until #100 reaches 10, so #101 counts 10 passes; then it goes on to M30.
// A plain expression is a condition too (not 0: true).
TEST(CompatHaas, ConditionalM99BranchesOnlyWhenTrue) {
  TempDir dir;
  const std::string prog =
      "#100 = 0\n#101 = 0\n#102 = 0\nN10 #100 = #100 + 1\n#101 = #101 + 1\n"
      "N50 [#100 LT 10] M99 P10\n[#100 - 10] M99 P70\n#102 = 1\nN70 M30\n";
  const auto r = run(dir, prog, "haas", {"--var", "100", "--var", "101", "--var", "102"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  EXPECT_EQ(var(r, 100), 10.0);
  EXPECT_EQ(var(r, 101), 10.0);
  EXPECT_EQ(var(r, 102), 1.0);  // [10 - 10] is 0: no branch over #102 = 1
}

TEST(CompatHaas, AnExpressionHeadingABlockWithoutM99IsRefused) {
  TempDir dir;
  const auto r = run(dir, "#1 = 1\n[#1 GT 0] G0 X1.\nM30\n");
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.exit.code, 1);
  EXPECT_EQ(r.alarm()["code"], alarm_code(AlarmId::kNoAddress, "haas"));
  EXPECT_EQ(r.alarm()["line"], 2);
  EXPECT_EQ(r.alarm()["column"], 1);
  // Fanuc has no conditional M99: the same head is a value without an address.
  TempDir dir2;
  const auto f = run(dir2, "#1 = 1\n[#1 GT 0] M99 P10\nN10 M30\n", "fanuc");
  ASSERT_TRUE(f.report_ok) << f.err;
  EXPECT_EQ(f.exit.code, 1);
  EXPECT_EQ(f.alarm()["code"], alarm_code(AlarmId::kNoAddress, "fanuc"));
}

TEST(CompatHaas, G31WithoutFeedInItsBlockIsRefused) {
  TempDir dir;
  const auto r = run(dir, "G1 F300.\nG31 Z-10.\nM30\n");
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.exit.code, 1);
  EXPECT_EQ(r.alarm()["code"], alarm_code(AlarmId::kSkipNoFeed, "haas"));
  EXPECT_EQ(r.alarm()["line"], 2);
}

TEST(CompatHaas, G31MissRecordsTheEndPointAndGoesOn) {
  TempDir dir;
  const auto r =
      run(dir, "G90 G31 Z-50. F500.\n#100 = #5063\nG0 X5.\nM30\n", "haas", {"--var", "100"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  EXPECT_DOUBLE_EQ(var(r, 100), -50.0);
  EXPECT_FALSE(r.report["skips"][0]["triggered"].get<bool>());
  EXPECT_DOUBLE_EQ(r.report["final"]["machine_position"]["X"].get<double>(), 5.0);
}

TEST(CompatHaas, G31HasNoPAndNoK) {
  for (const char* block : {"G31 P1 Z-10. F100.", "G31 K1 Z-10. F100."}) {
    TempDir dir;
    const auto r = run(dir, std::string(block) + "\nM30\n");
    ASSERT_TRUE(r.report_ok) << r.err;
    EXPECT_EQ(r.exit.code, 1) << block;
    EXPECT_EQ(r.alarm()["code"], alarm_code(AlarmId::kSkipSyntax, "haas")) << block;
  }
}

TEST(CompatHaas, G31StoresTheToolReferencePointInTheWorkSystem) {
  TempDir dir;
  const auto s = z_plane(dir);
  const auto p = dir.write("p.nc",
                           "G10 L2 P1 Z-20.\nG54 G43 H1 G0 Z0.\nG31 Z-150. F300.\n"
                           "#100 = #5063\n#101 = #5063 - #5083\nM30\n");
  const auto m = mill(dir, "haas", "[tool_offsets]\n1 = { length = 50.0 }\n");
  const auto r =
      run_with_report(dir, p, {"-m", m.string(), "-s", s.string(), "--var", "100", "--var", "101"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  // The trigger is on the axis (the gauge line): machine Z-100 = work -80,
  // which #5063 holds; the tip is H1 = 50 lower.
  EXPECT_NEAR(var(r, 100), -80.0, 1e-6);
  EXPECT_NEAR(var(r, 101), -130.0, 1e-6);
}

TEST(CompatHaas, M99PInASubprogramBranchesWithinIt) {
  const std::string prog =
      "#100 = 0\nM98 P200\n#101 = 1\nM30\nN20 #102 = 7\nM30\n"
      "O200\nN20 #100 = #100 + 1\nIF [#100 GE 3] GOTO 40\nM99 P20\nN40 M99\n";
  TempDir dir;
  const auto r = run(dir, prog, "haas", {"--var", "100", "--var", "101"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  EXPECT_EQ(var(r, 100), 3.0);
  EXPECT_EQ(var(r, 101), 1.0);
  // Fanuc: M99 P20 returns to N20 of the caller after one pass.
  TempDir dir2;
  const auto f = run(dir2, prog, "fanuc", {"--var", "100", "--var", "101", "--var", "102"});
  ASSERT_EQ(f.exit.code, 0) << f.err;
  EXPECT_EQ(var(f, 100), 1.0);
  EXPECT_EQ(var(f, 102), 7.0);
  EXPECT_TRUE(f.report["variables"]["101"].is_null());
}

TEST(CompatHaas, ToolOffsetVariablesUseHaasNumbers) {
  TempDir dir;
  const std::string prog =
      "#2001 = 100.\n#2201 = -0.25\n#2401 = 6.\n#2601 = 0.01\n"
      "G43 H1\n#100 = #5083\n#101 = #11001\n#102 = #10001\n#103 = #13001\n#104 = #12001\nM30\n";
  const auto r =
      run(dir, prog, "haas",
          {"--var", "100", "--var", "101", "--var", "102", "--var", "103", "--var", "104"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  EXPECT_DOUBLE_EQ(var(r, 100), 99.75);  // length + wear
  EXPECT_DOUBLE_EQ(var(r, 101), 100.0);  // geometry
  EXPECT_DOUBLE_EQ(var(r, 102), -0.25);  // wear
  EXPECT_DOUBLE_EQ(var(r, 103), 6.0);
  EXPECT_DOUBLE_EQ(var(r, 104), 0.01);
  // Fanuc's short forms: #2001 is the wear, #2201 the geometry.
  TempDir dir2;
  const auto f = run(dir2, prog, "fanuc", {"--var", "101", "--var", "102"});
  ASSERT_EQ(f.exit.code, 1) << f.err;  // #2401 is no variable of a Fanuc control
}

// A mill3 with rotary axes after X Y Z (e.g. "A", "C", or "B", "C"), under
// `dialect`.
std::filesystem::path rotary_mill(TempDir& dir, const std::string& dialect,
                                  const std::vector<std::string>& axes) {
  std::string text = "extends = \"mill3\"\nname = \"m5\"\ndialect = \"" + dialect + "\"\n";
  for (const auto& a : axes) {
    text += "[[axis]]\nname = \"" + a +
            "\"\nmin = -9999.0\nmax = 9999.0\nrapid = 10000.0\nmax_feed = 5000.0\n"
            "accel = 1000.0\n";
  }
  return dir.write("m5_" + dialect + ".toml", text);
}

ReportRun run_rotary(TempDir& dir, const std::string& text, const std::string& dialect,
                     const std::vector<std::string>& axes, std::vector<std::string> extra) {
  const auto p = dir.write("p.nc", text);
  std::vector<std::string> args = {"-m", rotary_mill(dir, dialect, axes).string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_with_report(dir, p, args);
}

// 96-8000, Macros, "Offsets": #5221-#5225 are G54's X, Y, Z, A, B; Autodesk's
// Haas post writes #5226 for G54's C. On an X Y Z A C machine #5224 is A,
// #5225 (B) no axis, #5226 C, read and written; G10 (by letter) agrees.
TEST(CompatHaas, WorkOffsetVariablesAreNumberedByAxisLetter) {
  TempDir dir;
  const std::string prog =
      "G10 L2 P1 A10. C2.5\n#100 = #5224\n#101 = #5226\n#102 = #5225\n"
      "#5246 = 7.\n#5244 = -3.\n#7006 = 4.\n#103 = #7006\n#104 = #7005\n"
      "G55 G0 X0 Y0 Z0 A0 C0\n#105 = #5025\n#106 = #5024\nM30\n";
  std::vector<std::string> vars;
  for (int v = 100; v <= 106; ++v) vars.insert(vars.end(), {"--var", std::to_string(v)});
  const auto r = run_rotary(dir, prog, "haas", {"A", "C"}, vars);
  ASSERT_EQ(r.exit.code, 0) << r.err;
  EXPECT_EQ(var(r, 100), 10.0);  // G54 A
  EXPECT_EQ(var(r, 101), 2.5);   // G54 C
  EXPECT_TRUE(r.report["variables"]["102"].is_null()) << r.report["variables"].dump();
  EXPECT_EQ(var(r, 103), 4.0);  // G54.1 P1 C
  EXPECT_TRUE(r.report["variables"]["104"].is_null()) << r.report["variables"].dump();
  // #5246 went to G55's C, #5244 to its A: the machine's C (its fifth axis,
  // #5025: the position variables stay by position) stands at 7 at G55 C0.
  EXPECT_EQ(var(r, 105), 7.0);
  EXPECT_EQ(var(r, 106), -3.0);
}

TEST(CompatHaas, AnOffsetVariableOfALetterTheMachineLacksIsAnAlarm) {
  TempDir dir;
  const auto r = run_rotary(dir, "#5226 = 1.\n#5225 = 2.\nM30\n", "haas", {"B", "C"}, {});
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.exit.code, 0) << r.err;  // X Y Z B C: #5225 B, #5226 C
  TempDir dir2;
  const auto a = run_rotary(dir2, "#5226 = 1.\n#5224 = 2.\nM30\n", "haas", {"B", "C"}, {});
  ASSERT_TRUE(a.report_ok) << a.err;
  EXPECT_EQ(a.exit.code, 1);
  EXPECT_EQ(a.alarm()["code"], alarm_code(AlarmId::kIllegalVariable, "haas"));
  EXPECT_EQ(a.alarm()["line"], 2);
  EXPECT_NE(a.alarm()["message"].get<std::string>().find("no A axis"), std::string::npos)
      << a.alarm().dump();
  TempDir dir3;  // no seventh letter: #5227 names no axis even on a 6-axis machine
  const auto u = run_rotary(dir3, "#5227 = 1.\nM30\n", "haas", {"A", "B", "C"}, {});
  ASSERT_TRUE(u.report_ok) << u.err;
  EXPECT_EQ(u.exit.code, 1);
  EXPECT_EQ(u.alarm()["code"], alarm_code(AlarmId::kIllegalVariable, "haas"));
}

// --repeat follows the offsets a program writes under their variable and
// axis: #5226 is G54's C on X Y Z A C.
TEST(CompatHaas, RepeatNamesAnOffsetVariableByItsLetter) {
  TempDir dir;
  const auto p = dir.write("p.nc", "#5226 = 1.5\nM30\n");
  const auto r = run_cli(
      {"run", "-m", rotary_mill(dir, "haas", {"A", "C"}).string(), "--repeat", "1", p.string()});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("#5226 G54 C "), std::string::npos) << r.out;
}

// Fanuc numbers the offsets by the controlled-axis order: on X Y Z A C,
// #5225 is C and #5226 (a sixth axis) is an alarm.
TEST(CompatHaas, FanucStillNumbersTheOffsetVariablesByPosition) {
  TempDir dir;
  const auto r = run_rotary(dir, "G10 L2 P1 A10. C2.5\n#100 = #5224\n#101 = #5225\nM30\n", "fanuc",
                            {"A", "C"}, {"--var", "100", "--var", "101"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  EXPECT_EQ(var(r, 100), 10.0);
  EXPECT_EQ(var(r, 101), 2.5);
  TempDir dir2;
  const auto a = run_rotary(dir2, "#5225 = 1.\n#5226 = 2.\nM30\n", "fanuc", {"A", "C"}, {});
  ASSERT_TRUE(a.report_ok) << a.err;
  EXPECT_EQ(a.exit.code, 1);
  EXPECT_EQ(a.alarm()["code"], alarm_code(AlarmId::kIllegalVariable, "fanuc"));
  EXPECT_EQ(a.alarm()["line"], 2);
}

TEST(CompatHaas, MacroAlarm3000CarriesTheNumberAndTheComment) {
  TempDir dir;
  const auto r = run(dir, "G0 X1.\n#3000 = 15 (PROBE OPEN)\nG0 X2.\nM30\n");
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.exit.code, 1);
  EXPECT_EQ(r.alarm()["number"], 3015);
  EXPECT_EQ(r.alarm()["line"], 2);
  EXPECT_NE(r.alarm()["message"].get<std::string>().find("PROBE OPEN"), std::string::npos)
      << r.alarm().dump();
  EXPECT_DOUBLE_EQ(r.report["final"]["machine_position"]["X"].get<double>(), 1.0);
}

TEST(CompatHaas, MillisecondTimerAndDateVariablesRead) {
  TempDir dir;
  // 10 mm at 600 mm/min: one second of feed, plus 5 ms of acceleration
  // (10 mm/s at 2000 mm/s^2) and the servo settling into position after it
  // (time constant 1/kp = 20 ms on mill3).
  const auto r = run(dir, "#3001 = 0\nG1 X10. F600.\n#100 = #3001\n#101 = #3011\nM30\n", "haas",
                     {"--var", "100", "--var", "101"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  EXPECT_GE(var(r, 100), 1000.0);
  EXPECT_LE(var(r, 100), 1100.0);
  EXPECT_GT(var(r, 101), 19700101.0);
}

TEST(CompatHaas, G65LRepeatsKeepTheLocalsOfTheFirstPass) {
  TempDir dir;
  dir.write("O9200.nc", "O9200\n#1 = #1 + 1\n#100 = #1\nM99\n");
  const auto r =
      run(dir, "G65 P9200 L3 A1.\nM30\n", "haas", {"-I", dir.path.string(), "--var", "100"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  EXPECT_EQ(var(r, 100), 4.0);
}

// Posted programs open with % and their O block: GOTO and M99 P find the
// labels after them (every Fanuc-family dialect).
TEST(CompatHaas, GotoFindsItsLabelInAProgramOpenedByPercentAndO) {
  for (const char* dialect : {"haas", "fanuc"}) {
    TempDir dir;
    const auto r =
        run(dir, "%\nO1001 (POSTED)\n#1 = 2\nGOTO 40\n#1 = 5\nN40 #100 = #1 + 1\nM30\n%\n", dialect,
            {"--var", "100"});
    ASSERT_EQ(r.exit.code, 0) << dialect << ": " << r.err;
    EXPECT_EQ(var(r, 100), 3.0) << dialect;
  }
}

TEST(CompatHaas, DialectIsListedAndSelectable) {
  const auto r = run_cli({"dialects"});
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("haas"), std::string::npos);
  EXPECT_NE(r.out.find("work offsets #5201.. by axis letter"), std::string::npos) << r.out;
  TempDir dir;
  const auto p = dir.write("p.nc", "M97 P10\nM30\nN10 #100 = 5\nM99\n");
  const auto d = run_with_report(dir, p, {"-d", "haas", "--var", "100"});
  ASSERT_EQ(d.exit.code, 0) << d.err;
  EXPECT_EQ(var(d, 100), 5.0);
}

}  // namespace
}  // namespace skipnc::test
