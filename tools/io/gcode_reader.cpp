#include "tools/io/gcode_reader.h"

#include <istream>

#include "tools/io/gcode_block.h"
#include "tools/io/gcode_interpreter.h"

namespace scallop {

void readGcode(std::istream& in, const std::string& source, const PathFileOptions& options,
               ToolPathFile& out) {
  out.format = "gcode";
  out.arcTolerance = options.arcTolerance;
  GcodeInterpreter interpreter(source, options, out);
  std::string line;
  int64_t lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string where = source + ":" + std::to_string(lineNo);
    if (!interpreter.block(lexGcodeBlock(line, where, options.blockDelete), lineNo)) break;
  }
  interpreter.finish();
}

}  // namespace scallop
