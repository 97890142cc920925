#include "tools/cli/simulate_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <utility>

#include "base/input_error.h"
#include "tools/cli/command.h"
#include "tools/cli/interrupt.h"
#include "tools/cli/progress.h"
#include "tools/io/job.h"
#include "tools/io/job_cutter_shapes.h"
#include "tools/run/job_loader.h"
#include "tools/run/report.h"
#include "tools/run/simulation_plan.h"
#include "tools/run/tiled_simulation.h"

namespace scallop {

using nlohmann::json;

namespace {

// The teeth model's feed marks (report.json "feed_marks", docs/teeth.md), one line.
void printFeedMarks(const json& report) {
  if (!report.contains("feed_marks")) return;
  const json& f = report["feed_marks"];
  if (!f.contains("line")) {
    std::printf("feed marks: not measured: %s\n", f["reason"].get<std::string>().c_str());
    return;
  }
  std::printf("feed marks along the pass centre line: %.4f um peak to valley",
              f["peak_to_valley_um"].get<double>());
  if (!f["mean_spacing_mm"].is_null())
    std::printf(", %.5f mm apart", f["mean_spacing_mm"].get<double>());
  if (f.contains("predicted"))
    std::printf(" (closed form %.4f um, %g mm)", f["predicted"]["peak_to_valley_um"].get<double>(),
                f["predicted"]["spacing_mm"].get<double>());
  std::printf("\n");
}

// What `simulate` prints on stdout for people (--json prints the document instead).
void printOutcome(const RunOutcome& outcome, const std::string& outDir) {
  const json& d = outcome.document;
  if (outcome.kind == RunOutcome::Kind::kBands) {
    std::printf("wrote bands %lld..%lld of %lld into %s; `scallop merge %s` when all exist\n",
                d["bands"][0].get<long long>(), d["bands"][1].get<long long>() - 1,
                d["of"].get<long long>(), outDir.c_str(), outDir.c_str());
    return;
  }
  const json& g = d["grid"];
  const json& m = d["measurements"];
  if (outcome.kind == RunOutcome::Kind::kTiled) {
    std::printf("heights: %lld x %lld cells in %lld bands, z in [%.6f, %.6f] mm, %.2f s\n",
                g["nx"].get<long long>(), g["ny"].get<long long>(),
                d["tiled"]["bands"].get<long long>(), m["min_height"].get<double>(),
                m["max_height"].get<double>(), d["timings_s"]["total"].get<double>());
    printFeedMarks(d);
    std::printf("wrote %s/heights.exr, heights.gsf, preview.png, report.json\n", outDir.c_str());
    return;
  }
  std::printf(
      "heights: %lld x %lld cells, z in [%.6f, %.6f] mm, %.2f exact evaluations per cell, %.2f "
      "s\n",
      g["nx"].get<long long>(), g["ny"].get<long long>(), m["min_height"].get<double>(),
      m["max_height"].get<double>(), m["exact_evaluations_per_cell"].get<double>(),
      d["timings_s"]["cast"].get<double>());
  if (m.contains("max_scallop_height"))
    std::printf("largest scallop between passes: %.6f mm\n", m["max_scallop_height"].get<double>());
  printFeedMarks(d);
  namespace fs = std::filesystem;
  const fs::path dir(outDir);
  std::printf("wrote %s\n      %s\n      %s\n", (dir / "heights.exr").c_str(),
              (dir / "heights.gsf").c_str(), (dir / "preview.png").c_str());
  for (const auto& name : d["outputs"])
    if (name == "view.png") std::printf("      %s\n", (dir / "view.png").c_str());
  std::printf("      %s\n", (dir / "report.json").c_str());
}

Job loadSimulateJob(const SimulateArgs& args) {
  if (!args.pathFile.empty() && args.jobFile.empty())
    throw InputError("--path",
                     "needs a JOB file for the tool (unless the path has CUTTER/), "
                     "stock and grid");
  // A grid too large to hold is accepted here: the run computes it in bands.
  const bool exact = args.run.method == "exact";
  return args.jobFile.empty() ? loadJob(defaultJobJson(), "built-in default job", !exact)
                              : loadJobFile(args.jobFile, !exact, args.pathFile, args.arcChords);
}

// --print-bands: the band layout the job and --tile-rows give, without computing, so
// that a scheduler script can split the bands between its tasks (scripts/slurm-bands.sh).
int printBands(const SimulateArgs& args) {
  const Job job = loadSimulateJob(args);
  RunSettings inBands = args.run;  // the layout of every band, whichever are asked for
  inBands.tiled = true;
  inBands.bands.clear();
  const SimulationPlan plan = planSimulation(job, inBands);
  const GridSpec& grid = plan.grid;
  const BandLayout& layout = plan.layout;
  const json doc = {{"bands", layout.bands},
                    {"band_rows", layout.bandRows},
                    {"rows", grid.ny},
                    {"columns", grid.nx},
                    {"exr_tile_rows", layout.tileHeight}};
  if (args.run.quiet) {
    std::fputs((doc.dump(2) + "\n").c_str(), stdout);
  } else {
    std::printf("bands=%lld band_rows=%lld rows=%lld columns=%lld exr_tile_rows=%d\n",
                (long long)layout.bands, (long long)layout.bandRows, (long long)grid.ny,
                (long long)grid.nx, layout.tileHeight);
  }
  return 0;
}

}  // namespace

int runSimulate(const SimulateArgs& args) {
  const RunSettings& run = args.run;
  Job job = loadSimulateJob(args);
  ProgressBar bar("simulating");
  RunSettings settings = run;
  settings.progress = [&bar](int64_t done, int64_t total) { bar.update(done, total); };
  settings.computed = [&bar] {
    bar.finish();
    throwIfInterrupted();  // a Ctrl-C during the last tiles: write nothing
  };
  const RunOutcome outcome = runSimulation(std::move(job), settings);
  if (run.quiet)
    std::fputs(reportText(outcome.document).c_str(), stdout);
  else
    printOutcome(outcome, run.outDir);
  return 0;
}

namespace {

// The cutter types come from the shape table (tools/io/job_cutter_shapes.h).
std::string simulateHelp() {
  return std::string(
             "Simulate a job (JSON): its exact height map, preview and report.\n"
             "Writes DIR/heights.exr (float32 channel Z, mm), DIR/heights.gsf\n"
             "(Gwyddion, metres), DIR/preview.png (shaded colour map with scale) and\n"
             "DIR/report.json (inputs, grid, timings, measurements).\n"
             "Without JOB, runs the built-in default job (see --print-default-job):\n"
             "a bull cutter R=3 r=1 raster over 20x20 mm, lead 5 deg, step-over 2.884 mm.\n"
             "Job file keys (docs/CONVENTIONS.md has each one, with units and ranges):\n"
             "  tool{type, ...} or tools{\"N\": {...}} (G-code T words); type is one of\n"
             "    ") +
         cutterTypeList() + "\n" +
         "    (each type's keys: `scallop cutter --list`); teeth: flutes, helix_deg,\n"
         "    runout_mm, runout_phase_deg, tooth_offsets, tooth_angles_deg, edge_span,\n"
         "    tooth_edge_spans, rake_deg, tooth_rakes_deg (docs/teeth.md)\n"
         "  cutting{model (envelope|teeth), feed_per_tooth (mm), phase_deg}, spindle (cw|ccw)\n"
         "  stock{min,max} | stock{stl} | stock{gsf}    grid{spacing, "
         "frame{origin,u,normal,size}}\n"
         "  path{raster{direction,step_over,depth,lead_deg,tilt_deg,zigzag,segment_length} | "
         "file},\n"
         "    arc_chords, machine{kinematics,tcp_on,tcp_off,...} (5-axis G-code)\n"
         "  design{stl, gouge_tolerance (mm, default 0.001), normal_deviation, gouge_depth}:\n"
         "    machined - design statistics, the gouging moves (file lines), DIR/deviation.png,\n"
         "    and with normal_deviation DIR/deviation.ply (signed distance along the normal).\n"
         "Path files by extension: .cl .apt .cls (APT CL data: GOTO, CUTTER, RAPID, ...),\n"
         ".nc .ngc .gcode .tap (G-code G0-G3, G17-G21, G90/G91), .txt (x y z [i j k] lines).\n"
         "Without \"tool\", an APT CUTTER/ statement defines the cutter.";
}

}  // namespace

Command addSimulateCommand(CLI::App& parent, CommonOptions& common) {
  auto args = std::make_shared<SimulateArgs>();
  auto printDefault = std::make_shared<bool>(false);
  auto printBandLayout = std::make_shared<bool>(false);
  CLI::App* app = parent.add_subcommand("simulate", simulateHelp());
  app->add_option("JOB", args->jobFile, "Job file (JSON); omit for the built-in default job");
  app->add_option("-o,--output", args->run.outDir,
                  "Output folder, created if missing; other files in it are left alone")
      ->capture_default_str();
  app->add_option("--path", args->pathFile,
                  "Tool-path file that replaces the job's path (format from the extension;\n"
                  "needs JOB for the stock and grid)");
  addThreadsOption(*app, common);
  app->add_flag("--arc-chords", args->arcChords,
                "G-code arcs as chords within 1e-4 mm (the old baseline), not exact arc moves");
  app->add_flag("--json", args->run.quiet, "Print report.json on stdout (and nothing else there)");
  app->add_option("--method", args->run.method,
                  "exact: exact swept-solid heights (default); stamp: classical z-map baseline,\n"
                  "the cutter stamped along each move at a step whose scallop is <= 1e-4 mm")
      ->check(CLI::IsMember({"exact", "stamp"}))
      ->capture_default_str();
  app->add_flag("--tiled", args->run.tiled,
                "Compute and write the map in bands of rows with bounded memory (tiled\n"
                "OpenEXR, streamed GSF); chosen by itself when the map does not fit in memory");
  app->add_option("--tile-rows", args->run.tileRows,
                  "Rows per band (default: bands of <= 256 MB of heights); implies --tiled")
      ->check(CLI::PositiveNumber);
  CLI::Option* bands =
      app->add_option("--bands", args->run.bands,
                      "K:M: compute only bands K..M-1 and write DIR/band-K.raw (float64 mm) and\n"
                      "DIR/band-K.json (written last, with the .raw's MD5: the band is complete\n"
                      "only then); `scallop merge DIR` assembles the outputs when all exist");
  app->add_flag("--print-bands", *printBandLayout,
                "Print the band layout of JOB with --tile-rows and exit, computing nothing:\n"
                "one line 'bands=B band_rows=R rows=NY columns=NX exr_tile_rows=T' (with\n"
                "--json, a JSON object); --bands K:M then takes 0 <= K < M <= B")
      ->excludes(bands);
  app->add_flag("--view", args->run.view,
                "Also write DIR/view.png: the map ray-traced in 3-D in oblique light with\n"
                "shadows, as `scallop render` draws it with its defaults (whole map in memory)");
  app->add_flag("--print-default-job", *printDefault,
                "Print the built-in default job file and exit");
  return {app, [args, printDefault, printBandLayout, &common]() {
            if (*printDefault) {
              std::puts(defaultJobJson());
              return 0;
            }
            if (*printBandLayout) return printBands(*args);
            args->run.threads = common.threads;
            return runSimulate(*args);
          }};
}

}  // namespace scallop
