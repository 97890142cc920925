// Canned drilling cycles of G-code (G73, G81-G86, G88, G89) as the moves a machine
// makes: the cycle layer of the G-code reader (tools/io/gcode_reader.h).
//
// One hole at (x, y), in the XY plane (G17), as LinuxCNC and Fanuc run it:
//   1. if the tool is below the R level, a rapid up to R;
//   2. a rapid in XY to the hole, then a rapid down to R;
//   3. the cycle's moves along Z (below); every feed is a cutting move, swept exactly;
//   4. the retract to the end level, the initial Z (G98, when above R) or R (G99).
// The Z moves of each cycle:
//   G81, G82 (dwell), G86 (spindle stop), G88 (manual retract): feed to Z, rapid out.
//   G85, G89 (dwell): feed to Z, feed back to R.  G84 (tapping): the same.
//   G73 (chip break): pecks of Q, each followed by a rapid up by kPeckClearance.
//   G83 (deep hole): pecks of Q, a rapid out to R after each, then down again to
//     kPeckClearance above the last depth. That way down runs inside the hole already
//     cut, so sweeping it changes no height; it is recorded as a cutting move so that
//     the crash check (rapids below the stock top, tool_path_file.h) does not flag it.
// G87 (back boring) is refused by the reader: it cuts from below.
#pragma once

#include <functional>

#include "base/vec3.h"

namespace scallop {

// The clearance of G73's chip-breaking retract and of G83's return into the hole, mm
// (LinuxCNC's 0.010 inch).
constexpr double kPeckClearance = 0.254;

struct DrillCycle {
  int code = 810;       // G code in tenths: 730, 810, ..., 890
  double clearZ = 0;    // the R level, mm (absolute)
  double bottomZ = 0;   // the hole bottom Z, mm (absolute), <= clearZ
  double retractZ = 0;  // the level the cycle ends at, mm, >= clearZ
  double peck = 0;      // Q, mm (> 0), for G73 and G83
};

// Emits the moves of one hole at (x, y) from `current` (the tool tip, mm) through
// moveTo(target, rapid), which also makes `target` the current point.
void drillHole(const DrillCycle& cycle, const Vec3& current, double x, double y,
               const std::function<void(const Vec3&, bool rapid)>& moveTo);

}  // namespace scallop
