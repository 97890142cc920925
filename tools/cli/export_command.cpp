#include "tools/cli/export_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "analysis/profile_metrology.h"
#include "sweep/input_error.h"
#include "tools/cli/command.h"
#include "tools/io/file_names.h"
#include "tools/io/height_export.h"
#include "tools/io/height_images.h"
#include "tools/io/x3p_writer.h"

namespace scallop {

namespace {

struct ExportArgs {
  std::string file, to;
  std::vector<double> profile;
  double cutoffMm = 0.8, stepMm = 0;
};

int runExport(const ExportArgs& args) {
  const std::string ext = lowerExtension(args.to);
  const bool known = ext == ".x3p" || ext == ".png" || ext == ".tif" || ext == ".tiff" ||
                     ext == ".gsf" || ext == ".exr" || ext == ".csv";
  if (!known || (ext == ".csv") != !args.profile.empty()) {
    std::fprintf(stderr, "scallop export: error: %s\n",
                 !known ? "--to: expected a file name ending in .x3p, .png, .tif, .tiff, .gsf, "
                          ".exr or .csv"
                 : ext == ".csv" ? "--to .csv writes a profile: give --profile x0 y0 x1 y1"
                                 : "--profile goes with a .csv output only");
    return 2;
  }
  const ZMap map = readHeightFile(args.file);
  const std::string title = "scallop height map from " + args.file;
  if (ext == ".x3p") {
    writeHeightsX3p(map, args.to, title);
  } else if (ext == ".png" || ext == ".tif" || ext == ".tiff") {
    writeHeights16(map, args.to);
  } else if (ext == ".gsf") {
    writeHeightsGsf(map, args.to, title);
  } else if (ext == ".exr") {
    writeHeightsExr(map, args.to);
  } else {
    const Profile p = extractProfile(map, args.profile[0], args.profile[1], args.profile[2],
                                     args.profile[3], args.stepMm, "--profile");
    // The roughness column is filled when the profile is long enough for the cutoff.
    const double needMm = 3 * args.cutoffMm;
    const double lengthMm = double(p.height.size() - 1) * p.stepMm;
    if (lengthMm >= needMm) {
      const RoughnessStats r = roughness(p, args.cutoffMm, "--cutoff");
      writeProfileCsv(p, &r, args.to);
    } else {
      writeProfileCsv(p, nullptr, args.to);
    }
  }
  std::fprintf(stderr, "scallop: wrote %s\n", args.to.c_str());
  return 0;
}

}  // namespace

Command addExportCommand(CLI::App& parent, CommonOptions&) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* app = parent.add_subcommand(
      "export",
      "Convert a height map written by scallop (FILE.gsf or FILE.exr) for metrology software.\n"
      "The format follows --to's extension:\n"
      "  .x3p         ISO 25178-72 / ISO 5436-2 X3P (zip: main.xml, bindata/data.bin float64\n"
      "               heights in m, MD5 checksums); Gwyddion, MountainsMap, openGPS read it\n"
      "  .png .tif    16-bit grey, z_mm = z_offset_mm + z_scale_mm * value, both numbers in\n"
      "               the metadata (ImageDescription, and PNG text chunks); north up\n"
      "  .gsf .exr    the simulate outputs' formats (conversion between them)\n"
      "  .csv         with --profile: distance_mm,x_mm,y_mm,z_mm,roughness_mm per sample\n"
      "               (roughness: ISO 16610-21 Gaussian filter of --cutoff, when the line is\n"
      "               at least 3 cutoffs long; empty in the run-in and run-out)");
  app->add_option("FILE", args->file, "Height map: .gsf or .exr")->required();
  app->add_option("--to", args->to, "Output file; its extension picks the format")->required();
  app->add_option("--profile", args->profile, "x0 y0 x1 y1: the profile line for .csv, mm")
      ->expected(4)
      ->allow_extra_args(false);
  app->add_option("--cutoff", args->cutoffMm, "Gaussian filter cutoff lc for .csv, mm")
      ->capture_default_str();
  app->add_option("--step", args->stepMm, "Profile sample spacing, mm (default: grid spacing)");
  return {app, [args]() { return runExport(*args); }};
}

}  // namespace scallop
