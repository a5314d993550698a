// Issue "real probing programs run as their authors wrote them", LinuxCNC
// part: each test is named after the construct a public probing program
// uses (docs/compatibility.md) and asserts what the user sees in the report.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "support/report_run.hpp"
#include "support/run_cli.hpp"

namespace skipnc::test {
namespace {

// A LinuxCNC mill (X Y Z, mm) with the INI and HAL values some programs read.
std::filesystem::path lcnc_machine(TempDir& dir, const std::string& extra = "") {
  return dir.write("m.toml",
                   "extends = \"mill3\"\nname = \"lcnc\"\ndialect = \"linuxcnc\"\n" + extra);
}

std::string message_text(const ReportRun& r) {
  std::string all;
  for (const auto& m : r.report["messages"]) all += m.get<std::string>() + "\n";
  return all;
}

TEST(CompatLinuxcnc, AbortEndsTheRunWithAnAlarmCarryingTheText) {
  TempDir dir;
  const auto m = lcnc_machine(dir);
  const auto p = dir.write("p.ngc",
                           "#<depth> = 12.5\n"
                           "o100 if [#<depth> GT 10]\n"
                           "(abort, depth #<depth> too deep)\n"
                           "o100 endif\n"
                           "G0 X10\nM2\n");
  const auto r = run_with_report(dir, p, {"-m", m.string()});
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.exit.code, 1);
  EXPECT_EQ(r.status(), "alarm");
  EXPECT_EQ(r.alarm()["line"], 3);
  EXPECT_NE(r.alarm()["message"].get<std::string>().find("depth 12.500000 too deep"),
            std::string::npos)
      << r.alarm().dump();
  EXPECT_EQ(r.report["final"]["position"]["X"], 0.0);  // the G0 X10 never ran
}

TEST(CompatLinuxcnc, IniAndHalValuesComeFromTheMachineFile) {
  TempDir dir;
  const auto m = lcnc_machine(dir,
                              "[ini.PROBE]\nFEED_FAST = 400\nBALL_DIAMETER = 2.0\n"
                              "[hal]\n\"motion.probe-input\" = false\n\"probe.offset\" = 0.25\n");
  const auto p = dir.write("p.ngc",
                           "(debug, #<_ini[probe]feed_fast> #<_ini[PROBE]BALL_DIAMETER>)\n"
                           "(debug, #<_hal[motion.probe-input]> #<_hal[probe.offset]>)\nM2\n");
  const auto r = run_with_report(dir, p, {"-m", m.string()});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  EXPECT_EQ(r.report["messages"][0], " 400.000000 2.000000");
  EXPECT_EQ(r.report["messages"][1], " 0.000000 0.250000");
}

TEST(CompatLinuxcnc, MissingIniValueNamesTheTableAndKeyToAdd) {
  TempDir dir;
  const auto m = lcnc_machine(dir);
  const auto p = dir.write("p.ngc", "#1 = #<_ini[toolsensor]z>\nM2\n");
  const auto r = run_with_report(dir, p, {"-m", m.string()});
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.exit.code, 1);
  const std::string msg = r.alarm()["message"];
  EXPECT_NE(msg.find("[ini.TOOLSENSOR] Z = value"), std::string::npos) << msg;
  const auto p2 = dir.write("p2.ngc", "#1 = #<_hal[probe.x]>\nM2\n");
  const auto r2 = run_with_report(dir, p2, {"-m", m.string()});
  EXPECT_NE(r2.alarm()["message"].get<std::string>().find("[hal] table: \"probe.x\" = value"),
            std::string::npos)
      << r2.alarm().dump();
}

TEST(CompatLinuxcnc, M70M72RestoreAndM73RestoresOnReturn) {
  TempDir dir;
  const auto m = lcnc_machine(dir);
  // The sub switches to G20 G91 F10 and G55; M73 puts G21 G90 F500 G54 back.
  const auto p = dir.write("p.ngc",
                           "o<imperial> sub\nM73\nG20 G91 G55 F10\no<imperial> endsub\n"
                           "G21 G90 G54 F500\n"
                           "o<imperial> call\n"
                           "(debug, #<_metric> #<_absolute> #<_feed> #5220)\n"
                           "M70\nG20 G91 F7\nM72\n"
                           "(debug, #<_metric> #<_absolute> #<_feed>)\n"
                           "M70\nM71\nM72\nM2\n");
  const auto r = run_with_report(dir, p, {"-m", m.string()});
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.report["messages"][0], " 1.000000 1.000000 500.000000 1.000000");
  EXPECT_EQ(r.report["messages"][1], " 1.000000 1.000000 500.000000");
  // M72 after M71: nothing saved at this level, an alarm (line 14).
  EXPECT_EQ(r.exit.code, 1);
  EXPECT_EQ(r.alarm()["line"], 14);
}

TEST(CompatLinuxcnc, LogAndProbeFilesAreWrittenAndNamed) {
  TempDir dir;
  const auto m = lcnc_machine(dir);
  const auto scene = dir.write("s.toml",
                               "[[trigger]]\nsignal = \"X0.4\"\naxis = \"Z\"\nat = -3.0\n"
                               "direction = \"decreasing\"\n");
  const auto p = dir.write("p.ngc",
                           "(PROBEOPEN probe.txt)\n(LOGOPEN,run.log)\n"
                           "G21 G90 G0 X1 Y2 Z0\nG38.2 Z-10 F100\n"
                           "(LOG,touched at #5063)\n(PROBECLOSE)\n(LOGCLOSE)\nM2\n");
  const auto logs = dir.path / "logs";
  std::filesystem::create_directory(logs);
  const auto r = run_with_report(
      dir, p, {"-m", m.string(), "--scene", scene.string(), "--log-dir", logs.string()});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  const std::string probe = read_file(logs / "probe.txt");
  // The latch: Z -3 (the trigger) within the servo's lag at F100.
  EXPECT_EQ(probe.substr(0, 23), "1.000000 2.000000 -3.00");
  EXPECT_EQ(std::count(probe.begin(), probe.end(), ' '), 8);  // 9 numbers: X Y Z A B C U V W
  const std::string log = read_file(logs / "run.log");
  EXPECT_EQ(log.substr(0, 15), "touched at -3.0");
  EXPECT_EQ(log.back(), '\n');
  const std::string said = message_text(r);
  EXPECT_NE(said.find("probe log 'probe.txt': 1 lines written"), std::string::npos) << said;
  EXPECT_NE(said.find("log 'run.log': 1 lines written"), std::string::npos) << said;
}

TEST(CompatLinuxcnc, MissingNamedSubListsTheFoldersSearched) {
  TempDir dir;
  const auto m = lcnc_machine(dir);
  std::filesystem::create_directory(dir.path / "subs");
  const auto p = dir.write("p.ngc", "o<probe_corner> call [1]\nM2\n");
  const auto r = run_with_report(dir, p, {"-m", m.string(), "-I", (dir.path / "subs").string()});
  ASSERT_TRUE(r.report_ok) << r.err;
  const std::string msg = r.alarm()["message"];
  EXPECT_NE(msg.find("no probe_corner.ngc in the folders searched: '" +
                     (dir.path / "subs").string() + "'"),
            std::string::npos)
      << msg;
}

// rs274 (LinuxCNC 2.9) refuses a G38.2/G38.4 whose end point is its start
// point and nothing shorter than that: 0.0001 mm runs.
TEST(CompatLinuxcnc, G38TooShortRefusedAsRs274RefusesIt) {
  TempDir dir;
  const auto m = lcnc_machine(dir);
  const auto p =
      dir.write("p.ngc", "G21 G90 G0 Z0\nG38.3 Z-0.0001 F100\nG38.2 Z-0.0002 F100\nM2\n");
  const auto r = run_with_report(dir, p, {"-m", m.string()});
  ASSERT_TRUE(r.report_ok) << r.err;
  EXPECT_EQ(r.alarm()["key"], "probe_no_contact");  // ran, no contact: the move was not refused
  EXPECT_EQ(r.alarm()["line"], 3);
  const auto p2 = dir.write("p2.ngc", "G21 G90 G0 Z0\nG38.2 Z0 F100\nM2\n");
  const auto r2 = run_with_report(dir, p2, {"-m", m.string()});
  EXPECT_EQ(r2.alarm()["number"], 9084);  // "Start point too close to probe point"
}

}  // namespace
}  // namespace skipnc::test
