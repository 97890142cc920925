// `scallop simulate`: runs a job and writes heights.exr, heights.gsf, preview.png and
// report.json into an output folder (CONVENTIONS.md "Height images").
#pragma once

#include <string>

namespace scallop {

struct SimulateArgs {
  std::string jobFile;  // empty: the built-in default job
  std::string outDir = "scallop-out";
  int threads = 0;               // 0: all cores
  bool json = false;             // print report.json on stdout
  std::string method = "exact";  // "exact" or "stamp" (raycast/stamp_caster.h)
};

// Returns the process exit status; throws InputError for bad input.
int runSimulate(const SimulateArgs& args);

}  // namespace scallop
