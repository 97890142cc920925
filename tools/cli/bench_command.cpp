#include "tools/cli/bench_command.h"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "tools/cli/command.h"
#include "tools/cli/progress.h"
#include "tools/run/bench_run.h"
#include "tools/run/report.h"

namespace scallop {

using nlohmann::json;

namespace {

void printTable(std::FILE* out, const json& doc) {
  std::fprintf(out, "%-4s %12s %7s %9s %10s %10s %9s %9s %8s\n", "case", "cells", "moves",
               "segments", "evals/cell", "seconds", "Mcells/s", "peak MB", "2v1");
  for (const json& c : doc["cases"]) {
    const std::string speedup =
        c["speedup_2v1"].is_null() ? "-" : fmt::format("{:.2f}", c["speedup_2v1"].get<double>());
    std::fprintf(out, "%-4s %12lld %7lld %9lld %10.2f %10.3f %9.3f %9.0f %8s\n",
                 c["name"].get<std::string>().c_str(), c["cells"].get<long long>(),
                 c["moves"].get<long long>(), c["segments"].get<long long>(),
                 c["evals_per_cell"].get<double>(), c["seconds"].get<double>(),
                 c["mcells_per_s"].get<double>(), c["peak_rss_mb"].get<double>(), speedup.c_str());
  }
  // The scene: build time against the cast's, moves a second, bytes a move.
  std::fprintf(out, "\n%-4s %9s %9s %12s %12s %14s\n", "case", "scene s", "cast s", "moves/s",
               "scene B/move", "peak-map B/mv");
  for (const json& c : doc["cases"])
    std::fprintf(out, "%-4s %9.3f %9.3f %12.0f %12.0f %14.0f\n",
                 c["name"].get<std::string>().c_str(), c["scene_seconds"].get<double>(),
                 c["cast_seconds"].get<double>(), c["scene_moves_per_s"].get<double>(),
                 c["scene_bytes_per_move"].get<double>(),
                 c["peak_beyond_map_bytes_per_move"].get<double>());
  if (doc.contains("reading")) {
    // B11: the G-code reader's rate on one core (tools/run/read_bench.h).
    const json& r = doc["reading"];
    std::fprintf(out, "\n%-4s %10s %9s %10s %9s %12s\n", "case", "MB", "moves", "seconds", "MB/s",
                 "moves/s");
    std::fprintf(out, "%-4s %10.1f %9lld %10.3f %9.1f %12.0f\n", "B11",
                 r["bytes"].get<double>() / 1e6, r["moves"].get<long long>(),
                 r["seconds"].get<double>(), r["mb_per_s"].get<double>(),
                 r["moves_per_s"].get<double>());
  }
  bool teeth = false;
  for (const json& c : doc["cases"]) teeth = teeth || c.contains("teeth_over_envelope");
  if (teeth) {
    std::fprintf(out, "\nteeth against the envelope (same raster and grid, B1's; %s threads):\n",
                 doc["threads"].dump().c_str());
    std::fprintf(out, "%-4s %10s %12s %8s\n", "case", "teeth s", "envelope s", "ratio");
    for (const json& c : doc["cases"])
      if (c.contains("teeth_over_envelope"))
        std::fprintf(out, "%-4s %10.3f %12.3f %7.1fx\n", c["name"].get<std::string>().c_str(),
                     c["seconds"].get<double>(), c["envelope_seconds"].get<double>(),
                     c["teeth_over_envelope"].get<double>());
  }
  if (doc["stamp"].empty()) return;
  std::fprintf(out, "\nstamping baseline (z-map, same window, max error <= 1e-4 mm):\n");
  std::fprintf(out, "%-4s %9s %9s %10s %11s %10s %10s %8s\n", "case", "window", "cells", "step mm",
               "max err mm", "stamp s", "exact s", "ratio");
  for (const auto& [name, s] : doc["stamp"].items())
    std::fprintf(out, "%-4s %7.2fmm %9lld %10.5f %11.2e %10.3f %10.3f %7.1fx\n", name.c_str(),
                 s["window_mm"].get<double>(), s["cells"].get<long long>(),
                 s["step_mm"].get<double>(), s["max_error_mm"].get<double>(),
                 s["stamp_seconds"].get<double>(), s["exact_seconds"].get<double>(),
                 doc["stamp_ratio"][name].get<double>());
}

// Runs the cases and prints the table (or the document with --json); returns the exit
// status.
int runBenchCommand(BenchSettings settings, bool json) {
  settings.openStage = [](const std::string& label) -> CellProgress {
    auto bar = std::make_shared<ProgressBar>(label);  // polls for Ctrl-C while it lives
    return [bar](int64_t done, int64_t total) { bar->update(done, total); };
  };
  const BenchResult result = runBench(settings);
  if (json) {
    std::fputs(reportText(result.report).c_str(), stdout);
  } else {
    printTable(stdout, result.report);
  }
  return 0;
}

constexpr const char* kBenchHelp =
    "Run the standard performance cases and print a table.\n"
    "Run the standard performance cases with exact heights and print a table (or JSON):\n"
    "  B1 raster: stock 20 x 20 mm, bull R=3 r=1, lead 5 deg, step-over 0.8 mm, one move\n"
    "     per pass, grid spacing 1 um (4e8 cells);\n"
    "  B2 B1 with every pass cut into 0.05 mm moves;\n"
    "  B3 freeform 5-axis as CAM writes it: CL text with a tool axis at every point 0.05 mm\n"
    "     apart (read by the CL-text reader), tip on z = 0.5 sin(2 pi x/10) cos(2 pi y/14),\n"
    "     passes 0.5 mm apart, axis = surface normal leaned 5 deg along the feed, so the\n"
    "     axis turns inside every move; 2 um (1e8 cells);\n"
    "  B3c B3's tips with one constant axis per move (the old B3), 2 um;\n"
    "  B4 the mount_rush ball R3 drop-cutter raster (OpenCAMLib, tests/data), 86 x 43.5 mm\n"
    "     at 0.01 mm (3.7e7 cells);\n"
    "  B5 B1 with the teeth cutting model (2 flutes, fz 0.1 mm; --quick: a 4 mm square),\n"
    "     beside the envelope on the same grid (B1's raster) and the ratio of the times;\n"
    "  B6 (only with --case B6) B3's path with a taper barrel (form R250, tip R2, taper\n"
    "     10 deg), passes as far apart as leaves B3's scallop on a plane, 2 um;\n"
    "  B7 (only with --case B7) B1's raster with a tapered ball (tip R1, taper 5 deg), 1 um;\n"
    "  B8 (only with --case B8) surf-topo's face-milling case A2: a face mill with two\n"
    "     round inserts (bull R10 r5, edge_span), one 26 um in and 9 um up, fz 0.4 mm,\n"
    "     ap 0.4 mm, counter-clockwise, one pass over a 5 x 5 mm stock at 25 um;\n"
    "  B9 (only with --case B9) 10^6 moves: ball R1 finishing G-code over 100 x 50 mm\n"
    "     (--area A: A x A/2), passes 0.1 mm apart, a point every 0.05 mm, 20 um; reports\n"
    "     the scene's build in moves/s and its bytes a move;\n"
    "  B11 reading: B9's kind of G-code (10^6 plain G1 moves, 25 MB; --quick 20 x 10 mm,\n"
    "     4 10^4 moves; --area A: A x A/2) generated into a temporary file and read as a\n"
    "     user's file: MB/s and moves/s on one core.\n"
    "Each case runs through simulate() at 1 thread and at --threads (default 2), twice\n"
    "each (alternating; the faster run counts), and reports cells, moves, exact\n"
    "evaluations per cell, seconds, Mcells/s, peak memory and the 2-vs-1-thread\n"
    "speed-up. The stamping baseline (classical z-map) runs on a\n"
    "small window of B1 and B3 with the largest step whose error is <= 1e-4 mm, and\n"
    "its time over the exact time on that window is reported as stamp_ratio.\n"
    "Full size needs ~3.5 GB of memory; on 2 cores each case takes a few minutes (B3: 21-26 s\n"
    "a run at 2 threads, and every case runs four times) but B5, whose teeth take about\n"
    "half an hour. --quick uses 10x coarser spacing (about a minute in all), --area a\n"
    "smaller square of each case (B4: at the relief's centre).";

}  // namespace

Command addBenchCommand(CLI::App& parent, CommonOptions& common) {
  auto args = std::make_shared<BenchSettings>();
  auto json = std::make_shared<bool>(false);
  CLI::App* app = parent.add_subcommand("bench", kBenchHelp);
  app->add_flag("--json", *json, "Print one JSON document on stdout (and nothing else there)");
  app->add_flag("--quick", args->quick, "10x coarser grid spacing (10 um and 20 um): CI-friendly");
  app->add_option("--case", args->cases,
                  "Run only this case (B1, B2, B3, B3c, B4, B5, B6, B7, B8, B9, B11); may be "
                  "repeated")
      ->check(CLI::IsMember({"B1", "B2", "B3", "B3c", "B4", "B5", "B6", "B7", "B8", "B9", "B11"}));
  app->add_option("--area", args->area, "Square stock of this side, mm, instead of 20 mm")
      ->check(CLI::PositiveNumber);
  app->add_option("--stamp-window", args->stampWindow,
                  "Side of the stamping baseline's window, mm (default 0.5, or 1 with --quick)")
      ->check(CLI::PositiveNumber);
  app->add_flag(
      "--no-stamp", [args](std::int64_t) { args->stamp = false; }, "Skip the stamping baseline");
  addThreadsOption(*app, common);
  return {app, [args, json, &common]() {
            args->threads = common.threads;
            return runBenchCommand(*args, *json);
          }};
}

}  // namespace scallop
