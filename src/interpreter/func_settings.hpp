// What Macro B's functions depend on beyond their arguments (expr.cpp
// MacroBRules::context): 6004#0 NAT, set once at the start of the run
// (interpreter.cpp), and the increment ROUND rounds to inside an address
// word, set while the word is evaluated (ncblock.cpp collect_words). Held
// by the interpreter as one member.
#pragma once

namespace skipnc::interp {

struct FunctionSettings {
  bool nat = false;  // 6004#0 NAT: signed ranges of ATAN / ASIN
  // ROUND inside an address word rounds to this increment (0: to a whole
  // number, as in a macro statement).
  double word_round_increment = 0.0;
};

}  // namespace skipnc::interp
