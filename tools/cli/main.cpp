// scallop: command-line entry point. Parses the command line, sets the thread count,
// and maps errors to the exit statuses of CONVENTIONS.md:
//   0 success, 1 bad input, 2 usage error, 3 internal error; 130 after Ctrl-C
// (tools/cli/interrupt.h).
#include <tbb/global_control.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/version.h"
#include "tools/cli/command.h"
#include "tools/cli/interrupt.h"

namespace {

constexpr const char* kDescription =
    "scallop: exact machined-surface topography of milling tool paths.\n"
    "Sweeps milling cutters along tool paths with any tool axis and computes on a grid the\n"
    "exact lowest point of the swept solids (double precision, 1e-6 mm). Lengths in mm,\n"
    "angles in degrees. Exit status: 0 success, 1 bad input, 2 usage error, 3 internal\n"
    "error, 130 interrupted (Ctrl-C; no partial outputs are left).\n"
    "Start with `scallop simulate` (a built-in job); `scallop COMMAND --help` has every\n"
    "option with its unit, docs/CONVENTIONS.md every job key.";

}  // namespace

int main(int argc, char** argv) {
  scallop::installInterruptHandler();  // Ctrl-C in a long loop then ends cleanly
#if defined(__GLIBC__)
  // Blocks of 4 MB and more (the z-map, the scene's arrays) are mapped and unmapped on
  // their own. glibc would otherwise raise this threshold at the first large free, after
  // which a freed scene stays resident in malloc's heaps through the next run: on the
  // bench's four B3 runs, 36 MB more peak memory.
  mallopt(M_MMAP_THRESHOLD, 4 << 20);
#endif
  CLI::App app{kDescription, "scallop"};
  app.set_version_flag("--version", std::string("scallop ") + scallop::kScallopVersion,
                       "Print the version and exit");
  scallop::useOneLineCommandList(app);
  app.require_subcommand(1);
  scallop::CommonOptions common;

  // Every subcommand, in the order --help lists them.
  std::vector<scallop::Command> commands;
  commands.push_back(scallop::addSimulateCommand(app, common));
  commands.push_back(scallop::addSurfaceCommand(app, common));
  commands.push_back(scallop::addGougeCommand(app, common));
  commands.push_back(scallop::addIntervalCommand(app, common));
  commands.push_back(scallop::addValidateCommand(app, common));
  commands.push_back(scallop::addBenchCommand(app, common));
  commands.push_back(scallop::addMergeCommand(app, common));
  commands.push_back(scallop::addStatsCommand(app, common));
  commands.push_back(scallop::addExportCommand(app, common));
  commands.push_back(scallop::addRenderCommand(app, common));
  commands.push_back(scallop::addCollectCommand(app, common));
  commands.push_back(scallop::addCutterCommand(app, common));

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // --help exits 0; every usage error is 2
  }

  std::unique_ptr<tbb::global_control> threadLimit;
  if (common.threads > 0)
    threadLimit = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, size_t(common.threads));

  try {
    for (const scallop::Command& command : commands)
      if (command.app->parsed()) return command.run();
  } catch (const scallop::Interrupted&) {
    // Thrown from a progress callback; unwinding removed every temporary output.
    std::fprintf(stderr, "scallop: interrupted\n");
    return 130;
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
