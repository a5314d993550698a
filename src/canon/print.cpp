#include "canon/print.hpp"

#include <charconv>
#include <iterator>
#include <type_traits>

namespace skipnc::canon {
namespace {

// The shortest text that reads back to the same double (std::to_chars), the
// hot part of `skipnc canon`; -0.0 is written as 0.
void number_to(fmt::memory_buffer& out, double v) {
  char buf[32];
  // Fast path for the common case, a value with at most three decimals (what
  // a program of 0.001 mm words produces): if m / 1000 is v exactly, "m with
  // the point three places in, trailing zeros dropped" is the shortest text
  // that reads back to v, the same as std::to_chars gives.
  if (v > -1e9 && v < 1e9) {
    const double scaled = v * 1000.0;
    const auto m = static_cast<long long>(scaled < 0 ? scaled - 0.5 : scaled + 0.5);
    if (static_cast<double>(m) / 1000.0 == v) {
      unsigned long long a =
          m < 0 ? static_cast<unsigned long long>(-m) : static_cast<unsigned long long>(m);
      char* e = buf + sizeof buf;
      char* p = e;
      int frac = 3;
      while (frac > 0 && a % 10 == 0) {  // drop trailing zeros of the fraction
        a /= 10;
        --frac;
      }
      for (int i = 0; i < frac; ++i) {
        *--p = static_cast<char>('0' + a % 10);
        a /= 10;
      }
      if (frac > 0) *--p = '.';
      do {
        *--p = static_cast<char>('0' + a % 10);
        a /= 10;
      } while (a != 0);
      if (m < 0) *--p = '-';
      out.append(p, e);
      return;
    }
  }
  const auto r = std::to_chars(buf, buf + sizeof buf, v + 0.0);
  out.append(buf, r.ptr);
}

void axes_to(fmt::memory_buffer& out, const AxisVec& v, const AxisNames& axes) {
  for (int i = 0; i < axes.count; ++i) {
    out.push_back(' ');
    out.push_back(axes.names[i]);
    number_to(out, v[i]);
  }
}

void text_to(fmt::memory_buffer& out, std::string_view s) {
  out.append(s.data(), s.data() + s.size());
}

const char* stop_name(StopKind k) {
  switch (k) {
    case StopKind::kProgramStop:
      return "M00";
    case StopKind::kOptionalStop:
      return "M01";
    case StopKind::kProgramEnd:
      return "M02";
    case StopKind::kRewindEnd:
      return "M30";
  }
  return "?";
}

}  // namespace

void format_to(fmt::memory_buffer& out, const Stamped& s, const AxisNames& axes) {
  auto it = fmt::appender(out);
  {
    char buf[16];
    const auto r = std::to_chars(buf, buf + sizeof buf, s.line);
    out.append(buf, r.ptr);
    out.push_back(' ');
  }
  std::visit(
      [&](const auto& c) {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, Rapid>) {
          text_to(out, "RAPID");
          axes_to(out, c.target, axes);
          if (!c.linear) text_to(out, " NONLINEAR");
        } else if constexpr (std::is_same_v<T, Feed>) {
          text_to(out, "FEED");
          axes_to(out, c.target, axes);
          text_to(out, " F");
          number_to(out, c.feed_mm_per_min);
          if (c.exact_stop) text_to(out, " EXACT");
        } else if constexpr (std::is_same_v<T, Arc>) {
          text_to(out, c.ccw ? "ARC_CCW" : "ARC_CW");
          axes_to(out, c.target, axes);
          text_to(out, " C");
          out.push_back(axes.names[c.plane.a0]);
          out.push_back('=');
          number_to(out, c.center0);
          text_to(out, " C");
          out.push_back(axes.names[c.plane.a1]);
          out.push_back('=');
          number_to(out, c.center1);
          text_to(out, " F");
          number_to(out, c.feed_mm_per_min);
          if (c.extra_turns != 0) fmt::format_to(it, " TURNS{}", c.extra_turns);
          if (c.exact_stop) text_to(out, " EXACT");
        } else if constexpr (std::is_same_v<T, Dwell>) {
          fmt::format_to(it, "DWELL {}", c.seconds);
        } else if constexpr (std::is_same_v<T, Skip>) {
          const SkipSpec& sp = c.spec;
          fmt::format_to(it, "SKIP");
          axes_to(out, c.target, axes);
          fmt::format_to(it, " F{} KIND={}", c.feed_mm_per_min,
                         sp.kind == SkipKind::kSkip        ? "skip"
                         : sp.kind == SkipKind::kMultiStep ? "multi_step"
                                                           : "torque");
          if (sp.p >= 0) fmt::format_to(it, " P{}", sp.p);
          for (int i = 0; i < sp.input_count; ++i) {
            fmt::format_to(it, " IN={}{}.{}", sp.inputs[i].area, sp.inputs[i].byte,
                           static_cast<int>(sp.inputs[i].bit));
          }
          if (sp.torque_ends) {
            fmt::format_to(it, " TORQUE_AXIS={} LIMIT={}% DELAY={}", axes.names[sp.torque_axis],
                           sp.torque_limit_pct, sp.torque_delay_s);
          }
          fmt::format_to(it, " {}{}{}{}", sp.active_low ? "LOW" : "HIGH",
                         sp.edge ? " EDGE" : " LEVEL",
                         sp.stop == SkipStop::kImmediate ? " STOP=immediate" : " STOP=decelerate",
                         sp.alarm_on_miss ? " K1" : "");
        } else if constexpr (std::is_same_v<T, Spindle>) {
          fmt::format_to(it, "SPINDLE S{} {}", c.rpm,
                         c.direction > 0   ? "CW"
                         : c.direction < 0 ? "CCW"
                                           : "OFF");
          if (c.surface_speed > 0.0) fmt::format_to(it, " CSS={}", c.surface_speed);
          if (c.max_rpm > 0.0) fmt::format_to(it, " MAX={}", c.max_rpm);
        } else if constexpr (std::is_same_v<T, ToolSelect>) {
          fmt::format_to(it, "TOOL T{}", c.tool);
        } else if constexpr (std::is_same_v<T, MCode>) {
          fmt::format_to(it, "MCODE M{}", c.code);
        } else if constexpr (std::is_same_v<T, Stop>) {
          fmt::format_to(it, "STOP {}", stop_name(c.kind));
        } else if constexpr (std::is_same_v<T, Message>) {
          fmt::format_to(it, "MESSAGE {}", c.text);
        }
      },
      s.cmd);
  out.push_back('\n');
}

std::string to_string(const Stamped& cmd, const AxisNames& axes) {
  fmt::memory_buffer b;
  format_to(b, cmd, axes);
  return std::string(b.data(), b.size() - 1);
}

}  // namespace skipnc::canon
