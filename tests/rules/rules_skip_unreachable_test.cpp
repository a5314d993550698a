// Issue 16: a skip whose direction leads away from everything in the scene
// that switches its inputs can only run to its end point; skipnc says so
// before the move (warning skip_unreachable), and says nothing when the
// skip can be met or when nothing in the scene drives its inputs.
#include <gtest/gtest.h>

#include <string>

#include "rules/rule_rig.hpp"

namespace skipnc::rules {
namespace {

int unreachable_count(const Outcome& o) {
  int n = 0;
  for (const auto& w : o.r.warnings) n += w.code == "skip_unreachable" ? 1 : 0;
  return n;
}

// A trigger on while X > 40: a G31 toward -X is away from it, toward +X
// meets it (even with the end point short of the plane: the direction
// counts, a short move is an ordinary miss).
TEST(SkipUnreachable, ATriggerBehindTheMoveIsSaidAndOneAheadIsNot) {
  const auto rig = [] { return Rig().trigger("X0.4", 'X', 40.0, false); };
  const Outcome away = rig().run("G21 G90 G54 G0 X0\nG31 X-30. F1000.\nM30\n");
  ASSERT_TRUE(away.completed()) << away.alarm_code();
  ASSERT_EQ(unreachable_count(away), 1);
  EXPECT_EQ(away.r.warnings[0].line, 2U);
  EXPECT_NE(away.r.warnings[0].text.find("along -X"), std::string::npos) << away.r.warnings[0].text;
  EXPECT_EQ(unreachable_count(rig().run("G21 G90 G54 G0 X0\nG31 X60. F1000.\nM30\n")), 0);
  EXPECT_EQ(unreachable_count(rig().run("G21 G90 G54 G0 X0\nG31 X20. F1000.\nM30\n")), 0)
      << "short of the plane but toward it: a miss, not a wrong direction";
}

// A move along Y never changes X: a trigger plane in X cannot be met.
TEST(SkipUnreachable, AMoveParallelToTheTriggerPlaneIsSaid) {
  const Outcome o = Rig().trigger("X0.4", 'X', 40.0, false).run("G0 X0 Y0\nG31 Y50. F1000.\nM30\n");
  EXPECT_EQ(unreachable_count(o), 1);
}

// A pulse comes in time, not in space; a scene that drives none of the
// skip's inputs (here no scene at all) is not a reason to warn either.
TEST(SkipUnreachable, PulsesAndUndrivenInputsAreNotSaid) {
  EXPECT_EQ(unreachable_count(Rig().pulse("X0.4", 0.1, 0.01).run("G31 X-30. F1000.\nM30\n")), 0);
  EXPECT_EQ(unreachable_count(Rig().run("G31 X-30. F1000.\nM30\n")), 0);
  // A trigger on another input than the one the G31 listens to.
  EXPECT_EQ(
      unreachable_count(Rig().trigger("X0.1", 'X', 40.0, false).run("G31 X-30. F1000.\nM30\n")), 0);
}

// One of two triggers on the input is ahead: the skip can be met.
TEST(SkipUnreachable, OneReachableSourceIsEnough) {
  const Outcome o = Rig()
                        .trigger("X0.4", 'X', 40.0, false)
                        .trigger("X0.4", 'X', -20.0, true)
                        .run("G0 X0\nG31 X-30. F1000.\nM30\n");
  EXPECT_EQ(unreachable_count(o), 0);
}

}  // namespace
}  // namespace skipnc::rules
