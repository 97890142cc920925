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
  double feedPerTooth = 0, runout = 0;
  int flutes = 2;
  bool json = false;
  CLI::Option* cornerOption = nullptr;
  CLI::Option* feedOption = nullptr;
};

std::string micrometres(double mm) {
  const double um = std::fabs(mm) < 5e-7 ? 0.0 : mm * 1000;  // no "-0.000"
  return fmt::format("{:+.3f}", um);
}

// Along the feed: the feed marks' closed form (analysis/feed_mark_formula.h).
void printFeedMarks(const IntervalComparison& c) {
  const FeedMarkPrediction& f = c.feedMarks;
  std::printf("\nfeed marks along the pass centre line, fz = %g mm, %d flutes, runout %g mm:\n",
              c.feedPerToothMm, c.cutter.teeth.flutes, c.cutter.teeth.runout);
  if (!f.applicable) {
    std::printf("  not applicable: %s\n", f.reason.c_str());
    return;
  }
  const char* arc = c.cutter.type == CutterType::Ball   ? "the ball's R"
                    : c.cutter.type == CutterType::Bull ? "the corner radius r"
                                                        : "the profile's arc at the contact";
  std::printf("  rho_f = %g mm (%s), marks %g mm apart (%s)\n", f.profileRadiusMm, arc, f.spacingMm,
              f.regime.c_str());
  std::printf(
      "  h_f = %.6f um (the teeth's arcs as circles; without runout rho_f - sqrt(rho_f^2 - "
      "s^2/4)), %.6f um (as parabolas; s^2 / (8 rho_f))\n",
      f.heightMm * 1e3, f.heightParabolaMm * 1e3);
  if (f.hasRunoutThreshold)
    std::printf(
        "  runout threshold rho* = %.6f um: above it one tooth cuts alone (marks 2 fz "
        "apart)\n",
        f.runoutThresholdMm * 1e3);
}

void printTable(const IntervalComparison& c) {
  std::printf("%s cutter R = %g mm", toString(c.cutter.type), c.cutter.radius);
  if (c.cutter.type == CutterType::Bull)
    std::printf(", corner radius = %g mm", c.cutter.cornerRadius);
  std::printf("; lead %g deg, tilt %g deg; target scallop h = %g mm\n", c.leadDeg, c.tiltDeg,
              c.scallopMm);
  std::printf("simulated exact L/2 = %.6f mm (+c side %.6f mm, -c side %.6f mm)\n\n",
              c.exact.halfIntervalMm(), c.exact.plusMm, c.exact.minusMm);
  std::printf("%-16s %10s %18s %15s %15s  %s\n", "procedure", "L/2 [mm]", "sim. scallop [mm]",
              "error [um]", "L/2-exact [um]", "source");
  for (const ProcedureComparison& p : c.procedures) {
    if (!p.applicable) {
      std::printf("%-16s %s\n", p.name.c_str(), ("not applicable: " + p.reason).c_str());
      continue;
    }
    const std::string scallop =
        p.cusp.covered ? fmt::format("{:.6f}", p.cusp.heightMm) : std::string("uncut strip");
    const std::string error =
        p.cusp.covered ? micrometres(p.cusp.heightMm - c.scallopMm) : std::string("-");
    std::printf("%-16s %10.6f %18s %15s %15s  %s\n", p.name.c_str(), p.halfIntervalMm,
                scallop.c_str(), error.c_str(),
                micrometres(p.halfIntervalMm - c.exact.halfIntervalMm()).c_str(), p.source.c_str());
  }
  std::printf(
      "\nerror = simulated scallop left by two passes 2 L/2 apart - h; "
      "exact = where a simulated pass rises h above its floor\n");
  if (c.feedPerToothMm > 0) printFeedMarks(c);
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
  request.feedPerToothGiven = args.feedOption->count() > 0;
  request.feedPerToothMm = args.feedPerTooth;
  request.flutes = args.flutes;
  request.runoutMm = args.runout;
  const IntervalComparison comparison = compareIntervals(request);
  if (args.json)
    std::printf("%s\n", toJson(comparison).dump(2).c_str());
  else
    printTable(comparison);
  return 0;
}

constexpr const char* kIntervalHelp =
    "Path interval (step-over) for a scallop height, by every procedure.\n"
    "Path interval (half step-over L/2, mm) for a scallop height h by every procedure of\n"
    "the seeds (computational: seed 000 Fig. 1; sekine, redonnet, bedi: seed 000 Eqs.\n"
    "(4)-(11); ball: seed 001 Eq. (1)) and by the two that take any cutter, lead and tilt\n"
    "(exact: the cutter's shadow along the feed, to 1e-9 mm; effective_radius: the\n"
    "osculating circle at the contact), each with the scallop that two simulated passes\n"
    "2 L/2 apart really leave and its error against h (um); and the simulated exact L/2,\n"
    "where a single simulated pass rises h above its floor (exact to 1e-10 mm, not\n"
    "limited by a grid). The pass feeds along +x; lead tilts the axis towards the feed,\n"
    "tilt towards the cross-feed +c; with a tilt the two sides differ and both are given.\n"
    "Example: scallop interval --tool bull --radius 3 --corner-radius 1 --lead 5 --scallop 0.05\n"
    "\n"
    "Along the feed (--feed-per-tooth fz): the teeth leave feed marks on the pass centre\n"
    "line. With a lead, each tooth passes the contact point fz after the one before and\n"
    "leaves there the circle of the cutter's feed-direction profile, rho_f = R for a ball,\n"
    "r for a bull (its contact is on the corner), so the marks are arcs of chord fz:\n"
    "  h_f = rho_f - sqrt(rho_f^2 - fz^2/4) ~ fz^2 / (8 rho_f)   (0 < |lead| < 90, no tilt;\n"
    "  not for a flat end mill, whose corner is sharp, nor without lead, where every tooth\n"
    "  passes the tip). With 2 flutes a runout rho lowers one tooth by 2 rho sin(lead) and\n"
    "  shifts the marks by 2 rho cos(lead); above\n"
    "  rho* = (-rho_f sin(lead) + sqrt(rho_f^2 sin^2(lead) + fz^2 cos^2(lead))) / (2 cos^2(lead))\n"
    "  ~ fz^2 / (4 rho_f sin(lead)) the other tooth no longer cuts there: marks 2 fz apart.\n"
    "Example: scallop interval --tool ball --radius 3 --lead 15 --scallop 0.01 "
    "--feed-per-tooth 0.1\n"
    "  (h_f = 0.417 um, rho* = 3.21 um; docs/teeth.md has the derivation)";

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
  args->feedOption = app->add_option(
      "--feed-per-tooth", args->feedPerTooth,
      "Feed per tooth fz, mm (> 0): adds the feed marks' height h_f along the pass\n"
      "(feed per minute / (rpm x flutes))");
  app->add_option("--flutes", args->flutes,
                  "Teeth of the cutter, 1-16 (default 2); the runout threshold needs 2");
  app->add_option(
      "--runout", args->runout,
      "Runout rho, mm, of tooth 0 towards the contact (0 <= rho <= R / 10; default 0):\n"
      "below rho* both teeth cut (their cusps by parabolic arcs), above it one");
  app->add_flag("--json", args->json, "Print one JSON document on stdout (and nothing else there)");
  addThreadsOption(*app, common);
  return {app, [args]() { return runInterval(*args); }};
}

}  // namespace scallop
