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
#include <filesystem>
#include <string>

#include "interpreter/impl.hpp"

namespace skipnc::interp {
namespace {

namespace fs = std::filesystem;
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

// As LinuxCNC writes it: lower case (the parser keeps names upper case).
std::string shown(const std::string& label) {
  std::string s = "o" + label;
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Whether a raw line can be an O-word: after spaces, an optional '/n' and
// an optional N number, an 'o'.
bool may_be_oword(std::string_view t) noexcept {
  std::size_t i = 0;
  auto spaces = [&] {
    while (i < t.size() && (t[i] == ' ' || t[i] == '\t')) ++i;
  };
  spaces();
  if (i < t.size() && t[i] == '/') {
    ++i;
    if (i < t.size() && t[i] >= '1' && t[i] <= '9') ++i;
    spaces();
  }
  if (i < t.size() && (t[i] == 'N' || t[i] == 'n')) {
    ++i;
    while (i < t.size() && ((t[i] >= '0' && t[i] <= '9') || t[i] == ' ' || t[i] == '\t')) ++i;
  }
  return i < t.size() && (t[i] == 'O' || t[i] == 'o');
}

}  // namespace

// Reads forward from the current position to the O-word with `label` whose
// keyword is one of `kinds`; blk and block_pos are then that block and the
// source is after it. A skip from the same block to the same kinds is kept.
Flow<void> Interpreter::Impl::skip_to_oword(const std::string& label, std::uint32_t kinds,
                                            SourceLoc where) {
  Frame& f = frames.back();
  gcode::Source& src = *f.file->src;
  // The block and what it looks for (kinds: bits of OKind, below 2^16).
  const std::uint64_t key = (block_pos.offset << 16) | (kinds & 0xffffu);
  if (auto it = f.file->ojumps.find(key); it != f.file->ojumps.end()) {
    const ProgramFile::OJump j = it->second;
    auto sk = src.seek(j.at);
    SKIPNC_TRY(sk);
    auto got = read_block();
    SKIPNC_TRY(got);
    f.resume = src.tell();
    return {};
  }
  for (;;) {
    const gcode::SourcePos here = src.tell();
    auto more = src.next(raw);
    SKIPNC_TRY(more);
    if (!*more) {
      std::string want;
      for (int k = 1; k <= static_cast<int>(OKind::kContinue); ++k) {
        if ((kinds & bit(static_cast<OKind>(k))) == 0) continue;
        if (!want.empty()) want += ", ";
        want += shown(label) + " " + keyword(static_cast<OKind>(k));
      }
      return fail(AlarmId::kOwordFlow, "the file ends before " + want, where);
    }
    if (!may_be_oword(raw.text)) continue;
    block_pos = here;
    cur_line = raw.line;
    cur_col = raw.column;
    auto parsed = gcode::parse_block(raw.text, SourceLoc{f.file->display, raw.line, raw.column},
                                     raw.offset, blk, parse_limits);
    SKIPNC_TRY(parsed);
    if (blk.stmt.kind != gcode::StmtKind::kOword) continue;
    if ((kinds & bit(blk.stmt.okind)) == 0) continue;
    if (blk.names[static_cast<std::size_t>(blk.stmt.label)] != label) continue;
    f.resume = src.tell();
    f.file->ojumps.emplace(key, ProgramFile::OJump{here, f.resume});
    return {};
  }
}

// The `o<label> sub` of a call: in the file being run, in the main
// program's file, then in <label>.ngc on the include path (LinuxCNC's
// SUBROUTINE_PATH: a file named after the subroutine, holding it).
Flow<bool> Interpreter::Impl::find_sub(const std::string& label, ProgramFile*& file,
                                       gcode::SourcePos& at, SourceLoc where) {
  auto scan = [&](ProgramFile& pf) -> Result<bool> {
    if (!pf.subs_scanned) {
      auto opened = scanner_for(pf);
      SKIPNC_TRY(opened);
      const std::unique_ptr<gcode::Source> scanner = std::move(*opened);
      gcode::RawBlock rb;
      gcode::Block b;
      for (;;) {
        auto more = scanner->next(rb);
        SKIPNC_TRY(more);
        if (!*more) break;
        if (!may_be_oword(rb.text)) continue;
        auto parsed = gcode::parse_block(rb.text, SourceLoc{pf.display, rb.line, rb.column},
                                         rb.offset, b, parse_limits);
        if (!parsed) continue;  // reported when (and if) the line runs
        if (b.stmt.kind == gcode::StmtKind::kOword && b.stmt.okind == OKind::kSub) {
          pf.subs.emplace(b.names[static_cast<std::size_t>(b.stmt.label)], scanner->tell());
        }
        if (b.stmt.kind == gcode::StmtKind::kOword && b.stmt.okind == OKind::kEndsub) {
          pf.endsubs.insert(b.names[static_cast<std::size_t>(b.stmt.label)]);
        }
      }
      pf.subs_scanned = true;
    }
    if (auto it = pf.subs.find(label); it != pf.subs.end()) {
      // A sub without its endsub would run to the end of the file and end
      // the program there: an alarm, as LinuxCNC's rs274 stops ("File ended
      // with no percent sign or program end").
      if (!pf.endsubs.contains(label)) {
        return fail(AlarmId::kOwordFlow,
                    shown(label) + " sub in " + pf.display + " has no " + shown(label) + " endsub",
                    where);
      }
      file = &pf;
      at = it->second;
      return true;
    }
    return false;
  };
  for (ProgramFile* pf : {frames.back().file, files.front().get()}) {
    auto r = scan(*pf);
    SKIPNC_TRY(r);
    if (*r) return true;
  }
  if (label.size() < 3 || label.front() != '<') return false;
  // A named subroutine in a file of its own: <name>.ngc, lower case as
  // LinuxCNC looks for it.
  std::string name = label.substr(1, label.size() - 2);
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const auto& d : include_dirs()) {
    const fs::path p = fs::path(d) / (name + ".ngc");
    std::error_code ec;
    if (!fs::is_regular_file(p, ec)) continue;
    if (!path_inside(p, fs::path(d))) {  // o</..>: as M98's files, inside the folder
      return fail(AlarmId::kProgramNotFound,
                  shown(label) + ": '" + p.string() + "' leads outside the include folder", where);
    }
    bool added = false;
    auto have = program_file(p, added);
    SKIPNC_TRY(have);
    auto r = scan(**have);
    SKIPNC_TRY(r);
    if (*r) return true;
    return fail(AlarmId::kProgramNotFound,
                p.filename().string() + " has no " + shown(label) + " sub", where);
  }
  return false;
}

// What a call without its sub says: where it looked. LinuxCNC looks in the
// running file, then <name>.ngc in the SUBROUTINE_PATH folders (here -I).
std::string Interpreter::Impl::sub_not_found(const std::string& label) const {
  std::string text = "no " + shown(label) + " sub: not in " + frames.back().file->display;
  if (frames.back().file != files.front().get()) text += " nor " + files.front()->display;
  if (label.size() < 3 || label.front() != '<') return text;
  std::string name = label.substr(1, label.size() - 2);
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  text += ", and no " + name + ".ngc in the folders searched:";
  for (const auto& d : include_dirs()) text += " '" + d + "'";
  return text + " (a folder is added with -I)";
}

Flow<void> Interpreter::Impl::oword_call(const std::string& label, SourceLoc where) {
  int levels = 0;
  for (std::size_t i = 1; i < frames.size(); ++i) levels += frames[i].macro ? 1 : 0;
  const int max = dialect.sw.call_levels > 0 ? dialect.sw.call_levels : mc.limits.max_macro_levels;
  if (levels >= max) {
    return fail(AlarmId::kMacroNesting,
                "subroutine calls nested deeper than " + std::to_string(max) + " levels", where);
  }
  // The arguments, all read before the call level opens.
  std::vector<double> args;
  for (const gcode::ExprId e : blk.args) {
    auto v = eval(e);
    SKIPNC_TRY(v);
    args.push_back(v->num());
  }
  if (args.size() > 30) {
    return fail(AlarmId::kMacroFormat, "more than 30 arguments in a call", where);
  }
  ProgramFile* file = nullptr;
  gcode::SourcePos at;
  auto found = find_sub(label, file, at, where);
  SKIPNC_TRY(found);
  if (!*found) return fail(AlarmId::kProgramNotFound, sub_not_found(label), where);
  Frame f;
  f.file = file;
  f.start = at;
  f.macro = true;
  f.sub_label = label;
  auto pushed = push_frame(f, shown(label) + " call", where);
  if (!pushed) return pushed;
  vars.push_level();
  for (std::size_t i = 0; i < args.size(); ++i) {
    vars.set(static_cast<int>(i) + 1, Value::of(args[i]));
  }
  for (int i = static_cast<int>(args.size()) + 1; i <= 30; ++i) vars.set(i, Value::of(0.0));
  ngc_value_returned = false;
  return {};
}

Flow<Step> Interpreter::Impl::oword_return(const gcode::Stmt& s, SourceLoc where) {
  const std::string& label = blk.names[static_cast<std::size_t>(s.label)];
  Frame& f = frames.back();
  if (frames.size() == 1 || f.sub_label.empty()) {
    return fail(AlarmId::kOwordFlow,
                shown(label) + " " + keyword(s.okind) + " outside a subroutine", where);
  }
  if (f.sub_label != label) {
    return fail(AlarmId::kOwordFlow,
                shown(label) + " " + keyword(s.okind) + " in " + shown(f.sub_label) + " sub",
                where);
  }
  std::optional<double> value;
  if (!blk.args.empty()) {
    auto v = eval(blk.args.front());
    SKIPNC_TRY(v);
    value = v->num();
  }
  ngc_state_on_return();
  frames.pop_back();
  vars.pop_level();
  Frame& caller = frames.back();
  auto sk = caller.file->src->seek(caller.resume);
  SKIPNC_TRY(sk);
  ngc_value_returned = value.has_value();
  if (value) ngc_value = Value::of(*value);
  return Step::kContinue;
}

Flow<Step> Interpreter::Impl::execute_oword(CommandSink& out) {
  (void)out;
  const gcode::Stmt s = blk.stmt;
  const SourceLoc where = loc(s.column);
  std::string label = blk.names[static_cast<std::size_t>(s.label)];
  if (s.target != gcode::kNoExpr) {
    // o[expr] call: the subroutine's number, rounded.
    auto v = eval(s.target);
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
      auto k = skip_to_oword(label, bit(OKind::kEndsub), where);
      SKIPNC_TRY(k);
      return Step::kContinue;
    }
    case OKind::kEndsub:
    case OKind::kReturn:
      return oword_return(s, where);
    case OKind::kCall: {
      auto c = oword_call(label, where);
      SKIPNC_TRY(c);
      return Step::kContinue;
    }
    case OKind::kIf:
    case OKind::kElseif:
    case OKind::kElse:
    case OKind::kEndif:
      return oword_branch(s.okind, label, where);
    case OKind::kNone:
      return fail(AlarmId::kInternal, "unknown O-word statement", where);
    default:
      return oword_loop(s.okind, label, where);
  }
}

// The condition of the O-word block being run: true when not zero.
Flow<bool> Interpreter::Impl::oword_condition() {
  auto v = eval(blk.args.front());
  SKIPNC_TRY(v);
  return v->num() != 0.0;
}

// if / elseif / else / endif.
Flow<Step> Interpreter::Impl::oword_branch(gcode::OKind kind, const std::string& label,
                                           SourceLoc where) {
  switch (kind) {
    case OKind::kIf: {
      auto c = oword_condition();
      SKIPNC_TRY(c);
      if (*c) return Step::kContinue;
      for (;;) {
        auto k = skip_to_oword(label, bit(OKind::kElseif) | bit(OKind::kElse) | bit(OKind::kEndif),
                               where);
        SKIPNC_TRY(k);
        if (blk.stmt.okind != OKind::kElseif) return Step::kContinue;
        auto e = oword_condition();
        SKIPNC_TRY(e);
        if (*e) return Step::kContinue;
      }
    }
    case OKind::kElseif:
    case OKind::kElse: {
      // The end of a branch that ran: on past the endif.
      auto k = skip_to_oword(label, bit(OKind::kEndif), where);
      SKIPNC_TRY(k);
      return Step::kContinue;
    }
    case OKind::kEndif:
      return Step::kContinue;
    default:
      return Step::kContinue;
  }
}

// do / while / endwhile / repeat / endrepeat / break / continue, on the
// frame's loop stack.
Flow<Step> Interpreter::Impl::oword_loop(gcode::OKind kind, const std::string& label,
                                         SourceLoc where) {
  Frame& f = frames.back();
  auto find_loop = [&](OKind of) -> OLoop* {
    for (std::size_t i = f.oloops.size(); i-- > 0;) {
      if (f.oloops[i].label == label && (of == OKind::kNone || f.oloops[i].kind == of)) {
        return &f.oloops[i];
      }
    }
    return nullptr;
  };
  auto seek_to = [&](gcode::SourcePos p) -> Flow<Step> {
    auto sk = f.file->src->seek(p);
    SKIPNC_TRY(sk);
    f.resume = p;
    return Step::kContinue;
  };
  // Leaves a loop: past its closing statement.
  auto leave = [&](const OLoop& l) -> Flow<Step> {
    const OKind opened = l.kind;
    const std::string lab = l.label;
    auto sk = f.file->src->seek(l.body);
    SKIPNC_TRY(sk);
    // The closing statement, found from the opening block.
    block_pos = l.start;
    auto k = skip_to_oword(lab,
                           opened == OKind::kWhile    ? bit(OKind::kEndwhile)
                           : opened == OKind::kRepeat ? bit(OKind::kEndrepeat)
                                                      : bit(OKind::kWhile),
                           where);
    SKIPNC_TRY(k);
    return Step::kContinue;
  };
  switch (kind) {
    case OKind::kDo: {
      const gcode::SourcePos body = f.file->src->tell();
      if (OLoop* l = find_loop(OKind::kDo); l != nullptr && l->start == block_pos) {
        return Step::kContinue;  // a continue came back here
      }
      f.oloops.push_back(OLoop{label, OKind::kDo, block_pos, body, 0.0});
      return Step::kContinue;
    }
    case OKind::kWhile: {
      if (!f.oloops.empty() && f.oloops.back().label == label &&
          f.oloops.back().kind == OKind::kDo) {
        // The end of a do loop.
        auto c = oword_condition();
        SKIPNC_TRY(c);
        if (*c) return seek_to(f.oloops.back().body);
        f.oloops.pop_back();
        return Step::kContinue;
      }
      auto c = oword_condition();
      SKIPNC_TRY(c);
      const bool again = !f.oloops.empty() && f.oloops.back().label == label &&
                         f.oloops.back().kind == OKind::kWhile &&
                         f.oloops.back().start == block_pos;
      if (*c) {
        if (!again) {
          f.oloops.push_back(OLoop{label, OKind::kWhile, block_pos, f.file->src->tell(), 0.0});
        }
        return Step::kContinue;
      }
      if (again) f.oloops.pop_back();
      auto k = skip_to_oword(label, bit(OKind::kEndwhile), where);
      SKIPNC_TRY(k);
      return Step::kContinue;
    }
    case OKind::kEndwhile: {
      if (f.oloops.empty() || f.oloops.back().label != label ||
          f.oloops.back().kind != OKind::kWhile) {
        return fail(AlarmId::kOwordFlow, shown(label) + " endwhile without its while", where);
      }
      return seek_to(f.oloops.back().start);
    }
    case OKind::kRepeat: {
      auto v = eval(blk.args.front());
      SKIPNC_TRY(v);
      const double n = std::round(v->num());
      if (n < 1) {
        auto k = skip_to_oword(label, bit(OKind::kEndrepeat), where);
        SKIPNC_TRY(k);
        return Step::kContinue;
      }
      f.oloops.push_back(OLoop{label, OKind::kRepeat, block_pos, f.file->src->tell(), n});
      return Step::kContinue;
    }
    case OKind::kEndrepeat: {
      if (f.oloops.empty() || f.oloops.back().label != label ||
          f.oloops.back().kind != OKind::kRepeat) {
        return fail(AlarmId::kOwordFlow, shown(label) + " endrepeat without its repeat", where);
      }
      OLoop& l = f.oloops.back();
      l.left -= 1.0;
      if (l.left >= 1.0) return seek_to(l.body);
      f.oloops.pop_back();
      return Step::kContinue;
    }
    case OKind::kBreak:
    case OKind::kContinue: {
      OLoop* l = find_loop(OKind::kNone);
      if (l == nullptr) {
        return fail(AlarmId::kOwordFlow,
                    shown(label) + " " + keyword(kind) + " outside a loop labelled " + shown(label),
                    where);
      }
      f.oloops.resize(static_cast<std::size_t>(l - f.oloops.data()) + 1);
      OLoop loop = f.oloops.back();
      if (kind == OKind::kBreak) {
        f.oloops.pop_back();
        return leave(loop);
      }
      switch (loop.kind) {
        case OKind::kWhile:
          return seek_to(loop.start);  // the condition again
        case OKind::kDo:
          return seek_to(loop.body);
        default: {
          OLoop& r = f.oloops.back();
          r.left -= 1.0;
          if (r.left >= 1.0) return seek_to(r.body);
          f.oloops.pop_back();
          return leave(loop);
        }
      }
    }
    default:
      break;
  }
  return fail(AlarmId::kInternal, "unknown O-word statement", where);
}

// The parameter settings of an RS274NGC line: every value is read first,
// then all are set (LinuxCNC: "parameter setting" happens after the whole
// line is read, so "#1=2 #2=#1" gives #2 the old #1).
Flow<void> Interpreter::Impl::ngc_assignments() {
  if (blk.assigns.empty()) return {};
  std::vector<Value> values;
  values.reserve(blk.assigns.size());
  for (const gcode::Assignment& a : blk.assigns) {
    auto v = eval(a.rhs);
    SKIPNC_TRY(v);
    values.push_back(Value::of(v->num()));
  }
  for (std::size_t i = 0; i < blk.assigns.size(); ++i) {
    auto r = assign(blk.assigns[i].lhs, values[i]);
    if (!r) return r;
  }
  return {};
}

}  // namespace skipnc::interp
