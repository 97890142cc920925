#include "tools/job.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "sweep/input_error.h"
#include "tools/tool_path_file.h"

namespace scallop {

using nlohmann::json;

namespace {

// --- Strict field access: every message names the field and what it should be. ----

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
  return d;
}

Vec3 point(const json& obj, const std::string& key, const std::string& field) {
  if (!obj.contains(key)) throw InputError(field, "missing; expected [x, y, z] in mm");
  const json& v = obj.at(key);
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    throw InputError(field, "expected [x, y, z] (three numbers, mm), got " + v.dump());
  const Vec3 p{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  if (!isFinite(p)) throw InputError(field, "coordinates must be finite");
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

void checkGridFitsMemory(const GridSpec& grid, const std::string& field) {
  // Heights are held in double, plus one float32 row buffer per image while writing.
  const double cells = double(grid.nx) * double(grid.ny);
  const double need = cells * (sizeof(double) + sizeof(float));
  double available = 0;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kb = 0;
  std::string unit;
  while (meminfo >> key >> kb >> unit)
    if (key == "MemAvailable:") available = kb * 1024;
  if (available <= 0) available = 8.0 * (1ull << 30);
  if (need > 0.8 * available) {
    std::ostringstream msg;
    msg.precision(3);
    msg << "a " << grid.nx << " x " << grid.ny << " grid needs " << need / double(1ull << 30)
        << " GiB of memory, but only " << available / double(1ull << 30)
        << " GiB are available; use a larger spacing or a smaller stock";
    throw InputError(field, msg.str());
  }
}

Job parseJob(const std::string& textIn, const std::string& source, bool checkMemory) {
  json doc;
  try {
    doc = json::parse(textIn);
  } catch (const json::parse_error& e) {
    std::string reason = e.what();
    const size_t colon = reason.find("]: ");
    const size_t pos = reason.find(": ", colon == std::string::npos ? 0 : colon + 3);
    if (pos != std::string::npos) reason = reason.substr(pos + 2);
    throw InputError(source + ":" + lineColumn(textIn, e.byte), "malformed JSON: " + reason);
  }
  if (!doc.is_object()) throw InputError(source, "expected a JSON object at the top level");

  try {
    rejectUnknownKeys(doc, {"tool", "stock", "grid", "path", "sweep"}, "");
    Job job;
    job.source = source;
    job.cutter = parseTool(requireObject(doc, "tool", "tool"));

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

    if (doc.contains("sweep")) {
      const json& sweep = requireObject(doc, "sweep", "sweep");
      rejectUnknownKeys(sweep, {"axis_tolerance"}, "sweep");
      job.axisTolerance = number(sweep, "axis_tolerance", "sweep.axis_tolerance");
      if (job.axisTolerance <= 0) throw InputError("sweep.axis_tolerance", "must be > 0 mm");
    }

    const json& path = requireObject(doc, "path", "path");
    rejectUnknownKeys(path, {"raster", "file"}, "path");
    if (path.contains("raster") == path.contains("file"))
      throw InputError("path", "expected exactly one of \"raster\" or \"file\"");
    if (path.contains("raster")) {
      job.isRaster = true;
      job.raster = parseRaster(requireObject(path, "raster", "path.raster"));
      job.path = makeRaster(job.cutter, job.stock, job.raster);
    } else {
      const std::string file = text(path, "file", "path.file");
      namespace fs = std::filesystem;
      fs::path p(file);
      if (p.is_relative() && source.find('/') != std::string::npos)
        p = fs::path(source).parent_path() / p;
      job.pathFile = p.string();
      job.path = readToolPathFile(job.pathFile);
    }
    return job;
  } catch (const InputError& e) {
    // Lead every field error with the file it came from.
    if (e.where().rfind(source, 0) == 0) throw;
    throw InputError(source + ": " + e.where(), std::string(e.what()).substr(e.where().size() + 2));
  }
}

Job loadJobFile(const std::string& path, bool checkMemory) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the job file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseJob(text.str(), path, checkMemory);
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
              {"grid", {{"spacing", job.spacing}}},
              {"sweep", {{"axis_tolerance", job.axisTolerance}}}};
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
    out["path"] = {{"file", job.pathFile}};
  }
  return out;
}

}  // namespace scallop
