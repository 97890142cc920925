// `scallop bench`: the standard performance cases (tools/run/bench_cases.h), each run
// through the same simulate() as `scallop simulate`, at 1 and 2 threads, plus the
// stamping baseline on a small window at equal accuracy (<= 1e-4 mm).
#pragma once

#include <string>
#include <vector>

namespace scallop {

struct BenchArgs {
  bool json = false;
  bool quick = false;              // 10x coarser spacing
  std::vector<std::string> cases;  // empty: all
  double area = 0;                 // > 0: stock side, mm
  double stampWindow = 0;          // > 0: side of the baseline's window, mm (0: default)
  bool stamp = true;               // run the stamping baseline (B1 and B3)
  int threads = 0;                 // threads of the timed run (0: 2); also run at 1
};

// Returns the process exit status; throws InputError for bad input.
int runBench(const BenchArgs& args);

}  // namespace scallop
