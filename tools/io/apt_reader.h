// APT / CL data reader (.cl, .apt, .cls): the cutter-location statements CAM systems
// write for post-processors.
//
// Statements are MAJOR/arg,arg,... ; "$$" starts a comment, a line ending in "$"
// continues on the next one, upper or lower case alike. Understood:
//   GOTO/x,y,z          linear move to tip (x, y, z), axis unchanged (+Z at first)
//   GOTO/x,y,z,i,j,k    the same with tool axis (i, j, k) (5-axis, normalised)
//   FROM/x,y,z[,i,j,k]  start location, no move
//   RAPID               the next GOTO is a rapid (not cut)
//   CUTTER/d[,r]        diameter d and corner radius r: r = 0 flat, r = d/2 ball, else
//                       bull; also the 7-value form d,r,e,f,a,b,h of a torus end mill
//                       (e = d/2 - r, f = r, a = b = 0; h = flute length)
//   UNITS/MM, UNITS/INCHES   lengths in inches are converted to mm
//   MULTAX[/ON|OFF], FEDRAT, PARTNO, PPRINT, SPINDL, COOLNT, CLPRNT, FINI, END
//                       accepted, no effect on the geometry
// Any other statement is ignored with a warning naming its line. Errors (InputError
// "file:line"): malformed numbers, wrong argument counts, a zero axis, a continuation
// at the end of the file, a unit change after the first move, a second CUTTER/ that
// differs from the first.
#pragma once

#include <iosfwd>
#include <string>

#include "tools/io/tool_path_file.h"

namespace scallop {

void readApt(std::istream& in, const std::string& source, ToolPathFile& out);

}  // namespace scallop
