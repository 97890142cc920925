// The heights hash of a quick bench case simulated as `scallop simulate` runs it, for the
// tests that check that the bench (CLI or run) computes those same heights.
#pragma once

#include <fmt/format.h>

#include <string>

#include "raycast/simulation.h"
#include "tools/run/bench_cases.h"

namespace scallop::test {

inline std::string simulatedQuickHash(const std::string& name, double areaMm) {
  BenchCaseOptions options;
  options.quick = true;
  options.area = areaMm;
  const BenchCase b = makeBenchCase(name, options);
  const SimulationResult sim = simulate(b.cutter, b.path, b.stock, b.grid);
  return fmt::format("{:016x}", heightsHash(sim.map));
}

}  // namespace scallop::test
