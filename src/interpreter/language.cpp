// The language objects (language.hpp): each language's rules, and the
// interpreter's parts each of its questions goes to.
#include "interpreter/language.hpp"

#include <string>

#include "interpreter/impl.hpp"

namespace skipnc::interp {

namespace {

constexpr Language::Rules kMacroBRules{};

// LinuxCNC 2.9 (docs/languages.md, "RS274NGC as skipnc runs it"; each rule
// is cited where it is used).
constexpr Language::Rules kRs274ngcRules = [] {
  Language::Rules r;
  r.kind = config::Language::kRs274ngc;
  r.syntax = gcode::Syntax::kRs274ngc;
  r.semicolon_ends_block = false;
  r.comment_line_runs = true;
  r.round_computed_words = false;
  r.e_word_for_m67_only = true;
  r.dwell_p_seconds = true;
  r.g53_g0_g1_only = true;
  r.arc_turns_p = true;
  r.arc_radius_linuxcnc = true;
  r.cycle_levels_linuxcnc = true;
  r.g43_tool_in_spindle = true;
  r.state_codes = true;
  r.offsets_in_mm = true;
  r.offsets_in_params = true;
  return r;
}();

// grbl 1.1 (gcode.c, "Grbl v1.1 Commands"): LinuxCNC's codes and stored
// values, its own words ("Non-Command Words": no D, E, H or Q), G10 without
// P the active system, #5161.. in mm whatever the machine file says.
constexpr Language::Rules kGrblRules = [] {
  Language::Rules r = kRs274ngcRules;
  r.kind = config::Language::kGrbl;
  r.syntax = gcode::Syntax::kGrbl;
  r.addresses = "FSTPRKLIJ";
  r.address_owner = "control";
  r.e_word_for_m67_only = false;
  r.g10_p_optional = true;
  r.state_codes = false;
  r.params_in_machine_unit = false;
  return r;
}();

// The parameter settings of an RS274NGC line: every value is read first,
// then all are set (LinuxCNC: "parameter setting" happens after the whole
// line is read, so "#1=2 #2=#1" gives #2 the old #1).
Flow<void> assignments(Interpreter::Impl& im) {
  if (im.blk.assigns.empty()) return {};
  std::vector<Value> values;
  values.reserve(im.blk.assigns.size());
  for (const gcode::Assignment& a : im.blk.assigns) {
    auto v = im.eval(a.rhs);
    SKIPNC_TRY(v);
    values.push_back(Value::of(v->num()));
  }
  for (std::size_t i = 0; i < im.blk.assigns.size(); ++i) {
    auto r = im.assign(im.blk.assigns[i].lhs, values[i]);
    if (!r) return r;
  }
  return {};
}

// An RS274NGC line of words: read with the parameters as they were before
// it, then its settings, its comments, its codes. (Inlined: once per block.)
[[gnu::always_inline]] inline Flow<Step> words_line(Interpreter::Impl& im, LinuxcncFamily& lang,
                                                    CommandSink& out) {
  im.cur_words.clear();
  auto w = im.collect_words(im.cur_words);
  SKIPNC_TRY(w);
  auto a = assignments(im);
  SKIPNC_TRY(a);
  auto c = lang.comments(im);
  SKIPNC_TRY(c);
  if (im.blk.words.empty()) return Step::kContinue;
  return im.execute_nc(im.cur_words, out);
}

}  // namespace

std::unique_ptr<Language> make_language(config::Language kind) {
  switch (kind) {
    case config::Language::kRs274ngc:
      return std::make_unique<Rs274ngc>();
    case config::Language::kGrbl:
      return std::make_unique<Grbl>();
    case config::Language::kMacroB:
      break;
  }
  return std::make_unique<MacroB>();
}

// ---- What a language has unless it says otherwise: Macro B's

Flow<void> Language::load_persistent(Impl& im) {
  return Flow<void>(interp::load_persistent(im.mc.persistent_vars, im.vars.persistent()));
}

Result<void> Language::save_persistent(Impl& im) {
  if (im.mc.persistent_vars.empty() || !im.vars.persistent_dirty()) return {};
  return interp::save_persistent(im.mc.persistent_vars, im.vars.persistent());
}

// #1-#33, #100-#199, #500-#999.
Flow<void> Language::preset(Impl& im, int n, double v) {
  if (VariableStore::is_persistent(n)) {
    im.vars.persistent()[static_cast<std::size_t>(n - 500)] = Value::of(v);
  } else if (VariableStore::is_local(n) || VariableStore::is_common(n)) {
    im.vars.set(n, Value::of(v));
  } else {
    return fail(AlarmId::kUsage, "variable #" + std::to_string(n) +
                                     " cannot be set before a run (#1-#33, #100-#199, #500-#999)");
  }
  return {};
}

Flow<Value> Language::read_param(Impl& im, int n, SourceLoc where) {
  return im.read_macro_var(n, where);  // sysvars.cpp
}

Flow<void> Language::write_param(Impl& im, int n, Value v, SourceLoc where) {
  return im.write_macro_var(n, v, where);
}

Flow<Value> Language::read_named(Impl& im, const std::string& name, SourceLoc where) {
  return im.read_macro_named(name, where);
}

Flow<void> Language::write_named(Impl& im, const std::string& name, Value v, SourceLoc where) {
  return im.write_macro_named(name, v, where);
}

Flow<void> Language::reference_return(Impl& im, const Words& words, int g, CommandSink& out) {
  return im.reference_return_fanuc(words, g, out);  // motion.cpp
}

Flow<void> Language::data_setting(Impl& im, const Words& words, SourceLoc where) {
  return im.data_setting_fanuc(words, where);  // ncblock.cpp
}

// The dialect's success flag, when it has one.
void Language::store_probe(Impl& im, const AxisVec&, bool triggered) {
  if (im.dialect.skip_vars.success_flag > 0) {
    im.vars.set(im.dialect.skip_vars.success_flag, Value::of(triggered ? 1.0 : 0.0));
  }
}

bool Language::probe_inverted(const Impl& im, int param) const {
  return im.params.bit(param, 0);
}

// Macro B keeps no work offsets, G92 or modal states in parameters and has
// no code of Action::kNgc (the code table gives it none).
void Language::select_work(Impl&, int) {}

void Language::store_g92(Impl&) {}

Flow<void> Language::own_action(Impl& im, const Words&, GCode code) {
  return fail(AlarmId::kInternal, "no action for " + code_name(code), im.loc(im.cur_col));
}

Flow<void> Language::state_codes(Impl&, const Words&, const ModalState&, SourceLoc) {
  return {};
}

void Language::begin_block() {}

void Language::roll_back_block() {}

// ---- Macro B

MacroB::MacroB() : Language(kMacroBRules, kMacroBExpr) {}

void MacroB::start(Impl&) {}

Flow<Step> MacroB::execute(Impl& im, CommandSink& out) {
  if (im.blk.stmt.kind != gcode::StmtKind::kNone) {
    if (!im.blk.words.empty()) {
      // Fanuc: an NC statement and a macro statement in one block (PS0127).
      const gcode::Word& w = im.blk.words.front();
      return fail(AlarmId::kNcMacroStatement,
                  std::string("NC address ") + w.letter + " and a macro statement in one block",
                  im.loc(w.column));
    }
    if (im.blk.has_n) im.modal.seq = static_cast<int>(im.blk.n % 100000000);  // #4114
    return im.execute_statement();
  }
  if (im.blk.condition != gcode::kNoExpr) [[unlikely]] {
    // Haas's `[expr] M99 Pn`: every expression is a condition, 0 false and
    // anything else true (96-8000, Macros, "Conditional expressions"); a
    // false one passes the block by.
    auto v = im.eval(im.blk.condition);
    SKIPNC_TRY(v);
    if (v->num() == 0.0) return Step::kContinue;
  }
  im.cur_words.clear();
  auto c = im.collect_words(im.cur_words);
  SKIPNC_TRY(c);
  return im.execute_nc(im.cur_words, out);
}

// ---- LinuxCNC and grbl

// The log files of (LOGOPEN,..) and (PROBEOPEN ..), then the persistent
// parameters.
Result<void> LinuxcncFamily::save_persistent(Impl& im) {
  if (auto l = write_logs(im); !l) return l;  // ngc_room.cpp
  return Language::save_persistent(im);
}

// ---- RS274NGC

Rs274ngc::Rs274ngc() : LinuxcncFamily(kRs274ngcRules, kNgcExpr) {}

void Rs274ngc::start(Impl& im) {
  start_params(im);  // ngc_params.cpp
}

// RS274NGC: the words and the settings' values are read with the
// parameters as they were before the line; then the settings take effect,
// then the comments speak, then the codes run.
Flow<Step> Rs274ngc::execute(Impl& im, CommandSink& out) {
  if (im.blk.has_n) im.modal.seq = static_cast<int>(im.blk.n % 100000000);
  if (im.blk.stmt.kind == gcode::StmtKind::kOword) {
    auto c = comments(im);  // an O-word line's comments speak first
    SKIPNC_TRY(c);
    return execute_oword(im);  // oword.cpp
  }
  return words_line(im, *this, out);
}

// The log files, then the parameter file.
Result<void> Rs274ngc::save_persistent(Impl& im) {
  if (auto l = write_logs(im); !l) return l;
  if (im.mc.persistent_vars.empty()) return {};
  std::vector<double> values;
  for (const int n : state.var_file_numbers) {
    auto v = read_numbered(im, n, SourceLoc{});
    values.push_back(v ? v->num() : 0.0);
  }
  return save_var_file(im.mc.persistent_vars, state.var_file_numbers, values);
}

Flow<void> Rs274ngc::preset(Impl& im, int n, double v) {
  if (write_numbered(im, n, Value::of(v), SourceLoc{})) return {};
  return fail(AlarmId::kUsage, "parameter #" + std::to_string(n) +
                                   " cannot be set before a run (#1-#5060, #5071-#5209, "
                                   "#5221-#5399)");
}

Flow<Value> Rs274ngc::read_param(Impl& im, int n, SourceLoc where) {
  return read_numbered(im, n, where);  // ngc_params.cpp
}

Flow<void> Rs274ngc::write_param(Impl& im, int n, Value v, SourceLoc where) {
  return write_numbered(im, n, v, where);
}

Flow<Value> Rs274ngc::read_named(Impl& im, const std::string& name, SourceLoc where) {
  return read_name(im, name, where);
}

Flow<void> Rs274ngc::write_named(Impl& im, const std::string& name, Value v, SourceLoc where) {
  return write_name(im, name, v, where);
}

// #5061-#5070 (the latch in the block's work coordinates) and the probe log.
void Rs274ngc::store_probe(Impl& im, const AxisVec&, bool triggered) {
  store_probe_params(im, im.skip_result.work, triggered);
  probe_log(im);
}

// ---- grbl

Grbl::Grbl() : LinuxcncFamily(kGrblRules, kNgcExpr) {}

Flow<Step> Grbl::execute(Impl& im, CommandSink& out) {
  if (im.blk.has_n) im.modal.seq = static_cast<int>(im.blk.n % 100000000);
  if (im.blk.stmt.kind != gcode::StmtKind::kNone) return system_line(im, out);  // grbl_system.cpp
  if (system.locked && !im.blk.words.empty()) {
    return fail(AlarmId::kGrblLocked,
                "grbl is in alarm until $H or $X ($22 = 1: homing is required at start)",
                im.loc(im.blk.words.front().column));
  }
  return words_line(im, *this, out);
}

// $6 as the program set it (grbl_system.cpp).
bool Grbl::probe_inverted(const Impl&, int param) const {
  return (static_cast<long long>(setting(param)) & 1) != 0;
}

}  // namespace skipnc::interp
