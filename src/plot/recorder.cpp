#include "plot/recorder.hpp"

#include <algorithm>
#include <limits>
#include <type_traits>
#include <utility>

#include "config/skip_inputs.hpp"

namespace skipnc::plot {

const char* move_kind_name(MoveKind k) noexcept {
  switch (k) {
    case MoveKind::kNone:
      return "none";
    case MoveKind::kRapid:
      return "rapid";
    case MoveKind::kFeed:
      return "feed";
    case MoveKind::kArc:
      return "arc";
    case MoveKind::kSkip:
      return "skip";
    case MoveKind::kDwell:
      return "dwell";
  }
  return "none";
}

namespace {

constexpr std::size_t kMaxSignals = 32;
constexpr std::size_t kMaxPending = 1 << 16;

// Channel c of a sample: cmd[0..n), act[0..n), following error[0..n),
// torque[0..n), then the path speed.
double channel(const Sample& s, int n, int c) noexcept {
  const int axis = c % n;
  switch (c / n) {
    case 0:
      return s.cmd[axis];
    case 1:
      return s.act[axis];
    case 2:
      return s.cmd[axis] - s.act[axis];
    case 3:
      return s.torque[axis];
    default:
      return s.feed_mm_min;
  }
}

double tolerance(const Decimation& d, int n, int c) noexcept {
  switch (c / n) {
    case 0:
    case 1:
      return d.pos_tol_mm;
    case 2:
      return d.fe_tol_mm;
    case 3:
      return d.torque_tol_pct;
    default:
      return d.feed_tol_mm_min;
  }
}

}  // namespace

Recorder::Recorder(const config::MachineConfig& m, Decimation d)
    : n_(std::max(1, m.axis_count())), d_(d) {
  const auto channels = static_cast<std::size_t>(4 * n_ + 1);
  lo_.resize(channels);
  hi_.resize(channels);
  lo_next_.resize(channels);
  hi_next_.resize(channels);
  kept_.reserve(std::min<std::size_t>(d_.max_samples + 64, 1 << 16));
}

void Recorder::emit(const canon::Stamped& c) {
  // A command after a skip is emitted once the axes are at rest, so the
  // last period seen holds its start.
  if (tail_from_trace_ && have_prev_) tail_ = prev_.cmd;
  tail_from_trace_ = false;
  MoveKind kind = MoveKind::kNone;
  std::visit(
      [&](const auto& cmd) {
        using T = std::decay_t<decltype(cmd)>;
        if constexpr (std::is_same_v<T, canon::Rapid>) {
          kind = MoveKind::kRapid;
        } else if constexpr (std::is_same_v<T, canon::Feed>) {
          kind = MoveKind::kFeed;
        } else if constexpr (std::is_same_v<T, canon::Arc>) {
          kind = MoveKind::kArc;
        } else if constexpr (std::is_same_v<T, canon::Dwell>) {
          kind = MoveKind::kDwell;
        } else if constexpr (std::is_same_v<T, canon::ToolSelect>) {
          selected_tool_ = cmd.tool;
        } else if constexpr (std::is_same_v<T, canon::MCode>) {
          if (cmd.code == 6 && selected_tool_ >= 0) pending_tool_ = selected_tool_;
        } else if constexpr (std::is_same_v<T, canon::Skip>) {
          kind = MoveKind::kSkip;
          if (skip_moves_.size() < d_.max_skip_moves) {
            skip_moves_.push_back(
                SkipMove{c.line, c.source, tail_, cmd.target, cmd.feed_mm_per_min});
          } else {
            ++skip_moves_dropped_;
          }
          tail_from_trace_ = true;
        }
        if constexpr (std::is_same_v<T, canon::Rapid> || std::is_same_v<T, canon::Feed> ||
                      std::is_same_v<T, canon::Arc> || std::is_same_v<T, canon::Skip>) {
          tail_ = cmd.target;
        }
      },
      c.cmd);
  if (kind == MoveKind::kNone) return;
  if (pending_.size() >= kMaxPending) pending_.pop_front();
  pending_.push_back(Pending{c.line, c.source, kind});
}

// The kind of the command that started the block at `line`. Commands are
// emitted before the kernel runs them, in order; a command that never shows
// in the trace (a zero-length move) is passed over.
MoveKind Recorder::take_kind(std::uint32_t line, std::uint32_t source) {
  const auto it = std::find_if(pending_.begin(), pending_.end(), [&](const Pending& p) {
    return p.line == line && p.source == source;
  });
  if (it == pending_.end()) return MoveKind::kNone;
  const MoveKind k = it->kind;
  pending_.erase(pending_.begin(), it + 1);
  return k;
}

void Recorder::reset_sleeve(const Sample& anchor) {
  anchor_ = anchor;
  std::fill(lo_.begin(), lo_.end(), -std::numeric_limits<double>::infinity());
  std::fill(hi_.begin(), hi_.end(), std::numeric_limits<double>::infinity());
}

// Narrows every channel's range of slopes from the anchor so that the line
// passes within tolerance of `s`; false when some range becomes empty.
bool Recorder::sleeve_accepts(const Sample& s) {
  const double dt = s.t - anchor_.t;
  if (dt <= 0.0) return true;
  const int channels = static_cast<int>(lo_.size());
  std::vector<double>& lo = lo_next_;
  std::vector<double>& hi = hi_next_;
  for (int c = 0; c < channels; ++c) {
    const double y = channel(s, n_, c) - channel(anchor_, n_, c);
    const double tol = tolerance(d_, n_, c) * scale_;
    const auto ci = static_cast<std::size_t>(c);
    lo[ci] = std::max(lo_[ci], (y - tol) / dt);
    hi[ci] = std::min(hi_[ci], (y + tol) / dt);
    if (lo[ci] > hi[ci]) return false;
  }
  lo_.swap(lo);
  hi_.swap(hi);
  return true;
}

void Recorder::keep(const Sample& s) {
  if (!kept_.empty() && kept_.back().t >= s.t) {
    kept_.back().pin = std::max(kept_.back().pin, s.pin);
    return;
  }
  kept_.push_back(s);
  recent_.clear();
  if (kept_.size() > d_.max_samples) thin();
}

// Doubles the tolerances and thins the kept samples with them. Hard pins
// stay; block boundaries stay while the tolerance is at most 4x.
void Recorder::thin() {
  std::size_t guard = 0;
  while (kept_.size() > d_.max_samples && guard++ < 8) {
    const std::size_t before = kept_.size();
    scale_ *= 2.0;
    std::vector<Sample> out;
    out.reserve(kept_.size() / 2 + 16);
    auto pinned = [&](const Sample& s) {
      return s.pin >= kPinHard || (s.pin == kPinSoft && scale_ <= 4.0);
    };
    out.push_back(kept_.front());
    reset_sleeve(kept_.front());
    for (std::size_t i = 1; i < kept_.size(); ++i) {
      const Sample& s = kept_[i];
      const bool last = i + 1 == kept_.size();
      if (!sleeve_accepts(s)) {
        if (out.back().t < kept_[i - 1].t) out.push_back(kept_[i - 1]);
        reset_sleeve(out.back());
        (void)sleeve_accepts(s);
      }
      if (pinned(s) || last) {
        out.push_back(s);
        reset_sleeve(s);
      }
    }
    kept_ = std::move(out);
    if (kept_.size() * 10 > before * 9) break;  // pins dominate: thinning no longer helps
  }
  if (kept_.size() > d_.max_samples) {
    d_.max_samples = std::min(kept_.size() + kept_.size() / 2, d_.max_kept);
  }
  if (kept_.size() >= d_.max_kept) thin_pins();
  reset_sleeve(kept_.back());
}

// Pins dominate and the hard bound is reached: every other sample goes,
// pinned or not (the first and the last stay). Memory stays within
// max_kept samples however long the run; edges then lose their periods
// around, not the edge's place to the drawing's resolution.
void Recorder::thin_pins() {
  std::vector<Sample> out;
  out.reserve(kept_.size() / 2 + 2);
  for (std::size_t i = 0; i < kept_.size(); ++i) {
    if (i % 2 == 0 || i + 1 == kept_.size()) out.push_back(kept_[i]);
  }
  kept_ = std::move(out);
}

// Past max_blocks block runs, each pair of neighbouring runs becomes one
// (the first's line and kind, the second's end); runs of skip blocks are
// merged only when the others are not enough. The open run (the last) stays.
void Recorder::merge_blocks() {
  for (const bool skips_too : {false, true}) {
    std::vector<BlockRun> out;
    out.reserve(blocks_.size());
    std::size_t i = 0;
    for (; i + 2 < blocks_.size(); i += 2) {
      const BlockRun& a = blocks_[i];
      const BlockRun& b = blocks_[i + 1];
      if (!skips_too && (a.kind == MoveKind::kSkip || b.kind == MoveKind::kSkip)) {
        out.push_back(a);
        out.push_back(b);
        continue;
      }
      BlockRun m = a;
      m.t1 = b.t1;
      m.end_act = b.end_act;
      m.end_cmd = b.end_cmd;
      out.push_back(m);
    }
    for (; i < blocks_.size(); ++i) out.push_back(blocks_[i]);
    blocks_ = std::move(out);
    if (blocks_.size() * 4 <= d_.max_blocks * 3) return;
  }
}

// A change to the tool already in the spindle changes nothing drawn and is
// not kept. Past max_tool_changes every other change goes (the first and the
// last stay): memory stays bounded however many changes the program makes.
void Recorder::add_tool_change(double t, int tool) {
  if (!tool_changes_.empty() && tool_changes_.back().tool == tool) return;
  tool_changes_.push_back(ToolChange{t, tool});
  if (tool_changes_.size() <= std::max<std::size_t>(d_.max_tool_changes, 2)) return;
  std::vector<ToolChange> out;
  out.reserve(tool_changes_.size() / 2 + 2);
  for (std::size_t i = 0; i < tool_changes_.size(); ++i) {
    if (i % 2 == 0 || i + 1 == tool_changes_.size()) out.push_back(tool_changes_[i]);
  }
  tool_changes_dropped_ += tool_changes_.size() - out.size();
  tool_changes_ = std::move(out);
}

Sample Recorder::sample_of(const sim::TraceRow& r) {
  Sample cur;
  cur.t = r.time_s;
  cur.line = r.line;
  cur.source = r.source;
  cur.feed_mm_min = r.feed_mm_per_min;
  if (r.commanded != nullptr) cur.cmd = *r.commanded;
  if (r.actual != nullptr) cur.act = *r.actual;
  if (r.torque != nullptr) cur.torque = *r.torque;
  if (r.plant != nullptr) {
    const std::size_t ns = std::min(r.plant->signal_count(), kMaxSignals);
    if (signal_names_.empty()) {
      for (std::size_t i = 0; i < ns; ++i) {
        signal_names_.push_back(config::signal_name(r.plant->signal_addr(i)));
      }
    }
    for (std::size_t i = 0; i < ns; ++i) {
      if (r.plant->signal_level(i)) cur.signals |= 1U << i;
    }
  }
  return cur;
}

void Recorder::keep_edge(Sample& cur, bool prev_kept) {
  // The periods just before the edge, the edge itself and the next few.
  std::deque<Sample> before;
  before.swap(recent_);
  for (Sample s : before) {
    s.pin = kPinHard;
    keep(s);
  }
  if (!prev_kept && (before.empty() || before.back().t < prev_.t)) {
    Sample p = prev_;
    p.pin = kPinHard;
    keep(p);
  } else if (!kept_.empty()) {
    kept_.back().pin = kPinHard;
  }
  cur.pin = kPinHard;
  keep(cur);
  reset_sleeve(cur);
  keep_after_ = d_.keep_around_edge;
}

void Recorder::keep_block_start(Sample& cur, bool prev_kept) {
  if (!prev_kept) {
    Sample p = prev_;
    p.pin = kPinSoft;
    keep(p);
  } else {
    kept_.back().pin = std::max(kept_.back().pin, kPinSoft);
  }
  cur.pin = kPinSoft;
  keep(cur);
  reset_sleeve(cur);
}

// The tool in the spindle changes at the period the simulation changed it
// (the plant's spindle tool: the one contacts and cuts use), which may be
// long after the M06 was read: the interpreter reads on past it while the
// motion before it runs, and the next M06 may be read before the first is
// made. Rows without a plant place the M06 read last at the first period
// after it in which the command stands.
void Recorder::place_tool_change(const sim::TraceRow& r, const Sample& cur) {
  if (r.plant != nullptr) {
    const int tool = r.plant->probing().spindle_tool();
    if (plant_tool_ >= 0 && tool != plant_tool_) add_tool_change(cur.t, tool);
    plant_tool_ = tool;
    pending_tool_ = -1;
  } else if (pending_tool_ >= 0 && have_prev_ && cur.cmd == prev_.cmd) {
    add_tool_change(cur.t, pending_tool_);
    pending_tool_ = -1;
  }
}

void Recorder::row(const sim::TraceRow& r) {
  ++rows_;
  Sample cur = sample_of(r);
  if (!have_prev_) {
    place_tool_change(r, cur);
    have_prev_ = true;
    cur.pin = kPinHard;
    blocks_.push_back(BlockRun{cur.line, cur.source, take_kind(cur.line, cur.source), cur.t, cur.t,
                               cur.act, cur.act, cur.cmd});
    keep(cur);
    reset_sleeve(cur);
    prev_ = cur;
    return;
  }
  place_tool_change(r, cur);
  const bool new_block = cur.line != prev_.line || cur.source != prev_.source;
  const bool edge = cur.signals != prev_.signals;
  if (new_block) {
    BlockRun& b = blocks_.back();
    b.t1 = prev_.t;
    b.end_act = prev_.act;
    b.end_cmd = prev_.cmd;
    blocks_.push_back(BlockRun{cur.line, cur.source, take_kind(cur.line, cur.source), cur.t, cur.t,
                               cur.act, cur.act, cur.cmd});
    if (blocks_.size() > d_.max_blocks) merge_blocks();
  }
  const bool prev_kept = !kept_.empty() && kept_.back().t >= prev_.t;
  if (edge) {
    keep_edge(cur, prev_kept);
  } else if (new_block) {
    keep_block_start(cur, prev_kept);
  } else if (keep_after_ > 0) {
    --keep_after_;
    cur.pin = kPinHard;
    keep(cur);
    reset_sleeve(cur);
  } else if (!sleeve_accepts(cur)) {
    keep(prev_);
    reset_sleeve(prev_);
    (void)sleeve_accepts(cur);
    recent_.push_back(cur);
  } else {
    recent_.push_back(cur);
    if (recent_.size() > static_cast<std::size_t>(d_.keep_around_edge)) recent_.pop_front();
  }
  prev_ = cur;
}

void Recorder::finish() {
  if (!have_prev_) return;
  BlockRun& b = blocks_.back();
  b.t1 = prev_.t;
  b.end_act = prev_.act;
  b.end_cmd = prev_.cmd;
  Sample last = prev_;
  last.pin = kPinHard;
  keep(last);
}

}  // namespace skipnc::plot
