#include "tools/io/job.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <vector>

#include "raycast/simulation.h"
#include "sweep/input_error.h"
#include "tools/io/stl_io.h"
#include "tools/io/tool_path_file.h"

namespace scallop {

using nlohmann::json;

namespace {

// --- Strict field access: every message names the field and what it should be. ----

// Every number of a job is a length in mm, an angle in degrees or a tolerance: none is
// meaningful beyond 1 km, and bounding them keeps squares and products (and the
// float32 heights written) far from overflow, where a wrong map would be silent.
constexpr double kMaxMagnitude = 1e6;

// Rejects an object holding the same key twice (JSON allows it, nlohmann keeps the
// last silently), naming the field path, e.g. "grid.spacing: duplicate key".
struct OpenObjects {
  std::vector<std::pair<std::string, std::set<std::string>>> stack;  // field path, keys seen
  std::string lastKey;
};

json::parser_callback_t duplicateKeyCheck(OpenObjects& open) {
  return [&open](int /*depth*/, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) {
      const std::string parent = open.stack.empty() ? "" : open.stack.back().first;
      open.stack.push_back({parent.empty() ? open.lastKey : parent + "." + open.lastKey, {}});
      open.lastKey.clear();
    } else if (event == json::parse_event_t::object_end) {
      if (!open.stack.empty()) open.stack.pop_back();
    } else if (event == json::parse_event_t::key && !open.stack.empty()) {
      open.lastKey = parsed.get<std::string>();
      if (!open.stack.back().second.insert(open.lastKey).second) {
        const std::string& obj = open.stack.back().first;
        throw InputError(obj.empty() ? open.lastKey : obj + "." + open.lastKey,
                         "duplicate key; each key may appear once per object");
      }
    } else if (event == json::parse_event_t::array_start) {
      open.lastKey += "[]";
    }
    return true;
  };
}

const json& requireObject(const json& parent, const std::string& key, const std::string& field) {
  if (!parent.contains(key)) throw InputError(field, "missing; expected an object");
  const json& v = parent.at(key);
  if (!v.is_object()) throw InputError(field, "expected an object, got " + v.dump());
  return v;
}

void rejectUnknownKeys(const json& obj, const std::set<std::string>& known,
                       const std::string& field) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    if (known.count(it.key())) continue;
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    throw InputError(field.empty() ? it.key() : field + "." + it.key(),
                     "unknown key; expected one of: " + list);
  }
}

double number(const json& obj, const std::string& key, const std::string& field,
              const double* fallback = nullptr) {
  if (!obj.contains(key)) {
    if (fallback) return *fallback;
    throw InputError(field, "missing; expected a number");
  }
  const json& v = obj.at(key);
  if (!v.is_number()) throw InputError(field, "expected a number, got " + v.dump());
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw InputError(field, "expected a finite number");
  if (std::fabs(d) > kMaxMagnitude)
    throw InputError(field, "must be within +-1e6 (mm: 1 km), got " + v.dump());
  return d;
}

Vec3 point(const json& obj, const std::string& key, const std::string& field) {
  if (!obj.contains(key)) throw InputError(field, "missing; expected [x, y, z] in mm");
  const json& v = obj.at(key);
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    throw InputError(field, "expected [x, y, z] (three numbers, mm), got " + v.dump());
  const Vec3 p{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  if (!isFinite(p)) throw InputError(field, "coordinates must be finite");
  if (std::fmax(std::fabs(p.x), std::fmax(std::fabs(p.y), std::fabs(p.z))) > kMaxMagnitude)
    throw InputError(field, "coordinates must be within +-1e6 mm (1 km), got " + v.dump());
  return p;
}

std::string text(const json& obj, const std::string& key, const std::string& field) {
  if (!obj.contains(key)) throw InputError(field, "missing; expected a string");
  const json& v = obj.at(key);
  if (!v.is_string()) throw InputError(field, "expected a string, got " + v.dump());
  return v.get<std::string>();
}

bool boolean(const json& obj, const std::string& key, const std::string& field, bool fallback) {
  if (!obj.contains(key)) return fallback;
  const json& v = obj.at(key);
  if (!v.is_boolean()) throw InputError(field, "expected true or false, got " + v.dump());
  return v.get<bool>();
}

// --- The sections of a job file. -------------------------------------------------

Cutter parseTool(const json& tool) {
  rejectUnknownKeys(tool, {"type", "radius", "corner_radius", "flute_length"}, "tool");
  const CutterType type = parseCutterType(text(tool, "type", "tool.type"), "tool.type");
  const double zero = 0;
  const double radius = number(tool, "radius", "tool.radius");
  double corner = 0;
  if (type == CutterType::Bull) {
    corner = number(tool, "corner_radius", "tool.corner_radius");
  } else if (tool.contains("corner_radius")) {
    throw InputError("tool.corner_radius",
                     std::string("only a bull cutter takes a corner radius (a ") + toString(type) +
                         " cutter's is fixed)");
  }
  const double flute = number(tool, "flute_length", "tool.flute_length", &zero);
  if (tool.contains("flute_length") && flute <= 0)
    throw InputError("tool.flute_length", "must be > 0 mm");
  return Cutter::make(type, radius, corner, flute, "tool");
}

RasterSpec parseRaster(const json& r) {
  const std::string f = "path.raster.";
  rejectUnknownKeys(
      r, {"direction", "step_over", "depth", "lead_deg", "tilt_deg", "zigzag", "segment_length"},
      "path.raster");
  RasterSpec spec;
  const std::string dir = text(r, "direction", f + "direction");
  if (dir != "x" && dir != "y")
    throw InputError(f + "direction", "expected \"x\" or \"y\", got \"" + dir + "\"");
  spec.direction = dir[0];
  const double zero = 0;
  spec.stepOver = number(r, "step_over", f + "step_over");
  spec.depth = number(r, "depth", f + "depth");
  spec.leadDeg = number(r, "lead_deg", f + "lead_deg", &zero);
  spec.tiltDeg = number(r, "tilt_deg", f + "tilt_deg", &zero);
  spec.zigzag = boolean(r, "zigzag", f + "zigzag", false);
  spec.segmentLength = number(r, "segment_length", f + "segment_length", &zero);
  return spec;
}

// makeRaster holds every move (up to its own limit of 5e7): refuse, before generating
// it, a raster whose moves alone would not fit in memory. Counts as sweep/raster.cpp
// does; invalid values are left to makeRaster's messages.
void checkRasterFitsMemory(const Job& job) {
  const RasterSpec& r = job.raster;
  if (!(r.stepOver > 0) || !(r.segmentLength >= 0)) return;
  const bool alongX = r.direction == 'x';
  const double cross =
      alongX ? job.stock.max.y - job.stock.min.y : job.stock.max.x - job.stock.min.x;
  const double feed =
      (alongX ? job.stock.max.x - job.stock.min.x : job.stock.max.y - job.stock.min.y) +
      2 * job.cutter.radius + 2;
  const double passes = std::floor(cross / r.stepOver + 1e-9) + 1;
  const double moves = passes * (r.segmentLength > 0 ? std::ceil(feed / r.segmentLength) + 1 : 2);
  const double need = moves * double(sizeof(Move));
  const double available = availableMemoryBytes();
  if (need > 0.8 * available) {
    std::ostringstream msg;
    msg << "gives " << moves << " moves, which need " << std::setprecision(15) << need
        << " bytes of memory, but only " << std::fixed << std::setprecision(1)
        << available / double(1ull << 30) << " GiB are available";
    throw InputError(r.segmentLength > 0 ? "path.raster.segment_length" : "path.raster.step_over",
                     msg.str());
  }
}

// The position of a byte offset as "line L, column C" for malformed-JSON messages.
std::string lineColumn(const std::string& s, size_t byte) {
  size_t line = 1, col = 1;
  for (size_t k = 0; k + 1 < byte && k < s.size(); ++k) {
    if (s[k] == '\n')
      ++line, col = 1;
    else
      ++col;
  }
  return std::to_string(line) + ":" + std::to_string(col);
}

}  // namespace

const char* defaultJobJson() {
  return R"({
  "tool":  {"type": "bull", "radius": 3.0, "corner_radius": 1.0},
  "stock": {"min": [0, 0, -5], "max": [20, 20, 0]},
  "grid":  {"spacing": 0.01},
  "path":  {"raster": {"direction": "x", "step_over": 2.884, "depth": 0.5,
                       "lead_deg": 5, "tilt_deg": 0, "zigzag": false}}
})";
}

GridSpec Job::grid() const {
  return gridCovering(stock.min.x, stock.min.y, stock.max.x, stock.max.y, spacing);
}

void checkPathMagnitudes(const ToolPath& path, const std::vector<int64_t>& lines,
                         const std::string& file) {
  auto far = [](const Vec3& p) {
    return std::fmax(std::fabs(p.x), std::fmax(std::fabs(p.y), std::fabs(p.z))) > kMaxMagnitude;
  };
  for (size_t k = 0; k < path.moves.size(); ++k) {
    const Move& m = path.moves[k];
    if (!far(m.from.tip) && !far(m.to.tip)) continue;
    const Vec3& p = far(m.to.tip) ? m.to.tip : m.from.tip;
    std::ostringstream msg;
    msg << "the tip position (" << p.x << ", " << p.y << ", " << p.z
        << ") is beyond +-1e6 mm (1 km) from the origin";
    throw InputError(k < lines.size() ? file + ":" + std::to_string(lines[k]) : file, msg.str());
  }
}

double availableMemoryBytes() {
  double available = 0;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kb = 0;
  std::string unit;
  while (meminfo >> key >> kb >> unit)
    if (key == "MemAvailable:") available = kb * 1024;
  return available > 0 ? available : 8.0 * (1ull << 30);
}

void checkSceneFitsMemory(const Job& job) {
  // The scene's own estimate (raycast/simulation.h), made from the moves before anything
  // is built: it errs high, never low, so what it accepts is never killed for memory.
  size_t moves = 0;
  const double need = estimateSceneBytes(job.cutter, job.path, job.stock.max.z, &moves);
  const double available = availableMemoryBytes();
  if (need > 0.8 * available) {
    std::ostringstream msg;
    msg << "the exact simulation of " << moves << " cutting moves needs about "
        << std::setprecision(need < 1e15 ? 15 : 3) << need << " bytes (" << std::fixed
        << std::setprecision(1) << need / double(1ull << 30)
        << " GiB) of memory for its culling scene, but only " << available / double(1ull << 30)
        << " GiB are available; split the path into several jobs (--tiled bounds only the "
           "height map's memory, not the scene's)";
    throw InputError(job.source + ": path", msg.str());
  }
}

void checkGridFitsMemory(const GridSpec& grid, const std::string& field) {
  // Heights are held in double, plus one float32 row buffer per image while writing.
  const double cells = double(grid.nx) * double(grid.ny);
  const double need = cells * (sizeof(double) + sizeof(float));
  const double available = availableMemoryBytes();
  if (need > 0.8 * available) {
    std::ostringstream msg;
    msg.precision(3);
    msg << "a " << grid.nx << " x " << grid.ny << " grid needs " << need / double(1ull << 30)
        << " GiB (" << std::fixed << std::setprecision(0) << need << " bytes) of memory, but only "
        << std::defaultfloat << std::setprecision(3) << available / double(1ull << 30)
        << " GiB are available; use a larger spacing, a smaller stock, or --method exact with "
           "--tiled (bands of rows, bounded memory)";
    throw InputError(field, msg.str());
  }
}

Job parseJob(const std::string& textIn, const std::string& source, bool checkMemory,
             const std::string& pathOverride) {
  json doc;
  OpenObjects openObjects;
  try {
    doc = json::parse(textIn, duplicateKeyCheck(openObjects));
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.where(), e.reason());
  } catch (const json::out_of_range& e) {  // a number beyond double, e.g. 1e400
    std::string reason = e.what();
    reason = reason.substr(reason.find(']') + 2);
    throw InputError(source, "malformed JSON: " + reason);
  } catch (const json::parse_error& e) {
    std::string reason = e.what();
    const size_t colon = reason.find("]: ");
    const size_t pos = reason.find(": ", colon == std::string::npos ? 0 : colon + 3);
    if (pos != std::string::npos) reason = reason.substr(pos + 2);
    throw InputError(source + ":" + lineColumn(textIn, e.byte), "malformed JSON: " + reason);
  }
  if (!doc.is_object()) throw InputError(source, "expected a JSON object at the top level");

  try {
    // "sweep": {"axis_tolerance"} cut turning moves into constant-axis pieces before
    // they were swept exactly; a job that still sets it is told so rather than
    // silently given a different meaning.
    if (doc.contains("sweep"))
      throw InputError("sweep.axis_tolerance",
                       "is no longer used: moves whose axis turns are swept exactly, with no "
                       "tolerance; remove \"sweep\" from the job");
    rejectUnknownKeys(doc, {"tool", "stock", "grid", "path", "design"}, "");
    Job job;
    job.source = source;
    // Without "tool" the path file's CUTTER/ statement defines it (below).
    if (doc.contains("tool")) job.cutter = parseTool(requireObject(doc, "tool", "tool"));
    namespace fs = std::filesystem;
    auto besideJob = [&](const std::string& file) {
      fs::path p(file);
      if (p.is_relative() && source.find('/') != std::string::npos)
        p = fs::path(source).parent_path() / p;
      return p.string();
    };

    const json& stock = requireObject(doc, "stock", "stock");
    rejectUnknownKeys(stock, {"min", "max"}, "stock");
    job.stock.extend(point(stock, "min", "stock.min"));
    const Vec3 mx = point(stock, "max", "stock.max");
    if (!(mx.x > job.stock.min.x && mx.y > job.stock.min.y && mx.z > job.stock.min.z))
      throw InputError("stock.max", "must be greater than stock.min in x, y and z");
    job.stock.extend(mx);

    const json& grid = requireObject(doc, "grid", "grid");
    rejectUnknownKeys(grid, {"spacing"}, "grid");
    job.spacing = number(grid, "spacing", "grid.spacing");
    if (job.spacing <= 0) throw InputError("grid.spacing", "must be > 0 mm");
    const double nx = std::ceil((job.stock.max.x - job.stock.min.x) / job.spacing);
    const double ny = std::ceil((job.stock.max.y - job.stock.min.y) / job.spacing);
    if (nx * ny > 9e15) throw InputError("grid.spacing", "gives more cells than can be counted");
    if (checkMemory) checkGridFitsMemory(job.grid(), "grid.spacing");

    if (doc.contains("design")) {
      const json& design = requireObject(doc, "design", "design");
      rejectUnknownKeys(design, {"stl", "gouge_tolerance"}, "design");
      job.designFile = besideJob(text(design, "stl", "design.stl"));
      job.gougeTolerance =
          number(design, "gouge_tolerance", "design.gouge_tolerance", &job.gougeTolerance);
      if (job.gougeTolerance < 0) throw InputError("design.gouge_tolerance", "must be >= 0 mm");
      job.design = std::make_shared<const TriangleMesh>(readStl(job.designFile));
    }

    const json pathDoc =
        pathOverride.empty() ? requireObject(doc, "path", "path") : json{{"file", pathOverride}};
    const json& path = pathDoc;
    rejectUnknownKeys(path, {"raster", "file"}, "path");
    if (path.contains("raster") == path.contains("file"))
      throw InputError("path", "expected exactly one of \"raster\" or \"file\"");
    if (path.contains("raster") && !doc.contains("tool"))
      throw InputError("tool", "missing; expected an object");
    if (path.contains("raster")) {
      job.isRaster = true;
      job.raster = parseRaster(requireObject(path, "raster", "path.raster"));
      checkRasterFitsMemory(job);
      job.path = makeRaster(job.cutter, job.stock, job.raster);
    } else {
      const std::string file = text(path, "file", "path.file");
      // --path names a file from the working directory, a job's file is beside the job.
      job.pathFile = pathOverride.empty() ? besideJob(file) : file;
      ToolPathFile read = readToolPathFile(job.pathFile);
      if (!doc.contains("tool") && !read.cutter)
        throw InputError(
            "tool", "missing; expected an object (or a CUTTER/ statement in " + job.pathFile + ")");
      if (!doc.contains("tool")) job.cutter = *read.cutter;
      if (doc.contains("tool") && read.cutter &&
          (read.cutter->type != job.cutter.type || read.cutter->radius != job.cutter.radius ||
           read.cutter->cornerRadius != job.cutter.cornerRadius))
        read.warnings.add(job.pathFile,
                          "its CUTTER/ differs from the job's \"tool\"; the job's "
                          "tool is used");
      checkPathMagnitudes(read.path, read.moveLines, job.pathFile);
      warnRapidsIntoStock(read, job.cutter, job.stock, job.pathFile);
      job.path = std::move(read.path);
      job.moveLines = std::move(read.moveLines);
      job.pathWarnings = std::move(read.warnings);
      job.pathFormat = read.format;
    }
    return job;
  } catch (const InputError& e) {
    // Lead every field error with the file it came from.
    if (e.where().rfind(source, 0) == 0) throw;
    throw InputError(source + ": " + e.where(), e.reason());
  }
}

Job loadJobFile(const std::string& path, bool checkMemory, const std::string& pathOverride) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, "is a folder, expected a job file (JSON)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the job file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseJob(text.str(), path, checkMemory, pathOverride);
}

json jobToJson(const Job& job) {
  json tool = {{"type", toString(job.cutter.type)},
               {"radius", job.cutter.radius},
               {"corner_radius", job.cutter.cornerRadius},
               {"flute_length", job.cutter.fluteLength}};
  json out = {{"tool", tool},
              {"stock",
               {{"min", {job.stock.min.x, job.stock.min.y, job.stock.min.z}},
                {"max", {job.stock.max.x, job.stock.max.y, job.stock.max.z}}}},
              {"grid", {{"spacing", job.spacing}}}};
  if (job.isRaster) {
    const RasterSpec& r = job.raster;
    out["path"] = {{"raster",
                    {{"direction", std::string(1, r.direction)},
                     {"step_over", r.stepOver},
                     {"depth", r.depth},
                     {"lead_deg", r.leadDeg},
                     {"tilt_deg", r.tiltDeg},
                     {"zigzag", r.zigzag},
                     {"segment_length", r.segmentLength}}}};
  } else {
    out["path"] = {{"file", job.pathFile}, {"format", job.pathFormat}};
  }
  if (job.design)
    out["design"] = {{"stl", job.designFile}, {"gouge_tolerance", job.gougeTolerance}};
  return out;
}

}  // namespace scallop
