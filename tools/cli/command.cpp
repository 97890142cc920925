#include "tools/cli/command.h"

#include <CLI/CLI.hpp>

namespace scallop {

void addThreadsOption(CLI::App& command, CommonOptions& common) {
  command
      .add_option("--threads", common.threads,
                  "Worker threads (default: all cores); results do not depend on it")
      ->check(CLI::Range(0, 1 << 16));
}

}  // namespace scallop
