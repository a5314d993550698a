// The interpreter's small state that an NC block may change, as one value.
// `Interpreter::Impl` derives from it (the members keep their names); a
// block starts from a copy of it and an alarmed block puts the copy back
// with one assignment (ncblock.cpp run_block, docs/architecture.md "The
// block transaction"). No member owns memory: the copy is a plain memcpy
// of a few hundred bytes. The large tables a block may write (work
// offsets, tool offsets, variables, the call stack) are journaled instead
// (journal.hpp), and the axis shifts (AxisShifts, below) and the program
// frame (Impl::program_frame) are copied by the first write of a block to
// them.
#pragma once

#include <bit>
#include <cstdint>
#include <type_traits>

#include "core/axes.hpp"
#include "interpreter/cycles.hpp"
#include "interpreter/frame_codes.hpp"
#include "interpreter/lathe.hpp"
#include "interpreter/modal.hpp"
#include "interpreter/skip_state.hpp"
#include "interpreter/transform.hpp"

namespace skipnc::interp {

// What the interpreter is waiting for at a synchronisation point.
enum class Pending : std::uint8_t { kNone, kRerun, kSkip };

struct BlockState {
  ModalState modal;
  AxisVec pos;                 // commanded machine position, mm
  double length_offset = 0.0;  // active tool length offset (mm), on length_axis
  LatheState lathe_state;      // the T code's wear offset, G90's Z (lathe.hpp)
  SkipBlockState skip_state;   // G31.n, the last cutting feed (skip_state.hpp)

  Pending pending = Pending::kNone;
  bool motion_since_sync = false;
  bool ended = false;
  std::int64_t parts_count = 0;
  // The operator messages' text kept (limits.max_message_bytes), and
  // whether the later ones were dropped (Impl::add_message).
  std::int64_t message_bytes = 0;
  bool messages_dropped = false;

  // mill_codes.cpp: canned cycle data (modal until G80 or group 01) and G16
  // (the program -> work frame is Impl::program_frame, saved on its first write).
  cycles::Data cycle_data;
  FrameCodeState frame_codes;  // G16, the last polar and G68 angles (frame_codes.hpp)
};

// The axis shifts few blocks change (G52, G92, G45-G48, a lathe's T code),
// kept beside BlockState: a block copies them only when it first writes one
// (Impl::shifts, BlockSaved in journal.hpp), not at its start.
struct AxisShifts {
  AxisVec local_shift;      // G52
  AxisVec g92_shift;        // G92
  AxisVec tool_pos_offset;  // G45-G48 accumulated (dialects that have them)
  AxisVec g45_delta;        // this block's G45-G48 change (incremental targets), mm
  // Lathe (lathe.cpp): offsets are kept in program values.
  AxisVec lathe_tool_offset;    // T code: geometry + wear, program values (mm)
  AxisVec tool_offset_pending;  // its last change not yet moved, machine mm (U/W moves)
  // A G45-G48 change or a T offset the next move carries (Impl::axis_targets):
  // any of them not +0.0 to the bit.
  bool moves_pending() const noexcept {
    return !plus_zero(g45_delta) || !plus_zero(tool_offset_pending);
  }
  // Every value +0.0 to the bit (-0.0 is not: a write of +0.0 over it changes it).
  static bool plus_zero(const AxisVec& v) noexcept {
    std::uint64_t bits = 0;
    for (int i = 0; i < kMaxAxes; ++i) bits |= std::bit_cast<std::uint64_t>(v[i]);
    return bits == 0;
  }
};

// The copy a block takes must not allocate: no member may own memory.
static_assert(std::is_trivially_copyable_v<BlockState>);
static_assert(std::is_trivially_copyable_v<cycles::Data>);
static_assert(std::is_trivially_copyable_v<LatheState>);
static_assert(std::is_trivially_copyable_v<FrameCodeState>);
static_assert(std::is_trivially_copyable_v<SkipBlockState>);
static_assert(std::is_trivially_copyable_v<AxisShifts>);

}  // namespace skipnc::interp
