#include "tools/io/job.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "raycast/stock_map.h"
#include "tools/io/file_names.h"
#include "tools/io/gcode_block.h"
#include "tools/io/height_export.h"
#include "tools/io/job_cutters.h"
#include "tools/io/job_fields.h"
#include "tools/io/stl_io.h"
#include "tools/io/tool_path_file.h"

namespace scallop {

using nlohmann::json;
using namespace jobfield;

namespace {

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

// "work_offsets": {"G54": [x, y, z], ..., "G59": [...]}.
std::array<Vec3, 6> parseWorkOffsets(const json& offsets) {
  std::array<Vec3, 6> out{};
  rejectUnknownKeys(offsets, {"G54", "G55", "G56", "G57", "G58", "G59"}, "work_offsets");
  for (int k = 0; k < 6; ++k) {
    const std::string key = "G5" + std::to_string(4 + k);
    if (offsets.contains(key)) out[size_t(k)] = point(offsets, key, "work_offsets." + key);
  }
  return out;
}

// A list of G or M codes, e.g. ["G43.4", "M128"], in canonical text (gcodeWordText).
std::vector<std::string> parseCodes(const json& m, const std::string& key,
                                    const std::vector<std::string>& fallback) {
  const std::string f = "machine." + key;
  if (!m.contains(key)) return fallback;
  const json& v = m.at(key);
  if (!v.is_array()) throw InputError(f, "expected a list of G or M codes, e.g. [\"G43.4\"]");
  std::vector<std::string> out;
  for (const json& c : v) {
    const std::string s = c.is_string() ? c.get<std::string>() : "";
    double value = 0;
    if (s.size() < 2 || (s[0] != 'G' && s[0] != 'M') || !parseDecimal(s.substr(1), value) ||
        gcodeTenths(value) < 0)
      throw InputError(f, "expected codes such as \"G43.4\" or \"M128\", got " + c.dump());
    out.push_back(gcodeWordText(s[0], value));
  }
  return out;
}

MachineSpec parseMachine(const json& m) {
  rejectUnknownKeys(m, {"kinematics", "tcp_on", "tcp_off", "pivot", "offset"}, "machine");
  MachineSpec spec;
  const std::string kin = text(m, "kinematics", "machine.kinematics");
  if (kin == "xyzbc-trt")
    spec.geometry.kinematics = RotaryKinematics::TableBC;
  else if (kin == "xyzac-trt")
    spec.geometry.kinematics = RotaryKinematics::TableAC;
  else
    throw InputError("machine.kinematics",
                     "expected \"xyzbc-trt\" or \"xyzac-trt\", got \"" + kin + "\"");
  spec.tcpOn = parseCodes(m, "tcp_on", spec.tcpOn);
  spec.tcpOff = parseCodes(m, "tcp_off", spec.tcpOff);
  for (const std::string& c : spec.tcpOn)
    if (std::find(spec.tcpOff.begin(), spec.tcpOff.end(), c) != spec.tcpOff.end())
      throw InputError("machine.tcp_off", c + " is also in tcp_on");
  if (m.contains("pivot")) spec.geometry.pivot = point(m, "pivot", "machine.pivot");
  if (m.contains("offset")) spec.geometry.offset = point(m, "offset", "machine.offset");
  return spec;
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

// "grid.frame": {"origin", "u", "normal", "size": [wu, wv], "depth"} (CONVENTIONS.md
// "Frames").
GridFrame parseFrame(const json& f) {
  rejectUnknownKeys(f, {"origin", "u", "normal", "size", "depth"}, "grid.frame");
  const Vec3 origin = point(f, "origin", "grid.frame.origin");
  const Vec3 u = point(f, "u", "grid.frame.u");
  const Vec3 normal = point(f, "normal", "grid.frame.normal");
  if (!f.contains("size")) throw InputError("grid.frame.size", "missing; expected [wu, wv] (mm)");
  const json& size = f.at("size");
  if (!size.is_array() || size.size() != 2 || !size[0].is_number() || !size[1].is_number())
    throw InputError("grid.frame.size", "expected [wu, wv], two numbers (mm)");
  const double wu = size[0].get<double>(), wv = size[1].get<double>();
  if (!(wu > 0 && wv > 0 && wu <= kMaxMagnitudeMm && wv <= kMaxMagnitudeMm))
    throw InputError("grid.frame.size",
                     "must be > 0 and at most 1e6 mm along u and v, got " + size.dump());
  double depth = HUGE_VAL;  // the whole line
  if (f.contains("depth")) {
    depth = number(f, "depth", "grid.frame.depth");
    if (depth < 0) throw InputError("grid.frame.depth", "must be >= 0 mm");
  }
  return makeGridFrame(origin, u, normal, wu, wv, depth, "grid.frame");
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

PathFileOptions Job::pathOptions() const {
  PathFileOptions o;
  o.blockDelete = blockDelete;
  o.arcChords = arcChords;
  o.workOffsets = workOffsets;
  o.tools = tools;
  o.machine = machine;
  o.teeth = cutting.teeth();
  o.flutes = cutter.teeth.flutes;
  // In a frame the axes are judged in its coordinates, once the path is moved there.
  o.axesFromAbove = !frame;
  return o;
}

GridSpec Job::grid() const {
  if (frame) return frame->grid(spacing);
  return gridCovering(stock.min.x, stock.min.y, stock.max.x, stock.max.y, spacing);
}

void Job::fillStockHeights(ZMap& map) const {
  if (stockSolid) stockSolid->fillHeights(map);
  if (stockMap) fillFromHeightMap(map, *stockMap);
}

double Job::stockTop() const {
  return frame ? stockTopInFrame(stock, *frame) : stock.max.z;
}

void checkPathMagnitudes(const ToolPath& path, const std::vector<int64_t>& lines,
                         const std::string& file) {
  auto far = [](const Vec3& p) {
    return std::fmax(std::fabs(p.x), std::fmax(std::fabs(p.y), std::fabs(p.z))) > kMaxMagnitudeMm;
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

Job parseJob(const std::string& textIn, const std::string& source,
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
    rejectUnknownKeys(doc,
                      {"tool", "tools", "cutting", "stock", "grid", "path", "design",
                       "work_offsets", "block_delete", "arc_chords", "machine", "spindle"},
                      "");
    Job job;
    job.source = source;
    // Without "tool" the path file's CUTTER/ statement defines it (below).
    job.hasTool = doc.contains("tool");
    if (job.hasTool) job.cutter = parseCutter(requireObject(doc, "tool", "tool"), "tool");
    if (doc.contains("tools")) {
      if (job.hasTool) throw InputError("tools", "a job has \"tool\" or \"tools\", not both");
      job.tools = parseTools(requireObject(doc, "tools", "tools"));
      // The largest cutter stands for all in summaries and estimates (job.h).
      job.cutter = job.tools.begin()->second;
      for (const auto& [number, cutter] : job.tools)
        if (cutter.radius + cutter.fluteLength > job.cutter.radius + job.cutter.fluteLength)
          job.cutter = cutter;
    }
    if (doc.contains("cutting"))
      job.cutting = parseCuttingModel(requireObject(doc, "cutting", "cutting"));
    job.cutting.counterClockwise = parseSpindle(doc);
    if (doc.contains("work_offsets"))
      job.workOffsets = parseWorkOffsets(requireObject(doc, "work_offsets", "work_offsets"));
    job.blockDelete = boolean(doc, "block_delete", "block_delete", false);
    job.arcChords = boolean(doc, "arc_chords", "arc_chords", false);
    if (doc.contains("machine"))
      job.machine = parseMachine(requireObject(doc, "machine", "machine"));
    namespace fs = std::filesystem;
    auto besideJob = [&](const std::string& file) {
      fs::path p(file);
      if (p.is_relative() && source.find('/') != std::string::npos)
        p = fs::path(source).parent_path() / p;
      return p.string();
    };

    const json& stock = requireObject(doc, "stock", "stock");
    if (stock.contains("stl")) {
      rejectUnknownKeys(stock, {"stl"}, "stock");
      job.stockStlFile = besideJob(text(stock, "stl", "stock.stl"));
      job.stockSolid = readStockSolid(job.stockStlFile);
      job.stock = job.stockSolid->bounds();
    } else if (stock.contains("gsf")) {
      rejectUnknownKeys(stock, {"gsf", "min", "max"}, "stock");
      job.stockGsfFile = besideJob(text(stock, "gsf", "stock.gsf"));
      job.stockMap = readStockMap(job.stockGsfFile);
      job.stock = stockMapBox(*job.stockMap, stock);
    } else {
      rejectUnknownKeys(stock, {"min", "max"}, "stock");
      job.stock.extend(point(stock, "min", "stock.min"));
      const Vec3 mx = point(stock, "max", "stock.max");
      if (!(mx.x > job.stock.min.x && mx.y > job.stock.min.y && mx.z > job.stock.min.z))
        throw InputError("stock.max", "must be greater than stock.min in x, y and z");
      job.stock.extend(mx);
    }

    const json& grid = requireObject(doc, "grid", "grid");
    rejectUnknownKeys(grid, {"spacing", "frame"}, "grid");
    job.spacing = number(grid, "spacing", "grid.spacing");
    if (job.spacing <= 0) throw InputError("grid.spacing", "must be > 0 mm");
    if (grid.contains("frame")) job.frame = parseFrame(requireObject(grid, "frame", "grid.frame"));
    const double nx =
        std::ceil((job.frame ? job.frame->sizeU : job.stock.max.x - job.stock.min.x) / job.spacing);
    const double ny =
        std::ceil((job.frame ? job.frame->sizeV : job.stock.max.y - job.stock.min.y) / job.spacing);
    if (nx * ny > 9e15) throw InputError("grid.spacing", "gives more cells than can be counted");

    if (doc.contains("design")) {
      const json& design = requireObject(doc, "design", "design");
      rejectUnknownKeys(
          design,
          {"stl", "gouge_tolerance", "normal_deviation", "gouge_depth", "scallop_limit", "view"},
          "design");
      job.designFile = besideJob(text(design, "stl", "design.stl"));
      job.gougeTolerance =
          number(design, "gouge_tolerance", "design.gouge_tolerance", &job.gougeTolerance);
      if (job.gougeTolerance < 0) throw InputError("design.gouge_tolerance", "must be >= 0 mm");
      job.normalDeviation = boolean(design, "normal_deviation", "design.normal_deviation", false);
      job.gougeDepth = number(design, "gouge_depth", "design.gouge_depth", &job.gougeDepth);
      if (!(job.gougeDepth > 0))
        throw InputError("design.gouge_depth",
                         "must be > 0 mm (how far below the design surface a cut still counts)");
      if (design.contains("scallop_limit")) {
        job.scallopLimit = number(design, "scallop_limit", "design.scallop_limit");
        if (!(job.scallopLimit > 0))
          throw InputError("design.scallop_limit",
                           "must be > 0 mm (the deviation above which material left counts)");
        if (!job.normalDeviation)
          throw InputError("design.scallop_limit", "goes with \"normal_deviation\": true");
      }
      if (design.contains("view")) {
        const json& view = requireObject(design, "view", "design.view");
        rejectUnknownKeys(view,
                          {"azimuth_deg", "elevation_deg", "light_azimuth_deg",
                           "light_elevation_deg", "projection"},
                          "design.view");
        job.viewAzimuthDeg =
            number(view, "azimuth_deg", "design.view.azimuth_deg", &job.viewAzimuthDeg);
        job.viewElevationDeg =
            number(view, "elevation_deg", "design.view.elevation_deg", &job.viewElevationDeg);
        if (!(std::fabs(job.viewAzimuthDeg) <= 360))
          throw InputError("design.view.azimuth_deg", "must be within [-360, 360] degrees");
        if (!(std::fabs(job.viewElevationDeg) <= 90))
          throw InputError("design.view.elevation_deg", "must be within [-90, 90] degrees");
        // The light as `scallop render`'s: azimuth clockwise from +y, elevation above
        // the horizon; both or neither.
        if (view.contains("light_azimuth_deg") != view.contains("light_elevation_deg"))
          throw InputError("design.view",
                           "give light_azimuth_deg and light_elevation_deg "
                           "together (or neither: the light at the viewer's "
                           "shoulder)");
        if (view.contains("light_azimuth_deg")) {
          job.viewLightAzimuthDeg =
              number(view, "light_azimuth_deg", "design.view.light_azimuth_deg", nullptr);
          job.viewLightElevationDeg =
              number(view, "light_elevation_deg", "design.view.light_elevation_deg", nullptr);
          if (!(std::fabs(job.viewLightAzimuthDeg) <= 360))
            throw InputError("design.view.light_azimuth_deg", "must be within [-360, 360] degrees");
          if (!(job.viewLightElevationDeg > 0 && job.viewLightElevationDeg <= 90))
            throw InputError("design.view.light_elevation_deg", "must be within (0, 90] degrees");
        }
        if (view.contains("projection")) {
          const json& p = view["projection"];
          if (!p.is_string() || (p != "ortho" && p != "perspective"))
            throw InputError("design.view.projection", "expected \"ortho\" or \"perspective\"");
          job.viewPerspective = p == "perspective";
        }
        if (!job.normalDeviation)
          throw InputError("design.view", "goes with \"normal_deviation\": true");
      }
    }

    const json pathDoc =
        pathOverride.empty() ? requireObject(doc, "path", "path") : json{{"file", pathOverride}};
    const json& path = pathDoc;
    rejectUnknownKeys(path, {"raster", "file"}, "path");
    if (path.contains("raster") == path.contains("file"))
      throw InputError("path", "expected exactly one of \"raster\" or \"file\"");
    if (path.contains("raster") && !doc.contains("tool"))
      throw InputError("tool", doc.contains("tools") ? "a raster needs one \"tool\", not \"tools\""
                                                     : "missing; expected an object");
    if (path.contains("raster")) {
      job.isRaster = true;
      job.raster = parseRaster(requireObject(path, "raster", "path.raster"));
    } else {
      const std::string file = text(path, "file", "path.file");
      // --path names a file from the working directory, a job's file is beside the job.
      job.pathFile = pathOverride.empty() ? besideJob(file) : file;
    }
    return job;
  } catch (const InputError& e) {
    throwFromJob(e, source);
  }
}

std::shared_ptr<const ZMap> readStockMap(const std::string& path) {
  if (lowerExtension(path) != ".gsf")
    throw InputError("stock.gsf", path + ": expected a .gsf height map (a previous run's)");
  try {
    return std::make_shared<const ZMap>(readHeightFile(path));
  } catch (const InputError& e) {
    throw InputError("stock.gsf", e.what());
  }
}

Box3 stockMapBox(const ZMap& map, const nlohmann::json& stock) {
  const GridSpec& g = map.grid();
  Box3 box;
  double low = HUGE_VAL, high = -HUGE_VAL;
  for (double h : map.heights())
    if (!std::isnan(h)) low = std::min(low, h), high = std::max(high, h);
  if (!(low <= high)) throw InputError("stock.gsf", "holds no material (every cell is void)");
  const double x1 = g.originX + double(g.nx) * g.spacing, y1 = g.originY + double(g.ny) * g.spacing;
  if (!stock.contains("min") && !stock.contains("max")) {
    box.extend({g.originX, g.originY, low});
    box.extend({x1, y1, high});
    return box;
  }
  const Vec3 mn = point(stock, "min", "stock.min"), mx = point(stock, "max", "stock.max");
  if (!(mx.x > mn.x && mx.y > mn.y))
    throw InputError("stock.max", "must be greater than stock.min in x and y");
  if (mn.x < g.originX || mn.y < g.originY || mx.x > x1 || mx.y > y1)
    throw InputError("stock.gsf",
                     fmt::format("its grid [{:g}, {:g}] x [{:g}, {:g}] mm does not cover the "
                                 "job's grid [{:g}, {:g}] x [{:g}, {:g}] mm (stock.min, stock.max)",
                                 g.originX, x1, g.originY, y1, mn.x, mx.x, mn.y, mx.y));
  box.extend({mn.x, mn.y, low});
  box.extend({mx.x, mx.y, high});
  return box;
}

std::shared_ptr<const StockSolid> readStockSolid(const std::string& path) {
  TriangleMesh mesh;
  try {
    mesh = readStl(path);
  } catch (const InputError& e) {
    throw InputError("stock.stl", e.what());
  }
  checkClosedSolid(mesh, "stock.stl (" + path + ")");
  return std::make_shared<const StockSolid>(std::move(mesh));
}

void throwFromJob(const InputError& e, const std::string& source) {
  // Lead every field error with the file it came from.
  if (e.where().rfind(source, 0) == 0) throw e;
  throw InputError(source + ": " + e.where(), e.reason());
}

json jobToJson(const Job& job) {
  json out = {{"stock",
               {{"min", {job.stock.min.x, job.stock.min.y, job.stock.min.z}},
                {"max", {job.stock.max.x, job.stock.max.y, job.stock.max.z}}}},
              {"grid", {{"spacing", job.spacing}}}};
  if (job.stockSolid) out["stock"]["stl"] = job.stockStlFile;
  if (job.stockMap) out["stock"]["gsf"] = job.stockGsfFile;
  if (job.frame) {
    const GridFrame& f = *job.frame;
    auto vec = [](const Vec3& p) { return json{p.x, p.y, p.z}; };
    json frame = {{"origin", vec(f.origin)},
                  {"u", vec(f.u)},
                  {"normal", vec(f.normal)},
                  {"v", vec(f.v)},
                  {"size", {f.sizeU, f.sizeV}}};
    if (std::isfinite(f.depth)) frame["depth"] = f.depth;
    out["grid"]["frame"] = frame;
  }
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
  if (job.tools.empty()) {
    out["tool"] = cutterToJson(job.cutter);
  } else {
    json tools = json::object();
    for (const auto& [number, cutter] : job.tools)
      tools[std::to_string(number)] = cutterToJson(cutter);
    out["tools"] = tools;
  }
  out["cutting"] = cuttingModelToJson(job.cutting);
  if (job.cutting.counterClockwise) out["spindle"] = "ccw";
  if (job.design) {
    out["design"] = {{"stl", job.designFile}, {"gouge_tolerance", job.gougeTolerance}};
    if (job.normalDeviation)
      out["design"].update({{"normal_deviation", true}, {"gouge_depth", job.gougeDepth}});
    if (!std::isnan(job.scallopLimit)) out["design"]["scallop_limit"] = job.scallopLimit;
    if (job.normalDeviation) {
      out["design"]["view"] = {{"azimuth_deg", job.viewAzimuthDeg},
                               {"elevation_deg", job.viewElevationDeg}};
      if (!std::isnan(job.viewLightAzimuthDeg))
        out["design"]["view"].update({{"light_azimuth_deg", job.viewLightAzimuthDeg},
                                      {"light_elevation_deg", job.viewLightElevationDeg}});
      if (job.viewPerspective) out["design"]["view"]["projection"] = "perspective";
    }
  }
  json offsets = json::object();
  for (int k = 0; k < 6; ++k) {
    const Vec3& o = job.workOffsets[size_t(k)];
    if (o != Vec3{}) offsets["G5" + std::to_string(4 + k)] = {o.x, o.y, o.z};
  }
  if (!offsets.empty()) out["work_offsets"] = offsets;
  if (job.blockDelete) out["block_delete"] = true;
  if (job.arcChords) out["arc_chords"] = true;
  if (job.machine) {
    const TableMachine& g = job.machine->geometry;
    out["machine"] = {
        {"kinematics", g.kinematics == RotaryKinematics::TableBC ? "xyzbc-trt" : "xyzac-trt"},
        {"tcp_on", job.machine->tcpOn},
        {"tcp_off", job.machine->tcpOff},
        {"pivot", {g.pivot.x, g.pivot.y, g.pivot.z}},
        {"offset", {g.offset.x, g.offset.y, g.offset.z}}};
  }
  return out;
}

}  // namespace scallop
