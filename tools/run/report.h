// report.json: the one builder of what every run reports. `simulate` (in memory and in
// bands), `merge`, the gouge run (tools/run/gouge_run.h) and the benchmark run
// (tools/run/bench_run.h), from the CLI or the Python module alike, all start their
// document with newReport() and write or print it with writeReport() / reportText(); a
// simulation's whole report comes from simulationReport(), so the in-memory and the
// tiled runs cannot drift apart.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "analysis/surface_metrology.h"
#include "raycast/grid_frame.h"
#include "raycast/zmap.h"

namespace scallop {

struct Job;

// {"scallop_version", "threads"}: `requestedThreads` is --threads (0: all cores).
nlohmann::json newReport(int requestedThreads);

// The report as printed and stored: indented by 2, with a final newline.
std::string reportText(const nlohmann::json& report);

// Writes DIR/report.json atomically and returns its text (what --json prints).
std::string writeReport(const nlohmann::json& report, const std::string& dir);

// What one simulation run measured; the report's sections are built from it.
struct RunRecord {
  // The run: the job echoed (jobToJson), its grid and how it was swept.
  std::string jobSource;
  nlohmann::json inputs;
  GridSpec grid;
  std::string method = "exact";  // or "stamp", with its step
  double stampStepMm = 0;
  int64_t cuttingMoves = 0, sweptSegments = 0, cullingTiles = 0;
  int requestedThreads = 0;
  // Timings, s.
  double sceneSeconds = 0, castSeconds = 0, writeSeconds = 0, totalSeconds = 0;
  // The heights.
  double minHeight = 0, maxHeight = 0, exactEvaluations = 0;
  int64_t unprovenSearches = 0;  // CastStats::unprovenSearches
  nlohmann::json raster;        // rasterMeasurements() for a raster job, else null
  nlohmann::json surfaceStats;  // surfaceStatsJson()
  // Optional sections, left out when null.
  nlohmann::json pathFile;    // pathFileReport() for a job with a path file
  nlohmann::json design;      // designReport(), which also wrote deviation.png
  nlohmann::json tiled;       // {"bands", "band_rows", "exr_tile_rows"} of a banded run
  nlohmann::json feedMarks;   // the teeth model's, tools/run/feed_mark_report.h
  nlohmann::json frameCells;  // frameCellsJson() for a map in a frame
};

nlohmann::json simulationReport(const RunRecord& run);

// The grid block: {"origin", "spacing", "nx", "ny", "cell_centre", "units"}.
nlohmann::json gridToJson(const GridSpec& g);
GridSpec gridFromJson(const nlohmann::json& j);

// A frame's cell counts: {"void_cells", "cut_through_cells"} (CONVENTIONS.md "Frames").
nlohmann::json frameCellsJson(const FrameCellCounts& counts);

// For a raster: floor_z and the largest scallop between the first and the last pass
// on `map` (a band of a map gives its own share), and beside it the scallop the
// path-interval procedures predict for the step-over (predicted_scallop_height: exact,
// analysis/pass_section.h; predicted_scallop_height_effective_radius: the osculating
// circle, analysis/contact_curvature.h; null where not applicable).
nlohmann::json rasterMeasurements(const Job& job, const ZMap& map);

// The "surface_stats" block: {"standard", "levelling", "cells", "area_mm2", "Sa_mm",
// "Sq_mm", "Ssk", "Sku", "Sp_mm", "Sv_mm", "Sz_mm", "reference_plane": {...},
// "notes"}. NaN parameters (Sa of a banded map) become null.
nlohmann::json surfaceStatsJson(const SurfaceStats& stats);

// The in-memory report's block: the whole map, plane levelled.
nlohmann::json mapSurfaceStatsJson(const ZMap& map);

}  // namespace scallop
