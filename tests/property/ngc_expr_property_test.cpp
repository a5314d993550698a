// RS274NGC expressions (the linuxcnc dialect) against a model of LinuxCNC's
// rules written here from its documentation and rs274's answers
// (docs/languages.md): random expression trees over numbers and #1-#40,
// evaluated by the interpreter (its fast path where it applies, the general
// path where it does not: a system parameter in the tree sends it there) and
// by the model, give the same value or the same refusal.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "property/program_gen.hpp"

namespace skipnc::property {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

struct Expr {
  std::string text;
  std::optional<double> value;  // nullopt: LinuxCNC refuses it (divide by zero, domain)
};

// The parameters the programs set: #1-#40 = k - 20 (so 0 and negatives appear),
// and #5220 (the coordinate system, 1 in G54) as a system parameter.
double param(int k) {
  return k == 5220 ? 1.0 : static_cast<double>(k - 20);
}

Expr leaf() {
  const int kind = *rc::gen::inRange(0, 4);
  if (kind == 0) {
    const int k = *rc::gen::inRange(1, 41);
    return {"#" + std::to_string(k), param(k)};
  }
  if (kind == 1) return {"#5220", param(5220)};
  const int v = *rc::gen::inRange(-40, 41);
  const int frac = *rc::gen::inRange(0, 4);
  const double x = v / static_cast<double>(frac == 0 ? 1 : frac * 2);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", std::fabs(x));
  const double written = std::stod(buf) * (x < 0 ? -1.0 : 1.0);  // the value as written
  // A negative number is a unary minus on a number.
  return {x < 0 ? std::string("[-") + buf + "]" : std::string(buf), written};
}

Expr expr(int depth) {
  if (depth == 0 || *rc::gen::inRange(0, 3) == 0) return leaf();
  const int kind = *rc::gen::inRange(0, 3);
  if (kind == 0) {
    static const char* kFuncs[] = {"SIN", "COS", "ABS", "FIX", "FUP", "ROUND", "SQRT"};
    const int f = *rc::gen::inRange(0, 7);
    Expr a = expr(depth - 1);
    Expr out{std::string(kFuncs[f]) + "[" + a.text + "]", std::nullopt};
    if (!a.value) return out;
    const double x = *a.value;
    switch (f) {
      case 0:
        out.value = std::sin(x * kDeg);
        break;
      case 1:
        out.value = std::cos(x * kDeg);
        break;
      case 2:
        out.value = std::fabs(x);
        break;
      case 3:
        out.value = std::floor(x);
        break;
      case 4:
        out.value = std::ceil(x);
        break;
      case 5:
        out.value = x < 0 ? -std::floor(-x + 0.5) : std::floor(x + 0.5);
        break;
      default:
        if (x >= 0) out.value = std::sqrt(x);
        break;
    }
    return out;
  }
  static const char* kOps[] = {"+",  "-",  "*",  "/",   "MOD", "**", "EQ",
                               "NE", "GT", "LT", "AND", "OR",  "XOR"};
  const int o = *rc::gen::inRange(0, 13);
  Expr a = expr(depth - 1);
  Expr b = expr(depth - 1);
  // Brackets around every operation: the model need not know precedence
  // here (GcodeParserNgc.PrecedenceIsLinuxCncs checks it).
  Expr out{"[" + a.text + " " + kOps[o] + " " + b.text + "]", std::nullopt};
  if (!a.value || !b.value) return out;
  const double x = *a.value, y = *b.value;
  double r = 0.0;
  switch (o) {
    case 0:
      r = x + y;
      break;
    case 1:
      r = x - y;
      break;
    case 2:
      r = x * y;
      break;
    case 3:
      if (y == 0.0) return out;
      r = x / y;
      break;
    case 4:
      if (y == 0.0) return out;
      r = std::fmod(x, y);
      if (r < 0.0) r += std::fabs(y);
      break;
    case 5:
      if ((x < 0.0 && y != std::trunc(y)) || (x == 0.0 && y < 0.0)) return out;
      r = std::pow(x, y);
      break;
    case 6:
      r = std::fabs(x - y) < 0.0001 ? 1 : 0;
      break;
    case 7:
      r = std::fabs(x - y) >= 0.0001 ? 1 : 0;
      break;
    case 8:
      r = x > y ? 1 : 0;
      break;
    case 9:
      r = x < y ? 1 : 0;
      break;
    case 10:
      r = (x != 0.0 && y != 0.0) ? 1 : 0;
      break;
    case 11:
      r = (x != 0.0 || y != 0.0) ? 1 : 0;
      break;
    default:
      r = ((x != 0.0) != (y != 0.0)) ? 1 : 0;
      break;
  }
  if (!std::isfinite(r)) return out;  // overflow: refused
  out.value = r;
  return out;
}

RC_GTEST_PROP(NgcExpr, TheInterpreterGivesLinuxCncsValue, ()) {
  const Machine m("linuxcnc");
  const Expr e = expr(*rc::gen::inRange(1, 5));
  std::string program = "G21 G90 G54\n";
  for (int k = 1; k <= 40; ++k) {
    program += "#" + std::to_string(k) + " = " + std::to_string(k - 20) + "\n";
  }
  program += "#100 = " + e.text + "\nM2\n";
  RC_TAG(e.value.has_value() ? "value" : "refused");
  RC_LOG() << e.text << " -> " << (e.value ? std::to_string(*e.value) : "refused") << "\n";
  auto in = interp::Interpreter::create(m.setup(program), AxisVec{});
  RC_ASSERT(in.has_value());
  Collect sink;
  bool alarmed = false;
  for (int guard = 0; guard < 100; ++guard) {
    auto st = (*in)->step(sink);
    if (!st) {
      alarmed = true;
      break;
    }
    if (*st == interp::Step::kEnd) break;
    if (*st == interp::Step::kSync) {
      interp::SyncState s;
      RC_ASSERT((*in)->sync(s).has_value());
    }
  }
  if (!e.value) {
    RC_ASSERT(alarmed);
    return;
  }
  RC_ASSERT(!alarmed);
  auto v = (*in)->read_variable(100);
  RC_ASSERT(v.has_value());
  const double want = *e.value;
  RC_ASSERT(std::fabs(v->num() - want) <= 1e-9 * std::max(1.0, std::fabs(want)));
}

}  // namespace
}  // namespace skipnc::property
