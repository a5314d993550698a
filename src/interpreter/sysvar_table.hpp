// The system variables of Custom Macro B, named once. Numbers as on Fanuc
// (the custom macro chapter, "system variables", of the Series 0i/30i
// operator's manuals; the Yaskawa LX3 manual of a Fanuc-compatible control
// prints the same numbers). read_var and write_var look a number up here and
// act on its Id; docs/macro.md is the table of what each gives, and a test
// checks that every range here is in it.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace skipnc::interp::sysvar {

enum class Id : std::uint8_t {
  kHWearShort,      // #2001-#2200 H wear, when the machine has <= 200 offsets
  kHGeomShort,      // #2201-#2400 H geometry, the same
  kWorkOffsetOld,   // #2500-#2806: X, Y, Z, 4th of EXT and G54-G59 (rows of 100)
  kAlarm,           // #3000 user alarm
  kClockMs,         // #3001 millisecond timer
  kClockHours,      // #3002 hour timer
  kControl,         // #3003-#3005 single block / feed hold / settings: kept
  kMessageStop,     // #3006 stop with message
  kMirror,          // #3007 mirror image state
  kDate,            // #3011 YYYYMMDD
  kTime,            // #3012 HHMMSS
  kPartsDone,       // #3901
  kPartsRequired,   // #3902
  kModalG,          // #4001-#4022 (#4201-#4222): G code of each modal group
  kModalB,          // #4102 (#4302)
  kModalD,          // #4107
  kModalE,          // #4108
  kModalF,          // #4109
  kModalH,          // #4111
  kModalM,          // #4113 last M
  kModalN,          // #4114 last sequence number
  kModalO,          // #4115 running program number
  kModalS,          // #4119
  kModalT,          // #4120
  kModalP,          // #4130 G54.1 P
  kBlockEnd,        // #5001-#5008 end point of the last block (work)
  kMachinePos,      // #5021-#5028 current position (machine)
  kWorkPos,         // #5041-#5048 current position (work)
  kSkipPos,         // #5061-#5068 skip position (work)
  kLengthOffset,    // #5081-#5088 active tool length offset
  kServoError,      // #5101-#5108 following error
  kWorkOffset,      // #5201-#5340: EXT, G54..G59, 20 per set
  kWorkOffsetP48,   // #7001-#7960: G54.1 P1-P48, 20 per set
  kHWear,           // #10001.. tool offset memory C
  kHGeom,           // #11001..
  kDWear,           // #12001..
  kDGeom,           // #13001..
  kWorkOffsetP300,  // #14001-#19980: G54.1 P1-P300, 20 per set
  kSettingError,    // #26000-#26079: G54.4 data No. 00-07, 10 per set
};

enum Access : std::uint8_t { kRead = 1, kWrite = 2, kReadWrite = 3 };

struct Range {
  Id id;
  int first;
  int last;
  std::uint8_t access;
  // Changes while the axes move: a read after queued motion waits for it
  // (buffer stop).
  bool live;
  // The same value is also at first + `alias` (#4201.. = #4001..: the
  // executing block's modal, the same here since blocks run one at a time).
  int alias = 0;
};

// Sorted by `first`, no overlaps (tests/unit/interpreter_sysvar_table_test.cpp).
inline constexpr Range kRanges[] = {
    {Id::kHWearShort, 2001, 2200, kReadWrite, false},
    {Id::kHGeomShort, 2201, 2400, kReadWrite, false},
    {Id::kWorkOffsetOld, 2500, 2506, kReadWrite, false},
    {Id::kWorkOffsetOld, 2600, 2606, kReadWrite, false},
    {Id::kWorkOffsetOld, 2700, 2706, kReadWrite, false},
    {Id::kWorkOffsetOld, 2800, 2806, kReadWrite, false},
    {Id::kAlarm, 3000, 3000, kReadWrite, false},
    {Id::kClockMs, 3001, 3001, kReadWrite, true},
    {Id::kClockHours, 3002, 3002, kReadWrite, true},
    {Id::kControl, 3003, 3005, kReadWrite, false},
    {Id::kMessageStop, 3006, 3006, kReadWrite, false},
    {Id::kMirror, 3007, 3007, kRead, false},
    {Id::kDate, 3011, 3011, kRead, false},
    {Id::kTime, 3012, 3012, kRead, false},
    {Id::kPartsDone, 3901, 3901, kReadWrite, false},
    {Id::kPartsRequired, 3902, 3902, kReadWrite, false},
    {Id::kModalG, 4001, 4022, kRead, false, 200},
    {Id::kModalB, 4102, 4102, kRead, false, 200},
    {Id::kModalD, 4107, 4107, kRead, false, 200},
    {Id::kModalE, 4108, 4108, kRead, false, 200},
    {Id::kModalF, 4109, 4109, kRead, false, 200},
    {Id::kModalH, 4111, 4111, kRead, false, 200},
    {Id::kModalM, 4113, 4113, kRead, false, 200},
    {Id::kModalN, 4114, 4114, kRead, false, 200},
    {Id::kModalO, 4115, 4115, kRead, false, 200},
    {Id::kModalS, 4119, 4119, kRead, false, 200},
    {Id::kModalT, 4120, 4120, kRead, false, 200},
    {Id::kModalP, 4130, 4130, kRead, false, 200},
    {Id::kBlockEnd, 5001, 5008, kRead, false},
    {Id::kMachinePos, 5021, 5028, kRead, true},
    {Id::kWorkPos, 5041, 5048, kRead, true},
    {Id::kSkipPos, 5061, 5068, kRead, false},
    {Id::kLengthOffset, 5081, 5088, kRead, false},
    {Id::kServoError, 5101, 5108, kRead, true},
    {Id::kWorkOffset, 5201, 5340, kReadWrite, false},
    {Id::kWorkOffsetP48, 7001, 7960, kReadWrite, false},
    {Id::kHWear, 10001, 10999, kReadWrite, false},
    {Id::kHGeom, 11001, 11999, kReadWrite, false},
    {Id::kDWear, 12001, 12999, kReadWrite, false},
    {Id::kDGeom, 13001, 13999, kReadWrite, false},
    {Id::kWorkOffsetP300, 14001, 19980, kReadWrite, false},
    {Id::kSettingError, 26000, 26079, kReadWrite, false},
};

// The older work-offset numbering: #2500 + 100 (axis - 1) + set.
inline constexpr int kWorkOffsetOldAxis1 = 2500;

// The letters of a work offset's variables when a dialect numbers them by
// letter (offset_variables_by = "letter", Haas): #5221 X .. #5225 B as
// 96-8000 lists them, #5226 C as Autodesk's Haas post writes it. No source
// read names a seventh (U V W): those slots name no axis.
inline constexpr std::string_view kOffsetSlotLetters = "XYZABC";

// The machine axis (0-based, in the machine's order) that slot `slot`
// (0-based) of a work offset names: the slot-th axis of `axis_count` (by
// position) or the axis with the slot-th letter above (by letter), which
// `axis_of(letter)` finds (-1: none); -1 when the machine has no such axis.
template <class AxisOf>
constexpr int offset_slot_axis(bool by_letter, int axis_count, int slot, AxisOf axis_of) noexcept {
  if (slot < 0) return -1;
  if (!by_letter) return slot < axis_count ? slot : -1;
  if (slot >= static_cast<int>(kOffsetSlotLetters.size())) return -1;
  return axis_of(kOffsetSlotLetters[static_cast<std::size_t>(slot)]);
}

// Blocks of numbers that are the control's own, written or not: a write to
// a number in one that no range above allows is "write protected" (116),
// not "no such variable" (115).
struct Block {
  int first;
  int last;
};
inline constexpr Block kProtected[] = {{3000, 3999}, {4001, 4330}, {5001, 5108}};

// The range that holds `n` (an alias counts), nullptr when none. `number`
// is set to the number within the range (the alias resolved).
const Range* find(int n, int& number) noexcept;

inline bool is_protected(int n) noexcept {
  for (const Block& b : kProtected) {
    if (n >= b.first && n <= b.last) return true;
  }
  return false;
}

// Fanuc 30i system variable names (#_NAME, #_NAME[i]) and their numbers
// (the same manuals' table of names).
struct Name {
  std::string_view name;
  int number;  // the variable, or the base of [i] (number + i)
  int count;   // 0: no index; else i = 1..count
};

inline constexpr Name kNames[] = {
    {"_ALM", 3000, 0},    {"_CLOCK1", 3001, 0}, {"_CLOCK2", 3002, 0}, {"_MSGSTP", 3006, 0},
    {"_DATE", 3011, 0},   {"_TIME", 3012, 0},   {"_PRTSA", 3901, 0},  {"_PRTSN", 3902, 0},
    {"_ABSIO", 5000, 8},  {"_ABSMT", 5020, 8},  {"_ABSOT", 5040, 8},  {"_ABSKP", 5060, 8},
    {"_TOFSWZ", 5080, 8}, {"_SRVO", 5100, 8},   {"_WZCMN", 5200, 20}, {"_WZG54", 5220, 20},
    {"_WZG55", 5240, 20}, {"_WZG56", 5260, 20}, {"_WZG57", 5280, 20}, {"_WZG58", 5300, 20},
    {"_WZG59", 5320, 20},
};

}  // namespace skipnc::interp::sysvar
