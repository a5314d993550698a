// SegmentQueue: a full ring refuses a push and changes nothing.
#include <gtest/gtest.h>

#include "planner/planner.hpp"
#include "support/motion.hpp"

namespace skipnc::planner {
namespace {

using test::mill_limits;
using test::xyz;

Move line(AxisVec to, double feed, std::uint32_t tag) {
  Move m;
  m.kind = Move::Kind::kLine;
  m.target = to;
  m.feed_mm_s = feed;
  m.tag = tag;
  return m;
}

// Fills a ring of 4 with collinear lines (each one's exit speed depends on
// what follows it, so a refused move that slipped into the lookahead would
// show in the profiles).
void fill(SegmentQueue& q) {
  for (std::uint32_t k = 1; k <= 4; ++k) {
    ASSERT_TRUE(q.push(line(xyz(10.0 * k, 0, 0), 200.0, k)));
  }
}

TEST(SegmentQueue, PushOnAFullRingIsRefusedAndChangesNothing) {
  SegmentQueue q(mill_limits(), 4);
  SegmentQueue reference(mill_limits(), 4);
  fill(q);
  fill(reference);
  ASSERT_TRUE(q.full());

  EXPECT_FALSE(q.push(line(xyz(50, 0, 0), 200.0, 5)));
  Move dwell;
  dwell.kind = Move::Kind::kDwell;
  dwell.dwell_s = 1.0;
  EXPECT_FALSE(q.push(dwell));

  EXPECT_EQ(q.size(), 4U);
  EXPECT_EQ(q.tail_position(), xyz(40, 0, 0));
  // The queued segments are those of a ring that never saw the refused moves.
  while (!reference.empty()) {
    const Segment* a = q.front();
    const Segment* b = reference.front();
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->tag, b->tag);
    EXPECT_EQ(a->start, b->start);
    EXPECT_EQ(a->end, b->end);
    EXPECT_EQ(a->v_entry, b->v_entry);
    EXPECT_EQ(a->v_exit, b->v_exit);
    EXPECT_EQ(a->duration, b->duration);
    q.pop_front();
    reference.pop_front();
  }
  EXPECT_TRUE(q.empty());
}

TEST(SegmentQueue, APoppedSegmentMakesRoomAgain) {
  SegmentQueue q(mill_limits(), 4);
  fill(q);
  ASSERT_FALSE(q.push(line(xyz(50, 0, 0), 200.0, 5)));
  q.pop_front();
  EXPECT_TRUE(q.push(line(xyz(50, 0, 0), 200.0, 5)));
  EXPECT_TRUE(q.full());
  EXPECT_EQ(q.tail_position(), xyz(50, 0, 0));
}

}  // namespace
}  // namespace skipnc::planner
