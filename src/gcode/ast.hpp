// The syntax of one block, as the parser sees it: no meaning is given to any
// word here. A Block owns flat arrays (words, expression nodes, names) that
// are reused from block to block, so parsing a block does not allocate once
// the arrays have grown to the program's largest block.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/diag.hpp"

namespace skipnc::gcode {

using ExprId = std::int32_t;  // index into Block::nodes; -1 = none
inline constexpr ExprId kNoExpr = -1;

// clang-format off
enum class Op : std::uint8_t {
  kNumber,    // value
  kVar,       // #a          (a: expression giving the variable number)
  kVarNum,    // #n          (n written as a number: value; two levels deep, as #a)
  kNamedVar,  // #<name> or #_NAME   (name: index into Block::names)
  kNeg,       // -a
  kAdd, kSub, kMul, kDiv, kMod, kAnd, kOr, kXor,  // a op b
  kPow,                                           // a ** b (RS274NGC)
  kEq, kNe, kGt, kGe, kLt, kLe,                   // a op b (conditions)
  kFunc,      // fn(a) or fn(a, b)
};

enum class Func : std::uint8_t {
  kNone, kSin, kCos, kTan, kAsin, kAcos, kAtan, kSqrt, kAbs, kRound, kFix, kFup,
  kLn, kExp, kPow, kBin, kBcd, kAdp,
  kExists,    // EXISTS[#<name>] (RS274NGC): a is the kNamedVar node
};

// The language a block is read in: Fanuc Custom Macro B (and the
// Fanuc-compatible controls), LinuxCNC's RS274NGC with O-word control flow,
// or grbl's plain G code (no parameters, no expressions).
enum class Syntax : std::uint8_t { kMacroB, kRs274ngc, kGrbl };

// An O-word statement (RS274NGC): `o<label> <keyword> [...]`.
enum class OKind : std::uint8_t {
  kNone, kSub, kEndsub, kCall, kReturn, kIf, kElseif, kElse, kEndif,
  kWhile, kEndwhile, kDo, kRepeat, kEndrepeat, kBreak, kContinue,
};
// clang-format on

// A node of an expression tree. In a block the parser gives out, an
// operator's operands (a, and b where it has two) are nodes of the same
// block: their indices are valid (the evaluator's fast path relies on it).
// Only a function's b may be kNoExpr (one argument); numbers and variables
// have no operand nodes.
struct ExprNode {      // 32 bytes (26 and padding): the largest member first
  double value = 0.0;  // kNumber; kVarNum: the variable's number
  ExprId a = kNoExpr;
  ExprId b = kNoExpr;
  std::int32_t name = -1;    // kNamedVar
  std::uint32_t column = 0;  // 1-based column of the node's first character
  Op op = Op::kNumber;
  Func fn = Func::kNone;
};

// The expression nodes of a block: a std::vector used as storage, whose size
// is the capacity reached so far and never shrinks, and a count of the nodes
// in use. Clearing a block and parsing the next one writes only the nodes
// that block holds: no copy, no value-initialisation of spare storage.
class NodeArray {
 public:
  std::size_t size() const noexcept { return n_; }
  bool empty() const noexcept { return n_ == 0; }
  std::size_t capacity() const noexcept { return store_.size(); }
  ExprNode* data() noexcept { return store_.data(); }
  const ExprNode* data() const noexcept { return store_.data(); }
  ExprNode& operator[](std::size_t i) noexcept { return store_[i]; }
  const ExprNode& operator[](std::size_t i) const noexcept { return store_[i]; }
  const ExprNode& at(std::size_t i) const {
    if (i >= n_) throw std::out_of_range("NodeArray::at");
    return store_[i];
  }
  const ExprNode* begin() const noexcept { return store_.data(); }
  const ExprNode* end() const noexcept { return store_.data() + n_; }
  void clear() noexcept { n_ = 0; }
  // Storage for at least `cap` nodes; the nodes in use are kept.
  void reserve(std::size_t cap) {
    if (store_.size() < cap) store_.resize(cap);
  }
  // The first n nodes of the storage are the block's (n <= capacity()).
  void set_size(std::size_t n) noexcept { n_ = n; }

 private:
  std::vector<ExprNode> store_;
  std::size_t n_ = 0;
};

// Expression trees are at most this deep (operators, signs, brackets and
// variable references counted together, "#n" as two levels). Evaluation
// recurses over the tree; the bound keeps its stack small whatever a block
// holds ("1+1+...+1").
inline constexpr int kMaxExprDepth = 1000;

// One address word: a letter and a value, either a literal number or an
// expression (X#1, X[#1+2], X-#2, G#10).
struct Word {
  char letter = 0;  // 'A'..'Z', upper case
  bool is_expr = false;
  bool has_point = false;  // literal written with a decimal point
  double value = 0.0;      // literal value (is_expr == false)
  ExprId expr = kNoExpr;   // is_expr == true
  std::uint32_t column = 0;
};

enum class StmtKind : std::uint8_t {
  kNone,
  kAssign,  // #lhs = rhs      (lhs: expression node of kind kVar/kNamedVar)
  kGoto,    // GOTO target
  kIfGoto,  // IF [cond] GOTO target
  kIfThen,  // IF [cond] THEN #lhs = rhs
  kWhile,   // WHILE [cond] DO loop
  kDo,      // DO loop (no WHILE: endless loop)
  kEnd,     // END loop
  kPopen,   // POPEN
  kPclos,   // PCLOS
  kDprnt,   // DPRNT[...]  (items in Block::print_items)
  kBprnt,   // BPRNT[...]
  kOword,   // o<label> keyword [args] (RS274NGC; okind, label, Block::args)
  // grbl's '$' system line: the text after '$' (upper case, without spaces
  // and comments) in Block::names[label]; "$J=" keeps the jog's words in
  // Block::words (kGrblJog).
  kGrblSystem,
  kGrblJog,
};

// One item of DPRNT/BPRNT: text to print, or a variable with a format.
struct PrintItem {
  bool is_text = false;
  std::int32_t text = -1;  // index into Block::names (the literal text)
  ExprId var = kNoExpr;    // expression node of kind kVar/kNamedVar
  int int_digits = 0;      // [ab]: a
  int frac_digits = 0;     //       b
};

struct Stmt {
  StmtKind kind = StmtKind::kNone;
  ExprId lhs = kNoExpr;
  ExprId rhs = kNoExpr;
  ExprId cond = kNoExpr;
  ExprId target = kNoExpr;  // GOTO target expression
  int loop = 0;             // DO/END identifier as written (1..3 on Fanuc)
  std::uint32_t column = 0;
  OKind okind = OKind::kNone;
  std::int32_t label = -1;  // kOword: index into Block::names ("100", "<NAME>")
};

// A parameter setting of an RS274NGC line ("#1 = 2 #<a> = #1 G1 X#a"):
// every value on the line is read before any setting takes effect.
struct Assignment {
  ExprId lhs = kNoExpr;
  ExprId rhs = kNoExpr;
};

struct Comment {
  std::int32_t text = -1;  // index into Block::names: the text inside ( )
  std::uint32_t column = 0;
};

struct Block {
  SourceLoc loc;             // file, line, column of the block's first character
  std::uint64_t offset = 0;  // byte offset of the block in its file
  bool percent = false;      // the block is a '%' (tape start or end)
  int block_delete = -1;     // -1: no '/'; 1..9: '/n' ('/' alone is 1)
  bool has_n = false;
  std::int64_t n = 0;  // N sequence number
  bool has_o = false;
  std::int64_t o = 0;       // O program number at the head of the block
  std::vector<Word> words;  // in the order written
  Stmt stmt;
  NodeArray nodes;
  std::vector<std::string> names;  // named variables, comment texts, print texts
  std::vector<Comment> comments;
  std::vector<PrintItem> print_items;
  std::vector<ExprId> args;         // kOword: the [expr] arguments / condition
  std::vector<Assignment> assigns;  // RS274NGC parameter settings
  // Haas's conditional M99 (`N50 [#100 LT 10] M99 P10`): the block runs only
  // when the expression is not 0 (ParseLimits::conditional_m99).
  ExprId condition = kNoExpr;

  void clear() noexcept {
    loc = {};
    offset = 0;
    percent = false;
    block_delete = -1;
    has_n = false;
    n = 0;
    has_o = false;
    o = 0;
    words.clear();
    stmt = {};
    nodes.clear();
    names.clear();
    comments.clear();
    print_items.clear();
    args.clear();
    assigns.clear();
    condition = kNoExpr;
  }
  // True when the block has neither words nor a statement (only comments or nothing).
  bool empty() const noexcept {
    return words.empty() && stmt.kind == StmtKind::kNone && !percent && !has_o && assigns.empty();
  }
};

}  // namespace skipnc::gcode
