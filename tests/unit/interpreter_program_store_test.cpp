// The program store (src/interpreter/program_store.hpp) without an
// interpreter: called programs by number across files and folders, subs by
// name, the one scan that indexes both, sequence-number lookups, what a
// missing program or sub says, and include folders that cannot be left.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "interpreter/program_store.hpp"
#include "support/run_cli.hpp"

namespace fs = std::filesystem;
using skipnc::AlarmId;
using skipnc::SourceLoc;
using skipnc::gcode::Syntax;
using skipnc::interp::Frame;
using skipnc::interp::ProgramAt;
using skipnc::interp::ProgramStore;
using skipnc::test::TempDir;

namespace {

constexpr SourceLoc kAt{"main.nc", 7, 3};

// A store over the program text `text` (named main.nc), called programs
// looked for in `dirs`.
struct Store {
  std::string text;
  ProgramStore store;
  Store(std::string program, std::vector<std::string> dirs, Syntax syntax = Syntax::kMacroB,
        std::int64_t max_labels = 1000000)
      : text(std::move(program)) {
    ProgramStore::Options o;
    o.main_name = "main.nc";
    o.main_text = &text;
    o.include_dirs = std::move(dirs);
    o.parse.syntax = syntax;
    o.source.semicolon_ends_block = syntax == Syntax::kMacroB;
    o.max_label_index = max_labels;
    auto r = store.open(std::move(o));
    EXPECT_TRUE(r.has_value());
  }
};

// The text of the block at `p.at` in its file.
std::string block_at(const ProgramAt& p) {
  auto s = p.file->src->seek(p.at);
  EXPECT_TRUE(s.has_value());
  skipnc::gcode::RawBlock rb;
  auto more = p.file->src->next(rb);
  EXPECT_TRUE(more.has_value() && *more);
  return std::string(rb.text);
}

TEST(ProgramStore, ProgramsByNumberInTheMainFileFoldersAndLibraries) {
  TempDir t;
  t.write("O100.nc", "O100 (ALONE)\nG1 X1.\nM99\n");
  t.write("O0042.nc", "G0 X42.\nM99\n");  // no O block: run from the top
  t.write("ALL-PROG.TXT", "%\nO9810\nG0 X10.\nM99\nO9811\nG0 X11.\nM99\n%\n");
  Store s("O1\nG0 X0\nM98 P2\nM30\nO2\nG0 X2.\nM99\n", {t.path.string()});

  // O<number>: in the file shown as `file`, at the block `text`.
  auto expect_program = [&](std::int64_t number, const std::string& file, const char* text) {
    auto p = s.store.find_program(number, kAt);
    ASSERT_TRUE(p.has_value()) << p.error().detail;
    EXPECT_EQ(p->file->display, file) << "O" << number;
    EXPECT_EQ(block_at(*p), text) << "O" << number;
  };
  expect_program(2, "main.nc", "G0 X2.");
  expect_program(100, "O100.nc", "G1 X1.");
  expect_program(42, "O0042.nc", "G0 X42.");
  expect_program(9811, "ALL-PROG.TXT", "G0 X11.");
  // Now loaded: found among the loaded files, in the same file object.
  auto second = s.store.find_program(9811, kAt);
  auto first = s.store.find_program(9810, kAt);
  ASSERT_TRUE(first.has_value() && second.has_value());
  EXPECT_EQ(first->file, second->file);
  EXPECT_EQ(block_at(*first), "G0 X10.");
  EXPECT_EQ(s.store.main_file().display, "main.nc");
}

TEST(ProgramStore, TheRunningFileIsSearchedFirst) {
  TempDir t;
  t.write("O7.nc", "O7\nG0 X7.\nM99\nO8\nG0 X8.\nM99\n");
  Store s("O1\nM98 P7\nM30\nO8\nG0 X-8.\nM99\n", {t.path.string()});
  auto seven = s.store.find_program(7, kAt);
  ASSERT_TRUE(seven.has_value());
  // From the main program, O8 is the main file's.
  auto from_main = s.store.find_program(8, kAt);
  ASSERT_TRUE(from_main.has_value());
  EXPECT_EQ(block_at(*from_main), "G0 X-8.");
  // Running inside O7.nc, its own O8 wins.
  Frame f;
  f.file = seven->file;
  f.start = seven->at;
  s.store.frames.push_back(f);
  auto from_o7 = s.store.find_program(8, kAt);
  ASSERT_TRUE(from_o7.has_value());
  EXPECT_EQ(block_at(*from_o7), "G0 X8.");
}

TEST(ProgramStore, OneScanIndexesProgramNumbersAndSubs) {
  Store s(
      "o100 sub\nG1 X1\no100 endsub\n"
      "o<probe_x> sub\nG38.2 X10 F100\no<probe_x> endsub\n"
      "O2000\nG0 X20\nM30\n",
      {}, Syntax::kRs274ngc);
  auto sub = s.store.find_sub("<PROBE_X>", kAt);
  ASSERT_TRUE(sub.has_value()) << sub.error().detail;
  ASSERT_TRUE(sub->has_value());
  EXPECT_EQ(block_at(**sub), "G38.2 X10 F100");
  const auto& file = s.store.main_file();
  EXPECT_TRUE(file.indexed);
  EXPECT_TRUE(file.subs.contains("100"));
  EXPECT_TRUE(file.endsubs.contains("<PROBE_X>"));
  // The same scan found the O numbers: with the text gone (a second scan
  // would find nothing), O2000 and o100 are still known.
  s.text.clear();
  auto number = s.store.find_program(2000, kAt);
  ASSERT_TRUE(number.has_value()) << number.error().detail;
  EXPECT_EQ(block_at(*number), "G0 X20");
  auto numbered_sub = s.store.find_sub("100", kAt);
  ASSERT_TRUE(numbered_sub.has_value() && numbered_sub->has_value());
  EXPECT_EQ(block_at(**numbered_sub), "G1 X1");
}

TEST(ProgramStore, MacroBHasNoSubs) {
  // In Fanuc's syntax an `o<name> sub` line is no O-word: not indexed.
  Store s("O1\no<probe> sub\nG0 X0\no<probe> endsub\nM30\n", {});
  auto sub = s.store.find_sub("<PROBE>", kAt);
  ASSERT_TRUE(sub.has_value());
  EXPECT_FALSE(sub->has_value());
  EXPECT_TRUE(s.store.main_file().programs.contains(1));
}

TEST(ProgramStore, SubsInTheirOwnFileAndTheirErrors) {
  TempDir t;
  t.write("probe_x.ngc", "o<probe_x> sub\nG38.2 X5 F50\no<probe_x> endsub\nM2\n");
  t.write("empty.ngc", "G0 X0\nM2\n");
  t.write("open.ngc", "o<open> sub\nG0 X1\nM2\n");
  Store s("o<probe_x> call\nM2\n", {t.path.string()}, Syntax::kRs274ngc);
  auto sub = s.store.find_sub("<PROBE_X>", kAt);
  ASSERT_TRUE(sub.has_value() && sub->has_value());
  EXPECT_EQ((*sub)->file->display, "probe_x.ngc");
  EXPECT_EQ(block_at(**sub), "G38.2 X5 F50");

  // Found once: the folders are not searched again (the file is open).
  fs::remove(t.path / "probe_x.ngc");
  auto again = s.store.find_sub("<PROBE_X>", kAt);
  ASSERT_TRUE(again.has_value() && again->has_value());
  EXPECT_EQ((*again)->file, (*sub)->file);
  EXPECT_EQ((*again)->at, (*sub)->at);

  auto none = s.store.find_sub("<EMPTY>", kAt);
  ASSERT_FALSE(none.has_value());
  EXPECT_EQ(none.error().id, AlarmId::kProgramNotFound);
  EXPECT_EQ(none.error().detail, "empty.ngc has no o<empty> sub");
  EXPECT_EQ(none.error().loc, kAt);

  auto open = s.store.find_sub("<OPEN>", kAt);
  ASSERT_FALSE(open.has_value());
  EXPECT_EQ(open.error().id, AlarmId::kOwordFlow);
  EXPECT_EQ(open.error().detail, "o<open> sub in open.ngc has no o<open> endsub");
}

TEST(ProgramStore, AMissingSubListsTheFoldersSearched) {
  TempDir a, b;
  Store s("o<gone> call\nM2\n", {a.path.string(), b.path.string()}, Syntax::kRs274ngc);
  auto sub = s.store.find_sub("<GONE>", kAt);
  ASSERT_TRUE(sub.has_value());
  EXPECT_FALSE(sub->has_value());
  EXPECT_EQ(s.store.sub_not_found("<GONE>"),
            "no o<gone> sub: not in main.nc, and no gone.ngc in the folders searched: '" +
                a.path.string() + "' '" + b.path.string() + "' (a folder is added with -I)");
  EXPECT_EQ(s.store.sub_not_found("12"), "no o12 sub: not in main.nc");
}

TEST(ProgramStore, AMissingProgramSaysWhereItLooked) {
  TempDir t;
  t.write("LIB.TXT", "%\nO9810\nM99\n%\n");
  Store s("O1\nM98 P555\nM30\n", {t.path.string()});
  auto p = s.store.find_program(555, kAt);
  ASSERT_FALSE(p.has_value());
  EXPECT_EQ(p.error().id, AlarmId::kProgramNotFound);
  EXPECT_EQ(p.error().loc, kAt);
  EXPECT_EQ(p.error().detail,
            "program O555 not found: looked in the programs loaded, then in '" + t.path.string() +
                "' for O555.nc O555.NC o555.nc 555.nc O555 O0555.nc O0555, and for O555 inside "
                "LIB.TXT");
}

TEST(ProgramStore, IncludeFoldersCannotBeLeftThroughLinks) {
  TempDir t;
  const fs::path inc = t.path / "inc";
  const fs::path outside = t.path / "outside";
  fs::create_directories(inc);
  fs::create_directories(outside);
  t.write("outside/O300.nc", "O300\nG0 X300.\nM99\n");
  t.write("outside/secret.ngc", "o<secret> sub\nG0 X1\no<secret> endsub\n");
  fs::create_symlink(outside / "O300.nc", inc / "O300.nc");
  fs::create_symlink(outside / "secret.ngc", inc / "secret.ngc");

  Store fanuc("O1\nM98 P300\nM30\n", {inc.string()});
  auto p = fanuc.store.find_program(300, kAt);
  ASSERT_FALSE(p.has_value());
  EXPECT_EQ(p.error().id, AlarmId::kProgramNotFound);
  EXPECT_EQ(p.error().detail,
            "program O300: '" + (inc / "O300.nc").string() + "' leads outside the include folder");

  Store ngc("o<secret> call\nM2\n", {inc.string()}, Syntax::kRs274ngc);
  auto sub = ngc.store.find_sub("<SECRET>", kAt);
  ASSERT_FALSE(sub.has_value());
  EXPECT_EQ(sub.error().id, AlarmId::kProgramNotFound);
  EXPECT_EQ(sub.error().detail,
            "o<secret>: '" + (inc / "secret.ngc").string() + "' leads outside the include folder");
}

// Sequence numbers: the first N n after the block asked from, else the
// first of the program; the same with the full index and with the bounded
// one (limits.max_label_index passed).
void check_labels(std::int64_t max_labels) {
  const std::string text = "O1\nN10 G0 X1\nN20 G0 X2\nN10 G0 X3\nM30\nO2\nN10 G0 X9\nM99\n";
  Store s(text, {}, Syntax::kMacroB, max_labels);
  const Frame& main = s.store.frames.front();
  const auto n20 = static_cast<std::uint64_t>(text.find("N20"));
  const auto second_n10 = static_cast<std::uint64_t>(text.find("N10 G0 X3"));

  auto after_n20 = s.store.find_label(main, 10, n20, kAt);
  ASSERT_TRUE(after_n20.has_value());
  EXPECT_EQ(after_n20->offset, second_n10);
  // From the last N10, forward finds none in O1 (O2's N10 is another
  // program): back to the first.
  auto wrapped = s.store.find_label(main, 10, second_n10, kAt);
  ASSERT_TRUE(wrapped.has_value());
  EXPECT_EQ(wrapped->offset, text.find("N10 G0 X1"));
  EXPECT_EQ(wrapped->line, 2u);

  auto missing = s.store.find_label(main, 99, 0, kAt);
  ASSERT_FALSE(missing.has_value());
  EXPECT_EQ(missing.error().id, AlarmId::kSequenceNotFound);
  EXPECT_EQ(missing.error().detail, "sequence number N99 not found in this program");
}

TEST(ProgramStore, LabelsWithTheFullIndex) {
  check_labels(1000000);
}

TEST(ProgramStore, LabelsBeyondTheIndexLimit) {
  check_labels(1);
}

}  // namespace
