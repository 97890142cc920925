#include "tools/run/gouge_run.h"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <utility>

#include "base/constants.h"
#include "base/input_error.h"
#include "tools/io/atomic_file.h"
#include "tools/io/height_images.h"
#include "tools/io/stl_io.h"
#include "tools/render/preview_png.h"
#include "tools/run/report.h"
#include "tools/run/stopwatch.h"

namespace scallop {

using nlohmann::json;

namespace {

// Lengths are bounded by 1 km (kMaxMagnitudeMm) as everywhere in scallop.
void requirePositive(double v, const char* field, const char* what) {
  if (!(v > 0) || !(v <= kMaxMagnitudeMm))
    throw InputError(field, fmt::format("{} must be in (0, 1e6], got {}", what, v));
}

void writePostures(const StrategyResult& r, const std::string& path) {
  writeStreamAtomically(path, "the postures file", [&](std::ostream& out) {
    out << "index,plane,line,cc_x,cc_y,cc_z,normal_x,normal_y,normal_z,feed_x,feed_y,feed_z,"
           "tip_x,tip_y,tip_z,axis_x,axis_y,axis_z,inclination_deg,reversed,k_negative,"
           "verdict,vertex_test,exact_depth_mm,deepest_triangle,initial_exact_depth_mm\n";
    for (size_t i = 0; i < r.postures.size(); ++i) {
      const PostureResult& p = r.postures[i];
      const Vec3 &c = p.cc.point, &n = p.cc.normal, &f = p.feedUsed, &t = p.pose.tip,
                 &a = p.pose.axis;
      out << fmt::format(
          "{},{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},"
          "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:g},{},{},{},{},{:.12g},{},{:.12g}\n",
          i + 1, p.cc.plane + 1, p.cc.line + 1, c.x, c.y, c.z, n.x, n.y, n.z, f.x, f.y, f.z, t.x,
          t.y, t.z, a.x, a.y, a.z, p.inclinationDeg, int(p.reversed), int(p.kNegative),
          toString(p.verdict), p.vertexFree ? "free" : "interference", p.exactDepth,
          p.deepestTriangle < 0 ? std::string() : std::to_string(p.deepestTriangle + 1),
          p.initialExactDepth);
    }
  });
}

// Checks the settings and sets the strategy's feed and inclination axes from their names.
void checkSettings(GougeSettings& a) {
  requirePositive(a.radius, "--radius", "the cutter radius (mm)");
  requirePositive(a.length, "--length", "the flute length (mm)");
  StrategyOptions& so = a.strategy;
  if (a.feed != "x" && a.feed != "y")
    throw InputError("--feed", "expected x or y, got '" + a.feed + "'");
  so.feedAxis = a.feed[0];
  if (a.inclinationAxis != "normal" && a.inclinationAxis != "feed")
    throw InputError("--inclination-axis",
                     "expected normal or feed, got '" + a.inclinationAxis + "'");
  so.inclinationAxis =
      a.inclinationAxis == "normal" ? InclinationAxis::Normal : InclinationAxis::Feed;
  if (a.normals != "up" && a.normals != "file")
    throw InputError("--normals", "expected up or file, got '" + a.normals + "'");
  if (so.sliceSpacing != 0)
    requirePositive(so.sliceSpacing, "--slice-spacing", "the slicing plane spacing (mm)");
  if (so.ccStep != 0) requirePositive(so.ccStep, "--cc-step", "the cc-point step (mm)");
  if (so.vertexTestLength != 0)
    requirePositive(so.vertexTestLength, "--test-length", "the vertex test length (mm)");
  requirePositive(so.gougeTolerance, "--tolerance", "the gouge tolerance (mm)");
  requirePositive(a.mapTolerance, "--map-tolerance", "the gouge map tolerance (mm)");
  if (a.gridSpacing != 0) requirePositive(a.gridSpacing, "--grid-spacing", "the grid spacing (mm)");
  if (!a.outDir.empty()) ensureWritableDirectory(a.outDir);
}

// The report's "gouge_map" block.
json gougeMapJson(const GridSpec& grid, double tolerance, const GougeMapStats& g) {
  auto frac = [&](int64_t n) { return g.designCells ? double(n) / double(g.designCells) : 0.0; };
  return {{"grid",
           {{"origin", {grid.originX, grid.originY}},
            {"spacing", grid.spacing},
            {"nx", grid.nx},
            {"ny", grid.ny}}},
          {"tolerance", tolerance},
          {"swept_segments", g.sweptSegments},
          {"design_cells", g.designCells},
          {"untouched_cells", g.untouchedCells},
          {"over_cut",
           {{"cells", g.overCutCells},
            {"fraction", frac(g.overCutCells)},
            {"max_depth", g.maxOverCut},
            {"mean_depth", g.meanOverCut}}},
          {"under_cut",
           {{"cells", g.underCutCells},
            {"fraction", frac(g.underCutCells)},
            {"max_height", g.maxUnderCut},
            {"mean_height", g.meanUnderCut}}},
          {"depth", "vertical: design height - machined height on the z-map, mm"}};
}

}  // namespace

GougeResult runGouge(GougeSettings a) {
  const auto tStart = Clock::now();
  checkSettings(a);
  const StrategyOptions& so = a.strategy;
  const Cutter cutter = Cutter::make(CutterType::Flat, a.radius, 0, a.length, "tool");

  StlInfo info;
  TriangleMesh mesh = readStl(a.surface, &info);
  if (a.normals == "up") info.repairs.flippedUp = orientNormalsUp(mesh);
  if (info.repairs.degenerateDropped && a.warning)
    a.warning(fmt::format("{}: dropped {} degenerate triangles (first: {})", a.surface,
                          info.repairs.degenerateDropped, info.repairs.firstDegenerate.front()));
  const auto tRead = Clock::now();
  const MeshIndex index(mesh);
  const StrategyResult r = runPeripheralStrategy(index, cutter, so);
  const double strategySeconds = secondsSince(tRead);
  const StrategySummary& s = r.summary;

  json mapJson = nullptr;
  GougeMap gm;
  double mapSeconds = 0;
  if (!a.noMap) {
    const auto tMap = Clock::now();
    const Box3 box = mesh.bounds();
    const double spacing = a.gridSpacing > 0
                               ? a.gridSpacing
                               : std::max(box.max.x - box.min.x, box.max.y - box.min.y) / 300;
    const double cells =
        std::ceil((box.max.x - box.min.x) / spacing) * std::ceil((box.max.y - box.min.y) / spacing);
    if (cells > 2e8)
      throw InputError("--grid-spacing",
                       fmt::format("{} mm gives {:.3g} cells (limit 2e8)", spacing, cells));
    const GridSpec grid = gridCovering(box.min.x, box.min.y, box.max.x, box.max.y, spacing);
    GougeMapOptions mo;
    mo.tolerance = a.mapTolerance;
    gm = gougeMap(index, cutter, r.path, grid, mo);
    mapSeconds = secondsSince(tMap);
    mapJson = gougeMapJson(grid, a.mapTolerance, gm.stats);
  }

  json j = newReport(a.threads);
  j["surface"] = {{"file", a.surface},
                  {"format", toString(info.format)},
                  {"facets_in_file", info.facets},
                  {"triangles", mesh.triangles.size()},
                  {"vertices", mesh.vertices.size()},
                  {"normals", a.normals},
                  {"repairs",
                   {{"degenerate_dropped", info.repairs.degenerateDropped},
                    {"first_degenerate", info.repairs.firstDegenerate},
                    {"flipped_up", info.repairs.flippedUp}}}};
  j["tool"] = {{"type", "flat"}, {"radius", a.radius}, {"flute_length", a.length}};
  j["strategy"] = {{"slice_spacing", so.sliceSpacing > 0 ? so.sliceSpacing : a.length},
                   {"slicing_planes", r.planes},
                   {"feed_axis", a.feed},
                   {"cc_step", so.ccStep},
                   {"cc_axial_position", so.ccAxialPosition},
                   {"inclination_step_deg", so.inclinationStepDeg},
                   {"inclination_max_deg", so.inclinationMaxDeg},
                   {"inclination_axis", a.inclinationAxis},
                   {"incline_both_ways", so.inclineBothWays},
                   {"vertex_test_length", so.vertexTestLength > 0 ? so.vertexTestLength : a.length},
                   {"vertex_tolerance", so.vertexTolerance}};
  j["cc_points"] = s.ccPoints;
  j["vertex_test"] = {
      {"free_initial", s.freeInitial}, {"inclined", s.inclined},
      {"reversed", s.reversed},        {"non_machinable", s.nonMachinable},
      {"k_negative", s.kNegative},     {"initial_interference", s.initialVertexInterference}};
  j["non_machinable_pct"] = s.nonMachinablePct();
  j["machinable_pct"] = s.machinablePct();
  j["groups"] = {{"forward", s.groupsForward},
                 {"backward", s.groupsBackward},
                 {"non_machinable", s.groupsNonMachinable}};
  j["exact"] = {
      {"checked_postures", s.checkedPostures},
      {"gouging_postures", s.gougingPostures},
      {"max_depth", s.maxDepth},
      {"mean_depth", s.meanDepth},
      {"tolerance", so.gougeTolerance},
      {"initial_gouging", s.initialExactGouging},
      {"depth",
       "max over the surface inside the flute's axial extent of R - distance from the axis, mm"}};
  j["missed_by_vertex_test"] = s.missedByVertexTest;
  j["gouge_map"] = mapJson;

  json outputs = json::array();
  if (!a.posturesCsv.empty()) {
    writePostures(r, a.posturesCsv);
    outputs.push_back(a.posturesCsv);
  }
  namespace fs = std::filesystem;
  if (!a.outDir.empty()) {
    if (!a.noMap) {
      const std::string png = (fs::path(a.outDir) / "gouge_map.png").string();
      const std::string exr = (fs::path(a.outDir) / "gouge_depth.exr").string();
      PreviewOptions po;
      po.title = fmt::format("gouge depth over {:g} mm", a.mapTolerance);
      writePreviewPng(gm.overCut, png, po);
      writeHeightsExr(gm.overCut, exr);
      outputs.push_back(png);
      outputs.push_back(exr);
    }
    outputs.push_back((fs::path(a.outDir) / "report.json").string());
  }
  j["outputs"] = outputs;
  j["timings_s"] = {{"strategy_and_exact", strategySeconds},
                    {"gouge_map", mapSeconds},
                    {"total", secondsSince(tStart)}};
  GougeResult result;
  result.reportText = a.outDir.empty() ? reportText(j) : writeReport(j, a.outDir);
  result.report = std::move(j);
  result.stlFormat = toString(info.format);
  result.triangles = mesh.triangles.size();
  result.vertices = mesh.vertices.size();
  result.sliceSpacingMm = so.sliceSpacing > 0 ? so.sliceSpacing : a.length;
  result.summary = s;
  if (!a.noMap) result.map = gm.stats;
  for (const auto& o : outputs) result.outputs.push_back(o.get<std::string>());
  return result;
}

}  // namespace scallop
