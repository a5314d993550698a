// Programs that never end by themselves: for tests of what stops a run
// (signals, the processor-time limit, the trace-size limit).
#pragma once

namespace skipnc::test {

// Motion without end: back and forth until something stops it.
inline constexpr const char* kEndlessMotion =
    "WHILE [1 EQ 1] DO1\n"
    "G1 X100. F20000\n"
    "G1 X0\n"
    "END1\n";

// No motion: the interpreter alone is busy, for ever.
inline constexpr const char* kEndlessStatements =
    "WHILE [1 EQ 1] DO1\n"
    "#1=#1+1\n"
    "END1\n";

}  // namespace skipnc::test
