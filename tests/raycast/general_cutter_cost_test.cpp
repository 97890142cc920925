// The cost of a cell with a cutter of any profile against B1's bull (docs/algorithm.md
// "Cutters of any profile"): B1's raster (lead 5 deg, 0.3 x 0.3 mm of it) cast with its
// bull and with a tapered ball of the same tip radius (3 mm, taper 3 deg). A manual
// measurement, not a check (disabled): run it under callgrind, once per cutter,
//   SCALLOP_COST_CUTTER=bull|taper_ball valgrind --tool=callgrind build/tests/scallop_tests
//     --gtest_also_run_disabled_tests --gtest_filter='GeneralCutterCost.*'
// and divide the instructions by the cells it prints. The heights of the two agree
// where the contact lies on the tip sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "base/constants.h"
#include "raycast/simulation.h"
#include "raycast/zmap.h"
#include "raycast/zmap_caster.h"
#include "sweep/cutter_profile.h"
#include "sweep/cutter_shapes.h"
#include "tools/run/bench_cases.h"

namespace scallop {
namespace {

TEST(GeneralCutterCost, DISABLED_B1RasterCellCost) {
  BenchCaseOptions options;
  const char* area = std::getenv("SCALLOP_COST_AREA");  // mm, default 0.3
  options.area = area ? std::atof(area) : 0.3;
  BenchCase b = makeBenchCase("B1", options);
  const char* which = std::getenv("SCALLOP_COST_CUTTER");
  if (which && std::strcmp(which, "taper_ball") == 0) {
    // Ball tip of radius 3 mm, flank at 3 degrees from the axis, 20 mm of flute.
    const double r = 3, taper = degToRad(3);
    const double rho = r * std::cos(taper), s = r - r * std::sin(taper);
    const double top = 20;
    const std::vector<ProfileSegment> chain{{0, 0, rho, s, r},
                                            {rho, s, rho + (top - s) * std::tan(taper), top}};
    b.cutter = cutterOfChain(CutterType::TaperBall, chain, "tool");
  }
  const SimulationOptions simulation;
  const std::unique_ptr<SweptScene> scene =
      buildScene(b.cutter, b.path, b.stock, b.grid.spacing, simulation);
  ZMap map(b.grid, b.stock.max.z);
  const CastStats cast = castZMap(*scene, map, simulation.cast);
  std::printf("%s: cells %lld, exact evaluations %llu\n", toString(b.cutter.type),
              static_cast<long long>(b.grid.cells()),
              static_cast<unsigned long long>(cast.exactEvaluations));
}

}  // namespace
}  // namespace scallop
