// Job: what `scallop simulate` runs, read from a JSON job file (CONVENTIONS.md "Job
// file"). Parsing is strict: unknown keys, missing keys and wrong types are errors that
// name the file, the line (for malformed JSON) or the field, and what was expected.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/stock_solid.h"
#include "analysis/triangle_mesh.h"
#include "base/vec3.h"
#include "raycast/grid_frame.h"
#include "raycast/zmap.h"
#include "sweep/cutter.h"
#include "sweep/cutting_model.h"
#include "sweep/pose.h"
#include "sweep/raster.h"
#include "tools/io/tool_path_file.h"

namespace scallop {

class InputError;

struct Job {
  std::string source;    // file name, or "built-in default job"
  bool hasTool = false;  // "tool" was given; otherwise the path file's CUTTER/ is the tool
  // The one cutter, or with "tools" (or an APT file of several CUTTER/s) the one of
  // largest radius: what single-cutter summaries and memory estimates use (they err
  // high). The moves' own cutters are path.cutters.
  Cutter cutter;
  // "tools": {"1": {cutter}, ...}: T number -> cutter (CONVENTIONS.md "Tools").
  std::map<int64_t, Cutter> tools;
  // "cutting": the envelope (default) or the teeth model (docs/teeth.md).
  CuttingModel cutting;
  // "work_offsets": {"G54": [x, y, z], ...}: G-code work offsets, mm (zero by default).
  std::array<Vec3, 6> workOffsets{};
  // "block_delete": true skips G-code lines starting with '/'.
  bool blockDelete = false;
  // G-code arcs as chords within 1e-4 mm (the --arc-chords baseline), not exact moves.
  bool arcChords = false;
  // "machine": a 5-axis machine for G-code rotary words (CONVENTIONS.md "Machines").
  std::optional<MachineSpec> machine;
  // "stock": a box {"min", "max"}, {"gsf": FILE} or {"stl": FILE} a closed solid (CONVENTIONS.md
  // "Stock"): then `stock` is the solid's bounding box (the grid's extent) and the
  // heights start from `stockSolid`.
  Box3 stock;
  std::string stockStlFile;                      // resolved; empty for a box
  std::shared_ptr<const StockSolid> stockSolid;  // read while parsing
  // "stock": {"gsf": FILE}: the material under a previous run's heights (void cells
  // none); `stock` is then its grid's rectangle (or the job's "min", "max" within it)
  // from its lowest to its highest height.
  std::string stockGsfFile;              // resolved; empty otherwise
  std::shared_ptr<const ZMap> stockMap;  // read while parsing
  double spacing = 0;                    // grid cell side, mm
  // "grid": {"frame": {...}}: a map along any direction (CONVENTIONS.md "Frames"). Once
  // loaded (tools/run/job_loader.h), `path` is in the frame's coordinates.
  std::optional<GridFrame> frame;
  bool isRaster = false;
  RasterSpec raster;     // when isRaster
  std::string pathFile;  // when not: the tool-path file, resolved to a path
  ToolPath path;         // built from either by loadJobInputs (tools/run/job_loader.h)
  // From a path file: its format, the file line of each move and the warnings
  // (unknown statements, rapids into the stock), echoed into report.json.
  std::string pathFormat;
  std::vector<int64_t> moveLines;
  PathWarnings pathWarnings;
  IgnoredWords ignoredWords;         // words of the file that change no geometry
  std::vector<int64_t> toolNumbers;  // T number of path.cutters[k] (multi-tool files)
  // The read (report.json path_file): every move the file made (`path` holds those that
  // can reach the grid, tools/io/move_window.h), the file's bytes and the seconds taken.
  size_t movesRead = 0;
  double pathFileBytes = 0, pathReadSeconds = 0;
  std::vector<MoveWindowFilter::ToolMoves> toolMoves;  // every cutting move read, by tool
  // The options the path file was read with (pathOptions() when it was read: its flute
  // count may come from the file's own cutter), so that a re-read makes the same moves.
  PathFileOptions pathReadOptions;
  // "design": {"stl": FILE, "gouge_tolerance": mm}: the part the path should make.
  std::string designFile;                      // resolved; empty without a design
  std::shared_ptr<const TriangleMesh> design;  // read by loadJobInputs
  double gougeTolerance = 1e-3;                // mm below the design that is a gouge
  // "normal_deviation": true: deviation.ply along the vertex normals (CONVENTIONS.md
  // "Normal deviation on a design surface"); cuts deeper than gouge_depth (mm) below the
  // design surface do not count.
  bool normalDeviation = false;
  double gougeDepth = 1;
  double scallopLimit = NAN;  // mm: design.scallop_limit (NaN: none)
  // design.view: the angles deviation_view.png is drawn from (tools/render/deviation_view_png.h).
  double viewAzimuthDeg = 30, viewElevationDeg = 35;
  // design.view.light_azimuth_deg / light_elevation_deg (NaN: the light above the
  // viewer's right shoulder) and design.view.projection ("perspective": true).
  double viewLightAzimuthDeg = NAN, viewLightElevationDeg = NAN;
  bool viewPerspective = false;

  GridSpec grid() const;
  // The stock's highest point on the map's lines: stock.max.z, or in a frame the box's
  // highest w (mm).
  double stockTop() const;
  // A stock of any shape (stock.stl or stock.gsf), not a box: the map's cells start at
  // fillStockHeights (kNoMaterial where a line holds none; raycast/grid_frame.h).
  bool shapedStock() const { return stockSolid || stockMap; }
  void fillStockHeights(ZMap& map) const;
  // How the path file is read: block delete, work offsets, tools, machine, and for the
  // teeth model the one tool's flute count (G-code feeds per tooth).
  PathFileOptions pathOptions() const;
};

// The built-in default job: a bull cutter raster with lead (the README's main job).
const char* defaultJobJson();

// Parses and validates the text of a job file, and only that: no file is read and no
// path is built (tools/run/job_loader.h does both). `source` names the file in messages
// and resolves the relative file names of "path" and "design". Throws InputError.
// A non-empty `pathOverride` (simulate --path FILE) replaces the job's "path".
// "tool" may be left out when the path file defines the cutter (APT CUTTER/).
Job parseJob(const std::string& text, const std::string& source,
             const std::string& pathOverride = "");

// The closed solid of a job's "stock": {"stl": path}; InputError naming stock.stl when
// the file cannot be read or is not a closed, consistently oriented solid.
std::shared_ptr<const StockSolid> readStockSolid(const std::string& path);

// The height map of a job's "stock": {"gsf": path}; InputError naming stock.gsf.
std::shared_ptr<const ZMap> readStockMap(const std::string& path);
// The box of a map stock: its grid's rectangle, or the job's "min", "max" (x, y) that
// it must cover (InputError naming stock.gsf otherwise), from its lowest height to its
// highest.
Box3 stockMapBox(const ZMap& map, const nlohmann::json& stock);

// Rethrows `e`, an error met while reading the job from `source`, with `source`
// leading its place (unless it already does): "job.json: grid.spacing: ...".
[[noreturn]] void throwFromJob(const InputError& e, const std::string& source);

// Refuses a path with a tip beyond +-1e6 mm (1 km) in x, y or z, as the job's own
// numbers are bounded: the geometry's squares and tile counts stay far from
// overflow. Names "file:line" from `lines` (ToolPathFile::moveLines) when given.
void checkPathMagnitudes(const ToolPath& path, const std::vector<int64_t>& lines,
                         const std::string& file);

// The job as JSON (the inputs echoed into report.json).
nlohmann::json jobToJson(const Job& job);

}  // namespace scallop
