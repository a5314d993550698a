// The skip family's own state in a block (skip.cpp): the G31.n step of the
// block being executed, the feed of the last cutting move (CompassNC's G31
// without F), and whether the last skip that ran to its end point without
// a signal has had #5061.. read since (warning skip_missed_read). Part of
// BlockState (block_state.hpp), so a block changes it on its copy like the
// rest; trivially copyable.
#pragma once

namespace skipnc::interp {

struct SkipBlockState {
  double last_cut_feed = 0.0;  // F of the last non-rapid move (program units)
  int step = 0;                // G31.n of the block (0: G31 or no skip), for skip_block
  bool missed_unread = false;  // the skip ran without a signal, #5061.. not read since
};

}  // namespace skipnc::interp
