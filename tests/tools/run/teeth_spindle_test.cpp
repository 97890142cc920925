// The spindle's direction end to end (CONVENTIONS.md "Teeth: spindle direction and
// per-tooth geometry"): a counter-clockwise job, by the job's "spindle" or by G-code M4,
// gives the heights of the clockwise job mirrored in y, bit for bit, cell for cell. The
// grid is dyadic and symmetric about y = 0 so that cell j's centre is exactly minus
// cell (ny - 1 - j)'s.
#include <gtest/gtest.h>

#include <string>

#include "base/input_error.h"
#include "raycast/simulation.h"
#include "tests/support/cli_harness.h"
#include "tools/io/job.h"
#include "tools/run/job_loader.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

class TeethSpindle : public test::CliFixture {
 protected:
  ZMap simulateJob(const std::string& program, const std::string& spindle) {
    write("p.nc", program);
    const fs::path jobFile = write("job.json", R"({
      "tool":  {"type": "bull", "radius": 1.0, "corner_radius": 0.5, "flutes": 3,
                "helix_deg": 20, "runout_mm": 0.002, "tooth_angles_deg": [0, 110, 250],
                "tooth_offsets": [[0, 0], [0.001, 0.003], [-0.002, 0]]},
      "cutting": {"model": "teeth", "feed_per_tooth": 0.05, "phase_deg": 30},
      "stock": {"min": [0, -0.5, -1], "max": [1, 0.5, 0]},
      "grid":  {"spacing": 0.015625},
      "path":  {"file": "p.nc"})" + spindle + "}");
    const Job job = loadJobFile(jobFile.string());
    SimulationOptions options;
    options.cutting = job.cutting;
    return simulate(job.cutter, job.path, job.stock, job.grid(), options).map;
  }
};

// Ramps and turns in every direction, each also mirrored (Y negated).
std::string program(double ySign, const char* spindle) {
  auto y = [&](double v) { return std::to_string(ySign * v); };
  return std::string("G21 G90 G94 S10000 ") + spindle + "\nG0 X-0.6 Y" + y(-0.4) +
         " Z0.5\nG1 Z-0.05 F1500\nX0.5 Y" + y(0.1) + " Z-0.1\nX1.4 Y" + y(0.35) + "\nX0.3 Y" +
         y(0.45) + " Z-0.12\nG0 Z1\nM30\n";
}

TEST_F(TeethSpindle, CounterClockwiseIsTheMirroredClockwiseJobBitForBit) {
  const ZMap cw = simulateJob(program(-1, "M3"), "");
  const ZMap byKey = simulateJob(program(1, ""), R"(, "spindle": "ccw")");
  const ZMap byM4 = simulateJob(program(1, "M4"), "");
  const ZMap plain = simulateJob(program(1, "M3"), R"(, "spindle": "ccw")");  // M3 wins
  ASSERT_EQ(cw.ny(), 64);
  int cut = 0, differ = 0;
  for (int64_t j = 0; j < cw.ny(); ++j)
    for (int64_t i = 0; i < cw.nx(); ++i) {
      const double want = cw.at(i, cw.ny() - 1 - j);
      ASSERT_EQ(byKey.at(i, j), want) << i << " " << j;
      ASSERT_EQ(byM4.at(i, j), want) << i << " " << j;
      cut += want < 0;
      differ += plain.at(i, j) != want;
    }
  EXPECT_GT(cut, 2000);
  EXPECT_GT(differ, cut / 4);  // the directions leave different marks
}

TEST_F(TeethSpindle, UnknownSpindleNamesTheKey) {
  try {
    simulateJob(program(1, ""), R"(, "spindle": "left")");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("spindle"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("ccw"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace scallop
