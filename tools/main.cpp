// scallop: command-line entry point. Parses the command line, sets the thread count,
// and maps errors to the exit statuses of CONVENTIONS.md:
//   0 success, 1 bad input, 2 usage error, 3 internal error.
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <memory>
#include <new>

#include "sweep/input_error.h"
#include "tools/job.h"
#include "tools/simulate_command.h"

namespace {

constexpr const char* kDescription =
    "scallop: exact machined-surface topography of milling tool paths.\n"
    "Sweeps ball, flat and bull (torus) cutters along linear moves, with any tool axis,\n"
    "and computes on a z-map grid the exact lowest point of the swept solids (double\n"
    "precision, 1e-6 mm). Lengths in mm, angles in degrees.";

constexpr const char* kSimulateHelp =
    "Simulate a job file and write DIR/heights.exr (float32 channel Z, mm), DIR/heights.gsf\n"
    "(Gwyddion, metres), DIR/preview.png (shaded colour map with scale) and\n"
    "DIR/report.json (inputs, grid, timings, measurements).\n"
    "Without JOB, runs the built-in default job (see --print-default-job):\n"
    "a bull cutter R=3 r=1 raster over 20x20 mm, lead 5 deg, step-over 2.884 mm.\n"
    "Job file keys: tool{type,radius,corner_radius,flute_length}, stock{min,max},\n"
    "grid{spacing}, path{raster{direction,step_over,depth,lead_deg,tilt_deg,zigzag,\n"
    "segment_length} | file}, sweep{axis_tolerance}.";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{kDescription, "scallop"};
  app.require_subcommand(1);
  int threads = 0;

  scallop::SimulateArgs sim;
  bool printDefault = false;
  CLI::App* simulate = app.add_subcommand("simulate", kSimulateHelp);
  simulate->add_option("JOB", sim.jobFile, "Job file (JSON); omit for the built-in default job");
  simulate->add_option("-o,--output", sim.outDir,
                       "Output folder, created if missing; other files in it are left alone")
      ->capture_default_str();
  simulate->add_option("--threads", threads, "Worker threads (default: all cores); results do not depend on it")
      ->check(CLI::NonNegativeNumber);
  simulate->add_flag("--json", sim.json, "Print report.json on stdout (and nothing else there)");
  simulate->add_flag("--print-default-job", printDefault,
                     "Print the built-in default job file and exit");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // --help exits 0; every usage error is 2
  }

  std::unique_ptr<tbb::global_control> threadLimit;
  if (threads > 0)
    threadLimit = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, size_t(threads));
  sim.threads = threads;

  try {
    if (simulate->parsed()) {
      if (printDefault) {
        std::puts(scallop::defaultJobJson());
        return 0;
      }
      return scallop::runSimulate(sim);
    }
  } catch (const scallop::InputError& e) {
    std::fprintf(stderr, "scallop: error: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "scallop: internal error: out of memory\n");
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "scallop: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}
