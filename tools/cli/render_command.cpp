#include "tools/cli/render_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "tools/cli/command.h"
#include "tools/cli/interrupt.h"
#include "tools/cli/progress.h"
#include "tools/run/render_run.h"
#include "tools/run/stopwatch.h"

namespace scallop {

namespace {

struct RenderArgs {
  RenderRequest request;
  std::vector<int> size{1600, 1000};
  std::vector<double> view{210, 40}, light{315, 45};
  std::string projection = "ortho", colourMap = "viridis";
  bool titleGiven = false;
};

int runRenderCommand(RenderArgs& args) {
  const auto tStart = Clock::now();
  RenderOptions& o = args.request.options;
  o.widthPx = args.size[0], o.heightPx = args.size[1];
  o.view = {args.view[0], args.view[1]};
  o.light = {args.light[0], args.light[1]};
  o.projection =
      args.projection == "perspective" ? Projection::kPerspective : Projection::kOrthographic;
  o.colourMap = parseColourMap(args.colourMap, "--colormap");
  if (!args.titleGiven) o.title = args.request.heights;
  ProgressBar bar("rendering");
  o.progress = [&bar](int64_t done, int64_t total) {
    bar.update(done, total);
    throwIfInterrupted();  // Ctrl-C: stop tracing, write nothing
  };
  const RenderSummary s = runRender(args.request);
  bar.finish();
  std::fprintf(stderr,
               "scallop: wrote %s (%d x %d px; heights x %g%s; surface from %lld x %lld nodes, "
               "means of %d x %d cells; %.2f s)\n",
               args.request.output.c_str(), o.widthPx, o.heightPx, s.exaggeration,
               s.automaticExaggeration ? ", automatic" : "", (long long)s.nodesX,
               (long long)s.nodesY, s.blockCells, s.blockCells, secondsSince(tStart));
  return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& parent, CommonOptions& common) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* app = parent.add_subcommand(
      "render",
      "Draw a height map in 3-D, ray-traced with light, shadows and a colour bar.\n"
      "A picture for papers and reports, ray-traced with Embree: the surface in oblique\n"
      "light with shadows, coloured by height, on walls down to a base,\n"
      "a colour bar in um (or mm), a box with ticks in mm, and a note of the vertical\n"
      "exaggeration, light and view. HEIGHTS is any height map scallop reads: .gsf, .exr,\n"
      ".x3p, the 16-bit .png/.tif of `scallop export`, or a folder of `simulate --bands`\n"
      "files (not merged). The surface is bilinear between the cell centres (cells without\n"
      "a height, NaN, leave a hole). Anti-aliasing: the surface is traced from block means\n"
      "of k x k cells, k = the finest pixel footprint over the spacing, smoothed by\n"
      "[1 2 1]/4 along x and y (a prefiltered mip-map level), at a fixed 2 x 2 grid of\n"
      "samples a pixel, so marks finer than a pixel are averaged, not aliased into moire;\n"
      "render a --region to see them. The same bytes whatever --threads. Angles in degrees: "
      "azimuth\n"
      "clockwise from north (+y), elevation above the horizon in (0, 90]; `--view 180 90\n"
      "--projection ortho` is the map seen from straight above, north up.");
  app->add_option("HEIGHTS", args->request.heights, "Height map file, or a folder of band files")
      ->required();
  app->add_option("-o,--output", args->request.output, "The picture to write, .png")->required();
  app->add_option("--size", args->size, "W H: the picture's width and height, px, in [1, 16384]")
      ->expected(2)
      ->allow_extra_args(false)
      ->capture_default_str();
  app->add_option("--view", args->view,
                  "AZ EL: where the camera stands, seen from the surface's middle")
      ->expected(2)
      ->allow_extra_args(false)
      ->capture_default_str();
  app->add_option("--light", args->light, "AZ EL: where the light comes from")
      ->expected(2)
      ->allow_extra_args(false)
      ->capture_default_str();
  app->add_option("--exaggeration", args->request.options.exaggeration,
                  "Vertical exaggeration, in (0, 1e6] (default: the relief, the colour range,\n"
                  "a fifth of the region's longer side, to two digits; printed on the picture)");
  app->add_option("--projection", args->projection, "ortho or perspective")
      ->check(CLI::IsMember({"ortho", "perspective"}))
      ->capture_default_str();
  app->add_option("--region", args->request.region,
                  "x0 y0 x1 y1: only the cells whose centres lie in this rectangle, mm")
      ->expected(4)
      ->allow_extra_args(false);
  app->add_option("--colormap", args->colourMap,
                  "viridis (preview.png's) or grey; the colour range is preview.png's (robust\n"
                  "percentiles of the region)")
      ->check(CLI::IsMember({"viridis", "grey", "gray"}))
      ->capture_default_str();
  app->add_option("--title", args->request.options.title,
                  "Drawn above the picture (default: HEIGHTS; \"\": none)")
      ->each([args](const std::string&) { args->titleGiven = true; });
  addThreadsOption(*app, common);
  return {app, [args]() { return runRenderCommand(*args); }};
}

}  // namespace scallop
