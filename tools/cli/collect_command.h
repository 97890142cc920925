// `scallop collect DIR...`: the report.json files of many runs (a parameter study, one
// output folder per job) gathered into one CSV table, a row per run: the folder, the
// job, the job's inputs flattened (tool.radius, stock.min[0], path.raster.step_over,
// ...), then the chosen measurements (report.json paths such as
// measurements.max_scallop_height; --columns). Every report is read and checked before
// the table is written (atomically), so a bad one leaves no partial CSV.
#pragma once

#include <string>
#include <vector>

namespace scallop {

struct CollectArgs {
  std::vector<std::string> dirs;     // output folders (or report.json files)
  std::string output;                // -o: the CSV file; empty: stdout
  std::vector<std::string> columns;  // report.json paths; empty: the default measurements
};

// Returns the process exit status; throws InputError (exit 1) naming a missing or
// damaged report.json, or a --columns entry that no report has.
int runCollect(const CollectArgs& args);

}  // namespace scallop
