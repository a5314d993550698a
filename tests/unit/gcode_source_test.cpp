#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "gcode/ast.hpp"
#include "gcode/parser.hpp"
#include "gcode/source.hpp"

namespace skipnc::gcode {
namespace {

namespace fs = std::filesystem;

struct Got {
  std::string text;
  std::uint64_t offset = 0;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  friend bool operator==(const Got&, const Got&) = default;
};

std::ostream& operator<<(std::ostream& os, const Got& g) {
  return os << "{\"" << g.text << "\" @" << g.offset << " " << g.line << ":" << g.column << "}";
}

// Reads every block; an error is recorded as a block "!<alarm key>".
std::vector<Got> read_all(Source& src) {
  std::vector<Got> out;
  RawBlock b;
  for (int guard = 0; guard < 1000000; ++guard) {
    auto r = src.next(b);
    if (!r) {
      out.push_back({"!" + std::string(alarm_key(r.error().id)), 0, r.error().loc.line,
                     r.error().loc.column});
      continue;
    }
    if (!*r) break;
    out.push_back({std::string(b.text), b.offset, b.line, b.column});
  }
  return out;
}

std::vector<Got> read_string(std::string text, SourceLimits limits = {}) {
  auto src = make_string_source("mem.nc", std::move(text), limits);
  return read_all(*src);
}

// A file in a fresh temporary directory, removed with the fixture.
class TempDir {
 public:
  TempDir() {
    const auto base = fs::temp_directory_path();
    for (int i = 0;; ++i) {
      dir_ = base / ("skipnc_gcode_test_" + std::to_string(::getpid()) + "_" + std::to_string(i));
      if (fs::create_directory(dir_)) break;
    }
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string write(const std::string& name, const std::string& content) const {
    const auto path = (dir_ / name).string();
    std::ofstream f(path, std::ios::binary);
    f << content;
    return path;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  fs::path dir_;
};

std::unique_ptr<Source> open_ok(const std::string& path, SourceLimits limits = {}) {
  auto r = open_file_source(path, "prog.nc", limits);
  EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().detail);
  return r ? std::move(*r) : nullptr;
}

// ------------------------------------------------------------ end of block

TEST(GcodeSource, LinesAndCrLf) {
  const auto got = read_string("G0 X1\nG1 Y2\r\nM30");
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0], (Got{"G0 X1", 0, 1, 1}));
  EXPECT_EQ(got[1], (Got{"G1 Y2", 6, 2, 1}));
  EXPECT_EQ(got[2], (Got{"M30", 13, 3, 1}));
}

TEST(GcodeSource, EmptyLinesAreEmptyBlocks) {
  EXPECT_TRUE(read_string("").empty());
  const auto got = read_string("\n\r\nG0\n");
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0], (Got{"", 0, 1, 1}));
  EXPECT_EQ(got[1], (Got{"", 1, 2, 1}));
  EXPECT_EQ(got[2], (Got{"G0", 3, 3, 1}));
}

TEST(GcodeSource, SemicolonEndsBlock) {
  const auto got = read_string("G0;G1 X2;M3\nM30");
  ASSERT_EQ(got.size(), 4u);
  EXPECT_EQ(got[0], (Got{"G0", 0, 1, 1}));
  EXPECT_EQ(got[1], (Got{"G1 X2", 3, 1, 4}));
  EXPECT_EQ(got[2], (Got{"M3", 9, 1, 10}));
  EXPECT_EQ(got[3], (Got{"M30", 12, 2, 1}));
}

TEST(GcodeSource, SemicolonBeforeLineEndIsOneEndOfBlock) {
  // Listings are often written with the EOB shown as ';' at the end of lines.
  const auto got = read_string("O1 ;\nG0 X1;\r\nM30 ;");
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0], (Got{"O1 ", 0, 1, 1}));
  EXPECT_EQ(got[1], (Got{"G0 X1", 5, 2, 1}));
  EXPECT_EQ(got[2], (Got{"M30 ", 13, 3, 1}));
  // ';' then an empty line is still an empty block.
  const auto two = read_string("G0;\n\nG1");
  ASSERT_EQ(two.size(), 3u);
  EXPECT_EQ(two[1], (Got{"", 4, 2, 1}));
}

// Lines of every length around the width the scanner reads at a time (16
// bytes), one end of block anywhere in them, and a last line without an end.
TEST(GcodeSource, LinesOfEveryLengthAndEndOfBlockPlace) {
  std::string text;
  std::vector<Got> want;
  std::vector<Got> want_ngc;  // ';' is no end of block
  std::uint32_t line = 1;
  for (std::size_t len = 0; len <= 40; ++len) {
    std::string body(len, 'X');
    for (std::size_t k = 0; k < len; ++k) body[k] = static_cast<char>('A' + k % 26);
    const auto at = static_cast<std::uint64_t>(text.size());
    want_ngc.push_back({body, at, line, 1});
    if (len >= 2 && len % 3 == 0) {
      body[len / 2] = ';';
      want_ngc.back().text = body;
      want.push_back({body.substr(0, len / 2), at, line, 1});
      want.push_back({body.substr(len / 2 + 1), at + len / 2 + 1, line,
                      static_cast<std::uint32_t>(len / 2 + 2)});
    } else {
      want.push_back({body, at, line, 1});
    }
    text += body + (len == 40 ? "" : "\n");
    ++line;
  }
  EXPECT_EQ(read_string(text), want);
  EXPECT_EQ(read_string(text, SourceLimits{.semicolon_ends_block = false}), want_ngc);
}

TEST(GcodeSource, SemicolonInCommentDoesNotEndBlock) {
  const auto got = read_string("G0 (A;B) X1;(C;D)\nM30");
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0].text, "G0 (A;B) X1");
  EXPECT_EQ(got[1], (Got{"(C;D)", 12, 1, 13}));
  EXPECT_EQ(got[2].text, "M30");
  // A newline ends the block even in an unclosed comment: the parser reports it.
  const auto open = read_string("G0 (A;B\nG1");
  ASSERT_EQ(open.size(), 2u);
  EXPECT_EQ(open[0].text, "G0 (A;B");
  EXPECT_EQ(open[1], (Got{"G1", 8, 2, 1}));
}

TEST(GcodeSource, PercentIsLeftToTheParser) {
  const auto got = read_string("%\nO1\nM30\n%\n");
  ASSERT_EQ(got.size(), 4u);
  EXPECT_EQ(got[0].text, "%");
  EXPECT_EQ(got[3].text, "%");
}

TEST(GcodeSource, ByteOrderMarkIsSkipped) {
  const auto got = read_string("\xEF\xBB\xBFG0\nG1");
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0], (Got{"G0", 3, 1, 1}));
}

TEST(GcodeSource, NulBytesAreCharacters) {
  const std::string text("G0\0X1\nG1", 8);
  const auto got = read_string(text);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].text, std::string("G0\0X1", 5));
  Block b;
  const auto r = parse_block(got[0].text, SourceLoc{"mem.nc", 1, 1}, 0, b);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().id, AlarmId::kIllegalChar);
  EXPECT_EQ(r.error().loc.column, 3u);
}

// ------------------------------------------------------------ long blocks

TEST(GcodeSource, LongBlockIsReportedOnceAndSkipped) {
  SourceLimits limits;
  limits.max_block_bytes = 16;
  const std::string text = "G0\n" + std::string(100, 'X') + "\nG1 X2;" + std::string(17, 'Y') +
                           ";" + std::string(16, 'Z') + "\nM30";
  const auto got = read_string(text, limits);
  ASSERT_EQ(got.size(), 6u);
  EXPECT_EQ(got[0].text, "G0");
  EXPECT_EQ(got[1], (Got{"!block_too_long", 0, 2, 1}));
  EXPECT_EQ(got[2], (Got{"G1 X2", 104, 3, 1}));
  EXPECT_EQ(got[3], (Got{"!block_too_long", 0, 3, 7}));
  EXPECT_EQ(got[4].text, std::string(16, 'Z'));  // exactly the limit is fine
  EXPECT_EQ(got[4].column, 25u);
  EXPECT_EQ(got[5], (Got{"M30", 145, 4, 1}));
}

TEST(GcodeSource, LongBlockErrorNamesTheSource) {
  SourceLimits limits;
  limits.max_block_bytes = 4;
  auto src = make_string_source("long.nc", "G01 X1", limits);
  RawBlock b;
  auto r = src->next(b);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().id, AlarmId::kBlockTooLong);
  EXPECT_EQ(r.error().loc, (SourceLoc{"long.nc", 1, 1}));
  auto end = src->next(b);
  ASSERT_TRUE(end);
  EXPECT_FALSE(*end);
}

// ------------------------------------------------------------ seek and tell

void expect_seek_round_trip(Source& src) {
  std::vector<SourcePos> pos;
  std::vector<Got> blocks;
  RawBlock b;
  for (;;) {
    pos.push_back(src.tell());
    auto r = src.next(b);
    ASSERT_TRUE(r) << r.error().detail;
    if (!*r) break;
    blocks.push_back({std::string(b.text), b.offset, b.line, b.column});
    EXPECT_EQ(pos.back().offset, b.offset);
    EXPECT_EQ(pos.back().line, b.line);
    EXPECT_EQ(pos.back().column, b.column);
  }
  ASSERT_GE(blocks.size(), 3u);
  // Back to each block, in an order that jumps around.
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const std::size_t i = (k * 7) % blocks.size();
    ASSERT_TRUE(src.seek(pos[i]));
    ASSERT_TRUE(src.next(b).value());
    EXPECT_EQ((Got{std::string(b.text), b.offset, b.line, b.column}), blocks[i]) << "block " << i;
    // And the one after it follows.
    if (i + 1 < blocks.size()) {
      ASSERT_TRUE(src.next(b).value());
      EXPECT_EQ(std::string(b.text), blocks[i + 1].text);
    }
  }
  // At the end: nothing more.
  ASSERT_TRUE(src.seek(pos.back()));
  EXPECT_FALSE(src.next(b).value());
}

std::string sample_program() {
  std::string text = "%\nO1000 (SAMPLE; WITH SEMICOLON)\r\n";
  for (int i = 1; i <= 60; ++i) {
    text += "N" + std::to_string(i * 10) + " G1 X" + std::to_string(i) + ".5 Y-" +
            std::to_string(i % 7) + ";#1=#1+1\n";
    if (i % 9 == 0) text += "\n(COMMENT LINE " + std::to_string(i) + ")\r\n";
  }
  text += "M30\n%";
  return text;
}

TEST(GcodeSource, StringSeekTellRoundTrip) {
  auto src = make_string_source("mem.nc", sample_program());
  EXPECT_EQ(src->name(), "mem.nc");
  EXPECT_EQ(src->tell().offset, 0u);
  EXPECT_EQ(src->tell().line, 1u);
  EXPECT_EQ(src->tell().column, 1u);
  expect_seek_round_trip(*src);
}

TEST(GcodeSource, FileSeekTellRoundTrip) {
  TempDir dir;
  const auto path = dir.write("prog.nc", sample_program());
  // A small window makes the file source slide and re-read.
  for (std::size_t window : {std::size_t{64}, std::size_t{100}, std::size_t{1} << 20}) {
    SourceLimits limits;
    limits.window_bytes = window;
    limits.max_block_bytes = 48;
    auto src = open_ok(path, limits);
    ASSERT_TRUE(src);
    EXPECT_EQ(src->name(), "prog.nc");
    expect_seek_round_trip(*src);
  }
}

TEST(GcodeSource, SeekPastEndFails) {
  auto src = make_string_source("mem.nc", "G0\nG1\n");
  auto r = src->seek(SourcePos{100, 9, 1});
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().id, AlarmId::kFileAccess);
  EXPECT_TRUE(src->seek(SourcePos{6, 3, 1}));
  RawBlock b;
  EXPECT_FALSE(src->next(b).value());
}

// ------------------------------------------------------------ files

TEST(GcodeSource, FileGivesTheSameBlocksAsMemory) {
  TempDir dir;
  // Random text with all the characters the scanner cares about.
  std::mt19937 rng(12345);
  const std::string alphabet = "G01 X.-#[]();;\n\n\r\nABC%";
  std::string text;
  for (int i = 0; i < 20000; ++i) text += alphabet[rng() % alphabet.size()];
  const auto path = dir.write("random.nc", text);
  for (std::size_t max_block : {std::size_t{8}, std::size_t{30}, std::size_t{1000}}) {
    SourceLimits limits;
    limits.max_block_bytes = max_block;
    const auto expected = read_string(text, limits);
    for (std::size_t window : {std::size_t{1}, std::size_t{37}, std::size_t{4096}}) {
      limits.window_bytes = window;
      auto src = open_ok(path, limits);
      ASSERT_TRUE(src);
      EXPECT_EQ(read_all(*src), expected) << "max block " << max_block << " window " << window;
    }
  }
}

TEST(GcodeSource, FileLongLineInBoundedWindow) {
  TempDir dir;
  const std::string text = "G0\n" + std::string(1 << 20, 'X') + ";G1\nM30\n";
  const auto path = dir.write("long.nc", text);
  SourceLimits limits;
  limits.window_bytes = 4096;
  limits.max_block_bytes = 256;
  auto src = open_ok(path, limits);
  ASSERT_TRUE(src);
  const auto got = read_all(*src);
  ASSERT_EQ(got.size(), 4u);
  EXPECT_EQ(got[0].text, "G0");
  EXPECT_EQ(got[1], (Got{"!block_too_long", 0, 2, 1}));
  EXPECT_EQ(got[2], (Got{"G1", 3 + (1u << 20) + 1, 2, (1u << 20) + 2}));
  EXPECT_EQ(got[3], (Got{"M30", 3 + (1u << 20) + 4, 3, 1}));
}

TEST(GcodeSource, MissingFileIsFileAccess) {
  TempDir dir;
  auto r = open_file_source(dir.path("nope.nc"), "nope.nc");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().id, AlarmId::kFileAccess);
  EXPECT_NE(r.error().detail.find("nope.nc"), std::string::npos);
  auto d = open_file_source(fs::temp_directory_path().string(), "tmp");
  ASSERT_FALSE(d);
  EXPECT_EQ(d.error().id, AlarmId::kFileAccess);
}

TEST(GcodeSource, BinaryFileDoesNotCrash) {
  TempDir dir;
  std::mt19937 rng(7);
  std::string bytes(200000, '\0');
  for (char& c : bytes) c = static_cast<char>(rng() % 256);
  const auto path = dir.write("binary.bin", bytes);
  SourceLimits limits;
  limits.window_bytes = 1000;
  limits.max_block_bytes = 300;
  auto src = open_ok(path, limits);
  ASSERT_TRUE(src);
  RawBlock raw;
  Block block;
  int blocks = 0;
  int parse_errors = 0;
  int too_long = 0;
  for (;;) {
    auto r = src->next(raw);
    if (!r) {
      EXPECT_EQ(r.error().id, AlarmId::kBlockTooLong);
      ++too_long;
      continue;
    }
    if (!*r) break;
    ++blocks;
    if (!parse_block(raw.text, SourceLoc{"binary.bin", raw.line, raw.column}, raw.offset, block))
      ++parse_errors;
  }
  EXPECT_GT(blocks, 100);
  EXPECT_GT(parse_errors, 0);
  RecordProperty("too_long_blocks", too_long);
}

TEST(GcodeSource, FileUtf8BomIsSkipped) {
  TempDir dir;
  const auto path = dir.write("bom.nc", "\xEF\xBB\xBFG0\nG1\n");
  auto src = open_ok(path);
  ASSERT_TRUE(src);
  EXPECT_EQ(src->tell().offset, 3u);
  const auto got = read_all(*src);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0], (Got{"G0", 3, 1, 1}));
  ASSERT_TRUE(src->seek(SourcePos{0, 1, 1}));
  RawBlock b;
  ASSERT_TRUE(src->next(b).value());
  EXPECT_EQ(b.text, "G0");
}

long resident_kb() {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

TEST(GcodeSource, LargeFileStreamsInBoundedMemory) {
  TempDir dir;
  const auto path = dir.path("big.nc");
  constexpr long kBlocks = 800000;  // about 25 MB
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    for (long i = 0; i < kBlocks; ++i) {
      std::fprintf(f, "N%ld G1 X%ld.123 Y-%ld.5 F1000.\n", i, i % 1000, i % 77);
    }
    std::fclose(f);
  }
  ASSERT_GT(fs::file_size(path), 20u << 20);
  const long before = resident_kb();
  auto src = open_ok(path);
  ASSERT_TRUE(src);
  RawBlock raw;
  Block block;
  long count = 0;
  std::string last;
  for (;;) {
    auto r = src->next(raw);
    ASSERT_TRUE(r) << r.error().detail;
    if (!*r) break;
    ++count;
    ASSERT_TRUE(
        parse_block(raw.text, SourceLoc{"big.nc", raw.line, raw.column}, raw.offset, block));
    if (count == kBlocks) last = std::string(raw.text);
  }
  EXPECT_EQ(count, kBlocks);
  EXPECT_EQ(last, "N799999 G1 X999.123 Y-46.5 F1000.");
  EXPECT_EQ(block.n, kBlocks - 1);
  EXPECT_EQ(src->tell().line, static_cast<std::uint32_t>(kBlocks + 1));
  const long after = resident_kb();
  if (before > 0 && after > 0) {
    EXPECT_LT(after - before, 8 * 1024) << "resident memory grew by " << after - before << " kB";
  }
}

}  // namespace
}  // namespace skipnc::gcode
