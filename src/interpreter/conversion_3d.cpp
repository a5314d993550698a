// The 3-D coordinate conversion `G68 X Y Z I J K R` / G69 and the workpiece
// setting error compensation G54.4 on the mill (transform.hpp holds the
// arithmetic).
//
// Source: Fanuc Series 16/18/160/180-MODEL C operator's manual (machining
// centre), B-62764EN/01, 14 "Functions to simplify programming",
// "Three-dimensional coordinate conversion":
// - format `G68 Xp x1 Yp y1 Zp z1 I i1 J j1 K k1 R a`: X Y Z the centre of
//   rotation, I J K the direction of the axis of rotation, R the angular
//   displacement; G69 cancels;
// - X Y Z are absolute coordinates, also in G91;
// - a second G68 in the mode rotates the coordinate system a second time,
//   its data in the coordinate system the first one formed (X'Y'Z'); without
//   X Y Z its centre is the first one's; the manual speaks of two rotations;
// - P/S alarm 5044 when a G68 block has no I, J or K, when I J K are all 0,
//   or when it has no R.
// What the manual leaves open and skipnc decides (docs/probing-cycles.md):
// a first G68 without X, Y or Z turns about the present position on the
// missing axes (as the plane rotation does); a third G68 is the same format
// alarm; the conversion is not combined with the plane rotation, scaling or
// mirror image (alarm not_simulated either way round).
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "interpreter/impl.hpp"

namespace skipnc::interp {

namespace {

// G68 R without a decimal point is in 0.001 degree (as the plane rotation).
double angle_of(const WordVal& w, bool calculator) {
  return w.is_expr || w.has_point || calculator ? w.value : w.value * 0.001;
}

}  // namespace

Flow<xform::Transform> Interpreter::Impl::conversion_3d(const Words& words, const MillRequest& req,
                                                        const xform::Point& here) const {
  const SourceLoc at = req.frame_at;
  auto format = [&](const std::string& why) {
    return fail(AlarmId::kG68Format, "G68 3-D coordinate conversion: " + why, at);
  };
  if (frame().rotating) {
    return fail(AlarmId::kNotSimulated,
                "G68 I J K in the plane rotation mode (G68 without I J K) is not simulated by "
                "skipnc",
                at);
  }
  if (frame().mirror[0] || frame().mirror[1] || frame().mirror[2] || frame().scale[0] != 1.0 ||
      frame().scale[1] != 1.0 || frame().scale[2] != 1.0) {
    return fail(AlarmId::kNotSimulated,
                "G68 I J K under scaling or mirror image (G51, G51.1) is not simulated by skipnc",
                at);
  }
  if (!words.has('I') || !words.has('J') || !words.has('K')) {
    return format("I, J and K must all be given");
  }
  const xform::Point axis{word_length(words.at('I')), word_length(words.at('J')),
                          word_length(words.at('K'))};
  if (axis[0] == 0.0 && axis[1] == 0.0 && axis[2] == 0.0) return format("I, J and K are all 0");
  if (!words.has('R')) return format("no angular displacement R");
  if (frame().conversions() >= xform::kMaxConversions) {
    return format("a third G68 in the mode (the coordinate system is rotated twice at most)");
  }
  const double angle = angle_of(words.at('R'), params.bit(config::param::kCalculatorDecimal));
  // The centre, absolute in the frame this conversion is made in; a missing
  // axis: the first conversion's centre, else the present position.
  xform::Spatial s = frame().spatial ? *frame().spatial : xform::Spatial{};
  const xform::Point fallback = s.conversions > 0 ? s.conversion[0].center : here;
  xform::Conversion k;
  for (int i = 0; i < 3; ++i) {
    const char c = "XYZ"[i];
    const auto u = static_cast<std::size_t>(i);
    k.center[u] =
        axis_of_letter[c - 'A'] >= 0 && words.has(c) ? word_length(words.at(c)) : fallback[u];
  }
  k.m = xform::axis_angle(axis, angle);
  if (modal.cutter != CutterComp::kOff && (!xform::keeps_z(k.m) || frame().tilted())) {
    return fail(AlarmId::kNotSimulated,
                "a G68 I J K not about Z in G41/G42 is not simulated by skipnc", at);
  }
  s.conversion[static_cast<std::size_t>(s.conversions)] = k;
  ++s.conversions;
  return xform::with_spatial(frame(), s);
}

// G54.4 Pn (Fanuc 30i/31i additional manual A-79634E "Workpiece Setting
// Error Compensation", pages read: 10, 17, 19): data set n turns and shifts
// the workpiece coordinate system by its errors dx dy dz (the setting
// system's origin in the workpiece coordinates), da db dc (turned about X,
// then Y, then Z, right-handed); the errors of No. 00 (COMMON) are added to
// those of set n (on a machine without table rotation axes simply added);
// G54.4 P0 cancels. The data: #26000 + 10 n + 0..5 (dx dy dz da db dc), as
// the Autodesk Fusion Fanuc post writes them (#[26000 + 10 n] = #135 ...
// G54.4 Pn). Decided here (docs/probing-cycles.md): P is 0-7 (the sets of
// Mazak's G54.4 P1-P7; Fanuc's count is not in the pages read), a missing or
// other P is alarm bad_value, the data are read when G54.4 is, in program
// units and degrees; G54.4 under the plane rotation G68 is not simulated.
Flow<xform::Transform> Interpreter::Impl::setting_error(const Words& words,
                                                        const MillRequest& req) const {
  if (!words.has('P')) {
    return fail(AlarmId::kBadValue, "G54.4 without P (the setting error data set, 0-7)",
                req.frame_at);
  }
  const WordVal& p = words.at('P');
  if (p.value != std::trunc(p.value) || p.value < 0 || p.value > 7) {
    return fail(AlarmId::kBadValue,
                fmt::format("G54.4 P{}: the setting error data set is 0 to 7", p.value),
                loc(p.column));
  }
  if (frame().rotating) {
    return fail(AlarmId::kNotSimulated,
                "G54.4 in the plane rotation mode (G68) is not simulated by skipnc", req.frame_at);
  }
  xform::Spatial s = frame().spatial ? *frame().spatial : xform::Spatial{};
  const auto n = static_cast<std::size_t>(p.value);
  if (modal.cutter != CutterComp::kOff && n > 0) {
    return fail(AlarmId::kNotSimulated, "G54.4 in G41/G42 is not simulated by skipnc",
                req.frame_at);
  }
  s.setting_error = n > 0;
  auto error = [&](std::size_t i) {
    return setting_error_data[i].num() + setting_error_data[10 * n + i].num();
  };
  s.setting_shift = n > 0 ? xform::Point{error(0), error(1), error(2)} : xform::Point{};
  s.setting_turn =
      xform::turn_xyz(n > 0 ? error(3) : 0.0, n > 0 ? error(4) : 0.0, n > 0 ? error(5) : 0.0);
  return xform::with_spatial(frame(), s);
}

}  // namespace skipnc::interp
