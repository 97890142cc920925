// scallop_perf_guard: the workload that scripts/perf-guard.sh counts instructions on.
//
// Wall times on the shared 2-core machines move by +-20 %, so they cannot tell a 2 %
// slowdown of the kernel from noise. Instructions counted by callgrind can: for the same
// binary and input they are the same number on every run, whatever else the machine does.
// This driver runs standard bench cases (tools/run/bench_cases.h) at a small area on one
// thread and asks callgrind, through its client requests, for one dump per phase:
//   "<case> scene"  building the culling scene (buildScene),
//   "<case> cast"   casting every cell of the grid (castZMap),
// so that the script can divide each dump's instructions by the case's moves or cells.
// Outside valgrind the requests do nothing and the driver just runs the cases.
//
// It links the simulation libraries and the tool-path readers only: OpenImageIO, which
// the full CLI loads, pulls in libhwy, whose start-up code executes an instruction
// (RDTSCP) that valgrind 3.19 cannot run.
//
// SCALLOP_PERF_GUARD_EXTRA_CELLS_PERCENT=P (the script's --extra-cells) casts P % of the
// grid's rows a second time inside the "cast" dump: a deliberate slowdown of P %, with
// which the guard's own test shows that it fails.
//
// Output: one line a case, "<case> cells=N moves=M evaluations=E hash=H" (the heights'
// hash: equal hashes mean the same heights bit for bit).
#include <tbb/global_control.h>
#include <valgrind/callgrind.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "raycast/simulation.h"
// --against REV may build this file in an older tree, whose tools/ was one flat folder.
#if __has_include("tools/run/bench_cases.h")
#include "tools/run/bench_cases.h"
#else
#include "bench_cases.h"
#endif

namespace scallop {
namespace {

// The guard's cases: B1 (constant-axis raster, one move a pass), B3 (turning-axis
// freeform CL path) and B4 (real 3-axis CAM output, many short moves). Each area gives
// 0.3-1 M cells: a few seconds under callgrind, yet far more cells than a region's
// set-up, so instructions a cell are those of a full run's interior (B3's windows are
// 16 % dearer a cell than a small stock; the guard compares like with like).
struct GuardCase {
  const char* name;
  double areaMm;
};
// B9 (10^6 short moves at full size; 4 mm: 2e4 cells, 3 443 moves) is measured only when
// named: scripts/perf-guard.sh --case B9, for the scene's instructions a move.
// B6 and B7 (general-profile cutters on B3's and B1's paths) likewise, at B3's
// and B1's areas: scripts/perf-guard.sh --case B6 --case B7.
// B5 (B1 with teeth) and two variants of it, for the cost of per-tooth geometry
// relative to B5: B5o with tooth 1 moved out by 3 um (both teeth cut: two groups) and
// B5d with tooth 1 at [2, 9] um (it finishes alone) and B5r with every tooth raked
// [5, 3] degrees, at 0.6 mm (3.6e5 cells): named only.
constexpr GuardCase kCases[] = {{"B1", 1.0},  {"B3", 1.0},  {"B4", 5.0}, {"B5", 0.6}, {"B5o", 0.6},
                                {"B5d", 0.6}, {"B5r", 0.6}, {"B6", 1.0}, {"B7", 1.0}, {"B9", 4.0}};

bool namedOnly(const std::string& name) {
  return name != "B1" && name != "B3" && name != "B4";
}

// B5r's rakes, where the tree has them (--against REV may build an older one).
template <class Teeth>
auto rakeEveryTooth(Teeth& teeth, int) -> decltype(teeth.editToothRakes(), void()) {
  using Rake = typename std::decay_t<decltype(teeth.editToothRakes())>::value_type;
  teeth.editToothRakes().assign(size_t(teeth.flutes), Rake{5, 3});
}
template <class Teeth>
void rakeEveryTooth(Teeth&, long) {}

void runCase(const GuardCase& c, double extraPercent) {
  BenchCaseOptions options;
  options.area = c.areaMm;
  const std::string name = c.name;
  BenchCase b = makeBenchCase(name.substr(0, 2), options);
  if (name == "B5o") b.cutter.teeth.editToothOffsets() = {{0, 0}, {0.003, 0}};
  if (name == "B5d") b.cutter.teeth.editToothOffsets() = {{0, 0}, {0.002, 0.009}};
  if (name == "B5r") rakeEveryTooth(b.cutter.teeth, 0);
  // The default cases cut with the envelope (no teeth): the default options are the
  // bench's (and trees older than the teeth model build this driver too). B5's teeth
  // come with their case.
  SimulationOptions simulation;
  if (name.rfind("B5", 0) == 0) simulation.cutting = b.cutting;

  const std::string sceneDump = std::string(c.name) + " scene";
  const std::string castDump = std::string(c.name) + " cast";
  CALLGRIND_ZERO_STATS;
  const std::unique_ptr<SweptScene> scene =
      buildScene(b.cutter, b.path, b.stock, b.grid.spacing, simulation);
  CALLGRIND_DUMP_STATS_AT(sceneDump.c_str());
  ZMap map(b.grid, b.stock.max.z);
  CALLGRIND_ZERO_STATS;  // the map's allocation and fill are not the cast's
  const CastStats cast = castZMap(*scene, map, simulation.cast);
  if (extraPercent > 0) {
    GridSpec extra = b.grid;
    extra.ny = std::max<int64_t>(1, int64_t(double(b.grid.ny) * extraPercent / 100));
    ZMap again(extra, b.stock.max.z);
    castZMap(*scene, again, simulation.cast);
  }
  CALLGRIND_DUMP_STATS_AT(castDump.c_str());

  std::printf("%s cells=%lld moves=%zu evaluations=%llu hash=%016llx\n", c.name,
              static_cast<long long>(b.grid.cells()), b.path.moves.size(),
              static_cast<unsigned long long>(cast.exactEvaluations),
              static_cast<unsigned long long>(heightsHash(map)));
  std::fflush(stdout);
}

}  // namespace
}  // namespace scallop

int main(int argc, char** argv) {
  // One thread: the instruction count of a parallel run depends on the work split.
  const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  const char* extra = std::getenv("SCALLOP_PERF_GUARD_EXTRA_CELLS_PERCENT");
  const double extraPercent = extra ? std::atof(extra) : 0;
  std::vector<std::string> wanted(argv + 1, argv + argc);
  for (const std::string& w : wanted) {
    bool known = false;
    for (const scallop::GuardCase& c : scallop::kCases) known = known || w == c.name;
    if (!known) {
      std::fprintf(stderr,
                   "scallop_perf_guard: unknown case '%s' (expected B1, B3, B4, B5, B5o, B5d, "
                   "B5r, B6, B7 or B9)\n",
                   w.c_str());
      return 1;
    }
  }
  try {
    for (const scallop::GuardCase& c : scallop::kCases) {
      const std::string name = c.name;
      bool run = wanted.empty() && !scallop::namedOnly(name);
      for (const std::string& w : wanted) run = run || w == c.name;
      if (run) scallop::runCase(c, extraPercent);
    }
  } catch (const std::exception& e) {  // InputError: B4's data folder missing
    std::fprintf(stderr, "scallop_perf_guard: %s\n", e.what());
    return 1;
  }
  return 0;
}
