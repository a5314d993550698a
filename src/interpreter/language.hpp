// The program languages (docs/languages.md): Fanuc Custom Macro B, LinuxCNC's
// RS274NGC and grbl. One language object is chosen per run from the
// dialect's `language` (make_language); the interpreter asks it wherever
// the languages differ and tests no language itself.
//
// What a language decides comes in three kinds, by how often it is asked:
// - `Rules`: answers fixed for the language (the syntax, the units of the
//   stored offsets, which words a block may hold, ...), plain data read on
//   the hot path without a call;
// - the virtual functions: the work that differs (what a block is and how it
//   runs, the parameters, reference return, G10, the probe's result, the
//   persistent parameters), called at most once per block or per parameter
//   read of the general path;
// - `ExprRules` (expr.cpp): the expression evaluator compiled for the
//   language's operators and functions, chosen once per expression.
// The language's own state lives in its object: RS274NGC's #<_value>, the
// parameter file's numbers, M70-M73 and the log files (NgcState); grbl's `$`
// settings and probe report (GrblState).
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/dialect.hpp"
#include "core/axes.hpp"
#include "gcode/parser.hpp"
#include "gcode/source.hpp"
#include "interpreter/flow.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/ngc_room.hpp"
#include "interpreter/variables.hpp"

namespace skipnc::interp {

struct Words;
struct OLoop;                        // program_store.hpp
struct ExprRules;                    // expr.cpp
extern const ExprRules kMacroBExpr;  // Macro B's operators and functions
extern const ExprRules kNgcExpr;     // RS274NGC's (grbl's too: it has only numbers)

class Language {
 public:
  using Impl = Interpreter::Impl;

  struct Rules {
    config::Language kind = config::Language::kMacroB;
    gcode::Syntax syntax = gcode::Syntax::kMacroB;
    // Lines: ';' ends a block (Macro B) or begins a comment; a line of
    // comments alone runs as a block ((debug,..) reads parameters) or only
    // shows its (MSG,..).
    bool semicolon_ends_block = true;
    bool comment_line_runs = false;
    // Words: a computed length is rounded to the address's least input
    // increment (X#1); the letters a block may hold besides the axes, G, M
    // and N, and what the alarm for another calls the one that refuses it;
    // E only with M67/M68 (RS274NGC).
    bool round_computed_words = true;
    std::string_view addresses = "FSTHDPQRKLIJE";
    const char* address_owner = "machine";
    bool e_word_for_m67_only = false;
    // Codes: G04 P and a canned cycle's P in seconds (else milliseconds
    // without a decimal point); G53 only with G0 or G1, G53 G1 a feed;
    // G02/G03 P (turns); LinuxCNC's arc radius check and canned-cycle
    // levels; G43 without H takes the tool in the spindle; G10 without P is
    // the active system; M70-M73 save and restore the modal state.
    bool dwell_p_seconds = false;
    bool g53_g0_g1_only = false;
    bool arc_turns_p = false;
    bool arc_radius_linuxcnc = false;
    bool cycle_levels_linuxcnc = false;
    bool g43_tool_in_spindle = false;
    bool g10_p_optional = false;
    bool state_codes = false;
    // Stored values: work and tool offsets kept in mm (else in the input
    // unit in force, offset_units.hpp); #5161-#5390 hold G28, G30, G92 and
    // the work offsets (selecting a system loads it, G92 stores there), in
    // the machine's unit (LinuxCNC) or in mm (grbl).
    bool offsets_in_mm = false;
    bool offsets_in_params = false;
    bool params_in_machine_unit = true;
  };

  Language(const Rules& r, const ExprRules& e) noexcept : rules(r), expr(e) {}
  Language(const Language&) = delete;
  Language& operator=(const Language&) = delete;
  virtual ~Language() = default;

  const Rules rules;
  const ExprRules& expr;

  // The start of a run (offsets and tools set): the language's parameters.
  virtual void start(Impl& im) = 0;
  // One block read: a statement, an O-word, a `$` line or words.
  virtual Flow<Step> execute(Impl& im, CommandSink& out) = 0;
  // What follows is Macro B's unless the language says otherwise
  // (language.cpp): the interpreter's variables and the Fanuc family's codes.
  // The machine's persistent parameters: read at the start (the file is
  // locked), written at the end (with the language's log files); a value
  // given before the run (-D).
  virtual Flow<void> load_persistent(Impl& im);
  virtual Result<void> save_persistent(Impl& im);
  virtual Flow<void> preset(Impl& im, int n, double v);
  // Numbered and named parameters.
  virtual Flow<Value> read_param(Impl& im, int n, SourceLoc where);
  virtual Flow<void> write_param(Impl& im, int n, Value v, SourceLoc where);
  virtual Flow<Value> read_named(Impl& im, const std::string& name, SourceLoc where);
  virtual Flow<void> write_named(Impl& im, const std::string& name, Value v, SourceLoc where);
  // G28 / G30 and G10.
  virtual Flow<void> reference_return(Impl& im, const Words& words, int g, CommandSink& out);
  virtual Flow<void> data_setting(Impl& im, const Words& words, SourceLoc where);
  // After a G38 probe (`latch`: where it stopped, machine mm): where its
  // result is kept; whether the probe input is inverted (a parameter bit, or
  // grbl's $6).
  virtual void store_probe(Impl& im, const AxisVec& latch, bool triggered);
  virtual bool probe_inverted(const Impl& im, int param) const;
  // The LinuxCNC family's own codes and stored values (ngc_codes.cpp,
  // ngc_params.cpp, ngc_room.cpp); the interpreter asks for them only where
  // its rules say the language has them (Rules::offsets_in_params,
  // Rules::state_codes, Action::kNgc of the code table), and Macro B has none.
  // A block selects work system `set` (1-9); G92 has set an offset.
  virtual void select_work(Impl& im, int set);
  virtual void store_g92(Impl& im);
  // A code of Action::kNgc (G28.1 G30.1 G43.1 G92.1-G92.3).
  virtual Flow<void> own_action(Impl& im, const Words& words, GCode code);
  // M70-M73 of a block (`before`: the modes before its own), and what they
  // saved as a block begins and when it is alarmed.
  virtual Flow<void> state_codes(Impl& im, const Words& words, const ModalState& before,
                                 SourceLoc where);
  virtual void begin_block();
  virtual void roll_back_block();
};

// Fanuc Custom Macro B (and the dialects of its family).
class MacroB final : public Language {
 public:
  MacroB();
  void start(Impl& im) override;
  Flow<Step> execute(Impl& im, CommandSink& out) override;
};

// The state RS274NGC keeps, and grbl with it (ngc_params.cpp, ngc_room.cpp,
// oword.cpp).
struct NgcState {
  Value value;                        // #<_value>: the last return / endsub value
  bool value_returned = false;        // #<_value_returned>
  std::vector<int> var_file_numbers;  // the parameters the var file keeps (ngc_params.cpp)
  NgcRoom room;                       // M70-M73, log files (ngc_room.hpp)
};

// LinuxCNC's axis slots X Y Z A B C U V W (the order of #5061.., #5161..,
// #5221..): the slot of `letter`, -1 if it has none.
int ngc_axis_index(char letter) noexcept;

// What LinuxCNC and grbl share: their codes (G28/G30 through #5161..,
// G10 L2/L20), the stored values in #5161-#5390, the comments that speak and
// their log files, M70-M73's saved states.
class LinuxcncFamily : public Language {
 public:
  NgcState state;
  Result<void> save_persistent(Impl& im) override;
  // ngc_codes.cpp
  Flow<void> reference_return(Impl& im, const Words& words, int g, CommandSink& out) override;
  Flow<void> data_setting(Impl& im, const Words& words, SourceLoc where) override;
  Flow<void> own_action(Impl& im, const Words& words, GCode code) override;
  void store_g92(Impl& im) override;
  // ngc_room.cpp
  Flow<void> state_codes(Impl& im, const Words& words, const ModalState& before,
                         SourceLoc where) override;
  void begin_block() override;
  void roll_back_block() override;
  // A sub returns (endsub / return): the state its M73 saved comes back.
  void state_on_return(Impl& im);
  // ngc_params.cpp: the numbered parameters #0-#5601 and the named ones.
  void select_work(Impl& im, int set) override;  // #5221.. into the work offsets
  Flow<Value> read_numbered(Impl& im, int n, SourceLoc where);
  Flow<void> write_numbered(Impl& im, int n, Value v, SourceLoc where);
  Flow<Value> read_name(Impl& im, const std::string& name, SourceLoc where);
  Flow<void> write_name(Impl& im, const std::string& name, Value v, SourceLoc where);
  bool named_exists(Impl& im, const std::string& name);  // EXISTS[#<name>]
  // The comments of the block that speak: (msg,..), (debug,..), (log,..) ...
  Flow<void> comments(Impl& im);

 protected:
  LinuxcncFamily(const Rules& r, const ExprRules& e) noexcept : Language(r, e) {}
  // #5221.. from the machine file's work offsets (ngc_params.cpp).
  void start_params(Impl& im);
  // #5061-#5070 after a G38, and the line of the probe log.
  void store_probe_params(Impl& im, const AxisVec& latch_work, bool triggered);
  void probe_log(Impl& im);
  Result<void> write_logs(Impl& im);  // the files of (LOGOPEN,..) and (PROBEOPEN ..)

 private:
  std::optional<Flow<Value>> predefined(Impl& im, const std::string& name, SourceLoc where);
  std::optional<Flow<Value>> ini_hal(Impl& im, const std::string& n, SourceLoc where);
  Flow<std::string> message_text(Impl& im, std::string_view text, SourceLoc where);
  Flow<void> log_comment(Impl& im, std::string_view text, SourceLoc where);
  void restore_state(Impl& im, const NgcSavedState& s);
  std::vector<NgcSavedState> saved_before_;  // M70-M73's states as the block began
  bool had_saved_ = false;
};

// LinuxCNC's RS274NGC: its numbered and named parameters, O-words, the
// parameter file.
class Rs274ngc final : public LinuxcncFamily {
 public:
  Rs274ngc();
  void start(Impl& im) override;
  Flow<Step> execute(Impl& im, CommandSink& out) override;
  Flow<void> load_persistent(Impl& im) override;  // ngc_params.cpp: the parameter file
  Result<void> save_persistent(Impl& im) override;
  Flow<void> preset(Impl& im, int n, double v) override;
  Flow<Value> read_param(Impl& im, int n, SourceLoc where) override;
  Flow<void> write_param(Impl& im, int n, Value v, SourceLoc where) override;
  Flow<Value> read_named(Impl& im, const std::string& name, SourceLoc where) override;
  Flow<void> write_named(Impl& im, const std::string& name, Value v, SourceLoc where) override;
  void store_probe(Impl& im, const AxisVec& latch, bool triggered) override;

 private:
  // oword.cpp: the O-word flow (sub, call, return, if, while, do, repeat,
  // break, continue).
  Flow<Step> execute_oword(Impl& im);
  Flow<void> oword_call(Impl& im, const std::string& label, SourceLoc where);
  Flow<void> skip_to_oword(Impl& im, const std::string& label, std::uint32_t kinds,
                           SourceLoc where);
  Flow<Step> oword_return(Impl& im, const gcode::Stmt& s, SourceLoc where);
  Flow<bool> oword_condition(Impl& im);
  Flow<Step> oword_branch(Impl& im, gcode::OKind kind, const std::string& label, SourceLoc where);
  Flow<Step> oword_loop(Impl& im, gcode::OKind kind, const std::string& label, SourceLoc where);
  Flow<Step> oword_while(Impl& im, const std::string& label, SourceLoc where);
  Flow<Step> oword_break(Impl& im, gcode::OKind kind, const std::string& label, SourceLoc where);
  Flow<Step> oword_seek(Impl& im, gcode::SourcePos p);
  Flow<Step> oword_leave(Impl& im, const OLoop& l, SourceLoc where);
};

// grbl's own state (grbl_system.cpp).
struct GrblState {
  std::map<int, double> settings;      // $n: the dialect's table, the axes, what `$n=` set
  std::string build_info;              // `$I=text`
  std::array<std::string, 2> startup;  // `$N0=` `$N1=` (kept, not run)
  bool locked = false;                 // $22 = 1: in alarm until `$H` or `$X`
  AxisVec prb;                         // the last probe's [PRB:], machine mm
  bool prb_ok = false;
};

// grbl: LinuxCNC's codes without parameters, expressions or subprograms, and
// its `$` system lines (grbl_system.cpp); the interpreter's own variables are
// Macro B's.
class Grbl final : public LinuxcncFamily {
 public:
  Grbl();
  GrblState system;
  void start(Impl& im) override;
  Flow<Step> execute(Impl& im, CommandSink& out) override;
  bool probe_inverted(const Impl& im, int param) const override;
  void store_probe(Impl& im, const AxisVec& latch, bool triggered) override;

 private:
  double setting(int n) const noexcept;
  std::string coords(const Impl& im, const AxisVec& mm) const;
  Flow<Step> system_line(Impl& im, CommandSink& out);
  Flow<Step> report(Impl& im, const std::string& text);
  Flow<Step> store_setting(Impl& im, const std::string& text, CommandSink& out);
  Flow<Step> home(Impl& im, CommandSink& out);
  Flow<Step> jog(Impl& im, CommandSink& out);
  void list_settings(Impl& im);
  void list_offsets(Impl& im);
  void modal_line(Impl& im);
};

std::unique_ptr<Language> make_language(config::Language kind);

}  // namespace skipnc::interp
