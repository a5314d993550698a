// Program libraries on the include path: a shop's punched multi-program file
// (%, O9810 ... M99, O9811 ... M99, %) is searched like a folder of O<n>.nc
// files, and PROGRAM NOT FOUND says where it looked.
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

// Two programs in one file, as punched from a control's memory.
constexpr const char* kAllProg =
    "%\n"
    "O9810 (FIRST)\n"
    "#101=#1+1.\n"
    "M98 P9811\n"
    "M99\n"
    "O9811 (SECOND)\n"
    "#102=22.\n"
    "M99\n"
    "%\n";

TEST(ProgramLibrary, AMultiProgramFileInTheIncludeFolderIsSearched) {
  TempDir t;
  fs::create_directories(t.path / "lib");
  t.write("lib/ALL-PROG.TXT", kAllProg);
  const auto prog = t.write("main.nc", "G65 P9810 A4.\n#103=#101+#102\nM30\n");
  const json r = run_report(t, {prog.string(), "-I", (t.path / "lib").string(), "--var", "101",
                                "--var", "102", "--var", "103"});
  ASSERT_EQ(r["status"], "completed") << r.dump();
  // O9810 from the library, and O9811 called from it out of the same file.
  EXPECT_EQ(r["variables"], json::parse(R"({"101": 5.0, "102": 22.0, "103": 27.0})"));
}

TEST(ProgramLibrary, AnIncludeThatNamesAFileMakesItALibrary) {
  TempDir t;
  const auto lib = t.write("shop.prg", kAllProg);
  const auto prog = t.write("main.nc", "M98 P9811\nM30\n");
  const json r = run_report(t, {prog.string(), "-I", lib.string(), "--var", "102"});
  ASSERT_EQ(r["status"], "completed") << r.dump();
  EXPECT_EQ(r["variables"]["102"], 22.0);
}

TEST(ProgramLibrary, AFileNamedAfterTheProgramComesBeforeALibrary) {
  TempDir t;
  fs::create_directories(t.path / "lib");
  t.write("lib/ALL-PROG.TXT", kAllProg);
  t.write("lib/O9811.nc", "O9811\n#102=33.\nM99\n");
  const auto prog = t.write("main.nc", "M98 P9811\nM30\n");
  const json r = run_report(t, {prog.string(), "-I", (t.path / "lib").string(), "--var", "102"});
  EXPECT_EQ(r["variables"]["102"], 33.0);
}

TEST(ProgramLibrary, ProgramNotFoundListsTheFoldersNamesAndLibrariesTried) {
  TempDir t;
  fs::create_directories(t.path / "lib");
  fs::create_directories(t.path / "more");
  t.write("lib/ALL-PROG.TXT", kAllProg);
  t.write("lib/notes.md", "O4321 is not a program file\n");
  const auto prog = t.write("main.nc", "#1=1\nM98 P4321\nM30\n");
  const json r = run_report(
      t, {prog.string(), "-I", (t.path / "lib").string(), "-I", (t.path / "more").string()});
  ASSERT_EQ(r["status"], "alarm");
  EXPECT_EQ(r["alarm"]["number"], 76);  // Fanuc PS0076 PROGRAM NOT FOUND
  EXPECT_EQ(r["alarm"]["line"], 2);
  const std::string m = r["alarm"]["message"].get<std::string>();
  for (const std::string& part :
       {(t.path / "lib").string(), (t.path / "more").string(), std::string("O4321.nc"),
        std::string("4321.nc"), std::string(" O4321,"), std::string("ALL-PROG.TXT")}) {
    EXPECT_NE(m.find(part), std::string::npos) << part << " not in: " << m;
  }
  EXPECT_EQ(m.find("notes.md"), std::string::npos) << m;  // not a program file ending
}

}  // namespace
