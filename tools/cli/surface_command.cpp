#include "tools/cli/surface_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "base/input_error.h"
#include "tools/cli/command.h"

namespace scallop {

int runSurface(SurfaceArgs args) {
  const nlohmann::json j = writeAnalyticSurface(args.settings);
  if (args.json) {
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf(
        "wrote %s: %s %g x %g mm, z in [%.6g, %.6g] mm, %zu triangles, %zu vertices (%s STL)\n",
        args.settings.output.c_str(), args.settings.shape.c_str(), args.settings.spec.sizeX,
        args.settings.spec.sizeY, j["z_range_mm"][0].get<double>(),
        j["z_range_mm"][1].get<double>(), j["triangles"].get<size_t>(), j["vertices"].get<size_t>(),
        args.settings.ascii ? "ASCII" : "binary");
  }
  return 0;
}

namespace {

constexpr const char* kSurfaceHelp =
    "Write a faceted analytic test surface as STL.\n"
    "Write a faceted test surface as STL: analytic height fields over [0, X] x [0, Y] mm,\n"
    "sampled on a regular grid (two triangles per cell, normals up), standing in for the\n"
    "convex, concave, saddle and mixed test models of seed 004 (u = 2x/X - 1, v = 2y/Y - 1):\n"
    "  dome    z = h (1 - (u^2 + v^2)/2)             convex\n"
    "  bowl    z = h (u^2 + v^2)/2                   concave\n"
    "  saddle  z = h (1 + u^2 - v^2)/2               saddle\n"
    "  wave    z = h (1 + sin(1.5 pi u) cos(pi v))/2 mixed\n"
    "  plane   z = 0\n"
    "  trough  z = 0 with a cylindrical groove of radius r, depth min(h, r), along y at x = X/2";

}  // namespace

Command addSurfaceCommand(CLI::App& parent, CommonOptions&) {
  auto args = std::make_shared<SurfaceArgs>();
  auto size = std::make_shared<std::vector<double>>(std::vector<double>{100, 100});
  CLI::App* app = parent.add_subcommand("surface", kSurfaceHelp);
  app->add_option("--shape", args->settings.shape, "dome | bowl | saddle | wave | plane | trough")
      ->capture_default_str();
  app->add_option("--size", *size, "X Y: extent of the surface, mm")
      ->expected(2)
      ->capture_default_str();
  app->add_option("--facets", args->settings.spec.facets,
                  "Approximate number of triangles (facet density)")
      ->capture_default_str();
  app->add_option("--height", args->settings.spec.height,
                  "Height h of the shape, mm (default 0.2 min(X, Y))");
  app->add_option("--trough-radius", args->settings.spec.troughRadius,
                  "Groove radius r of the trough, mm (default X/8)");
  app->add_option("-o,--output", args->settings.output, "Output STL file (written atomically)")
      ->required();
  app->add_flag("--ascii", args->settings.ascii, "Write ASCII STL (default binary)");
  app->add_flag("--json", args->json, "Print a JSON summary on stdout (and nothing else there)");
  return {app, [args, size]() {
            args->settings.spec.sizeX = (*size)[0];
            args->settings.spec.sizeY = (*size)[1];
            return runSurface(*args);
          }};
}

}  // namespace scallop
