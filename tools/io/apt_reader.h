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
//   LOADTL/n            tool change: with the job's "tools" (PathFileOptions::tools) the
//                       moves after it cut with tool n (not in tools: an error naming
//                       the line); without, it only numbers the CUTTER/ that follows
//   MULTAX[/ON|OFF], FEDRAT, PARTNO, PPRINT, SPINDL, COOLNT, CLPRNT, FINI, END
//                       accepted, no effect on the geometry
// Tool changes: without the job's "tools", a CUTTER/ that differs from the one before
// is a new tool for the moves after it (path.cutters, Move::tool; the moves before the
// first CUTTER/ cut with it); a file of one cutter leaves path.cutters empty and
// `cutter` set. With "tools", LOADTL/n picks the cutter and CUTTER/ only describes it.
// Any other statement is ignored with a warning naming its line. Errors (InputError
// "file:line"): malformed numbers, wrong argument counts, a zero axis, a continuation
// at the end of the file, a unit change after the first move, a LOADTL/ number missing
// from the job's tools, a GOTO with several tools and none loaded.
#pragma once

#include <iosfwd>
#include <string>

#include "tools/io/tool_path_file.h"

namespace scallop {

void readApt(std::istream& in, const std::string& source, const PathFileOptions& options,
             ToolPathFile& out);
void readApt(std::istream& in, const std::string& source, ToolPathFile& out);

}  // namespace scallop
