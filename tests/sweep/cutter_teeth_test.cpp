// The teeth's premises (sweep/cutter.h CutterTeeth, sweep/tooth_sweep.h): validation of
// the keys, the spindle envelope that bounds every edge point (the crossing search's
// lower bound), the edges lying on the cutter's surface, and moves without a feed per
// tooth refused. (The spindle angle along a path: tooth_sweep_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/brute_force_reference.h"
#include "sweep/cutter.h"
#include "sweep/tool_path_sweep.h"
#include "sweep/tooth_sweep.h"
#include "tests/support/input_error_message.h"

namespace scallop {
namespace {

TEST(CutterTeeth, MakeNamesTheFieldOfEachBadValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectRejected([] { CutterTeeth::make(0, 0, 0, 0, 3, "tools[1]"); }, "tools[1].flutes");
  expectRejected([] { CutterTeeth::make(17, 0, 0, 0, 3); }, "tool.flutes");
  expectRejected([] { CutterTeeth::make(2, -1, 0, 0, 3); }, "tool.helix_deg");
  expectRejected([] { CutterTeeth::make(2, 61, 0, 0, 3); }, "tool.helix_deg");
  expectRejected([&] { CutterTeeth::make(2, nan, 0, 0, 3); }, "tool.helix_deg");
  expectRejected([] { CutterTeeth::make(2, 0, -0.001, 0, 3); }, "tool.runout_mm");
  expectRejected([] { CutterTeeth::make(2, 0, 0.31, 0, 3); }, "tool.runout_mm");
  expectRejected([&] { CutterTeeth::make(2, 0, 0, nan, 3); }, "tool.runout_phase_deg");
  const CutterTeeth ok = CutterTeeth::make(4, 30, 0.01, -90, 3);
  EXPECT_EQ(ok.flutes, 4);
  EXPECT_EQ(ok.helixDeg, 30);
  EXPECT_EQ(ok.runout, 0.01);
  EXPECT_EQ(ok.runoutPhaseDeg, -90);
}

TEST(CutterTeeth, SpindleEnvelopePushesTheProfileOutByTheRunout) {
  Cutter ball = Cutter::make(CutterType::Ball, 3);
  EXPECT_EQ(ball.spindleEnvelope().radius, 3);  // no runout: the cutter itself
  ball.teeth.runout = 0.02;
  const Cutter env = ball.spindleEnvelope();
  EXPECT_EQ(env.type, CutterType::Bull);
  EXPECT_DOUBLE_EQ(env.radius, 3.02);
  EXPECT_EQ(env.cornerRadius, 3);
  EXPECT_EQ(env.fluteLength, ball.fluteLength);
  Cutter flat = Cutter::make(CutterType::Flat, 2);
  flat.teeth.runout = 0.01;
  EXPECT_EQ(flat.spindleEnvelope().type, CutterType::Flat);
  EXPECT_DOUBLE_EQ(flat.spindleEnvelope().radius, 2.01);
}

// Random cutters with teeth on random moves (tilted, some turning).
struct ToothCase {
  Cutter cutter;
  PoseCurve curve;
  double phaseStart, phaseRate;
};

ToothCase randomCase(std::mt19937& rng, int i) {
  std::uniform_real_distribution<double> U(0, 1);
  const int type = i % 3;
  Cutter c = type == 0   ? Cutter::make(CutterType::Ball, 1 + 3 * U(rng))
             : type == 1 ? Cutter::make(CutterType::Bull, 3, 0.3 + 2 * U(rng))
                         : Cutter::make(CutterType::Flat, 1 + 3 * U(rng));
  c.teeth = CutterTeeth::make(1 + i % 4, 45 * U(rng), c.radius / 10 * U(rng) * (i % 2),
                              360 * U(rng), c.radius);
  const double tilt0 = 1.2 * U(rng), tilt1 = tilt0 + (i % 4 == 3 ? 0.3 * U(rng) : 0);
  const double az = 2 * kPi * U(rng);
  const Vec3 a0 = ref::unitFromAngles(tilt0, az), a1 = ref::unitFromAngles(tilt1, az + 0.2);
  const Vec3 p0{4 * U(rng), 4 * U(rng), U(rng)}, p1{4 * U(rng), 4 * U(rng), U(rng)};
  const PoseCurve curve = PoseCurve::linear({p0, a0}, {p1, i % 4 == 3 ? a1 : a0});
  return {c, curve, 2 * kPi * U(rng), 50 * U(rng)};
}

TEST(CutterTeeth, EveryEdgePointLiesOnTheCutterAndInsideTheSpindleEnvelope) {
  std::mt19937 rng(18);
  std::uniform_real_distribution<double> U(0, 1);
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const ToothCase tc = randomCase(rng, i);
    const Cutter& c = tc.cutter;
    const ToothSweep teeth(c, tc.curve, tc.phaseStart, tc.phaseRate);
    const Cutter envCutter = c.spindleEnvelope();
    const ref::RefCutter env = ref::makeRefCutter(envCutter.type, envCutter.radius,
                                                  envCutter.cornerRadius, envCutter.fluteLength);
    const ref::RefCutter own = ref::makeRefCutter(c.type, c.radius, c.cornerRadius, c.fluteLength);
    for (int j = 0; j < 50; ++j) {
      const double t = U(rng);
      const int k = int(U(rng) * c.teeth.flutes) % c.teeth.flutes;
      // A point on the flat bottom, or on the profile at a random height.
      const bool bottom = j % 5 == 0 && c.bottomRadius() > 0;
      const double h = bottom ? 0 : c.fluteLength * U(rng);
      const double rho = bottom ? c.bottomRadius() * U(rng) : -1;
      const Vec3 p = teeth.edgePoint(k, h, rho, t);
      const Pose pose = tc.curve.pose(t);
      // Inside the spindle envelope standing at pose(t): the search's lower bound.
      EXPECT_TRUE(ref::inside(env, pose.tip, pose.axis, p, 1e-9)) << "case " << i << " " << j;
      // On the cutter's own surface: inside it (standing where the runout puts it),
      // and outside once pushed 1e-6 mm away from its axis.
      const Vec3 runoutTip = teeth.edgePoint(k, 0, 0, t);  // the cutter's own axis point
      EXPECT_TRUE(ref::inside(own, runoutTip, pose.axis, p, 1e-9)) << "case " << i << " " << j;
      const Vec3 across = p - runoutTip - dot(p - runoutTip, pose.axis) * pose.axis;
      if (!bottom && length(across) > 1e-6) {
        EXPECT_FALSE(ref::inside(own, runoutTip, pose.axis, p + normalize(across) * 1e-6))
            << "case " << i << " " << j;
      }
      ++checked;
    }
  }
  std::printf("edge points checked: %d\n", checked);
}

TEST(CutterTeeth, SweepRefusesMovesWithoutAFeedPerTooth) {
  const Cutter c = Cutter::make(CutterType::Ball, 3);
  ToolPath path;
  Move m;
  m.from = {{0, 0, 0}, {0, 0, 1}};
  m.to = {{1, 0, 0}, {0, 0, 1}};
  path.moves = {m, m};
  path.moves[1].from.tip = {1, 0, 0}, path.moves[1].to.tip = {2, 1, 0};
  path.moves[0].feedPerTooth = 0.1;  // the first carries its own, the second none
  CuttingModel cm;
  cm.kind = CuttingModelKind::Teeth;
  expectRejected([&] { sweepToolPath(c, path, cm); }, "path move 2");
  cm.feedPerTooth = 0.05;  // the job's feed serves the second
  EXPECT_EQ(sweepToolPath(c, path, cm).size(), 2u);
}

}  // namespace
}  // namespace scallop
