// docs/codes.md: every G and M code per dialect and machine type, with what
// skipnc does with it. The status of each code is not written by hand: each
// code is run through the interpreter, one small program per code, dialect
// and machine, and classified by what happened (see codes.cpp). A test
// compares the page with docs/codes.md, so the page cannot drift.
#pragma once

#include <string>
#include <vector>

#include "core/diag.hpp"

namespace skipnc::interp {

enum class CodeStatus : std::uint8_t {
  kSimulated,     // runs and has its effect
  kNoEffect,      // accepted, changes nothing in the simulation
  kNotSimulated,  // alarm not_simulated: a real code skipnc does not model
  kImproper,      // alarm unknown_g_code: not a code of this machine or control
};

// The status of one G code (x10: G54.1 = 541) on a built-in machine
// ("mill3", "lathe2") under a dialect, found by running it.
[[nodiscard]] Result<CodeStatus> g_code_status(int code, const std::string& machine,
                                               const std::string& dialect);

// True for the G codes that are accepted without effect (mill_codes.cpp).
bool g_code_without_effect(int code) noexcept;

// The whole page (Markdown).
[[nodiscard]] Result<std::string> codes_markdown();

}  // namespace skipnc::interp
