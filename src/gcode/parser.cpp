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
//
// This file: numbers, the words of a block, the block itself. Expressions
// are in parser_expr.cpp, macro statements in parser_stmt.cpp, the Parser
// class in parser_impl.hpp.
#include "gcode/parser.hpp"

#include <array>
#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>

#include "gcode/parser_impl.hpp"

namespace skipnc::gcode::detail {

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

// Head of the block: '%', '/n', then 'O' or ':' program number and 'N'
// sequence number (Macro B), or 'N' line number and an O-word (RS274NGC:
// `o100 sub`, `o<name> call [1] [2]`, ...; grbl has no O).
bool Parser::parse_head() {
  const bool ngc = ngc_ || grbl_;
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
    if (is_digit(c) && !(ngc && c == '0')) {
      if (c == '0') return error(AlarmId::kIllegalChar, "block delete switch /0 (use /1../9)", p_);
      out_.block_delete = c - '0';
      ++p_;
      c = peek();
    }
  }
  if (ngc) {
    if (c == 'N') {
      if (!parse_sequence_number(false)) return false;
      c = peek();
    }
    if (c != 'O') return true;
    if (grbl_) return error(AlarmId::kIllegalAddress, "'O' is not a word of this control", p_);
    return parse_oword(p_);
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
  return c != 'N' || parse_sequence_number(true);
}

// p_ at 'N'. Macro B (`strict`) refuses a sign and a computed number with
// their own alarms; RS274NGC's line number only needs digits.
bool Parser::parse_sequence_number(bool strict) {
  const char* at = p_;
  ++p_;
  if (strict) {
    const int v = peek();
    if (v == '-' || v == '+') return error(AlarmId::kBadSign, "sequence number with a sign", p_);
    if (v == '#' || v == '[') {
      return error(AlarmId::kMacroFormat, "sequence number must be a constant", p_);
    }
  }
  bool any = false;
  if (!parse_uint(out_.n, strict ? "sequence number" : "line number", any)) return false;
  if (!any) return error(AlarmId::kNoValue, "'N' has no value", at);
  out_.has_n = true;
  return true;
}

// p_ after the 'o' of an O-word: its label, a number (`number` set too), a
// <name>, or an [expression] (`computed`).
inline bool Parser::parse_olabel(std::string& label, ExprId& computed, std::int64_t& number) {
  const int c = peek();
  if (c == '<') {
    std::string name;
    if (!parse_named(name, false)) return false;
    label = "<" + name + ">";
  } else if (is_digit(c)) {
    bool any = false;
    if (!parse_uint(number, "O-word number", any)) return false;
    label = std::to_string(number);
  } else if (c == '[') {
    // o[expr] call: the number computed when the call runs.
    computed = parse_bracket();
    if (computed == kFail) return false;
  } else {
    return unexpected("a number, <name> or [expression] after 'o'", p_);
  }
  return true;
}

// p_ after an O-word's keyword: its [arguments], as many as `kind` takes
// (comments between them read past).
inline bool Parser::parse_oword_args(OKind kind) {
  const bool needs_one = kind == OKind::kIf || kind == OKind::kElseif || kind == OKind::kWhile ||
                         kind == OKind::kRepeat;
  const bool takes_many = kind == OKind::kCall;
  const bool takes_one = needs_one || kind == OKind::kReturn || kind == OKind::kEndsub;
  for (int next = peek(); next == '[' || next == '('; next = peek()) {
    if (next == '(') {  // a comment between the arguments (LinuxCNC reads past it)
      if (!parse_comment()) return false;
      continue;
    }
    if (!takes_many && !(takes_one && out_.args.empty())) {
      return error(AlarmId::kMacroFormat, "this O-word statement takes no more arguments", p_);
    }
    const ExprId e = parse_bracket();
    if (e == kFail) return false;
    out_.args.push_back(e);
  }
  if (needs_one && out_.args.empty()) {
    return unexpected("a [condition] or [count] after the O-word keyword", p_);
  }
  return true;
}

// p_ at 'O': o<label> keyword [expr]... The label is a number ("o100",
// leading zeros dropped) or a name ("o<probe_x>", upper-cased, spaces dropped).
bool Parser::parse_oword(const char* at) {
  ++p_;
  std::string label;
  ExprId computed = kNoExpr;
  std::int64_t number = -1;
  if (!parse_olabel(label, computed, number)) return false;
  {
    // A program's title ("O100", "O<name>" alone, as LinuxCNC's Fanuc-style
    // numbered programs called by M98): a program number, no statement.
    const int next = peek();
    if (computed == kNoExpr && (next < 0 || next == '(' || next == ';')) {
      out_.has_o = true;
      out_.o = number >= 0 ? number : 0;
      return true;
    }
  }
  struct Kw {
    std::string_view kw;
    OKind kind;
  };
  // Longer keywords before their prefixes.
  static constexpr Kw kKeywords[] = {
      {"ENDSUB", OKind::kEndsub}, {"SUB", OKind::kSub},       {"CALL", OKind::kCall},
      {"RETURN", OKind::kReturn}, {"ELSEIF", OKind::kElseif}, {"ELSE", OKind::kElse},
      {"ENDIF", OKind::kEndif},   {"IF", OKind::kIf},         {"ENDWHILE", OKind::kEndwhile},
      {"WHILE", OKind::kWhile},   {"DO", OKind::kDo},         {"ENDREPEAT", OKind::kEndrepeat},
      {"REPEAT", OKind::kRepeat}, {"BREAK", OKind::kBreak},   {"CONTINUE", OKind::kContinue},
  };
  (void)peek();
  OKind kind = OKind::kNone;
  for (const Kw& k : kKeywords) {
    if (match_kw(k.kw)) {
      kind = k.kind;
      break;
    }
  }
  if (kind == OKind::kNone) {
    return unexpected(
        "an O-word keyword (sub, endsub, call, return, if, elseif, else, endif, "
        "while, endwhile, do, repeat, endrepeat, break, continue)",
        p_);
  }
  if (computed != kNoExpr && kind != OKind::kCall) {
    return error(AlarmId::kMacroFormat, "a computed O-word number is for a call only", at);
  }
  if (!begin_stmt(StmtKind::kOword, at)) return false;
  out_.stmt.okind = kind;
  out_.stmt.label = add_name(std::move(label));
  out_.stmt.target = computed;
  return parse_oword_args(kind);
}

// p_ at a letter after an address: the function named there, or kNoExpr
// (nothing consumed) when none is.
ExprId Parser::ngc_word_function(char c) {
  const char* at = p_;
  const FuncName* f = find_function(static_cast<unsigned char>(to_upper(c)));
  if (f == nullptr) return kNoExpr;
  return parse_function(f->fn, at);
}

// p_ at '#': one parameter setting of an RS274NGC line.
bool Parser::parse_ngc_assign() {
  const ExprId lhs = parse_var(false);
  if (lhs == kFail) return false;
  if (peek() != '=') return unexpected("'=' after the parameter", p_);
  ++p_;
  const ExprId rhs = parse_expr();
  if (rhs == kFail) return false;
  out_.assigns.push_back(Assignment{lhs, rhs});
  return true;
}

// Address word at p_ (a letter): X10, X-.5, X#1, X-#2, X[#1+2], X-[#1].
inline bool Parser::parse_word() {
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
  } else if ((c == '#' || c == '[') && !grbl_) {
    e = c == '#' ? parse_var(false) : parse_bracket();
    if (e == kFail) return false;
    if (negative) e = add_node(Op::kNeg, col(sign_at), e);
    if (e == kFail) return false;
  } else if (ngc_ && is_letter(static_cast<char>(c)) &&
             (e = ngc_word_function(static_cast<char>(c))) != kNoExpr) {
    // RS274NGC: a function is a value of its own (X SIN[30], X EXISTS[#<a>]).
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

// Keywords come before single-letter addresses. `c` is the upper-cased letter at p_.
inline bool Parser::try_keyword(int c, const char* at, bool& handled) {
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

inline Result<void> Parser::run() {
  // Head: '%', '/', 'O', ':' or 'N' first.
  const int first = peek();
  if (first == '%' || first == '/' || first == 'O' || first == 'N' ||
      (first == ':' && !ngc_ && !grbl_)) {
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
  if (grbl_) [[unlikely]] {
    const char* const at = skip(p_);
    if (at != end_ && *at == '$' && !parse_grbl_system(at))
      return std::unexpected(std::move(*err_));
  }
  const bool macro_b = !ngc_ && !grbl_;  // read once, not at each word
  for (;;) {
    const char* const at = skip(p_);
    p_ = at;
    if (at == end_) break;
    const int c = static_cast<unsigned char>(to_upper(*at));
    bool ok = true;
    if (!macro_b) [[unlikely]] {
      if (c == ';') break;  // a comment to the end of the line
      if (c == '(') {
        ok = parse_comment();
      } else if (out_.stmt.kind == StmtKind::kOword) {
        ok = error(AlarmId::kMacroFormat, "only a comment may follow an O-word statement", at);
      } else if (is_upper(c)) {
        ok = word_fast(c, at) || parse_word();
      } else if (c == '#' && ngc_) {
        ok = parse_ngc_assign();
      } else if (c == '#' || c == '[') {
        ok = error(AlarmId::kIllegalChar,
                   std::string("this control has no ") +
                       (c == '#' ? "parameters ('#')" : "expressions ('[')"),
                   at);
      } else {
        ok = bad_block_char(at);
      }
      if (!ok) return std::unexpected(std::move(*err_));
      continue;
    }
    if (is_upper(c)) {
      // A letter followed by a sign, digit or point is no keyword's start.
      if (word_fast(c, at)) continue;
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
    } else if (c == '[' && conditional_m99_ && out_.words.empty() &&
               out_.stmt.kind == StmtKind::kNone && out_.condition == kNoExpr) [[unlikely]] {
      ok = parse_condition(at);
    } else {
      ok = bad_block_char(at);
    }
    if (!ok) return std::unexpected(std::move(*err_));
  }
  if (out_.condition != kNoExpr && !check_condition(condition_at_)) [[unlikely]] {
    return std::unexpected(std::move(*err_));
  }
  if (err_) return std::unexpected(std::move(*err_));  // never expected: errors stop the parse
  return {};
}

// grbl's system line ("Grbl v1.1 Commands"): `$` then a command, the
// pre-parser having removed spaces and comments and raised the case. The
// text goes to the block whole; `$J=` goes on as a block of words (the jog).
bool Parser::parse_grbl_system(const char* at) {
  if (!begin_stmt(StmtKind::kGrblSystem, at)) return false;
  std::string text;
  const char* q = at + 1;
  int depth = 0;
  for (; q < end_; ++q) {
    const char c = *q;
    if (depth == 0 && c == ';') break;
    if (c == '(') ++depth;
    if (depth == 0 && !is_space(c)) text.push_back(static_cast<char>(to_upper(c)));
    if (c == ')' && depth > 0) --depth;
    if (depth == 0 && text == "J=") {
      out_.stmt.kind = StmtKind::kGrblJog;
      ++q;
      break;
    }
  }
  out_.stmt.label = static_cast<std::int32_t>(out_.names.size());
  out_.names.push_back(std::move(text));
  p_ = out_.stmt.kind == StmtKind::kGrblJog ? q : end_;
  return true;
}

bool Parser::parse_condition(const char* at) {
  p_ = at;
  condition_at_ = at;
  const ExprId e = parse_bracket();
  if (e == kFail) return false;
  out_.condition = e;
  return true;
}

// The conditional form is M99's alone (Haas 96-8000, Macros, "Conditional
// expressions"): before anything else it is a value without an address.
bool Parser::check_condition(const char* at) {
  for (const Word& w : out_.words) {
    if (w.letter == 'M' && !w.is_expr && w.value == 99.0) return true;
  }
  return error(AlarmId::kNoAddress,
               "an expression at the head of a block makes M99 conditional; this block has no M99",
               at);
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

}  // namespace skipnc::gcode::detail

namespace skipnc::gcode {

Result<void> parse_block(std::string_view text, SourceLoc loc, std::uint64_t offset, Block& out,
                         const ParseLimits& limits) {
  out.clear();
  out.loc = loc;
  out.offset = offset;
  if (limits.slash_comments) {
    bool in_comment = false;
    for (std::size_t i = 0; i + 1 < text.size(); ++i) {
      if (text[i] == '(') in_comment = true;
      if (text[i] == ')') in_comment = false;
      if (!in_comment && text[i] == '/' && text[i + 1] == '/') {
        text = text.substr(0, i);
        break;
      }
    }
  }
  detail::Parser parser(text, loc, out, limits, false);
  auto r = parser.run();
  parser.finish();
  if (parser.depth_needed()) [[unlikely]] {
    // Many nodes: again, measuring the depth of each tree. (Written out
    // twice: a shared lambda or loop cost the usual block 0.3-0.8 %.)
    out.clear();
    out.loc = loc;
    out.offset = offset;
    detail::Parser tracked(text, loc, out, limits, true);
    r = tracked.run();
    tracked.finish();
  }
  return r;
}

}  // namespace skipnc::gcode