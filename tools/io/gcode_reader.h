// G-code reader (.nc, .ngc, .gcode, .tap): the 3-axis subset of RS-274 that CAM
// post-processors write for milling, axis +Z throughout.
//
// Understood words (upper or lower case, spaces anywhere):
//   G0 rapid, G1 linear, G2/G3 arc clockwise/counter-clockwise (modal)
//   G17/G18/G19 arc plane XY/ZX/YZ; the third axis moves linearly (helix)
//   G20/G21 inches/mm, G90/G91 absolute/incremental X Y Z
//   X Y Z target; I J K arc centre, incremental from the start; R arc radius
//   (R < 0: the long way round); F feed, S spindle speed, N line number (read,
//   no effect); G40 G49 G80 G94 (cancel compensation/cycles, feed per minute: the
//   defaults) and M0-M5, M7-M9, M30 (stops, spindle, coolant) have no effect on the
//   geometry. Comments: ( ... ) and ; to the end of the line; '%' lines.
// Arcs are cut into chords whose distance from the arc (sagitta) is at most
// PathFileOptions::arcTolerance. Everything else is an error naming the line
// (InputError "file:line"): other G/M words or letters (tool changes, offsets, canned
// cycles, A/B/C axes), malformed or non-finite numbers, a word twice, an unclosed
// comment, a move before X, Y and Z are known, arcs whose start and end radii differ
// by more than 0.002 mm (or an R too small for the chord), and units switched after
// the first move (mixed units).
#pragma once

#include <iosfwd>
#include <string>

#include "tools/io/tool_path_file.h"

namespace scallop {

void readGcode(std::istream& in, const std::string& source, const PathFileOptions& options,
               ToolPathFile& out);

}  // namespace scallop
