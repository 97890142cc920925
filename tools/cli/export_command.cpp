#include "tools/cli/export_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "tools/cli/command.h"
#include "tools/io/file_names.h"
#include "tools/io/height_export.h"
#include "tools/io/height_formats.h"
#include "tools/run/map_export.h"

namespace scallop {

namespace {

struct ExportArgs {
  std::string file, to;
  std::vector<double> profile;
  double cutoffMm = 0.8, stepMm = 0;
  // --hillshade and the options that go with it only.
  bool hillshade = false, colour = false;
  Light light;
  double exaggeration = NAN;  // NaN: automatic
  std::vector<double> region;
  std::string title;
  std::vector<std::string> hillshadeOnly;  // those of them given, for the usage check
};

int writeHillshade(const ExportArgs& args, const ZMap& map) {
  auto given = [&args](const char* name) {
    return std::find(args.hillshadeOnly.begin(), args.hillshadeOnly.end(), name) !=
           args.hillshadeOnly.end();
  };
  // NaN is how the picture asks for the automatic value: typed out, it is bad input.
  if (std::isnan(args.exaggeration) && given("--exaggeration"))
    throw InputError("--exaggeration", "must be a factor in (0, 1e6], got nan");
  HillshadeOptions options;
  options.light = args.light;
  options.exaggeration = args.exaggeration;
  options.colour = args.colour;
  options.title = given("--title")
                      ? args.title
                      : "hill shade of " + std::filesystem::path(args.file).filename().string();
  const HillshadeExport e = exportHillshade(map, args.region, options, args.to, "--region");
  std::fprintf(stderr, "scallop: wrote %s (%lld x %lld cells, heights x %g)\n", args.to.c_str(),
               (long long)e.cellsX, (long long)e.cellsY, e.exaggeration);
  return 0;
}

// The usage errors (exit 2) of --to, --profile and --hillshade; empty when none.
std::string usageError(const ExportArgs& args, const std::string& ext) {
  if (!findHeightFormat(args.to) && ext != ".csv")
    return "--to: expected a file name ending in " + heightExtensions(false) +
           " (heights) or .csv (a profile)";
  if (ext == ".csv" && args.profile.empty())
    return "--to .csv writes a profile: give --profile x0 y0 x1 y1";
  if (ext != ".csv" && !args.profile.empty()) return "--profile goes with a .csv output only";
  if (args.hillshade && ext != ".png")
    return "--hillshade writes a picture: give --to a file name ending in .png";
  if (!args.hillshade && !args.hillshadeOnly.empty())
    return args.hillshadeOnly.front() + " goes with --hillshade only";
  return "";
}

int runExport(const ExportArgs& args) {
  const std::string ext = lowerExtension(args.to);
  const std::string usage = usageError(args, ext);
  if (!usage.empty()) {
    std::fprintf(stderr, "scallop export: error: %s\n", usage.c_str());
    return 2;
  }
  std::string frame;
  const ZMap map = readHeightFile(args.file, &frame);
  if (args.hillshade) return writeHillshade(args, map);
  const std::string title = "scallop height map from " + args.file;
  if (ext == ".csv")
    exportProfileCsv(map, args.profile, args.stepMm, args.cutoffMm, args.to, "--profile",
                     "--cutoff");
  else
    exportHeightMap(map, args.to, title, frame);
  std::fprintf(stderr, "scallop: wrote %s\n", args.to.c_str());
  return 0;
}

}  // namespace

Command addExportCommand(CLI::App& parent, CommonOptions&) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* app = parent.add_subcommand(
      "export",
      "Convert a height map to X3P, TIFF, PNG or a CSV profile.\n"
      "Convert a height map (FILE.gsf, FILE.exr or FILE.x3p) for metrology software.\n"
      "The format follows --to's extension:\n"
      "  .x3p         ISO 25178-72 / ISO 5436-2 X3P (zip: main.xml, bindata/data.bin float64\n"
      "               heights in m, MD5 checksums); Gwyddion, MountainsMap, openGPS read it\n"
      "  .png .tif    16-bit grey, z_mm = z_offset_mm + z_scale_mm * value, both numbers in\n"
      "               the metadata (ImageDescription, and PNG text chunks); north up\n"
      "  .gsf .exr    the simulate outputs' formats (conversion between them)\n"
      "  .csv         with --profile: distance_mm,x_mm,y_mm,z_mm,roughness_mm per sample\n"
      "               (roughness: ISO 16610-21 Gaussian filter of --cutoff, when the line is\n"
      "               at least 3 cutoffs long; empty in the run-in and run-out)\n"
      "With --hillshade, --to OUT.png is instead a picture for people: the surface lit as a\n"
      "relief (Lambert light from --azimuth, --elevation), grey, or with --colour\n"
      "preview.png's picture (the same renderer, colours and exaggeration rule; cells\n"
      "without material white); heights exaggerated by --exaggeration (default: automatic, so\n"
      "that micrometre scallops and feed marks show), the factor and the light in the\n"
      "legend, with a scale bar; --region crops it. Maps larger than 1600 cells a side\n"
      "are reduced (block minimum).");
  app->add_option("FILE", args->file, "Height map: .gsf, .exr or .x3p")->required();
  app->add_option("--to", args->to, "Output file; its extension picks the format")->required();
  app->add_option("--profile", args->profile, "x0 y0 x1 y1: the profile line for .csv, mm")
      ->expected(4)
      ->allow_extra_args(false);
  app->add_option("--cutoff", args->cutoffMm, "Gaussian filter cutoff lc for .csv, mm")
      ->capture_default_str();
  app->add_option("--step", args->stepMm, "Profile sample spacing, mm (default: grid spacing)");
  app->add_flag("--hillshade", args->hillshade,
                "--to .png is a hill-shaded picture, not 16-bit heights");
  CLI::Option* options[] = {
      app->add_option("--azimuth", args->light.azimuthDeg,
                      "Where the light comes from, degrees clockwise from north (+y)")
          ->capture_default_str(),
      app->add_option("--elevation", args->light.elevationDeg,
                      "Light above the horizon, degrees, in (0, 90]")
          ->capture_default_str(),
      app->add_option("--exaggeration", args->exaggeration,
                      "Vertical exaggeration, in (0, 1e6] (default: automatic)"),
      app->add_flag("--colour,--color", args->colour,
                    "Blend the preview's height colours (viridis) with the shading"),
      app->add_option("--region", args->region, "x0 y0 x1 y1: only the cells in it, mm")
          ->expected(4)
          ->allow_extra_args(false),
      app->add_option("--title", args->title,
                      "Drawn above the map (default: the file's name; \"\": none)")};
  app->final_callback([app, args, options]() {
    for (CLI::Option* o : options)
      if (o->count() > 0) args->hillshadeOnly.push_back(o->get_name());
  });
  return {app, [args]() { return runExport(*args); }};
}

}  // namespace scallop
