// Block parser: one pass over the text of a block, no allocation on the
// normal path once the block's arrays have grown, no exceptions.
//
// Fanuc rules followed here:
//  - outside comments, case does not matter (letters are upper-cased) and
//    spaces and tabs are ignored everywhere, also inside numbers and keywords
//    ("G 0 1", "GO TO 10", "X 1 0 .5");
//  - inside DPRNT/BPRNT text, spaces are significant and '*' prints a space;
//  - precedence, highest first: functions and brackets, unary sign,
//    * / MOD AND, + - OR XOR, EQ NE GT GE LT LE.
//
// For speed (programs are mostly "X-12.5" and "#3=[#1*SIN[#2]+1.]"):
// expressions are read by precedence climbing, one loop per bracket level
// rather than one function per precedence level; "#n", numbers and function
// names written the usual way have fast paths, and anything else (spaces
// inside, many digits, errors) goes back to the general code, which reads
// it again from its start; nodes are built in a local buffer; error
// messages are built out of line.
#include "gcode/parser.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <ranges>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <vector>

namespace skipnc::gcode {
namespace {

// A parse function returning an ExprId returns this on error.
constexpr ExprId kFail = -2;

// Hard bound on nesting, whatever the limits say, so that recursion can
// never exhaust the stack.
constexpr int kMaxNestingHard = 512;

// Significant digits an std::uint64_t always holds.
constexpr int kMantissaDigits = 19;

constexpr std::array<double, 23> kPow10 = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                           1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                           1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

constexpr bool is_digit(int c) noexcept {
  return static_cast<unsigned>(c - '0') < 10u;
}
constexpr bool is_upper(int c) noexcept {
  return static_cast<unsigned>(c - 'A') < 26u;
}
constexpr bool is_space(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\r';
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
std::string show_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
  constexpr char kHex[] = "0123456789ABCDEF";
  std::string s = "byte 0x";
  s += kHex[u >> 4];
  s += kHex[u & 0xf];
  return s;
}

// Text of [a, b), shortened when long.
std::string excerpt(const char* a, const char* b) {
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

// Longer names before their prefixes (SQRT before SQR).
constexpr std::array<FuncName, 20> kFuncs = {{
    {"SIN", Func::kSin},   {"COS", Func::kCos},   {"TAN", Func::kTan},     {"ASIN", Func::kAsin},
    {"ACOS", Func::kAcos}, {"ATAN", Func::kAtan}, {"ATN", Func::kAtan},    {"SQRT", Func::kSqrt},
    {"SQR", Func::kSqrt},  {"ABS", Func::kAbs},   {"ROUND", Func::kRound}, {"RND", Func::kRound},
    {"FIX", Func::kFix},   {"FUP", Func::kFup},   {"LN", Func::kLn},       {"EXP", Func::kExp},
    {"POW", Func::kPow},   {"BIN", Func::kBin},   {"BCD", Func::kBcd},     {"ADP", Func::kAdp},
}};

// The functions of kFuncs by first letter, in kFuncs order.
struct FuncGroup {
  std::uint8_t count = 0;
  std::array<std::uint8_t, 6> index{};
};
constexpr std::array<FuncGroup, 26> make_func_groups() {
  std::array<FuncGroup, 26> g{};
  for (std::size_t i = 0; i < kFuncs.size(); ++i) {
    FuncGroup& f = g[static_cast<std::size_t>(kFuncs[i].name[0] - 'A')];
    f.index[f.count++] = static_cast<std::uint8_t>(i);
  }
  return g;
}
constexpr std::array<FuncGroup, 26> kFuncGroups = make_func_groups();

// Letters of a name packed in an integer, the first one lowest.
constexpr std::uint64_t name_key(std::string_view name) {
  std::uint64_t k = 0;
  for (std::size_t i = 0; i < name.size(); ++i) {
    k |= std::uint64_t{static_cast<unsigned char>(name[i])} << (8 * i);
  }
  return k;
}
constexpr std::size_t kMaxFuncName = 5;  // ROUND
constexpr std::array<std::uint64_t, kFuncs.size()> make_func_keys() {
  std::array<std::uint64_t, kFuncs.size()> k{};
  for (std::size_t i = 0; i < kFuncs.size(); ++i) k[i] = name_key(kFuncs[i].name);
  return k;
}
constexpr std::array<std::uint64_t, kFuncs.size()> kFuncKeys = make_func_keys();
// The bytes of each name in its key.
constexpr std::array<std::uint64_t, kFuncs.size()> make_func_masks() {
  std::array<std::uint64_t, kFuncs.size()> m{};
  for (std::size_t i = 0; i < kFuncs.size(); ++i) {
    m[i] = (std::uint64_t{1} << (8 * kFuncs[i].name.size())) - 1;
  }
  return m;
}
constexpr std::array<std::uint64_t, kFuncs.size()> kFuncMasks = make_func_masks();
static_assert(std::ranges::all_of(kFuncs,
                                  [](const FuncName& f) { return f.name.size() <= kMaxFuncName; }));

// Expression trees of a variable reference "#n" are two levels deep.
static_assert(kMaxExprDepth >= 2);

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
  // Index of the node added. References to nodes do not survive it.
  std::size_t add(const ExprNode& x) {
    if (n_ == cap_) [[unlikely]] {
      grow();
    }
    data_[n_] = x;
    return n_++;
  }
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
  Parser(std::string_view text, SourceLoc loc, Block& out, const ParseLimits& limits)
      : begin_(text.data()),
        p_(text.data()),
        end_(text.data() + text.size()),
        loc_(loc),
        out_(out),
        max_digits_(std::max(1, limits.max_digits)),
        uint_digits_(std::min(max_digits_, 18)),
        fast_digits_(std::min(max_digits_, kMantissaDigits)),
        max_depth_(std::clamp(limits.max_bracket_depth, 0, kMaxNestingHard)) {
    // Typical blocks never grow the arrays past this: no reallocation while
    // the first blocks of a program are parsed.
    if (out_.words.capacity() < 16) out_.words.reserve(16);
  }

  Result<void> run();
  // Leaves exactly the nodes built in the block (whether run() succeeded or not).
  void finish() { nodes_.finish(); }

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
  int depth_of(ExprId id) const noexcept { return id >= 0 ? node(id).depth : 0; }
  ExprNode& node(ExprId id) noexcept { return nodes_[static_cast<std::size_t>(id)]; }
  const ExprNode& node(ExprId id) const noexcept { return nodes_[static_cast<std::size_t>(id)]; }
  // A node whose depth is known to be within kMaxExprDepth.
  ExprId push_node(Op op, std::uint32_t column, ExprId a, ExprId b, int depth, double value = 0.0) {
    return static_cast<ExprId>(nodes_.add(ExprNode{.value = value,
                                                   .a = a,
                                                   .b = b,
                                                   .column = column,
                                                   .depth = static_cast<std::uint16_t>(depth),
                                                   .op = op}));
  }
  // kFail when the tree would be deeper than kMaxExprDepth.
  ExprId add_node(Op op, std::uint32_t column, ExprId a = kNoExpr, ExprId b = kNoExpr) {
    if (a == kFail || b == kFail) return kFail;
    const int depth = 1 + std::max(depth_of(a), depth_of(b));
    if (depth > kMaxExprDepth) [[unlikely]] {
      too_deep(column);
      return kFail;
    }
    return push_node(op, column, a, b, depth);
  }
  ExprId add_number(double v, std::uint32_t column) {
    return push_node(Op::kNumber, column, kNoExpr, kNoExpr, 1, v);
  }
  // "#n": the number node, then the variable node.
  ExprId add_var_number(std::int64_t n, std::uint32_t num_column, std::uint32_t var_column) {
    const ExprId num = add_number(static_cast<double>(n), num_column);
    return push_node(Op::kVar, var_column, num, kNoExpr, 2);
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

  // A number at p_ written together ("123", "1.5", ".25"), not too many
  // digits, no digit or point after the spaces that follow, exact as a
  // double: its value, p_ past it and those spaces. False, nothing consumed,
  // for anything else, errors included: the general path reads it again.
  [[gnu::always_inline]] bool number_fast(double& value, bool& has_point) {
    const char* const start = p_;
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
    const char* after = skip(q);
    if (ndigits == 0 || ndigits > fast_digits_ || mant > (std::uint64_t{1} << 53) ||
        (after < end_ && (*after == '.' || is_digit(*after)))) [[unlikely]] {
      return false;
    }
    p_ = after;
    has_point = point;
    // As number_value: at most 19 decimals, a power of ten held exactly.
    value = frac == 0 ? static_cast<double>(mant) : static_cast<double>(mant) / kPow10[frac];
    return true;
  }
  // "#n" at p_ written together, few enough digits to be no error, no digit
  // or point after the spaces that follow: its nodes, p_ past it and those
  // spaces. False, nothing consumed, for anything else.
  [[gnu::always_inline]] bool var_number_fast(ExprId& id) {
    const char* const at = p_;
    const char* const d = at + 1;
    const char* const lim = d + std::min<std::ptrdiff_t>(end_ - d, uint_digits_);
    const char* q = d;
    std::int64_t v = 0;
    for (unsigned k = 0; q < lim && (k = digit_value(*q)) < 10; ++q) v = v * 10 + k;
    if (q == d) [[unlikely]] {
      return false;
    }
    const char* after = skip(q);
    if (after < end_ && (is_digit(*after) || *after == '.')) [[unlikely]] {
      return false;
    }
    p_ = after;
    id = add_var_number(v, col(d), col(at));
    return true;
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
  bool parse_word();
  bool parse_head();

  // ---- expressions
  ExprId parse_expr();
  int binary_op(Op& op);
  ExprId parse_number_node();   // p_ at a digit or '.'
  ExprId parse_operand(int c);  // the cases parse_expr leaves: signs, functions, errors
  ExprId parse_signed();        // p_ at a sign
  ExprId parse_primary(int c);  // c: the upper-cased character at p_
  ExprId parse_bracket();       // p_ at '['
  const FuncName* find_function(int c);
  [[gnu::noinline]] const FuncName* find_function_spaced(const FuncGroup& g);
  ExprId parse_function(Func fn, const char* at);
  ExprId parse_var(bool raw);  // p_ at '#'
  ExprId parse_var_general(bool raw);
  bool parse_named(std::string& name, bool raw);

  // ---- statements
  bool begin_stmt(StmtKind kind, const char* at);
  bool parse_assign_tail(ExprId lhs);
  bool parse_goto_target();
  bool parse_loop_number(std::string_view what);
  bool parse_if(const char* at);
  bool parse_while(const char* at);
  bool parse_print(StmtKind kind, const char* at);
  bool parse_comment();
  bool try_keyword(int c, const char* at, bool& handled);

  const char* begin_;
  const char* p_;
  const char* end_;
  SourceLoc loc_;
  Block& out_;
  int max_digits_;
  int uint_digits_;  // digits of an unsigned integer (N, O, #n, ...)
  int fast_digits_;  // digits of a number that can be neither too many nor inexact
  int max_depth_;
  int depth_ = 0;
  NodeSlots nodes_{out_.nodes};
  std::optional<Error> err_;  // the first error
};

// The general case of parse_number.
bool Parser::parse_number_slow(double& value, bool& has_point) {
  const char* start = p_;
  std::uint64_t mant = 0;
  int exp10 = 0;  // value = mant * 10^exp10
  int nsig = 0;   // significant digits seen (leading zeros excluded)
  int ndigits = 0;
  has_point = false;
  const char* q = p_;
  for (;;) {
    // A run of digits, the common case, without looking for spaces.
    for (; q < end_ && is_digit(*q); ++q) {
      const auto d = static_cast<std::uint64_t>(*q - '0');
      ++ndigits;
      if (nsig == 0 && d == 0) {
        if (has_point) --exp10;
        continue;
      }
      if (++nsig > max_digits_) {
        const char* e = q + 1;
        while (e < end_ && (is_digit(*e) || *e == '.' || is_space(*e))) ++e;
        return error(AlarmId::kTooManyDigits,
                     "number " + excerpt(start, e) + " has more than " +
                         std::to_string(max_digits_) + " significant digits",
                     start);
      }
      if (nsig <= kMantissaDigits) {
        mant = mant * 10 + d;
        if (has_point) --exp10;
      } else if (!has_point) {
        ++exp10;
      }
    }
    p_ = q;
    q = skip(q);
    if (q == end_) break;
    if (*q == '.') {
      if (has_point) {
        return error(AlarmId::kBadDecimalPoint, "second decimal point in " + excerpt(start, q + 1),
                     q);
      }
      has_point = true;
      p_ = ++q;
    } else if (!is_digit(*q)) {
      break;
    }
  }
  if (ndigits == 0) return error(AlarmId::kNoValue, "decimal point without digits", start);
  return number_value(mant, exp10, start, value);
}

// value = mant * 10^exp10, correctly rounded. p_ is at the end of the number
// written from `start`.
bool Parser::number_value(std::uint64_t mant, int exp10, const char* start, double& value) {
  if (exp10 == 0 && mant <= (std::uint64_t{1} << 53)) {
    value = static_cast<double>(mant);  // integers: no division
  } else if (mant == 0) {
    value = 0.0;
  } else if (exp10 < 0 && exp10 >= -22 && mant <= (std::uint64_t{1} << 53)) {
    value = static_cast<double>(mant) / kPow10[static_cast<std::size_t>(-exp10)];
  } else if (exp10 >= 0 && exp10 <= 22 && mant <= (std::uint64_t{1} << 53)) {
    value = static_cast<double>(mant) * kPow10[static_cast<std::size_t>(exp10)];
  } else {
    // Rare: let the library round "mant e exp10" correctly.
    std::array<char, 48> buf{};
    char* w = std::to_chars(buf.data(), buf.data() + 24, mant).ptr;
    *w++ = 'e';
    w = std::to_chars(w, buf.data() + buf.size(), exp10).ptr;
    const auto r = std::from_chars(buf.data(), w, value);
    if (r.ec == std::errc::result_out_of_range) {
      if (exp10 < 0) {
        value = 0.0;
      } else {
        return error(AlarmId::kTooManyDigits, "number " + excerpt(start, p_) + " is too large",
                     start);
      }
    }
  }
  return true;
}

// Unsigned integer at p_ (N, O, loop numbers, variable numbers, GOTO n).
// `any` tells whether there was a digit at all; a point or a sign is an error.
bool Parser::parse_uint(std::int64_t& value, std::string_view what, bool& any) {
  const char* start = p_;
  const int limit = uint_digits_;
  std::int64_t v = 0;
  int nsig = 0;
  any = false;
  for (;;) {
    const char* q = skip(p_);
    if (q == end_) break;
    const char c = *q;
    if (is_digit(c)) {
      any = true;
      if (v != 0 || c != '0') {
        if (++nsig > limit) {
          const char* e = q + 1;
          while (e < end_ && (is_digit(*e) || is_space(*e))) ++e;
          return error(AlarmId::kTooManyDigits,
                       std::string(what) + " " + excerpt(start, e) + " has more than " +
                           std::to_string(limit) + " digits",
                       start);
        }
      }
      v = v * 10 + (c - '0');
      p_ = q + 1;
    } else if (c == '.' && any) {
      return error(AlarmId::kBadDecimalPoint, std::string(what) + " cannot have a decimal point",
                   q);
    } else {
      break;
    }
  }
  value = v;
  return true;
}

// Head of the block: '%', '/n', 'O' or ':' program number, 'N' sequence number.
bool Parser::parse_head() {
  int c = peek();
  if (c == '%') {
    out_.percent = true;
    ++p_;
    return true;
  }
  if (c == '/') {
    ++p_;
    out_.block_delete = 1;
    c = peek();
    if (is_digit(c)) {
      if (c == '0') return error(AlarmId::kIllegalChar, "block delete switch /0 (use /1../9)", p_);
      out_.block_delete = c - '0';
      ++p_;
      c = peek();
    }
  }
  if (c == 'O' || c == ':') {
    const char* at = p_;
    ++p_;
    const int v = peek();
    if (v == '-' || v == '+') return error(AlarmId::kBadSign, "program number with a sign", p_);
    bool any = false;
    if (!parse_uint(out_.o, "program number", any)) return false;
    if (!any) return error(AlarmId::kNoValue, "program number is missing after 'O'", at);
    out_.has_o = true;
    c = peek();
  }
  if (c == 'N') {
    const char* at = p_;
    ++p_;
    const int v = peek();
    if (v == '-' || v == '+') return error(AlarmId::kBadSign, "sequence number with a sign", p_);
    if (v == '#' || v == '[') {
      return error(AlarmId::kMacroFormat, "sequence number must be a constant", p_);
    }
    bool any = false;
    if (!parse_uint(out_.n, "sequence number", any)) return false;
    if (!any) return error(AlarmId::kNoValue, "'N' has no value", at);
    out_.has_n = true;
  }
  return true;
}

// Address word at p_ (a letter): X10, X-.5, X#1, X-#2, X[#1+2], X-[#1].
bool Parser::parse_word() {
  const char* const at = p_;
  const char* q = skip(at + 1);
  int c = at_char(q);
  const char* sign_at = nullptr;
  if (c == '-' || c == '+') {
    sign_at = q;
    q = skip(q + 1);
    c = at_char(q);
  }
  p_ = q;
  const bool negative = sign_at != nullptr && *sign_at == '-';
  double value = 0.0;
  bool point = false;
  ExprId e = kNoExpr;
  if (is_digit(c) || c == '.') {
    if (!parse_number(value, point)) return false;
    if (negative) value = -value;
  } else if (c == '#' || c == '[') {
    e = c == '#' ? parse_var(false) : parse_bracket();
    if (e == kFail) return false;
    if (negative) e = add_node(Op::kNeg, col(sign_at), e);
    if (e == kFail) return false;
  } else {
    return bad_word(to_upper(*at), at, sign_at);
  }
  // Built in place: a Word put together on the stack and copied would be
  // read back before its stores complete (store forwarding).
  Word& w = out_.words.emplace_back();
  w.letter = to_upper(*at);
  w.is_expr = e != kNoExpr;
  w.has_point = point;
  w.value = value;
  w.expr = e;
  w.column = col(at);
  return true;
}

// A letter not followed by a value (p_ where the value should be).
bool Parser::bad_word(char letter, const char* at, const char* sign_at) {
  if (sign_at != nullptr) {
    return error(AlarmId::kBadSign,
                 std::string("sign after '") + letter + "' is not followed by a value", sign_at);
  }
  return error(AlarmId::kNoValue, std::string("'") + letter + "' has no value", at);
}

// ---- expressions

// Binary operator at p_, consumed. Returns its precedence, 3 for * / MOD
// AND, 2 for + - OR XOR, 1 for the comparisons; 0, consuming nothing, when
// there is none.
int Parser::binary_op(Op& op) {
  if (p_ == end_) return 0;
  switch (*p_) {
    case '*':
      op = Op::kMul;
      ++p_;
      return 3;
    case '/':
      op = Op::kDiv;
      ++p_;
      return 3;
    case '+':
      op = Op::kAdd;
      ++p_;
      return 2;
    case '-':
      op = Op::kSub;
      ++p_;
      return 2;
    case 'M':
    case 'm':
      op = Op::kMod;
      return match_kw("MOD") ? 3 : 0;
    case 'A':
    case 'a':
      op = Op::kAnd;
      return match_kw("AND") ? 3 : 0;
    case 'O':
    case 'o':
      op = Op::kOr;
      return match_kw("OR") ? 2 : 0;
    case 'X':
    case 'x':
      op = Op::kXor;
      return match_kw("XOR") ? 2 : 0;
    case 'E':
    case 'e':
      op = Op::kEq;
      return match_kw("EQ") ? 1 : 0;
    case 'N':
    case 'n':
      op = Op::kNe;
      return match_kw("NE") ? 1 : 0;
    case 'G':
    case 'g':
      if (match_kw("GT")) {
        op = Op::kGt;
        return 1;
      }
      op = Op::kGe;
      return match_kw("GE") ? 1 : 0;
    case 'L':
    case 'l':
      if (match_kw("LT")) {
        op = Op::kLt;
        return 1;
      }
      op = Op::kLe;
      return match_kw("LE") ? 1 : 0;
    default:
      return 0;
  }
}

// Operators by precedence climbing: operands are read in a loop, and the
// operators waiting for their right-hand side are kept on a small stack, at
// most one per precedence level. Binary operators group from the left; a
// binary node's column is that of its left operand's first character.
ExprId Parser::parse_expr() {
  struct Pending {
    ExprId lhs;
    std::uint32_t start;  // column of lhs
    std::uint16_t depth;  // of lhs
    Op op;
    std::uint8_t prec;
  };
  std::array<Pending, 3> stack;
  std::size_t n = 0;
  for (;;) {
    // An operand; p_ then at the next significant character.
    const char* const at = skip(p_);
    p_ = at;
    const int c = at_char(at);
    ExprId a = kFail;
    int depth = 1;  // of a
    if (c == '#') {
      if (var_number_fast(a)) {
        depth = 2;
      } else {
        a = parse_var_general(false);
        if (a == kFail) return kFail;
        depth = depth_of(a);
        p_ = skip(p_);
      }
    } else if (is_digit(c) || c == '.') {
      double v = 0.0;
      bool point = false;
      if (number_fast(v, point)) {
        a = add_number(v, col(at));
      } else {
        a = parse_number_node();
        if (a == kFail) return kFail;
        p_ = skip(p_);
      }
    } else if (c == '[') {
      if (!enter(at)) return kFail;
      ++p_;
      a = parse_expr();
      if (a == kFail || !close_bracket(at)) return kFail;
      leave();
      depth = depth_of(a);
      p_ = skip(p_);
    } else {
      const FuncName* f = nullptr;
      if (is_upper(c & ~0x20)) f = find_function(c & ~0x20);
      a = f != nullptr ? parse_function(f->fn, at) : parse_operand(c);
      if (a == kFail) return kFail;
      depth = depth_of(a);
      p_ = skip(p_);
    }
    // The next operator; the waiting ones that bind at least as tightly get
    // their right-hand side.
    std::uint32_t start = col(at);
    Op op = Op::kNumber;
    const int prec = binary_op(op);
    while (n > 0 && stack[n - 1].prec >= prec) {
      const Pending& t = stack[--n];
      depth = 1 + std::max<int>(t.depth, depth);
      if (depth > kMaxExprDepth) [[unlikely]] {
        too_deep(t.start);
        return kFail;
      }
      a = push_node(t.op, t.start, t.lhs, a, depth);
      start = t.start;
    }
    if (prec == 0) return a;
    stack[n++] =
        Pending{a, start, static_cast<std::uint16_t>(depth), op, static_cast<std::uint8_t>(prec)};
  }
}

ExprId Parser::parse_number_node() {
  const char* at = p_;
  double v = 0.0;
  bool point = false;
  if (!parse_number(v, point)) return kFail;
  return add_number(v, col(at));
}

// `c`: the character at p_ as written.
ExprId Parser::parse_operand(int c) {
  if (c == '-' || c == '+') return parse_signed();
  return parse_primary(c < 0 ? c : static_cast<unsigned char>(to_upper(static_cast<char>(c))));
}

// Signs are read in a loop (no recursion): "- - -#1" is three kNeg nodes
// chained through their `a`, the last one pointing at the operand.
ExprId Parser::parse_signed() {
  ExprId first = kNoExpr;
  ExprId last = kNoExpr;
  int c = peek();
  for (; c == '-' || c == '+'; c = peek()) {
    if (c == '-') {
      const ExprId n = add_node(Op::kNeg, col(p_));
      if (last == kNoExpr) {
        first = n;
      } else {
        node(last).a = n;
      }
      last = n;
    }
    ++p_;
  }
  const ExprId operand = parse_primary(c);
  if (operand == kFail) return kFail;
  if (last == kNoExpr) return operand;
  node(last).a = operand;
  // The chain's depths, now that its operand is known.
  int signs = 0;
  for (ExprId i = first; i != operand; i = node(i).a) ++signs;
  int depth = signs + depth_of(operand);
  if (depth > kMaxExprDepth) {
    too_deep(node(first).column);
    return kFail;
  }
  for (ExprId i = first; i != operand; i = node(i).a) {
    node(i).depth = static_cast<std::uint16_t>(depth--);
  }
  return first;
}

// The function whose name is at p_ (`c`: its first letter, upper-cased),
// p_ past the name; nullptr, p_ unchanged, when there is none.
const FuncName* Parser::find_function(int c) {
  const FuncGroup& g = kFuncGroups[static_cast<std::size_t>(c - 'A')];
  // The letters written together at p_, up to the longest name. Unless a
  // space follows them (a name may be spelt "S I N"), the function is the
  // first of its group whose name they begin with, as match_kw would find.
  const char* const at = p_;
  const auto max = std::min(static_cast<std::size_t>(end_ - at), kMaxFuncName);
  std::size_t n = 1;
  while (n < max && is_letter(at[n])) ++n;
  if (n < kMaxFuncName && at + n != end_ && is_space(at[n])) [[unlikely]] {
    return find_function_spaced(g);
  }
  // The bytes at p_ with letters upper-cased. A name is letters only, so
  // the bytes after the n letters can never match one.
  std::uint64_t key = 0;
  if (end_ - at >= 8) {
    std::memcpy(&key, at, 8);
    if constexpr (std::endian::native == std::endian::big) key = std::byteswap(key);
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      key |= std::uint64_t{static_cast<unsigned char>(at[i])} << (8 * i);
    }
  }
  key &= 0xDFDFDFDFDFDFDFDFu;  // upper case: n letters, then anything
  for (std::size_t i = 0; i < g.count; ++i) {
    const std::size_t f = g.index[i];
    // Equal bytes are letters: the name is among the n letters.
    if ((key & kFuncMasks[f]) == kFuncKeys[f]) {
      p_ = at + kFuncs[f].name.size();
      return &kFuncs[f];
    }
  }
  return nullptr;
}

// find_function() when the name may have spaces in it.
const FuncName* Parser::find_function_spaced(const FuncGroup& g) {
  for (std::size_t i = 0; i < g.count; ++i) {
    const FuncName& f = kFuncs[g.index[i]];
    if (match_kw(f.name)) return &f;
  }
  return nullptr;
}

// `c`: the upper-cased character at p_.
ExprId Parser::parse_primary(int c) {
  if (c == '#') return parse_var(false);
  if (is_digit(c) || c == '.') return parse_number_node();
  if (c == '[') return parse_bracket();
  if (is_upper(c)) {
    const char* at = p_;
    const FuncName* f = find_function(c);
    if (f != nullptr) return parse_function(f->fn, at);
  }
  return bad_operand(c, p_);
}

// No operand at `at` (`c`: its upper-cased character).
ExprId Parser::bad_operand(int c, const char* at) {
  if (is_upper(c)) {
    const char* e = at;
    while (e < end_ && (is_name_char(*e) || is_space(*e))) ++e;
    return error_expr(AlarmId::kMacroFormat, "unknown function or operator " + excerpt(at, e), at);
  }
  if (c < 0) return error_expr(AlarmId::kMacroFormat, "expression ends too early", at);
  if (c == ']') return error_expr(AlarmId::kMacroFormat, "operand missing before ']'", at);
  return error_expr(AlarmId::kMacroFormat, "expected a value, found " + show_char(*at), at);
}

ExprId Parser::parse_bracket() {
  const char* open = p_;
  if (!enter(open)) return kFail;
  ++p_;
  const ExprId e = parse_expr();
  if (e == kFail || !close_bracket(open)) return kFail;
  leave();
  return e;
}

// p_ just after the function name.
ExprId Parser::parse_function(Func fn, const char* at) {
  if (peek() != '[') {
    unexpected("'[' after the function name", p_);
    return kFail;
  }
  const char* open = p_;
  if (!enter(open)) return kFail;
  ++p_;
  const ExprId a = parse_expr();
  if (a == kFail) return kFail;
  ExprId b = kNoExpr;
  if (peek() == ',') {
    if (fn != Func::kAtan && fn != Func::kPow) {
      return error_expr(AlarmId::kMacroFormat, "this function takes one argument", p_);
    }
    ++p_;
    b = parse_expr();
    if (b == kFail) return kFail;
  }
  if (!close_bracket(open)) return kFail;
  leave();
  if (fn == Func::kAtan && b == kNoExpr) {
    // Fanuc form ATAN[a]/[b]: a '/' directly followed by '['.
    const char* q = skip(p_);
    if (q < end_ && *q == '/') {
      const char* r = skip(q + 1);
      if (r < end_ && *r == '[') {
        p_ = r;
        b = parse_bracket();
        if (b == kFail) return kFail;
      }
    }
  }
  if (fn == Func::kPow && b == kNoExpr) {
    return error_expr(AlarmId::kMacroFormat, "POW needs two arguments: POW[a,b]", at);
  }
  const ExprId n = add_node(Op::kFunc, col(at), a, b);
  if (n == kFail) return kFail;
  node(n).fn = fn;
  return n;
}

// Name after "#<" or "#_" (p_ at '<' or '_'). Upper-cased, spaces dropped.
// "#_NAME[i]" keeps the index text in the name. `raw`: inside DPRNT text,
// where a space ends the name.
bool Parser::parse_named(std::string& name, bool raw) {
  const char* at = p_;
  name.clear();
  if (*p_ == '<') {
    ++p_;
    for (;;) {
      if (p_ == end_) return error(AlarmId::kMacroFormat, "'#<' name is not closed by '>'", at);
      const char c = *p_++;
      if (c == '>') break;
      if (is_space(c)) continue;
      const auto u = static_cast<unsigned char>(c);
      if (u < 0x21 || u > 0x7e || c == '<' || c == '(' || c == ')') {
        return error(AlarmId::kIllegalChar, show_char(c) + " in a variable name", p_ - 1);
      }
      name += to_upper(c);
    }
    if (name.empty()) return error(AlarmId::kMacroFormat, "empty variable name '#<>'", at);
    return true;
  }
  // '_' name: letters, digits, '_' written together, then an optional index.
  while (p_ < end_ && is_name_char(*p_)) name += to_upper(*p_++);
  if (name.size() < 2) return error(AlarmId::kMacroFormat, "'#_' without a name", at);
  const char* q = raw ? p_ : skip(p_);
  if (q < end_ && *q == '[') {
    const char* open = q;
    int level = 0;
    for (; q < end_; ++q) {
      const char c = *q;
      if (is_space(c)) continue;
      if (c == '[') {
        if (level + depth_ >= max_depth_) {
          return error(AlarmId::kBracketNesting,
                       "brackets nested deeper than " + std::to_string(max_depth_) + " levels", q);
        }
        ++level;
      } else if (c == ']') {
        --level;
      } else {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x21 || u > 0x7e || c == '(' || c == ')') {
          return error(AlarmId::kIllegalChar, show_char(c) + " in a variable index", q);
        }
      }
      name += to_upper(c);
      if (level == 0) break;
    }
    if (level != 0) return error(AlarmId::kBracketNesting, "'[' is not closed", open);
    p_ = q + 1;
  }
  return true;
}

// Variable reference at p_ ('#'): #123, #[expr], ##1, #<name>, #_NAME[i].
// `raw`: inside DPRNT text, where spaces end the variable number.
ExprId Parser::parse_var(bool raw) {
  ExprId id = kNoExpr;
  if (!raw && var_number_fast(id)) return id;
  return parse_var_general(raw);
}

// The general case of parse_var.
ExprId Parser::parse_var_general(bool raw) {
  const char* at = p_;
  ++p_;
  const char* q = raw ? p_ : skip(p_);
  const char c = q < end_ ? *q : '\0';
  if (q < end_ && is_digit(c)) {
    p_ = q;
    std::int64_t v = 0;
    if (raw) {
      const char* s = p_;
      while (p_ < end_ && is_digit(*p_)) ++p_;
      if (p_ - s > uint_digits_) {
        return error_expr(AlarmId::kTooManyDigits, "variable number " + excerpt(s, p_), s);
      }
      for (const char* d = s; d < p_; ++d) v = v * 10 + (*d - '0');
    } else {
      bool any = false;
      if (!parse_uint(v, "variable number", any)) return kFail;
    }
    return add_var_number(v, col(q), col(at));
  }
  if (q < end_ && c == '[') {
    p_ = q;
    const ExprId e = parse_bracket();
    if (e == kFail) return kFail;
    return add_node(Op::kVar, col(at), e);
  }
  if (q < end_ && c == '#') {
    p_ = q;
    if (!enter(q)) return kFail;
    const ExprId e = parse_var(raw);
    if (e == kFail) return kFail;
    leave();
    return add_node(Op::kVar, col(at), e);
  }
  if (q < end_ && (c == '<' || c == '_')) {
    p_ = q;
    std::string name;
    if (!parse_named(name, raw)) return kFail;
    const ExprId n = add_node(Op::kNamedVar, col(at));
    node(n).name = add_name(std::move(name));
    return n;
  }
  return error_expr(AlarmId::kNoValue, "'#' without a variable number", at);
}

// ---- statements

bool Parser::begin_stmt(StmtKind kind, const char* at) {
  if (out_.stmt.kind != StmtKind::kNone) [[unlikely]] {
    return error(AlarmId::kMacroFormat, "two macro statements in one block", at);
  }
  out_.stmt.kind = kind;
  out_.stmt.column = col(at);
  return true;
}

// p_ after the left-hand side: "= expr".
bool Parser::parse_assign_tail(ExprId lhs) {
  if (peek() != '=') [[unlikely]] {
    return unexpected("'=' after the variable", p_);
  }
  ++p_;
  const ExprId rhs = parse_expr();
  if (rhs == kFail) return false;
  out_.stmt.lhs = lhs;
  out_.stmt.rhs = rhs;
  return true;
}

// GOTO n, GOTO#1, GOTO[expr].
bool Parser::parse_goto_target() {
  const int c = peek();
  const char* at = p_;
  ExprId t = kFail;
  if (is_digit(c)) {
    std::int64_t v = 0;
    bool any = false;
    if (!parse_uint(v, "sequence number", any)) return false;
    t = add_number(static_cast<double>(v), col(at));
  } else if (c == '#') {
    t = parse_var(false);
  } else if (c == '[') {
    t = parse_bracket();
  } else if (c == '-' || c == '+') {
    return error(AlarmId::kBadSign, "GOTO target with a sign", at);
  } else {
    return unexpected("a sequence number after GOTO", at);
  }
  if (t == kFail) return false;
  out_.stmt.target = t;
  return true;
}

bool Parser::parse_loop_number(std::string_view what) {
  const int c = peek();
  if (!is_digit(c)) {
    return unexpected("a loop number after " + std::string(what), p_);
  }
  const char* at = p_;
  std::int64_t v = 0;
  bool any = false;
  if (!parse_uint(v, "loop number", any)) return false;
  if (v > std::numeric_limits<int>::max()) {
    return error(AlarmId::kIllegalLoopNumber, "loop number " + excerpt(at, p_), at);
  }
  out_.stmt.loop = static_cast<int>(v);
  return true;
}

// p_ after IF: [cond] GOTO n | [cond] THEN #i = expr.
bool Parser::parse_if(const char* at) {
  if (!begin_stmt(StmtKind::kIfGoto, at)) return false;
  if (peek() != '[') return unexpected("'[' after IF", p_);
  const ExprId cond = parse_bracket();
  if (cond == kFail) return false;
  out_.stmt.cond = cond;
  const int c = peek();
  if (c == 'G' && match_kw("GOTO")) return parse_goto_target();
  if (c == 'T' && match_kw("THEN")) {
    out_.stmt.kind = StmtKind::kIfThen;
    if (peek() != '#') return unexpected("an assignment '#i = ...' after THEN", p_);
    const ExprId lhs = parse_var(false);
    if (lhs == kFail) return false;
    return parse_assign_tail(lhs);
  }
  return unexpected("GOTO or THEN after IF [...]", p_);
}

// p_ after WHILE: [cond] DO m.
bool Parser::parse_while(const char* at) {
  if (!begin_stmt(StmtKind::kWhile, at)) return false;
  if (peek() != '[') return unexpected("'[' after WHILE", p_);
  const ExprId cond = parse_bracket();
  if (cond == kFail) return false;
  out_.stmt.cond = cond;
  if (!(peek() == 'D' && match_kw("DO"))) return unexpected("DO after WHILE [...]", p_);
  return parse_loop_number("DO");
}

// p_ after DPRNT/BPRNT: [items]. Text is taken as written (letters upper-cased,
// spaces kept, '*' printed as a space); "#i[ab]" is a variable with a format.
bool Parser::parse_print(StmtKind kind, const char* at) {
  if (!begin_stmt(kind, at)) return false;
  if (peek() != '[') return unexpected("'[' after the print command", p_);
  const char* open = p_;
  ++p_;
  std::int32_t text = -1;  // the text item being built, if any
  for (;;) {
    if (p_ == end_) return error(AlarmId::kBracketNesting, "'[' is not closed", open);
    const char c = *p_;
    if (c == ']') {
      ++p_;
      return true;
    }
    if (c == '#') {
      text = -1;
      PrintItem item;
      item.var = parse_var(true);
      if (item.var == kFail) return false;
      if (p_ < end_ && *p_ == '[') {
        // [ab]: integer and fraction digits; [b] (BPRNT style): fraction digits.
        const char* f = p_;
        const char* e = p_ + 1;
        while (e < end_ && is_digit(*e)) ++e;
        const auto n = e - (p_ + 1);
        if (e == end_ || *e != ']' || n < 1 || n > 2) {
          return error(AlarmId::kMacroFormat, "print format must be [ab] or [b] digits", f);
        }
        if (n == 2) {
          item.int_digits = p_[1] - '0';
          item.frac_digits = p_[2] - '0';
        } else {
          item.frac_digits = p_[1] - '0';
        }
        p_ = e + 1;
      }
      out_.print_items.push_back(item);
      continue;
    }
    const auto u = static_cast<unsigned char>(c);
    if (c == '[' || c == '(' || c == ')' || (u < 0x20 && c != '\t') || u > 0x7e) {
      return error(AlarmId::kIllegalChar, show_char(c) + " in print text", p_);
    }
    if (text < 0) {
      text = add_name(std::string());
      PrintItem item;
      item.is_text = true;
      item.text = text;
      out_.print_items.push_back(item);
    }
    out_.names[static_cast<std::size_t>(text)] += (c == '*' || c == '\t') ? ' ' : to_upper(c);
    ++p_;
  }
}

// p_ at '('. Text is kept as written. No nesting.
bool Parser::parse_comment() {
  const char* open = p_;
  const auto rest = static_cast<std::size_t>(end_ - (open + 1));
  const auto* close = static_cast<const char*>(std::memchr(open + 1, ')', rest));
  const char* q = close != nullptr ? close : end_;
  if (const void* inner = std::memchr(open + 1, '(', static_cast<std::size_t>(q - (open + 1)))) {
    return error(AlarmId::kIllegalChar, "'(' inside a comment", static_cast<const char*>(inner));
  }
  if (q == end_) return error(AlarmId::kIllegalChar, "comment is not closed by ')'", open);
  Comment cm;
  cm.text = add_name(std::string(open + 1, q));
  cm.column = col(open);
  out_.comments.push_back(cm);
  p_ = q + 1;
  return true;
}

// Keywords come before single-letter addresses. `c` is the upper-cased letter at p_.
bool Parser::try_keyword(int c, const char* at, bool& handled) {
  handled = true;
  switch (c) {
    case 'G':
      if (match_kw("GOTO")) {
        return begin_stmt(StmtKind::kGoto, at) && parse_goto_target();
      }
      break;
    case 'I':
      if (match_kw("IF")) return parse_if(at);
      break;
    case 'W':
      if (match_kw("WHILE")) return parse_while(at);
      break;
    case 'D':
      if (match_kw("DPRNT")) return parse_print(StmtKind::kDprnt, at);
      if (match_kw("DO")) return begin_stmt(StmtKind::kDo, at) && parse_loop_number("DO");
      break;
    case 'E':
      if (match_kw("END")) return begin_stmt(StmtKind::kEnd, at) && parse_loop_number("END");
      break;
    case 'P':
      if (match_kw("POPEN")) return begin_stmt(StmtKind::kPopen, at);
      if (match_kw("PCLOS")) return begin_stmt(StmtKind::kPclos, at);
      break;
    case 'B':
      if (match_kw("BPRNT")) return parse_print(StmtKind::kBprnt, at);
      break;
    default:
      break;
  }
  handled = false;
  return true;
}

Result<void> Parser::run() {
  // Head: '%', '/', 'O', ':' or 'N' first.
  const int first = peek();
  if (first == '%' || first == '/' || first == 'O' || first == ':' || first == 'N') {
    if (!parse_head()) return std::unexpected(std::move(*err_));
  }
  if (out_.percent) {
    // Only comments may follow '%'.
    for (int c = peek(); c >= 0; c = peek()) {
      if (c != '(') {
        error(AlarmId::kIllegalChar, show_char(*p_) + " after '%'", p_);
        return std::unexpected(std::move(*err_));
      }
      if (!parse_comment()) return std::unexpected(std::move(*err_));
    }
    return {};
  }
  for (;;) {
    const char* const at = skip(p_);
    p_ = at;
    if (at == end_) break;
    const int c = static_cast<unsigned char>(to_upper(*at));
    bool ok = true;
    if (is_upper(c)) {
      bool handled = false;
      ok = try_keyword(c, at, handled);
      if (ok && !handled) ok = parse_word();
    } else if (c == '(') {
      ok = parse_comment();
    } else if (c == '#') {
      ok = begin_stmt(StmtKind::kAssign, at);
      if (ok) {
        const ExprId lhs = parse_var(false);
        ok = lhs != kFail && parse_assign_tail(lhs);
      }
    } else {
      ok = bad_block_char(at);
    }
    if (!ok) return std::unexpected(std::move(*err_));
  }
  if (err_) return std::unexpected(std::move(*err_));  // never expected: errors stop the parse
  return {};
}

// A character that cannot start anything in a block.
bool Parser::bad_block_char(const char* at) {
  const char c = *at;
  if (is_digit(c) || c == '.' || c == '-' || c == '+' || c == '[') {
    const char* e = at + 1;
    while (e < end_ && (is_digit(*e) || *e == '.' || is_space(*e))) ++e;
    return error(AlarmId::kNoAddress, "value " + excerpt(at, e) + " has no address letter", at);
  }
  if (c == ']') return error(AlarmId::kBracketNesting, "']' without '['", at);
  if (c == '=') return error(AlarmId::kMacroFormat, "'=' without a variable on its left", at);
  if (c == ')') return error(AlarmId::kIllegalChar, "')' without '('", at);
  return error(AlarmId::kIllegalChar, "illegal character " + show_char(c), at);
}

}  // namespace

Result<void> parse_block(std::string_view text, SourceLoc loc, std::uint64_t offset, Block& out,
                         const ParseLimits& limits) {
  out.clear();
  out.loc = loc;
  out.offset = offset;
  Parser parser(text, loc, out, limits);
  auto r = parser.run();
  parser.finish();
  return r;
}

}  // namespace skipnc::gcode
