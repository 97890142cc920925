#include "tools/cli/interval_command.h"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "analysis/path_interval.h"
#include "sweep/input_error.h"
#include "tools/cli/command.h"

namespace scallop {

using nlohmann::json;

namespace {

json numberOrNull(bool valid, double v) {
  return valid ? json(v) : json(nullptr);
}

}  // namespace

IntervalComparison compareIntervals(const SimulatedPass& pass, double scallopMm) {
  IntervalComparison out;
  out.cutter = pass.cutter();
  out.leadDeg = pass.leadDeg();
  out.tiltDeg = pass.tiltDeg();
  out.scallopMm = scallopMm;
  out.exact = pass.halfIntervals(scallopMm);

  const Cutter& c = pass.cutter();
  if (c.type == CutterType::Flat) {
    for (const ProcedureInfo& procedure : kProcedures) {
      ProcedureComparison p;
      p.name = procedure.name;
      p.source = procedure.source;
      p.reason = p.name + ": the seeds give no procedure for a flat end mill (seed 000 " +
                 "covers filleted, seed 001 Eq. (1) ball end mills)";
      out.procedures.push_back(p);
    }
    return out;
  }
  ProcedureTool tool;
  tool.type = c.type == CutterType::Ball ? ProcedureToolType::Ball : ProcedureToolType::Bull;
  tool.radiusMm = c.radius;
  tool.cornerRadiusMm = c.type == CutterType::Ball ? 0 : c.cornerRadius;
  for (const NamedProcedureResult& r : halfIntervalProcedures(tool, pass.leadDeg(), scallopMm)) {
    ProcedureComparison p;
    p.name = r.name;
    p.source = r.source;
    p.applicable = r.result.applicable;
    p.reason = r.result.reason;
    // A ball's sphere looks the same in every posture; a torus does not, and the
    // filleted procedures of seed 000 model the inclination along the feed only.
    if (p.applicable && c.type == CutterType::Bull && pass.tiltDeg() != 0) {
      p.applicable = false;
      p.reason = r.name + ": seed 000 models inclination along the feed only; tilt = " +
                 fmt::format("{:g}", pass.tiltDeg()) + " deg is outside it";
    }
    if (p.applicable) {
      p.halfIntervalMm = r.result.value;
      p.cusp = pass.cusp(2 * p.halfIntervalMm);
    }
    out.procedures.push_back(p);
  }
  return out;
}

json toolJson(const Cutter& cutter) {
  json t = {{"type", toString(cutter.type)}, {"radius", cutter.radius}};
  if (cutter.type == CutterType::Bull) t["corner_radius"] = cutter.cornerRadius;
  return t;
}

json toJson(const IntervalComparison& c) {
  json doc;
  doc["tool"] = toolJson(c.cutter);
  doc["lead_deg"] = c.leadDeg;
  doc["tilt_deg"] = c.tiltDeg;
  doc["scallop"] = c.scallopMm;
  doc["simulated_half_interval"] = c.exact.halfIntervalMm();
  doc["simulated_half_interval_plus"] = c.exact.plusMm;
  doc["simulated_half_interval_minus"] = c.exact.minusMm;
  json procs = json::array();
  for (const ProcedureComparison& p : c.procedures) {
    const bool simulated = p.applicable && p.cusp.covered;
    procs.push_back({{"name", p.name},
                     {"source", p.source},
                     {"applicable", p.applicable},
                     {"reason", p.reason},
                     {"half_interval", numberOrNull(p.applicable, p.halfIntervalMm)},
                     {"simulated_scallop", numberOrNull(simulated, p.cusp.heightMm)},
                     {"scallop_error", numberOrNull(simulated, p.cusp.heightMm - c.scallopMm)},
                     {"half_interval_error",
                      numberOrNull(p.applicable, p.halfIntervalMm - c.exact.halfIntervalMm())}});
  }
  doc["procedures"] = procs;
  doc["units"] = {{"length", "mm"}, {"angle", "deg"}};
  return doc;
}

void checkAngleOption(const char* option, double deg) {
  if (!std::isfinite(deg) || std::fabs(deg) >= 90)
    throw InputError(
        option, "must be an angle in degrees with |angle| < 90, got " + fmt::format("{:g}", deg));
}

Cutter cutterFromOptions(const std::string& tool, double radius, double cornerRadius,
                         bool cornerGiven) {
  const CutterType type = parseCutterType(tool, "--tool");
  if (!(radius > 0) || !(radius <= 1e6))
    throw InputError("--radius",
                     "must be a length in (0, 1e6] mm, got " + fmt::format("{:g}", radius));
  if (type != CutterType::Bull) {
    if (cornerGiven)
      throw InputError("--corner-radius",
                       std::string("only a bull cutter has a corner radius; a ") + toString(type) +
                           " cutter's is fixed");
    return Cutter::make(type, radius, 0, 0, "tool");
  }
  if (!std::isfinite(cornerRadius) || cornerRadius <= 0 || cornerRadius >= radius)
    throw InputError("--corner-radius",
                     "must satisfy 0 < corner radius < radius = " + fmt::format("{:g}", radius) +
                         " mm for a bull cutter, got " + fmt::format("{:g}", cornerRadius) +
                         " (corner radius = radius is --tool ball)");
  return Cutter::make(type, radius, cornerRadius, 0, "tool");
}

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
    std::fprintf(stderr,
                 "scallop: error: --corner-radius is required for --tool bull\n"
                 "Run with --help for more information.\n");
    return 2;
  }
  const Cutter cutter = cutterFromOptions(args.tool, args.radius, args.cornerRadius, cornerGiven);
  checkAngleOption("--lead", args.leadDeg);
  checkAngleOption("--tilt", args.tiltDeg);
  if (!std::isfinite(args.scallop) || args.scallop <= 0)
    throw InputError("--scallop",
                     "must be a height > 0 mm, got " + fmt::format("{:g}", args.scallop));

  const SimulatedPass pass(cutter, args.leadDeg, args.tiltDeg);
  const IntervalComparison comparison = compareIntervals(pass, args.scallop);
  if (!comparison.exact.reachable) throw InputError("--scallop", comparison.exact.reason);
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
