// The parameter numbers the code reads, named once. Numbers as on Fanuc
// (the parameter manuals B-63950EN / B-64490EN); each is defined, with its
// range and text, in data/dialects/*.toml, and a dialect that lacks one reads
// its default 0. The skip switches of each dialect (6200, 6280, 1174, ...)
// are not here: they are dialect data ([switches] in data/dialects/*.toml).
#pragma once

namespace skipnc::config::param {

// One bit of a bit-type parameter.
struct Bit {
  int number;
  int bit;
};

inline constexpr Bit kDiameterX{1006, 3};          // DIA: lathe X in diameter
inline constexpr Bit kLinearRapid{1401, 1};        // LRP: G00 as linear interpolation
inline constexpr Bit kCalculatorDecimal{3401, 0};  // DPI: a value without point in mm/inch/s
inline constexpr Bit kDwellRevolutions{3405, 1};   // DWL: G04 in spindle revolutions (per-rev feed)
inline constexpr int kArcRadiusTolerance = 3410;   // arc end point radius difference, mm
inline constexpr Bit kCompStartTypeB{5003, 0};     // SUP: cutter comp start-up / cancel type B
inline constexpr int kShiftDirection = 5101;       // #4 RD1, #5 RD2: G76 / G87 shift direction
inline constexpr Bit kRotationIncremental{5400, 0};  // RIN: G68 R follows G90/G91
inline constexpr Bit kScalingFine{5400, 7};          // SCR: G51 P in 0.00001
inline constexpr int kRotationAngle = 5410;          // G68 angle without R, 0.001 degree
inline constexpr int kMagnification = 5411;          // G51 magnification without P
inline constexpr Bit kSignedArcFunctions{6004, 0};   // NAT: ATAN -180..180, ASIN -90..90
inline constexpr int kG37Feed = 6241;                // G37 measurement feed, mm/min
inline constexpr int kG37Gamma = 6251;               // G37 approach ends gamma before, mm

// Skip input addresses set by parameters (seed 000): 3008#1 XSG signal area,
// 3008#2 addresses by parameter, 3012 their byte, 3020-3023 the bits of
// SKIP..SKIP4, 3025 the X byte of SKIP5..SKIP12.
inline constexpr int kSkipAddressing = 3008;
inline constexpr Bit kSkipAreaG{3008, 1};
inline constexpr Bit kSkipByParameters{3008, 2};
inline constexpr int kSkipByte = 3012;
inline constexpr int kSkipBitFirst = 3020;
inline constexpr int kSkipBitLast = 3023;
inline constexpr int kSkip5To12Byte = 3025;

}  // namespace skipnc::config::param
