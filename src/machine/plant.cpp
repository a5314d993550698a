#include "machine/plant.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace skipnc::machine {

Plant::Plant(const config::MachineConfig& m, const Scene& scene, ServoClock clock)
    : m_(m), scene_(scene), clock_(clock), n_(m.axis_count()), probing_(scene_.probing, m) {
  plain_servo_ = scene_.stops.empty() && scene_.loads.empty();
  for (int i = 0; i < n_; ++i) {
    const auto k_i = static_cast<std::size_t>(i);
    const config::AxisConfig& a = m.axes[k_i];
    const double kp = a.kp_per_s;
    decay_[k_i] = kp > 0 ? std::exp(-kp * clock_.period_s()) : 0.0;
    lag_gain_[k_i] = kp > 0 ? (1.0 - a.feedforward) / (kp * clock_.period_s()) : 0.0;
    torque_per_mm_[k_i] = a.torque_pct_per_mm;
    torque_max_[k_i] = a.torque_max_pct;
    plain_servo_ = plain_servo_ && kp > 0.0;
  }
  set_locked(AxisMask{});
  auto signal_for = [&](const canon::SignalAddr& a) -> Signal& {
    for (auto& s : signals_) {
      if (s.addr == a) return s;
    }
    signals_.push_back(Signal{a, false, {}});
    return signals_.back();
  };
  for (std::size_t i = 0; i < scene_.triggers.size(); ++i) {
    sources_.push_back(Source{SourceKind::kTrigger, i, false});
    signal_for(scene_.triggers[i].signal).sources.push_back(sources_.size() - 1);
  }
  for (std::size_t i = 0; i < scene_.pulses.size(); ++i) {
    sources_.push_back(Source{SourceKind::kPulse, i, false});
    signal_for(scene_.pulses[i].signal).sources.push_back(sources_.size() - 1);
  }
  timed_sources_ = sources_.size();
  for (std::size_t i = 0; i < probing_.source_count(); ++i) {
    sources_.push_back(Source{SourceKind::kProbing, i, false});
    probing_source_.push_back(sources_.size() - 1);
    signal_for(probing_.source_signal(i)).sources.push_back(sources_.size() - 1);
  }
  events_.reserve(sources_.size() * 2 + 4);
}

void Plant::reset(const AxisVec& position) {
  actual_ = position;
  torque_ = AxisVec{};
  probing_.reset(position);
  for (auto& s : sources_) {
    if (s.kind == SourceKind::kTrigger) {
      const Trigger& t = scene_.triggers[s.index];
      s.on = trigger_on(t, actual_[t.axis]);
    } else if (s.kind == SourceKind::kPulse) {
      const Pulse& p = scene_.pulses[s.index];
      s.on = p.at_time_s <= 0.0 && p.duration_s > 0.0;
    } else {
      s.on = probing_.source_on(s.index);
    }
  }
  for (auto& sig : signals_) {
    sig.level = false;
    for (auto k : sig.sources) sig.level = sig.level || sources_[k].on;
  }
}

void Plant::advance(Tick k, const AxisVec& from, const AxisVec& to,
                    kernel::TickInput& in) noexcept {
  const AxisVec before = actual_;
  if (plain_servo_ && locked_.empty() && !limited_) {
    // The common case, the same arithmetic as the loop below without its
    // stops, loads, locked axes and torque limits.
    for (int i = 0; i < n_; ++i) {
      const auto k_i = static_cast<std::size_t>(i);
      const double e0 = from[i] - actual_[i];
      const double ess = (to[i] - from[i]) * lag_gain_[k_i];
      const double e1 = ess + (e0 - ess) * decay_[k_i];
      const double a1 = to[i] - e1;
      actual_[i] = a1;
      const double fe = to[i] - a1;
      const double limit = torque_max_[k_i];
      torque_[i] = std::clamp(torque_per_mm_[k_i] * fe + 0.0, -limit, limit);
    }
  } else {
    advance_servo(k, before, from, to);
  }
  in.actual = actual_;
  in.torque_pct = torque_;
  in.edge_count = 0;
  probing_.advance(before, actual_);
  // The axis that moved in the last period is asked first: it nearly always
  // moves in this one too (a probe's Z, the last axis, was reached last).
  const int j = moving_axis_;
  bool still = from[j] == to[j] && before[j] == actual_[j];
  for (int i = 0; still && i < n_; ++i) {
    still = from[i] == to[i] && before[i] == actual_[i];
    if (!still) moving_axis_ = i;
  }
  // Most periods: no trigger or pulse in the scene and no probing edge.
  if (timed_sources_ != 0 || !probing_.edges().empty()) source_edges(k, before, in);
  still_ = still && in.edge_count == 0 ? std::min(still_ + 1, 2) : 0;
}

std::int64_t Plant::quiet_ticks(Tick now) const noexcept {
  if (still_ < 2) return 0;
  // The next instant a pulse or a load of the scene begins or ends.
  const double t = clock_.seconds(now);
  double next = std::numeric_limits<double>::infinity();
  auto note = [&](double at) {
    if (at > t) next = std::fmin(next, at);
  };
  for (const Pulse& p : scene_.pulses) {
    note(p.at_time_s);
    note(p.at_time_s + p.duration_s);
  }
  for (const Load& l : scene_.loads) {
    note(l.at_time_s);
    note(l.at_time_s + l.duration_s);
  }
  constexpr std::int64_t kForever = INT64_MAX / 4;
  if (!std::isfinite(next)) return kForever;
  const double n = std::floor(next / clock_.period_s()) - static_cast<double>(now) - 2.0;
  return n > 0.0 ? static_cast<std::int64_t>(std::fmin(n, 1e18)) : 0;
}

void Plant::pass_cruise(std::int64_t n, const AxisVec& from, const AxisVec& to, const AxisVec& step,
                        kernel::TickInput& in) noexcept {
  for (int i = 0; i < n_; ++i) {
    const auto k_i = static_cast<std::size_t>(i);
    const double e0 = from[i] - actual_[i];
    const double ess = step[i] * lag_gain_[k_i];
    const double e1 = ess + (e0 - ess) * std::pow(decay_[k_i], static_cast<double>(n));
    const double a1 = to[i] - e1;
    actual_[i] = a1;
    const double fe = to[i] - a1;
    const double limit = torque_max_[k_i];
    torque_[i] = std::clamp(torque_per_mm_[k_i] * fe + 0.0, -limit, limit);
  }
  in.actual = actual_;
  in.torque_pct = torque_;
  in.edge_count = 0;
  still_ = 0;
}

void Plant::advance_servo(Tick k, const AxisVec& before, const AxisVec& from,
                          const AxisVec& to) noexcept {
  const double t_now = scene_.loads.empty() ? 0.0 : clock_.seconds(k);  // only loads need it
  for (int i = 0; i < n_; ++i) {
    const auto& ax = m_.axes[static_cast<std::size_t>(i)];
    if (locked_.has(i)) {
      torque_[i] = 0.0;
      continue;
    }
    const double kp = ax.kp_per_s;
    double a1;
    if (kp <= 0.0) {
      a1 = to[i];  // ideal servo: the axis is where it is commanded
    } else {
      // e' = (1 - ff) * vc - kp * e, exact over the period.
      const double e0 = from[i] - actual_[i];
      // (1 - ff) * vc / kp with vc = (to - from) / T.
      const double ess = (to[i] - from[i]) * lag_gain_[static_cast<std::size_t>(i)];
      const double e1 = ess + (e0 - ess) * decay_[static_cast<std::size_t>(i)];
      a1 = to[i] - e1;
    }
    for (const Stop& st : scene_.stops) {
      if (st.axis != i) continue;
      if (st.decreasing ? (a1 < st.at && before[i] >= st.at) : (a1 > st.at && before[i] <= st.at)) {
        a1 = st.at;
      }
    }
    actual_[i] = a1;
    const double fe = to[i] - a1;
    double load = 0.0;
    for (const Load& l : scene_.loads) {
      if (l.axis == i && t_now >= l.at_time_s && t_now < l.at_time_s + l.duration_s) {
        load += l.torque_pct;
      }
    }
    double limit = ax.torque_max_pct;
    if (torque_limit_[i] > 0.0) limit = std::fmin(limit, torque_limit_[i]);
    torque_[i] = std::clamp(ax.torque_pct_per_mm * fe + load, -limit, limit);
  }
}

void Plant::source_edges(Tick k, const AxisVec& before, kernel::TickInput& in) noexcept {
  // Source events inside the period, in time order.
  events_.clear();
  const double t0 = clock_.seconds(k - 1);
  for (std::size_t s = 0; s < timed_sources_; ++s) {  // a probe's edges come below
    const Source& src = sources_[s];
    if (src.kind == SourceKind::kTrigger) {
      const Trigger& t = scene_.triggers[src.index];
      const double p0 = before[t.axis], p1 = actual_[t.axis];
      const bool on1 = trigger_on(t, p1);
      if (on1 != src.on) {
        double frac = 1.0;
        if (p1 != p0) frac = std::clamp((t.at - p0) / (p1 - p0), 0.0, 1.0);
        if (frac <= 0.0) frac = std::nextafter(0.0, 1.0);
        events_.push_back(Event{frac, s, on1});
      }
    } else if (src.kind == SourceKind::kPulse) {
      const Pulse& p = scene_.pulses[src.index];
      const double on_t = p.at_time_s, off_t = p.at_time_s + p.duration_s;
      // An instant belongs to the period (t_{k-1}, t_k]; a tolerance far
      // below a period keeps an instant on a period boundary from being lost
      // (or counted twice) to rounding.
      constexpr double kEps = 1e-9;
      const double T = clock_.period_s();
      auto frac_of = [&](double t) { return (t - t0) / T; };
      auto inside = [&](double f) { return f > kEps && f <= 1.0 + kEps; };
      const double f_on = frac_of(on_t), f_off = frac_of(off_t);
      if (p.duration_s > 0.0 && inside(f_on))
        events_.push_back(Event{std::fmin(f_on, 1.0), s, true});
      if (p.duration_s > 0.0 && inside(f_off)) {
        events_.push_back(Event{std::fmin(f_off, 1.0), s, false});
      }
    }
  }
  for (const auto& e : probing_.edges()) {
    events_.push_back(Event{e.frac, probing_source_[e.source], e.on});
  }
  if (events_.empty()) return;
  // Equal instants: a switch-on before a switch-off (a touch inside one instant).
  std::sort(events_.begin(), events_.end(), [](const Event& a, const Event& b) {
    return a.frac < b.frac || (a.frac == b.frac && a.on && !b.on);
  });
  for (const Event& e : events_) {
    sources_[e.source].on = e.on;
    for (auto& sig : signals_) {
      bool level = false;
      bool mine = false;
      for (auto idx : sig.sources) {
        level = level || sources_[idx].on;
        mine = mine || idx == e.source;
      }
      if (!mine || level == sig.level) continue;
      sig.level = level;
      if (in.edge_count < kernel::TickInput::kMaxEdges) {
        in.edges[static_cast<std::size_t>(in.edge_count++)] =
            kernel::SignalEdge{sig.addr, level, e.frac};
      }
    }
  }
}

}  // namespace skipnc::machine
