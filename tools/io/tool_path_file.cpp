#include "tools/io/tool_path_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/available_memory.h"
#include "base/input_error.h"
#include "sweep/swept_segment.h"
#include "tools/io/apt_reader.h"
#include "tools/io/file_names.h"
#include "tools/io/gcode_reader.h"

namespace scallop {

void PathWarnings::add(const std::string& where, const std::string& what) {
  if (kept.size() < kMaxKept) kept.push_back(where + ": " + what);
  ++total;
}

void IgnoredWords::add(const std::string& word, const std::string& meaning, int64_t line) {
  auto it =
      std::find_if(entries.begin(), entries.end(), [&](const Entry& e) { return e.word == word; });
  if (it == entries.end()) it = entries.insert(entries.end(), Entry{word, meaning, 0, {}});
  ++it->count;
  if (it->lines.size() < kMaxLines && (it->lines.empty() || it->lines.back() != line))
    it->lines.push_back(line);
}

void ToolPathFile::addMove(const Pose& from, const Pose& to, bool rapid, int64_t line) {
  constexpr size_t kCheckedFrom = size_t(1) << 20;  // moves; /proc is read once a doubling
  const size_t n = path.moves.size();
  if (n == path.moves.capacity() && (n >= kCheckedFrom || memoryBytes > 0)) {
    const double perMove = double(sizeof(Move) + sizeof(int64_t));
    const double grown = 3 * double(std::max<size_t>(n, 1)) * perMove;  // old + new arrays
    const double available = memoryBytes > 0 ? memoryBytes : availableMemoryBytes();
    if (grown > 0.8 * available)
      throw InputError(
          fmt::format("{}:{}", source, line),
          fmt::format("the program's moves do not fit in memory: {} moves read so far take "
                      "{:.3g} GiB, and holding them as they grow needs {:.3g} GiB of the {:.3g} "
                      "GiB available; split the program into several jobs",
                      n, double(n) * perMove / double(1ull << 30), grown / double(1ull << 30),
                      available / double(1ull << 30)));
  }
  if (takePart && n >= partMoves) handOverPart();
  if (filter && n > 0) filter->judgeLast(path, moveLines);  // the last move is complete
  path.moves.push_back(Move{from, to, rapid});
  moveLines.push_back(line);
}

void ToolPathFile::handOverPart() {
  if (path.moves.empty()) return;
  takePart(path);
  movesHandedOver += path.moves.size();
  path.moves.clear();
  moveLines.clear();
}

bool parseDecimal(const std::string& token, double& value) {
  // [+-] digits [. digits] [e [+-] digits], at least one digit in the mantissa.
  size_t k = 0;
  const size_t n = token.size();
  if (k < n && (token[k] == '+' || token[k] == '-')) ++k;
  size_t digits = 0;
  while (k < n && std::isdigit(static_cast<unsigned char>(token[k]))) ++k, ++digits;
  if (k < n && token[k] == '.') {
    ++k;
    while (k < n && std::isdigit(static_cast<unsigned char>(token[k]))) ++k, ++digits;
  }
  if (digits == 0) return false;
  if (k < n && (token[k] == 'e' || token[k] == 'E')) {
    ++k;
    if (k < n && (token[k] == '+' || token[k] == '-')) ++k;
    size_t expDigits = 0;
    while (k < n && std::isdigit(static_cast<unsigned char>(token[k]))) ++k, ++expDigits;
    if (expDigits == 0) return false;
  }
  if (k != n) return false;
  // std::from_chars rounds correctly, as strtod does (the same double), without the
  // locale and at several times the speed; it takes no '+'.
  const char* first = token.data() + (token[0] == '+' ? 1 : 0);
  const auto [end, error] = std::from_chars(first, token.data() + n, value);
  if (error == std::errc::result_out_of_range)  // beyond double, or below: strtod's answer
    value = std::strtod(token.c_str(), nullptr);
  else if (end != token.data() + n)
    return false;
  return std::isfinite(value);  // overflow to inf is not a coordinate
}

Vec3 fileAxis(const Vec3& axis, const std::string& where, bool fromAbove) {
  const double len = length(axis);
  if (!(len >= 1e-9) || !std::isfinite(len))
    throw InputError(where, "the tool axis (i j k) must be a non-zero vector");
  // A z-map holds the lowest point of the cut seen from above; a cutter whose shank
  // points downwards cuts from below, which no height map can show.
  if (fromAbove && axis.z < 0)
    throw InputError(where, "the tool axis (i j k) points below the horizontal (k = " +
                                std::to_string(axis.z / len) +
                                "): a height map seen from above cannot show what it cuts; "
                                "scallop needs k >= 0");
  return std::fabs(len - 1) <= 1e-12 ? axis : axis / len;
}

void readClText(std::istream& in, const std::string& source, ToolPathFile& out,
                bool axesFromAbove) {
  out.format = "cl-text";
  std::string line;
  int64_t lineNo = 0, previousLine = 0;
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
    std::string token;
    double v[6];
    int n = 0;
    while (fields >> token) {
      if (n == 6)
        throw InputError(where, "expected 3 numbers (x y z) or 6 (x y z i j k), got more");
      if (!parseDecimal(token, v[n]))
        throw InputError(where, "expected a finite decimal number, got \"" + token + "\"");
      ++n;
    }
    if (n != 3 && n != 6)
      throw InputError(where,
                       "expected 3 numbers (x y z) or 6 (x y z i j k), got " + std::to_string(n));
    Pose pose{{v[0], v[1], v[2]}, {0, 0, 1}};
    if (n == 6) {
      pose.axis = fileAxis({v[3], v[4], v[5]}, where, axesFromAbove);
    }
    if (havePrevious) out.addMove(previous, pose, passBreak, lineNo);
    previous = pose;
    previousLine = lineNo;
    havePrevious = true;
    passBreak = false;
  }
  if (!havePrevious) throw InputError(source, "no cutter locations found");
  if (out.path.moves.empty())  // a single location: a stationary cut
    out.addMove(previous, previous, false, previousLine);
}

ToolPath parseToolPath(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  ToolPathFile file;
  readClText(in, source, file);
  return std::move(file.path);
}

namespace {

// A ".cl" file holding plain "x y z" lines (OpenCAMLib's habit) rather than APT: its
// first line that is neither blank nor a comment starts with a number.
bool looksLikeClText(std::istream& in) {
  std::string line;
  bool numeric = false;
  while (std::getline(in, line)) {
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#' || line.compare(first, 2, "$$") == 0)
      continue;
    const char c = line[first];
    numeric = std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
    break;
  }
  in.clear();
  in.seekg(0);
  return numeric;
}

// Distance from the xy segment [a, b] to the axis-aligned rectangle [lo, hi].
double segmentToBoxXY(const Vec3& a, const Vec3& b, const Vec3& lo, const Vec3& hi) {
  auto inside = [&](double x, double y) {
    return x >= lo.x && x <= hi.x && y >= lo.y && y <= hi.y;
  };
  auto pointToSeg = [](double px, double py, const Vec3& p, const Vec3& q) {
    const double dx = q.x - p.x, dy = q.y - p.y, l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((px - p.x) * dx + (py - p.y) * dy) / l2, 0.0, 1.0) : 0;
    return std::hypot(px - p.x - t * dx, py - p.y - t * dy);
  };
  if (inside(a.x, a.y) || inside(b.x, b.y)) return 0;
  auto pointToBox = [&](double x, double y) {
    return std::hypot(std::max({lo.x - x, 0.0, x - hi.x}), std::max({lo.y - y, 0.0, y - hi.y}));
  };
  double d = std::min(pointToBox(a.x, a.y), pointToBox(b.x, b.y));
  const Vec3 corners[4] = {{lo.x, lo.y, 0}, {hi.x, lo.y, 0}, {hi.x, hi.y, 0}, {lo.x, hi.y, 0}};
  for (const Vec3& c : corners) d = std::min(d, pointToSeg(c.x, c.y, a, b));
  // The segment may cross the box with both ends outside: then it meets an edge.
  // (Touching or collinear cases have a corner on the segment: distance 0 above.)
  for (int e = 0; e < 4 && d > 0; ++e) {
    const Vec3 &p = corners[e], &q = corners[(e + 1) % 4];
    auto side = [](const Vec3& o, const Vec3& u, const Vec3& v) {
      return (u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x);
    };
    if (side(a, b, p) * side(a, b, q) < 0 && side(p, q, a) * side(p, q, b) < 0) d = 0;
  }
  return d;
}

}  // namespace

void warnRapidsIntoStock(ToolPathFile& file, const Cutter& jobCutter, const Box3& stock,
                         const std::string& source, const StockSolid* solid,
                         const std::string& stockName) {
  const Vec3 down{0, 0, -1};
  for (size_t k = 0; k < file.path.moves.size(); ++k) {
    const Move& mv = file.path.moves[k];
    if (!mv.rapid) continue;
    // A multi-tool program's rapids carry the tool in the spindle (Move::tool).
    const Cutter& cutter =
        mv.tool < file.path.cutters.size() ? file.path.cutters[mv.tool] : jobCutter;
    // A retract straight up the tool axis only enters the space above the cutter's
    // current place, which CAM systems leave free; it is not flagged.
    const Vec3 d = mv.to.tip - mv.from.tip;
    if (mv.from.axis == mv.to.axis && d.z > 0 && length(cross(d, mv.from.axis)) <= 1e-12 * d.z)
      continue;
    // Lowest point below the tip; on a slerp between two axes the tilt never exceeds
    // the larger end tilt (a cap of the sphere is geodesically convex), so the lower
    // end offset bounds every intermediate axis.
    const double offset = std::min(cutterSupport(cutter, normalize(mv.from.axis), down).z,
                                   cutterSupport(cutter, normalize(mv.to.axis), down).z);
    const double z0 = mv.from.tip.z + offset, z1 = mv.to.tip.z + offset;
    const double top = stock.max.z;
    if (z0 >= top && z1 >= top) continue;
    // The part of the move where the lowest point is below the top: [t0, t1].
    double t0 = 0, t1 = 1;
    if (z0 >= top) t0 = (z0 - top) / (z0 - z1);
    if (z1 >= top) t1 = (top - z0) / (z1 - z0);
    const Vec3 a = mv.from.tip + (mv.to.tip - mv.from.tip) * t0;
    const Vec3 b = mv.from.tip + (mv.to.tip - mv.from.tip) * t1;
    // Horizontal reach of the cutter from its tip: R, plus the flute's lean when tilted.
    auto lean = [](const Vec3& axis) { return std::hypot(axis.x, axis.y) / length(axis); };
    const double reach =
        cutter.radius + cutter.fluteLength * std::max(lean(mv.from.axis), lean(mv.to.axis));
    if (segmentToBoxXY(a, b, stock.min, stock.max) >= reach) continue;
    const double lowest = std::min(z0, z1);
    const Vec3 lowTip = z0 <= z1 ? mv.from.tip : mv.to.tip;
    // What the check knows: the stock as it started, not what earlier moves left.
    const char* initial =
        "judged against the stock as it started, not the material earlier moves left: a crash "
        "on the machine unless they removed it";
    std::string what;
    if (solid) {
      Vec3 met;
      if (!solid->reachesAbove(a, b, reach, lowest, &met)) continue;
      what = fmt::format(
          "rapid move cuts {}: the solid rises to z = {:g} mm at (x, y) = ({:g}, {:g}) mm within "
          "the cutter's reach of the move, {:g} mm above the cutter's lowest point (z = {:g} mm); {}",
          stockName, met.z, met.x, met.y, met.z - lowest, lowest, initial);
    } else {
      what = fmt::format(
          "rapid move cuts {}: the cutter's lowest point, z = {:g} mm with the tip at (x, y) = "
          "({:g}, {:g}) mm, is {:g} mm below its top z = {:g} mm within the cutter's reach of "
          "it; {}",
          stockName, lowest, lowTip.x, lowTip.y, top - lowest, top, initial);
    }
    file.warnings.add(source + ":" + std::to_string(file.moveLines[k]), what);
  }
}

namespace {

void readInto(const std::string& path, const PathFileOptions& options, ToolPathFile& file) {
  const auto start = std::chrono::steady_clock::now();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the tool-path file");
  const std::string ext = lowerExtension(path);
  file.source = path;
  file.memoryBytes = options.memoryBytes;
  if (options.window && !file.takePart) file.filter = std::make_shared<MoveWindowFilter>(*options.window);
  if (ext == ".txt" || (ext == ".cl" && looksLikeClText(in))) {
    readClText(in, path, file, options.axesFromAbove);
  } else if (ext == ".cl" || ext == ".apt" || ext == ".cls") {
    readApt(in, path, options, file);
  } else if (ext == ".nc" || ext == ".ngc" || ext == ".gcode" || ext == ".tap") {
    readGcode(in, path, options, file);
  } else {
    throw InputError(path, "unknown tool-path file extension \"" + ext +
                               "\"; expected .cl, .apt, .cls (APT CL data), .nc, .ngc, "
                               ".gcode, .tap (G-code) or .txt (x y z [i j k] per line)");
  }
  if (in.bad()) throw InputError(path, "read error");
  file.movesRead = file.path.moves.size();
  if (file.filter) {
    file.filter->finish(file.path, file.moveLines);
    file.movesRead = file.filter->movesRead();
    file.toolMoves = file.filter->toolMoves();
    file.filter.reset();
  }
  in.clear();
  in.seekg(0, std::ios::end);
  file.fileBytes = double(in.tellg());
  file.readSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ToolPathFile readToolPathFile(const std::string& path, const PathFileOptions& options) {
  ToolPathFile file;
  readInto(path, options, file);
  return file;
}

ToolPathFile streamToolPathFile(const std::string& path, const PathFileOptions& options,
                                size_t partMoves, const std::function<void(ToolPath&)>& takePart) {
  ToolPathFile file;
  file.takePart = takePart;
  file.partMoves = std::max<size_t>(partMoves, 1);
  readInto(path, options, file);
  file.handOverPart();
  return file;
}

}  // namespace scallop
