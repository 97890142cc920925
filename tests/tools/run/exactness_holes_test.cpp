// The exactness hunt's reproducers (docs/testing.md "The exactness hunt"): moves whose
// heights were once outside their brackets, run through the whole pipeline (reader,
// machine, scene, caster) and checked cell by cell against the hunt's certificates
// (tests/hunt/hunt_reference.h, no code shared with sweep/).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "base/constants.h"
#include "hunt/hunt_reference.h"
#include "tests/support/temp_folder.h"
#include "tools/io/job.h"
#include "tools/run/job_loader.h"
#include "tools/run/simulation_run.h"

namespace scallop {
namespace {

using hunt::HuntCurve;
using hunt::Verdict;

class ExactnessHoles : public test::TempFolderTest {
 protected:
  ExactnessHoles() : TempFolderTest("holes") {}

  // The heights of `jobJson` with its path file `name` holding `path`.
  ZMap run(const std::string& jobJson, const std::string& name, const std::string& path) {
    std::filesystem::create_directories(dir_);
    std::ofstream(dir_ / name) << path;
    std::ofstream(dir_ / "job.json") << jobJson;
    Job job = loadJobFile((dir_ / "job.json").string());
    RunSettings settings;
    settings.quiet = true;
    return computeSimulation(job, settings).map;
  }

  // Every cell of `map` below `top` lies in its bracket: reached at h + tol and clear
  // below h - tol; cells at `top` clear below it.
  static void expectBracketed(const ZMap& map, const hunt::HuntCutter& cutter,
                              const HuntCurve& curve, double top, double tol) {
    int outside = 0;
    for (int64_t j = 0; j < map.ny(); ++j)
      for (int64_t i = 0; i < map.nx(); ++i) {
        const double x = map.grid().cellCentreX(i), y = map.grid().cellCentreY(j);
        const double h = map.at(i, j);
        const bool up = h >= top || hunt::provesReached(cutter, curve, {x, y, h + tol}) ==
                                        Verdict::kProven;
        const bool down = hunt::provesClear(cutter, curve, {x, y, h - tol}) == Verdict::kProven;
        if (!(up && down) && ++outside <= 5)
          ADD_FAILURE() << "cell (" << x << ", " << y << ") height " << h
                        << (up ? " too high" : " too deep");
      }
    EXPECT_EQ(outside, 0);
  }
};

// LinuxCNC's boat program, one move: a flat R5 tilted 5.5 deg moving almost in its bottom
// plane (direction . axis ~ -2e-5). The G-code through xyzac-trt cut a cell 0.111 mm too
// deep, the same move as CL data 10.8 um.
constexpr char kStock[] = R"("stock": {"min": [10, -5, -13.25], "max": [16, -1, 0]},
  "grid": {"spacing": 0.1},)";

TEST_F(ExactnessHoles, TiltedFlatEndMillInItsBottomPlane) {
  const std::string cl =
      "MULTAX\nRAPID\n"
      "GOTO/35.585,-7.418,-4.839,0.041761916319,-0.087156035725,0.995318927672\n"
      "GOTO/-27.8,-7.65,-2.2,0.041761916319,-0.087156035725,0.995318927672\n";
  const std::string gcode =
      "%\nM428\nG0 X35.585 Y-7.418 Z5 A-5.546 C-25.602\nG0 Z-4.839\n"
      "G1 X-27.8 Y-7.65 Z-2.2 F100\nM429\nM30\n%\n";
  const ZMap fromCl = run(std::string("{\"tool\": {\"type\": \"flat\", \"radius\": 5},") + kStock +
                              "\"path\": {\"file\": \"move.apt\"}}",
                          "move.apt", cl);
  const ZMap fromGcode =
      run(std::string("{\"tool\": {\"type\": \"flat\", \"radius\": 5},") +
              "\"machine\": {\"kinematics\": \"xyzac-trt\", \"tcp_on\": [\"M428\"], "
              "\"tcp_off\": [\"M429\"]}," +
              kStock + "\"path\": {\"file\": \"move.ngc\"}}",
          "move.ngc", gcode);
  const hunt::HuntCutter flat{5, 0, 20};
  const Vec3 p0{35.585, -7.418, -4.839}, p1{-27.8, -7.65, -2.2};
  const HuntCurve clCurve =
      hunt::straightCurve(p0, p1, {0.041761916319, -0.087156035725, 0.995318927672},
                          {0.041761916319, -0.087156035725, 0.995318927672});
  const double A = degToRad(-5.546), C = degToRad(-25.602);
  const HuntCurve machineCurve = hunt::rotaryCurve(true, p0, p1, A, A, C, C);
  expectBracketed(fromCl, flat, clCurve, 0, 1e-6);
  expectBracketed(fromGcode, flat, machineCurve, 0, 1e-6);
  // The two encodings of one move agree.
  ASSERT_EQ(fromCl.heights().size(), fromGcode.heights().size());
  double apart = 0;
  for (size_t k = 0; k < fromCl.heights().size(); ++k)
    apart = std::max(apart, std::fabs(fromCl.heights()[k] - fromGcode.heights()[k]));
  EXPECT_LT(apart, 1e-6);
}

}  // namespace
}  // namespace scallop
