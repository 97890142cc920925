// `scallop interval`: the path-interval procedures of the seeds next to the simulated
// truth for one cutter, posture and scallop height. The comparison and its JSON
// document are tools/run/interval_comparison.h, shared with the Python module.
// Added to the command line by addIntervalCommand (command.h).
#pragma once

#include "tools/run/interval_comparison.h"
