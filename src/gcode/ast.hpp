// The syntax of one block, as the parser sees it: no meaning is given to any
// word here. A Block owns flat arrays (words, expression nodes, names) that
// are reused from block to block, so parsing a block does not allocate once
// the arrays have grown to the program's largest block.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/diag.hpp"

namespace skipnc::gcode {

using ExprId = std::int32_t;  // index into Block::nodes; -1 = none
inline constexpr ExprId kNoExpr = -1;

enum class Op : std::uint8_t {
  kNumber,    // value
  kVar,       // #a          (a: expression giving the variable number)
  kNamedVar,  // #<name> or #_NAME   (name: index into Block::names)
  kNeg,       // -a
  kAdd, kSub, kMul, kDiv, kMod, kAnd, kOr, kXor,  // a op b
  kEq, kNe, kGt, kGe, kLt, kLe,                   // a op b (conditions)
  kFunc,      // fn(a) or fn(a, b)
};

enum class Func : std::uint8_t {
  kNone, kSin, kCos, kTan, kAsin, kAcos, kAtan, kSqrt, kAbs, kRound, kFix, kFup,
  kLn, kExp, kPow, kBin, kBcd, kAdp,
};

struct ExprNode {
  Op op = Op::kNumber;
  Func fn = Func::kNone;
  ExprId a = kNoExpr;
  ExprId b = kNoExpr;
  double value = 0.0;         // kNumber
  std::int32_t name = -1;     // kNamedVar
  std::uint32_t column = 0;   // 1-based column of the node's first character
  std::uint16_t depth = 1;    // levels of the tree from this node down (<= kMaxExprDepth)
};

// Expression trees are at most this deep (operators, signs, brackets and
// variable references counted together). Evaluation recurses over the tree;
// the bound keeps its stack small whatever a block holds ("1+1+...+1").
inline constexpr int kMaxExprDepth = 1000;

// One address word: a letter and a value, either a literal number or an
// expression (X#1, X[#1+2], X-#2, G#10).
struct Word {
  char letter = 0;            // 'A'..'Z', upper case
  bool is_expr = false;
  bool has_point = false;     // literal written with a decimal point
  double value = 0.0;         // literal value (is_expr == false)
  ExprId expr = kNoExpr;      // is_expr == true
  std::uint32_t column = 0;
};

enum class StmtKind : std::uint8_t {
  kNone,
  kAssign,   // #lhs = rhs      (lhs: expression node of kind kVar/kNamedVar)
  kGoto,     // GOTO target
  kIfGoto,   // IF [cond] GOTO target
  kIfThen,   // IF [cond] THEN #lhs = rhs
  kWhile,    // WHILE [cond] DO loop
  kDo,       // DO loop (no WHILE: endless loop)
  kEnd,      // END loop
  kPopen,    // POPEN
  kPclos,    // PCLOS
  kDprnt,    // DPRNT[...]  (items in Block::print_items)
  kBprnt,    // BPRNT[...]
};

// One item of DPRNT/BPRNT: text to print, or a variable with a format.
struct PrintItem {
  bool is_text = false;
  std::int32_t text = -1;    // index into Block::names (the literal text)
  ExprId var = kNoExpr;      // expression node of kind kVar/kNamedVar
  int int_digits = 0;        // [ab]: a
  int frac_digits = 0;       //       b
};

struct Stmt {
  StmtKind kind = StmtKind::kNone;
  ExprId lhs = kNoExpr;
  ExprId rhs = kNoExpr;
  ExprId cond = kNoExpr;
  ExprId target = kNoExpr;   // GOTO target expression
  int loop = 0;              // DO/END identifier as written (1..3 on Fanuc)
  std::uint32_t column = 0;
};

struct Comment {
  std::int32_t text = -1;    // index into Block::names: the text inside ( )
  std::uint32_t column = 0;
};

struct Block {
  SourceLoc loc;                 // file, line, column of the block's first character
  std::uint64_t offset = 0;      // byte offset of the block in its file
  bool percent = false;          // the block is a '%' (tape start or end)
  int block_delete = -1;         // -1: no '/'; 1..9: '/n' ('/' alone is 1)
  bool has_n = false;
  std::int64_t n = 0;            // N sequence number
  bool has_o = false;
  std::int64_t o = 0;            // O program number at the head of the block
  std::vector<Word> words;       // in the order written
  Stmt stmt;
  std::vector<ExprNode> nodes;
  std::vector<std::string> names;      // named variables, comment texts, print texts
  std::vector<Comment> comments;
  std::vector<PrintItem> print_items;

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
  }
  // True when the block has neither words nor a statement (only comments or nothing).
  bool empty() const noexcept {
    return words.empty() && stmt.kind == StmtKind::kNone && !percent && !has_o;
  }
};

}  // namespace skipnc::gcode
