// `scallop simulate`: runs a job and writes heights.exr, heights.gsf, preview.png and
// report.json into an output folder (CONVENTIONS.md "Height images"); the run itself
// is tools/run/simulation_run.h.
#pragma once

#include <string>

#include "tools/run/simulation_run.h"

namespace scallop {

struct SimulateArgs {
  std::string jobFile;     // empty: the built-in default job
  std::string pathFile;    // --path: replaces the job's path (tools/io/tool_path_file.h)
  bool arcChords = false;  // --arc-chords: G-code arcs as chords (the job key arc_chords)
  RunSettings run;         // run.quiet is --json: print report.json on stdout
};

// Returns the process exit status; throws InputError for bad input.
int runSimulate(const SimulateArgs& args);

}  // namespace scallop
