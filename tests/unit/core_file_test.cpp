// Files the user asked to keep are written whole or not at all
// (write_file_atomic: the report, the persistent variables), through a
// temporary file with a unique name ("<name>.tmp-XXXXXX").
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/file.hpp"
#include "support/run_cli.hpp"

namespace skipnc {
namespace {

namespace fs = std::filesystem;

// The names in `dir`, sorted: no temporary file may be left behind.
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(WriteFileAtomic, ReplacesTheFileAndLeavesNoTemporary) {
  test::TempDir dir;
  const fs::path p = dir.path / "out.json";
  { std::ofstream(p) << "old text that is longer than the new one\n"; }
  ASSERT_TRUE(write_file_atomic(p.string(), "{\"a\": 1}\n"));
  EXPECT_EQ(test::read_file(p), "{\"a\": 1}\n");
  EXPECT_EQ(names_in(dir.path), std::vector<std::string>{"out.json"});
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
  EXPECT_NE(r.error().detail.find("'" + missing.string() + "'"), std::string::npos)
      << r.error().detail;
  // The target is a folder: it is not a regular file, so it would be written
  // in place, which the system refuses; no temporary file is made and the
  // folder is untouched. (Before, the text went to "keep.tmp" and the rename
  // failed.)
  const fs::path folder = dir.path / "keep";
  fs::create_directory(folder);
  { std::ofstream(folder / "inside.txt") << "kept\n"; }
  r = write_file_atomic(folder.string(), "x");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().id, AlarmId::kFileAccess);
  EXPECT_NE(r.error().detail.find("cannot write '" + folder.string() + "'"), std::string::npos)
      << r.error().detail;
  EXPECT_EQ(names_in(dir.path), std::vector<std::string>{"keep"});
  EXPECT_EQ(test::read_file(folder / "inside.txt"), "kept\n");
}

}  // namespace
}  // namespace skipnc
