// Block parser, macro statements (assignment, GOTO, IF, WHILE, END, DO,
// DPRNT/BPRNT/POPEN/PCLOS) and comments (rules: the top of parser.cpp).
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

#include "gcode/parser_impl.hpp"

namespace skipnc::gcode::detail {

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

}  // namespace skipnc::gcode::detail
