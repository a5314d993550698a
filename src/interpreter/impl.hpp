// Internal state of the interpreter, shared by its translation units:
//   interpreter.cpp  reading and executing blocks, sync, the public interface
//   language.cpp     the language objects (language.hpp): Macro B, RS274NGC, grbl;
//                    their work in ngc_params.cpp, ngc_codes.cpp, ngc_room.cpp,
//                    grbl_system.cpp (members of the objects, not of Impl)
//   oword.cpp        RS274NGC's O-word flow (members of Rs274ngc)
//   macro_flow.cpp   macro statements: assignment, IF, GOTO, WHILE/DO/END, DPRNT
//   macro_call.cpp   M98/G65/G66 calls, M99 returns, arguments (programs are
//                    found by the program store, program_store.hpp)
//   expr.cpp         expression evaluation and the vacant rules
//   sysvars.cpp      system variables (#3000.., #4000.., #5000..)
//   ncblock.cpp      address words, the NC block as a transaction
//   block_plan.cpp   the block's plan: codes, groups, addresses, modal state
//   block_commit.cpp the block's commit: its steps in the control's order
//   offsets.cpp      machine <-> work through the offsets, G43, G10
//   motion.cpp       rapid, feed, arc, dwell commands
//   skip.cpp         the skip family (G31): dialect rules in, results out
//   skip_rules.cpp   the skip block's decisions as pure functions
//   mill_codes.cpp   the mill's codes beside the core table: canned cycles,
//                    G68/G16/G51/G51.1 frames, codes without effect, codes
//                    not simulated (pure parts in cycles.cpp, transform.cpp),
//                    the block's commands through cutter compensation
//   cutter_comp.cpp  cutter radius compensation C: the tool centre path
// What one feature alone keeps is an object of its own, one member here or
// in BlockState (docs/architecture.md, "Inside the interpreter"):
// PrintChannel (DPRNT), ToolMeasurement (G37), ModalMacro (G66),
// CallArguments (G65/G66 arguments), SkipResults (the last latch, #5061..),
// ControlVariables (#3001-#3005), FunctionSettings (NAT, ROUND in a word),
// CompStage (cutter compensation); in BlockState LatheState, FrameCodeState
// (G16, G68's angle), SkipBlockState (G31.n, the last cutting feed) and
// cycles::Data (canned cycles).
#pragma once

#include <array>
#include <bit>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <variant>
#include <vector>

#include "gcode/ast.hpp"
#include "gcode/parser.hpp"
#include "gcode/source.hpp"
#include "interpreter/block_state.hpp"
#include "interpreter/call_args.hpp"
#include "interpreter/codes.hpp"
#include "interpreter/comp_stage.hpp"
#include "interpreter/control_vars.hpp"
#include "interpreter/cutter_comp.hpp"
#include "interpreter/cycles.hpp"
#include "interpreter/flow.hpp"
#include "interpreter/func_settings.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/journal.hpp"
#include "interpreter/language.hpp"
#include "interpreter/modal_macro.hpp"
#include "interpreter/offset_units.hpp"
#include "interpreter/print_channel.hpp"
#include "interpreter/program_store.hpp"
#include "interpreter/skip_results.hpp"
#include "interpreter/skip_rules.hpp"
#include "interpreter/tool_measure.hpp"
#include "interpreter/transform.hpp"

namespace skipnc::interp {

namespace sysvar {
struct Range;
}

// Additional work coordinate systems G54.1 P1-P300 follow EXT and G54-G59.
inline constexpr int kExtraWorkSystems = 300;
inline constexpr int kWorkSystems = 7 + kExtraWorkSystems;

// One word's value after evaluation.
struct WordVal {
  double value = 0.0;
  bool has_point = false;
  bool is_expr = false;
  std::uint32_t column = 0;
};

// The words of one block, by address: w[c] holds address 'A' + c where
// bit c of `letters` is set (and is stale elsewhere).
struct Words {
  std::array<WordVal, 26> w;
  std::uint32_t letters = 0;
  int g_count = 0;
  std::array<GCode, 16> g{};
  std::array<std::uint32_t, 16> g_col{};
  int m_count = 0;
  std::array<int, 3> m{};
  static std::uint32_t bit(char c) noexcept { return 1u << (c - 'A'); }
  bool has(char c) const noexcept { return (letters & bit(c)) != 0; }
  const WordVal& at(char c) const noexcept { return w[static_cast<std::size_t>(c - 'A')]; }
  void set(char c, const WordVal& v) noexcept {
    w[static_cast<std::size_t>(c - 'A')] = v;
    letters |= bit(c);
  }
  void erase(char c) noexcept { letters &= ~bit(c); }
  // A cleared Words is as a new one.
  void clear() noexcept {
    letters = 0;
    g_count = 0;
    m_count = 0;
  }
  bool has_g(GCode code) const noexcept {
    for (int i = 0; i < g_count; ++i) {
      if (g[static_cast<std::size_t>(i)] == code) return true;
    }
    return false;
  }
};

// The codes of mill_codes.cpp seen in one block (planned, applied at commit).
struct MillRequest {
  const CodeDef* frame = nullptr;  // G68 G69 G50 G51 G50.1 G51.1, null: none
  std::string no_effect;           // a code accepted without effect: what it is (warning)
  SourceLoc frame_at;
  std::optional<Cycle> cycle;
  std::optional<bool> polar;  // G16 (true) / G15 (false)
  int skip_step = 0;          // G31.1-G31.3 (Mitsubishi multi-step skip function 1)
  bool g37 = false;           // automatic tool length measurement
  bool lookahead = false;     // G103 (block_lookahead_g103)
};

// The plan of one NC block (ncblock.cpp plan_block): its codes by group,
// its one-shot action and the modal state it leaves. Built without changing
// the interpreter.
struct BlockPlan {
  std::array<const CodeDef*, kGroupSlots> group{};  // the block's code of each modal group
  std::uint32_t named = 0;  // bit g: group[g] is set (plan_modal visits only these)
  // Each block's column of group[g], set with it and read only where group[g]
  // is set: not cleared for every block.
  std::array<std::uint32_t, kGroupSlots> column;
  Action action = Action::kNone;  // the group-00 command (G09 and G53 are flags)
  GCode action_code;
  bool exact_stop = false;     // G09
  bool machine_coord = false;  // G53
  int tool_pos_offset = 0;     // 45..48 for G45-G48
  bool call = false;           // G65 / G66 block
  std::int64_t call_program = 0;
  int call_repeats = 1;
  bool spindle_changed = false;
  MillRequest mill;  // cycles, frames, G16, G31.n, G37 (mill_codes.cpp)
  ModalState next;
};

// The plain motion block (ncblock.cpp plain_block): G00-G03 or no G code,
// axis words, F, I J K R and nothing else. What it needs of the machine,
// the dialect and the language, found once at the start of the run.
struct PlainBlock {
  bool on = false;                    // a mill: a lathe's blocks all take the transaction
  std::uint32_t letters = 0;          // bit c: address 'A' + c may be in a plain block
  std::array<bool, 4> motion_code{};  // G00-G03 are this control's motion codes
  double slowest_feed = 0.0;          // the lowest max_feed of the axes, mm/min (check_feeds)
  // Found again when Impl::shifts or Impl::program_frame changed (take_changed):
  bool moves_pending = false;  // a G45-G48 change or T offset to carry (AxisShifts)
  bool framed = false;         // a G68 / G51 / G51.1 / G68 I J K / G54.4 frame
};

// The parameters every motion block reads, read once at the start of the
// run (a run's parameters do not change while it runs).
struct BlockParams {
  bool linear_rapid = false;        // 1401#1 LRP (config::param::kLinearRapid)
  bool calculator_decimal = false;  // 3401#0 DPI (config::param::kCalculatorDecimal)
  double arc_tolerance = 0.02;      // 3410 (kArcRadiusTolerance), 0: 0.02 mm
};

// The commands of the block being executed, passed on when it succeeds.
struct BlockBuffer final : CommandSink {
  std::vector<canon::Stamped> cmds;
  void emit(const canon::Stamped& cmd) override { cmds.push_back(cmd); }
};

struct PendingSkip {
  SkipRecord record;
  AxisVec target;  // programmed end point, machine coordinates
  bool alarm_on_miss = false;
  SourceLoc loc;
  std::array<std::string, canon::SkipSpec::kMaxInputs> input_names;
  std::optional<GCode> g38;  // G38.2-G38.5 (none: not a G38 probe)
};

// The small state a block may change is the base BlockState (block_state.hpp);
// the large tables are journaled (journal.hpp: the offset tables, the base
// OffsetTables; the variables, variables.hpp).
struct Interpreter::Impl : BlockState, OffsetTables {
  Setup setup;
  const config::MachineConfig& mc;
  const config::Dialect& dialect;
  const config::Parameters& params;
  int axis_count = 0;
  std::array<char, kMaxAxes> axis_letter{};
  std::array<int, 26> axis_of_letter{};  // -1 when the letter is not an axis
  std::uint32_t axis_letters = 0;        // bit c set: letter 'A' + c is an axis

  // Program files, their indexes, include folders, the call stack
  // (program_store.hpp; programs.frames is the call stack).
  ProgramStore programs;
  std::vector<CallContext> contexts;  // every call path met; [0] the main program
  gcode::Block blk;
  BlockBuffer block_buffer;  // the running block's commands (reused)
  Words cur_words;           // the current block's words (reused: cleared, not rebuilt, per block)
  gcode::RawBlock raw;       // the current block's text: valid until the next block is read
  gcode::SourcePos block_pos;  // position of the current block
  PendingSkip pending_skip;
  bool rerun = false;  // re-executing the block after a sync
  std::uint32_t cur_line = 0;
  std::uint32_t cur_col = 1;

  // G52, G92, G45-G48 and a lathe's T code shifts (block_state.hpp).
  BlockSaved<AxisShifts> shifts;
  // The program -> work frame (G68 rotation, G51 scaling, G51.1 mirror,
  // G68 I J K, G54.4; mill_codes.cpp apply_frame_code writes it), read
  // through frame().
  BlockSaved<xform::Transform> program_frame;
  const xform::Transform& frame() const noexcept { return program_frame.get(); }
  int length_axis = 2;
  // Lathe (lathe.cpp). Program values of an axis are `axis_scale` times its
  // machine coordinate: 2 for an X axis programmed in diameter (1006#3), 1
  // otherwise. Offsets (work, G50/G92, G52, T) are kept in program values.
  std::array<double, kMaxAxes> axis_scale{};
  VariableStore vars;
  SkipResults skip_result;  // the last skip's latch, #5061.. (skip_results.hpp)
  SyncState last_sync;
  std::vector<std::string> messages;
  // Keeps an operator message for the report; past limits.max_message_bytes
  // the rest are dropped and one message says so (memory stays bounded, the
  // run goes on: a message is not the machine's business).
  void add_message(std::string text) {
    if (messages_dropped) return;
    if (message_bytes + static_cast<std::int64_t>(text.size()) > mc.limits.max_message_bytes) {
      messages_dropped = true;
      messages.push_back("(further messages dropped: limits.max_message_bytes = " +
                         std::to_string(mc.limits.max_message_bytes) + ")");
      return;
    }
    message_bytes += static_cast<std::int64_t>(text.size());
    messages.push_back(std::move(text));
  }
  std::vector<SkipRecord> skips;
  // Structured warnings (interpreter.hpp Warning); under --strict warn()
  // fails instead, so the block that raised it ends the run.
  std::vector<Warning> warnings;
  Flow<void> warn(const char* code, std::string text, SourceLoc where);
  std::uint32_t skip_missed_line = 0;
  std::int64_t statements = 0;
  std::int64_t parts_required = 0;
  ControlVariables control_vars;  // #3001-#3005 (control_vars.hpp)
  gcode::ParseLimits parse_limits;
  FunctionSettings functions;  // 6004#0 NAT, ROUND in a word (func_settings.hpp)
  CallArguments call_args;     // the G65/G66 block being executed (call_args.hpp)
  ModalMacro g66;              // the G66 macro the moving blocks call (modal_macro.hpp)
  // DPRNT: lines between POPEN and PCLOS, written whole at the end of the
  // run (print_channel.hpp).
  PrintChannel print{setup.dprnt_path, mc.limits.max_dprnt_bytes};

  // Held from the read of #500-#999 to their write (variables.hpp).
  PersistentLock persistent_lock;

  // The dialect's language (language.hpp): its rules, its own state.
  std::unique_ptr<Language> lang = make_language(dialect.sw.language);

  // How the program text is cut into blocks: ';' is a comment in RS274NGC and grbl.
  gcode::SourceLimits source_limits() const noexcept {
    gcode::SourceLimits l;
    l.semicolon_ends_block = lang->rules.semicolon_ends_block;
    return l;
  }

  Impl(const Setup& s);
  ~Impl();

  // interpreter.cpp
  Flow<void> init(const AxisVec& start);
  // One block; at a point where the machine must catch up (a sync) or at
  // the end, what cutter compensation holds goes out first (flush_held).
  Flow<Step> step(CommandSink& out) {
    auto r = step_block(out);
    if (r && (*r == Step::kSync || *r == Step::kEnd) && !comp.idle()) {
      SKIPNC_TRY(flush_held(*r, out));
    }
    return r;
  }
  Flow<void> flush_held(Step why, CommandSink& out);
  Flow<Step> step_block(CommandSink& out);
  void init_axes();
  void init_tables();
  Flow<void> init_variables();
  Flow<void> open_main();
  // The block read, to step_block: run it, read the next one, or the end.
  enum class Read : std::uint8_t { kRun, kNext, kEnd };
  Flow<Read> classify_block(Frame& f);
  Flow<Read> end_of_file();
  Flow<Read> percent_block(const Frame& f);
  Flow<Read> program_number_block(Frame& f);
  Flow<Step> execute(CommandSink& out) { return lang->execute(*this, out); }  // language.cpp
  Flow<bool> read_block();
  Flow<void> sync(const SyncState& s);
  SourceLoc loc(std::uint32_t column) const noexcept {
    return SourceLoc{programs.frames.empty()
                         ? std::string_view(setup.program_name)
                         : std::string_view(programs.frames.back().file->display),
                     cur_line, column};
  }
  // The statement limit; `column` names the block in its alarm.
  Flow<void> count_statement(std::uint32_t column) {
    if (++statements > mc.limits.max_macro_statements) [[unlikely]] {
      return statement_limit(column);
    }
    return {};
  }
  Flow<void> statement_limit(std::uint32_t column) const;

  // macro_flow.cpp
  Flow<Step> execute_statement();
  Flow<Step> goto_statement(const gcode::Stmt& s, SourceLoc where);
  Flow<Step> loop_statement(const gcode::Stmt& s, SourceLoc where);  // WHILE, DO
  Flow<Step> pass_false_while(int id, SourceLoc where);
  Flow<Step> end_statement(int id, SourceLoc where);
  Flow<bool> condition(gcode::ExprId cond, SourceLoc where);
  // GOTO / M99 P: the first N n after the block at offset `from`, else the first one.
  Flow<void> jump_to_label(std::int64_t n, std::uint64_t from, SourceLoc where);
  Flow<void> find_loop_end(Loop& l);
  Flow<void> leave_loops_for(std::uint64_t target);
  Flow<void> print_line(SourceLoc where);

  // macro_call.cpp
  Flow<void> call(std::int64_t program, int repeats, bool macro, SourceLoc where,
                  bool modal_call = false);
  std::uint32_t context_of(CallContext c);  // index of c, added when new
  Flow<void> push_frame(Frame f, std::string call, SourceLoc where);
  Flow<Step> return_from_sub(std::optional<std::int64_t> label, SourceLoc where);
  Flow<void> local_call(std::int64_t label, int repeats, SourceLoc where);
  Flow<void> macro_call(std::int64_t program, int repeats, bool modal_call, SourceLoc where);
  Flow<void> collect_argument(const gcode::Word& w, const WordVal& v, int& ijk_set, int& ijk_last);
  bool in_modal_call() const noexcept;

  // expr.cpp
  // The language's evaluator (lang->expr): a fast path without alarms,
  // then, where it gives up, every rule with its alarms.
  Flow<Value> eval(gcode::ExprId id);
  Flow<int> var_number(gcode::ExprId lhs);
  Flow<void> assign(gcode::ExprId lhs, Value v);

  // sysvars.cpp: read_var .. write_named_var ask the language; Macro B's
  // variables are read_macro_var .. write_macro_named.
  Flow<Value> read_var(int n, SourceLoc where);
  Flow<Value> read_macro_var(int n, SourceLoc where);
  Flow<void> write_macro_var(int n, Value v, SourceLoc where);
  Flow<Value> read_macro_named(const std::string& name, SourceLoc where);
  Flow<void> write_macro_named(const std::string& name, Value v, SourceLoc where);
  Flow<Value> read_position(const sysvar::Range& r, int i, SourceLoc where);
  Value read_modal(const sysvar::Range& r, int i) const;
  Value read_control(const sysvar::Range& r, int n) const;
  Flow<void> write_control(const sysvar::Range& r, int n, Value v, SourceLoc where);
  Flow<void> write_var(int n, Value v, SourceLoc where);
  double* tool_field(const sysvar::Range& r, int k) noexcept;
  Flow<Value> read_named_var(const std::string& name, SourceLoc where);
  Flow<void> write_named_var(const std::string& name, Value v, SourceLoc where);

  // ncblock.cpp (the transaction), block_plan.cpp (plan_*), block_commit.cpp
  // (commit_*), offsets.cpp (the offsets, G43, G10)
  Flow<void> collect_words(Words& words);
  Flow<void> code_word(Words& words, const gcode::Word& w, double value) const;
  // An NC block: a plain motion block (plain_block) or the transaction.
  Flow<Step> execute_nc(const Words& words, CommandSink& out) {
    if (plain_block(words, out)) return Step::kContinue;
    return run_block(words, out);
  }
  Flow<Step> run_block(const Words& words, CommandSink& out);
  PlainBlock plain;
  BlockParams block_params;
  void init_plain();
  bool plain_code(GCode code) const;
  bool plain_block(const Words& words, CommandSink& out);
  const AxisVec* plain_move(const Words& words, canon::Command& cmd, const AxisVec& fallback);
  canon::Stamped plain_out;  // the plain block's command (reused)
  bool block_calls(const Words& words, const BlockPlan& plan) const noexcept;
  void begin_tables(bool calls);
  void commit_tables() noexcept;
  void roll_back_tables(bool calls);
  // What the block started from, beside BlockState, the journals and the
  // language's own (Language::begin_block; reused from block to block): the
  // call stack and the G66 macro when the block may call.
  struct Before {
    std::vector<Frame> frames;
    ModalMacro g66;
  } before_block;
  Flow<void> plan_block(const Words& words, BlockPlan& plan);
  Flow<void> plan_g_codes(const Words& words, BlockPlan& plan);
  Flow<const CodeDef*> g_code_def(GCode code, std::uint32_t col) const;
  Flow<void> plan_one_shot(const CodeDef& def, std::uint32_t col, BlockPlan& plan);
  Flow<void> plan_call(const Words& words, BlockPlan& plan);
  Flow<void> plan_addresses(const Words& words) const;
  static bool has_m(const Words& words, int code);
  Flow<void> plan_mill(BlockPlan& plan) const;
  void plan_cycle(BlockPlan& plan) const;
  Flow<void> plan_modal(const Words& words, BlockPlan& plan);
  Flow<int> offset_number(const Words& words, char letter) const;
  Flow<Step> commit_block(const Words& words, const BlockPlan& plan, CommandSink& out);
  // The block's (MSG, ...) comments, then its N (#4114).
  void commit_messages() {
    if (!blk.comments.empty()) comment_messages();
    if (blk.has_n) modal.seq = static_cast<int>(blk.n % 100000000);
  }
  void comment_messages();
  Flow<Step> commit_call(const BlockPlan& plan);
  void commit_modal(const Words& words, const BlockPlan& plan, CommandSink& out);
  Flow<void> commit_tool(const Words& words, const ModalState& before, CommandSink& out);
  void commit_spindle(const Words& words, bool changed, CommandSink& out);
  Flow<void> commit_shift(const Words& words, bool local);
  void commit_tool_pos_offset(const Words& words, int g);
  void commit_cycle_start(const ModalState& before);
  Flow<int> lookahead_limit(const Words& words) const;  // G103
  Flow<std::optional<Step>> commit_mill(const Words& words, const BlockPlan& plan, CommandSink& out,
                                        bool& moved);
  Flow<Step> commit_action(const Words& words, const BlockPlan& plan, CommandSink& out,
                           bool& moved);
  Flow<std::optional<Step>> commit_m_codes(const Words& words, CommandSink& out);
  Flow<Step> commit_sub_call(const Words& words);
  Flow<Step> commit_sub_return(const Words& words);
  Flow<Step> commit_local_sub_call(const Words& words);
  double unit_mm() const noexcept { return modal.units == Units::kInch ? 25.4 : 1.0; }
  // mm per unit of the values an RS274NGC control stores (#5161-#5390): the
  // machine's unit, not the program's (ngc_codes.cpp).
  // The unit of #5161-#5390: the machine's (LinuxCNC); grbl keeps mm whatever
  // the machine file says (its internal unit; $13 changes only the reports).
  double stored_mm() const noexcept {
    return mc.inch_machine && lang->rules.params_in_machine_unit ? 25.4 : 1.0;
  }
  // A length word in program units (a rotary axis too): without a decimal
  // point it is in least input increments.
  double word_length(const WordVal& w) const noexcept {
    if (w.is_expr || w.has_point || block_params.calculator_decimal) return w.value;
    return w.value * (modal.units == Units::kInch ? 0.0001 : 0.001);
  }
  double offset_total(int axis) const noexcept;                // mm
  double work_of(int axis, double machine_mm) const noexcept;  // program units
  // The tool offsets on an axis (length, G45-G48, lathe tool offset), mm.
  double tool_offset_total(int axis) const noexcept;
  // A position variable's value: work_of, or with the tool offsets left in
  // (the tool reference point) when the dialect says so for that variable.
  double position_var(int axis, double machine_mm, bool tool_offsets) const noexcept;
  double machine_of(int axis, double work_units) const noexcept;  // mm
  Flow<void> set_tool_length(const Words& words, LengthComp mode);
  Flow<void> data_setting(const Words& words, SourceLoc where);  // the language's G10
  Flow<void> data_setting_fanuc(const Words& words, SourceLoc where);
  // An offset or stored position (G10, G92, G52, G50, #2001.., #5201..,
  // LinuxCNC #5161-#5390) beyond kMaxOffsetMm: illegal_offset_value.
  static constexpr double kMaxOffsetMm = 999999.999;
  static Flow<void> check_offset(double mm, const std::string& what, SourceLoc at);

  // mill_codes.cpp
  // Parameters of G31.n: the skip condition; the feed is the next number.
  static constexpr int kSkipStepParam = skip_rules::kStepParam;
  static constexpr int kSettingErrorParam = 11200;  // G54.4 (fanuc.toml)
  Flow<bool> mill_code(const CodeDef& def, SourceLoc at, MillRequest& req) const;
  Flow<bool> apply_frame_code(const Words& words, const MillRequest& req);
  // G68 I J K (conversion_3d.cpp): the frame with one more 3-D conversion.
  Flow<xform::Transform> conversion_3d(const Words& words, const MillRequest& req,
                                       const xform::Point& here) const;
  Flow<xform::Transform> setting_error(const Words& words, const MillRequest& req) const;  // G54.4
  bool frame_active() const noexcept { return frame_codes.polar || frame().active(); }
  Flow<void> frame_targets(const Words& words, AxisVec& target, AxisMask& moved);
  // Cutter radius compensation (cutter_comp.hpp): the block's commands go
  // through the compensator when G41/G42 is active or a vector is left.
  CompStage comp;  // the compensator and its output buffer (comp_stage.hpp)
  Flow<crc::BlockMode> comp_mode(const BlockPlan& plan) const;
  Flow<void> check_feeds(const AxisVec& start);  // warning feed_clamped
  Flow<void> pass_block(const BlockPlan& plan, const AxisVec& start, CommandSink& out);
  // Returns the line of the move it ended perpendicular (0: nothing held).
  std::uint32_t flush_comp(CommandSink& out);
  // Moves the compensator does not offset: refused under G41/G42 (canned
  // cycles, G37) and, on a lathe, tool nose radius compensation.
  Flow<void> refuse_under_comp(const char* what, SourceLoc where) const;
  Flow<void> check_nose_radius_comp(SourceLoc where) const;
  Flow<Step> g37_block(const Words& words, CommandSink& out);
  Flow<void> finish_g37(const SyncState& s);
  ToolMeasurement g37;  // the G37 under way (tool_measure.hpp)

  // motion.cpp
  Flow<Step> motion(const Words& words, CommandSink& out, bool skip, bool g53);
  // skip.cpp
  Flow<Step> skip_block(const Words& words, const AxisVec& target, AxisMask moved,
                        CommandSink& out);
  Flow<void> refuse_skip_arc(const Words& words, SourceLoc at) const;
  skip_rules::BlockWords skip_words(const Words& words, AxisMask moved, SourceLoc at) const;
  Flow<void> skip_inputs(const skip_rules::BlockWords& b, const skip_rules::Form& form,
                         canon::SkipSpec& spec);
  Flow<void> finish_skip(const SyncState& s);
  AxisVec record_skip(const SyncState& s);
  Flow<Step> queue_skip(const canon::Skip& sk, SourceLoc at, CommandSink& out);
  // probe_g38.cpp: G38.2-G38.5
  Flow<Step> probe_block(const AxisVec& target, AxisMask moved, CommandSink& out);
  Flow<void> finish_probe(const SyncState& s);
  bool probe_inverted() const noexcept;  // the probe input's sense
  Flow<void> arc(const Words& words, const AxisVec& target, CommandSink& out);
  Flow<void> arc_move(const Words& words, const AxisVec& target, canon::Arc& a) const;
  Flow<void> dwell(const Words& words, CommandSink& out);
  Flow<void> reference_return(const Words& words, int g, CommandSink& out);  // the language's
  Flow<void> reference_return_fanuc(const Words& words, int g, CommandSink& out);
  Flow<Step> canned_cycle(const Words& words, CommandSink& out);
  // The modal F as a path feed: in feed per revolution, times the spindle
  // speed at the present position (0 with the spindle stopped).
  double feed_mm_per_min() const noexcept { return feed_to_mm_per_min(modal.feed); }
  double feed_to_mm_per_min(double f) const noexcept;
  // lathe.cpp
  // Target of the axis words of a block (X/U, Z/W, C/H on a lathe) in
  // machine coordinates; `moved` gets the axes that have a word.
  Flow<void> axis_targets(const Words& words, bool g53, AxisVec& target, AxisMask& moved);
  Flow<void> lathe_axis_words(const Words& words) const;  // X and U (Z and W) in one block
  void axis_target(int axis, const WordVal& w, bool inc_word, bool g53, AxisVec& target);
  void mill_axis_words(const Words& words, std::uint32_t letters, bool g53, AxisVec& target,
                       AxisMask& moved);
  bool has_axis_word(const Words& words) const noexcept;
  char incremental_letter(int axis) const noexcept;  // U W H on a lathe, 0 otherwise
  double spindle_rpm_at(const AxisVec& machine) const noexcept;
  Flow<void> need_spindle_for_feed(std::uint32_t column) const;  // column: of the alarm
  Flow<void> lathe_tool(const Words& words, ModalState& next);
  Flow<void> lathe_coordinate_setting(const Words& words);
  Flow<void> lathe_offset_setting(const Words& words, SourceLoc where);
  void emit_spindle(CommandSink& out);
  Flow<void> turning_cycle(const Words& words, AxisVec& target, AxisMask moved, CommandSink& out);
  void emit(CommandSink& out, canon::Command cmd);
  // The block's line, context and N on a command.
  void stamp(canon::Stamped& st) const noexcept {
    st.line = cur_line;
    st.source = programs.frames.back().context;
    st.n = blk.has_n ? static_cast<std::int32_t>(blk.n % 100000000) : -1;
  }
};

// Read for every axis word (inline: a few times per block).
inline double Interpreter::Impl::offset_total(int axis) const noexcept {
  double o = (work_offsets[0][axis] + work_offsets[static_cast<std::size_t>(modal.work)][axis]) *
                 offset_unit_mm(*this) +
             shifts.get().local_shift[axis] + shifts.get().g92_shift[axis] +
             shifts.get().tool_pos_offset[axis] + shifts.get().lathe_tool_offset[axis];
  if (axis == length_axis) o += length_offset;
  return o;
}

inline double Interpreter::Impl::machine_of(int axis, double work_units) const noexcept {
  return (work_units * unit_mm() + offset_total(axis)) / axis_scale[static_cast<std::size_t>(axis)];
}

}  // namespace skipnc::interp
