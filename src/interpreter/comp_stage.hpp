// Cutter radius compensation as the interpreter holds it (mill_codes.cpp
// pass_block / flush_comp): the compensator (cutter_comp.hpp) and the
// buffer a block's commands come out of it into (reused, not rebuilt per
// block). Held by the interpreter as one member, `comp`.
#pragma once

#include <cstdint>
#include <vector>

#include "canon/canon.hpp"
#include "core/axes.hpp"
#include "interpreter/cutter_comp.hpp"

namespace skipnc::interp {

struct CompStage {
  crc::Compensator state;
  std::vector<canon::Stamped> out;  // the commands through it of one block or flush

  bool idle() const noexcept { return state.idle(); }
  AxisVec vector() const noexcept { return state.vector(); }
  // What the compensator holds goes to `sink`, the held move ending
  // perpendicular. Returns the line of that move (0: nothing held).
  std::uint32_t flush(canon::CommandSink& sink) {
    out.clear();
    const std::uint32_t held = state.flush(out);
    for (const canon::Stamped& c : out) sink.emit(c);
    return held;
  }
};

}  // namespace skipnc::interp
