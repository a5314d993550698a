// Canned cycles, one hole at a time: the moves each cycle makes, written
// from Fanuc's rules (B-63944EN 5.1) by hand.
#include <gtest/gtest.h>

#include "interpreter/cycles.hpp"

namespace {

using skipnc::interp::Cycle;
using skipnc::interp::ReturnLevel;
using namespace skipnc::interp::cycles;

Move rapid(double x, double y, double z) {
  return Move{MoveKind::kRapid, {x, y, z}, 0.0, 0};
}
Move feed(double x, double y, double z) {
  return Move{MoveKind::kFeed, {x, y, z}, 0.0, 0};
}
Move dwell(double x, double y, double z, double s) {
  return Move{MoveKind::kDwell, {x, y, z}, s, 0};
}
Move spindle(double x, double y, double z, int dir) {
  return Move{MoveKind::kSpindle, {x, y, z}, 0.0, dir};
}
Move orient(double x, double y, double z) {
  return Move{MoveKind::kOrient, {x, y, z}, 0.0, 0};
}

// The tool at the initial level Z50 over X0 Y0; the hole at X10 Y20, point R
// at Z2, the bottom at Z-10.
Hole hole(Cycle c, ReturnLevel ret = ReturnLevel::kInitial) {
  Hole h;
  h.kind = c;
  h.ret = ret;
  h.from = {0, 0, 50};
  h.at = {10, 20};
  h.initial = 50;
  h.r = 2;
  h.bottom = -10;
  return h;
}

TEST(Cycles, G81G98RapidToRFeedToZRapidToInitialLevel) {
  const std::vector<Move> want = {rapid(10, 20, 50), rapid(10, 20, 2), feed(10, 20, -10),
                                  rapid(10, 20, 50)};
  EXPECT_EQ(hole_moves(hole(Cycle::kG81)), want);
}

TEST(Cycles, G81G99ReturnsToPointR) {
  const std::vector<Move> want = {rapid(10, 20, 50), rapid(10, 20, 2), feed(10, 20, -10),
                                  rapid(10, 20, 2)};
  EXPECT_EQ(hole_moves(hole(Cycle::kG81, ReturnLevel::kR)), want);
}

TEST(Cycles, G99NextHoleIsPositionedAtPointR) {
  Hole h = hole(Cycle::kG81, ReturnLevel::kR);
  h.from = {10, 20, 2};
  h.at = {30, 20};
  const std::vector<Move> want = {rapid(30, 20, 2), feed(30, 20, -10), rapid(30, 20, 2)};
  EXPECT_EQ(hole_moves(h), want);
}

TEST(Cycles, G82DwellsAtTheBottom) {
  Hole h = hole(Cycle::kG82);
  h.dwell_s = 0.5;
  const std::vector<Move> want = {rapid(10, 20, 50), rapid(10, 20, 2), feed(10, 20, -10),
                                  dwell(10, 20, -10, 0.5), rapid(10, 20, 50)};
  EXPECT_EQ(hole_moves(h), want);
}

TEST(Cycles, G73PecksQAndRetractsDByRapid) {
  // Q4 from R2: pecks to -2, -6, then the rest to -10; d = 0.5 (5114).
  Hole h = hole(Cycle::kG73, ReturnLevel::kR);
  h.q = 4;
  h.peck_clearance = 0.5;
  const std::vector<Move> want = {rapid(10, 20, 50),   rapid(10, 20, 2), feed(10, 20, -2),
                                  rapid(10, 20, -1.5), feed(10, 20, -6), rapid(10, 20, -5.5),
                                  feed(10, 20, -10),   rapid(10, 20, 2)};
  EXPECT_EQ(hole_moves(h), want);
}

TEST(Cycles, G83ReturnsToRAfterEachPeckAndRapidsBackToDShort) {
  // Q5 from R2: -3, -8, -10; d = 1 (5115): back down to -2 and -7 by rapid.
  Hole h = hole(Cycle::kG83);
  h.q = 5;
  h.peck_clearance = 1;
  const std::vector<Move> want = {
      rapid(10, 20, 50), rapid(10, 20, 2), feed(10, 20, -3),  rapid(10, 20, 2),  rapid(10, 20, -2),
      feed(10, 20, -8),  rapid(10, 20, 2), rapid(10, 20, -7), feed(10, 20, -10), rapid(10, 20, 50)};
  EXPECT_EQ(hole_moves(h), want);
}

TEST(Cycles, G83WithQDeeperThanTheHoleIsOneCut) {
  Hole h = hole(Cycle::kG83, ReturnLevel::kR);
  h.q = 20;
  h.peck_clearance = 1;
  const std::vector<Move> want = {rapid(10, 20, 50), rapid(10, 20, 2), feed(10, 20, -10),
                                  rapid(10, 20, 2)};
  EXPECT_EQ(hole_moves(h), want);
}

TEST(Cycles, G84ReversesTheSpindleAtTheBottomAndRestoresItAtR) {
  Hole h = hole(Cycle::kG84);
  h.dwell_s = 0.2;
  const std::vector<Move> want = {
      rapid(10, 20, 50),       rapid(10, 20, 2),         feed(10, 20, -10),
      dwell(10, 20, -10, 0.2), spindle(10, 20, -10, -1), feed(10, 20, 2),
      dwell(10, 20, 2, 0.2),   spindle(10, 20, 2, 1),    rapid(10, 20, 50)};
  EXPECT_EQ(hole_moves(h), want);
}

TEST(Cycles, G74LeftHandTapTurnsTheOtherWay) {
  Hole h = hole(Cycle::kG74, ReturnLevel::kR);
  const std::vector<Move> want = {rapid(10, 20, 50), rapid(10, 20, 2),
                                  feed(10, 20, -10), spindle(10, 20, -10, 1),
                                  feed(10, 20, 2),   spindle(10, 20, 2, -1)};
  EXPECT_EQ(hole_moves(h), want);
}

TEST(Cycles, G76OrientsShiftsQRetractsAndShiftsBack) {
  // Shift 0.3 in -X (5101 RD1 = 1).
  Hole h = hole(Cycle::kG76);
  h.q = 0.3;
  h.shift_dir = shift_direction(1);
  h.dwell_s = 0.1;
  const std::vector<Move> want = {
      rapid(10, 20, 50),       rapid(10, 20, 2),    feed(10, 20, -10),
      dwell(10, 20, -10, 0.1), orient(10, 20, -10), rapid(9.7, 20, -10),
      rapid(9.7, 20, 50),      rapid(10, 20, 50),   spindle(10, 20, 50, 1)};
  EXPECT_EQ(hole_moves(h), want);
}

TEST(Cycles, G85FeedsOutToR) {
  const std::vector<Move> want = {rapid(10, 20, 50), rapid(10, 20, 2), feed(10, 20, -10),
                                  feed(10, 20, 2), rapid(10, 20, 50)};
  EXPECT_EQ(hole_moves(hole(Cycle::kG85)), want);
}

TEST(Cycles, G86StopsTheSpindleAndRapidsOut) {
  const std::vector<Move> want = {rapid(10, 20, 50),       rapid(10, 20, 2), feed(10, 20, -10),
                                  spindle(10, 20, -10, 0), rapid(10, 20, 2), spindle(10, 20, 2, 1)};
  EXPECT_EQ(hole_moves(hole(Cycle::kG86, ReturnLevel::kR)), want);
}

TEST(Cycles, G87BackBoresUpwardFromRBelowThePart) {
  // Initial level 50, R at -20 (below the part), bore up to Z-10; shift +Y 1.
  Hole h = hole(Cycle::kG87, ReturnLevel::kR);  // G99 is not a return level of G87
  h.r = -20;
  h.bottom = -10;
  h.q = 1;
  h.shift_dir = shift_direction(2);
  const std::vector<Move> want = {rapid(10, 20, 50),  orient(10, 20, 50),  rapid(10, 21, 50),
                                  rapid(10, 21, -20), rapid(10, 20, -20),  spindle(10, 20, -20, 1),
                                  feed(10, 20, -10),  orient(10, 20, -10), rapid(10, 21, -10),
                                  rapid(10, 21, 50),  rapid(10, 20, 50),   spindle(10, 20, 50, 1)};
  EXPECT_EQ(hole_moves(h), want);
}

TEST(Cycles, G89DwellsThenFeedsOut) {
  Hole h = hole(Cycle::kG89, ReturnLevel::kR);
  h.dwell_s = 1;
  const std::vector<Move> want = {rapid(10, 20, 50), rapid(10, 20, 2), feed(10, 20, -10),
                                  dwell(10, 20, -10, 1), feed(10, 20, 2)};
  EXPECT_EQ(hole_moves(h), want);
}

TEST(Cycles, G88StopsAtTheBottomAndRetractsWithTheSpindleStopped) {
  Hole h = hole(Cycle::kG88);
  h.dwell_s = 0.5;
  const std::vector<Move> want = {
      rapid(10, 20, 50),       rapid(10, 20, 2),  feed(10, 20, -10),     dwell(10, 20, -10, 0.5),
      spindle(10, 20, -10, 0), rapid(10, 20, 50), spindle(10, 20, 50, 1)};
  EXPECT_EQ(hole_moves(h), want);
}

TEST(CycleLevels, G90RAndZArePositions) {
  Data d;
  d.initial = 50;
  d.r = 2;
  d.have_r = true;
  d.z = -10;
  d.have_z = true;
  const Levels l = resolve_levels(d, false);
  EXPECT_DOUBLE_EQ(l.r, 2);
  EXPECT_DOUBLE_EQ(l.bottom, -10);
}

TEST(CycleLevels, G91RFromTheInitialLevelAndZFromR) {
  // Initial 50: R-48 -> point R at 2; Z-12 -> bottom at -10.
  Data d;
  d.initial = 50;
  d.r = -48;
  d.have_r = true;
  d.z = -12;
  d.have_z = true;
  const Levels l = resolve_levels(d, true);
  EXPECT_DOUBLE_EQ(l.r, 2);
  EXPECT_DOUBLE_EQ(l.bottom, -10);
}

TEST(CycleLevels, ROmittedIsTheInitialLevel) {
  Data d;
  d.initial = 5;
  d.z = -3;
  d.have_z = true;
  EXPECT_DOUBLE_EQ(resolve_levels(d, false).r, 5);
  EXPECT_DOUBLE_EQ(resolve_levels(d, false).bottom, -3);
}

TEST(CycleShift, RD1AndRD2ChooseTheDirection) {
  EXPECT_EQ(shift_direction(0), (std::array<double, 2>{1, 0}));
  EXPECT_EQ(shift_direction(1), (std::array<double, 2>{-1, 0}));
  EXPECT_EQ(shift_direction(2), (std::array<double, 2>{0, 1}));
  EXPECT_EQ(shift_direction(3), (std::array<double, 2>{0, -1}));
}

}  // namespace
