#include "tools/cli/gouge_command.h"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "analysis/gouge_check.h"
#include "base/constants.h"
#include "base/input_error.h"
#include "tools/cli/command.h"
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

}  // namespace

int runGouge(GougeArgs a) {
  const auto tStart = Clock::now();
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
  const Cutter cutter = Cutter::make(CutterType::Flat, a.radius, 0, a.length, "tool");

  StlInfo info;
  TriangleMesh mesh = readStl(a.surface, &info);
  if (a.normals == "up") info.repairs.flippedUp = orientNormalsUp(mesh);
  if (info.repairs.degenerateDropped)
    std::fprintf(stderr, "scallop: warning: %s: dropped %zu degenerate triangles (first: %zu)\n",
                 a.surface.c_str(), info.repairs.degenerateDropped,
                 info.repairs.firstDegenerate.front());
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
    const GougeMapStats& g = gm.stats;
    auto frac = [&](int64_t n) { return g.designCells ? double(n) / double(g.designCells) : 0.0; };
    mapJson = {{"grid",
                {{"origin", {grid.originX, grid.originY}},
                 {"spacing", grid.spacing},
                 {"nx", grid.nx},
                 {"ny", grid.ny}}},
               {"tolerance", a.mapTolerance},
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
  const std::string text = a.outDir.empty() ? reportText(j) : writeReport(j, a.outDir);

  if (a.json) {
    std::fputs(text.c_str(), stdout);
    return 0;
  }
  std::printf("%s: %s STL, %zu triangles, %zu vertices; flat cutter R=%g mm, L=%g mm\n",
              a.surface.c_str(), toString(info.format), mesh.triangles.size(), mesh.vertices.size(),
              a.radius, a.length);
  std::printf("%zu slicing planes %g mm apart, feed along %s\n", s.planes,
              so.sliceSpacing > 0 ? so.sliceSpacing : a.length, a.feed.c_str());
  std::printf("\n  total cc-points  failures  non-machinable %%  machinable %%\n");
  std::printf("  %15zu  %8zu  %16.2f  %12.2f\n\n", s.ccPoints, s.nonMachinable,
              s.nonMachinablePct(), s.machinablePct());
  std::printf("vertex test: %zu free initially, %zu inclined, %zu reversed, %zu non-machinable\n",
              s.freeInitial, s.inclined, s.reversed, s.nonMachinable);
  std::printf(
      "exact check: %zu of %zu accepted postures gouge (max %.6g mm, mean %.6g mm), %zu missed by "
      "the vertex test\n",
      s.gougingPostures, s.checkedPostures, s.maxDepth, s.meanDepth, s.missedByVertexTest);
  if (!a.noMap) {
    const GougeMapStats& g = gm.stats;
    std::printf(
        "gouge map: %lld of %lld cells over-cut by more than %g mm (max %.6g mm), %lld under-cut, "
        "%lld untouched\n",
        (long long)g.overCutCells, (long long)g.designCells, a.mapTolerance, g.maxOverCut,
        (long long)g.underCutCells, (long long)g.untouchedCells);
  }
  for (const auto& o : outputs) std::printf("wrote %s\n", o.get<std::string>().c_str());
  return 0;
}

namespace {

constexpr const char* kGougeHelp =
    "Seed 004's 5-axis peripheral (flank) milling strategy on an STL surface with a flat\n"
    "(cylinder) cutter, then the exact check of every posture it accepts.\n"
    "Strategy (seed 004 section 2): cc-points where slicing planes (spaced by the effective\n"
    "tool length) cross the facets; feed F along the slicing line; tool vector T = F x N,\n"
    "flank tangent at the cc-point; interference = a facet vertex inside the tool;\n"
    "inclination in steps up to a maximum until free; the orientation of +-T with k >= 0 is\n"
    "tried first, its reverse second; cc-points with no free posture are non-machinable.\n"
    "Exact check: the penetration depth of every nearby triangle (faces and edges, not only\n"
    "vertices) = max of R - distance from the axis over its points within the flute, mm.\n"
    "Gouge map: the accepted postures, joined along each slicing line, are swept exactly onto\n"
    "a z-map and compared with the design surface ray-cast from above (vertical depths, mm).\n"
    "STL: binary or ASCII by content; stored normals are recomputed from the winding,\n"
    "identical vertices welded, degenerate facets dropped (reported).\n"
    "Outputs: summary on stdout (or --json), --postures CSV (one row per cc-point),\n"
    "DIR/report.json, DIR/gouge_map.png (over-cut depth, mm) and DIR/gouge_depth.exr.";

}  // namespace

Command addGougeCommand(CLI::App& parent, CommonOptions& common) {
  auto a = std::make_shared<GougeArgs>();
  CLI::App* app = parent.add_subcommand("gouge", kGougeHelp);
  StrategyOptions& so = a->strategy;
  app->add_option("SURFACE", a->surface, "Surface to machine (STL, binary or ASCII)")->required();
  app->add_option("--radius", a->radius, "Cutter radius R, mm")->required();
  app->add_option("--length", a->length, "Flute length L (effective tool length), mm")->required();
  app->add_option("--slice-spacing", so.sliceSpacing,
                  "Distance between slicing planes, mm (default L)");
  app->add_option("--feed", a->feed, "Feed axis: x (planes y = const) or y")->capture_default_str();
  app->add_option("--cc-step", so.ccStep,
                  "Largest distance between cc-points along a slicing line, mm "
                  "(default: one cc-point per facet crossed)");
  app->add_option(
         "--cc-position", so.ccAxialPosition,
         "Where the cc-point sits along the flute, fraction of L from the tip (0: tip level, "
         "as the seed's tool coordinate system; 0.5: mid-flute)")
      ->capture_default_str();
  app->add_option("--inclination-step", so.inclinationStepDeg, "Inclination step, deg")
      ->capture_default_str();
  app->add_option("--inclination-max", so.inclinationMaxDeg, "Largest inclination, deg")
      ->capture_default_str();
  app->add_option(
         "--inclination-axis", a->inclinationAxis,
         "Rotation axis of the inclination: normal (the surface normal through the cc-point, "
         "axis tilts towards the feed) or feed (the feed line, axis tilts away from the surface)")
      ->capture_default_str();
  app->add_flag("--both-ways", so.inclineBothWays, "Also try -alpha at each inclination step");
  app->add_option("--test-length", so.vertexTestLength,
                  "Axial extent of the vertex test, mm (default L)");
  app->add_option("--tolerance", so.gougeTolerance, "Exact depth above this is a gouge, mm")
      ->capture_default_str();
  app->add_option("--map-tolerance", a->mapTolerance,
                  "Gouge map: machined below design by more than this, mm")
      ->capture_default_str();
  app->add_option("--grid-spacing", a->gridSpacing,
                  "Gouge map cell size, mm (default: longest side / 300)");
  app->add_flag("--no-map", a->noMap, "Skip the ray-cast gouge map");
  app->add_option(
         "--normals", a->normals,
         "up: turn facets to face +Z (surfaces milled from above; default); file: keep the winding")
      ->capture_default_str();
  app->add_option("--postures", a->posturesCsv, "Write one CSV row per cc-point to this file");
  app->add_option("-o,--output", a->outDir,
                  "Output folder for report.json, gouge_map.png, gouge_depth.exr");
  app->add_flag("--json", a->json, "Print the report as JSON on stdout (and nothing else there)");
  addThreadsOption(*app, common);
  return {app, [a, &common]() {
            a->threads = common.threads;
            return runGouge(*a);
          }};
}

}  // namespace scallop
