// Files the user asked to keep are written whole or not at all
// (write_file_atomic: the report, the persistent variables).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/file.hpp"
#include "support/run_cli.hpp"

namespace skipnc {
namespace {

namespace fs = std::filesystem;

TEST(WriteFileAtomic, ReplacesTheFileAndLeavesNoTemporary) {
  test::TempDir dir;
  const fs::path p = dir.path / "out.json";
  { std::ofstream(p) << "old text that is longer than the new one\n"; }
  ASSERT_TRUE(write_file_atomic(p.string(), "{\"a\": 1}\n"));
  EXPECT_EQ(test::read_file(p), "{\"a\": 1}\n");
  EXPECT_FALSE(fs::exists(dir.path / "out.json.tmp"));
  // Empty text is an empty file, not a missing one.
  ASSERT_TRUE(write_file_atomic(p.string(), ""));
  EXPECT_TRUE(fs::exists(p));
  EXPECT_EQ(fs::file_size(p), 0U);
}

TEST(WriteFileAtomic, AFailureNamesTheFileAndLeavesTheOldOneAsItWas) {
  test::TempDir dir;
  // No such folder: nothing can be written.
  const fs::path missing = dir.path / "no" / "such" / "out.json";
  auto r = write_file_atomic(missing.string(), "x");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().id, AlarmId::kFileAccess);
  EXPECT_NE(r.error().detail.find(missing.string() + ".tmp"), std::string::npos)
      << r.error().detail;
  // The target is a folder: the text is written to the temporary file, the
  // rename fails, the temporary is removed and the folder is untouched.
  const fs::path folder = dir.path / "keep";
  fs::create_directory(folder);
  { std::ofstream(folder / "inside.txt") << "kept\n"; }
  r = write_file_atomic(folder.string(), "x");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().id, AlarmId::kFileAccess);
  EXPECT_NE(r.error().detail.find("cannot replace '" + folder.string() + "'"), std::string::npos)
      << r.error().detail;
  EXPECT_FALSE(fs::exists(dir.path / "keep.tmp"));
  EXPECT_EQ(test::read_file(folder / "inside.txt"), "kept\n");
}

}  // namespace
}  // namespace skipnc
