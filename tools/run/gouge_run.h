// A gouge run: seed 004's peripheral-milling strategy on an STL surface, the exact check
// of every posture it accepts (analysis/peripheral_strategy.h, analysis/gouge_check.h)
// and the ray-cast gouge map, with report.json built by tools/run/report.h. `scallop
// gouge` is this plus its command line (tools/cli/gouge_command.cpp); the Python
// module's gouge() calls it too.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/gouge_check.h"
#include "analysis/peripheral_strategy.h"

namespace scallop {

struct GougeSettings {
  std::string surface;  // STL file, binary or ASCII
  double radius = 0;    // R, mm
  double length = 0;    // flute length L, mm
  // feedAxis and inclinationAxis are set from `feed` and `inclinationAxis` below.
  StrategyOptions strategy;
  std::string feed = "x";                  // x | y
  std::string inclinationAxis = "normal";  // normal | feed
  std::string normals = "up";              // up | file
  double mapTolerance = 1e-2;              // mm
  double gridSpacing = 0;                  // mm; <= 0: longest side / 300
  bool noMap = false;
  std::string posturesCsv;  // optional: one CSV row per cc-point
  std::string outDir;       // optional: report.json, gouge_map.png, gouge_depth.exr
  int threads = 0;          // as given to --threads (0: all cores), for the report
  // Told of repairs worth a warning (degenerate facets dropped) as soon as the STL is read.
  std::function<void(const std::string& message)> warning;
};

struct GougeResult {
  nlohmann::json report;   // report.json's document
  std::string reportText;  // as written to DIR/report.json (or as --json prints it)
  // For the summary people read.
  std::string stlFormat;  // "binary" or "ascii"
  size_t triangles = 0, vertices = 0;
  double sliceSpacingMm = 0;  // the spacing used (L when not given)
  StrategySummary summary;
  std::optional<GougeMapStats> map;  // none with noMap
  std::vector<std::string> outputs;  // files written, in the report's order
};

// Throws InputError naming the option (e.g. "--radius") for bad settings or the file
// for an unreadable surface; writes nothing then.
GougeResult runGouge(GougeSettings settings);

}  // namespace scallop
