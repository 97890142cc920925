// The words of one G-code block sorted into their modal groups (the groups of
// RS274/NGC and LinuxCNC: motion, plane, units, distance, ...), with the words scallop
// refuses named by line: the step between the lexer (gcode_block.h) and the
// interpreter (gcode_interpreter.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "tools/io/gcode_block.h"
#include "tools/io/tool_path_file.h"

namespace scallop {

// The words of one block by modal group, in tenths (-1: none in the block).
struct GcodeGroups {
  int motion = -1, plane = -1, units = -1, distance = -1, arcDistance = -1, feed = -1;
  int compensation = -1, length = -1, offset = -1, pathMode = -1, retract = -1, nonModal = -1;
  int tcp = -1;                      // 1: a tcp_on code, 0: a tcp_off code
  bool end = false, change = false;  // M2/M30, M6
  // M words that change no geometry, (word, meaning), and machine-specific M codes.
  std::vector<std::pair<std::string, std::string>> ignored;
  std::vector<std::string> unknownM;
};

// Sorts the G and M words of `b`; `machine` (may be null) gives the TCP codes, which
// take precedence. Throws InputError(where) for two words of one group and for the
// words scallop refuses (G41/G42, G87, G10/G52/G92, M98/M99, other G words).
GcodeGroups groupGcodeWords(const GcodeBlock& b, const MachineSpec* machine,
                            const std::string& where);

}  // namespace scallop
