#include "tools/cli/surface_command.h"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "base/input_error.h"
#include "tools/cli/command.h"
#include "tools/io/stl_io.h"

namespace scallop {

int runSurface(SurfaceArgs args) {
  args.spec.shape = parseSurfaceShape(args.shape);
  if (args.output.empty()) throw InputError("-o", "an output STL file is required");
  const TriangleMesh mesh = makeAnalyticSurface(args.spec);
  const std::string header =
      fmt::format("scallop surface {} {:g} x {:g} mm h={:g} mm", args.shape, args.spec.sizeX,
                  args.spec.sizeY, args.spec.heightOrDefault());
  writeStl(mesh, args.output, args.ascii ? StlFormat::Ascii : StlFormat::Binary, header);
  const Box3 box = mesh.bounds();
  if (args.json) {
    nlohmann::json j = {{"output", args.output},
                        {"format", args.ascii ? "ascii" : "binary"},
                        {"shape", args.shape},
                        {"size_mm", {args.spec.sizeX, args.spec.sizeY}},
                        {"height_mm", args.spec.heightOrDefault()},
                        {"triangles", mesh.triangles.size()},
                        {"vertices", mesh.vertices.size()},
                        {"z_range_mm", {box.min.z, box.max.z}}};
    if (args.spec.shape == SurfaceShape::Trough)
      j["trough_radius_mm"] = args.spec.troughRadiusOrDefault();
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf(
        "wrote %s: %s %g x %g mm, z in [%.6g, %.6g] mm, %zu triangles, %zu vertices (%s STL)\n",
        args.output.c_str(), args.shape.c_str(), args.spec.sizeX, args.spec.sizeY, box.min.z,
        box.max.z, mesh.triangles.size(), mesh.vertices.size(), args.ascii ? "ASCII" : "binary");
  }
  return 0;
}

namespace {

constexpr const char* kSurfaceHelp =
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
  app->add_option("--shape", args->shape, "dome | bowl | saddle | wave | plane | trough")
      ->capture_default_str();
  app->add_option("--size", *size, "X Y: extent of the surface, mm")
      ->expected(2)
      ->capture_default_str();
  app->add_option("--facets", args->spec.facets, "Approximate number of triangles (facet density)")
      ->capture_default_str();
  app->add_option("--height", args->spec.height,
                  "Height h of the shape, mm (default 0.2 min(X, Y))");
  app->add_option("--trough-radius", args->spec.troughRadius,
                  "Groove radius r of the trough, mm (default X/8)");
  app->add_option("-o,--output", args->output, "Output STL file (written atomically)")->required();
  app->add_flag("--ascii", args->ascii, "Write ASCII STL (default binary)");
  app->add_flag("--json", args->json, "Print a JSON summary on stdout (and nothing else there)");
  return {app, [args, size]() {
            args->spec.sizeX = (*size)[0];
            args->spec.sizeY = (*size)[1];
            return runSurface(*args);
          }};
}

}  // namespace scallop
