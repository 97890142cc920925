#include "tools/cli/gouge_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "tools/cli/command.h"
#include "tools/run/gouge_run.h"

namespace scallop {

namespace {

// Runs the gouge check and prints its summary (or the report with --json); returns the
// exit status.
int runGougeCommand(GougeSettings a, bool json) {
  a.warning = [](const std::string& message) {
    std::fprintf(stderr, "scallop: warning: %s\n", message.c_str());
  };
  const GougeResult r = runGouge(a);
  const StrategySummary& s = r.summary;
  if (json) {
    std::fputs(r.reportText.c_str(), stdout);
    return 0;
  }
  std::printf("%s: %s STL, %zu triangles, %zu vertices; flat cutter R=%g mm, L=%g mm\n",
              a.surface.c_str(), r.stlFormat.c_str(), r.triangles, r.vertices, a.radius, a.length);
  std::printf("%zu slicing planes %g mm apart, feed along %s\n", s.planes, r.sliceSpacingMm,
              a.feed.c_str());
  std::printf("\n  total cc-points  failures  non-machinable %%  machinable %%\n");
  std::printf("  %15zu  %8zu  %16.2f  %12.2f\n\n", s.ccPoints, s.nonMachinable,
              s.nonMachinablePct(), s.machinablePct());
  std::printf("vertex test: %zu free initially, %zu inclined, %zu reversed, %zu non-machinable\n",
              s.freeInitial, s.inclined, s.reversed, s.nonMachinable);
  std::printf(
      "exact check: %zu of %zu accepted postures gouge (max %.6g mm, mean %.6g mm), %zu missed by "
      "the vertex test\n",
      s.gougingPostures, s.checkedPostures, s.maxDepth, s.meanDepth, s.missedByVertexTest);
  if (r.map) {
    const GougeMapStats& g = *r.map;
    std::printf(
        "gouge map: %lld of %lld cells over-cut by more than %g mm (max %.6g mm), %lld under-cut, "
        "%lld untouched\n",
        (long long)g.overCutCells, (long long)g.designCells, a.mapTolerance, g.maxOverCut,
        (long long)g.underCutCells, (long long)g.untouchedCells);
  }
  for (const std::string& o : r.outputs) std::printf("wrote %s\n", o.c_str());
  return 0;
}

constexpr const char* kGougeHelp =
    "Seed 004's 5-axis flank-milling strategy on an STL, checked exactly.\n"
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
  auto a = std::make_shared<GougeSettings>();
  auto json = std::make_shared<bool>(false);
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
  app->add_flag("--json", *json, "Print the report as JSON on stdout (and nothing else there)");
  addThreadsOption(*app, common);
  return {app, [a, json, &common]() {
            a->threads = common.threads;
            return runGougeCommand(*a, *json);
          }};
}

}  // namespace scallop
