// Collects what a plot needs while a run goes on: a decimated copy of the
// per-servo-period trace, the executed blocks (one run of periods per
// source line) and the kind of each motion command.
//
// Decimation keeps a sample when dropping it would move any drawn channel
// (commanded and actual position, following error, path speed, torque) by
// more than its tolerance on a straight line between the kept neighbours
// (a per-channel "sleeve": O(channels) per period, no look-back). Samples are
// always kept at block boundaries, on both sides of every signal edge and for
// a few periods around it, so latch and stop points and signal edges are
// never lost. When the kept samples pass the budget the tolerances double
// and the kept samples are thinned again; edges stay.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <numeric>
#include <string>
#include <vector>

#include "config/machine_config.hpp"
#include "core/axes.hpp"
#include "sim/simulator.hpp"

namespace skipnc::plot {

enum class MoveKind : std::uint8_t { kNone, kRapid, kFeed, kArc, kSkip, kDwell };
const char* move_kind_name(MoveKind k) noexcept;

struct Sample {
  double t = 0.0;  // simulated seconds
  std::uint32_t line = 0;
  std::uint32_t source = 0;   // call context of the block (record::CallContext)
  std::uint32_t signals = 0;  // bit i: signal i (signal_names()[i]) on
  double feed_mm_min = 0.0;   // commanded path speed
  AxisVec cmd;                // machine coordinates, mm
  AxisVec act;
  AxisVec torque;        // % of rated
  std::uint8_t pin = 0;  // kPinSoft / kPinHard: never thinned (hard) or only at coarse levels
};

inline constexpr std::uint8_t kPinSoft = 1;  // block boundary
inline constexpr std::uint8_t kPinHard = 2;  // signal edge and the periods around it

// One executed block: consecutive servo periods with the same source line
// (in the same call context).
struct BlockRun {
  std::uint32_t line = 0;
  std::uint32_t source = 0;
  MoveKind kind = MoveKind::kNone;
  double t0 = 0.0;  // first period of the block
  double t1 = 0.0;  // last period of the block
  AxisVec start_act;
  AxisVec end_act;
  AxisVec end_cmd;  // where the command rested at the end of the block
};

// A G31-family command as the interpreter emitted it (machine coordinates).
struct SkipMove {
  std::uint32_t line = 0;
  std::uint32_t source = 0;
  AxisVec start;  // where the command stood when the block began
  AxisVec target;
  double feed_mm_min = 0.0;
};

// A tool change (T.. M06) as the plot places it: at the period the
// simulation put the tool in the spindle (Recorder::place_tool_change).
struct ToolChange {
  double t = 0.0;
  int tool = 0;
};

struct Decimation {
  double pos_tol_mm = 0.0005;  // commanded/actual position
  double fe_tol_mm = 0.0002;   // following error
  double feed_tol_mm_min = 0.5;
  double torque_tol_pct = 0.25;
  std::size_t max_samples = 40000;  // budget; tolerances double past it
  // Hard bounds, whatever the program's length: past max_kept samples the
  // pins (block boundaries, edges) are thinned too; past max_blocks block
  // runs, neighbouring runs are merged (skip blocks last).
  std::size_t max_kept = 80000;
  std::size_t max_blocks = 20000;
  // Past max_skip_moves skip commands the later ones are not kept (their
  // skip marks are drawn from where their blocks began); past
  // max_tool_changes tool changes every other one is dropped, the first and
  // the last kept.
  std::size_t max_skip_moves = 20000;
  std::size_t max_tool_changes = 20000;
  int keep_around_edge = 6;  // periods kept whole before and after a signal edge
};

class Recorder final : public sim::TraceSink, public canon::CommandSink {
 public:
  explicit Recorder(const config::MachineConfig& m, Decimation d = {});

  void row(const sim::TraceRow& r) override;
  // Periods in which nothing changes (a dwell, a feed hold) may be passed
  // over: the samples on either side draw them (a straight line in time).
  std::int64_t stride() const noexcept override { return std::int64_t{1} << 40; }
  void emit(const canon::Stamped& c) override;
  // Keeps the last period seen (call once the run has ended).
  void finish();

  const std::vector<Sample>& samples() const noexcept { return kept_; }
  const std::vector<BlockRun>& blocks() const noexcept { return blocks_; }
  const std::vector<SkipMove>& skip_moves() const noexcept { return skip_moves_; }
  const std::vector<std::string>& signal_names() const noexcept { return signal_names_; }
  const std::vector<ToolChange>& tool_changes() const noexcept { return tool_changes_; }
  std::uint64_t periods_seen() const noexcept { return rows_; }
  // Skip commands not kept (past max_skip_moves), tool changes dropped
  // (past max_tool_changes).
  std::uint64_t skip_moves_dropped() const noexcept { return skip_moves_dropped_; }
  std::uint64_t tool_changes_dropped() const noexcept { return tool_changes_dropped_; }
  // Tolerance multiplier reached (1, 2, 4, ...).
  double tolerance_scale() const noexcept { return scale_; }
  int axis_count() const noexcept { return n_; }

 private:
  struct Pending {
    std::uint32_t line;
    std::uint32_t source;
    MoveKind kind;
  };
  void keep(const Sample& s);
  // One trace row as a sample (time, block, positions, torque, signals).
  Sample sample_of(const sim::TraceRow& r);
  // An edge of a signal: the periods before it, it and the next few kept.
  void keep_edge(Sample& cur, bool prev_kept);
  // The first period of a block and the last of the one before, kept.
  void keep_block_start(Sample& cur, bool prev_kept);
  void reset_sleeve(const Sample& anchor);
  bool sleeve_accepts(const Sample& s);
  void thin();
  void thin_pins();
  void merge_blocks();
  void add_tool_change(double t, int tool);
  void place_tool_change(const sim::TraceRow& r, const Sample& cur);
  MoveKind take_kind(std::uint32_t line, std::uint32_t source);

  int n_ = 0;
  Decimation d_;
  double scale_ = 1.0;
  std::uint64_t rows_ = 0;
  std::vector<Sample> kept_;
  std::vector<BlockRun> blocks_;
  std::vector<SkipMove> skip_moves_;
  std::vector<std::string> signal_names_;
  std::deque<Pending> pending_;
  std::vector<ToolChange> tool_changes_;
  std::uint64_t skip_moves_dropped_ = 0;
  std::uint64_t tool_changes_dropped_ = 0;
  int selected_tool_ = -1;        // the last T word
  int pending_tool_ = -1;         // M06 seen, not yet placed in time (rows without a plant)
  int plant_tool_ = -1;           // the plant's spindle tool at the last row (-1: none yet)
  AxisVec tail_;                  // target of the last motion command
  bool tail_from_trace_ = false;  // after a skip: the next move starts where the machine stopped

  bool have_prev_ = false;
  Sample prev_;
  Sample anchor_;
  std::vector<double> lo_, hi_;  // admissible slopes per channel from the anchor
  std::vector<double> lo_next_, hi_next_;
  std::deque<Sample> recent_;  // periods after the last kept one (for edges)
  int keep_after_ = 0;
};

// Sends each period to two sinks (the CSV trace and a plot recorder).
class TeeTrace final : public sim::TraceSink {
 public:
  TeeTrace(sim::TraceSink* a, sim::TraceSink* b) : a_(a), b_(b) {}
  void row(const sim::TraceRow& r) override {
    if (a_ != nullptr) a_->row(r);
    if (b_ != nullptr) b_->row(r);
  }
  void last(const sim::TraceRow& r) override {
    if (a_ != nullptr) a_->last(r);
    if (b_ != nullptr) b_->last(r);
  }
  std::int64_t stride() const noexcept override {
    return std::gcd(a_ != nullptr ? a_->stride() : 0, b_ != nullptr ? b_->stride() : 0);
  }

 private:
  sim::TraceSink* a_;
  sim::TraceSink* b_;
};

}  // namespace skipnc::plot
