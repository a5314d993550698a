// The evaluator's two paths (expr.cpp): the fast one (numbers, #n of the
// ordinary variables, operators, and SIN COS ABS SQRT inline) and the general
// one (every rule with its alarms). An expression that reads a system
// variable takes the general path whole, so the same expression with and
// without "+#4001*0" is read once each way: the values must be equal to
// the bit.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "config/dialect.hpp"
#include "config/machine_config.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/variables.hpp"
#include "support/interp_mill.hpp"

namespace skipnc::interp {
namespace {

using test::Collect;
using test::Mill;

// The program run to its end or its first alarm. The interpreter keeps
// pointers to its machine, dialect and parameters: the Mill lives as long
// as it does (declared first, destroyed last).
struct ExprRun {
  std::unique_ptr<Mill> mill;
  std::unique_ptr<Interpreter> in;
  std::optional<Error> alarm;
  bool completed() const { return in && !alarm; }
  // #n after the run; NaN when vacant.
  double var(int n) const {
    auto v = in->read_variable(n);
    EXPECT_TRUE(v.has_value());
    return v && !v->vacant ? v->v : std::nan("");
  }
};

ExprRun run_program(const std::string& program) {
  auto mill = std::make_unique<Mill>();
  auto in = mill->start(program);
  ExprRun r{std::move(mill), std::move(in), std::nullopt};
  if (!r.in) return r;
  Collect out;
  for (int guard = 0; guard < 1000; ++guard) {
    auto st = r.in->step(out);
    if (!st) {
      r.alarm = st.error();
      return r;
    }
    if (*st == Step::kEnd) return r;
    EXPECT_NE(*st, Step::kSync);
  }
  ADD_FAILURE() << "the program did not end";
  return r;
}

constexpr double kExprPathsRad = 3.14159265358979323846 / 180.0;

TEST(ExprPaths, FastAndGeneralPathsGiveTheSameValues) {
  const char* kExprs[] = {
      "SIN[#1]*10.+COS[#2*3.]",          "SQRT[ABS[#3]]+ABS[SIN[#4]]",
      "[#1*SIN[#2]-#3/4.]/[2.+ABS[#4]]", "ABS[#5]+SIN[#5]+SQRT[#5]",
      "ATAN[#1]/[#2]+ROUND[#3]",         "COS[#[#6]]*#[#6+1]",
      "SQRT[#1*#1+#2*#2]-FIX[#3*7]",
  };
  std::string program = "#1=8.582\n#2=-48.064\n#3=16.12\n#4=-31.779\n#6=2.6\n";
  int n = 10;
  for (const char* e : kExprs) {
    program += "#" + std::to_string(n) + "=" + e + "\n";
    program += "#" + std::to_string(n + 1) + "=" + e + "+#4001*0\n";
    n += 2;
  }
  const ExprRun o = run_program(program + "M30\n");
  ASSERT_TRUE(o.completed()) << (o.alarm ? o.alarm->detail : "");
  for (int i = 10; i < n; i += 2) {
    EXPECT_FALSE(std::isnan(o.var(i))) << kExprs[(i - 10) / 2];
    EXPECT_EQ(std::bit_cast<std::uint64_t>(o.var(i)), std::bit_cast<std::uint64_t>(o.var(i + 1)))
        << kExprs[(i - 10) / 2] << ": " << o.var(i) << " " << o.var(i + 1);
  }
}

TEST(ExprPaths, InlineFunctionsHaveTheirDegreeValues) {
  const ExprRun o = run_program(
      "#1=30.\n#10=SIN[#1]\n#11=COS[60.]\n#12=ABS[-2.5]\n#13=SQRT[2.]\n"
      "#14=SIN[#2]\n#15=COS[#2]\n#16=ABS[#2]\n#17=SQRT[#2]\nM30\n");
  ASSERT_TRUE(o.completed()) << (o.alarm ? o.alarm->detail : "");
  EXPECT_EQ(o.var(10), std::sin(30.0 * kExprPathsRad));
  EXPECT_EQ(o.var(11), std::cos(60.0 * kExprPathsRad));
  EXPECT_EQ(o.var(12), 2.5);
  EXPECT_EQ(o.var(13), std::sqrt(2.0));
  // #2 vacant counts as 0 in a function's argument.
  EXPECT_EQ(o.var(14), 0.0);
  EXPECT_EQ(o.var(15), 1.0);
  EXPECT_EQ(o.var(16), 0.0);
  EXPECT_EQ(o.var(17), 0.0);
}

TEST(ExprPaths, SqrtOfANegativeValueStillAlarms) {
  const ExprRun fast = run_program("#1=-4.\n#2=SQRT[#1]\nM30\n");
  const ExprRun general = run_program("#1=-4.\n#2=SQRT[#1+#4001*0]\nM30\n");
  ASSERT_FALSE(fast.completed());
  ASSERT_TRUE(fast.alarm && general.alarm);
  EXPECT_EQ(fast.alarm->id, AlarmId::kIllegalArgument);
  EXPECT_EQ(fast.alarm->loc.line, 2u);
  EXPECT_EQ(fast.alarm->loc.column, 4u);
  EXPECT_EQ(fast.alarm->detail, general.alarm->detail);
}

// The variable an assignment writes: "#n" as written, or computed and
// rounded half away from zero.
TEST(ExprPaths, AssignedVariableNumbers) {
  const ExprRun o =
      run_program("#5=1.\n#[1.6]=7.\n#10=2.5\n#[#10]=8.\n#[-#10+5.]=9.\n#100=#5\nM30\n");
  ASSERT_TRUE(o.completed()) << (o.alarm ? o.alarm->detail : "");
  EXPECT_EQ(o.var(2), 7.0);
  EXPECT_EQ(o.var(3), 9.0);  // 2.5 -> #3, and -2.5+5 = 2.5 -> #3 again
  EXPECT_EQ(o.var(100), 1.0);
  const ExprRun far = run_program("#[1000000000]=1.\nM30\n");
  EXPECT_FALSE(far.completed());
}

}  // namespace
}  // namespace skipnc::interp
