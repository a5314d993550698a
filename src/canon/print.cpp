#include "canon/print.hpp"

#include <bit>
#include <charconv>
#include <cstring>
#include <iterator>
#include <type_traits>

#include "core/decimal.hpp"

namespace skipnc::canon {
namespace {

// Room a number takes at most (std::to_chars of a double needs 24).
constexpr std::size_t kNumberRoom = 32;

// The shortest text that reads back to the same double, written at p (which
// has kNumberRoom characters of room); returns the end. -0.0 is written as 0.
// The hot part of `skipnc canon`.
char* number_at(char* p, double v) noexcept {
  // Fast path for the common case, a value with at most three decimals (what
  // a program of 0.001 mm words produces): if m / 1000 is v exactly, "m with
  // the point three places in, trailing zeros dropped" is the shortest text
  // that reads back to v.
  if (v > -1e9 && v < 1e9) {
    const double scaled = v * 1000.0;
    const auto m = static_cast<long long>(scaled < 0 ? scaled - 0.5 : scaled + 0.5);
    if (static_cast<double>(m) / 1000.0 == v) return decimal::write_milli(p, m);
  }
  return decimal::write_shortest(p, v + 0.0);
}

using Field = TextWriter::Field;

// Writes the text of the common commands (lines, rapids, arcs; the axes of a
// skip) straight into a reserved stretch of the buffer: they are nearly every
// line of a program.
class LineWriter {
 public:
  // Room for the longest line of those commands: the line number, the name,
  // eight axes, two centre words, the feed and the flags.
  static constexpr std::size_t kRoom =
      20 + 8 + kMaxAxes * (2 + kNumberRoom) + 2 * (4 + kNumberRoom) + (2 + kNumberRoom) + 32 + 8;
  LineWriter(fmt::memory_buffer& out, Field* fields) : out_(out), fields_(fields) {
    const std::size_t start = out.size();
    out_.resize(start + kRoom);
    p_ = out_.data() + start;
  }
  LineWriter(const LineWriter&) = delete;
  LineWriter& operator=(const LineWriter&) = delete;
  ~LineWriter() { out_.resize(static_cast<std::size_t>(p_ - out_.data())); }

  // A literal: copied whole, its length known when compiled.
  template <std::size_t N>
  void text(const char (&s)[N]) noexcept {
    std::memcpy(p_, s, N - 1);
    p_ += N - 1;
  }
  void put(char c) noexcept { *p_++ = c; }
  // The value of field `f`: the text last written there when the value is
  // the same double, else number_at's, remembered.
  void number(double v, int f) noexcept {
    Field& field = fields_[f];
    const auto bits = std::bit_cast<std::uint64_t>(v);
    if (bits == field.bits) {
      std::memcpy(p_, field.text, kFieldCopy);
      p_ += field.size;
      return;
    }
    char* const e = number_at(p_, v);
    field.bits = bits;
    field.size = static_cast<std::uint32_t>(e - p_);
    std::memcpy(field.text, p_, kFieldCopy);
    p_ = e;
  }
  void line(std::uint32_t v) noexcept { p_ = decimal::write_uint32(p_, v); }
  void integer(long long v) noexcept { p_ = decimal::write_int(p_, v); }
  void axes(const AxisVec& v, const AxisNames& names) noexcept {
    for (int i = 0; i < names.count; ++i) {
      p_[0] = ' ';
      p_[1] = names.names[i];
      p_ += 2;
      number(v[i], i);
    }
  }

 private:
  // Characters of a field's text copied (the longest text is 24).
  static constexpr std::size_t kFieldCopy = 24;
  static_assert(sizeof(Field::text) >= kFieldCopy && kNumberRoom >= kFieldCopy);

  fmt::memory_buffer& out_;
  Field* fields_;
  char* p_;
};

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

// The lines of the common commands, written straight into the buffer.
void write_feed(fmt::memory_buffer& out, Field* fields, std::uint32_t line, const Feed& c,
                const AxisNames& axes) {
  LineWriter w(out, fields);
  w.line(line);
  w.text(" FEED");
  w.axes(c.target, axes);
  w.text(" F");
  w.number(c.feed_mm_per_min, TextWriter::kFeed);
  if (c.exact_stop) w.text(" EXACT");
  w.put('\n');
}

void write_rapid(fmt::memory_buffer& out, Field* fields, std::uint32_t line, const Rapid& c,
                 const AxisNames& axes) {
  LineWriter w(out, fields);
  w.line(line);
  w.text(" RAPID");
  w.axes(c.target, axes);
  if (!c.linear) w.text(" NONLINEAR");
  w.put('\n');
}

void write_arc(fmt::memory_buffer& out, Field* fields, std::uint32_t line, const Arc& c,
               const AxisNames& axes) {
  LineWriter w(out, fields);
  w.line(line);
  if (c.ccw) {
    w.text(" ARC_CCW");
  } else {
    w.text(" ARC_CW");
  }
  w.axes(c.target, axes);
  w.text(" C");
  w.put(axes.names[c.plane.a0]);
  w.put('=');
  w.number(c.center0, TextWriter::kCentre0);
  w.text(" C");
  w.put(axes.names[c.plane.a1]);
  w.put('=');
  w.number(c.center1, TextWriter::kCentre1);
  w.text(" F");
  w.number(c.feed_mm_per_min, TextWriter::kFeed);
  if (c.extra_turns != 0) {
    w.text(" TURNS");
    w.integer(c.extra_turns);
  }
  if (c.exact_stop) w.text(" EXACT");
  w.put('\n');
}

// "SKIP X.. F.. KIND=.. [P..] [IN=..] [TORQUE_AXIS=..] LOW|HIGH EDGE|LEVEL STOP=.. [K1]"
void write_skip(fmt::memory_buffer& out, Field* fields, const Skip& c, const AxisNames& axes) {
  auto it = fmt::appender(out);
  const SkipSpec& sp = c.spec;
  {
    LineWriter w(out, fields);
    w.text("SKIP");
    w.axes(c.target, axes);
  }
  fmt::format_to(it, " F{} KIND={}", c.feed_mm_per_min,
                 sp.kind == SkipKind::kSkip        ? "skip"
                 : sp.kind == SkipKind::kMultiStep ? "multi_step"
                 : sp.kind == SkipKind::kProbe     ? "probe"
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
  fmt::format_to(it, " {}{}{}{}", sp.active_low ? "LOW" : "HIGH", sp.edge ? " EDGE" : " LEVEL",
                 sp.stop == SkipStop::kImmediate ? " STOP=immediate" : " STOP=decelerate",
                 sp.alarm_on_miss ? " K1" : "");
}

// The text of the other commands after the line number (no newline).
void write_other(fmt::memory_buffer& out, Field* fields, const Command& cmd,
                 const AxisNames& axes) {
  auto it = fmt::appender(out);
  std::visit(
      [&](const auto& c) {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, Rapid> || std::is_same_v<T, Feed> ||
                      std::is_same_v<T, Arc>) {
          // written by format_to's own writers
        } else if constexpr (std::is_same_v<T, Dwell>) {
          fmt::format_to(it, "DWELL {}", c.seconds);
        } else if constexpr (std::is_same_v<T, Skip>) {
          write_skip(out, fields, c, axes);
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
        } else if constexpr (std::is_same_v<T, AxisRate>) {
          fmt::format_to(it, "AXIS_RATE {} RATE={} ACCEL={}", axes.names[c.axis], c.rate_mm_per_min,
                         c.accel_mm_s2);
        } else if constexpr (std::is_same_v<T, LookAhead>) {
          fmt::format_to(it, "LOOKAHEAD {}", c.blocks);
        }
      },
      cmd);
}

}  // namespace

void TextWriter::append(fmt::memory_buffer& out, const Stamped& s) {
  if (const auto* c = std::get_if<Feed>(&s.cmd)) return write_feed(out, fields_, s.line, *c, axes_);
  if (const auto* c = std::get_if<Rapid>(&s.cmd)) {
    return write_rapid(out, fields_, s.line, *c, axes_);
  }
  if (const auto* c = std::get_if<Arc>(&s.cmd)) return write_arc(out, fields_, s.line, *c, axes_);
  char buf[16];
  const auto r = std::to_chars(buf, buf + sizeof buf, s.line);
  out.append(buf, r.ptr);
  out.push_back(' ');
  write_other(out, fields_, s.cmd, axes_);
  out.push_back('\n');
}

void format_to(fmt::memory_buffer& out, const Stamped& s, const AxisNames& axes) {
  TextWriter(axes).append(out, s);
}

std::string to_string(const Stamped& cmd, const AxisNames& axes) {
  fmt::memory_buffer b;
  format_to(b, cmd, axes);
  return std::string(b.data(), b.size() - 1);
}

}  // namespace skipnc::canon
