// Issue 30, "Strict mode people can use": --strict with --allow CODE and the
// scene's [strict] allow; the protected-move idiom does not warn where the
// program reads the skip variables after checking for a miss (`canon`:
// Truth.CanonDoesNotWarnOnEverySkipVariableRead). Each runs the skipnc
// binary as a user would (the goldens truth/strict_allow,
// strict_allow_from_scene and strict_protected_move hold the report side).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "config/warning_codes.hpp"
#include "support/run_cli.hpp"

namespace skipnc::test {
namespace {

namespace fs = std::filesystem;

// The protected-move idiom as an IF ... GOTO test, then the read: no warning.
TEST(StrictModePeopleCanUse, ProtectedMoveReadAfterTheMissCheckDoesNotWarn) {
  TempDir dir;
  const auto prog = dir.write("p.nc",
                              "G21 G90 G54\nG0 Z10.\nG31 Z-5. F100.\n"
                              "IF [ABS[#5063 + 5.] LT 0.001] GOTO 10\n#3000 = 1 (OBSTRUCTED)\n"
                              "N10 #101 = #5063\nM30\n");
  const std::string err = (dir.path / "err.txt").string();
  const auto r = run_cli({"run", prog.string(), "--strict", "-q"}, err);
  EXPECT_EQ(r.exit_code, 0) << read_file(err);
  EXPECT_EQ(read_file(err).find("skip_missed_read"), std::string::npos) << read_file(err);
}

// --allow with a code no warning has is refused before the run (a typo would
// leave --strict stopping at the warning meant): exit 2, the codes listed.
TEST(StrictModePeopleCanUse, AllowOfAnUnknownCodeIsRefused) {
  TempDir dir;
  const auto prog = dir.write("p.nc", "G0 X1.\nM30\n");
  const std::string err = (dir.path / "err.txt").string();
  for (const char* cmd : {"run", "canon"}) {
    const auto r = run_cli({cmd, prog.string(), "--strict", "--allow", "no_efect"}, err);
    EXPECT_EQ(r.exit_code, 2) << cmd;
    EXPECT_NE(read_file(err).find("no_efect"), std::string::npos) << read_file(err);
    EXPECT_NE(read_file(err).find("no_effect"), std::string::npos) << read_file(err);
  }
  const auto ok = run_cli({"run", prog.string(), "--strict", "--allow", "no_effect", "-q"}, err);
  EXPECT_EQ(ok.exit_code, 0) << read_file(err);
}

// The scene's [strict] allow: a code no warning has is an error at its line
// and column; an allowed warning stays a warning (golden
// truth/strict_allow_from_scene); without the key the same run stops.
TEST(StrictModePeopleCanUse, SceneStrictAllowIsCheckedAndApplied) {
  TempDir dir;
  const fs::path golden = fs::path(SKIPNC_SOURCE_DIR) / "tests/golden/truth";
  const auto prog = golden / "strict_allow_from_scene.nc";
  const auto machine = golden / "strict_allow_from_scene.machine.toml";
  std::string scene = read_file(golden / "strict_allow_from_scene.scene.toml");
  const std::string err = (dir.path / "err.txt").string();
  auto run = [&](const std::string& text) {
    const auto s = dir.write("s.toml", text);
    return run_cli({"run", prog.string(), "-m", machine.string(), "--scene", s.string(), "--strict",
                    "-q"},
                   err)
        .exit_code;
  };
  EXPECT_EQ(run(scene), 0) << read_file(err);
  const std::string key = "allow = [\"probe_length_differs\"]";
  const auto at = scene.find(key);
  ASSERT_NE(at, std::string::npos);
  std::string without = scene;
  without.replace(at, key.size(), "allow = []");
  // Without the key the set-up's warning is an alarm before the first block.
  EXPECT_EQ(run(without), 1);
  EXPECT_NE(read_file(err).find("SN9076"), std::string::npos) << read_file(err);
  EXPECT_NE(read_file(err).find("probe_length_differs"), std::string::npos) << read_file(err);
  std::string typo = scene;
  typo.replace(at, key.size(), "allow = [\"probe_length_differ\"]");
  EXPECT_EQ(run(typo), 2);
  EXPECT_NE(read_file(err).find("s.toml:6:"), std::string::npos) << read_file(err);
  EXPECT_NE(read_file(err).find("probe_length_differ'"), std::string::npos) << read_file(err);
}

// The codes --allow accepts are the codes docs/cli.md's table lists.
TEST(StrictModePeopleCanUse, AllowableCodesAreTheDocumentedWarnings) {
  const std::string doc = read_file(fs::path(SKIPNC_SOURCE_DIR) / "docs/cli.md");
  for (auto code : config::kWarningCodes) {
    EXPECT_NE(doc.find("| `" + std::string(code) + "` |"), std::string::npos) << code;
  }
}

}  // namespace
}  // namespace skipnc::test
