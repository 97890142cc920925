// G-code arcs end to end (job -> reader -> exact sweep -> height map): a program of
// arcs in G17, G18 and G19, IJK and R forms, a helix and a full circle, against the
// brute-force sweep of the same circles written here from the definition; and the
// --arc-chords baseline (job key arc_chords), whose heights differ from the exact
// arcs' by the chord error, measured.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "base/constants.h"
#include "raycast/simulation.h"
#include "sweep/brute_force_reference.h"
#include "tests/support/cli_harness.h"
#include "tools/io/job.h"
#include "tools/run/job_loader.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

class GcodeArcs : public test::CliFixture {
 protected:
  Job load(const std::string& program, bool chords) {
    write("arcs.nc", program);
    const fs::path jobFile = write("arcs.json", std::string(R"({
      "tool":  {"type": "ball", "radius": 1, "flute_length": 4},
      "stock": {"min": [-6, -6, -3], "max": [6, 6, 0]},
      "grid":  {"spacing": 0.05},
      "path":  {"file": "arcs.nc"})") + (chords ? R"(, "arc_chords": true})" : "}"));
    return loadJobFile(jobFile.string());
  }
};

// The tip on a circle of the plane (u, v) (normal n = u x v): centre c, radius r, from
// angle a0 through the signed sweep s, rising h along n.
struct RefArc {
  Vec3 c, u, v;
  double r, a0, s, h;
  Vec3 at(double t) const {
    const double th = a0 + s * t;
    return c + u * (r * std::cos(th)) + v * (r * std::sin(th)) + cross(u, v) * (h * t);
  }
};

TEST_F(GcodeArcs, ArcProgramMatchesTheBruteForceOfItsCircles) {
  // Each arc written with the circle it is (centre, radius, angles by hand).
  const std::string program =
      "G21 G90 G17\nG0 X2 Y0 Z1\nG1 Z-0.5 F100\n"
      "G3 X0 Y2 R2\n"             // quarter circle about (0, 0), r 2, from 0 to pi/2
      "G2 X-2 Y0 Z-0.3 I0 J-2\n"  // helical G2 about (0, 0), clockwise the long way
      "G0 Z1\nG0 X4 Y-3\nG1 Z-0.4\n"
      "G2 X4 Y-3 I0 J1\n"  // full circle about (4, -2), r 1, from -pi/2
      "G0 Z1\nG18\nG0 X-3 Y-4 Z0.2\n"
      "G3 X-5 Y-4 Z0.2 I-1 K0\n"  // G18: (z, x) plane, centre x = -4, a dip to z = -0.8
      "G0 Z1\nG19\nG0 X4 Y3 Z0.3\n"
      "G2 X4 Y1 Z0.3 J-1 K0\n"  // G19: (y, z) plane, centre y = 2
      "G0 Z5\nM30\n";
  const Job job = load(program, false);
  ASSERT_EQ(job.path.arcs.size(), 5u);
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  // G2 from (0, 2) to (-2, 0) about the origin: clockwise, pi/2 -> pi - 2 pi = -pi.
  const std::vector<RefArc> arcs = {
      {{0, 0, -0.5}, x, y, 2, 0, kPi / 2, 0},
      {{0, 0, -0.5}, x, y, 2, kPi / 2, -1.5 * kPi, 0.2},
      {{4, -2, -0.4}, x, y, 1, -kPi / 2, -2 * kPi, 0},
      // G18 (u = z, v = x): from (z, x) = (0.2, -3) about (0.2, -4): angle pi/2 through
      // pi (z = -0.8) to 3 pi/2, G3.
      {{-4, -4, 0.2}, z, x, 1, kPi / 2, kPi, 0},
      // G19 (u = y, v = z): from (y, z) = (3, 0.3) about (2, 0.3): angle 0 to -pi, G2.
      {{4, 2, 0.3}, y, z, 1, 0, -kPi, 0}};
  const ref::RefCutter cutter = ref::makeRefCutter(CutterType::Ball, 1, 0, 4);
  const ZMap map = simulate(job.cutter, job.path, job.stock, job.grid()).map;
  const GridSpec& g = map.grid();
  std::mt19937_64 rng(37);
  std::uniform_int_distribution<int64_t> pick(0, g.nx * g.ny - 1);
  int cut = 0;
  double worst = 0;
  for (int k = 0; k < 150; ++k) {
    const int64_t cell = pick(rng), i = cell % g.nx, j = cell / g.nx;
    const double cx = g.cellCentreX(i), cy = g.cellCentreY(j);
    double want = job.stock.max.z, depth = -HUGE_VAL;
    for (const RefArc& a : arcs) {
      ref::RefCurve curve;
      curve.axis = [](double) { return Vec3{0, 0, 1}; };
      curve.tip = [&a](double t) { return a.at(t); };
      curve.p0 = a.at(0), curve.p1 = a.at(1);
      double d = 0;
      const ref::RefHit h = ref::turningLowest(cutter, curve, cx, cy, 2001, &d);
      if (h.hit) want = std::min(want, h.z), depth = std::max(depth, d);
    }
    // The plunge and the straight moves between arcs are rapids or vertical: they add
    // nothing the arcs' ends do not (the plunge ends at the first arc's start).
    if (std::fabs(depth) < 1e-5) continue;  // grazing lines
    if (want < job.stock.max.z) ++cut;
    worst = std::max(worst, std::fabs(map.at(i, j) - want));
    EXPECT_NEAR(map.at(i, j), want, 1e-6) << "(" << cx << ", " << cy << ")";
  }
  std::printf("arc program: %d cut cells of 150 checked, worst |map - reference| = %.3g mm\n", cut,
              worst);
  EXPECT_GE(cut, 20);
}

TEST_F(GcodeArcs, ChordBaselineDiffersByTheChordError) {
  // Horizontal arcs of radius 4 at depth 0.5 with a ball R1: chords within 1e-4 mm of
  // the arc move the groove sideways by at most that, so on its floor, where the
  // ball's slope is at most 0.8 / 0.6 (heights up to 0.4 mm above the tip), a height
  // moves by at most 1e-4 sqrt(1 + (4/3)^2) = 1.67e-4 mm.
  const std::string program =
      "G21 G90 G17\nG0 X4 Y0 Z1\nG1 Z-0.5 F100\nG3 X-4 Y0 R4\nG3 X4 Y0 I4 J0\nG0 Z5\n";
  const Job exact = load(program, false), chords = load(program, true);
  ASSERT_EQ(exact.path.moves.size(), 4u);
  ASSERT_GT(chords.path.moves.size(), 100u);
  const ZMap a = simulate(exact.cutter, exact.path, exact.stock, exact.grid()).map;
  const ZMap b = simulate(chords.cutter, chords.path, chords.stock, chords.grid()).map;
  const GridSpec& g = a.grid();
  double floorWorst = 0, worst = 0;
  for (int64_t j = 0; j < g.ny; ++j)
    for (int64_t i = 0; i < g.nx; ++i) {
      const double d = std::fabs(a.at(i, j) - b.at(i, j));
      worst = std::max(worst, d);
      if (a.at(i, j) <= -0.1) floorWorst = std::max(floorWorst, d);
    }
  std::printf("chord baseline: largest height difference %.3g mm on the floor, %.3g overall\n",
              floorWorst, worst);
  EXPECT_LE(floorWorst, 1e-4 * std::sqrt(1 + 16.0 / 9) + 1e-9);
  EXPECT_GE(floorWorst, 1e-5);  // the chords are measurably not the arc
}

}  // namespace
}  // namespace scallop
