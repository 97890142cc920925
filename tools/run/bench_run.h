// A benchmark run: the standard performance cases (tools/run/bench_cases.h), each run
// through the same simulate() as `scallop simulate`, at 1 thread and at the threads
// asked for, plus the stamping baseline on a small window at equal accuracy
// (<= 1e-4 mm), with its document built by tools/run/report.h. `scallop bench` is this
// plus its command line and table (tools/cli/bench_command.cpp); the Python module's
// bench() calls it too.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace scallop {

// The callback a stage of work calls after every tile of cells with the cells done and
// in all; it may throw to stop the run (the CLI's Ctrl-C, tools/cli/interrupt.h).
using CellProgress = std::function<void(int64_t done, int64_t total)>;

struct BenchSettings {
  bool quick = false;              // 10x coarser spacing
  std::vector<std::string> cases;  // empty: all
  double area = 0;                 // > 0: stock side, mm
  double stampWindow = 0;          // > 0: side of the baseline's window, mm (0: default)
  bool stamp = true;               // run the stamping baseline (B1 and B3)
  int threads = 0;                 // threads of the timed run (0: 2); also run at 1
  // Opens the progress display of one stage, e.g. "B1 (2 threads)" or "B1 stamping",
  // and returns its callback; the stage is over when every copy of it is destroyed.
  // Unset: no progress.
  std::function<CellProgress(const std::string& label)> openStage;
};

struct BenchResult {
  // newReport()'s fields, then "cases" (one object per case: cells, moves, segments,
  // evals_per_cell, seconds, ..., heights_hash), "stamp_ratio", "stamp", "quick",
  // "area_mm", "hardware_threads", "peak_rss_scope", "stamp_ratio_meaning".
  nlohmann::json report;
};

// Throws InputError (field "--case" / "--area") for an unknown case or a bad area, and
// InternalError when a case's heights differ between 1 thread and more.
BenchResult runBench(const BenchSettings& settings);

}  // namespace scallop
