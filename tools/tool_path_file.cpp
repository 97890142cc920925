#include "tools/tool_path_file.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "sweep/input_error.h"

namespace scallop {

ToolPath parseToolPath(const std::string& text, const std::string& source) {
  ToolPath path;
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  bool havePrevious = false, passBreak = false;
  Pose previous;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string where = source + ":" + std::to_string(lineNo);
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) {
      passBreak = havePrevious;
      continue;
    }
    if (line[first] == '#') continue;
    std::istringstream fields(line);
    double v[7];
    int n = 0;
    while (n < 7 && fields >> v[n]) ++n;
    if (!fields.eof() && n < 7) {
      throw InputError(where,
                       "expected numbers \"x y z\" or \"x y z i j k\", got \"" + line + "\"");
    }
    if (n != 3 && n != 6)
      throw InputError(where,
                       "expected 3 numbers (x y z) or 6 (x y z i j k), got " + std::to_string(n));
    for (int k = 0; k < n; ++k)
      if (!std::isfinite(v[k])) throw InputError(where, "coordinates must be finite numbers");
    Pose pose{{v[0], v[1], v[2]}, {0, 0, 1}};
    if (n == 6) {
      const Vec3 a{v[3], v[4], v[5]};
      if (length(a) < 1e-9) throw InputError(where, "the axis (i j k) must not be zero");
      pose.axis = normalize(a);
    }
    if (havePrevious) {
      Move mv{previous, pose, passBreak};
      path.moves.push_back(mv);
    }
    previous = pose;
    havePrevious = true;
    passBreak = false;
  }
  if (!havePrevious) throw InputError(source, "no cutter locations found");
  if (path.moves.empty())  // a single location: a stationary cut
    path.moves.push_back(Move{previous, previous, false});
  return path;
}

ToolPath readToolPathFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the tool-path file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseToolPath(text.str(), path);
}

}  // namespace scallop
