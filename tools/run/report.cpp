#include "tools/run/report.h"

#include <tbb/info.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "analysis/contact_curvature.h"
#include "analysis/pass_section.h"
#include "base/version.h"
#include "sweep/raster.h"
#include "sweep/swept_segment.h"
#include "tools/io/atomic_file.h"
#include "tools/io/job.h"

namespace scallop {

using nlohmann::json;

namespace {

constexpr const char* kSkuNote =
    "Sku is the plain kurtosis (3 for a Gaussian surface); Gwyddion shows the excess, Sku - 3";

json number(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

// The path-interval procedures' scallop for the raster's step-over, lead and tilt
// beside the measured one, over the same span (between the first and the last pass's
// floor contacts): the exact one (analysis/pass_section.h, every pass placed as
// sweep/raster.cpp places it, a zigzag's reversed passes mirrored across the feed) and
// the effective radius's (analysis/contact_curvature.h, two passes fed the same way),
// for the cutter's solid of revolution; null where not applicable.
void addScallopPredictions(const Job& job, int passes, double fromMm, double toMm, json& m) {
  const RasterSpec& r = job.raster;
  const bool alongX = r.direction == 'x';
  const double crossMin = alongX ? job.stock.min.y : job.stock.min.x;
  std::vector<PassPlacement> placements;
  for (int k = 0; k < passes; ++k) {
    // The section's +y is the cross-feed c = z x f: +y for feed +x, -x for feed +y.
    const bool reversed = r.zigzag && (k % 2 == 1);
    placements.push_back({crossMin + k * r.stepOver, reversed == alongX});
  }
  const PassSection section = PassSection::of(job.cutter, r.leadDeg, r.tiltDeg);
  double exact = 0;
  std::string reason;
  const bool ok = section.coverScallop(placements, fromMm, toMm, &exact, &reason);
  m["predicted_scallop_height"] = ok ? json(exact) : json(nullptr);
  const ProcedureResult osculating =
      scallopHeightEffectiveRadius(job.cutter, r.leadDeg, r.tiltDeg, 0.5 * r.stepOver);
  m["predicted_scallop_height_effective_radius"] =
      osculating.applicable ? json(osculating.value) : json(nullptr);
}

}  // namespace

json newReport(int requestedThreads) {
  json r;
  r["scallop_version"] = kScallopVersion;
  r["threads"] = requestedThreads > 0 ? requestedThreads : tbb::info::default_concurrency();
  return r;
}

std::string reportText(const json& report) {
  return report.dump(2) + "\n";
}

std::string writeReport(const json& report, const std::string& dir) {
  const std::string text = reportText(report);
  writeTextAtomically((std::filesystem::path(dir) / "report.json").string(), text, "the report");
  return text;
}

json simulationReport(const RunRecord& run) {
  json r = newReport(run.requestedThreads);
  r["job_source"] = run.jobSource;
  r["inputs"] = run.inputs;
  r["grid"] = gridToJson(run.grid);
  r["method"] = run.method;
  if (run.method == "stamp") r["stamp_step_mm"] = run.stampStepMm;
  r["sweep"] = {{"cutting_moves", run.cuttingMoves},
                {"swept_segments", run.sweptSegments},
                {"culling_tiles", run.cullingTiles}};
  r["timings_s"] = {{"scene_build", run.sceneSeconds},
                    {"cast", run.castSeconds},
                    {"write", run.writeSeconds},
                    {"total", run.totalSeconds}};
  const double cells = double(run.grid.cells());
  json meas = {{"min_height", run.minHeight},
               {"max_height", run.maxHeight},
               {"exact_evaluations_per_cell", cells > 0 ? run.exactEvaluations / cells : 0.0},
               {"unproven_cells", run.unprovenSearches},
               {"mcells_per_s", run.castSeconds > 0 ? cells / run.castSeconds / 1e6 : 0.0}};
  if (!run.raster.is_null()) meas.update(run.raster);
  if (!run.frameCells.is_null()) meas["frame"] = run.frameCells;
  r["measurements"] = meas;
  r["surface_stats"] = run.surfaceStats;
  r["outputs"] = {"heights.exr", "heights.gsf", "preview.png", "report.json"};
  if (!run.tiled.is_null()) r["tiled"] = run.tiled;
  if (!run.feedMarks.is_null()) r["feed_marks"] = run.feedMarks;
  if (!run.pathFile.is_null()) r["path_file"] = run.pathFile;
  if (!run.design.is_null()) r["design"] = run.design, r["outputs"].push_back("deviation.png");
  if (run.design.contains("normal_deviation") && run.design["normal_deviation"].contains("mesh"))
    r["outputs"].push_back("deviation.ply"), r["outputs"].push_back("deviation_view.png");
  return r;
}

json frameCellsJson(const FrameCellCounts& counts) {
  return {{"void_cells", counts.voidCells}, {"cut_through_cells", counts.cutThroughCells}};
}

json gridToJson(const GridSpec& g) {
  return {{"origin", {g.originX, g.originY}},
          {"spacing", g.spacing},
          {"nx", g.nx},
          {"ny", g.ny},
          {"cell_centre", "origin + (index + 1/2) * spacing"},
          {"units", "mm"}};
}

GridSpec gridFromJson(const json& j) {
  GridSpec g;
  g.originX = j.at("origin").at(0).get<double>();
  g.originY = j.at("origin").at(1).get<double>();
  g.spacing = j.at("spacing").get<double>();
  g.nx = j.at("nx").get<int64_t>();
  g.ny = j.at("ny").get<int64_t>();
  return g;
}

// The highest point left above the floor between the first and the last pass's floor
// contacts (where both neighbours have cut), i.e. the largest scallop on the map, mm.
json rasterMeasurements(const Job& job, const ZMap& map) {
  json m;
  const double floorZ = job.stock.max.z - job.raster.depth;
  m["floor_z"] = floorZ;
  const bool alongX = job.raster.direction == 'x';
  const double crossMin = alongX ? job.stock.min.y : job.stock.min.x;
  const double crossMax = alongX ? job.stock.max.y : job.stock.max.x;
  const int passes = int(std::floor((crossMax - crossMin) / job.raster.stepOver + 1e-9)) + 1;
  if (passes < 2) return m;
  // Where pass k touches the floor: its tip's cross coordinate plus the lowest point's
  // offset, which a tilt moves off the tip (and a zigzag mirrors on reversed passes),
  // as sweep/raster.cpp poses the cutter.
  auto contact = [&](int k) {
    const bool reversed = job.raster.zigzag && (k % 2 == 1);
    const Vec3 feed =
        alongX ? Vec3{reversed ? -1.0 : 1.0, 0, 0} : Vec3{0, reversed ? -1.0 : 1.0, 0};
    const Vec3 axis = leadTiltAxis(feed, job.raster.leadDeg, job.raster.tiltDeg);
    const Vec3 lowest = cutterSupport(job.cutter, axis, Vec3{0, 0, -1});
    return crossMin + k * job.raster.stepOver + (alongX ? lowest.y : lowest.x);
  };
  const double first = std::min(contact(0), contact(passes - 1));
  const double last = std::max(contact(0), contact(passes - 1));
  double top = -HUGE_VAL;
  const GridSpec& g = map.grid();
  for (int64_t j = 0; j < g.ny; ++j) {
    for (int64_t i = 0; i < g.nx; ++i) {
      const double c = alongX ? g.cellCentreY(j) : g.cellCentreX(i);
      if (c >= first && c <= last) top = std::max(top, map.at(i, j));
    }
  }
  m["max_scallop_height"] = top - floorZ;
  addScallopPredictions(job, passes, first, last, m);
  return m;
}

json surfaceStatsJson(const SurfaceStats& s) {
  return {{"standard", "ISO 25178-2"},
          {"levelling", s.levelling == Levelling::kPlane ? "least-squares plane" : "none"},
          {"cells", s.cells},
          {"area_mm2", s.areaMm2},
          {"Sa_mm", number(s.sa)},
          {"Sq_mm", number(s.sq)},
          {"Ssk", number(s.ssk)},
          {"Sku", number(s.sku)},
          {"Sp_mm", number(s.sp)},
          {"Sv_mm", number(s.sv)},
          {"Sz_mm", number(s.sz)},
          {"reference_plane",
           {{"centre_mm", {s.plane.x0, s.plane.y0}},
            {"z_at_centre_mm", s.plane.z0},
            {"slope_x", s.plane.slopeX},
            {"slope_y", s.plane.slopeY}}},
          {"notes", kSkuNote}};
}

json mapSurfaceStatsJson(const ZMap& map) {
  return surfaceStatsJson(surfaceStats(map, wholeMap(map.grid()), Levelling::kPlane));
}

}  // namespace scallop
