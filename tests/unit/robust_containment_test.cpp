// Containment (issue 7): a program cannot make skipnc read or write anything
// but what the user named. DPRNT output goes only to the --dprnt file;
// subprogram lookup stays inside the include folders (a program can only
// name a number, and a link that leads outside is refused).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include "support/report_run.hpp"

namespace fs = std::filesystem;

namespace skipnc::test {
namespace {

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    out.insert(fs::relative(e.path(), dir).string());
  }
  return out;
}

constexpr const char* kPrinting =
    "#100=12.5\n"
    "POPEN\n"
    "DPRNT[MEASURED*#100[3]]\n"
    "PCLOS\n"
    "M30\n";

TEST(RobustContainment, DprntWithoutDprntFileWritesNoFile) {
  TempDir dir;
  const auto prog = dir.write("print.nc", kPrinting);
  const auto report = dir.path / "report.json";
  const auto before = listing(dir.path);
  // Run from inside the program's folder, so a file written "beside the
  // program" or "in the current folder" would both show.
  const std::string cmd = "cd " + shell_quote(dir.path.string()) + " && " +
                          shell_quote(SKIPNC_BINARY) + " run print.nc -q --report report.json";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  auto after = listing(dir.path);
  after.erase("report.json");
  EXPECT_EQ(after, before);
  // The line still reaches the user, as a message of the report.
  const auto j = nlohmann::json::parse(read_file(report));
  ASSERT_EQ(j["messages"].size(), 1u);
  EXPECT_EQ(j["messages"][0].get<std::string>(), "MEASURED  12.500");
}

TEST(RobustContainment, DprntWritesOnlyTheNamedFile) {
  TempDir dir;
  TempDir out;
  const auto prog = dir.write("print.nc", kPrinting);
  const auto before = listing(dir.path);
  const auto r = run_with_report(out, prog, {"--dprnt", (out.path / "dprnt.txt").string()});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 0) << r.err;
  EXPECT_EQ(listing(dir.path), before);
  EXPECT_EQ(listing(out.path), (std::set<std::string>{"dprnt.txt", "report.json", "stderr.txt"}));
  EXPECT_EQ(read_file(out.path / "dprnt.txt"), "MEASURED  12.500\n");
}

TEST(RobustContainment, SubprogramOutsideTheIncludeFolderIsNotFound) {
  TempDir dir;
  fs::create_directory(dir.path / "inc");
  fs::create_directory(dir.path / "work");
  // O1234 exists, but beside the include folder, not in it.
  dir.write("O1234.nc", "O1234\n#100=1\nM99\n");
  const auto prog = dir.write("work/main.nc", "M98 P1234\nM30\n");
  const auto r = run_with_report(dir, prog, {"-I", (dir.path / "inc").string(), "--var", "100"});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 1);
  ASSERT_TRUE(r.report_ok);
  EXPECT_EQ(r.alarm().value("code", ""), alarm_code(AlarmId::kProgramNotFound));
  EXPECT_EQ(r.alarm().value("line", 0), 1);
  EXPECT_TRUE(r.report["variables"]["100"].is_null());
}

TEST(RobustContainment, LinkLeadingOutsideTheIncludeFolderIsRefused) {
  TempDir dir;
  fs::create_directory(dir.path / "inc");
  dir.write("secret.nc", "O1234\n#100=1\nM99\n");
  fs::create_symlink(dir.path / "secret.nc", dir.path / "inc" / "O1234.nc");
  const auto prog = dir.write("main.nc", "M98 P1234\nM30\n");
  const auto r = run_with_report(dir, prog, {"-I", (dir.path / "inc").string(), "--var", "100"});
  ASSERT_TRUE(r.exit.exited);
  EXPECT_EQ(r.exit.code, 1);
  ASSERT_TRUE(r.report_ok);
  EXPECT_EQ(r.alarm().value("code", ""), alarm_code(AlarmId::kProgramNotFound));
  EXPECT_TRUE(r.report["variables"]["100"].is_null());
}

TEST(RobustContainment, AProgramCannotNameAPath) {
  // Only digits follow P: a path, a sign, a variable holding a huge number
  // all end in an alarm, never in a file name.
  TempDir dir;
  fs::create_directory(dir.path / "inc");
  dir.write("O1.nc", "O1\n#100=1\nM99\n");
  for (const std::string call : {"M98 P../O1", "M98 P/etc/passwd", "M98 P-1", "M98 (../O1) P",
                                 "#1=99999999\nM98 P#1", "G65 P[0-1]", "M98 P999999999999999"}) {
    const auto prog = dir.write("main.nc", call + "\nM30\n");
    const auto r = run_with_report(dir, prog, {"-I", (dir.path / "inc").string(), "--var", "100"});
    ASSERT_TRUE(r.exit.exited) << call;
    EXPECT_EQ(r.exit.code, 1) << call << ": " << r.err;
    ASSERT_TRUE(r.report_ok) << call;
    EXPECT_EQ(r.status(), "alarm") << call;
    EXPECT_TRUE(r.report["variables"]["100"].is_null()) << call;
  }
}

}  // namespace
}  // namespace skipnc::test
