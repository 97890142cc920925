#include "tools/cli/interval_command.h"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "tools/cli/command.h"

namespace scallop {

using nlohmann::json;

namespace {

struct IntervalArgs {
  std::string tool;
  double radius = 0, cornerRadius = 0, leadDeg = 0, tiltDeg = 0, scallop = 0;
  bool json = false;
  CLI::Option* cornerOption = nullptr;
};

std::string micrometres(double mm) {
  const double um = std::fabs(mm) < 5e-7 ? 0.0 : mm * 1000;  // no "-0.000"
  return fmt::format("{:+.3f}", um);
}

void printTable(const IntervalComparison& c) {
  std::printf("%s cutter R = %g mm", toString(c.cutter.type), c.cutter.radius);
  if (c.cutter.type == CutterType::Bull)
    std::printf(", corner radius = %g mm", c.cutter.cornerRadius);
  std::printf("; lead %g deg, tilt %g deg; target scallop h = %g mm\n", c.leadDeg, c.tiltDeg,
              c.scallopMm);
  std::printf("simulated exact L/2 = %.6f mm (+c side %.6f mm, -c side %.6f mm)\n\n",
              c.exact.halfIntervalMm(), c.exact.plusMm, c.exact.minusMm);
  std::printf("%-14s %10s %18s %15s %15s  %s\n", "procedure", "L/2 [mm]", "sim. scallop [mm]",
              "error [um]", "L/2-exact [um]", "source");
  for (const ProcedureComparison& p : c.procedures) {
    if (!p.applicable) {
      std::printf("%-14s %s\n", p.name.c_str(), ("not applicable: " + p.reason).c_str());
      continue;
    }
    const std::string scallop =
        p.cusp.covered ? fmt::format("{:.6f}", p.cusp.heightMm) : std::string("uncut strip");
    const std::string error =
        p.cusp.covered ? micrometres(p.cusp.heightMm - c.scallopMm) : std::string("-");
    std::printf("%-14s %10.6f %18s %15s %15s  %s\n", p.name.c_str(), p.halfIntervalMm,
                scallop.c_str(), error.c_str(),
                micrometres(p.halfIntervalMm - c.exact.halfIntervalMm()).c_str(), p.source.c_str());
  }
  std::printf(
      "\nerror = simulated scallop left by two passes 2 L/2 apart - h; "
      "exact = where a simulated pass rises h above its floor\n");
}

int runInterval(const IntervalArgs& args) {
  const CutterType type = parseCutterType(args.tool, "--tool");
  const bool cornerGiven = args.cornerOption->count() > 0;
  if (type == CutterType::Bull && !cornerGiven) {
    // A missing option is a usage error (exit 2), not bad input.
    std::fprintf(stderr,
                 "scallop: error: --corner-radius is required for --tool bull\n"
                 "Run with --help for more information.\n");
    return 2;
  }
  IntervalRequest request;
  request.tool = args.tool;
  request.radiusMm = args.radius;
  request.cornerRadiusMm = args.cornerRadius;
  request.cornerGiven = cornerGiven;
  request.leadDeg = args.leadDeg;
  request.tiltDeg = args.tiltDeg;
  request.scallopMm = args.scallop;
  const IntervalComparison comparison = compareIntervals(request);
  if (args.json)
    std::printf("%s\n", toJson(comparison).dump(2).c_str());
  else
    printTable(comparison);
  return 0;
}

constexpr const char* kIntervalHelp =
    "Path interval (half step-over L/2, mm) for a scallop height h by every procedure of\n"
    "the seeds (computational: seed 000 Fig. 1; sekine, redonnet, bedi: seed 000 Eqs.\n"
    "(4)-(11); ball: seed 001 Eq. (1)), each with the scallop that two simulated passes\n"
    "2 L/2 apart really leave and its error against h (um); and the simulated exact L/2,\n"
    "where a single simulated pass rises h above its floor (exact to 1e-10 mm, not\n"
    "limited by a grid). The pass feeds along +x; lead tilts the axis towards the feed,\n"
    "tilt towards the cross-feed +c; with a tilt the two sides differ and both are given.\n"
    "Example: scallop interval --tool bull --radius 3 --corner-radius 1 --lead 5 --scallop 0.05";

}  // namespace

Command addIntervalCommand(CLI::App& parent, CommonOptions& common) {
  auto args = std::make_shared<IntervalArgs>();
  CLI::App* app = parent.add_subcommand("interval", kIntervalHelp);
  app->add_option("--tool", args->tool, "Cutter type: ball, bull or flat")->required();
  app->add_option("--radius", args->radius, "Cutter radius R, mm (> 0)")->required();
  args->cornerOption = app->add_option(
      "--corner-radius", args->cornerRadius,
      "Corner radius r of a bull cutter, mm (0 < r < R); required for --tool bull only");
  app->add_option("--lead", args->leadDeg,
                  "Lead: axis inclined towards the feed, deg (|lead| < 90; default 0)");
  app->add_option("--tilt", args->tiltDeg,
                  "Tilt: axis inclined towards the cross-feed, deg (|tilt| < 90; default 0)");
  app->add_option("--scallop", args->scallop, "Scallop height h, mm (> 0)")->required();
  app->add_flag("--json", args->json, "Print one JSON document on stdout (and nothing else there)");
  addThreadsOption(*app, common);
  return {app, [args]() { return runInterval(*args); }};
}

}  // namespace scallop
