#include "interpreter/interpreter.hpp"

#include <algorithm>
#include <filesystem>

#include "interpreter/impl.hpp"

namespace skipnc::interp {

namespace fs = std::filesystem;

Interpreter::Impl::Impl(const Setup& s)
    : setup(s), mc(*s.machine), dialect(*s.dialect), params(*s.params) {}

Interpreter::Impl::~Impl() {
  if (dprnt != nullptr) std::fclose(dprnt);
}

Result<void> Interpreter::Impl::init(const AxisVec& start) {
  axis_count = mc.axis_count();
  axis_of_letter.fill(-1);
  for (int i = 0; i < axis_count; ++i) {
    axis_letter[static_cast<std::size_t>(i)] = mc.axes[static_cast<std::size_t>(i)].name;
    axis_of_letter[static_cast<std::size_t>(mc.axes[static_cast<std::size_t>(i)].name - 'A')] = i;
  }
  length_axis = mc.axis_index('Z');
  pos = start;
  work_offsets = mc.work_offsets;
  tools.assign(static_cast<std::size_t>(mc.tool_offset_count) + 1, config::ToolOffset{});
  for (const auto& [n, t] : mc.tool_offsets) tools[static_cast<std::size_t>(n)] = t;
  modal.units = mc.inch_machine ? Units::kInch : Units::kMetric;
  if (!mc.persistent_vars.empty()) {
    auto r = load_persistent(mc.persistent_vars, vars.persistent());
    if (!r) return r;
  }
  auto file = std::make_unique<ProgramFile>();
  file->display = setup.program_name;
  if (setup.program_path.empty()) {
    file->src = gcode::make_string_source(setup.program_name, setup.program_text);
  } else {
    file->path = setup.program_path;
    auto src = gcode::open_file_source(setup.program_path, setup.program_name);
    if (!src) return std::unexpected(src.error());
    file->src = std::move(*src);
  }
  Frame main;
  main.file = file.get();
  main.start = file->src->tell();
  main.resume = main.start;
  files.push_back(std::move(file));
  frames.push_back(main);
  return {};
}

Result<void> Interpreter::Impl::count_statement(SourceLoc where) {
  if (++statements > mc.limits.max_macro_statements) {
    return fail(AlarmId::kLoopLimit,
                "more than " + std::to_string(mc.limits.max_macro_statements) +
                    " blocks executed (limits.max_macro_statements)",
                where);
  }
  return {};
}

// Reads the next block of the running frame into `blk`. False at the end of
// the file.
Result<bool> Interpreter::Impl::read_block() {
  Frame& f = frames.back();
  gcode::Source& src = *f.file->src;
  block_pos = src.tell();
  auto more = src.next(raw);
  if (!more) return std::unexpected(more.error());
  if (!*more) return false;
  cur_line = raw.line;
  cur_col = raw.column;
  auto parsed = gcode::parse_block(raw.text, SourceLoc{f.file->display, raw.line, raw.column},
                                   raw.offset, blk);
  if (!parsed) return std::unexpected(parsed.error());
  if (blk.has_n && f.file->labels.size() < 100000) f.file->labels.emplace(blk.n, block_pos);
  return true;
}

Result<Step> Interpreter::Impl::step(CommandSink& out) {
  if (ended) return Step::kEnd;
  if (pending != Pending::kNone) {
    return fail(AlarmId::kInternal, "step() called before sync()");
  }
  if (!rerun) {
    for (;;) {
      Frame& f = frames.back();
      auto got = read_block();
      if (!got) return std::unexpected(got.error());
      if (!*got) {
        // End of file: a subprogram returns, the main program ends.
        if (frames.size() > 1) {
          auto r = return_from_sub(std::nullopt, loc(1));
          if (!r) return r;
          continue;
        }
        ended = true;
        return Step::kEnd;
      }
      f.resume = f.file->src->tell();
      if (blk.block_delete >= 0) {
        // Block delete switch: off in a simulation unless a later option sets it.
        (void)0;
      }
      if (blk.percent) {
        if (frames.size() == 1 && block_pos.offset == f.start.offset) continue;  // tape start
        if (frames.size() > 1) {
          auto r = return_from_sub(std::nullopt, loc(1));
          if (!r) return r;
          continue;
        }
        ended = true;
        return Step::kEnd;
      }
      if (blk.has_o && blk.words.empty() && blk.stmt.kind == gcode::StmtKind::kNone) {
        // A program number heads a program. Reaching the next program's O
        // block while running one means the running program ended without
        // M99/M30: Fanuc treats the O as the start of a new program.
        if (block_pos.offset != f.start.offset) {
          if (frames.size() > 1) {
            auto r = return_from_sub(std::nullopt, loc(1));
            if (!r) return r;
            continue;
          }
        }
        continue;
      }
      if (blk.empty()) {
        for (const auto& c : blk.comments) {
          const std::string& t = blk.names[static_cast<std::size_t>(c.text)];
          if (t.size() >= 4 && (t.compare(0, 4, "MSG,") == 0)) messages.push_back(t.substr(4));
        }
        continue;
      }
      break;
    }
    raw_text.assign(raw.text);
    auto counted = count_statement(loc(cur_col));
    if (!counted) return std::unexpected(counted.error());
  }
  rerun = false;
  need_sync = false;
  auto r = execute(out);
  if (!r && need_sync) {
    // A live value was read while motion was queued: wait for the motion,
    // then run the same block again (nothing of it was committed).
    need_sync = false;
    rerun = true;
    pending = Pending::kRerun;
    return Step::kSync;
  }
  return r;
}

Result<Step> Interpreter::Impl::execute(CommandSink& out) {
  if (blk.stmt.kind != gcode::StmtKind::kNone) {
    for (const auto& w : blk.words) {
      return fail(AlarmId::kMacroFormat,
                  std::string("NC address ") + w.letter + " and a macro statement in one block",
                  loc(w.column));
    }
    return execute_statement(out);
  }
  Words words;
  auto c = collect_words(words);
  if (!c) return std::unexpected(c.error());
  return execute_nc(words, out);
}

Result<Step> Interpreter::Impl::execute_statement(CommandSink& out) {
  const gcode::Stmt& s = blk.stmt;
  const SourceLoc where = loc(s.column);
  using gcode::StmtKind;
  switch (s.kind) {
    case StmtKind::kAssign: {
      auto v = eval(s.rhs);
      if (!v) return std::unexpected(v.error());
      auto a = assign(s.lhs, *v);
      if (!a) return std::unexpected(a.error());
      return Step::kContinue;
    }
    case StmtKind::kIfThen: {
      auto c = eval(s.cond);
      if (!c) return std::unexpected(c.error());
      if (c->num() != 0.0) {
        auto v = eval(s.rhs);
        if (!v) return std::unexpected(v.error());
        auto a = assign(s.lhs, *v);
        if (!a) return std::unexpected(a.error());
      }
      return Step::kContinue;
    }
    case StmtKind::kGoto:
    case StmtKind::kIfGoto: {
      if (s.kind == StmtKind::kIfGoto) {
        auto c = eval(s.cond);
        if (!c) return std::unexpected(c.error());
        if (c->num() == 0.0) return Step::kContinue;
      }
      auto t = eval(s.target);
      if (!t) return std::unexpected(t.error());
      const double n = std::round(t->num());
      if (t->vacant || n < 1 || n > 99999999) {
        return fail(AlarmId::kSequenceNotFound,
                    "GOTO " + std::to_string(t->num()) + ": not a sequence number", where);
      }
      auto j = jump_to_label(static_cast<std::int64_t>(n), where);
      if (!j) return std::unexpected(j.error());
      return Step::kContinue;
    }
    case StmtKind::kWhile:
    case StmtKind::kDo: {
      if (s.loop < 1 || s.loop > 3) {
        return fail(AlarmId::kIllegalLoopNumber,
                    "DO " + std::to_string(s.loop) + ": loop numbers are 1, 2 and 3", where);
      }
      bool run = true;
      if (s.kind == StmtKind::kWhile) {
        auto c = eval(s.cond);
        if (!c) return std::unexpected(c.error());
        run = c->num() != 0.0;
      }
      Frame& f = frames.back();
      if (run) {
        if (f.loops.empty() || f.loops.back().pos.offset != block_pos.offset) {
          for (const auto& l : f.loops) {
            if (l.id == s.loop) {
              return fail(AlarmId::kIllegalLoopNumber,
                          "DO " + std::to_string(s.loop) + " inside a loop with the same number",
                          where);
            }
          }
          if (f.loops.size() >= 3) {
            return fail(AlarmId::kIllegalLoopNumber, "loops nested more than 3 deep", where);
          }
          f.loops.push_back(Loop{s.loop, block_pos});
        }
        return Step::kContinue;
      }
      if (!f.loops.empty() && f.loops.back().pos.offset == block_pos.offset) f.loops.pop_back();
      // Skip to the block after the matching END.
      const int id = s.loop;
      const SourceLoc start = where;
      for (;;) {
        auto got = read_block();
        if (!got) return std::unexpected(got.error());
        if (!*got || blk.percent) {
          return fail(AlarmId::kMissingEnd, "no END " + std::to_string(id) + " for this DO", start);
        }
        if (blk.stmt.kind == StmtKind::kEnd && blk.stmt.loop == id) break;
      }
      f.resume = f.file->src->tell();
      return Step::kContinue;
    }
    case StmtKind::kEnd: {
      Frame& f = frames.back();
      if (f.loops.empty() || f.loops.back().id != s.loop) {
        return fail(AlarmId::kMissingEnd,
                    "END " + std::to_string(s.loop) + " without a matching DO " +
                        std::to_string(s.loop),
                    where);
      }
      const gcode::SourcePos back = f.loops.back().pos;
      auto sk = f.file->src->seek(back);
      if (!sk) return std::unexpected(sk.error());
      f.resume = back;
      return Step::kContinue;
    }
    case StmtKind::kPopen: {
      if (setup.dprnt_path.empty()) {
        dprnt_open = true;  // DPRNT lines go to the report's messages only
        return Step::kContinue;
      }
      if (dprnt == nullptr) dprnt = std::fopen(setup.dprnt_path.c_str(), "ab");
      if (dprnt == nullptr) {
        return fail(AlarmId::kFileAccess, "POPEN: cannot open '" + setup.dprnt_path + "'", where);
      }
      dprnt_open = true;
      return Step::kContinue;
    }
    case StmtKind::kPclos:
      if (dprnt != nullptr) std::fflush(dprnt);
      dprnt_open = false;
      return Step::kContinue;
    case StmtKind::kDprnt:
    case StmtKind::kBprnt: {
      std::string line;
      for (const auto& item : blk.print_items) {
        if (item.is_text) {
          for (char ch : blk.names[static_cast<std::size_t>(item.text)]) line += ch == '*' ? ' ' : ch;
          continue;
        }
        auto v = eval(item.var);
        if (!v) return std::unexpected(v.error());
        const double x = v->num();
        char buf[64];
        if (item.frac_digits > 0) {
          std::snprintf(buf, sizeof buf, "%.*f", item.frac_digits, x);
        } else {
          std::snprintf(buf, sizeof buf, "%.0f", x);
        }
        if (x >= 0) line += ' ';
        line += buf;
      }
      messages.push_back(line);
      if (dprnt != nullptr && dprnt_open) {
        std::fputs(line.c_str(), dprnt);
        std::fputc('\n', dprnt);
      }
      (void)out;
      return Step::kContinue;
    }
    case StmtKind::kNone:
      break;
  }
  return Step::kContinue;
}

// Finds O<number>: in the running file, then the main file, then on the
// include path as O<n>.nc, <n>.nc, O<n> (and lower-case o). O numbers are
// compared as numbers (O0010 = O10).
Result<void> Interpreter::Impl::find_program(std::int64_t number, ProgramFile*& file,
                                             gcode::SourcePos& at) {
  auto scan = [&](ProgramFile& pf) -> Result<bool> {
    if (auto it = pf.programs.find(number); it != pf.programs.end()) {
      file = &pf;
      at = it->second;
      return true;
    }
    if (pf.scanned) return false;
    // Scan the file once for program numbers with a source of its own, so
    // the running read position is not disturbed.
    std::unique_ptr<gcode::Source> scanner;
    if (pf.path.empty()) {
      scanner = gcode::make_string_source(pf.display, setup.program_text);
    } else {
      auto s = gcode::open_file_source(pf.path, pf.display);
      if (!s) return std::unexpected(s.error());
      scanner = std::move(*s);
    }
    gcode::RawBlock rb;
    for (;;) {
      auto more = scanner->next(rb);
      if (!more) return std::unexpected(more.error());
      if (!*more) break;
      std::size_t i = 0;
      while (i < rb.text.size() && (rb.text[i] == ' ' || rb.text[i] == '\t')) ++i;
      if (i < rb.text.size() && (rb.text[i] == 'O' || rb.text[i] == 'o' || rb.text[i] == ':')) {
        std::int64_t n = 0;
        std::size_t j = i + 1;
        int digits = 0;
        while (j < rb.text.size() && rb.text[j] >= '0' && rb.text[j] <= '9' && digits < 12) {
          n = n * 10 + (rb.text[j] - '0');
          ++j;
          ++digits;
        }
        if (digits > 0) pf.programs.emplace(n, scanner->tell());
      }
    }
    pf.scanned = true;
    if (auto it = pf.programs.find(number); it != pf.programs.end()) {
      file = &pf;
      at = it->second;
      return true;
    }
    return false;
  };
  for (ProgramFile* pf : {frames.back().file, files.front().get()}) {
    auto r = scan(*pf);
    if (!r) return std::unexpected(r.error());
    if (*r) return {};
  }
  for (auto& pf : files) {
    auto r = scan(*pf);
    if (!r) return std::unexpected(r.error());
    if (*r) return {};
  }
  std::vector<std::string> dirs = setup.include_dirs;
  if (dirs.empty()) {
    dirs.push_back(setup.program_path.empty()
                       ? std::string(".")
                       : fs::path(setup.program_path).parent_path().string());
  }
  const std::string n = std::to_string(number);
  char padded[16];
  std::snprintf(padded, sizeof padded, "%04lld", static_cast<long long>(number));
  const std::string names[] = {"O" + n + ".nc", n + ".nc", "O" + n, "O" + std::string(padded) + ".nc",
                               "O" + std::string(padded), "o" + n + ".nc"};
  for (const auto& d : dirs) {
    for (const auto& name : names) {
      const fs::path p = fs::path(d.empty() ? "." : d) / name;
      std::error_code ec;
      if (!fs::is_regular_file(p, ec)) continue;
      auto pf = std::make_unique<ProgramFile>();
      pf->path = p.string();
      pf->display = p.filename().string();
      auto src = gcode::open_file_source(pf->path, pf->display);
      if (!src) return std::unexpected(src.error());
      pf->src = std::move(*src);
      ProgramFile* raw_pf = pf.get();
      files.push_back(std::move(pf));
      auto r = scan(*raw_pf);
      if (!r) return std::unexpected(r.error());
      if (*r) return {};
      // A file named after the program without an O block: run it from the top.
      file = raw_pf;
      at = gcode::SourcePos{};
      raw_pf->programs.emplace(number, at);
      return {};
    }
  }
  return fail(AlarmId::kProgramNotFound, "program O" + n + " not found", {});
}

// GOTO n / M99 Pn: search forward from the current block, then from the top
// of the running program.
Result<void> Interpreter::Impl::jump_to_label(std::int64_t n, SourceLoc where) {
  Frame& f = frames.back();
  gcode::Source& src = *f.file->src;
  if (auto it = f.file->labels.find(n); it != f.file->labels.end()) {
    auto s = src.seek(it->second);
    if (!s) return s;
    f.resume = it->second;
    return {};
  }
  const gcode::SourcePos here = src.tell();
  gcode::RawBlock rb;
  auto search = [&](bool wrap) -> Result<bool> {
    for (;;) {
      const gcode::SourcePos at = src.tell();
      if (wrap && at.offset >= here.offset) return false;
      auto more = src.next(rb);
      if (!more) return std::unexpected(more.error());
      if (!*more) return false;
      // Cheap check before parsing: an N must be in the text.
      if (rb.text.find_first_of("Nn") == std::string_view::npos) continue;
      gcode::Block b;
      auto p = gcode::parse_block(rb.text, SourceLoc{f.file->display, rb.line, rb.column},
                                  rb.offset, b);
      if (!p) continue;  // reported when (if) the block is executed
      if (b.has_o && at.offset != f.start.offset && !wrap) return false;  // next program
      if (b.percent) return false;
      if (b.has_n) {
        if (f.file->labels.size() < 100000) f.file->labels.emplace(b.n, at);
        if (b.n == n) {
          auto s = src.seek(at);
          if (!s) return std::unexpected(s.error());
          f.resume = at;
          return true;
        }
      }
    }
  };
  auto fwd = search(false);
  if (!fwd) return std::unexpected(fwd.error());
  if (*fwd) return {};
  auto s = src.seek(f.start);
  if (!s) return s;
  auto back = search(true);
  if (!back) return std::unexpected(back.error());
  if (*back) return {};
  return fail(AlarmId::kSequenceNotFound, "sequence number N" + std::to_string(n) + " not found",
              where);
}

Result<void> Interpreter::Impl::call(std::int64_t program, int repeats, bool macro,
                                     SourceLoc where) {
  int subs = 0, macros = 0;
  for (std::size_t i = 1; i < frames.size(); ++i) (frames[i].macro ? macros : subs)++;
  if (macro && macros >= mc.limits.max_macro_levels) {
    return fail(AlarmId::kMacroNesting,
                "macro call nesting deeper than " + std::to_string(mc.limits.max_macro_levels),
                where);
  }
  if (!macro && subs >= mc.limits.max_subprogram_levels) {
    return fail(AlarmId::kSubprogramNesting,
                "subprogram nesting deeper than " + std::to_string(mc.limits.max_subprogram_levels),
                where);
  }
  ProgramFile* file = nullptr;
  gcode::SourcePos at;
  auto found = find_program(program, file, at);
  if (!found) {
    Error e = found.error();
    e.loc = where;
    return std::unexpected(e);
  }
  frames.back().resume = frames.back().file->src->tell();
  Frame f;
  f.file = file;
  f.start = at;
  f.resume = at;
  f.program = program;
  f.repeats_left = repeats - 1;
  f.macro = macro;
  frames.push_back(f);
  return file->src->seek(at);
}

Result<Step> Interpreter::Impl::return_from_sub(std::optional<std::int64_t> label,
                                                SourceLoc where) {
  Frame& f = frames.back();
  if (frames.size() == 1) {
    // M99 in the main program: back to its start (or to the label), as the
    // control does; the statement limit ends an endless repetition.
    if (label) {
      auto j = jump_to_label(*label, where);
      if (!j) return std::unexpected(j.error());
      return Step::kContinue;
    }
    auto s = f.file->src->seek(f.start);
    if (!s) return std::unexpected(s.error());
    f.loops.clear();
    return Step::kContinue;
  }
  if (f.repeats_left > 0) {
    --f.repeats_left;
    f.loops.clear();
    auto s = f.file->src->seek(f.start);
    if (!s) return std::unexpected(s.error());
    return Step::kContinue;
  }
  const bool macro = f.macro;
  frames.pop_back();
  if (macro) vars.pop_level();
  Frame& caller = frames.back();
  auto s = caller.file->src->seek(caller.resume);
  if (!s) return std::unexpected(s.error());
  if (label) {
    auto j = jump_to_label(*label, where);
    if (!j) return std::unexpected(j.error());
  }
  return Step::kContinue;
}

Result<void> Interpreter::Impl::sync(const SyncState& s) {
  last_sync = s;
  motion_since_sync = false;
  const Pending was = pending;
  pending = Pending::kNone;
  if (was != Pending::kSkip) {
    pos = s.machine_position;
    return {};
  }
  PendingSkip& ps = pending_skip;
  AxisVec latch = s.triggered ? s.latch_machine : ps.target;
  skip_machine = latch;
  for (int i = 0; i < axis_count; ++i) skip_work[i] = work_of(i, latch[i]);
  have_skip = true;
  if (dialect.sw.next_block_from_stop || s.triggered) pos = s.machine_position;
  SkipRecord rec = ps.record;
  rec.triggered = s.triggered;
  rec.time_s = s.time_s;
  rec.position = skip_work;
  rec.machine_position = latch;
  for (int i = 0; i < axis_count; ++i) rec.end_position[i] = work_of(i, pos[i]);
  if (s.triggered && s.input_index >= 0 && s.input_index < canon::SkipSpec::kMaxInputs) {
    rec.signal = ps.input_names[static_cast<std::size_t>(s.input_index)];
  } else if (s.triggered && s.torque_reached) {
    rec.signal = "TORQUE";
  }
  skips.push_back(rec);
  const auto& sv = dialect.skip_vars;
  if (sv.success_flag > 0) vars.set(sv.success_flag, Value::of(s.triggered ? 1.0 : 0.0));
  for (int i = 0; i < axis_count; ++i) {
    const std::string axis(1, axis_letter[static_cast<std::size_t>(i)]);
    if (!sv.named_machine.empty()) {
      vars.set_named(sv.named_machine + axis, Value::of(latch[i] / unit_mm()));
    }
    if (!sv.named_local.empty()) vars.set_named(sv.named_local + axis, Value::of(skip_work[i]));
  }
  if (!s.triggered && ps.alarm_on_miss) {
    return fail(AlarmId::kSkipMiss, "the block reached its end point without a skip signal",
                ps.loc);
  }
  return {};
}

// ---------------------------------------------------------------------------

Interpreter::Interpreter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Interpreter::~Interpreter() = default;

Result<std::unique_ptr<Interpreter>> Interpreter::create(const Setup& setup,
                                                         const AxisVec& start_machine) {
  auto impl = std::make_unique<Impl>(setup);
  auto r = impl->init(start_machine);
  if (!r) return std::unexpected(r.error());
  return std::unique_ptr<Interpreter>(new Interpreter(std::move(impl)));
}

Result<Step> Interpreter::step(CommandSink& out) { return impl_->step(out); }
Result<void> Interpreter::sync(const SyncState& state) { return impl_->sync(state); }

Result<Value> Interpreter::read_variable(int number) const {
  return impl_->read_var(number, {});
}
Result<Value> Interpreter::read_named(std::string_view name) const {
  return impl_->read_named_var(std::string(name), {});
}
const ModalState& Interpreter::modal() const noexcept { return impl_->modal; }
AxisVec Interpreter::work_from_machine(const AxisVec& machine) const noexcept {
  AxisVec w;
  for (int i = 0; i < impl_->axis_count; ++i) w[i] = impl_->work_of(i, machine[i]);
  return w;
}
const std::vector<std::string>& Interpreter::messages() const noexcept { return impl_->messages; }
const std::vector<SkipRecord>& Interpreter::skips() const noexcept { return impl_->skips; }
std::uint32_t Interpreter::line() const noexcept { return impl_->cur_line; }
const AxisVec& Interpreter::position() const noexcept { return impl_->pos; }
Result<void> Interpreter::save_persistent() const {
  if (impl_->mc.persistent_vars.empty() || !impl_->vars.persistent_dirty()) return {};
  return interp::save_persistent(impl_->mc.persistent_vars, impl_->vars.persistent());
}

}  // namespace skipnc::interp
