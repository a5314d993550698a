// Custom macro B and the files around a run, as a user meets them through the
// skipnc command: the DPRNT file (--dprnt), the persistent variables
// #500-#999 (machine file), and subprogram lookup on the include path.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/report_run.hpp"
#include "support/run_cli.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using skipnc::test::read_file;
using skipnc::test::run_cli;
using skipnc::test::run_report;
using skipnc::test::TempDir;

namespace {

std::string mill3_with(const std::string& extra) {
  return read_file(fs::path(SKIPNC_SOURCE_DIR) / "data" / "machines" / "mill3.toml") + "\n" + extra;
}

TEST(MacroDprnt, LinesBetweenPopenAndPclosGoToTheNamedFileOnly) {
  TempDir t;
  const auto prog = t.write("p.nc",
                            "#1=1.5\n"
                            "DPRNT[BEFORE*POPEN]\n"
                            "POPEN\n"
                            "DPRNT[A#1[32]]\n"
                            "DPRNT[B#2[30]]\n"
                            "PCLOS\n"
                            "DPRNT[AFTER]\n"
                            "M30\n");
  const fs::path out = t.path / "out" / "probe.txt";
  fs::create_directories(out.parent_path());
  const json r = run_report(t, {prog.string(), "--dprnt", out.string()});
  EXPECT_EQ(r["status"], "completed");
  EXPECT_EQ(read_file(out), "A 1.50\nB 0\n");
  // Every line is also a message, in order.
  EXPECT_EQ(r["messages"], json::array({"BEFORE POPEN", "A 1.50", "B 0", "AFTER"}));
  // Written whole by a rename: nothing else is left in the folder.
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(out.parent_path())) {
    names.push_back(e.path().filename().string());
  }
  EXPECT_EQ(names, std::vector<std::string>{"probe.txt"});
}

TEST(MacroDprnt, NoFileWithoutPopenNorWithoutTheOption) {
  TempDir t;
  const auto no_popen = t.write("a.nc", "DPRNT[X]\nM30\n");
  const fs::path out = t.path / "out.txt";
  run_report(t, {no_popen.string(), "--dprnt", out.string()});
  EXPECT_FALSE(fs::exists(out));
  // POPEN without --dprnt: the lines are messages, no file appears anywhere.
  const auto popen = t.write("b.nc", "POPEN\nDPRNT[HELLO]\nPCLOS\nM30\n");
  const json r = run_report(t, {popen.string()});
  EXPECT_EQ(r["messages"], json::array({"HELLO"}));
  for (const auto& e : fs::directory_iterator(t.path)) {
    EXPECT_NE(e.path().extension(), ".txt") << e.path();
  }
}

TEST(MacroDprnt, FileIsWrittenWhenTheProgramEndsInAnAlarm) {
  TempDir t;
  const auto prog = t.write("p.nc", "POPEN\nDPRNT[FIRST]\n#3000=1(STOP)\nDPRNT[NEVER]\nM30\n");
  const fs::path out = t.path / "out.txt";
  const json r = run_report(t, {prog.string(), "--dprnt", out.string()});
  EXPECT_EQ(r["status"], "alarm");
  EXPECT_EQ(r["alarm"]["number"], 3001);
  EXPECT_EQ(read_file(out), "FIRST\n");
}

TEST(MacroPersistent, Vars500To999AreKeptAcrossRunsAndCommonsAreNot) {
  TempDir t;
  const fs::path store = t.path / "macro_vars.txt";
  const auto machine =
      t.write("m.toml", "persistent_variables = \"" + store.string() + "\"\n" + mill3_with(""));
  const auto first = t.write("first.nc", "#500=1.25\n#999=-7\n#100=3\nM30\n");
  json r = run_report(t, {first.string(), "-m", machine.string()});
  ASSERT_EQ(r["status"], "completed") << r.dump();
  EXPECT_TRUE(fs::exists(store));
  EXPECT_FALSE(fs::exists(store.string() + ".tmp"));
  const auto second = t.write("second.nc", "#501=#500*2\nM30\n");
  r = run_report(t, {second.string(), "-m", machine.string(), "--var", "500", "--var", "501",
                     "--var", "999", "--var", "100", "--var", "502"});
  EXPECT_EQ(r["variables"]["500"], 1.25);
  EXPECT_EQ(r["variables"]["501"], 2.5);
  EXPECT_EQ(r["variables"]["999"], -7.0);
  EXPECT_TRUE(r["variables"]["100"].is_null());  // #100-#199 are cleared at reset
  EXPECT_TRUE(r["variables"]["502"].is_null());
}

TEST(MacroLookup, ProgramFilesOnTheIncludePathByNumber) {
  TempDir t;
  fs::create_directories(t.path / "lib");
  t.write("lib/O9001.nc", "O9001\n#101=1\nM99\n");
  t.write("lib/9002.nc", "#102=2\nM99\n");  // no O block: runs from the top
  t.write("lib/O9003", "O9003\n#103=3\nM99\n");
  t.write("lib/O0012.nc", "O0012\n#104=4\nM99\n");
  const auto prog = t.write("main.nc", "M98 P9001\nM98 P9002\nG65 P9003\nM98 P12\nM30\n");
  const json r = run_report(t, {prog.string(), "-I", (t.path / "lib").string(), "--var", "101",
                                "--var", "102", "--var", "103", "--var", "104"});
  EXPECT_EQ(r["status"], "completed") << r.dump();
  EXPECT_EQ(r["variables"], json::parse(R"({"101": 1.0, "102": 2.0, "103": 3.0, "104": 4.0})"));
}

TEST(MacroLookup, DefaultIncludeFolderIsTheProgramsFolder) {
  TempDir t;
  t.write("O9100.nc", "O9100\n#101=#1\nM99\n");
  const auto prog = t.write("main.nc", "G65 P9100 A7.\nM30\n");
  const json r = run_report(t, {prog.string(), "--var", "101"});
  EXPECT_EQ(r["variables"]["101"], 7.0);
}

TEST(MacroLookup, TheRunningFileComesBeforeTheIncludePath) {
  TempDir t;
  t.write("O9200.nc", "O9200\n#101=2\nM99\n");
  const auto prog = t.write("main.nc", "M98 P9200\nM30\nO9200\n#101=1\nM99\n");
  const json r = run_report(t, {prog.string(), "--var", "101"});
  EXPECT_EQ(r["variables"]["101"], 1.0);
}

TEST(MacroLookup, ALinkLeadingOutsideTheIncludeFolderIsRefused) {
  TempDir t;
  fs::create_directories(t.path / "lib");
  fs::create_directories(t.path / "secret");
  t.write("secret/O9300.nc", "O9300\n#101=1\nM99\n");
  fs::create_symlink(t.path / "secret" / "O9300.nc", t.path / "lib" / "O9300.nc");
  const auto prog = t.write("main.nc", "M98 P9300\nM30\n");
  const json r = run_report(t, {prog.string(), "-I", (t.path / "lib").string(), "--var", "101"});
  EXPECT_EQ(r["status"], "alarm");
  EXPECT_EQ(r["alarm"]["number"], 76);
  EXPECT_EQ(r["alarm"]["line"], 1);
  EXPECT_TRUE(r["variables"]["101"].is_null());
}

TEST(MacroLookup, MissingProgramNamesItsNumberAndTheCallingLine) {
  TempDir t;
  const auto prog = t.write("main.nc", "#1=1\nG65 P4321 A1.\nM30\n");
  const json r = run_report(t, {prog.string()});
  EXPECT_EQ(r["alarm"]["number"], 76);
  EXPECT_EQ(r["alarm"]["line"], 2);
  EXPECT_NE(r["alarm"]["message"].get<std::string>().find("O4321"), std::string::npos);
}

}  // namespace
