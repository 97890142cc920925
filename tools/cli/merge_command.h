// `scallop merge DIR`: assembles the band files that `simulate --bands K:M` runs wrote
// into DIR (tools/run/tiled_simulation.h) into heights.exr, heights.gsf, preview.png and
// report.json, exactly as one `simulate --tiled` run would have written them.
#pragma once

#include <string>

namespace scallop {

struct MergeArgs {
  std::string dir;
  bool json = false;  // print report.json on stdout
};

// Returns the process exit status; throws InputError (exit 1) for a missing band, a
// band of another run or a damaged band file, naming the file.
int runMerge(const MergeArgs& args);

}  // namespace scallop
