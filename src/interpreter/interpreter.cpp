#include "interpreter/interpreter.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "interpreter/impl.hpp"
#include "interpreter/offset_units.hpp"

namespace skipnc::interp {

namespace fs = std::filesystem;

// How long a run waits for another that holds the persistent-variable file.
constexpr double kPersistentLockWaitS = 60.0;

namespace {

// The machine file's offsets are in mm; the Fanuc family keeps their numbers
// in the input unit (offset_units.hpp): the power-on unit's.
void scale_offsets(std::vector<AxisVec>& work, std::vector<config::ToolOffset>& tools, int axes,
                   double per) {
  for (AxisVec& o : work) {
    for (int i = 0; i < axes; ++i) o[i] /= per;
  }
  for (config::ToolOffset& t : tools) {
    for (double* f : {&t.length_geometry, &t.length_wear, &t.radius_geometry, &t.radius_wear,
                      &t.x_geometry, &t.z_geometry, &t.x_wear, &t.z_wear}) {
      *f /= per;
    }
  }
}

}  // namespace

Interpreter::Impl::Impl(const Setup& s)
    : setup(s), mc(*s.machine), dialect(*s.dialect), params(*s.params) {}

Interpreter::Impl::~Impl() = default;

// The axes' letters and scales; on a lathe, G-code system A's power-on modes.
void Interpreter::Impl::init_axes() {
  axis_count = mc.axis_count();
  axis_of_letter.fill(-1);
  for (int i = 0; i < axis_count; ++i) {
    axis_letter[static_cast<std::size_t>(i)] = mc.axes[static_cast<std::size_t>(i)].name;
    axis_of_letter[static_cast<std::size_t>(mc.axes[static_cast<std::size_t>(i)].name - 'A')] = i;
    axis_letters |= 1u << (mc.axes[static_cast<std::size_t>(i)].name - 'A');
  }
  length_axis = mc.axis_index('Z');
  axis_scale.fill(1.0);
  if (mc.lathe()) {
    // G-code system A: G18, G99 at power-on; no tool length offset (the T
    // code offsets X and Z); X in diameter with 1006#3.
    modal.lathe = true;
    modal.plane = PlaneSel::kZX;
    modal.feed_mode = FeedMode::kPerRev;
    length_axis = -1;
    if (params.bit(config::param::kDiameterX))
      axis_scale[static_cast<std::size_t>(mc.axis_index('X'))] = 2.0;
  }
}

// The language's parse settings, the offset tables from the machine file.
void Interpreter::Impl::init_tables() {
  work_offsets.assign(kWorkSystems, AxisVec{});
  std::copy(mc.work_offsets.begin(), mc.work_offsets.end(), work_offsets.setup().begin());
  parse_limits.max_bracket_depth = dialect.sw.macro_bracket_depth;
  parse_limits.syntax = lang->rules.syntax;
  parse_limits.slash_comments = dialect.sw.slash_comments;
  parse_limits.conditional_m99 = dialect.sw.conditional_m99;
  functions.nat = params.bit(config::param::kSignedArcFunctions);
  tools.assign(static_cast<std::size_t>(mc.tool_offset_count) + 1, config::ToolOffset{});
  for (const auto& [n, t] : mc.tool_offsets) tools.setup()[static_cast<std::size_t>(n)] = t;
  modal.units = mc.inch_machine ? Units::kInch : Units::kMetric;
  if (offset_unit_mm(*this) != 1.0) {
    scale_offsets(work_offsets.setup(), tools.setup(), axis_count, unit_mm());
  }
}

// The persistent variables (their file locked for the run), then the
// values the caller gave (Setup::variables).
Flow<void> Interpreter::Impl::init_variables() {
  if (!mc.persistent_vars.empty()) {
    // Locked until the run has written them back (save_persistent), so that
    // runs sharing the file do not lose each other's updates.
    auto l = PersistentLock::acquire(mc.persistent_vars, kPersistentLockWaitS);
    SKIPNC_TRY(l);
    persistent_lock = std::move(*l);
    SKIPNC_TRY(lang->load_persistent(*this));
  }
  for (const auto& [n, v] : setup.variables) {
    SKIPNC_TRY(lang->preset(*this, n, v));
  }
  return {};
}

// The main program's file and its frame, the call path's root (the program
// store, program_store.hpp).
Flow<void> Interpreter::Impl::open_main() {
  ProgramStore::Options store;
  store.main_name = setup.program_name;
  store.main_path = setup.program_path;
  store.main_text = &setup.program_text;
  store.include_dirs = setup.include_dirs;
  store.source = source_limits();
  store.parse = parse_limits;
  store.max_label_index = mc.limits.max_label_index;
  SKIPNC_TRY(programs.open(std::move(store)));
  const ProgramFile& file = programs.main_file();
  contexts.push_back(CallContext{file.display, 0, CallContext::kNone, 0, "", file.path});
  return {};
}

Flow<void> Interpreter::Impl::init(const AxisVec& start) {
  init_axes();
  pos = start;
  init_tables();
  lang->start(*this);  // language.cpp
  init_plain();        // ncblock.cpp
  SKIPNC_TRY(init_variables());
  return open_main();
}

// Under --strict the warning is the block's alarm.
Flow<void> Interpreter::Impl::warn(const char* code, std::string text, SourceLoc where) {
  if (setup.strict && std::find(setup.strict_allow.begin(), setup.strict_allow.end(),
                                std::string_view(code)) == setup.strict_allow.end()) {
    return fail(AlarmId::kStrictWarning, std::string(code) + ": " + text, where);
  }
  add_warning(warnings, Warning{code, programs.frames.empty() ? 0 : programs.frames.back().context,
                                where.line, std::move(text)});
  return {};
}

Flow<void> Interpreter::Impl::statement_limit(std::uint32_t column) const {
  return fail(AlarmId::kLoopLimit,
              "more than " + std::to_string(mc.limits.max_macro_statements) +
                  " blocks executed (limits.max_macro_statements)",
              loc(column));
}

// Reads the next block of the running frame into `blk`. False at the end of
// the file.
Flow<bool> Interpreter::Impl::read_block() {
  Frame& f = programs.frames.back();
  gcode::Source& src = *f.file->src;
  block_pos = src.tell();
  auto more = src.next(raw);
  SKIPNC_TRY(more);
  if (!*more) return false;
  cur_line = raw.line;
  cur_col = raw.column;
  auto parsed = gcode::parse_block(raw.text, SourceLoc{f.file->display, raw.line, raw.column},
                                   raw.offset, blk, parse_limits);
  SKIPNC_TRY(parsed);
  return true;
}

// At a sync or the end: what cutter compensation holds goes out, and the
// warning says which move ends perpendicular.
Flow<void> Interpreter::Impl::flush_held(Step why, CommandSink& out) {
  if (const std::uint32_t held = flush_comp(out); held != 0) {
    return warn("comp_lookahead",
                "cutter compensation: the move of line " + std::to_string(held) +
                    " ends perpendicular to its end point because " +
                    (why == Step::kEnd ? std::string("the program ends in G41/G42")
                                       : std::string("the interpreter waits for the machine "
                                                     "here (a live read, M00/M01, G31)")) +
                    "; the control does the same and the next move may overcut",
                loc(cur_col));
  }
  return {};
}

// The end of the running file: a subprogram returns, the main program ends.
Flow<Interpreter::Impl::Read> Interpreter::Impl::end_of_file() {
  if (programs.frames.size() > 1) {
    SKIPNC_TRY(return_from_sub(std::nullopt, loc(1)));
    return Read::kNext;
  }
  SKIPNC_TRY(
      warn("no_program_end", "the program ends at the end of its file without M02 or M30", loc(1)));
  ended = true;
  return Read::kEnd;
}

// A '%' line: the tape's start, a subprogram's end, or the main program's end.
Flow<Interpreter::Impl::Read> Interpreter::Impl::percent_block(const Frame& f) {
  if (programs.frames.size() == 1 && block_pos.offset == f.start.offset)
    return Read::kNext;  // tape start
  if (programs.frames.size() > 1) {
    SKIPNC_TRY(return_from_sub(std::nullopt, loc(1)));
    return Read::kNext;
  }
  // FANUC: % before M02/M30 is an alarm (PS5010 END OF RECORD); skipnc
  // ends the run there and says so (an alarm with --strict).
  SKIPNC_TRY(warn("no_program_end", "the program reaches % without M02 or M30", loc(1)));
  ended = true;
  return Read::kEnd;
}

// A program number heads a program. Reaching the next program's O block
// while running one means the running program ended without M99/M30:
// Fanuc treats the O as the start of a new program.
Flow<Interpreter::Impl::Read> Interpreter::Impl::program_number_block(Frame& f) {
  if (block_pos.offset != f.start.offset && programs.frames.size() > 1) {
    SKIPNC_TRY(return_from_sub(std::nullopt, loc(1)));
    return Read::kNext;
  }
  if (programs.frames.size() == 1 && f.program == 0) {
    f.program = blk.o;  // #4115 of the main program
    contexts.front().program = blk.o;
  }
  return Read::kNext;
}

// What the block just read is to the run: one to execute, one passed over
// (block delete, a program number, a comment line), or the program's end.
Flow<Interpreter::Impl::Read> Interpreter::Impl::classify_block(Frame& f) {
  // Block delete ("/" or "/n" at the start of the block): the block is
  // read and ignored while the operator's switch n is on (the dialect's
  // block_delete_param, bit n - 1).
  if (blk.block_delete >= 1 && dialect.sw.block_delete_param != 0 &&
      params.bit(dialect.sw.block_delete_param, blk.block_delete - 1)) {
    return Read::kNext;
  }
  if (blk.percent) return percent_block(f);
  if (blk.has_o && blk.words.empty() && blk.stmt.kind == gcode::StmtKind::kNone) {
    return program_number_block(f);
  }
  if (blk.empty() && lang->rules.comment_line_runs && !blk.comments.empty()) {
    return Read::kRun;  // (debug,..) reads parameters: it runs as a block (its comments)
  }
  if (blk.empty()) {
    for (const auto& c : blk.comments) {
      const std::string& t = blk.names[static_cast<std::size_t>(c.text)];
      if (t.size() >= 4 && (t.compare(0, 4, "MSG,") == 0)) add_message(t.substr(4));
    }
    return Read::kNext;
  }
  return Read::kRun;
}

Flow<Step> Interpreter::Impl::step_block(CommandSink& out) {
  if (ended) return Step::kEnd;
  if (pending != Pending::kNone) {
    return fail(AlarmId::kInternal, "step() called before sync()");
  }
  while (!rerun) {
    // Reads blocks until one to execute is in `blk`, or the program ends.
    Frame& f = programs.frames.back();
    auto got = read_block();
    SKIPNC_TRY(got);
    Read r = Read::kRun;
    if (!*got) {
      auto e = end_of_file();
      SKIPNC_TRY(e);
      r = *e;
    } else {
      f.resume = f.file->src->tell();
      if (blk.block_delete >= 1 || blk.percent || blk.has_o || blk.empty()) {
        auto c = classify_block(f);  // a block to pass over, or the end
        SKIPNC_TRY(c);
        r = *c;
      }
    }
    if (r == Read::kEnd) return Step::kEnd;
    if (r == Read::kRun) {
      SKIPNC_TRY(count_statement(cur_col));
      break;
    }
  }
  rerun = false;
  auto r = execute(out);
  if (!r && std::holds_alternative<NeedSync>(r.error())) {
    // A live value was read while motion was queued: wait for the motion,
    // then run the same block again (nothing of it was committed).
    rerun = true;
    pending = Pending::kRerun;
    return Step::kSync;
  }
  return r;
}

Flow<void> Interpreter::Impl::sync(const SyncState& s) {
  last_sync = s;
  motion_since_sync = false;
  const Pending was = pending;
  pending = Pending::kNone;
  if (was != Pending::kSkip) {
    // Under cutter compensation the tool centre is off the programmed point
    // by the offset vector; `pos` stays the programmed point.
    pos = s.machine_position - comp.vector();
    return {};
  }
  return finish_skip(s);
}

// ---------------------------------------------------------------------------

Interpreter::Interpreter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Interpreter::~Interpreter() = default;

Result<std::unique_ptr<Interpreter>> Interpreter::create(const Setup& setup,
                                                         const AxisVec& start_machine) {
  auto impl = std::make_unique<Impl>(setup);
  auto r = settled(impl->init(start_machine));
  SKIPNC_TRY(r);
  return std::unique_ptr<Interpreter>(new Interpreter(std::move(impl)));
}

Result<Step> Interpreter::step(CommandSink& out) {
  return settled(impl_->step(out));
}
Result<void> Interpreter::sync(const SyncState& state) {
  return settled(impl_->sync(state));
}

Result<Value> Interpreter::read_variable(int number) const {
  return settled(impl_->read_var(number, {}));
}
Result<Value> Interpreter::read_named(std::string_view name) const {
  // As the parser stores #<name>: upper case, without spaces.
  std::string key;
  for (char c : name) {
    if (c != ' ' && c != '\t')
      key += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return settled(impl_->read_named_var(key, {}));
}
const ModalState& Interpreter::modal() const noexcept {
  return impl_->modal;
}
AxisVec Interpreter::work_from_machine(const AxisVec& machine) const noexcept {
  AxisVec w;
  for (int i = 0; i < impl_->axis_count; ++i) w[i] = impl_->work_of(i, machine[i]);
  return w;
}
WorkFrame Interpreter::work_frame() const noexcept {
  WorkFrame f;
  f.unit_mm = impl_->unit_mm();
  const bool tool_in = impl_->dialect.sw.current_tool_offsets;
  for (int i = 0; i < impl_->axis_count; ++i) {
    f.scale[i] = impl_->axis_scale[static_cast<std::size_t>(i)];
    f.shift[i] = impl_->offset_total(i) - (tool_in ? impl_->tool_offset_total(i) : 0.0);
  }
  return f;
}
const std::vector<std::string>& Interpreter::messages() const noexcept {
  return impl_->messages;
}
const std::vector<Warning>& Interpreter::warnings() const noexcept {
  return impl_->warnings;
}
const std::vector<SkipRecord>& Interpreter::skips() const noexcept {
  return impl_->skips;
}
std::uint32_t Interpreter::line() const noexcept {
  return impl_->cur_line;
}
std::uint32_t Interpreter::context() const noexcept {
  return impl_->programs.frames.empty() ? 0 : impl_->programs.frames.back().context;
}
const std::vector<CallContext>& Interpreter::contexts() const noexcept {
  return impl_->contexts;
}
const SkipRecord* Interpreter::pending_skip() const noexcept {
  return impl_->pending == Pending::kSkip ? &impl_->pending_skip.record : nullptr;
}
AxisVec Interpreter::position() const noexcept {
  return impl_->pos + impl_->comp.vector();
}
Result<void> Interpreter::save_persistent() {
  // The DPRNT file (--dprnt) is written here too, whole, once per run.
  auto d = impl_->print.write();
  if (!d) return d;
  // The language's log files and persistent parameters (language.cpp).
  Result<void> r = impl_->lang->save_persistent(*impl_);
  impl_->persistent_lock.release();
  return r;
}
void Interpreter::release_persistent() noexcept {
  impl_->persistent_lock.release();
}

}  // namespace skipnc::interp
