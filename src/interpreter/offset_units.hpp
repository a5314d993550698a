// The unit of the stored offsets (docs/time-and-units.md, "Units of stored
// values"). The Fanuc family keeps the numbers of the work offsets
// (G54-G59, EXT, G54.1) and of the tool offsets (H, D) as they were set, in
// the input unit in force: "The unit systems for the following values are
// changed after inch/metric conversion: ... Workpiece origin offset value,
// Tool compensation value" (FANUC Series 30i/31i/32i-MODEL A common user's
// manual, B-63944EN/02, 8.2 "Inch/metric conversion (G20, G21)"; NCT 2000M
// manual 5.3: "The change of the unit will affect ... Coordinate and
// compensation data"). So 10.000 set under G21 is 10 inches after G20: the
// offsets are not converted. LinuxCNC and grbl keep lengths (machine units,
// mm) and convert what a program writes or reads.
#pragma once

namespace skipnc::interp {

// mm per stored unit of a work or tool offset: the input unit in force (Fanuc
// family) or 1 (stored in mm: LinuxCNC, grbl). `S` is the interpreter state.
template <class S>
double offset_unit_mm(const S& s) noexcept {
  return s.lang->rules.offsets_in_mm ? 1.0 : s.unit_mm();
}

}  // namespace skipnc::interp
