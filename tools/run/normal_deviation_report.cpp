#include "tools/run/normal_deviation_report.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/deviation_areas.h"
#include "analysis/normal_deviation.h"
#include "tools/io/job.h"
#include "tools/io/ply_writer.h"
#include "tools/render/deviation_view_png.h"

namespace scallop {

namespace {

constexpr int kHistogramBins = 20;

nlohmann::json statistics(const std::vector<double>& deviation, double gougeTolerance) {
  std::vector<double> values;
  for (double w : deviation)
    if (!std::isnan(w)) values.push_back(w);
  if (values.empty()) return {{"vertices", 0}};
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  double sum = 0, squares = 0;
  int64_t gouged = 0;
  for (double w : values) sum += w, squares += w * w, gouged += w < -gougeTolerance;
  const double n = double(values.size()), width = (*hi - *lo) / kHistogramBins;
  std::vector<int64_t> counts(kHistogramBins, 0);
  for (double w : values) {
    const int bin = width > 0 ? int((w - *lo) / width) : 0;
    ++counts[size_t(std::clamp(bin, 0, kHistogramBins - 1))];
  }
  return {{"vertices", values.size()},
          {"min_mm", *lo},
          {"max_mm", *hi},
          {"mean_mm", sum / n},
          {"rms_mm", std::sqrt(squares / n)},
          {"gouged_vertices", gouged},
          {"histogram", {{"from_mm", *lo}, {"bin_width_mm", width}, {"counts", counts}}}};
}

// The moves whose swept solids made the gouged vertices' values, deepest first (at most
// kMovesListed): 1-based move, its file line, how many vertices, the deepest value.
constexpr size_t kMovesListed = 20;
nlohmann::json gougingMoves(const Job& job, const NormalDeviation& d) {
  struct Gouging {
    int64_t vertices = 0;
    double deepest = HUGE_VAL;
  };
  std::map<int64_t, Gouging> byMove;
  for (size_t v = 0; v < d.deviation.size(); ++v)
    if (d.deviation[v] < -job.gougeTolerance && d.lowestMove[v] >= 0) {
      Gouging& g = byMove[d.lowestMove[v]];
      ++g.vertices;
      g.deepest = std::min(g.deepest, d.deviation[v]);
    }
  std::vector<std::pair<int64_t, Gouging>> moves(byMove.begin(), byMove.end());
  std::stable_sort(moves.begin(), moves.end(), [](const auto& a, const auto& b) {
    return a.second.deepest < b.second.deepest;
  });
  nlohmann::json list = nlohmann::json::array();
  for (size_t k = 0; k < std::min(moves.size(), kMovesListed); ++k) {
    const auto& [move, g] = moves[k];
    nlohmann::json m = {{"move", move + 1}, {"vertices", g.vertices}, {"deepest_mm", g.deepest}};
    if (size_t(move) < job.moveLines.size()) m["line"] = job.moveLines[size_t(move)];
    list.push_back(m);
  }
  return {{"count", moves.size()}, {"deepest", list}};
}

}  // namespace

nlohmann::json normalDeviationReport(const Job& job, const std::string& outDir, bool quiet) {
  const auto t0 = std::chrono::steady_clock::now();
  const NormalDeviation d =
      normalDeviation(job.cutter, job.path, job.stock, *job.design, job.gougeDepth);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  nlohmann::json r = statistics(d.deviation, job.gougeTolerance);
  r["gouge_depth_mm"] = job.gougeDepth;
  const DeviationAreas areas =
      deviationAreas(*job.design, d.deviation, job.scallopLimit, job.gougeTolerance);
  r["areas"] = {{"interpolation", "linear across each facet from its vertices"},
                {"measured_mm2", areas.measuredMm2},
                {"gouged_mm2", areas.gougedMm2},
                {"facets_left_out", areas.facetsLeftOut}};
  if (!std::isnan(job.scallopLimit)) {
    r["areas"]["scallop_limit_mm"] = job.scallopLimit;
    r["areas"]["above_limit_mm2"] = areas.aboveLimitMm2;
  }
  r["gouging_moves"] = gougingMoves(job, d);
  r["cut_through_vertices"] = d.cutThrough;
  r["no_material_vertices"] = d.noMaterial;
  r["unresolved_vertices"] = d.unresolved;
  r["candidate_moves"] = d.candidates;
  r["exact_evaluations"] = d.exactEvaluations;
  r["seconds"] = seconds;
  if (!outDir.empty()) {
    writeVertexValuesPly(
        *job.design, d.deviation, "deviation",
        {"scallop normal deviation of " + std::filesystem::path(job.designFile).filename().string(),
         "deviation: mm along the vertex normal from the design to the machined surface, "
         "positive = material left; NaN = no material or unresolved"},
        (std::filesystem::path(outDir) / "deviation.ply").string());
    r["mesh"] = "deviation.ply";
    DeviationView view;
    view.azimuthDeg = job.viewAzimuthDeg, view.elevationDeg = job.viewElevationDeg;
    view.light = {job.viewLightAzimuthDeg, job.viewLightElevationDeg};
    if (job.viewPerspective) view.projection = Projection::kPerspective;
    writeDeviationViewPng(
        *job.design, d.deviation, view,
        (std::filesystem::path(outDir) / "deviation_view.png").string(),
        "normal deviation of " + std::filesystem::path(job.designFile).filename().string());
    r["picture"] = "deviation_view.png";
  }
  // An open surface has no inside to check its facets against (vertex_normals.h): if the
  // tool reached vertex lines only from behind their normals, say so rather than write
  // a mesh of NaN in silence.
  if (d.unresolved > 0 && !r.contains("min_mm")) {
    const std::string warning =
        job.designFile + ": no vertex of the design has a deviation: at all " +
        std::to_string(d.unresolved) +
        " vertices the moves that reach the normal's line come from behind it (the axis "
        "points away from the normal); do the facets face inwards? List each facet's "
        "corners counter-clockwise seen from outside, where the tool is";
    r["warning"] = warning;
    std::fprintf(stderr, "scallop: warning: %s\n", warning.c_str());
  }
  if (!quiet) {
    std::fprintf(stderr, "design: normal deviation at %zu vertices", job.design->vertices.size());
    if (r.contains("min_mm"))
      std::fprintf(stderr, " in [%.6f, %.6f] mm, rms %.6f mm", r["min_mm"].get<double>(),
                   r["max_mm"].get<double>(), r["rms_mm"].get<double>());
    std::fprintf(stderr, "; %lld cut through, %lld without material, %lld unresolved\n",
                 (long long)d.cutThrough, (long long)d.noMaterial, (long long)d.unresolved);
  }
  return r;
}

}  // namespace scallop
