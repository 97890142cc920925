#include "tools/run/path_report.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "analysis/design_deviation.h"
#include "tools/io/job.h"
#include "tools/render/deviation_png.h"

namespace scallop {

using nlohmann::json;

json pathFileReport(const Job& job, bool quiet) {
  const PathWarnings& w = job.pathWarnings;
  if (!quiet) {
    for (size_t k = 0; k < std::min<size_t>(w.kept.size(), 20); ++k)
      std::fprintf(stderr, "scallop: warning: %s\n", w.kept[k].c_str());
    if (w.total > 20) std::fprintf(stderr, "scallop: %zu warnings in all\n", w.total);
  }
  return {{"format", job.pathFormat}, {"warnings", w.kept}, {"warnings_total", w.total}};
}

json designReport(const Job& job, const ZMap& map, const std::string& outDir, bool quiet) {
  const MeshIndex index(*job.design);
  DesignComparison c = compareWithDesign(map, index, job.gougeTolerance);
  attributeGouges(c, map, job.cutter, job.path);
  double limit = 0;
  if (!outDir.empty()) {
    const std::string png = (std::filesystem::path(outDir) / "deviation.png").string();
    limit = writeDeviationPng(
        c, png, "machined - design: " + std::filesystem::path(job.designFile).filename().string());
  }

  const DeviationSummary& s = c.summary;
  json gouges = json::array();
  for (size_t n = 0; n < std::min<size_t>(c.gouges.size(), 100); ++n) {
    const Gouge& g = c.gouges[n];
    json moves = json::array();
    for (size_t k = 0; k < std::min<size_t>(g.moves.size(), 20); ++k) {
      json m = {{"move", g.moves[k] + 1}};
      if (g.moves[k] < job.moveLines.size()) m["line"] = job.moveLines[g.moves[k]];
      moves.push_back(m);
    }
    gouges.push_back({{"x", g.x},
                      {"y", g.y},
                      {"depth_mm", g.depth},
                      {"design_z", g.designZ},
                      {"machined_z", g.machinedZ},
                      {"cells", g.cells},
                      {"area_mm2", g.areaMm2},
                      {"moves", moves}});
  }
  const double maxDepth = c.gouges.empty() ? 0.0 : c.gouges.front().depth;
  json r = {
      {"stl", job.designFile},
      {"gouge_tolerance_mm", job.gougeTolerance},
      {"cells_compared", s.cells},
      {"deviation_mm", {{"min", s.min}, {"max", s.max}, {"mean", s.mean}, {"rms", s.rms}}},
      {"overcut",
       {{"cells", s.overcutCells},
        {"area_mm2", s.overcutAreaMm2},
        {"max_depth_mm", std::max(0.0, -s.min)}}},
      {"undercut",
       {{"cells", s.undercutCells},
        {"area_mm2", s.undercutAreaMm2},
        {"max_mm", std::max(0.0, s.max)}}},
      {"gouges", {{"count", c.gouges.size()}, {"max_depth_mm", maxDepth}, {"deepest", gouges}}}};
  if (!outDir.empty()) {
    r["image"] = "deviation.png";
    r["image_colour_range_mm"] = limit;
  }
  if (!quiet) {
    std::fprintf(stderr,
                 "design: %lld cells compared, machined - design in [%.6f, %.6f] mm, rms %.6f "
                 "mm; %zu gouges deeper than %g mm",
                 (long long)s.cells, s.min, s.max, s.rms, c.gouges.size(), job.gougeTolerance);
    if (!c.gouges.empty()) {
      const Gouge& g = c.gouges.front();
      std::fprintf(stderr, ", deepest %.6f mm at (%.3f, %.3f)", g.depth, g.x, g.y);
      if (!g.moves.empty() && g.moves.front() < job.moveLines.size())
        std::fprintf(stderr, " by %s:%lld", job.pathFile.c_str(),
                     (long long)job.moveLines[g.moves.front()]);
    }
    std::fprintf(stderr, "\n");
  }
  return r;
}

}  // namespace scallop
