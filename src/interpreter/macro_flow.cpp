// Macro statements (Custom Macro B): assignment, IF ... GOTO / THEN, GOTO,
// WHILE ... DO m / END m, and the output statements POPEN, DPRNT, PCLOS.
//
// GOTO n and M99 Pn search the running program (never another program of
// the same file): forward from the block after the GOTO first, then from the
// program's first block, so the first N n after the GOTO wins and a
// backward jump finds the first N n of the program. Each program is scanned
// once, the first time a search needs it; later jumps use that table.
//
// Loops: DO m with m = 1..3, nested up to three deep. A GOTO may leave a loop
// (the loop is dropped from the frame's loop stack when the target is
// outside its WHILE..END range); jumping into a loop is refused by the END
// that finds no matching DO.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "core/file.hpp"
#include "interpreter/impl.hpp"

namespace skipnc::interp {
namespace {

constexpr std::uint64_t kNoEnd = std::numeric_limits<std::uint64_t>::max();

bool is_comparison(gcode::Op op) noexcept {
  using gcode::Op;
  return op == Op::kEq || op == Op::kNe || op == Op::kGt || op == Op::kGe || op == Op::kLt ||
         op == Op::kLe;
}

// A conditional expression: a comparison, or AND / OR / XOR of two of them
// (IF [[#1 EQ 1] OR [#2 EQ 2]]).
bool is_condition(const gcode::Block& b, gcode::ExprId id) noexcept {
  if (id < 0 || static_cast<std::size_t>(id) >= b.nodes.size()) return false;
  const gcode::ExprNode& n = b.nodes[static_cast<std::size_t>(id)];
  if (is_comparison(n.op)) return true;
  if (n.op == gcode::Op::kAnd || n.op == gcode::Op::kOr || n.op == gcode::Op::kXor) {
    return is_condition(b, n.a) && is_condition(b, n.b);
  }
  return false;
}

}  // namespace

Flow<bool> Interpreter::Impl::condition(gcode::ExprId cond, SourceLoc where) {
  if (!is_condition(blk, cond)) {
    return fail(AlarmId::kMacroFormat,
                "the condition must be a comparison (EQ NE GT GE LT LE), e.g. [#1 GT 0]", where);
  }
  auto c = eval(cond);
  SKIPNC_TRY(c);
  return c->num() != 0.0;
}

Flow<Step> Interpreter::Impl::execute_statement() {
  const gcode::Stmt& s = blk.stmt;
  using gcode::StmtKind;
  switch (s.kind) {
    case StmtKind::kAssign: {
      auto v = eval(s.rhs);
      SKIPNC_TRY(v);
      auto a = assign(s.lhs, *v);
      SKIPNC_TRY(a);
      return Step::kContinue;
    }
    case StmtKind::kIfThen: {
      auto c = condition(s.cond, loc(s.column));
      SKIPNC_TRY(c);
      if (*c) {
        auto v = eval(s.rhs);
        SKIPNC_TRY(v);
        auto a = assign(s.lhs, *v);
        SKIPNC_TRY(a);
      }
      return Step::kContinue;
    }
    case StmtKind::kGoto:
    case StmtKind::kIfGoto:
      return goto_statement(s, loc(s.column));
    case StmtKind::kWhile:
    case StmtKind::kDo:
      return loop_statement(s, loc(s.column));
    case StmtKind::kEnd:
      return end_statement(s.loop, loc(s.column));
    case StmtKind::kPopen:
      print.open();
      return Step::kContinue;
    case StmtKind::kPclos:
      print.close();
      return Step::kContinue;
    case StmtKind::kDprnt:
    case StmtKind::kBprnt: {
      auto p = print_line(loc(s.column));
      SKIPNC_TRY(p);
      return Step::kContinue;
    }
    case StmtKind::kOword:       // RS274NGC only (execute runs it: oword.cpp)
    case StmtKind::kGrblSystem:  // grbl only (execute runs it: grbl_system.cpp)
    case StmtKind::kGrblJog:
    case StmtKind::kNone:
      break;
  }
  return Step::kContinue;
}

// GOTO n, IF [...] GOTO n.
[[gnu::always_inline]] inline Flow<Step> Interpreter::Impl::goto_statement(const gcode::Stmt& s,
                                                                           SourceLoc where) {
  if (s.kind == gcode::StmtKind::kIfGoto) {
    auto c = condition(s.cond, where);
    SKIPNC_TRY(c);
    if (!*c) return Step::kContinue;
  }
  auto t = eval(s.target);
  SKIPNC_TRY(t);
  // Sequence numbers 1-99999 (Fanuc 0i/30i); the value is rounded.
  const double n = std::round(t->num());
  if (t->vacant || n < 1 || n > 99999) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "GOTO %.6g: sequence numbers are 1 to 99999", t->num());
    return fail(AlarmId::kIllegalSequenceNumber, t->vacant ? "GOTO a vacant variable" : buf, where);
  }
  auto j = jump_to_label(static_cast<std::int64_t>(n), block_pos.offset, where);
  SKIPNC_TRY(j);
  return Step::kContinue;
}

// WHILE [...] DO m, DO m: the loop entered (or entered again), or, for a
// false WHILE, on after its END.
[[gnu::always_inline]] inline Flow<Step> Interpreter::Impl::loop_statement(const gcode::Stmt& s,
                                                                           SourceLoc where) {
  if (s.loop < 1 || s.loop > 3) {
    return fail(AlarmId::kIllegalLoopNumber,
                "DO " + std::to_string(s.loop) + ": loop numbers are 1, 2 and 3", where);
  }
  bool run = true;
  if (s.kind == gcode::StmtKind::kWhile) {
    auto c = condition(s.cond, where);
    SKIPNC_TRY(c);
    run = *c;
  }
  Frame& f = programs.frames.back();
  const bool again = !f.loops.empty() && f.loops.back().pos.offset == block_pos.offset;
  if (run) {
    if (again) return Step::kContinue;
    // A loop with the same number still on the stack: either this DO is
    // inside it (illegal) or that loop was left by a GOTO.
    for (std::size_t i = f.loops.size(); i-- > 0;) {
      Loop& l = f.loops[i];
      if (l.id != s.loop) continue;
      auto e = find_loop_end(l);
      SKIPNC_TRY(e);
      if (block_pos.offset > l.pos.offset && block_pos.offset < l.end) {
        return fail(AlarmId::kIllegalLoopNumber,
                    "DO " + std::to_string(s.loop) + " inside a loop with the same number", where);
      }
      f.loops.resize(i);
      break;
    }
    if (f.loops.size() >= 3) {
      return fail(AlarmId::kIllegalLoopNumber, "loops nested more than 3 deep", where);
    }
    f.loops.push_back(Loop{s.loop, block_pos, 0, false});
    return Step::kContinue;
  }
  if (again) f.loops.pop_back();
  return pass_false_while(s.loop, where);
}

// A false WHILE: continue after the matching END (found once, then
// remembered: a false WHILE inside a loop costs one seek per pass, not a
// re-read).
Flow<Step> Interpreter::Impl::pass_false_while(int id, SourceLoc where) {
  Frame& f = programs.frames.back();
  if (auto known = f.file->while_exits.find(block_pos.offset); known != f.file->while_exits.end()) {
    auto sk = f.file->src->seek(known->second);
    SKIPNC_TRY(sk);
    f.resume = known->second;
    return Step::kContinue;
  }
  const std::uint64_t while_at = block_pos.offset;
  const std::uint64_t program_start = f.label_origin().offset;
  for (;;) {
    auto got = read_block();
    SKIPNC_TRY(got);
    if (!*got || blk.percent || (blk.has_o && block_pos.offset != program_start)) {
      return fail(AlarmId::kMissingEnd, "no END " + std::to_string(id) + " for this DO", where);
    }
    if (blk.stmt.kind == gcode::StmtKind::kEnd && blk.stmt.loop == id) break;
  }
  f.resume = f.file->src->tell();
  f.file->while_exits.emplace(while_at, f.resume);
  return Step::kContinue;
}

// END m: back to its DO.
[[gnu::always_inline]] inline Flow<Step> Interpreter::Impl::end_statement(int id, SourceLoc where) {
  if (id < 1 || id > 3) {
    return fail(AlarmId::kIllegalLoopNumber,
                "END " + std::to_string(id) + ": loop numbers are 1, 2 and 3", where);
  }
  Frame& f = programs.frames.back();
  if (f.loops.empty() || f.loops.back().id != id) {
    return fail(AlarmId::kMissingEnd,
                "END " + std::to_string(id) + " without a matching DO " + std::to_string(id),
                where);
  }
  Loop& l = f.loops.back();
  l.end = block_pos.offset;
  l.end_known = true;
  auto sk = f.file->src->seek(l.pos);
  SKIPNC_TRY(sk);
  f.resume = l.pos;
  return Step::kContinue;
}

// DPRNT: text as written ('*' is a space); #i[ab] prints the value rounded
// to b decimals (no decimal point when b = 0), a '-' before a negative value
// and a space before a positive one; a vacant variable prints as 0. The
// line goes to the report's messages, and to the --dprnt file when one was
// named and POPEN is in effect.
Flow<void> Interpreter::Impl::print_line(SourceLoc where) {
  std::string line;
  for (const auto& item : blk.print_items) {
    if (item.is_text) {
      line += blk.names[static_cast<std::size_t>(item.text)];
      continue;
    }
    auto v = eval(item.var);
    SKIPNC_TRY(v);
    const double x = v->num();
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", item.frac_digits, x);
    if (buf[0] != '-') line += ' ';
    // "-0.000" after rounding prints as " 0.000".
    if (buf[0] == '-' && std::strspn(buf + 1, "0.") == std::strlen(buf + 1)) {
      line += ' ';
      line += buf + 1;
    } else {
      line += buf;
    }
  }
  auto kept = print.keep(line, where);
  SKIPNC_TRY(kept);
  add_message(std::move(line));
  return {};
}

Flow<void> PrintChannel::keep(const std::string& line, SourceLoc where) {
  if (!open_ || path_.empty()) return {};
  if (static_cast<std::int64_t>(text_.size() + line.size() + 1) > limit_) {
    return fail(
        AlarmId::kDprntLimit,
        "the DPRNT file would pass limits.max_dprnt_bytes = " + std::to_string(limit_) + " bytes",
        where);
  }
  text_ += line;
  text_ += '\n';
  return {};
}

// The DPRNT file is written once, whole, at the end of the run: a temporary
// file beside it, then a rename. Nothing is written anywhere else.
Result<void> PrintChannel::write() const {
  if (!used_ || path_.empty()) return {};
  auto r = write_file_atomic(path_, text_);
  if (!r) {
    Error e = r.error();
    e.detail = "DPRNT: " + e.detail;
    return std::unexpected(std::move(e));
  }
  return {};
}

// Where the END of loop `l` is: the first END with its number after its DO,
// within the running program. kNoEnd when there is none.
Flow<void> Interpreter::Impl::find_loop_end(Loop& l) {
  if (l.end_known) return {};
  Frame& f = programs.frames.back();
  gcode::Source& src = *f.file->src;
  const gcode::SourcePos back = src.tell();
  auto s = src.seek(l.pos);
  if (!s) return s;
  gcode::RawBlock rb;
  gcode::Block b;
  l.end = kNoEnd;
  bool first = true;
  for (;;) {
    const gcode::SourcePos at = src.tell();
    auto more = src.next(rb);
    SKIPNC_TRY(more);
    if (!*more) break;
    if (first) {  // the DO block itself
      first = false;
      continue;
    }
    auto p = gcode::parse_block(rb.text, SourceLoc{f.file->display, rb.line, rb.column}, rb.offset,
                                b, parse_limits);
    if (!p) continue;  // reported if the block is ever executed
    if (b.percent || (b.has_o && at.offset != f.label_origin().offset)) break;
    if (b.stmt.kind == gcode::StmtKind::kEnd && b.stmt.loop == l.id) {
      l.end = at.offset;
      break;
    }
  }
  l.end_known = true;
  return src.seek(back);
}

// A jump to `target` leaves every loop whose WHILE..END range does not hold it.
Flow<void> Interpreter::Impl::leave_loops_for(std::uint64_t target) {
  Frame& f = programs.frames.back();
  while (!f.loops.empty()) {
    Loop& l = f.loops.back();
    auto e = find_loop_end(l);
    if (!e) return e;
    if (target >= l.pos.offset && target <= l.end) break;
    f.loops.pop_back();
  }
  return {};
}

// GOTO n / M99 Pn: the first N n after the block at `from`, else the first
// in the program (ProgramStore::find_label); loops the jump leaves are left.
Flow<void> Interpreter::Impl::jump_to_label(std::int64_t n, std::uint64_t from, SourceLoc where) {
  auto found = programs.find_label(programs.frames.back(), n, from, where);
  SKIPNC_TRY(found);
  Frame& f = programs.frames.back();
  gcode::Source& src = *f.file->src;
  const gcode::SourcePos target = *found;
  auto lv = leave_loops_for(target.offset);
  if (!lv) return lv;
  auto s = src.seek(target);
  if (!s) return s;
  f.resume = target;
  return {};
}

}  // namespace skipnc::interp
