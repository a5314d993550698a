#include <gtest/gtest.h>

#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>

#include "gcode/ast.hpp"
#include "gcode/parser.hpp"

namespace skipnc::gcode {
namespace {

constexpr std::string_view kFile = "test.nc";

Result<void> parse(std::string_view text, Block& b, const ParseLimits& limits = {}) {
  return parse_block(text, SourceLoc{kFile, 1, 1}, 0, b, limits);
}

Block parse_ok(std::string_view text) {
  Block b;
  const auto r = parse(text, b);
  EXPECT_TRUE(r.has_value()) << "'" << text << "': " << (r ? "" : r.error().detail);
  return b;
}

Error parse_err(std::string_view text, const ParseLimits& limits = {}) {
  Block b;
  auto r = parse(text, b, limits);
  EXPECT_FALSE(r.has_value()) << "'" << text << "' parsed";
  return r ? Error{} : r.error();
}

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

// The expression as an s-expression: "(+ #1 (* 2 #3))".
std::string show(const Block& b, ExprId id) {
  if (id == kNoExpr) return "none";
  const ExprNode& n = b.nodes.at(static_cast<std::size_t>(id));
  auto bin = [&](const char* op) {
    return std::string("(") + op + " " + show(b, n.a) + " " + show(b, n.b) + ")";
  };
  switch (n.op) {
    case Op::kNumber:
      return num(n.value);
    case Op::kVar:
      return "#" + show(b, n.a);
    case Op::kVarNum:
      return "#" + num(n.value);
    case Op::kNamedVar:
      return "#<" + b.names.at(static_cast<std::size_t>(n.name)) + ">";
    case Op::kNeg:
      return "(neg " + show(b, n.a) + ")";
    case Op::kAdd:
      return bin("+");
    case Op::kSub:
      return bin("-");
    case Op::kMul:
      return bin("*");
    case Op::kDiv:
      return bin("/");
    case Op::kMod:
      return bin("mod");
    case Op::kAnd:
      return bin("and");
    case Op::kOr:
      return bin("or");
    case Op::kXor:
      return bin("xor");
    case Op::kEq:
      return bin("eq");
    case Op::kNe:
      return bin("ne");
    case Op::kGt:
      return bin("gt");
    case Op::kGe:
      return bin("ge");
    case Op::kLt:
      return bin("lt");
    case Op::kLe:
      return bin("le");
    case Op::kPow:
      return bin("**");
    case Op::kFunc: {
      static constexpr const char* kNames[] = {
          "none", "sin", "cos", "tan", "asin", "acos", "atan", "sqrt", "abs",   "round",
          "fix",  "fup", "ln",  "exp", "pow",  "bin",  "bcd",  "adp",  "exists"};
      std::string s = std::string("(") + kNames[static_cast<int>(n.fn)] + " " + show(b, n.a);
      if (n.b != kNoExpr) s += " " + show(b, n.b);
      return s + ")";
    }
  }
  return "?";
}

// Right-hand side of the block's assignment.
std::string rhs(std::string_view text) {
  const Block b = parse_ok(text);
  EXPECT_EQ(b.stmt.kind, StmtKind::kAssign) << text;
  return show(b, b.stmt.rhs);
}

void expect_error(std::string_view text, AlarmId id, std::uint32_t column,
                  const ParseLimits& limits = {}) {
  const Error e = parse_err(text, limits);
  EXPECT_EQ(alarm_key(e.id), alarm_key(id)) << "'" << text << "': " << e.detail;
  EXPECT_EQ(e.loc.column, column) << "'" << text << "': " << e.detail;
  EXPECT_EQ(e.loc.file, kFile);
  EXPECT_EQ(e.loc.line, 1u);
  EXPECT_FALSE(e.detail.empty());
}

// ---------------------------------------------------------------- words

TEST(GcodeParser, SimpleBlock) {
  const Block b = parse_ok("G1 X10.123 Y-3.5 F1000.");
  ASSERT_EQ(b.words.size(), 4u);
  EXPECT_EQ(b.words[0].letter, 'G');
  EXPECT_EQ(b.words[0].value, 1.0);
  EXPECT_FALSE(b.words[0].has_point);
  EXPECT_EQ(b.words[0].column, 1u);
  EXPECT_EQ(b.words[1].letter, 'X');
  EXPECT_EQ(b.words[1].value, 10.123);
  EXPECT_TRUE(b.words[1].has_point);
  EXPECT_EQ(b.words[1].column, 4u);
  EXPECT_EQ(b.words[2].letter, 'Y');
  EXPECT_EQ(b.words[2].value, -3.5);
  EXPECT_EQ(b.words[2].column, 12u);
  EXPECT_EQ(b.words[3].letter, 'F');
  EXPECT_EQ(b.words[3].value, 1000.0);
  EXPECT_TRUE(b.words[3].has_point);
  EXPECT_EQ(b.words[3].column, 18u);
  EXPECT_FALSE(b.words[1].is_expr);
  EXPECT_EQ(b.stmt.kind, StmtKind::kNone);
  EXPECT_FALSE(b.has_n);
  EXPECT_FALSE(b.empty());
}

TEST(GcodeParser, LocationAndOffsetAreKept) {
  Block b;
  ASSERT_TRUE(parse_block("  X1", SourceLoc{"a.nc", 7, 5}, 1234, b));
  EXPECT_EQ(b.loc, (SourceLoc{"a.nc", 7, 5}));
  EXPECT_EQ(b.offset, 1234u);
  EXPECT_EQ(b.words.at(0).column, 7u);
  auto r = parse_block("G0 X", SourceLoc{"a.nc", 7, 5}, 0, b);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().loc, (SourceLoc{"a.nc", 7, 8}));
}

TEST(GcodeParser, NumberForms) {
  const Block b = parse_ok("X-.5 Y+1. F.5 Z10 A0.1 B1234567.891 C-0 U007");
  ASSERT_EQ(b.words.size(), 8u);
  EXPECT_EQ(b.words[0].value, -0.5);
  EXPECT_TRUE(b.words[0].has_point);
  EXPECT_EQ(b.words[1].value, 1.0);
  EXPECT_TRUE(b.words[1].has_point);
  EXPECT_EQ(b.words[2].value, 0.5);
  EXPECT_EQ(b.words[3].value, 10.0);
  EXPECT_FALSE(b.words[3].has_point);
  EXPECT_EQ(b.words[4].value, 0.1);
  EXPECT_EQ(b.words[5].value, 1234567.891);
  EXPECT_EQ(b.words[6].value, 0.0);
  EXPECT_EQ(b.words[7].value, 7.0);
}

TEST(GcodeParser, NumbersRoundCorrectly) {
  EXPECT_EQ(parse_ok("X.000000000000000000000000005").words.at(0).value, 5e-27);
  EXPECT_EQ(parse_ok("X123456789012345").words.at(0).value, 123456789012345.0);
  EXPECT_EQ(parse_ok("X1.23456789012345").words.at(0).value, 1.23456789012345);
  EXPECT_EQ(parse_ok("X0.3").words.at(0).value, 0.3);
  // Leading zeros are not significant digits.
  EXPECT_EQ(parse_ok("X0000000000000000000000001.5").words.at(0).value, 1.5);
}

TEST(GcodeParser, SpacesAreIgnoredInsideWords) {
  const Block b = parse_ok("G 0 1 X 1 0 .5\tY - 2");
  ASSERT_EQ(b.words.size(), 3u);
  EXPECT_EQ(b.words[0].letter, 'G');
  EXPECT_EQ(b.words[0].value, 1.0);
  EXPECT_EQ(b.words[1].value, 10.5);
  EXPECT_EQ(b.words[1].column, 7u);
  EXPECT_EQ(b.words[2].value, -2.0);
  const Block c = parse_ok("G0X1Y2Z3");
  ASSERT_EQ(c.words.size(), 4u);
  EXPECT_EQ(c.words[3].letter, 'Z');
  EXPECT_EQ(c.words[3].column, 7u);
}

// A word written together (read by the parser's quick path) and the same
// word with spaces inside (the general path) are the same word, to the bit.
TEST(GcodeParser, WordsTogetherOrSpreadAreTheSame) {
  const std::pair<std::string_view, std::string_view> pairs[] = {
      {"X-12.345", "X - 12 .345"},
      {"F500.", "F 500 ."},
      {"G1", "G 1"},
      {"y+.5", "Y + .5"},
      {"Z-0", "Z - 0"},
      {"A0.000001", "A 0.000 001"},
      {"B123456789012345", "B 123456789012345 "},
      {"C1234567.891", "C1234567 .891"},
  };
  for (const auto& [together, spread] : pairs) {
    const Block a = parse_ok(together);
    const Block b = parse_ok(spread);
    ASSERT_EQ(a.words.size(), 1u) << together;
    ASSERT_EQ(b.words.size(), 1u) << spread;
    EXPECT_EQ(a.words[0].letter, b.words[0].letter) << together;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a.words[0].value),
              std::bit_cast<std::uint64_t>(b.words[0].value))
        << together;
    EXPECT_EQ(a.words[0].has_point, b.words[0].has_point) << together;
    EXPECT_FALSE(a.words[0].is_expr);
  }
  EXPECT_TRUE(std::signbit(parse_ok("Z-0").words.at(0).value));
  // A letter, then a sign or digit, is a word; a keyword is still one.
  EXPECT_EQ(parse_ok("GOTO 5").stmt.kind, StmtKind::kGoto);
  EXPECT_EQ(parse_ok("X1 2.5").words.at(0).value, 12.5);
  EXPECT_EQ(parse_err("X1.2.5").id, AlarmId::kBadDecimalPoint);
}

TEST(GcodeParser, LowerCaseIsUpperCased) {
  const Block b = parse_ok("n10 g1 x-.5 f.5 (Keep Case)");
  EXPECT_TRUE(b.has_n);
  EXPECT_EQ(b.n, 10);
  ASSERT_EQ(b.words.size(), 3u);
  EXPECT_EQ(b.words[0].letter, 'G');
  EXPECT_EQ(b.words[1].letter, 'X');
  EXPECT_EQ(b.words[2].letter, 'F');
  EXPECT_EQ(b.names.at(0), "Keep Case");
}

TEST(GcodeParser, MacroCallArguments) {
  const Block b = parse_ok("G65P3001X0.Y0.A54.");
  ASSERT_EQ(b.words.size(), 5u);
  EXPECT_EQ(b.words[0].letter, 'G');
  EXPECT_EQ(b.words[0].value, 65.0);
  EXPECT_EQ(b.words[1].letter, 'P');
  EXPECT_EQ(b.words[1].value, 3001.0);
  EXPECT_EQ(b.words[2].letter, 'X');
  EXPECT_TRUE(b.words[2].has_point);
  EXPECT_EQ(b.words[4].letter, 'A');
  EXPECT_EQ(b.words[4].value, 54.0);
  EXPECT_TRUE(b.words[4].has_point);
  EXPECT_EQ(b.words[4].column, 15u);
}

TEST(GcodeParser, WordsWithVariablesAndExpressions) {
  const Block b = parse_ok("X#1 Y-#2 G#10 Z#[#1+1] A[#1+2] B-[#1] C+#3");
  ASSERT_EQ(b.words.size(), 7u);
  for (const Word& w : b.words) EXPECT_TRUE(w.is_expr) << w.letter;
  EXPECT_EQ(show(b, b.words[0].expr), "#1");
  EXPECT_EQ(show(b, b.words[1].expr), "(neg #2)");
  EXPECT_EQ(b.words[2].letter, 'G');
  EXPECT_EQ(show(b, b.words[2].expr), "#10");
  EXPECT_EQ(show(b, b.words[3].expr), "#(+ #1 1)");
  EXPECT_EQ(show(b, b.words[4].expr), "(+ #1 2)");
  EXPECT_EQ(show(b, b.words[5].expr), "(neg #1)");
  EXPECT_EQ(show(b, b.words[6].expr), "#3");
  // Columns: the word at its letter, nodes at their first character.
  EXPECT_EQ(b.words[1].column, 5u);
  EXPECT_EQ(b.nodes.at(static_cast<std::size_t>(b.words[1].expr)).column, 6u);  // '-'
  const ExprNode& var = b.nodes.at(static_cast<std::size_t>(b.words[0].expr));
  EXPECT_EQ(var.column, 2u);  // '#'
  EXPECT_EQ(var.op, Op::kVarNum);
  EXPECT_EQ(var.value, 1.0);
}

TEST(GcodeParser, NamedVariableInWord) {
  const Block b = parse_ok("X#_ABSKP[1] Y#<probe_x> Z2.");
  ASSERT_EQ(b.words.size(), 3u);
  EXPECT_EQ(show(b, b.words[0].expr), "#<_ABSKP[1]>");
  EXPECT_EQ(show(b, b.words[1].expr), "#<PROBE_X>");
  EXPECT_EQ(b.words[2].letter, 'Z');
  EXPECT_EQ(b.words[2].value, 2.0);
}

TEST(GcodeParser, ExpressionAfterAddressNeedsBrackets) {
  // Fanuc: X#1+5 is not X[#1+5]; the '+5' has no address.
  expect_error("X#1+5", AlarmId::kNoAddress, 4);
}

// ---------------------------------------------------------------- head of block

TEST(GcodeParser, EmptyBlock) {
  EXPECT_TRUE(parse_ok("").empty());
  EXPECT_TRUE(parse_ok("   \t").empty());
  const Block b = parse_ok("(only a comment)");
  EXPECT_TRUE(b.empty());
  ASSERT_EQ(b.comments.size(), 1u);
}

TEST(GcodeParser, Percent) {
  const Block b = parse_ok("%");
  EXPECT_TRUE(b.percent);
  EXPECT_FALSE(b.empty());
  EXPECT_TRUE(parse_ok("  % (tape start)").percent);
  expect_error("%G0", AlarmId::kIllegalChar, 2);
  expect_error("G0 %", AlarmId::kIllegalChar, 4);
}

TEST(GcodeParser, ProgramNumber) {
  Block b = parse_ok("O1234 (PART 7)");
  EXPECT_TRUE(b.has_o);
  EXPECT_EQ(b.o, 1234);
  EXPECT_FALSE(b.empty());
  ASSERT_EQ(b.comments.size(), 1u);
  EXPECT_EQ(b.names.at(0), "PART 7");
  b = parse_ok(":0100");
  EXPECT_TRUE(b.has_o);
  EXPECT_EQ(b.o, 100);
  b = parse_ok("o9810");
  EXPECT_EQ(b.o, 9810);
  expect_error("O", AlarmId::kNoValue, 1);
  expect_error("O-1", AlarmId::kBadSign, 2);
  expect_error("O12.5", AlarmId::kBadDecimalPoint, 4);
}

TEST(GcodeParser, SequenceNumber) {
  Block b = parse_ok("N123 G0");
  EXPECT_TRUE(b.has_n);
  EXPECT_EQ(b.n, 123);
  ASSERT_EQ(b.words.size(), 1u);
  EXPECT_EQ(b.words[0].letter, 'G');
  b = parse_ok("N 1 0");
  EXPECT_EQ(b.n, 10);
  EXPECT_TRUE(b.empty());
  expect_error("N", AlarmId::kNoValue, 1);
  expect_error("N-5", AlarmId::kBadSign, 2);
  expect_error("N10.", AlarmId::kBadDecimalPoint, 4);
}

TEST(GcodeParser, BlockDelete) {
  Block b = parse_ok("/N10 G0 X1");
  EXPECT_EQ(b.block_delete, 1);
  EXPECT_TRUE(b.has_n);
  EXPECT_EQ(b.n, 10);
  EXPECT_EQ(b.words.size(), 2u);
  b = parse_ok("/3 X1");
  EXPECT_EQ(b.block_delete, 3);
  b = parse_ok(" / 9 N5");
  EXPECT_EQ(b.block_delete, 9);
  EXPECT_EQ(b.n, 5);
  b = parse_ok("G0");
  EXPECT_EQ(b.block_delete, -1);
  expect_error("/0 X1", AlarmId::kIllegalChar, 2);
  expect_error("G0 /X1", AlarmId::kIllegalChar, 4);
}

// ---------------------------------------------------------------- comments

TEST(GcodeParser, Comments) {
  const Block b = parse_ok("G0 (Move; fast) X1 (MSG, Probe the part)");
  ASSERT_EQ(b.comments.size(), 2u);
  EXPECT_EQ(b.names.at(static_cast<std::size_t>(b.comments[0].text)), "Move; fast");
  EXPECT_EQ(b.comments[0].column, 4u);
  EXPECT_EQ(b.names.at(static_cast<std::size_t>(b.comments[1].text)), "MSG, Probe the part");
  EXPECT_EQ(b.comments[1].column, 20u);
  ASSERT_EQ(b.words.size(), 2u);
  EXPECT_EQ(b.words[1].letter, 'X');
  EXPECT_EQ(parse_ok("()").names.at(0), "");
}

TEST(GcodeParser, CommentErrors) {
  expect_error("G0 (A(B))", AlarmId::kIllegalChar, 6);
  expect_error("G0 (ABC", AlarmId::kIllegalChar, 4);
  expect_error("G0 X1)", AlarmId::kIllegalChar, 6);
}

// ---------------------------------------------------------------- word errors

TEST(GcodeParser, NoValue) {
  expect_error("G0 X", AlarmId::kNoValue, 4);
  expect_error("X Y1", AlarmId::kNoValue, 1);
  expect_error("G0 X.", AlarmId::kNoValue, 5);
  expect_error("X=1", AlarmId::kNoValue, 1);
  expect_error("X#", AlarmId::kNoValue, 2);
}

TEST(GcodeParser, BadSign) {
  expect_error("G0 X-", AlarmId::kBadSign, 5);
  expect_error("X-Y1", AlarmId::kBadSign, 2);
  expect_error("X--1", AlarmId::kBadSign, 2);
  expect_error("X +", AlarmId::kBadSign, 3);
}

TEST(GcodeParser, BadDecimalPoint) {
  expect_error("X1.2.3", AlarmId::kBadDecimalPoint, 5);
  expect_error("G1 X..5", AlarmId::kBadDecimalPoint, 6);
  expect_error("#1=1.2.", AlarmId::kBadDecimalPoint, 7);
}

TEST(GcodeParser, TooManyDigits) {
  EXPECT_EQ(parse_ok("X123456789012345").words.at(0).value, 123456789012345.0);
  expect_error("X1234567890123456", AlarmId::kTooManyDigits, 2);
  expect_error("G1 X1.234567890123456", AlarmId::kTooManyDigits, 5);
  const std::string huge = "G1 X" + std::string(400, '9') + " Y1";
  const Error e = parse_err(huge);
  EXPECT_EQ(e.id, AlarmId::kTooManyDigits);
  EXPECT_EQ(e.loc.column, 5u);
  EXPECT_LT(e.detail.size(), 200u);  // the message quotes an excerpt
  expect_error("N" + std::string(400, '1'), AlarmId::kTooManyDigits, 2);
  expect_error("#" + std::string(400, '1') + "=1", AlarmId::kTooManyDigits, 2);
  ParseLimits tight;
  tight.max_digits = 8;
  expect_error("X123456789", AlarmId::kTooManyDigits, 2, tight);
  Block b;
  EXPECT_TRUE(parse("X12345.678", b, tight));
}

TEST(GcodeParser, NoAddress) {
  expect_error("G0 (A) 10", AlarmId::kNoAddress, 8);
  expect_error("-5", AlarmId::kNoAddress, 1);
  expect_error(".5", AlarmId::kNoAddress, 1);
  expect_error("G0 [1]", AlarmId::kNoAddress, 4);
}

TEST(GcodeParser, IllegalCharacter) {
  expect_error("G0 $X1", AlarmId::kIllegalChar, 4);
  expect_error("G0 X1 &", AlarmId::kIllegalChar, 7);
  expect_error(std::string_view("G0\0X1", 5), AlarmId::kIllegalChar, 3);
  expect_error("G0 \xC3\xA9", AlarmId::kIllegalChar, 4);
  expect_error("G01 X10 ,C2.", AlarmId::kIllegalChar, 9);
  expect_error("G0 ]", AlarmId::kBracketNesting, 4);
  expect_error("G0 =1", AlarmId::kMacroFormat, 4);
}

// ---------------------------------------------------------------- macro statements

TEST(GcodeParser, Assignment) {
  Block b = parse_ok("#1=5");
  EXPECT_EQ(b.stmt.kind, StmtKind::kAssign);
  EXPECT_EQ(show(b, b.stmt.lhs), "#1");
  EXPECT_EQ(show(b, b.stmt.rhs), "5");
  EXPECT_EQ(b.stmt.column, 1u);
  EXPECT_TRUE(b.words.empty());
  EXPECT_FALSE(b.empty());
  b = parse_ok("# 1 0 0 = #1 + 2 * #3 (SET)");
  EXPECT_EQ(show(b, b.stmt.lhs), "#100");
  EXPECT_EQ(show(b, b.stmt.rhs), "(+ #1 (* 2 #3))");
  EXPECT_EQ(b.comments.size(), 1u);
  b = parse_ok("#[#1+1]=2.5");
  EXPECT_EQ(show(b, b.stmt.lhs), "#(+ #1 1)");
  EXPECT_EQ(show(b, b.stmt.rhs), "2.5");
  b = parse_ok("##1=1");
  EXPECT_EQ(show(b, b.stmt.lhs), "##1");
}

TEST(GcodeParser, NamedVariables) {
  Block b = parse_ok("#<tool_len> = #<Probe Z> - 1");
  EXPECT_EQ(show(b, b.stmt.lhs), "#<TOOL_LEN>");
  EXPECT_EQ(show(b, b.stmt.rhs), "(- #<PROBEZ> 1)");
  b = parse_ok("#100=#_ABSKP[1]");
  EXPECT_EQ(show(b, b.stmt.rhs), "#<_ABSKP[1]>");
  b = parse_ok("#_UOFS[#1 + 1] = #_abskp");
  EXPECT_EQ(show(b, b.stmt.lhs), "#<_UOFS[#1+1]>");
  EXPECT_EQ(show(b, b.stmt.rhs), "#<_ABSKP>");
  b = parse_ok("IF [#_ABSKP[2] GT #_ABSKP[1]] GOTO 5");
  EXPECT_EQ(show(b, b.stmt.cond), "(gt #<_ABSKP[2]> #<_ABSKP[1]>)");
  expect_error("#<abc=1", AlarmId::kMacroFormat, 2);
  expect_error("#<>=1", AlarmId::kMacroFormat, 2);
  expect_error("#_=1", AlarmId::kMacroFormat, 2);
  expect_error("#_A[1=1", AlarmId::kBracketNesting, 4);
}

TEST(GcodeParser, BlockMayStartWithSequenceNumber) {
  const Block b = parse_ok("N10 #1=5");
  EXPECT_TRUE(b.has_n);
  EXPECT_EQ(b.n, 10);
  EXPECT_EQ(b.stmt.kind, StmtKind::kAssign);
  EXPECT_EQ(b.stmt.column, 5u);
}

TEST(GcodeParser, WordsAndStatementAreBothKept) {
  const Block b = parse_ok("G0 X1 #1=2");
  EXPECT_EQ(b.words.size(), 2u);
  EXPECT_EQ(b.stmt.kind, StmtKind::kAssign);
  const Block c = parse_ok("#1=2 X5");
  ASSERT_EQ(c.words.size(), 1u);
  EXPECT_EQ(c.words[0].letter, 'X');
  EXPECT_EQ(show(c, c.stmt.rhs), "2");
}

TEST(GcodeParser, Precedence) {
  EXPECT_EQ(rhs("#1 = 1 + 2 * 3 - 4 / 5"), "(- (+ 1 (* 2 3)) (/ 4 5))");
  EXPECT_EQ(rhs("#1 = #2 OR #3 AND #4"), "(or #2 (and #3 #4))");
  EXPECT_EQ(rhs("#1 = #2 MOD 3 + 1"), "(+ (mod #2 3) 1)");
  EXPECT_EQ(rhs("#1 = 1 XOR 2 + 3"), "(+ (xor 1 2) 3)");
  EXPECT_EQ(rhs("#1 = 8 / 4 / 2"), "(/ (/ 8 4) 2)");
  EXPECT_EQ(rhs("#1 = 1 - 2 - 3"), "(- (- 1 2) 3)");
  EXPECT_EQ(rhs("#1 = [1 + 2] * 3"), "(* (+ 1 2) 3)");
  EXPECT_EQ(rhs("#1 = #2 + 1 EQ #3 * 2"), "(eq (+ #2 1) (* #3 2))");
  EXPECT_EQ(rhs("#1=#2AND#3XOR#4"), "(xor (and #2 #3) #4)");
  EXPECT_EQ(rhs("#1 = 6 mod 4"), "(mod 6 4)");
}

TEST(GcodeParser, Comparisons) {
  EXPECT_EQ(rhs("#1=[#2 EQ 1]"), "(eq #2 1)");
  EXPECT_EQ(rhs("#1=[#2 NE 1]"), "(ne #2 1)");
  EXPECT_EQ(rhs("#1=[#2 GT 1]"), "(gt #2 1)");
  EXPECT_EQ(rhs("#1=[#2 GE 1]"), "(ge #2 1)");
  EXPECT_EQ(rhs("#1=[#2 LT 1]"), "(lt #2 1)");
  EXPECT_EQ(rhs("#1=[#2 LE 1]"), "(le #2 1)");
  EXPECT_EQ(rhs("#1=[[#2 EQ 1] OR [#3 EQ 2]]"), "(or (eq #2 1) (eq #3 2))");
}

TEST(GcodeParser, UnaryOperators) {
  EXPECT_EQ(rhs("#1 = -#2"), "(neg #2)");
  EXPECT_EQ(rhs("#1 = - - 3"), "(neg (neg 3))");
  EXPECT_EQ(rhs("#1 = +5"), "5");
  EXPECT_EQ(rhs("#1 = 2 * -3"), "(* 2 (neg 3))");
  EXPECT_EQ(rhs("#1 = -2 * 3"), "(* (neg 2) 3)");
  EXPECT_EQ(rhs("#1 = -[1 + 2]"), "(neg (+ 1 2))");
  EXPECT_EQ(rhs("#1 = 1 - -1"), "(- 1 (neg 1))");
  // Long runs of signs are not recursion; the tree they make is bounded
  // (kMaxExprDepth levels) like any other, at the first sign.
  const auto n = static_cast<std::size_t>(kMaxExprDepth - 1);
  const Block b = parse_ok("#1=" + std::string(n, '-') + "1");
  EXPECT_EQ(b.nodes.size(), n + 2u);  // #1, the signs, 1
  expect_error("#1=" + std::string(100000, '-') + "1", AlarmId::kMacroFormat, 4);
}

// Depths are measured only in blocks of more than kMaxExprDepth / 2 nodes
// (a smaller block cannot hold a tree too deep); such a block is read again
// with depths measured, and what it gives is what one reading would.
TEST(GcodeParser, DepthBoundInLargeBlocks) {
  const auto k = static_cast<std::size_t>(kMaxExprDepth);
  // "#2" is two levels: k - 2 signs over it make a tree k levels deep.
  const Block at = parse_ok("#1=" + std::string(k - 2, '-') + "#2");
  EXPECT_EQ(at.nodes.size(), k);  // #1, the signs, #2
  expect_error("#1=" + std::string(k - 1, '-') + "#2", AlarmId::kMacroFormat, 4);
  // A left-deep chain: n terms, n - 1 operators, n levels.
  auto chain = [](std::size_t n) {
    std::string s = "#1=1";
    for (std::size_t i = 1; i < n; ++i) s += "+1";
    return s;
  };
  EXPECT_EQ(parse_ok(chain(k)).nodes.size(), 2 * k);
  expect_error(chain(k + 1), AlarmId::kMacroFormat, 4);
  // The first error of the block is the tree's depth, not the stray ']'
  // after it; a small block's error is its own.
  expect_error("#1=[" + chain(k + 1).substr(3) + "]] X1", AlarmId::kMacroFormat, 5);
  expect_error("#1=[1+1]] X1", AlarmId::kBracketNesting, 9);
  // Many nodes, every tree shallow: no error.
  const Block many = parse_ok("G1 X[#1*2+#3*4] Y[" + chain(300).substr(3) + "]");
  EXPECT_EQ(many.nodes.size(), 7u + 599u);
}

TEST(GcodeParser, Functions) {
  EXPECT_EQ(rhs("#1=SIN[30]"), "(sin 30)");
  EXPECT_EQ(rhs("#1=COS[#2]"), "(cos #2)");
  EXPECT_EQ(rhs("#1=TAN[1]"), "(tan 1)");
  EXPECT_EQ(rhs("#1=ASIN[1]"), "(asin 1)");
  EXPECT_EQ(rhs("#1=ACOS[1]"), "(acos 1)");
  EXPECT_EQ(rhs("#1=ATAN[1]"), "(atan 1)");
  EXPECT_EQ(rhs("#1=ATN[1]"), "(atan 1)");
  EXPECT_EQ(rhs("#1=SQRT[2]"), "(sqrt 2)");
  EXPECT_EQ(rhs("#1=SQR[2]"), "(sqrt 2)");
  EXPECT_EQ(rhs("#1=ABS[-2]"), "(abs (neg 2))");
  EXPECT_EQ(rhs("#1=ROUND[1.5]"), "(round 1.5)");
  EXPECT_EQ(rhs("#1=RND[1.5]"), "(round 1.5)");
  EXPECT_EQ(rhs("#1=FIX[1.5]"), "(fix 1.5)");
  EXPECT_EQ(rhs("#1=FUP[1.5]"), "(fup 1.5)");
  EXPECT_EQ(rhs("#1=LN[2]"), "(ln 2)");
  EXPECT_EQ(rhs("#1=EXP[2]"), "(exp 2)");
  EXPECT_EQ(rhs("#1=POW[2,3]"), "(pow 2 3)");
  EXPECT_EQ(rhs("#1=BIN[#2]"), "(bin #2)");
  EXPECT_EQ(rhs("#1=BCD[#2]"), "(bcd #2)");
  EXPECT_EQ(rhs("#1=ADP[#2]"), "(adp #2)");
  EXPECT_EQ(rhs("#1 = s i n [30] + cos[0]"), "(+ (sin 30) (cos 0))");
  EXPECT_EQ(rhs("#1=SQRT[#2*#2+#3*#3]"), "(sqrt (+ (* #2 #2) (* #3 #3)))");
  EXPECT_EQ(rhs("#1=2*SIN[30]"), "(* 2 (sin 30))");
}

TEST(GcodeParser, ArcTangentForms) {
  EXPECT_EQ(rhs("#1=ATAN[#2]/[#3]"), "(atan #2 #3)");
  EXPECT_EQ(rhs("#1=ATAN [#2] / [#3]"), "(atan #2 #3)");
  EXPECT_EQ(rhs("#1=ATAN[#2,#3]"), "(atan #2 #3)");
  EXPECT_EQ(rhs("#1=ATN[1]/[2]+1"), "(+ (atan 1 2) 1)");
  // A division by something else than a bracket is a division.
  EXPECT_EQ(rhs("#1=ATAN[1]/2"), "(/ (atan 1) 2)");
  EXPECT_EQ(rhs("#1=ATAN[1]/#2"), "(/ (atan 1) #2)");
}

TEST(GcodeParser, FunctionErrors) {
  expect_error("#1=POW[2]", AlarmId::kMacroFormat, 4);
  expect_error("#1=SIN[1,2]", AlarmId::kMacroFormat, 9);
  expect_error("#1=FOO[1]", AlarmId::kMacroFormat, 4);
  expect_error("#1=SIN 30", AlarmId::kMacroFormat, 8);
  expect_error("#1=SIN[30", AlarmId::kBracketNesting, 7);
}

TEST(GcodeParser, ExpressionNodeColumns) {
  const Block b = parse_ok("#1 = #2 + SIN[3]");
  const ExprNode& add = b.nodes.at(static_cast<std::size_t>(b.stmt.rhs));
  EXPECT_EQ(add.op, Op::kAdd);
  EXPECT_EQ(add.column, 6u);
  EXPECT_EQ(b.nodes.at(static_cast<std::size_t>(add.a)).column, 6u);
  const ExprNode& sin = b.nodes.at(static_cast<std::size_t>(add.b));
  EXPECT_EQ(sin.op, Op::kFunc);
  EXPECT_EQ(sin.fn, Func::kSin);
  EXPECT_EQ(sin.column, 11u);
  EXPECT_EQ(b.nodes.at(static_cast<std::size_t>(sin.a)).column, 15u);
  EXPECT_EQ(b.nodes.at(static_cast<std::size_t>(b.stmt.lhs)).column, 1u);
}

// Numbers, variable numbers and function names have fast paths for the
// usual spellings; spaces inside them, many digits and the like take the
// general path and read as they always did.
TEST(GcodeParser, NumbersSplitBySpaces) {
  const Block b = parse_ok("X1 0 Y1. 5 Z 1 .5 A1 B2");
  ASSERT_EQ(b.words.size(), 5u);
  EXPECT_EQ(b.words[0].value, 10.0);
  EXPECT_FALSE(b.words[0].has_point);
  EXPECT_EQ(b.words[1].value, 1.5);
  EXPECT_EQ(b.words[1].column, 6u);
  EXPECT_EQ(b.words[2].value, 1.5);
  EXPECT_EQ(b.words[2].column, 12u);
  EXPECT_EQ(b.words[3].value, 1.0);
  EXPECT_EQ(b.words[4].value, 2.0);
  EXPECT_EQ(b.words[4].column, 22u);
  EXPECT_EQ(rhs("#1 = 1 2 * 3"), "(* 12 3)");
  EXPECT_EQ(rhs("#1 = #1 2 + #0 0 3"), "(+ #12 #3)");
  EXPECT_EQ(rhs("#1=#2 +3"), "(+ #2 3)");
  EXPECT_EQ(rhs("#1=#" + std::string(20, '0') + "7"), "#7");
  EXPECT_EQ(rhs("#1=" + std::string(20, '0') + "1.25"), "1.25");
  expect_error("#1=#2 .5", AlarmId::kBadDecimalPoint, 7);
  expect_error("X1 .5 .5", AlarmId::kBadDecimalPoint, 7);
  expect_error("#1=#1234567890123456789", AlarmId::kTooManyDigits, 5);
}

TEST(GcodeParser, FunctionNamesAsWritten) {
  EXPECT_EQ(rhs("#1=sqrt[4]"), "(sqrt 4)");
  EXPECT_EQ(rhs("#1=SQR T[4]"), "(sqrt 4)");
  EXPECT_EQ(rhs("#1=S Q R[4]"), "(sqrt 4)");
  EXPECT_EQ(rhs("#1=A T N[1]+AbS[2]"), "(+ (atan 1) (abs 2))");
  EXPECT_EQ(rhs("#1=ROUND[1]*RND[2]"), "(* (round 1) (round 2))");
  EXPECT_EQ(rhs("#1=LN[1]"), "(ln 1)");
  expect_error("#1=SINE[1]", AlarmId::kMacroFormat, 7);
  expect_error("#1=SQ[1]", AlarmId::kMacroFormat, 4);
  expect_error("#1=LN", AlarmId::kMacroFormat, 6);
}

// A function name is looked up two ways: by its letters when 8 or more
// bytes are left in the block (all of them at once), and letter by letter
// nearer the end. Both give the same function, the same errors.
TEST(GcodeParser, FunctionNamesFarFromAndNearTheEnd) {
  const std::pair<const char*, const char*> kNames[] = {
      {"SIN", "sin"},     {"COS", "cos"},   {"TAN", "tan"},   {"ASIN", "asin"}, {"ACOS", "acos"},
      {"ATAN", "atan"},   {"ATN", "atan"},  {"SQRT", "sqrt"}, {"SQR", "sqrt"},  {"ABS", "abs"},
      {"ROUND", "round"}, {"RND", "round"}, {"FIX", "fix"},   {"FUP", "fup"},   {"LN", "ln"},
      {"EXP", "exp"},     {"BIN", "bin"},   {"BCD", "bcd"},   {"ADP", "adp"}};
  for (const auto& [name, shown] : kNames) {
    const std::string call = std::string(name) + "[1]";
    EXPECT_EQ(rhs("#1=" + call), std::string("(") + shown + " 1)") << name;
    EXPECT_EQ(rhs("#1=" + call + "+12345678"), std::string("(+ (") + shown + " 1) 12345678)")
        << name;
    std::string lower = call;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    EXPECT_EQ(rhs("#1=" + lower + "*#12345"), std::string("(* (") + shown + " 1) #12345)") << name;
  }
  EXPECT_EQ(rhs("#1=POW[2,3]+12345678"), "(+ (pow 2 3) 12345678)");
  // Not a name: the letters run on, or stop short of one.
  for (const std::string tail : {"", "+12345678"}) {
    expect_error("#1=SINE[1]" + tail, AlarmId::kMacroFormat, 7);
    expect_error("#1=SQ[1]" + tail, AlarmId::kMacroFormat, 4);
    expect_error("#1=SQRTX[1]" + tail, AlarmId::kMacroFormat, 8);
    expect_error("#1=FOO[1]" + tail, AlarmId::kMacroFormat, 4);
    expect_error("#1=SIN\xC3[1]" + tail, AlarmId::kMacroFormat, 7);
    EXPECT_EQ(rhs("#1=S IN[1]" + tail), tail.empty() ? "(sin 1)" : "(+ (sin 1) 12345678)");
  }
}

TEST(GcodeParser, OperatorsGroupByPrecedence) {
  EXPECT_EQ(rhs("#1=1*2+3*4 GT 5 AND 6 OR 7"), "(gt (+ (* 1 2) (* 3 4)) (or (and 5 6) 7))");
  EXPECT_EQ(rhs("#1=1 EQ 2 NE 3"), "(ne (eq 1 2) 3)");
  EXPECT_EQ(rhs("#1=1-2*3-4"), "(- (- 1 (* 2 3)) 4)");
  EXPECT_EQ(rhs("#1=1+2 LT 3*4-5 LE 6"), "(le (lt (+ 1 2) (- (* 3 4) 5)) 6)");
  EXPECT_EQ(rhs("#1=[[1+2]*[3+4]]/5"), "(/ (* (+ 1 2) (+ 3 4)) 5)");
  // A binary node's column is that of its left operand's first character.
  const Block b = parse_ok("#1=-1*2+3");
  const ExprNode& add = b.nodes.at(static_cast<std::size_t>(b.stmt.rhs));
  EXPECT_EQ(add.op, Op::kAdd);
  EXPECT_EQ(add.column, 4u);
  const ExprNode& mul = b.nodes.at(static_cast<std::size_t>(add.a));
  EXPECT_EQ(mul.op, Op::kMul);
  EXPECT_EQ(mul.column, 4u);
  EXPECT_EQ(b.nodes.at(static_cast<std::size_t>(add.b)).column, 9u);
}

TEST(GcodeParser, ExpressionErrors) {
  expect_error("#1=", AlarmId::kMacroFormat, 4);
  expect_error("#1=1+", AlarmId::kMacroFormat, 6);
  expect_error("#1=[1+]", AlarmId::kMacroFormat, 7);
  expect_error("#1=[]", AlarmId::kMacroFormat, 5);
  expect_error("#1=[1+2", AlarmId::kBracketNesting, 4);
  expect_error("#1=[1 2 3 $]", AlarmId::kMacroFormat, 11);
  expect_error("#1 X5", AlarmId::kMacroFormat, 4);
  expect_error("#1=1 #2=2", AlarmId::kMacroFormat, 6);
  expect_error("#1=#2.5", AlarmId::kBadDecimalPoint, 6);
}

TEST(GcodeParser, BracketNestingIsLimited) {
  ParseLimits limits;  // 64 by default
  const auto nested = [](int depth) {
    return "#1=" + std::string(static_cast<std::size_t>(depth), '[') + "1" +
           std::string(static_cast<std::size_t>(depth), ']');
  };
  EXPECT_EQ(rhs(nested(limits.max_bracket_depth)), "1");
  expect_error(nested(limits.max_bracket_depth + 1), AlarmId::kBracketNesting,
               4 + static_cast<std::uint32_t>(limits.max_bracket_depth));
  expect_error(nested(1000), AlarmId::kBracketNesting, 68);
  expect_error("X" + std::string(1000, '['), AlarmId::kBracketNesting, 66);
  expect_error("#1=" + std::string(1000, '#') + "1", AlarmId::kBracketNesting, 69);
  std::string funcs = "#1=";
  for (int i = 0; i < 1000; ++i) funcs += "SIN[";
  expect_error(funcs, AlarmId::kBracketNesting, 7 + 64 * 4);  // the 65th '['
  // The limit is the dialect's.
  ParseLimits five;
  five.max_bracket_depth = 5;
  Block b;
  EXPECT_TRUE(parse("IF[[[[[1]]]]]GOTO1", b, five));
  expect_error("IF[[[[[[1]]]]]]GOTO1", AlarmId::kBracketNesting, 8, five);
  // Even an absurd limit does not let recursion run away.
  ParseLimits huge;
  huge.max_bracket_depth = 1 << 30;
  EXPECT_FALSE(parse(nested(200000), b, huge));
}

TEST(GcodeParser, Goto) {
  Block b = parse_ok("GOTO 10");
  EXPECT_EQ(b.stmt.kind, StmtKind::kGoto);
  EXPECT_EQ(show(b, b.stmt.target), "10");
  EXPECT_EQ(b.stmt.column, 1u);
  EXPECT_TRUE(b.words.empty());
  b = parse_ok("GOTO#1");
  EXPECT_EQ(show(b, b.stmt.target), "#1");
  b = parse_ok("GOTO[#1+1]");
  EXPECT_EQ(show(b, b.stmt.target), "(+ #1 1)");
  b = parse_ok("G O T O 9 9 0");
  EXPECT_EQ(show(b, b.stmt.target), "990");
  b = parse_ok("N41GOTO#22");
  EXPECT_TRUE(b.has_n);
  EXPECT_EQ(b.n, 41);
  EXPECT_EQ(b.stmt.kind, StmtKind::kGoto);
  EXPECT_EQ(b.stmt.column, 4u);
  EXPECT_EQ(show(b, b.stmt.target), "#22");
  b = parse_ok("goto 5 (back)");
  EXPECT_EQ(show(b, b.stmt.target), "5");
  EXPECT_EQ(b.comments.size(), 1u);
  expect_error("GOTO", AlarmId::kMacroFormat, 5);
  expect_error("GOTO -1", AlarmId::kBadSign, 6);
  expect_error("GOTO 10.", AlarmId::kBadDecimalPoint, 8);
}

TEST(GcodeParser, IfGoto) {
  Block b = parse_ok("IF [#1 EQ 0] GOTO 5");
  EXPECT_EQ(b.stmt.kind, StmtKind::kIfGoto);
  EXPECT_EQ(show(b, b.stmt.cond), "(eq #1 0)");
  EXPECT_EQ(show(b, b.stmt.target), "5");
  b = parse_ok("IF[#1AND128EQ0]GOTO5");
  EXPECT_EQ(b.stmt.kind, StmtKind::kIfGoto);
  EXPECT_EQ(show(b, b.stmt.cond), "(eq (and #1 128) 0)");
  EXPECT_EQ(show(b, b.stmt.target), "5");
  b = parse_ok("N20 if[#5061 gt #100] goto #3");
  EXPECT_EQ(b.n, 20);
  EXPECT_EQ(show(b, b.stmt.cond), "(gt #5061 #100)");
  EXPECT_EQ(show(b, b.stmt.target), "#3");
  EXPECT_EQ(b.stmt.column, 5u);
  expect_error("IF #1 GOTO 5", AlarmId::kMacroFormat, 4);
  expect_error("IF [#1] X5", AlarmId::kMacroFormat, 9);
  expect_error("IF [#1 EQ 0 GOTO 5", AlarmId::kMacroFormat, 13);
}

TEST(GcodeParser, IfThen) {
  Block b = parse_ok("IF [#1 GT 2] THEN #1 = 2");
  EXPECT_EQ(b.stmt.kind, StmtKind::kIfThen);
  EXPECT_EQ(show(b, b.stmt.cond), "(gt #1 2)");
  EXPECT_EQ(show(b, b.stmt.lhs), "#1");
  EXPECT_EQ(show(b, b.stmt.rhs), "2");
  b = parse_ok("IF[#1NE#2]THEN#3=#1-#2");
  EXPECT_EQ(b.stmt.kind, StmtKind::kIfThen);
  EXPECT_EQ(show(b, b.stmt.cond), "(ne #1 #2)");
  EXPECT_EQ(show(b, b.stmt.lhs), "#3");
  EXPECT_EQ(show(b, b.stmt.rhs), "(- #1 #2)");
  b = parse_ok("IF[#1EQ1]THEN#3000=1(TOO SHORT)");
  EXPECT_EQ(show(b, b.stmt.lhs), "#3000");
  ASSERT_EQ(b.comments.size(), 1u);
  EXPECT_EQ(b.names.at(static_cast<std::size_t>(b.comments[0].text)), "TOO SHORT");
  expect_error("IF[#1EQ1]THEN", AlarmId::kMacroFormat, 14);
  expect_error("IF[#1EQ1]THEN X1", AlarmId::kMacroFormat, 15);
}

TEST(GcodeParser, Loops) {
  Block b = parse_ok("WHILE [#1 LT 10] DO 1");
  EXPECT_EQ(b.stmt.kind, StmtKind::kWhile);
  EXPECT_EQ(show(b, b.stmt.cond), "(lt #1 10)");
  EXPECT_EQ(b.stmt.loop, 1);
  b = parse_ok("WHILE[#1LE#2]DO2");
  EXPECT_EQ(b.stmt.kind, StmtKind::kWhile);
  EXPECT_EQ(show(b, b.stmt.cond), "(le #1 #2)");
  EXPECT_EQ(b.stmt.loop, 2);
  b = parse_ok("DO1");
  EXPECT_EQ(b.stmt.kind, StmtKind::kDo);
  EXPECT_EQ(b.stmt.loop, 1);
  b = parse_ok("N5 D O 3");
  EXPECT_EQ(b.stmt.kind, StmtKind::kDo);
  EXPECT_EQ(b.stmt.loop, 3);
  b = parse_ok("END 1");
  EXPECT_EQ(b.stmt.kind, StmtKind::kEnd);
  EXPECT_EQ(b.stmt.loop, 1);
  b = parse_ok("end2");
  EXPECT_EQ(b.stmt.kind, StmtKind::kEnd);
  EXPECT_EQ(b.stmt.loop, 2);
  // Loop numbers are kept as written; the range is the interpreter's check.
  EXPECT_EQ(parse_ok("END 7").stmt.loop, 7);
  // D01 is a D word, not DO.
  b = parse_ok("D01");
  EXPECT_EQ(b.stmt.kind, StmtKind::kNone);
  ASSERT_EQ(b.words.size(), 1u);
  EXPECT_EQ(b.words[0].letter, 'D');
  expect_error("DO", AlarmId::kMacroFormat, 3);
  expect_error("END", AlarmId::kMacroFormat, 4);
  expect_error("WHILE [#1 LT 10] 1", AlarmId::kMacroFormat, 18);
  expect_error("WHILE [#1 LT 10] DO #1", AlarmId::kMacroFormat, 21);
  expect_error("DO 1.", AlarmId::kBadDecimalPoint, 5);
}

TEST(GcodeParser, PopenPclos) {
  EXPECT_EQ(parse_ok("POPEN").stmt.kind, StmtKind::kPopen);
  EXPECT_EQ(parse_ok("pclos").stmt.kind, StmtKind::kPclos);
  EXPECT_EQ(parse_ok("N1 P O P E N").stmt.kind, StmtKind::kPopen);
}

TEST(GcodeParser, Dprnt) {
  const Block b = parse_ok("DPRNT[X#100[53]*Y-#101[53]]");
  EXPECT_EQ(b.stmt.kind, StmtKind::kDprnt);
  ASSERT_EQ(b.print_items.size(), 4u);
  EXPECT_TRUE(b.print_items[0].is_text);
  EXPECT_EQ(b.names.at(static_cast<std::size_t>(b.print_items[0].text)), "X");
  EXPECT_FALSE(b.print_items[1].is_text);
  EXPECT_EQ(show(b, b.print_items[1].var), "#100");
  EXPECT_EQ(b.print_items[1].int_digits, 5);
  EXPECT_EQ(b.print_items[1].frac_digits, 3);
  EXPECT_EQ(b.names.at(static_cast<std::size_t>(b.print_items[2].text)), " Y-");
  EXPECT_EQ(show(b, b.print_items[3].var), "#101");
}

TEST(GcodeParser, DprntTextKeepsSpaces) {
  const Block b = parse_ok("dprnt [meas x = #1[44]  done]");
  ASSERT_EQ(b.print_items.size(), 3u);
  EXPECT_EQ(b.names.at(static_cast<std::size_t>(b.print_items[0].text)), "MEAS X = ");
  EXPECT_EQ(b.print_items[1].int_digits, 4);
  EXPECT_EQ(b.print_items[1].frac_digits, 4);
  EXPECT_EQ(b.names.at(static_cast<std::size_t>(b.print_items[2].text)), "  DONE");
  const Block c = parse_ok("DPRNT[#1 #2[30]]");
  ASSERT_EQ(c.print_items.size(), 3u);
  EXPECT_EQ(show(c, c.print_items[0].var), "#1");
  EXPECT_EQ(c.print_items[0].int_digits, 0);  // no format written
  EXPECT_EQ(c.names.at(static_cast<std::size_t>(c.print_items[1].text)), " ");
  EXPECT_EQ(show(c, c.print_items[2].var), "#2");
  EXPECT_EQ(parse_ok("DPRNT[]").print_items.size(), 0u);
  const Block d = parse_ok("DPRNT[P#[#1+1][52]#<pos>[52]]");
  ASSERT_EQ(d.print_items.size(), 3u);
  EXPECT_EQ(show(d, d.print_items[1].var), "#(+ #1 1)");
  EXPECT_EQ(d.print_items[1].frac_digits, 2);
  EXPECT_EQ(show(d, d.print_items[2].var), "#<POS>");
}

TEST(GcodeParser, Bprnt) {
  const Block b = parse_ok("BPRNT[C**X#100[3]]");
  EXPECT_EQ(b.stmt.kind, StmtKind::kBprnt);
  ASSERT_EQ(b.print_items.size(), 2u);
  EXPECT_EQ(b.names.at(static_cast<std::size_t>(b.print_items[0].text)), "C  X");
  EXPECT_EQ(b.print_items[1].int_digits, 0);
  EXPECT_EQ(b.print_items[1].frac_digits, 3);
}

TEST(GcodeParser, PrintErrors) {
  expect_error("DPRNT[X#1[53]", AlarmId::kBracketNesting, 6);
  expect_error("DPRNT X", AlarmId::kMacroFormat, 7);
  expect_error("DPRNT[A[B]]", AlarmId::kIllegalChar, 8);
  expect_error("DPRNT[#1[5x]]", AlarmId::kMacroFormat, 9);
  expect_error("DPRNT[#1[123]]", AlarmId::kMacroFormat, 9);
  expect_error("DPRNT[A(B)]", AlarmId::kIllegalChar, 8);
}

TEST(GcodeParser, KeywordsBeforeAddresses) {
  // G O T O, I F, W H I L E, D O, E N D are keywords wherever they are spelt,
  // addresses otherwise.
  Block b = parse_ok("G0 E1. I2. W3. B4. P5");
  EXPECT_EQ(b.stmt.kind, StmtKind::kNone);
  EXPECT_EQ(b.words.size(), 6u);
  b = parse_ok("M98 P1234 L2");
  EXPECT_EQ(b.words.size(), 3u);
  expect_error("G0 GOTO 5 GOTO 6", AlarmId::kMacroFormat, 11);
}

// ---------------------------------------------------------------- block reuse

TEST(GcodeParser, BlockIsReused) {
  Block b;
  ASSERT_TRUE(parse("N1 #1=[#2+1]*SIN[#3] (C)", b));
  ASSERT_TRUE(parse("G1 X10.123 Y-3.5 F1000.", b));
  EXPECT_FALSE(b.has_n);
  EXPECT_EQ(b.stmt.kind, StmtKind::kNone);
  EXPECT_TRUE(b.nodes.empty());
  EXPECT_TRUE(b.names.empty());
  EXPECT_TRUE(b.comments.empty());
  EXPECT_EQ(b.words.size(), 4u);
  // Once the arrays have grown, parsing does not reallocate them.
  const Word* words = b.words.data();
  const ExprNode* nodes = b.nodes.data();
  for (int i = 0; i < 100; ++i) {
    ASSERT_TRUE(parse("G1 X10.123 Y-3.5 F1000.", b));
    ASSERT_TRUE(parse("#1=[#2+1]*3", b));
  }
  EXPECT_EQ(b.words.data(), words);
  EXPECT_EQ(b.nodes.data(), nodes);
  // A failed parse leaves a block that can be parsed into again.
  EXPECT_FALSE(parse("X1.2.3", b));
  ASSERT_TRUE(parse("Y2", b));
  ASSERT_EQ(b.words.size(), 1u);
  EXPECT_EQ(b.words[0].value, 2.0);
}

// A mixed program parses block by block without error.
TEST(GcodeParser, RealisticProgram) {
  const char* const lines[] = {
      "%",
      "O9810 (PROTECTED POSITIONING)",
      "#1=#5041 (X)",
      "N10 G31 P2 X[#24] Y[#25] F#9",
      "IF [ABS[#5061 - #24] GT 0.005] THEN #3000 = 91 (PATH OBSTRUCTED)",
      "#149=#5001*#4006",
      "WHILE[#149LT4]DO1",
      "#149=#149+1",
      "END1",
      "G65P9810Z-10.F1000.",
      "/2 M01",
      "POPEN",
      "DPRNT[X#5061[44]*Y#5062[44]]",
      "PCLOS",
      "M99",
  };
  Block b;
  for (const char* line : lines) {
    const auto r = parse(line, b);
    EXPECT_TRUE(r) << line << ": " << (r ? "" : r.error().detail);
  }
}

// ---- RS274NGC (LinuxCNC) and grbl

ParseLimits ngc_limits() {
  ParseLimits l;
  l.syntax = Syntax::kRs274ngc;
  return l;
}

Block parse_ngc(std::string_view text) {
  Block b;
  const auto r = parse(text, b, ngc_limits());
  EXPECT_TRUE(r.has_value()) << "'" << text << "': " << (r ? "" : r.error().detail);
  return b;
}

std::string ngc_rhs(std::string_view text) {
  const Block b = parse_ngc(text);
  EXPECT_EQ(b.assigns.size(), 1u) << text;
  return b.assigns.empty() ? "" : show(b, b.assigns.front().rhs);
}

TEST(GcodeParserNgc, PrecedenceIsLinuxCncs) {
  // ** above * / MOD above + - above comparisons above AND OR XOR; left to right.
  EXPECT_EQ(ngc_rhs("#1=[2**3**2]"), "(** (** 2 3) 2)");
  EXPECT_EQ(ngc_rhs("#1=[2+3 GT 4 AND 1]"), "(and (gt (+ 2 3) 4) 1)");
  EXPECT_EQ(ngc_rhs("#1=[1 OR 2 EQ 3]"), "(or 1 (eq 2 3))");
  EXPECT_EQ(ngc_rhs("#1=[7 MOD 3*2]"), "(* (mod 7 3) 2)");
  EXPECT_EQ(ngc_rhs("#1=[-2**2]"), "(** (neg 2) 2)");
  EXPECT_EQ(ngc_rhs("#1=EXISTS[#<abc>]"), "(exists #<ABC>)");
  EXPECT_EQ(ngc_rhs("#1=EXISTS[#<abc>]+12345678"), "(+ (exists #<ABC>) 12345678)");
  // The same text under Macro B: AND binds as *, and ** is no operator.
  EXPECT_EQ(rhs("#1=[2+3 GT 4 AND 1]"), "(gt (+ 2 3) (and 4 1))");
  parse_err("#1=[2**3]");
}

TEST(GcodeParserNgc, SeveralSettingsAndWordsOnALine) {
  const Block b = parse_ngc("#1=2 #<x> = [#1+1] G1 X#1 ; the rest is a comment (not one");
  ASSERT_EQ(b.assigns.size(), 2u);
  EXPECT_EQ(show(b, b.assigns[0].lhs), "#1");
  EXPECT_EQ(show(b, b.assigns[1].lhs), "#<X>");
  ASSERT_EQ(b.words.size(), 2u);
  EXPECT_EQ(b.words[1].letter, 'X');
  EXPECT_EQ(b.stmt.kind, StmtKind::kNone);
}

TEST(GcodeParserNgc, OWords) {
  struct Case {
    std::string_view text;
    OKind kind;
    std::string_view label;
    std::size_t args;
  };
  const Case cases[] = {
      {"o100 sub", OKind::kSub, "100", 0},
      {"O0100 ENDSUB", OKind::kEndsub, "100", 0},
      {"o100 endsub [#1*2]", OKind::kEndsub, "100", 1},
      {"o<probe_x> call [1] [2.5] [#<_x>]", OKind::kCall, "<PROBE_X>", 3},
      {"o<Probe X> call", OKind::kCall, "<PROBEX>", 0},
      {"o100 return [5]", OKind::kReturn, "100", 1},
      {"N20 o101 if [#1 GT 2]", OKind::kIf, "101", 1},
      {"o101 elseif [#1 LT 0]", OKind::kElseif, "101", 1},
      {"o101 else (comment)", OKind::kElse, "101", 0},
      {"o101 endif", OKind::kEndif, "101", 0},
      {"o102 while [#1 LT 3]", OKind::kWhile, "102", 1},
      {"o102 endwhile", OKind::kEndwhile, "102", 0},
      {"o103 do", OKind::kDo, "103", 0},
      {"o104 repeat [3]", OKind::kRepeat, "104", 1},
      {"o104 endrepeat", OKind::kEndrepeat, "104", 0},
      {"o102 break", OKind::kBreak, "102", 0},
      {"o102 continue ; why", OKind::kContinue, "102", 0},
  };
  for (const Case& c : cases) {
    const Block b = parse_ngc(c.text);
    EXPECT_EQ(b.stmt.kind, StmtKind::kOword) << c.text;
    EXPECT_EQ(b.stmt.okind, c.kind) << c.text;
    ASSERT_GE(b.stmt.label, 0) << c.text;
    EXPECT_EQ(b.names[static_cast<std::size_t>(b.stmt.label)], c.label) << c.text;
    EXPECT_EQ(b.args.size(), c.args) << c.text;
  }
}

TEST(GcodeParserNgc, ProgramTitlesAndComputedCalls) {
  // "O200" alone heads a Fanuc-style numbered program (called by M98).
  const Block t = parse_ngc("O200 (drill pattern)");
  EXPECT_TRUE(t.has_o);
  EXPECT_EQ(t.o, 200);
  EXPECT_EQ(t.stmt.kind, StmtKind::kNone);
  const Block c = parse_ngc("o[#2 * 10] call [1]");
  EXPECT_EQ(c.stmt.okind, OKind::kCall);
  EXPECT_EQ(show(c, c.stmt.target), "(* #2 10)");
  EXPECT_EQ(c.args.size(), 1u);
}

TEST(GcodeParserNgc, OWordErrors) {
  Block b;
  auto err = [&](std::string_view text) {
    auto r = parse(text, b, ngc_limits());
    EXPECT_FALSE(r.has_value()) << text;
    return r ? Error{} : r.error();
  };
  EXPECT_EQ(err("o100 jump").loc.column, 6u);             // no such keyword
  EXPECT_EQ(err("o[1] sub").id, AlarmId::kMacroFormat);   // computed: a call only
  EXPECT_EQ(err("o100 if").id, AlarmId::kMacroFormat);    // no condition
  EXPECT_EQ(err("o100 sub G1 X1").loc.column, 10u);       // only a comment may follow
  EXPECT_EQ(err("o100 return [1] [2]").loc.column, 17u);  // one value at most
  EXPECT_EQ(err("o x call").id, AlarmId::kMacroFormat);
}

TEST(GcodeParserGrbl, NumbersOnly) {
  ParseLimits l;
  l.syntax = Syntax::kGrbl;
  Block b;
  ASSERT_TRUE(parse("G38.2 Z-10 F100 ; probe", b, l));
  EXPECT_EQ(b.words.size(), 3u);
  auto e1 = parse("#1=2", b, l);
  ASSERT_FALSE(e1);
  EXPECT_EQ(e1.error().id, AlarmId::kIllegalChar);
  auto e2 = parse("G1 X[1+2]", b, l);
  ASSERT_FALSE(e2);
  EXPECT_EQ(e2.error().loc.column, 4u);  // the X, which has no number
  auto e3 = parse("O100", b, l);
  ASSERT_FALSE(e3);
  EXPECT_EQ(e3.error().id, AlarmId::kIllegalAddress);
}

}  // namespace
}  // namespace skipnc::gcode
