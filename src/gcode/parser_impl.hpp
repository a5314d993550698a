// Inside the block parser (not part of the gcode API): the Parser class,
// the node buffer it writes into, and the character rules. The parser's
// code is in three files: parser.cpp (numbers, words, the block),
// parser_expr.cpp (expressions, functions, variables) and parser_stmt.cpp
// (macro statements and comments). The rules it follows are described at the
// top of parser.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "core/diag.hpp"
#include "gcode/ast.hpp"
#include "gcode/parser.hpp"

namespace skipnc::gcode::detail {

// A parse function returning an ExprId returns this on error.
inline constexpr ExprId kFail = -2;

// Hard bound on nesting, whatever the limits say, so that recursion can
// never exhaust the stack.
inline constexpr int kMaxNestingHard = 512;

// Significant digits an std::uint64_t always holds.
inline constexpr int kMantissaDigits = 19;

inline constexpr std::array<double, 23> kPow10 = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                                  1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                                  1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

constexpr bool is_digit(int c) noexcept {
  return static_cast<unsigned>(c - '0') < 10u;
}
constexpr bool is_upper(int c) noexcept {
  return static_cast<unsigned>(c - 'A') < 26u;
}
// ' ', '\t' or '\r': one comparison for the characters above ' ' (nearly
// all), then their bit in a mask.
constexpr bool is_space(char c) noexcept {
  const auto u = static_cast<unsigned char>(c);
  constexpr std::uint64_t kSpaces =
      (std::uint64_t{1} << ' ') | (std::uint64_t{1} << '\t') | (std::uint64_t{1} << '\r');
  return u <= ' ' && ((kSpaces >> u) & 1u) != 0;
}
constexpr char to_upper(char c) noexcept {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - ('a' - 'A')) : c;
}
constexpr bool is_name_char(char c) noexcept {
  const char u = to_upper(c);
  return is_upper(u) || is_digit(u) || u == '_';
}
// Value of a decimal digit; 10 or more for any other character.
constexpr unsigned digit_value(char c) noexcept {
  return static_cast<unsigned>(static_cast<unsigned char>(c)) - unsigned{'0'};
}
constexpr bool is_letter(char c) noexcept {
  return static_cast<unsigned>((static_cast<unsigned char>(c) | 0x20u) - 'a') < 26u;
}
// `c` is `k` (an upper-case letter) in either case.
constexpr bool same_letter(char c, char k) noexcept {
  return (c & ~0x20) == k;
}

// The character as a user can read it in a message.
inline std::string show_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
  constexpr char kHex[] = "0123456789ABCDEF";
  std::string s = "byte 0x";
  s += kHex[u >> 4];
  s += kHex[u & 0xf];
  return s;
}

// Text of [a, b), shortened when long.
inline std::string excerpt(const char* a, const char* b) {
  constexpr std::ptrdiff_t kMax = 40;
  std::string s;
  if (b - a > kMax) {
    s.assign(a, a + kMax);
    s += "...";
  } else {
    s.assign(a, b);
  }
  return "'" + s + "'";
}

struct FuncName {
  std::string_view name;
  Func fn;
};

// The functions of one first letter (indices into the function table, parser_expr.cpp).
struct FuncGroup {
  std::uint8_t count = 0;
  std::array<std::uint8_t, 6> index{};
};

// The nodes of the block being parsed, written straight into the block's
// NodeArray: adding one is a store and a count (std::vector::push_back would
// bring its growth path into every caller). Past the storage's size it grows
// by doubling; the storage stays from block to block, so once warmed there
// is no allocation.
class NodeSlots {
 public:
  explicit NodeSlots(NodeArray& v) : v_(v) {
    v_.reserve(kInitial);
    data_ = v_.data();
    cap_ = v_.capacity();
  }
  NodeSlots(const NodeSlots&) = delete;
  NodeSlots& operator=(const NodeSlots&) = delete;
  ~NodeSlots() = default;

  ExprNode& operator[](std::size_t i) noexcept { return data_[i]; }
  const ExprNode& operator[](std::size_t i) const noexcept { return data_[i]; }
  // A new node, its fields to be written by the caller (each of them: the
  // storage holds an earlier block's nodes). References to nodes do not
  // survive it.
  ExprNode& add() {
    if (n_ == cap_) [[unlikely]] {
      grow();
    }
    return data_[n_++];
  }
  std::size_t size() const noexcept { return n_; }
  // The block's node count becomes the number of nodes built.
  void finish() noexcept { v_.set_size(n_); }

 private:
  [[gnu::noinline]] void grow() {
    v_.reserve(2 * cap_);
    data_ = v_.data();
    cap_ = v_.capacity();
  }

  static constexpr std::size_t kInitial = 64;
  static_assert(std::is_trivially_copyable_v<ExprNode> &&
                std::is_trivially_destructible_v<ExprNode>);

  NodeArray& v_;
  ExprNode* data_ = nullptr;
  std::size_t n_ = 0;
  std::size_t cap_ = 0;
};

class Parser {
 public:
  // `track_depth`: measure each tree's depth against kMaxExprDepth (see
  // depth_needed()).
  Parser(std::string_view text, SourceLoc loc, Block& out, const ParseLimits& limits,
         bool track_depth)
      : begin_(text.data()),
        p_(text.data()),
        end_(text.data() + text.size()),
        loc_(loc),
        out_(out),
        max_digits_(std::max(1, limits.max_digits)),
        uint_digits_(std::min(max_digits_, 18)),
        fast_digits_(std::min(max_digits_, kMantissaDigits)),
        max_depth_(std::clamp(limits.max_bracket_depth, 0, kMaxNestingHard)),
        ngc_(limits.syntax == Syntax::kRs274ngc),
        grbl_(limits.syntax == Syntax::kGrbl),
        conditional_m99_(limits.conditional_m99),
        track_depth_(track_depth) {
    // Typical blocks never grow the arrays past this: no reallocation while
    // the first blocks of a program are parsed.
    if (out_.words.capacity() < 16) out_.words.reserve(16);
  }

  // (run, parse_word and try_keyword are inlined into their one caller: the
  // per-block path stays one function, as it was when they shared a file.)
  [[gnu::always_inline]] Result<void> run();
  // Haas's `[expr] M99 ...`: the expression at the head of the block, then
  // (at the block's end) the check that the block holds M99.
  bool parse_condition(const char* at);
  bool check_condition(const char* at);
  // Leaves exactly the nodes built in the block (whether run() succeeded or not).
  void finish() { nodes_.finish(); }
  // A tree is at most twice as deep as it has nodes ("#n", one node, counts
  // as two levels), so a block of no more than kMaxExprDepth / 2 nodes holds
  // no tree too deep, and a parse that did not track depths gave what one
  // that did would give, error or not (that error would have come at a node
  // past that count). True when the block has more nodes than that: it is
  // to be parsed again with depths tracked.
  bool depth_needed() const noexcept {
    return !track_depth_ && nodes_.size() > static_cast<std::size_t>(kMaxExprDepth / 2);
  }

 private:
  // ---- characters
  const char* skip(const char* q) const noexcept {
    while (q < end_ && is_space(*q)) ++q;
    return q;
  }
  // Next significant character, upper-cased; -1 at the end. Moves p_ past spaces.
  int peek() noexcept {
    p_ = skip(p_);
    return p_ < end_ ? static_cast<unsigned char>(to_upper(*p_)) : -1;
  }
  // Character at q as it is written, -1 at the end.
  int at_char(const char* q) const noexcept {
    return q < end_ ? static_cast<unsigned char>(*q) : -1;
  }
  std::uint32_t col(const char* q) const noexcept {
    return loc_.column + static_cast<std::uint32_t>(q - begin_);
  }
  // Matches an upper-case keyword at p_, spaces allowed between its letters.
  bool match_kw(std::string_view kw) noexcept {
    const char* q = p_;
    // Written in one piece, the usual case: no look for spaces. A letter that
    // differs ends the match unless it is a space.
    if (static_cast<std::size_t>(end_ - q) >= kw.size()) {
      std::size_t i = 0;
      while (i < kw.size() && same_letter(q[i], kw[i])) ++i;
      if (i == kw.size()) {
        p_ = q + i;
        return true;
      }
      if (!is_space(q[i])) return false;
    }
    for (const char k : kw) {
      q = skip(q);
      if (q == end_ || !same_letter(*q, k)) return false;
      ++q;
    }
    p_ = q;
    return true;
  }

  // ---- errors (out of line: they keep the hot paths small)
  bool error(AlarmId id, std::string detail, const char* at) {
    return error_col(id, std::move(detail), col(at));
  }
  [[gnu::noinline, gnu::cold]] bool error_col(AlarmId id, std::string detail,
                                              std::uint32_t column) {
    if (!err_) {
      err_.emplace(Error{id, std::move(detail), SourceLoc{loc_.file, loc_.line, column}, -1});
    }
    return false;
  }
  [[gnu::noinline, gnu::cold]] bool too_deep(std::uint32_t column) {
    return error_col(AlarmId::kMacroFormat,
                     "expression more than " + std::to_string(kMaxExprDepth) +
                         " levels deep (operators, signs and brackets)",
                     column);
  }
  ExprId error_expr(AlarmId id, std::string detail, const char* at) {
    error(id, std::move(detail), at);
    return kFail;
  }
  // Unexpected character where `what` was expected.
  [[gnu::noinline, gnu::cold]] bool unexpected(std::string_view what, const char* at) {
    if (at >= end_) {
      return error(AlarmId::kMacroFormat, "expected " + std::string(what) + " at end of block", at);
    }
    return error(AlarmId::kMacroFormat,
                 "expected " + std::string(what) + ", found " + show_char(*at), at);
  }
  [[gnu::noinline, gnu::cold]] bool too_nested(const char* at) {
    return error(AlarmId::kBracketNesting,
                 "brackets nested deeper than " + std::to_string(max_depth_) + " levels", at);
  }
  // p_ where the ']' closing the bracket opened at `open` should be.
  [[gnu::noinline, gnu::cold]] bool not_closed(const char* open) {
    if (p_ == end_) return error(AlarmId::kBracketNesting, "'[' is not closed", open);
    return unexpected("']'", p_);
  }
  [[gnu::noinline, gnu::cold]] ExprId bad_operand(int c, const char* at);
  [[gnu::noinline, gnu::cold]] bool bad_word(char letter, const char* at, const char* sign_at);
  [[gnu::noinline, gnu::cold]] bool bad_block_char(const char* at);

  // ---- node building
  ExprNode& node(ExprId id) noexcept { return nodes_[static_cast<std::size_t>(id)]; }
  const ExprNode& node(ExprId id) const noexcept { return nodes_[static_cast<std::size_t>(id)]; }
  // Levels of the tree from a node down (0: none), while depths are tracked.
  int depth_of(ExprId id) const noexcept {
    return id >= 0 ? depths_[static_cast<std::size_t>(id)] : 0;
  }
  [[gnu::noinline]] void set_depth(ExprId id, int depth) {
    const auto i = static_cast<std::size_t>(id);
    if (depths_.size() <= i) depths_.resize(i + 1);
    depths_[i] = static_cast<std::uint16_t>(depth);
  }
  // A node whose depth is known to be within kMaxExprDepth; `kTrack`: the
  // depth is kept (track_depth_).
  template <bool kTrack>
  ExprId push_node(Op op, std::uint32_t column, ExprId a, ExprId b, int depth, double value = 0.0) {
    // Written field by field in place: no node put together aside and copied.
    ExprNode& x = nodes_.add();
    x.value = value;
    x.a = a;
    x.b = b;
    x.name = -1;
    x.column = column;
    x.op = op;
    x.fn = Func::kNone;
    const auto id = static_cast<ExprId>(nodes_.size() - 1);
    if constexpr (kTrack) set_depth(id, depth);
    return id;
  }
  ExprId push_node(Op op, std::uint32_t column, ExprId a, ExprId b, int depth, double value = 0.0) {
    if (track_depth_) [[unlikely]] {
      return push_node<true>(op, column, a, b, depth, value);
    }
    return push_node<false>(op, column, a, b, depth, value);
  }
  // kFail when the tree would be deeper than kMaxExprDepth.
  ExprId add_node(Op op, std::uint32_t column, ExprId a = kNoExpr, ExprId b = kNoExpr) {
    if (a == kFail || b == kFail) return kFail;
    if (track_depth_) [[unlikely]] {
      const int depth = 1 + std::max(depth_of(a), depth_of(b));
      if (depth > kMaxExprDepth) {
        too_deep(column);
        return kFail;
      }
      return push_node<true>(op, column, a, b, depth);
    }
    return push_node<false>(op, column, a, b, 0);
  }
  ExprId add_number(double v, std::uint32_t column) {
    return push_node(Op::kNumber, column, kNoExpr, kNoExpr, 1, v);
  }
  // "#n": one node holding n, counted two levels deep as "#[n]" is.
  ExprId add_var_number(std::int64_t n, std::uint32_t var_column) {
    return push_node(Op::kVarNum, var_column, kNoExpr, kNoExpr, 2, static_cast<double>(n));
  }
  std::int32_t add_name(std::string s) {
    out_.names.push_back(std::move(s));
    return static_cast<std::int32_t>(out_.names.size() - 1);
  }

  // ---- nesting
  bool enter(const char* at) {
    if (depth_ >= max_depth_) [[unlikely]] {
      return too_nested(at);
    }
    ++depth_;
    return true;
  }
  void leave() noexcept { --depth_; }
  // Consumes the ']' closing a bracket opened at `open`.
  bool close_bracket(const char* open) {
    p_ = skip(p_);
    if (p_ < end_ && *p_ == ']') [[likely]] {
      ++p_;
      return true;
    }
    return not_closed(open);
  }

  // ---- fast paths of the common cases, inlined where they are used

  // The number written together from `start` ("123", "1.5", ".25"), not
  // too many digits, no digit or point after the spaces that follow, exact
  // as a double: its value, whether it has a point, and `after` past those
  // spaces. False for anything else, errors included: the general path
  // reads it again.
  [[gnu::always_inline]] bool read_fast(const char* start, double& value, bool& has_point,
                                        const char*& after) const noexcept {
    const char* q = start;
    std::uint64_t mant = 0;
    for (unsigned d = 0; q < end_ && (d = digit_value(*q)) < 10; ++q) mant = mant * 10 + d;
    std::size_t frac = 0;
    const bool point = q < end_ && *q == '.';
    if (point) {
      const char* f = ++q;
      for (unsigned d = 0; q < end_ && (d = digit_value(*q)) < 10; ++q) mant = mant * 10 + d;
      frac = static_cast<std::size_t>(q - f);
    }
    const auto ndigits = (q - start) - (point ? 1 : 0);
    if (ndigits == 0) return false;  // X#1, X[...], a point alone
    after = skip(q);
    if (ndigits > fast_digits_ || mant > (std::uint64_t{1} << 53) ||
        (after < end_ && (*after == '.' || is_digit(*after)))) [[unlikely]] {
      return false;
    }
    has_point = point;
    // As number_value: at most 19 decimals, a power of ten held exactly.
    value = frac == 0 ? static_cast<double>(mant) : static_cast<double>(mant) / kPow10[frac];
    return true;
  }
  // A number at p_ as read_fast takes it: its value, p_ past it and the
  // spaces that follow. False, nothing consumed, for anything else.
  [[gnu::always_inline]] bool number_fast(double& value, bool& has_point) {
    const char* after = nullptr;
    if (!read_fast(p_, value, has_point, after)) return false;
    p_ = after;
    return true;
  }
  // The common word, written together: the letter `c` (upper case) at `at`,
  // an optional sign right after it, then a number read_fast takes ("X-12.345",
  // "G1", "F500."). The same value and Word as parse_word's; p_ past it and
  // the spaces that follow. False, nothing consumed, for anything else (a
  // keyword, an expression, a space inside, too many digits): parse_word
  // reads it.
  [[gnu::always_inline]] bool word_fast(int c, const char* at) {
    const char* q = at + 1;
    if (q == end_) return false;
    bool negative = false;
    if (digit_value(*q) >= 10) {
      if (*q == '-' || *q == '+') {
        negative = *q == '-';
        ++q;
      } else if (*q != '.') {
        return false;  // X#1, X[...], a keyword, a space
      }
    }
    double v = 0.0;
    bool point = false;
    const char* after = nullptr;
    if (!read_fast(q, v, point, after)) return false;
    p_ = after;
    Word& w = out_.words.emplace_back();
    w.letter = static_cast<char>(c);
    w.is_expr = false;
    w.has_point = point;
    w.value = negative ? -v : v;
    w.expr = kNoExpr;
    w.column = col(at);
    return true;
  }
  // "#n" at `at` written together, few enough digits to be no error, no
  // digit or point after the spaces that follow: n, and `after` past those
  // spaces. False for anything else: the general path reads it.
  [[gnu::always_inline]] bool read_var_fast(const char* at, std::int64_t& n,
                                            const char*& after) const noexcept {
    const char* const d = at + 1;
    const char* const lim = d + std::min<std::ptrdiff_t>(end_ - d, uint_digits_);
    const char* q = d;
    std::int64_t v = 0;
    for (unsigned k = 0; q < lim && (k = digit_value(*q)) < 10; ++q) v = v * 10 + k;
    if (q == d) [[unlikely]] {
      return false;
    }
    after = skip(q);
    if (after < end_ && (is_digit(*after) || *after == '.')) [[unlikely]] {
      return false;
    }
    n = v;
    return true;
  }
  // "#n" at p_ as read_var_fast takes it: its node, p_ past it and the
  // spaces that follow. False, nothing consumed, for anything else.
  [[gnu::always_inline]] bool var_number_fast(ExprId& id) {
    const char* const at = p_;
    std::int64_t v = 0;
    const char* after = nullptr;
    if (!read_var_fast(at, v, after)) return false;
    p_ = after;
    id = add_var_number(v, col(at));
    return true;
  }
  // A lone "#n" or number the fast readers take, then ']' (SIN[#12],
  // ABS[2.5]): its node, p_ at the ']'. kNoExpr, nothing consumed, for
  // anything else: parse_expr reads it, to the same node.
  [[gnu::always_inline]] ExprId lone_operand() {
    const char* const at = skip(p_);
    if (at == end_) return kNoExpr;
    const char* after = nullptr;
    if (*at == '#') {
      std::int64_t v = 0;
      if (!read_var_fast(at, v, after) || after == end_ || *after != ']') return kNoExpr;
      p_ = after;
      return add_var_number(v, col(at));
    }
    double x = 0.0;
    bool point = false;
    if (!read_fast(at, x, point, after) || after == end_ || *after != ']') return kNoExpr;
    p_ = after;
    return add_number(x, col(at));
  }

  // ---- literals

  // Number literal at p_ (digit or '.'): digits with at most one point,
  // spaces ignored. Exact for up to 15 significant digits and 22 decimals.
  [[gnu::always_inline]] bool parse_number(double& value, bool& has_point) {
    return number_fast(value, has_point) || parse_number_slow(value, has_point);
  }
  bool parse_number_slow(double& value, bool& has_point);
  bool number_value(std::uint64_t mant, int exp10, const char* start, double& value);
  bool parse_uint(std::int64_t& value, std::string_view what, bool& any);
  [[gnu::always_inline]] bool parse_word();
  bool parse_head();
  bool parse_sequence_number(bool strict);

  // ---- expressions
  ExprId parse_expr() {
    if (track_depth_) [[unlikely]] {
      return parse_expr_t<true>();
    }
    return parse_expr_t<false>();
  }
  template <bool kTrack>
  ExprId parse_expr_t();
  [[gnu::always_inline]] int binary_op(Op& op);  // inlined into parse_expr's loop
  [[gnu::always_inline]] int binary_op_fanuc(Op& op);
  ExprId parse_number_node();   // p_ at a digit or '.'
  ExprId parse_operand(int c);  // the cases parse_expr leaves: signs, functions, errors
  ExprId parse_signed();        // p_ at a sign
  ExprId parse_primary(int c);  // c: the upper-cased character at p_
  ExprId parse_bracket();       // p_ at '['
  const FuncName* find_function(int c);
  [[gnu::always_inline]] const FuncName* find_function_here(int c);  // parser_expr.cpp
  [[gnu::noinline]] const FuncName* find_function_spaced(const FuncGroup& g);
  ExprId parse_function(Func fn, const char* at);
  ExprId parse_var(bool raw);  // p_ at '#'
  ExprId parse_var_general(bool raw);
  bool parse_named(std::string& name, bool raw);

  // ---- statements
  bool begin_stmt(StmtKind kind, const char* at);
  bool parse_grbl_system(const char* at);
  bool parse_assign_tail(ExprId lhs);
  bool parse_goto_target();
  bool parse_loop_number(std::string_view what);
  bool parse_if(const char* at);
  bool parse_while(const char* at);
  bool parse_print(StmtKind kind, const char* at);
  bool parse_comment();
  bool parse_oword(const char* at);
  [[gnu::always_inline]] bool parse_olabel(std::string& label, ExprId& computed,
                                           std::int64_t& number);
  [[gnu::always_inline]] bool parse_oword_args(OKind kind);
  bool parse_ngc_assign();
  ExprId ngc_word_function(char c);
  [[gnu::noinline]] int ngc_precedence(Op op) const noexcept;
  [[gnu::always_inline]] bool try_keyword(int c, const char* at, bool& handled);

  const char* begin_;
  const char* p_;
  const char* end_;
  SourceLoc loc_;
  Block& out_;
  int max_digits_;
  int uint_digits_;  // digits of an unsigned integer (N, O, #n, ...)
  int fast_digits_;  // digits of a number that can be neither too many nor inexact
  int max_depth_;
  bool ngc_;              // RS274NGC: O-words, several parameter settings, ';' comments, '**'
  bool grbl_;             // grbl: numbers only, no parameters or expressions
  bool conditional_m99_;  // `[expr] M99` (Haas)
  const char* condition_at_ = nullptr;  // its '['
  int depth_ = 0;
  NodeSlots nodes_{out_.nodes};
  const bool track_depth_;
  std::vector<std::uint16_t> depths_;  // by node, while track_depth_
  std::optional<Error> err_;           // the first error
};

// Both are compiled once, in parser_expr.cpp.
extern template ExprId Parser::parse_expr_t<false>();
extern template ExprId Parser::parse_expr_t<true>();

}  // namespace skipnc::gcode::detail
