// Block parser, expressions: precedence climbing (one loop per bracket
// level), functions and variables (rules: the top of parser.cpp).
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <ranges>
#include <string>
#include <string_view>

#include "gcode/parser_impl.hpp"

namespace skipnc::gcode::detail {
namespace {

// Longer names before their prefixes (SQRT before SQR).
constexpr std::array<FuncName, 21> kFuncs = {{
    {"SIN", Func::kSin},   {"COS", Func::kCos},     {"TAN", Func::kTan},
    {"ASIN", Func::kAsin}, {"ACOS", Func::kAcos},   {"ATAN", Func::kAtan},
    {"ATN", Func::kAtan},  {"SQRT", Func::kSqrt},   {"SQR", Func::kSqrt},
    {"ABS", Func::kAbs},   {"ROUND", Func::kRound}, {"RND", Func::kRound},
    {"FIX", Func::kFix},   {"FUP", Func::kFup},     {"LN", Func::kLn},
    {"EXP", Func::kExp},   {"POW", Func::kPow},     {"BIN", Func::kBin},
    {"BCD", Func::kBcd},   {"ADP", Func::kAdp},     {"EXISTS", Func::kExists},
}};

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
constexpr std::size_t kMaxFuncName = 6;  // EXISTS
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

// The names by their keys: a table of 64 slots indexed by a multiplicative
// hash of the key, with a multiplier under which no two names share a slot
// (found at compile time). A slot holds its name's key and its index in
// kFuncs, or an index of -1.
constexpr unsigned kFuncHashBits = 6;
struct FuncSlot {
  std::uint64_t key = 0;
  std::int8_t index = -1;
};
constexpr std::size_t func_slot(std::uint64_t key, std::uint64_t mul) {
  return static_cast<std::size_t>((key * mul) >> (64 - kFuncHashBits));
}
// Candidates from the splitmix64 sequence (neighbouring odd numbers would
// spread the names alike).
constexpr std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15u);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
  return z ^ (z >> 31);
}
constexpr std::uint64_t make_func_mul() {
  for (std::uint64_t state = 0;;) {
    const std::uint64_t mul = splitmix64(state) | 1u;
    std::array<bool, std::size_t{1} << kFuncHashBits> used{};
    bool clash = false;
    for (std::size_t i = 0; i < kFuncs.size() && !clash; ++i) {
      const std::size_t s = func_slot(kFuncKeys[i], mul);
      clash = used[s];
      used[s] = true;
    }
    if (!clash) return mul;
  }
}
constexpr std::uint64_t kFuncMul = make_func_mul();
constexpr std::array<FuncSlot, std::size_t{1} << kFuncHashBits> make_func_slots() {
  std::array<FuncSlot, std::size_t{1} << kFuncHashBits> t{};
  for (std::size_t i = 0; i < kFuncs.size(); ++i) {
    FuncSlot& s = t[func_slot(kFuncKeys[i], kFuncMul)];
    s.key = kFuncKeys[i];
    s.index = static_cast<std::int8_t>(i);
  }
  return t;
}
constexpr auto kFuncSlots = make_func_slots();

// How many of the 8 bytes of w (the first lowest) are letters (as
// is_letter says) before the first that is not: all bytes at once.
constexpr std::size_t leading_letters(std::uint64_t w) {
  constexpr std::uint64_t kOnes = 0x0101010101010101u;
  constexpr std::uint64_t kHigh = 0x80 * kOnes;
  const std::uint64_t low = (w | 0x20 * kOnes) & ~kHigh;        // lower case, high bits cleared
  const std::uint64_t from_a = low + (0x80 - 'a') * kOnes;      // high bit: >= 'a'
  const std::uint64_t past_z = low + (0x80 - 'z' - 1) * kOnes;  // high bit: > 'z'
  const std::uint64_t other = ~(from_a & ~past_z & ~w) & kHigh;
  return other == 0 ? 8 : static_cast<std::size_t>(std::countr_zero(other)) / 8;
}
static_assert(leading_letters(name_key("SIN[#1]]")) == 3);
static_assert(leading_letters(name_key("sqrt[2]]")) == 4);
static_assert(leading_letters(name_key("ABCDEFGH")) == 8);
static_assert(leading_letters(name_key("Z@`{[z0]")) == 1);
static_assert(leading_letters(0xC1C1C1C1C1C1C141u) == 1);  // 'A', then bytes >= 0x80

// Expression trees of a variable reference "#n" are two levels deep.
static_assert(kMaxExprDepth >= 2);

}  // namespace

// Binary operator at p_, consumed. Returns its precedence, 3 for * / MOD
// AND, 2 for + - OR XOR, 1 for the comparisons; 0, consuming nothing, when
// there is none.
inline int Parser::binary_op(Op& op) {
  if (p_ == end_) return 0;
  if (ngc_) [[unlikely]] {
    if (*p_ == '*' && p_ + 1 < end_ && p_[1] == '*') {
      op = Op::kPow;
      p_ += 2;
      return 5;
    }
    if (*p_ == ']' || *p_ == ',') return 0;
    const char* was = p_;
    Op o = Op::kNumber;
    const int fanuc = binary_op_fanuc(o);
    if (fanuc == 0) {
      p_ = was;
      return 0;
    }
    op = o;
    return ngc_precedence(o);
  }
  return binary_op_fanuc(op);
}

// RS274NGC precedence (LinuxCNC, "G-code overview", binary operators):
// ** highest, then * / MOD, then + -, then the comparisons, then AND OR XOR.
int Parser::ngc_precedence(Op op) const noexcept {
  switch (op) {
    case Op::kPow:
      return 5;
    case Op::kMul:
    case Op::kDiv:
    case Op::kMod:
      return 4;
    case Op::kAdd:
    case Op::kSub:
      return 3;
    case Op::kAnd:
    case Op::kOr:
    case Op::kXor:
      return 1;
    default:
      return 2;
  }
}

inline int Parser::binary_op_fanuc(Op& op) {
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
// `kTrack`: with depths tracked (track_depth_), the code of the usual parse
// being the one without.
template <bool kTrack>
ExprId Parser::parse_expr_t() {
  struct Pending {
    ExprId lhs;
    std::uint32_t start;  // column of lhs
    std::uint16_t depth;  // of lhs
    Op op;
    std::uint8_t prec;
  };
  std::array<Pending, 5> stack;
  std::size_t n = 0;
  for (;;) {
    // An operand; p_ then at the next significant character.
    const char* const at = skip(p_);
    p_ = at;
    const int c = at_char(at);
    ExprId a = kFail;
    int depth = 1;  // of a, while depths are tracked
    if (c == '#') {
      if (var_number_fast(a)) {
        depth = 2;
      } else {
        a = parse_var_general(false);
        if (a == kFail) return kFail;
        if constexpr (kTrack) depth = depth_of(a);
        p_ = skip(p_);
      }
    } else if (is_digit(c) || c == '.') {
      double v = 0.0;
      bool point = false;
      if (number_fast(v, point)) {
        // add_number, with the depth's keeping decided when compiled
        a = push_node<kTrack>(Op::kNumber, col(at), kNoExpr, kNoExpr, 1, v);
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
      if constexpr (kTrack) depth = depth_of(a);
      p_ = skip(p_);
    } else {
      const FuncName* f = nullptr;
      if (is_upper(c & ~0x20)) f = find_function_here(c & ~0x20);
      a = f != nullptr ? parse_function(f->fn, at) : parse_operand(c);
      if (a == kFail) return kFail;
      if constexpr (kTrack) depth = depth_of(a);
      p_ = skip(p_);
    }
    // The next operator; the waiting ones that bind at least as tightly get
    // their right-hand side.
    std::uint32_t start = col(at);
    Op op = Op::kNumber;
    const int prec = binary_op(op);
    while (n > 0 && stack[n - 1].prec >= prec) {
      const Pending& t = stack[--n];
      if constexpr (kTrack) {
        depth = 1 + std::max<int>(t.depth, depth);
        if (depth > kMaxExprDepth) {
          too_deep(t.start);
          return kFail;
        }
      }
      a = push_node<kTrack>(t.op, t.start, t.lhs, a, depth);
      start = t.start;
    }
    if (prec == 0) return a;
    stack[n++] =
        Pending{a, start, static_cast<std::uint16_t>(depth), op, static_cast<std::uint8_t>(prec)};
  }
}

template ExprId Parser::parse_expr_t<false>();
template ExprId Parser::parse_expr_t<true>();

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
  if (!track_depth_) return first;
  // The chain's depths, now that its operand is known.
  int signs = 0;
  for (ExprId i = first; i != operand; i = node(i).a) ++signs;
  int depth = signs + depth_of(operand);
  if (depth > kMaxExprDepth) {
    too_deep(node(first).column);
    return kFail;
  }
  for (ExprId i = first; i != operand; i = node(i).a) set_depth(i, depth--);
  return first;
}

// The function whose name is at p_ (`c`: its first letter, upper-cased),
// p_ past the name; nullptr, p_ unchanged, when there is none.
const FuncName* Parser::find_function(int c) {
  return find_function_here(c);
}

// find_function(), inlined into parse_expr.
inline const FuncName* Parser::find_function_here(int c) {
  const FuncGroup& g = kFuncGroups[static_cast<std::size_t>(c - 'A')];
  // The letters written together at p_, up to the longest name. Unless a
  // space follows them (a name may be spelt "S I N"), the function is the
  // first of its group whose name they begin with, as match_kw would find.
  const char* const at = p_;
  std::size_t n = 1;
  // The bytes at p_ with letters upper-cased. A name is letters only, so
  // the bytes after the n letters can never match one.
  std::uint64_t key = 0;
  if (end_ - at >= 8) {
    std::memcpy(&key, at, 8);
    if constexpr (std::endian::native == std::endian::big) key = std::byteswap(key);
    n = std::min(leading_letters(key), kMaxFuncName);
  } else {
    const auto max = std::min(static_cast<std::size_t>(end_ - at), kMaxFuncName);
    while (n < max && is_letter(at[n])) ++n;
    for (std::size_t i = 0; i < n; ++i) {
      key |= std::uint64_t{static_cast<unsigned char>(at[i])} << (8 * i);
    }
  }
  if (n < kMaxFuncName && at + n != end_ && is_space(at[n])) [[unlikely]] {
    return find_function_spaced(g);
  }
  key &= 0xDFDFDFDFDFDFDFDFu;  // upper case: n letters, then anything
  // The usual case: the n letters are a name. It is the one the search
  // below finds too: of two names, only SQR is the beginning of another
  // (SQRT), and SQRT comes first.
  const std::uint64_t letters = key & ((std::uint64_t{1} << (8 * n)) - 1);
  const FuncSlot& slot = kFuncSlots[func_slot(letters, kFuncMul)];
  if (slot.key == letters && slot.index >= 0) [[likely]] {
    const FuncName& f = kFuncs[static_cast<std::size_t>(slot.index)];
    p_ = at + f.name.size();
    return &f;
  }
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
  ExprId a = lone_operand();
  ExprId b = kNoExpr;
  if (a != kNoExpr) {
    ++p_;  // the ']' after it
  } else {
    a = parse_expr();
    if (a == kFail) return kFail;
    if (peek() == ',') {
      if (fn != Func::kAtan && fn != Func::kPow) {
        return error_expr(AlarmId::kMacroFormat, "this function takes one argument", p_);
      }
      ++p_;
      b = parse_expr();
      if (b == kFail) return kFail;
    }
    if (!close_bracket(open)) return kFail;
  }
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
    return add_var_number(v, col(at));
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

}  // namespace skipnc::gcode::detail
