// scallop_deviation_speed: the normal deviation against the z-map on the same path
// (the target: design points a second at least 1/2 of the z-map's cells a
// second). The job: a ball raster over a plane, the z-map at 0.05 mm (200 x 200 cells),
// and a design that is the plane with its vertices at those cells' centres (40 000
// points), or ("curved") the same vertices on a gentle wave (every vertex its own
// normal). One thread.
//
//   scallop_deviation_speed zmap|deviation|curved [REPEATS]
//
// runs simulate() or normalDeviation() REPEATS times (default 1) and prints, for each
// call, the items (cells or points), its wall seconds and a hash of the results. Under
// callgrind each call is one dump ("zmap" or "deviation") holding only its instructions.
// It links the simulation libraries only (OpenImageIO's libhwy would stop valgrind).
#include <tbb/global_control.h>
#include <valgrind/callgrind.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "analysis/normal_deviation.h"
#include "base/fnv1a.h"
#include "raycast/simulation.h"
#include "sweep/raster.h"

namespace scallop {
namespace {

uint64_t hashOf(const std::vector<double>& values) {
  Fnv1a hash;  // word-wise over the values' bits
  for (double v : values) hash.addWordOf(v);
  return hash.value;
}

int run(const std::string& mode, int repeats) {
  const Cutter cutter = Cutter::make(CutterType::Ball, 1);
  const Box3 stock{{0, 0, -3}, {10, 10, 0}};
  const GridSpec grid = gridCovering(0, 0, 10, 10, 0.05);
  RasterSpec raster;
  raster.stepOver = 0.7;
  raster.depth = 0.4;
  const ToolPath path = makeRaster(cutter, stock, raster);
  const double planeZ = -0.45;                      // below the passes' floor: every line is cut
  const double wave = mode == "curved" ? 0.02 : 0;  // mm
  auto point = [&](int64_t i, int64_t j) {
    const double x = grid.cellCentreX(i), y = grid.cellCentreY(j);
    return Vec3{x, y, planeZ + wave * std::sin(3 * x) * std::cos(2 * y)};
  };
  std::vector<std::array<Vec3, 3>> soup;  // wound so that the normal is +z
  for (int64_t i = 0; i + 1 < grid.nx; ++i)
    for (int64_t j = 0; j + 1 < grid.ny; ++j) {
      soup.push_back({point(i, j), point(i + 1, j), point(i, j + 1)});
      soup.push_back({point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)});
    }
  const TriangleMesh design = meshFromTriangles(soup);

  for (int r = 0; r < repeats; ++r) {
    if (mode == "zmap") {
      CALLGRIND_ZERO_STATS;
      const auto t0 = std::chrono::steady_clock::now();
      const SimulationResult result = simulate(cutter, path, stock, grid);
      const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - t0;
      CALLGRIND_DUMP_STATS_AT("zmap");
      std::printf("zmap cells=%lld seconds=%.6f hash=%016llx\n",
                  static_cast<long long>(grid.cells()), seconds.count(),
                  static_cast<unsigned long long>(hashOf(result.map.heights())));
    } else if (mode == "deviation" || mode == "curved") {
      CALLGRIND_ZERO_STATS;
      const auto t0 = std::chrono::steady_clock::now();
      const NormalDeviation d = normalDeviation(cutter, path, stock, design, 1.0);
      const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - t0;
      CALLGRIND_DUMP_STATS_AT("deviation");
      std::printf(
          "deviation points=%zu seconds=%.6f candidates=%llu evaluations=%llu hash=%016llx\n",
          design.vertices.size(), seconds.count(), static_cast<unsigned long long>(d.candidates),
          static_cast<unsigned long long>(d.exactEvaluations),
          static_cast<unsigned long long>(hashOf(d.deviation)));
    } else {
      std::fprintf(stderr, "usage: scallop_deviation_speed zmap|deviation|curved [REPEATS]\n");
      return 2;
    }
  }
  return 0;
}

}  // namespace
}  // namespace scallop

int main(int argc, char** argv) {
  const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  if (argc < 2) {
    std::fprintf(stderr, "usage: scallop_deviation_speed zmap|deviation|curved [REPEATS]\n");
    return 2;
  }
  return scallop::run(argv[1], argc > 2 ? std::atoi(argv[2]) : 1);
}
