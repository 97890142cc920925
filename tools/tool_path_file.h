// Tool-path files: cutter locations as text, one per line.
//
//   # comment lines start with '#'
//   x y z            tip position, axis +Z (3-axis), mm
//   x y z i j k      tip position and tool axis (normalised on reading)
//   (blank line)     ends a pass: the move to the next location is a rapid
//
// Consecutive locations are joined by linear cutting moves. This is the format of
// OpenCAMLib-style drop-cutter output (e.g. shared/data/mount_rush/*.cl.txt).
#pragma once

#include <string>

#include "sweep/pose.h"

namespace scallop {

// Throws InputError naming "file:line" and what was expected.
ToolPath readToolPathFile(const std::string& path);
ToolPath parseToolPath(const std::string& text, const std::string& source);

}  // namespace scallop
