// Casting B3 as the full-size bench casts it, in a fraction of the time: the scene of the
// whole 20 x 20 mm B3 path is built once, and 7 x 7 windows of 0.3 mm spread evenly over
// the stock (1.1 M cells at 2 um) are cast against it.
//
// Why not a small stock (`scallop bench --area 2`, or BM_Cast): a small stock has fewer
// passes beside each cell and fewer moves per region, and there B3 cost 16 % fewer
// instructions a cell than on the full path; its gains did not carry over. These windows
// ask what the full run asks of a cell (2.08 exact evaluations a cell against its 2.11),
// so they are the set to count instructions on, for example with callgrind's
// --toggle-collect='*castZMap*' and --benchmark_filter=B3Windows. Their cells/s run ~10 %
// below `scallop bench --case B3`'s (a window is a dozen tiles for two threads): compare
// them with each other, not with the bench.
// The label carries the heights' hash: equal hashes mean the same heights bit for bit.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>
#include <string>

#include "base/fnv1a.h"
#include "raycast/simulation.h"
#include "raycast/zmap_caster.h"
#include "tools/run/bench_cases.h"

namespace scallop {
namespace {

void BM_CastB3Windows(benchmark::State& state) {
  constexpr int kWindows = 7;      // a side
  constexpr double kSideMm = 0.3;  // of each window
  const BenchCase b = makeBenchCase("B3", BenchCaseOptions());
  SimulationOptions options;
  options.cutting = b.cutting;
  const std::unique_ptr<SweptScene> scene =
      buildScene(b.cutter, b.path, b.stock, b.grid.spacing, options);
  const int64_t n = int64_t(kSideMm / b.grid.spacing);
  uint64_t evaluations = 0, hash = 0;
  int64_t cells = 0;
  for (auto _ : state) {
    Fnv1a windowsHash;  // over the windows' hashes
    for (int a = 0; a < kWindows; ++a) {
      for (int c = 0; c < kWindows; ++c) {
        GridSpec window = b.grid;
        window.offsetI = int64_t((a + 0.5) / kWindows * double(b.grid.nx)) - n / 2;
        window.offsetJ = int64_t((c + 0.5) / kWindows * double(b.grid.ny)) - n / 2;
        window.nx = window.ny = n;
        ZMap map(window, b.stock.max.z);
        evaluations += castZMap(*scene, map, options.cast).exactEvaluations;
        cells += window.cells();
        windowsHash.addWord(heightsHash(map));
      }
    }
    hash = windowsHash.value;
  }
  state.SetItemsProcessed(cells);
  state.counters["evals_per_cell"] = double(evaluations) / double(cells);
  char label[96];
  std::snprintf(label, sizeof label, "B3, 7 x 7 windows of 0.3 mm, cells/s; hash %016llx",
                static_cast<unsigned long long>(hash));
  state.SetLabel(label);
}
BENCHMARK(BM_CastB3Windows)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace
}  // namespace scallop
