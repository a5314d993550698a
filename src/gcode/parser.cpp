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
#include "gcode/parser.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>

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
  return c >= '0' && c <= '9';
}
constexpr bool is_upper(int c) noexcept {
  return c >= 'A' && c <= 'Z';
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

class Parser {
 public:
  Parser(std::string_view text, SourceLoc loc, Block& out, const ParseLimits& limits)
      : begin_(text.data()),
        p_(text.data()),
        end_(text.data() + text.size()),
        loc_(loc),
        out_(out),
        max_digits_(std::max(1, limits.max_digits)),
        max_depth_(std::clamp(limits.max_bracket_depth, 0, kMaxNestingHard)) {}

  Result<void> run();

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
  std::uint32_t col(const char* q) const noexcept {
    return loc_.column + static_cast<std::uint32_t>(q - begin_);
  }
  // Matches an upper-case keyword at p_, spaces allowed between its letters.
  bool match_kw(std::string_view kw) noexcept {
    const char* q = p_;
    for (const char k : kw) {
      q = skip(q);
      if (q == end_ || to_upper(*q) != k) return false;
      ++q;
    }
    p_ = q;
    return true;
  }

  // ---- errors
  bool error(AlarmId id, std::string detail, const char* at) {
    if (!failed_) {
      failed_ = true;
      err_ = Error{id, std::move(detail), SourceLoc{loc_.file, loc_.line, col(at)}, -1};
    }
    return false;
  }
  ExprId error_expr(AlarmId id, std::string detail, const char* at) {
    error(id, std::move(detail), at);
    return kFail;
  }
  // Unexpected character where `what` was expected.
  bool unexpected(std::string_view what, const char* at) {
    if (at >= end_) {
      return error(AlarmId::kMacroFormat, "expected " + std::string(what) + " at end of block", at);
    }
    return error(AlarmId::kMacroFormat,
                 "expected " + std::string(what) + ", found " + show_char(*at), at);
  }

  // ---- node building
  ExprId add_node(Op op, std::uint32_t column, ExprId a = kNoExpr, ExprId b = kNoExpr) {
    ExprNode& n = out_.nodes.emplace_back();
    n.op = op;
    n.a = a;
    n.b = b;
    n.column = column;
    return static_cast<ExprId>(out_.nodes.size() - 1);
  }
  ExprId add_number(double v, std::uint32_t column) {
    const ExprId id = add_node(Op::kNumber, column);
    out_.nodes[static_cast<std::size_t>(id)].value = v;
    return id;
  }
  std::int32_t add_name(std::string s) {
    out_.names.push_back(std::move(s));
    return static_cast<std::int32_t>(out_.names.size() - 1);
  }

  // ---- nesting
  bool enter(const char* at) {
    if (depth_ >= max_depth_) {
      return error(AlarmId::kBracketNesting,
                   "brackets nested deeper than " + std::to_string(max_depth_) + " levels", at);
    }
    ++depth_;
    return true;
  }
  void leave() noexcept { --depth_; }
  // Consumes the ']' closing a bracket opened at `open`.
  bool close_bracket(const char* open) {
    const int c = peek();
    if (c == ']') {
      ++p_;
      return true;
    }
    if (c < 0) return error(AlarmId::kBracketNesting, "'[' is not closed", open);
    return unexpected("']'", p_);
  }

  // ---- literals
  bool parse_number(double& value, bool& has_point);
  bool parse_uint(std::int64_t& value, std::string_view what, bool& any);
  bool parse_word();
  bool parse_head();

  // ---- expressions
  ExprId parse_expr();  // comparisons (lowest)
  ExprId parse_sum();
  ExprId parse_term();
  ExprId parse_unary();
  ExprId parse_primary();
  ExprId parse_bracket();  // p_ at '['
  ExprId parse_function(Func fn, const char* at);
  ExprId parse_var(bool raw);  // p_ at '#'
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
  int max_depth_;
  int depth_ = 0;
  bool failed_ = false;
  Error err_;
};

// Number literal at p_ (digit or '.'): digits with at most one point,
// spaces ignored. Exact for up to 15 significant digits and 22 decimals.
bool Parser::parse_number(double& value, bool& has_point) {
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
  const int limit = std::min(max_digits_, 18);
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
  const char* at = p_;
  const char letter = to_upper(*p_);
  ++p_;
  int c = peek();
  const char* sign_at = nullptr;
  bool negative = false;
  if (c == '-' || c == '+') {
    sign_at = p_;
    negative = c == '-';
    ++p_;
    c = peek();
    if (!(is_digit(c) || c == '.' || c == '#' || c == '[')) {
      return error(AlarmId::kBadSign,
                   std::string("sign after '") + letter + "' is not followed by a value", sign_at);
    }
  }
  if (is_digit(c) || c == '.') {
    // Built in place: copying a Word just written is slow (store forwarding).
    Word& w = out_.words.emplace_back();
    w.letter = letter;
    w.column = col(at);
    if (!parse_number(w.value, w.has_point)) return false;
    if (negative) w.value = -w.value;
    return true;
  }
  if (c == '#' || c == '[') {
    ExprId e = c == '#' ? parse_var(false) : parse_bracket();
    if (e == kFail) return false;
    if (negative) e = add_node(Op::kNeg, col(sign_at), e);
    Word& w = out_.words.emplace_back();
    w.letter = letter;
    w.column = col(at);
    w.is_expr = true;
    w.expr = e;
    return true;
  }
  return error(AlarmId::kNoValue, std::string("'") + letter + "' has no value", at);
}

// ---- expressions

ExprId Parser::parse_expr() {
  const std::uint32_t start = col(skip(p_));
  ExprId a = parse_sum();
  if (a == kFail) return kFail;
  for (;;) {
    const int c = peek();
    Op op;
    if (c == 'E' && match_kw("EQ")) {
      op = Op::kEq;
    } else if (c == 'N' && match_kw("NE")) {
      op = Op::kNe;
    } else if (c == 'G' && match_kw("GT")) {
      op = Op::kGt;
    } else if (c == 'G' && match_kw("GE")) {
      op = Op::kGe;
    } else if (c == 'L' && match_kw("LT")) {
      op = Op::kLt;
    } else if (c == 'L' && match_kw("LE")) {
      op = Op::kLe;
    } else {
      return a;
    }
    const ExprId b = parse_sum();
    if (b == kFail) return kFail;
    a = add_node(op, start, a, b);
  }
}

ExprId Parser::parse_sum() {
  const std::uint32_t start = col(skip(p_));
  ExprId a = parse_term();
  if (a == kFail) return kFail;
  for (;;) {
    const int c = peek();
    Op op;
    if (c == '+') {
      ++p_;
      op = Op::kAdd;
    } else if (c == '-') {
      ++p_;
      op = Op::kSub;
    } else if (c == 'O' && match_kw("OR")) {
      op = Op::kOr;
    } else if (c == 'X' && match_kw("XOR")) {
      op = Op::kXor;
    } else {
      return a;
    }
    const ExprId b = parse_term();
    if (b == kFail) return kFail;
    a = add_node(op, start, a, b);
  }
}

ExprId Parser::parse_term() {
  const std::uint32_t start = col(skip(p_));
  ExprId a = parse_unary();
  if (a == kFail) return kFail;
  for (;;) {
    const int c = peek();
    Op op;
    if (c == '*') {
      ++p_;
      op = Op::kMul;
    } else if (c == '/') {
      ++p_;
      op = Op::kDiv;
    } else if (c == 'M' && match_kw("MOD")) {
      op = Op::kMod;
    } else if (c == 'A' && match_kw("AND")) {
      op = Op::kAnd;
    } else {
      return a;
    }
    const ExprId b = parse_unary();
    if (b == kFail) return kFail;
    a = add_node(op, start, a, b);
  }
}

// Signs are read in a loop (no recursion): "- - -#1" is three kNeg nodes
// chained through their `a`, the last one pointing at the operand.
ExprId Parser::parse_unary() {
  ExprId first = kNoExpr;
  ExprId last = kNoExpr;
  for (int c = peek(); c == '-' || c == '+'; c = peek()) {
    if (c == '-') {
      const ExprId n = add_node(Op::kNeg, col(p_));
      if (last == kNoExpr) {
        first = n;
      } else {
        out_.nodes[static_cast<std::size_t>(last)].a = n;
      }
      last = n;
    }
    ++p_;
  }
  const ExprId operand = parse_primary();
  if (operand == kFail) return kFail;
  if (last == kNoExpr) return operand;
  out_.nodes[static_cast<std::size_t>(last)].a = operand;
  return first;
}

ExprId Parser::parse_primary() {
  const int c = peek();
  const char* at = p_;
  if (is_digit(c) || c == '.') {
    double v = 0.0;
    bool point = false;
    if (!parse_number(v, point)) return kFail;
    return add_number(v, col(at));
  }
  if (c == '#') return parse_var(false);
  if (c == '[') return parse_bracket();
  if (is_upper(c)) {
    for (const FuncName& f : kFuncs) {
      if (f.name[0] == c && match_kw(f.name)) return parse_function(f.fn, at);
    }
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
  out_.nodes[static_cast<std::size_t>(n)].fn = fn;
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
      if (p_ - s > std::min(max_digits_, 18)) {
        return error_expr(AlarmId::kTooManyDigits, "variable number " + excerpt(s, p_), s);
      }
      for (const char* d = s; d < p_; ++d) v = v * 10 + (*d - '0');
    } else {
      bool any = false;
      if (!parse_uint(v, "variable number", any)) return kFail;
    }
    const ExprId num = add_number(static_cast<double>(v), col(q));
    return add_node(Op::kVar, col(at), num);
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
    out_.nodes[static_cast<std::size_t>(n)].name = add_name(std::move(name));
    return n;
  }
  return error_expr(AlarmId::kNoValue, "'#' without a variable number", at);
}

// ---- statements

bool Parser::begin_stmt(StmtKind kind, const char* at) {
  if (out_.stmt.kind != StmtKind::kNone) {
    return error(AlarmId::kMacroFormat, "two macro statements in one block", at);
  }
  out_.stmt.kind = kind;
  out_.stmt.column = col(at);
  return true;
}

// p_ after the left-hand side: "= expr".
bool Parser::parse_assign_tail(ExprId lhs) {
  if (peek() != '=') return unexpected("'=' after the variable", p_);
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
  const char* q = p_ + 1;
  for (; q < end_; ++q) {
    if (*q == ')') break;
    if (*q == '(') return error(AlarmId::kIllegalChar, "'(' inside a comment", q);
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
  if (!parse_head()) return std::unexpected(std::move(err_));
  if (out_.percent) {
    // Only comments may follow '%'.
    for (int c = peek(); c >= 0; c = peek()) {
      if (c != '(') {
        error(AlarmId::kIllegalChar, show_char(*p_) + " after '%'", p_);
        return std::unexpected(std::move(err_));
      }
      if (!parse_comment()) return std::unexpected(std::move(err_));
    }
    return {};
  }
  for (int c = peek(); c >= 0; c = peek()) {
    const char* at = p_;
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
    } else if (is_digit(c) || c == '.' || c == '-' || c == '+' || c == '[') {
      const char* e = at + 1;
      while (e < end_ && (is_digit(*e) || *e == '.' || is_space(*e))) ++e;
      ok = error(AlarmId::kNoAddress, "value " + excerpt(at, e) + " has no address letter", at);
    } else if (c == ']') {
      ok = error(AlarmId::kBracketNesting, "']' without '['", at);
    } else if (c == '=') {
      ok = error(AlarmId::kMacroFormat, "'=' without a variable on its left", at);
    } else if (c == ')') {
      ok = error(AlarmId::kIllegalChar, "')' without '('", at);
    } else {
      ok = error(AlarmId::kIllegalChar, "illegal character " + show_char(*at), at);
    }
    if (!ok) return std::unexpected(std::move(err_));
  }
  if (failed_) return std::unexpected(std::move(err_));  // never expected: errors stop the parse
  return {};
}

}  // namespace

Result<void> parse_block(std::string_view text, SourceLoc loc, std::uint64_t offset, Block& out,
                         const ParseLimits& limits) {
  out.clear();
  out.loc = loc;
  out.offset = offset;
  Parser parser(text, loc, out, limits);
  return parser.run();
}

}  // namespace skipnc::gcode
