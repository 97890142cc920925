#include "tools/cli/stats_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "tools/cli/command.h"
#include "tools/io/height_export.h"
#include "tools/run/profile_roughness.h"
#include "tools/run/stats_document.h"

namespace scallop {

using nlohmann::json;

namespace {

struct StatsArgs {
  std::string file;
  std::vector<double> region, profile;
  std::string level = "plane";
  double cutoffMm = 0.8, lambdaSMm = 0, stepMm = 0;
  bool unfiltered = false, json = false;
};

int runStats(const StatsArgs& args) {
  const ZMap map = readHeightFile(args.file);
  const GridSpec& g = map.grid();
  const CellRegion region = statsRegion(g, args.region, "--region");
  SurfaceStats s;
  json doc = surfaceStatsDocument(map, region, parseLevelling(args.level, "--level"), &s);
  doc["file"] = args.file;
  std::optional<ProfileRoughness> profile;
  if (!args.profile.empty()) {
    RoughnessFilter filter;
    filter.cutoffMm = args.unfiltered ? 0 : args.cutoffMm;
    filter.lambdaSMm = args.lambdaSMm;
    if (!args.unfiltered && !(args.cutoffMm > 0))
      throw InputError("--cutoff", "must be a positive length in mm (use --unfiltered for none)");
    profile = profileRoughness(map, args.profile, args.stepMm, filter, "--profile",
                               args.lambdaSMm > 0 ? "--lambda-s" : "--cutoff");
    doc["profile"] = profileRoughnessDocument(*profile);
  }
  if (args.json) {
    std::printf("%s\n", doc.dump(2).c_str());
    return 0;
  }
  const auto& r = doc["region_mm"];
  std::printf(
      "%s: %lld x %lld cells of %g mm; region [%g, %g] x [%g, %g] mm (%lld cells), "
      "levelling: %s\n",
      args.file.c_str(), (long long)g.nx, (long long)g.ny, g.spacing, r[0].get<double>(),
      r[2].get<double>(), r[1].get<double>(), r[3].get<double>(), (long long)s.cells,
      args.level == "none" ? "none (heights from the mean)" : "least-squares plane");
  std::printf(
      "  Sa  = %.6g mm\n  Sq  = %.6g mm\n  Ssk = %.6g\n  Sku = %.6g  (plain kurtosis: "
      "3 for a Gaussian surface; Gwyddion shows Sku - 3)\n  Sp  = %.6g mm\n"
      "  Sv  = %.6g mm\n  Sz  = %.6g mm\n",
      s.sa, s.sq, s.ssk, s.sku, s.sp, s.sv, s.sz);
  if (profile) {
    const Profile& l = profile->profile;
    const RoughnessStats& rough = profile->roughness;
    std::printf(
        "profile (%g, %g) -> (%g, %g) mm; filter: %s;\n"
        "  evaluation length %g mm from %g mm along the line, %d sampling length(s) of %g mm:\n"
        "  Ra  = %.6g mm\n  Rq  = %.6g mm\n  Rz  = %.6g mm\n  Rt  = %.6g mm\n  Rsm = %s\n",
        l.x0, l.y0, l.x1, l.y1, rough.filter.name().c_str(), rough.evaluationLengthMm,
        rough.evaluationStartMm, rough.samplingLengths, rough.samplingLengthMm, rough.ra, rough.rq,
        rough.rz, rough.rt,
        std::isfinite(rough.rsm) ? fmt::format("{:.6g} mm", rough.rsm).c_str()
                                 : "none (fewer than two profile elements)");
  }
  return 0;
}

}  // namespace

Command addStatsCommand(CLI::App& parent, CommonOptions& common) {
  auto args = std::make_shared<StatsArgs>();
  CLI::App* app = parent.add_subcommand(
      "stats",
      "ISO 25178-2 height parameters (Sa, Sq, ...) of a height map.\n"
      "Sa, Sq, Ssk, Sku, Sp, Sv, Sz of a height map (FILE.gsf, FILE.exr or FILE.x3p), over\n"
      "the whole map or a --region, after least-squares plane levelling (default) or none\n"
      "(heights from the mean). Sku is the plain kurtosis (3 for a Gaussian surface;\n"
      "Gwyddion shows the excess, Sku - 3). With --profile, also\n"
      "Ra, Rq, Rz, Rt, Rsm (ISO 4287 / 21920-2) of the line's roughness profile: ISO 16610-21\n"
      "Gaussian filter of cutoff --cutoff (lc), optionally --lambda-s (ls), up to 5 sampling\n"
      "lengths (ISO 4288), run-in/out of one cutoff each; or --unfiltered: the profile less\n"
      "its least-squares line, one sampling length (feed marks as a ruler measures them).\n"
      "The output names the filter, the evaluation length and the sampling lengths.\n"
      "Cell (i, j) is one sample at its centre. Lengths in mm.");
  app->add_option("FILE", args->file, "Height map: .gsf (Gwyddion Simple Field), .exr or .x3p")
      ->required();
  app->add_option("--region", args->region,
                  "x0 y0 x1 y1: only the cells whose centres lie in this rectangle, mm")
      ->expected(4)
      ->allow_extra_args(false);
  app->add_option("--level", args->level,
                  "plane: heights from the least-squares plane; none: from the mean height")
      ->check(CLI::IsMember({"plane", "none"}))
      ->capture_default_str();
  app->add_option("--profile", args->profile,
                  "x0 y0 x1 y1: also the roughness of this line's profile, mm")
      ->expected(4)
      ->allow_extra_args(false);
  app->add_option("--cutoff", args->cutoffMm,
                  "Gaussian filter cutoff lc, mm (ISO 4288: 0.08, 0.25, 0.8, 2.5 or 8 for Ra\n"
                  "up to 0.02, 0.1, 2, 10, 80 um)")
      ->capture_default_str();
  app->add_option("--lambda-s", args->lambdaSMm,
                  "Short-wave Gaussian cutoff ls, mm (ISO 3274: 0.0025 or 0.008); default none:\n"
                  "a z-map is already sampled at its grid spacing");
  app->add_flag("--unfiltered", args->unfiltered,
                "No lc filter: Ra ... Rsm of the profile less its least-squares line");
  app->add_option("--step", args->stepMm, "Profile sample spacing, mm (default: grid spacing)");
  addThreadsOption(*app, common);
  app->add_flag("--json", args->json, "Print one JSON document on stdout (and nothing else)");
  return {app, [args]() { return runStats(*args); }};
}

}  // namespace scallop
