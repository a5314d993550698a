// Expression evaluation with Fanuc Custom Macro B rules (docs/macro.md):
// - values are IEEE doubles, as the 15i/30i state ("double-precision real
//   data ... as laid down in the applicable IEEE standard", 15i operator's
//   manual B-63324EN, custom macro, limitations); EQ and NE compare exactly,
//   the manual tells the programmer to allow for errors himself
//   (IF [ABS[#1-#2] LT 0.1]); no tolerance is added here;
// - a vacant variable stays vacant only when referenced alone (#2 = #1);
//   in arithmetic it counts as 0;
// - EQ and NE tell vacant from 0; GT GE LT LE treat vacant as 0;
// - AND OR XOR are bitwise on whole numbers; MOD keeps the dividend's sign;
// - angles are degrees; FIX truncates toward zero, FUP rounds away from it;
//   ROUND rounds half away from zero, and inside an address word to the
//   address's least input increment;
// - ASIN gives 270..90 and ATAN 0..360 degrees, or -90..90 and -180..180
//   with parameter 6004#0 NAT = 1; TAN of an odd multiple of 90 degrees is a
//   division by zero (TAN is SIN/COS).
// RS274NGC (LinuxCNC) differs, as its interpreter computes them
// (measured with rs274, tests/rs274/): EQ and NE allow 0.0001 (its
// TOLERANCE_EQUAL); AND OR XOR are logical (non-zero is true, the result
// 0 or 1); MOD gives a result of the divisor's range, never negative
// (-7 MOD 3 = 2); ** is the power; FIX is floor and FUP ceiling
// (FIX[-1.5] = -2, FUP[-1.5] = -1); ATAN and ASIN are signed (-180..180,
// -90..90); EXISTS[#<name>] is 1 when the named parameter is set.
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "interpreter/impl.hpp"

namespace skipnc::interp {
namespace {

constexpr double kRad = 3.14159265358979323846 / 180.0;

double round_half_away(double x) noexcept {
  return std::round(x);
}

// What the control raises for an operator's or a function's bad argument.
struct Fault {
  AlarmId id;
  const char* why;
};

// The context a function's value depends on.
struct FuncContext {
  bool nat;                // 6004#0 NAT: signed ranges of ATAN / ASIN
  double round_increment;  // ROUND inside an address word (0: whole numbers)
  bool inch;               // ADP: the least input increment is 0.0001 inch
};

// LinuxCNC's TOLERANCE_EQUAL: EQ and NE of RS274NGC.
constexpr double kNgcEqualTolerance = 0.0001;

// The trigonometric functions (degrees) at x (and y, ATAN's second
// argument, when given), in r; or the fault to raise.
std::optional<Fault> trig_value(gcode::Func fn, double x, const double* y, bool nat,
                                double& r) noexcept {
  using gcode::Func;
  auto bad = [](const char* what) { return Fault{AlarmId::kIllegalArgument, what}; };
  switch (fn) {
    case Func::kTan:
      if (std::fmod(std::fabs(x), 180.0) == 90.0) {
        return Fault{AlarmId::kDivisionByZero, "TAN of an odd multiple of 90 degrees"};
      }
      r = std::tan(x * kRad);
      return std::nullopt;
    case Func::kAsin:
      if (x < -1.0 || x > 1.0) return bad("ASIN of a value outside -1..1");
      r = std::asin(x) / kRad;
      if (!nat && r < 0.0) r += 360.0;  // NAT = 0: 270..90
      return std::nullopt;
    case Func::kAcos:
      if (x < -1.0 || x > 1.0) return bad("ACOS of a value outside -1..1");
      r = std::acos(x) / kRad;
      return std::nullopt;
    case Func::kAtan:
      if (y != nullptr) {
        if (x == 0.0 && *y == 0.0) return bad("ATAN[0]/[0]");
        r = std::atan2(x, *y) / kRad;
      } else {
        r = std::atan(x) / kRad;
      }
      if (!nat && r < 0.0) r += 360.0;  // NAT = 0: 0..360
      return std::nullopt;
    default:
      return Fault{AlarmId::kMacroFormat, "function not available in this control"};
  }
}

// SIN, COS, ABS and SQRT of a value not negative at x, in r (the
// functions of nearly every program, inlined into the fast path; the
// others and SQRT's fault are function_value's). False for any other.
[[gnu::always_inline]] inline bool common_function(gcode::Func fn, double x, double& r) noexcept {
  using gcode::Func;
  switch (fn) {
    case Func::kSin:
      r = std::sin(x * kRad);
      return true;
    case Func::kCos:
      r = std::cos(x * kRad);
      return true;
    case Func::kAbs:
      r = std::fabs(x);
      return true;
    case Func::kSqrt:
      if (x < 0.0) return false;
      r = std::sqrt(x);
      return true;
    default:
      return false;
  }
}

// Macro B's POW, BIN (BCD -> binary), BCD (binary -> BCD) and ADP, in r;
// or the fault to raise.
std::optional<Fault> fanuc_function_value(gcode::Func fn, double x, const double* y,
                                          const FuncContext& cx, double& r) noexcept {
  using gcode::Func;
  auto bad = [](const char* what) { return Fault{AlarmId::kIllegalArgument, what}; };
  switch (fn) {
    case Func::kPow:
      if (y == nullptr) return bad("POW needs two arguments");
      if (x < 0.0 && *y != std::trunc(*y))
        return bad("POW of a negative base to a fractional power");
      if (x == 0.0 && *y <= 0.0) return bad("POW of zero to a power that is not positive");
      r = std::pow(x, *y);
      return std::nullopt;
    case Func::kBin: {
      if (x < 0 || x != std::trunc(x) || x > 9.0e15) return bad("BIN of a value that is not BCD");
      auto v = static_cast<std::uint64_t>(x);
      std::uint64_t out = 0, mul = 1;
      while (v != 0) {
        const std::uint64_t d = v & 0xF;
        if (d > 9) return bad("BIN of a value that is not BCD");
        out += d * mul;
        mul *= 10;
        v >>= 4;
      }
      r = static_cast<double>(out);
      return std::nullopt;
    }
    case Func::kBcd: {
      if (x < 0 || x != std::trunc(x) || x > 9.0e15)
        return bad("BCD of a negative or fractional value");
      auto v = static_cast<std::uint64_t>(x);
      std::uint64_t out = 0;
      int shift = 0;
      while (v != 0 && shift < 64) {
        out |= (v % 10) << shift;
        v /= 10;
        shift += 4;
      }
      r = static_cast<double>(out);
      return std::nullopt;
    }
    case Func::kAdp:
      // ADP: the value of an argument written without a decimal point, as
      // if written with one (X10 -> #24 = 0.010 -> ADP[#24] = 10).
      r = x / (cx.inch ? 0.0001 : 0.001);
      return std::nullopt;
    default:
      return Fault{AlarmId::kMacroFormat, "function not available in this control"};
  }
}

// The value of fn at x (and y, the second argument of ATAN and POW, when
// given), in r; or the fault to raise, under the language's rules `R`. One
// set of rules for both evaluators.
template <class R>
std::optional<Fault> function_value(gcode::Func fn, double x, const double* y,
                                    const FuncContext& cx, double& r) noexcept {
  using gcode::Func;
  if (common_function(fn, x, r)) return std::nullopt;
  switch (fn) {
    case Func::kTan:
    case Func::kAsin:
    case Func::kAcos:
    case Func::kAtan:
      return trig_value(fn, x, y, cx.nat, r);
    case Func::kSqrt:  // of a negative value (common_function takes the others)
      return Fault{AlarmId::kIllegalArgument, "SQRT of a negative value"};
    case Func::kSin:
    case Func::kCos:
    case Func::kAbs:
      break;  // common_function's
    case Func::kRound:
      r = cx.round_increment > 0.0 ? round_half_away(x / cx.round_increment) * cx.round_increment
                                   : round_half_away(x);
      return std::nullopt;
    case Func::kFix:
      r = R::fix(x);
      return std::nullopt;
    case Func::kFup:
      r = R::fup(x);
      return std::nullopt;
    case Func::kLn:
      if (x <= 0.0) return Fault{AlarmId::kIllegalArgument, "LN of a value that is not positive"};
      r = std::log(x);
      return std::nullopt;
    case Func::kExp:
      r = std::exp(x);
      return std::nullopt;
    case Func::kPow:
    case Func::kBin:
    case Func::kBcd:
    case Func::kAdp:
      if constexpr (R::kFanucFunctions) return fanuc_function_value(fn, x, y, cx, r);
      break;
    case Func::kExists:  // evaluated by the interpreter (it names a parameter)
    case Func::kNone:
      break;
  }
  return Fault{AlarmId::kMacroFormat, "function not available in this control"};
}

// The RS274NGC operators (see the top of the file), in r; or the fault.
std::optional<Fault> ngc_operator_value(gcode::Op op, double x, double y, double& r) noexcept {
  using gcode::Op;
  switch (op) {
    case Op::kPow:
      if (x < 0.0 && y != std::trunc(y)) {
        return Fault{AlarmId::kIllegalArgument, "a negative value to a fractional power"};
      }
      if (x == 0.0 && y < 0.0) return Fault{AlarmId::kDivisionByZero, "zero to a negative power"};
      r = std::pow(x, y);
      break;
    case Op::kMod:
      if (y == 0.0) return Fault{AlarmId::kDivisionByZero, "MOD by zero"};
      r = std::fmod(x, y);
      if (r < 0.0) r += std::fabs(y);
      break;
    case Op::kAnd:
      r = (x == 0.0 || y == 0.0) ? 0.0 : 1.0;
      break;
    case Op::kOr:
      r = (x != 0.0 || y != 0.0) ? 1.0 : 0.0;
      break;
    case Op::kXor:
      r = ((x == 0.0) != (y == 0.0)) ? 1.0 : 0.0;
      break;
    case Op::kEq:
      r = std::fabs(x - y) < kNgcEqualTolerance ? 1.0 : 0.0;
      break;
    case Op::kNe:
      r = std::fabs(x - y) >= kNgcEqualTolerance ? 1.0 : 0.0;
      break;
    default:
      return Fault{AlarmId::kMacroFormat, "unknown operator"};  // not one of ngc_own
  }
  if (!std::isfinite(r)) return Fault{AlarmId::kOverflow, "result out of range"};
  return std::nullopt;
}

// The value of the binary operator op on a and b, in r; or the fault to
// raise. One set of rules for both evaluators.
// (Inlined: it is the inner step of the fast path.)
[[gnu::always_inline]] inline std::optional<Fault> operator_value(gcode::Op op, Value a, Value b,
                                                                  double& r) noexcept {
  using gcode::Op;
  const double x = a.num(), y = b.num();
  auto whole = [](double d) { return static_cast<std::int64_t>(round_half_away(d)); };
  auto bit_ok = [](double d) { return std::fabs(d) < 9.0e15; };
  switch (op) {
    case Op::kAdd:
    case Op::kSub:
    case Op::kMul:
    case Op::kDiv:
      if (op == Op::kDiv && y == 0.0) return Fault{AlarmId::kDivisionByZero, "division by zero"};
      r = op == Op::kAdd ? x + y : op == Op::kSub ? x - y : op == Op::kMul ? x * y : x / y;
      if (!std::isfinite(r)) return Fault{AlarmId::kOverflow, "result out of range"};
      return std::nullopt;
    case Op::kMod: {
      if (!bit_ok(x) || !bit_ok(y)) return Fault{AlarmId::kOverflow, "MOD operand too large"};
      const std::int64_t k = whole(y);
      if (k == 0) return Fault{AlarmId::kDivisionByZero, "MOD by zero"};
      r = static_cast<double>(whole(x) % k);
      return std::nullopt;
    }
    case Op::kAnd:
    case Op::kOr:
    case Op::kXor: {
      if (!bit_ok(x) || !bit_ok(y)) return Fault{AlarmId::kOverflow, "logical operand too large"};
      const std::int64_t p = whole(x), q = whole(y);
      r = static_cast<double>(op == Op::kAnd ? (p & q) : op == Op::kOr ? (p | q) : (p ^ q));
      return std::nullopt;
    }
    case Op::kEq:
    case Op::kNe: {
      // Vacant is told from 0 here, and only here.
      const bool eq = a.vacant == b.vacant && (a.vacant || a.v == b.v);
      r = eq == (op == Op::kEq) ? 1.0 : 0.0;
      return std::nullopt;
    }
    case Op::kGt:
      r = x > y ? 1.0 : 0.0;
      return std::nullopt;
    case Op::kGe:
      r = x >= y ? 1.0 : 0.0;
      return std::nullopt;
    case Op::kLt:
      r = x < y ? 1.0 : 0.0;
      return std::nullopt;
    case Op::kLe:
      r = x <= y ? 1.0 : 0.0;
      return std::nullopt;
    default:
      break;
  }
  return Fault{AlarmId::kMacroFormat, "unknown operator"};
}

// The RS274NGC operators with rules of their own (the others are Macro B's).
constexpr bool ngc_own(gcode::Op op) noexcept {
  using gcode::Op;
  return op == Op::kPow || op == Op::kMod || op == Op::kAnd || op == Op::kOr || op == Op::kXor ||
         op == Op::kEq || op == Op::kNe;
}

// The expression rules of each language, as types: the evaluators below
// are compiled once for each (kMacroBExpr, kNgcExpr), so that no rule is
// asked per node or per character.
struct MacroBRules {
  static constexpr bool kFanucFunctions = true;  // POW BIN BCD ADP
  static double fix(double x) noexcept { return std::trunc(x); }
  static double fup(double x) noexcept { return x >= 0 ? std::ceil(x) : std::floor(x); }
  // 6004#0 and the increments of address words.
  static FuncContext context(const Interpreter::Impl& im) noexcept {
    return FuncContext{im.functions.nat, im.functions.word_round_increment,
                       im.modal.units == Units::kInch};
  }
  [[gnu::always_inline]] static std::optional<Fault> binary(gcode::Op op, Value a, Value b,
                                                            double& r) noexcept {
    if (op == gcode::Op::kPow) {
      return Fault{AlarmId::kMacroFormat, "'**' is not an operator of this control"};
    }
    return operator_value(op, a, b, r);
  }
  // #x on the fast path: local, common and persistent variables (false:
  // the general path reads it).
  [[gnu::always_inline]] static bool plain_var(const Interpreter::Impl& im, double x,
                                               Value& out) noexcept {
    if (!(std::fabs(x) < 1e9)) return false;
    int num = static_cast<int>(x);
    if (num != x) num = static_cast<int>(round_half_away(x));  // #[1.6] is #2
    return whole_var(im, num, out);
  }
  // The same for "#n", n written in the block: a whole number >= 0.
  [[gnu::always_inline]] static bool plain_var_number(const Interpreter::Impl& im, double x,
                                                      Value& out) noexcept {
    if (!(x < 1e9)) return false;
    return whole_var(im, static_cast<int>(x), out);
  }
  // #num: #0 is vacant, the ordinary variables are read.
  [[gnu::always_inline]] static bool whole_var(const Interpreter::Impl& im, int num,
                                               Value& out) noexcept {
    if (num == 0) {
      out = Value::null();
      return true;
    }
    return im.vars.find(num, out);
  }
  // "#n = v" on the fast path: the variables write_macro_var (sysvars.cpp)
  // stores in the variable store as they are, local, common and persistent
  // (false: write_var writes the others, with their rules and alarms).
  static bool plain_store(Interpreter::Impl& im, int n, Value v) {
    if (!VariableStore::is_local(n) && !VariableStore::is_common(n) &&
        !VariableStore::is_persistent(n)) {
      return false;
    }
    im.vars.set(n, v);
    return true;
  }
  static Flow<Value> exists(Interpreter::Impl& im, const gcode::ExprNode& n) {
    return fail(AlarmId::kMacroFormat, "function not available in this control", im.loc(n.column));
  }
};

template <class R>
Flow<Value> general(Interpreter::Impl& im, gcode::ExprId id);

struct NgcRules {
  static constexpr bool kFanucFunctions = false;  // no POW BIN BCD ADP ('**' is the power)
  static double fix(double x) noexcept { return std::floor(x); }
  static double fup(double x) noexcept { return std::ceil(x); }
  // Signed ATAN / ASIN, ROUND to whole numbers.
  static FuncContext context(const Interpreter::Impl& im) noexcept {
    return FuncContext{true, 0.0, im.modal.units == Units::kInch};
  }
  [[gnu::always_inline]] static std::optional<Fault> binary(gcode::Op op, Value a, Value b,
                                                            double& r) noexcept {
    if (ngc_own(op)) return ngc_operator_value(op, a.num(), b.num(), r);
    return operator_value(op, a, b, r);
  }
  // RS274NGC: #1-#30 of the call level and #31-#5060, 0 until set (no
  // vacant value); the system parameters the general way.
  static bool plain_var(const Interpreter::Impl& im, double x, Value& out) noexcept {
    const double k = std::round(x);
    if (!(k >= 1.0 && k < 5061.0)) return false;
    const int num = static_cast<int>(k);
    out = Value::of(num <= 30 ? im.vars.get(num).num() : im.vars.ngc_param(num));
    return true;
  }
  // The same for "#n", n written in the block: a whole number >= 0, its
  // own rounding.
  static bool plain_var_number(const Interpreter::Impl& im, double x, Value& out) noexcept {
    if (!(x >= 1.0 && x < 5061.0)) return false;
    const int num = static_cast<int>(x);
    out = Value::of(num <= 30 ? im.vars.get(num).num() : im.vars.ngc_param(num));
    return true;
  }
  // EXISTS[#<name>]: 1 when set; EXISTS[#n]: 1 when n is a parameter's
  // number (#0-#5602).
  static Flow<Value> exists(Interpreter::Impl& im, const gcode::ExprNode& n) {
    const gcode::ExprNode& v = im.blk.nodes[static_cast<std::size_t>(n.a)];
    if (v.op == gcode::Op::kVar || v.op == gcode::Op::kVarNum) {
      double x = v.value;
      if (v.op == gcode::Op::kVar) {
        auto num = general<NgcRules>(im, v.a);
        if (!num) return num;
        x = num->num();
      }
      const double k = std::round(x);
      return Value::of(k >= 0 && k < VariableStore::kNgcParams ? 1.0 : 0.0);
    }
    if (v.op != gcode::Op::kNamedVar) {
      return fail(AlarmId::kMacroFormat, "EXISTS takes a named parameter: EXISTS[#<name>]",
                  im.loc(n.column));
    }
    // NgcRules are the LinuxCNC family's (language.cpp), whose names these are.
    auto& family = static_cast<LinuxcncFamily&>(*im.lang);
    const std::string& name = im.blk.names[static_cast<std::size_t>(v.name)];
    return Value::of(family.named_exists(im, name) ? 1.0 : 0.0);
  }
};

// The common case of evaluation, without building Result objects: numbers,
// local/common/persistent variables, operators and functions
// (operator_value and function_value hold their rules for both paths). It gives up
// (false) wherever the rules need more: an alarm, a system or named
// variable. eval() then evaluates the expression the
// general way, which gives the same value or the alarm; nothing here has a
// side effect, so the second pass is safe.
//
// plain() checks the root's index; below it, the walk follows the operands
// the parser wrote (gcode/ast.hpp: an operator's operands are valid nodes
// of the same block), with the block's node array at hand.
template <class R>
bool plain(const Interpreter::Impl& im, gcode::ExprId id, Value& out) noexcept;

template <class R>
bool plain_node(const Interpreter::Impl& im, const gcode::ExprNode* nodes, const gcode::ExprNode& n,
                Value& out) noexcept;

// A leaf of plain()'s trees: a number, or "#n" (n written as a number) of
// a variable plain_var() reads. False for anything else.
template <class R>
[[gnu::always_inline]] inline bool leaf(const Interpreter::Impl& im, const gcode::ExprNode& n,
                                        Value& out) noexcept {
  if (n.op == gcode::Op::kNumber) {
    out = Value::of(n.value);
    return true;
  }
  if (n.op == gcode::Op::kVarNum) return R::plain_var_number(im, n.value, out);
  return false;
}

// An operand of plain(): a leaf, or SIN COS ABS SQRT of a leaf (nearly
// every operand), read here without a call; anything else, and any of
// these plain() gives up on, through plain_node(). The same value as
// plain() gives.
template <class R>
[[gnu::always_inline]] inline bool operand(const Interpreter::Impl& im,
                                           const gcode::ExprNode* nodes, gcode::ExprId id,
                                           Value& out) noexcept {
  const gcode::ExprNode& n = nodes[static_cast<std::size_t>(id)];
  if (leaf<R>(im, n, out)) return true;
  Value x;
  double r = 0.0;
  if (n.op == gcode::Op::kFunc && n.b == gcode::kNoExpr &&
      leaf<R>(im, nodes[static_cast<std::size_t>(n.a)], x) && common_function(n.fn, x.num(), r) &&
      std::isfinite(r)) {
    out = Value::of(r + 0.0);
    return true;
  }
  return plain_node<R>(im, nodes, n, out);
}

template <class R>
bool plain(const Interpreter::Impl& im, gcode::ExprId id, Value& out) noexcept {
  if (id < 0 || static_cast<std::size_t>(id) >= im.blk.nodes.size()) return false;
  const gcode::ExprNode* nodes = im.blk.nodes.data();
  return plain_node<R>(im, nodes, nodes[static_cast<std::size_t>(id)], out);
}

template <class R>
bool plain_node(const Interpreter::Impl& im, const gcode::ExprNode* nodes, const gcode::ExprNode& n,
                Value& out) noexcept {
  using gcode::Op;
  Value a, b;
  switch (n.op) {
    case Op::kNumber:
      out = Value::of(n.value);
      return true;
    case Op::kVarNum:
      return R::plain_var_number(im, n.value, out);
    case Op::kVar:
      if (!operand<R>(im, nodes, n.a, a)) return false;
      return R::plain_var(im, a.num(), out);
    case Op::kNeg:
      if (!operand<R>(im, nodes, n.a, a)) return false;
      out = Value::of(0.0 - a.num());
      return true;
    case Op::kFunc:
      break;
    case Op::kNamedVar:
      return false;
    default: {
      if (!operand<R>(im, nodes, n.a, a) || !operand<R>(im, nodes, n.b, b)) return false;
      double r = 0.0;
      if (R::binary(n.op, a, b, r)) return false;
      out = Value::of(r + 0.0);
      return true;
    }
  }
  if (!operand<R>(im, nodes, n.a, a)) return false;
  double r = 0.0;
  if (n.b == gcode::kNoExpr && common_function(n.fn, a.num(), r)) {
    if (!std::isfinite(r)) return false;
    out = Value::of(r + 0.0);
    return true;
  }
  double y = 0.0;
  if (n.b != gcode::kNoExpr) {
    if (!operand<R>(im, nodes, n.b, b)) return false;
    y = b.num();
  }
  if (function_value<R>(n.fn, a.num(), n.b != gcode::kNoExpr ? &y : nullptr, R::context(im), r)) {
    return false;  // EXISTS too: it names a parameter (general)
  }
  if (!std::isfinite(r)) return false;
  out = Value::of(r + 0.0);
  return true;
}

// A function node, every rule with its alarms.
template <class R>
Flow<Value> general_function(Interpreter::Impl& im, const gcode::ExprNode& n) {
  if (n.fn == gcode::Func::kExists) return R::exists(im, n);
  auto a = general<R>(im, n.a);
  if (!a) return a;
  double y = 0.0;
  if (n.b != gcode::kNoExpr) {
    auto b = general<R>(im, n.b);
    if (!b) return b;
    y = b->num();
  }
  double r = 0.0;
  if (auto f = function_value<R>(n.fn, a->num(), n.b != gcode::kNoExpr ? &y : nullptr,
                                 R::context(im), r)) {
    return fail(f->id, f->why, im.loc(n.column));
  }
  if (!std::isfinite(r)) return fail(AlarmId::kOverflow, "result out of range", im.loc(n.column));
  return Value::of(r + 0.0);  // no -0
}

// Every rule, with its alarms (plain is the fast path of the same rules).
template <class R>
Flow<Value> general(Interpreter::Impl& im, gcode::ExprId id) {
  if (id < 0 || static_cast<std::size_t>(id) >= im.blk.nodes.size()) {
    return fail(AlarmId::kMacroFormat, "missing expression", im.loc(im.cur_col));
  }
  const gcode::ExprNode& n = im.blk.nodes[static_cast<std::size_t>(id)];
  using gcode::Op;
  switch (n.op) {
    case Op::kNumber:
      return Value::of(n.value);
    case Op::kVar:
    case Op::kVarNum: {
      auto num = im.var_number(id);
      SKIPNC_TRY(num);
      return im.read_var(*num, im.loc(n.column));
    }
    case Op::kNamedVar:
      return im.read_named_var(im.blk.names[static_cast<std::size_t>(n.name)], im.loc(n.column));
    case Op::kNeg: {
      auto a = general<R>(im, n.a);
      if (!a) return a;
      return Value::of(0.0 - a->num());  // -#1 with #1 vacant is 0, not -0
    }
    case Op::kFunc:
      return general_function<R>(im, n);
    default: {
      auto a = general<R>(im, n.a);
      if (!a) return a;
      auto b = general<R>(im, n.b);
      if (!b) return b;
      double r = 0.0;
      if (auto f = R::binary(n.op, *a, *b, r)) return fail(f->id, f->why, im.loc(n.column));
      return Value::of(r + 0.0);  // no -0
    }
  }
}

}  // namespace

// A language's evaluator: both paths compiled for its rules.
struct ExprRules {
  bool (*plain)(const Interpreter::Impl&, gcode::ExprId, Value&) noexcept;
  Flow<Value> (*general)(Interpreter::Impl&, gcode::ExprId);
  // An assignment's store without the language's write_param, where its
  // rules allow (nullptr: never).
  bool (*plain_store)(Interpreter::Impl&, int, Value);
};

const ExprRules kMacroBExpr{&plain<MacroBRules>, &general<MacroBRules>, &MacroBRules::plain_store};
// RS274NGC's numbered parameters are written by Rs274ngc::write_param.
const ExprRules kNgcExpr{&plain<NgcRules>, &general<NgcRules>, nullptr};

Flow<int> Interpreter::Impl::var_number(gcode::ExprId lhs) {
  const gcode::ExprNode& n = blk.nodes[static_cast<std::size_t>(lhs)];
  double x = 0.0;
  if (n.op == gcode::Op::kVarNum) {
    x = n.value;  // "#n"
  } else if (n.a >= 0 && static_cast<std::size_t>(n.a) < blk.nodes.size() &&
             blk.nodes[static_cast<std::size_t>(n.a)].op == gcode::Op::kNumber) {
    x = blk.nodes[static_cast<std::size_t>(n.a)].value;  // "#[n]", as eval() would give it
  } else {
    auto v = eval(n.a);
    SKIPNC_TRY(v);
    x = v->num();
  }
  // #[#i] with #i vacant is #0; a fraction is rounded (a whole number is
  // its own rounding: no call).
  if (!(std::fabs(x) < 1e9) || static_cast<int>(x) != x) x = round_half_away(x);
  if (!(std::fabs(x) < 1e9)) {
    return fail(AlarmId::kIllegalVariable, "variable number out of range", loc(n.column));
  }
  return static_cast<int>(x);
}

Flow<void> Interpreter::Impl::assign(gcode::ExprId lhs, Value v) {
  const gcode::ExprNode& n = blk.nodes[static_cast<std::size_t>(lhs)];
  if (!v.vacant && !std::isfinite(v.v)) {
    return fail(AlarmId::kOverflow, "the value to store is not a finite number", loc(n.column));
  }
  if (n.op == gcode::Op::kNamedVar) {
    return write_named_var(blk.names[static_cast<std::size_t>(n.name)], v, loc(n.column));
  }
  int num = 0;
  if (n.op == gcode::Op::kVarNum && n.value < 1e9) {
    num = static_cast<int>(n.value);  // "#n": n is a whole number written in the block
  } else {
    auto k = var_number(lhs);
    SKIPNC_TRY(k);
    num = *k;
  }
  if (lang->expr.plain_store != nullptr && lang->expr.plain_store(*this, num, v)) return {};
  return write_var(num, v, loc(n.column));
}

Flow<Value> Interpreter::Impl::eval(gcode::ExprId id) {
  Value v;
  if (lang->expr.plain(*this, id, v)) return v;
  return lang->expr.general(*this, id);
}

}  // namespace skipnc::interp
