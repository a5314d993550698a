// Calls: program lookup, M98 subprogram calls, G65 / G66 macro calls with
// their arguments, and M99 returns.
//
// Programs are found by the program store (program_store.cpp).
#include <cstring>
#include <string>

#include "interpreter/impl.hpp"

namespace skipnc::interp {

// Nesting (Fanuc): G65/G66 macro calls up to 4 levels, M98 subprogram calls
// up to 10 levels, each counted on its own (limits.max_macro_levels,
// limits.max_subprogram_levels of the machine file).
// The context of a call: one per distinct call path (file, program, caller,
// calling line and code), so that a block's context names its call stack.
std::uint32_t Interpreter::Impl::context_of(CallContext c) {
  for (std::size_t i = 0; i < contexts.size(); ++i) {
    if (contexts[i] == c) return static_cast<std::uint32_t>(i);
  }
  contexts.push_back(std::move(c));
  return static_cast<std::uint32_t>(contexts.size() - 1);
}

Flow<void> Interpreter::Impl::call(std::int64_t program, int repeats, bool macro, SourceLoc where,
                                   bool modal_call) {
  int subs = 0, macros = 0;
  for (std::size_t i = 1; i < programs.frames.size(); ++i)
    (programs.frames[i].macro ? macros : subs)++;
  if (macro && macros >= mc.limits.max_macro_levels) {
    return fail(
        AlarmId::kMacroNesting,
        "macro call nesting deeper than " + std::to_string(mc.limits.max_macro_levels) + " levels",
        where);
  }
  if (!macro && subs >= mc.limits.max_subprogram_levels) {
    return fail(AlarmId::kSubprogramNesting,
                "subprogram nesting deeper than " +
                    std::to_string(mc.limits.max_subprogram_levels) + " levels",
                where);
  }
  auto found = programs.find_program(program, where);
  SKIPNC_TRY(found);
  Frame f;
  f.file = found->file;
  f.start = found->at;
  f.program = program;
  f.repeats_left = repeats - 1;
  f.macro = macro;
  return push_frame(
      f, (macro ? (modal_call ? "G66 P" : "G65 P") : "M98 P") + std::to_string(program), where);
}

// M97 Pn Ll (Haas "M97 Local Sub-Program Call"): the block at Nn of the
// running program, as a subprogram level of its own (counted with M98's),
// run l times; M99 returns to the block after the M97.
Flow<void> Interpreter::Impl::local_call(std::int64_t label, int repeats, SourceLoc where) {
  int subs = 0;
  for (std::size_t i = 1; i < programs.frames.size(); ++i) subs += programs.frames[i].macro ? 0 : 1;
  if (subs >= mc.limits.max_subprogram_levels) {
    return fail(AlarmId::kSubprogramNesting,
                "subprogram nesting deeper than " +
                    std::to_string(mc.limits.max_subprogram_levels) + " levels",
                where);
  }
  const gcode::SourcePos resume = programs.frames.back().file->src->tell();
  auto at = programs.find_label(programs.frames.back(), label, block_pos.offset, where);
  SKIPNC_TRY(at);
  const Frame& caller = programs.frames.back();
  Frame f;
  f.file = caller.file;
  f.start = *at;
  f.program = caller.program;
  f.repeats_left = repeats - 1;
  f.local = true;
  f.program_start = caller.label_origin();
  // find_label read the file: the caller resumes after the M97 block.
  auto s = caller.file->src->seek(resume);
  SKIPNC_TRY(s);
  return push_frame(std::move(f), "M97 P" + std::to_string(label), where);
}

// The called program's frame on top of the caller's: the caller resumes
// after the calling block, the call path gets its context, reading goes on
// at the frame's start.
Flow<void> Interpreter::Impl::push_frame(Frame f, std::string call, SourceLoc where) {
  programs.frames.back().resume = programs.frames.back().file->src->tell();
  f.resume = f.start;
  f.context = context_of(CallContext{f.file->display, f.program, programs.frames.back().context,
                                     where.line, std::move(call), f.file->path});
  programs.frames.push_back(std::move(f));
  const Frame& top = programs.frames.back();
  return top.file->src->seek(top.start);
}

// M99 (or the end of a called program): runs the program again while
// repetitions are left, else returns to the block after the call, or with
// M99 Pn to sequence number n of the calling program.
Flow<Step> Interpreter::Impl::return_from_sub(std::optional<std::int64_t> label, SourceLoc where) {
  Frame& f = programs.frames.back();
  if (programs.frames.size() == 1) {
    // M99 in the main program: back to its start (or to the label), as the
    // control does; the statement limit ends an endless repetition.
    if (label) {
      auto j = jump_to_label(*label, block_pos.offset, where);
      SKIPNC_TRY(j);
      return Step::kContinue;
    }
    auto s = f.file->src->seek(f.start);
    SKIPNC_TRY(s);
    f.loops.clear();
    return Step::kContinue;
  }
  if (label && dialect.sw.m99_p_jumps_in_subprogram) {
    // Haas: M99 Pn in a subprogram branches to Nn of that subprogram; it
    // does not return to the caller.
    auto j = jump_to_label(*label, block_pos.offset, where);
    SKIPNC_TRY(j);
    return Step::kContinue;
  }
  if (f.repeats_left > 0) {
    --f.repeats_left;
    f.loops.clear();
    auto s = f.file->src->seek(f.start);
    SKIPNC_TRY(s);
    return Step::kContinue;
  }
  const bool macro = f.macro;
  programs.frames.pop_back();
  if (macro) vars.pop_level();
  Frame& caller = programs.frames.back();
  auto s = caller.file->src->seek(caller.resume);
  SKIPNC_TRY(s);
  if (label) {
    const std::uint64_t from = caller.resume.offset > 0 ? caller.resume.offset - 1 : 0;
    auto j = jump_to_label(*label, from, where);
    SKIPNC_TRY(j);
  }
  return Step::kContinue;
}

bool Interpreter::Impl::in_modal_call() const noexcept {
  for (const Frame& f : programs.frames) {
    if (f.modal_call) return true;
  }
  return false;
}

// One argument word of a G65/G66 block, in block order.
// Specification I: A B C D E F H I J K M Q R S T U V W X Y Z -> #1..#26
// (A1 B2 C3 I4 J5 K6 D7 E8 F9 H11 M13 Q17 R18 S19 T20 U21 V22 W23 X24 Y25
// Z26). Specification II: I J K repeated up to ten times -> #4..#33, a new
// set starting when a letter does not follow the previous one in I J K
// order. Where both name one variable (D and I2 -> #7), the later word wins
// (Fanuc 16i operator's manual B-63684EN, custom macro, "mixture of argument
// specifications I and II").
// Decimal point (same manual, "position of the decimal point"): a value
// written without a decimal point is in the least input increment of its
// address: lengths (X Y Z U V W I J K Q R and axis letters) become
// 0.001 mm / 0.0001 inch per unit (unless parameter 3401#0 DPI = 1); the
// other addresses (D E F H M S T, and A B C when they are not axes) are
// taken as written. Expressions (X#1, X[...]) are taken as computed.
Flow<void> Interpreter::Impl::collect_argument(const gcode::Word& w, const WordVal& v, int& ijk_set,
                                               int& ijk_last) {
  static constexpr std::array<std::int8_t, 26> kSpecI = {
      1,  2,  3,  7,  8,  9,  -1, 11, 4,  5,  6,  -1, 13,  // A..M
      -1, -1, -1, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26,  // N..Z
  };
  const char c = w.letter;
  int var = 0;
  if (c == 'I' || c == 'J' || c == 'K') {
    const int k = c - 'I';
    if (ijk_set < 0 || k <= ijk_last) ++ijk_set;
    ijk_last = k;
    if (ijk_set >= 10) {
      return fail(AlarmId::kIllegalArgumentAddress,
                  std::string("more than ten sets of I J K arguments (") + c + ")", loc(w.column));
    }
    var = 4 + ijk_set * 3 + k;
  } else {
    var = kSpecI[static_cast<std::size_t>(c - 'A')];
    if (var < 0) {
      return fail(AlarmId::kIllegalArgumentAddress,
                  std::string(1, c) + " cannot be a macro argument", loc(w.column));
    }
  }
  const bool length = axis_of_letter[static_cast<std::size_t>(c - 'A')] >= 0 ||
                      std::strchr("IJKQRUVWXYZ", c) != nullptr;
  const double x = length ? word_length(v) : v.value;
  call_args.set(var, x);
  return {};
}

Flow<void> Interpreter::Impl::macro_call(std::int64_t program, int repeats, bool modal_call,
                                         SourceLoc where) {
  const std::array<Value, kLocalCount + 1> args = modal_call ? g66.args : call_args.values;
  auto c = call(program, repeats, true, where, modal_call);
  if (!c) return c;
  programs.frames.back().modal_call = modal_call;
  vars.push_level();
  vars.locals() = args;
  return {};
}

}  // namespace skipnc::interp
