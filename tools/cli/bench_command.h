// `scallop bench`: the standard performance cases at 1 and 2 threads and the stamping
// baseline, printed as a table or JSON; the run itself is tools/run/bench_run.h.
// Added to the command line by addBenchCommand (command.h).
#pragma once
