// RS274NGC (LinuxCNC) O-word statements and parameter settings:
//   o<l> sub ... o<l> endsub [v]    a subroutine; passed over where it stands
//   o<l> call [a] [b] ...           #1.. = a b ... in a new call level
//   o<l> return [v]                 back to the caller; #<_value> = v
//   o<l> if [c] / elseif [c] / else / endif
//   o<l> while [c] ... o<l> endwhile
//   o<l> do ... o<l> while [c]
//   o<l> repeat [n] ... o<l> endrepeat
//   o<l> break / o<l> continue      of the loop labelled l
// as LinuxCNC's "O Codes" chapter describes them. A statement is matched
// with its partner by its label, looking forward in the file from where it
// stands; what lies between is not parsed unless it is an O-word (LinuxCNC
// skips such lines the same way). Each match, once found, is kept per
// file, so a loop runs without re-reading its body to find its end.
#include <cctype>
#include <cmath>
#include <string>

#include "interpreter/impl.hpp"

namespace skipnc::interp {
namespace {

using gcode::OKind;

constexpr std::uint32_t bit(OKind k) noexcept {
  return 1u << static_cast<unsigned>(k);
}

const char* keyword(OKind k) noexcept {
  switch (k) {
    case OKind::kSub:
      return "sub";
    case OKind::kEndsub:
      return "endsub";
    case OKind::kCall:
      return "call";
    case OKind::kReturn:
      return "return";
    case OKind::kIf:
      return "if";
    case OKind::kElseif:
      return "elseif";
    case OKind::kElse:
      return "else";
    case OKind::kEndif:
      return "endif";
    case OKind::kWhile:
      return "while";
    case OKind::kEndwhile:
      return "endwhile";
    case OKind::kDo:
      return "do";
    case OKind::kRepeat:
      return "repeat";
    case OKind::kEndrepeat:
      return "endrepeat";
    case OKind::kBreak:
      return "break";
    case OKind::kContinue:
      return "continue";
    case OKind::kNone:
      break;
  }
  return "?";
}

}  // namespace

// Reads forward from the current position to the O-word with `label` whose
// keyword is one of `kinds`; blk and block_pos are then that block and the
// source is after it. A skip from the same block to the same kinds is kept.
Flow<void> Rs274ngc::skip_to_oword(Impl& im, const std::string& label, std::uint32_t kinds,
                                   SourceLoc where) {
  Frame& f = im.programs.frames.back();
  gcode::Source& src = *f.file->src;
  // The block and what it looks for (kinds: bits of OKind, below 2^16).
  const std::uint64_t key = (im.block_pos.offset << 16) | (kinds & 0xffffu);
  if (auto it = f.file->ojumps.find(key); it != f.file->ojumps.end()) {
    const ProgramFile::OJump j = it->second;
    auto sk = src.seek(j.at);
    SKIPNC_TRY(sk);
    auto got = im.read_block();
    SKIPNC_TRY(got);
    f.resume = src.tell();
    return {};
  }
  for (;;) {
    const gcode::SourcePos here = src.tell();
    auto more = src.next(im.raw);
    SKIPNC_TRY(more);
    if (!*more) {
      std::string want;
      for (int k = 1; k <= static_cast<int>(OKind::kContinue); ++k) {
        if ((kinds & bit(static_cast<OKind>(k))) == 0) continue;
        if (!want.empty()) want += ", ";
        want += shown_oword(label) + " " + keyword(static_cast<OKind>(k));
      }
      return fail(AlarmId::kOwordFlow, "the file ends before " + want, where);
    }
    if (!may_be_oword(im.raw.text)) continue;
    im.block_pos = here;
    im.cur_line = im.raw.line;
    im.cur_col = im.raw.column;
    auto parsed =
        gcode::parse_block(im.raw.text, SourceLoc{f.file->display, im.raw.line, im.raw.column},
                           im.raw.offset, im.blk, im.parse_limits);
    SKIPNC_TRY(parsed);
    if (im.blk.stmt.kind != gcode::StmtKind::kOword) continue;
    if ((kinds & bit(im.blk.stmt.okind)) == 0) continue;
    if (im.blk.names[static_cast<std::size_t>(im.blk.stmt.label)] != label) continue;
    f.resume = src.tell();
    f.file->ojumps.emplace(key, ProgramFile::OJump{here, f.resume});
    return {};
  }
}

Flow<void> Rs274ngc::oword_call(Impl& im, const std::string& label, SourceLoc where) {
  int levels = 0;
  for (std::size_t i = 1; i < im.programs.frames.size(); ++i)
    levels += im.programs.frames[i].macro ? 1 : 0;
  const int max =
      im.dialect.sw.call_levels > 0 ? im.dialect.sw.call_levels : im.mc.limits.max_macro_levels;
  if (levels >= max) {
    return fail(AlarmId::kMacroNesting,
                "subroutine calls nested deeper than " + std::to_string(max) + " levels", where);
  }
  // The arguments, all read before the call level opens.
  std::vector<double> args;
  for (const gcode::ExprId e : im.blk.args) {
    auto v = im.eval(e);
    SKIPNC_TRY(v);
    args.push_back(v->num());
  }
  if (args.size() > 30) {
    return fail(AlarmId::kMacroFormat, "more than 30 arguments in a call", where);
  }
  auto found = im.programs.find_sub(label, where);
  SKIPNC_TRY(found);
  if (!*found) return fail(AlarmId::kProgramNotFound, im.programs.sub_not_found(label), where);
  Frame f;
  f.file = (*found)->file;
  f.start = (*found)->at;
  f.macro = true;
  f.sub_label = label;
  auto pushed = im.push_frame(f, shown_oword(label) + " call", where);
  if (!pushed) return pushed;
  im.vars.push_level();
  for (std::size_t i = 0; i < args.size(); ++i) {
    im.vars.set(static_cast<int>(i) + 1, Value::of(args[i]));
  }
  for (int i = static_cast<int>(args.size()) + 1; i <= 30; ++i) im.vars.set(i, Value::of(0.0));
  state.value_returned = false;
  return {};
}

Flow<Step> Rs274ngc::oword_return(Impl& im, const gcode::Stmt& s, SourceLoc where) {
  const std::string& label = im.blk.names[static_cast<std::size_t>(s.label)];
  Frame& f = im.programs.frames.back();
  if (im.programs.frames.size() == 1 || f.sub_label.empty()) {
    return fail(AlarmId::kOwordFlow,
                shown_oword(label) + " " + keyword(s.okind) + " outside a subroutine", where);
  }
  if (f.sub_label != label) {
    return fail(
        AlarmId::kOwordFlow,
        shown_oword(label) + " " + keyword(s.okind) + " in " + shown_oword(f.sub_label) + " sub",
        where);
  }
  std::optional<double> value;
  if (!im.blk.args.empty()) {
    auto v = im.eval(im.blk.args.front());
    SKIPNC_TRY(v);
    value = v->num();
  }
  state_on_return(im);  // ngc_room.cpp
  im.programs.frames.pop_back();
  im.vars.pop_level();
  Frame& caller = im.programs.frames.back();
  auto sk = caller.file->src->seek(caller.resume);
  SKIPNC_TRY(sk);
  NgcState& ns = state;
  ns.value_returned = value.has_value();
  if (value) ns.value = Value::of(*value);
  return Step::kContinue;
}

Flow<Step> Rs274ngc::execute_oword(Impl& im) {
  const gcode::Stmt s = im.blk.stmt;
  const SourceLoc where = im.loc(s.column);
  std::string label = im.blk.names[static_cast<std::size_t>(s.label)];
  if (s.target != gcode::kNoExpr) {
    // o[expr] call: the subroutine's number, rounded.
    auto v = im.eval(s.target);
    SKIPNC_TRY(v);
    const double n = std::round(v->num());
    if (!(n >= 0 && n < 1e9)) {
      return fail(AlarmId::kProgramNotFound,
                  "o[...] call: no subroutine number " + std::to_string(v->num()), where);
    }
    label = std::to_string(static_cast<std::int64_t>(n));
  }
  switch (s.okind) {
    case OKind::kSub: {
      // A definition met in the flow of the program is passed over.
      auto k = skip_to_oword(im, label, bit(OKind::kEndsub), where);
      SKIPNC_TRY(k);
      return Step::kContinue;
    }
    case OKind::kEndsub:
    case OKind::kReturn:
      return oword_return(im, s, where);
    case OKind::kCall: {
      auto c = oword_call(im, label, where);
      SKIPNC_TRY(c);
      return Step::kContinue;
    }
    case OKind::kIf:
    case OKind::kElseif:
    case OKind::kElse:
    case OKind::kEndif:
      return oword_branch(im, s.okind, label, where);
    case OKind::kNone:
      return fail(AlarmId::kInternal, "unknown O-word statement", where);
    default:
      return oword_loop(im, s.okind, label, where);
  }
}

// The condition of the O-word block being run: true when not zero.
Flow<bool> Rs274ngc::oword_condition(Impl& im) {
  auto v = im.eval(im.blk.args.front());
  SKIPNC_TRY(v);
  return v->num() != 0.0;
}

// if / elseif / else / endif.
Flow<Step> Rs274ngc::oword_branch(Impl& im, gcode::OKind kind, const std::string& label,
                                  SourceLoc where) {
  switch (kind) {
    case OKind::kIf: {
      auto c = oword_condition(im);
      SKIPNC_TRY(c);
      if (*c) return Step::kContinue;
      for (;;) {
        auto k = skip_to_oword(im, label,
                               bit(OKind::kElseif) | bit(OKind::kElse) | bit(OKind::kEndif), where);
        SKIPNC_TRY(k);
        if (im.blk.stmt.okind != OKind::kElseif) return Step::kContinue;
        auto e = oword_condition(im);
        SKIPNC_TRY(e);
        if (*e) return Step::kContinue;
      }
    }
    case OKind::kElseif:
    case OKind::kElse: {
      // The end of a branch that ran: on past the endif.
      auto k = skip_to_oword(im, label, bit(OKind::kEndif), where);
      SKIPNC_TRY(k);
      return Step::kContinue;
    }
    case OKind::kEndif:
      return Step::kContinue;
    default:
      return Step::kContinue;
  }
}

namespace {

// The innermost loop of the frame with `label` (and kind `of`, unless kNone).
OLoop* find_oloop(Frame& f, const std::string& label, OKind of) noexcept {
  for (std::size_t i = f.oloops.size(); i-- > 0;) {
    if (f.oloops[i].label == label && (of == OKind::kNone || f.oloops[i].kind == of)) {
      return &f.oloops[i];
    }
  }
  return nullptr;
}

}  // namespace

// Reading goes on at `p` of the running frame.
inline Flow<Step> Rs274ngc::oword_seek(Impl& im, gcode::SourcePos p) {
  Frame& f = im.programs.frames.back();
  auto sk = f.file->src->seek(p);
  SKIPNC_TRY(sk);
  f.resume = p;
  return Step::kContinue;
}

// Leaves a loop: past its closing statement, found from the opening block.
Flow<Step> Rs274ngc::oword_leave(Impl& im, const OLoop& l, SourceLoc where) {
  const OKind opened = l.kind;
  const std::string label = l.label;
  auto sk = im.programs.frames.back().file->src->seek(l.body);
  SKIPNC_TRY(sk);
  im.block_pos = l.start;
  auto k = skip_to_oword(im, label,
                         opened == OKind::kWhile    ? bit(OKind::kEndwhile)
                         : opened == OKind::kRepeat ? bit(OKind::kEndrepeat)
                                                    : bit(OKind::kWhile),
                         where);
  SKIPNC_TRY(k);
  return Step::kContinue;
}

// `while`: the end of a do loop, or the head of a while loop.
inline Flow<Step> Rs274ngc::oword_while(Impl& im, const std::string& label, SourceLoc where) {
  Frame& f = im.programs.frames.back();
  if (!f.oloops.empty() && f.oloops.back().label == label && f.oloops.back().kind == OKind::kDo) {
    // The end of a do loop.
    auto c = oword_condition(im);
    SKIPNC_TRY(c);
    if (*c) return oword_seek(im, f.oloops.back().body);
    f.oloops.pop_back();
    return Step::kContinue;
  }
  auto c = oword_condition(im);
  SKIPNC_TRY(c);
  const bool again = !f.oloops.empty() && f.oloops.back().label == label &&
                     f.oloops.back().kind == OKind::kWhile && f.oloops.back().start == im.block_pos;
  if (*c) {
    if (!again) {
      f.oloops.push_back(OLoop{label, OKind::kWhile, im.block_pos, f.file->src->tell(), 0.0});
    }
    return Step::kContinue;
  }
  if (again) f.oloops.pop_back();
  auto k = skip_to_oword(im, label, bit(OKind::kEndwhile), where);
  SKIPNC_TRY(k);
  return Step::kContinue;
}

// `break` and `continue` of the loop labelled `label`.
inline Flow<Step> Rs274ngc::oword_break(Impl& im, gcode::OKind kind, const std::string& label,
                                        SourceLoc where) {
  Frame& f = im.programs.frames.back();
  OLoop* l = find_oloop(f, label, OKind::kNone);
  if (l == nullptr) {
    return fail(
        AlarmId::kOwordFlow,
        shown_oword(label) + " " + keyword(kind) + " outside a loop labelled " + shown_oword(label),
        where);
  }
  f.oloops.resize(static_cast<std::size_t>(l - f.oloops.data()) + 1);
  OLoop loop = f.oloops.back();
  if (kind == OKind::kBreak) {
    f.oloops.pop_back();
    return oword_leave(im, loop, where);
  }
  switch (loop.kind) {
    case OKind::kWhile:
      return oword_seek(im, loop.start);  // the condition again
    case OKind::kDo:
      return oword_seek(im, loop.body);
    default: {
      OLoop& r = f.oloops.back();
      r.left -= 1.0;
      if (r.left >= 1.0) return oword_seek(im, r.body);
      f.oloops.pop_back();
      return oword_leave(im, loop, where);
    }
  }
}

// do / while / endwhile / repeat / endrepeat / break / continue, on the
// frame's loop stack.
Flow<Step> Rs274ngc::oword_loop(Impl& im, gcode::OKind kind, const std::string& label,
                                SourceLoc where) {
  Frame& f = im.programs.frames.back();
  switch (kind) {
    case OKind::kDo: {
      const gcode::SourcePos body = f.file->src->tell();
      if (OLoop* l = find_oloop(f, label, OKind::kDo); l != nullptr && l->start == im.block_pos) {
        return Step::kContinue;  // a continue came back here
      }
      f.oloops.push_back(OLoop{label, OKind::kDo, im.block_pos, body, 0.0});
      return Step::kContinue;
    }
    case OKind::kWhile:
      return oword_while(im, label, where);
    case OKind::kEndwhile: {
      if (f.oloops.empty() || f.oloops.back().label != label ||
          f.oloops.back().kind != OKind::kWhile) {
        return fail(AlarmId::kOwordFlow, shown_oword(label) + " endwhile without its while", where);
      }
      return oword_seek(im, f.oloops.back().start);
    }
    case OKind::kRepeat: {
      auto v = im.eval(im.blk.args.front());
      SKIPNC_TRY(v);
      const double n = std::round(v->num());
      if (n < 1) {
        auto k = skip_to_oword(im, label, bit(OKind::kEndrepeat), where);
        SKIPNC_TRY(k);
        return Step::kContinue;
      }
      f.oloops.push_back(OLoop{label, OKind::kRepeat, im.block_pos, f.file->src->tell(), n});
      return Step::kContinue;
    }
    case OKind::kEndrepeat: {
      if (f.oloops.empty() || f.oloops.back().label != label ||
          f.oloops.back().kind != OKind::kRepeat) {
        return fail(AlarmId::kOwordFlow, shown_oword(label) + " endrepeat without its repeat",
                    where);
      }
      OLoop& l = f.oloops.back();
      l.left -= 1.0;
      if (l.left >= 1.0) return oword_seek(im, l.body);
      f.oloops.pop_back();
      return Step::kContinue;
    }
    case OKind::kBreak:
    case OKind::kContinue:
      return oword_break(im, kind, label, where);
    default:
      break;
  }
  return fail(AlarmId::kInternal, "unknown O-word statement", where);
}

}  // namespace skipnc::interp
