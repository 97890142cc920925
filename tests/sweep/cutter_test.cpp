// Cutter::make validation and defaults (CONVENTIONS.md "Cutters"), parseCutterType,
// and cutterSupport checked against the definition of the solid via the brute-force
// reference's inside() and support value.
#include "sweep/cutter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/brute_force_reference.h"
#include "sweep/swept_segment.h"

namespace scallop {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInfty = std::numeric_limits<double>::infinity();

// Runs `make` and expects an InputError whose message names `field`.
template <class F>
void expectRejected(F&& make, const std::string& field, const std::string& what) {
  try {
    make();
    ADD_FAILURE() << what << ": accepted, expected an InputError naming " << field;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos)
        << what << ": message \"" << e.what() << "\" does not name " << field;
    EXPECT_NE(e.where().find(field), std::string::npos) << what << ": where() = " << e.where();
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": threw a non-InputError: " << e.what();
  }
}

TEST(Cutter, RejectsBadRadius) {
  for (CutterType t : {CutterType::Ball, CutterType::Flat, CutterType::Bull}) {
    for (double R : {0.0, -1.0, -kInfty, kNaN, kInfty}) {
      expectRejected([&] { Cutter::make(t, R, 0.5); }, "tool.radius",
                     std::string(toString(t)) + " R=" + std::to_string(R));
    }
  }
}

TEST(Cutter, RejectsBadBullCornerRadius) {
  // 0 < r < R for bull: r < 0, r > R, r = R (that is a ball), NaN and inf are errors.
  for (double r : {-0.1, -kInfty, 3.5, 3.0, kNaN, kInfty}) {
    expectRejected([&] { Cutter::make(CutterType::Bull, 3.0, r); }, "tool.corner_radius",
                   "bull r=" + std::to_string(r));
  }
}

TEST(Cutter, RejectsNonFiniteFluteLength) {
  for (CutterType t : {CutterType::Ball, CutterType::Flat, CutterType::Bull}) {
    for (double L : {kNaN, kInfty}) {
      expectRejected([&] { Cutter::make(t, 2.0, 0.5, L); }, "tool.flute_length",
                     std::string(toString(t)) + " L=" + std::to_string(L));
    }
  }
}

TEST(Cutter, FieldPrefixIsUsed) {
  expectRejected([] { Cutter::make(CutterType::Ball, -1, 0, 0, "job.tools[2]"); },
                 "job.tools[2].radius", "custom prefix");
  expectRejected([] { Cutter::make(CutterType::Bull, 2, 2, 0, "t"); }, "t.corner_radius",
                 "custom prefix");
}

TEST(Cutter, Defaults) {
  const Cutter ball = Cutter::make(CutterType::Ball, 2.5);
  EXPECT_EQ(ball.type, CutterType::Ball);
  EXPECT_EQ(ball.radius, 2.5);
  EXPECT_EQ(ball.cornerRadius, 2.5);  // a ball is a bull with r = R
  EXPECT_EQ(ball.fluteLength, 10.0);  // 4 R
  EXPECT_EQ(ball.bottomRadius(), 0.0);

  const Cutter flat = Cutter::make(CutterType::Flat, 3);
  EXPECT_EQ(flat.cornerRadius, 0.0);
  EXPECT_EQ(flat.fluteLength, 12.0);
  EXPECT_EQ(flat.bottomRadius(), 3.0);

  const Cutter bull = Cutter::make(CutterType::Bull, 3, 1, 7);
  EXPECT_EQ(bull.cornerRadius, 1.0);
  EXPECT_EQ(bull.fluteLength, 7.0);
  EXPECT_EQ(bull.bottomRadius(), 2.0);

  // fluteLength <= 0 means the default; the corner radius is only read for bull.
  EXPECT_EQ(Cutter::make(CutterType::Bull, 3, 1, -2).fluteLength, 12.0);
  EXPECT_EQ(Cutter::make(CutterType::Ball, 2, 0.3).cornerRadius, 2.0);
  EXPECT_EQ(Cutter::make(CutterType::Flat, 2, 0.3).cornerRadius, 0.0);
}

TEST(Cutter, ParseType) {
  EXPECT_EQ(parseCutterType("ball"), CutterType::Ball);
  EXPECT_EQ(parseCutterType("flat"), CutterType::Flat);
  EXPECT_EQ(parseCutterType("bull"), CutterType::Bull);
  for (CutterType t : {CutterType::Ball, CutterType::Flat, CutterType::Bull})
    EXPECT_EQ(parseCutterType(toString(t)), t);
  expectRejected([] { parseCutterType("torus"); }, "tool.type", "torus");
  expectRejected([] { parseCutterType(""); }, "tool.type", "empty");
  expectRejected([] { parseCutterType("endmill", "job.tool.type"); }, "job.tool.type",
                 "custom field");
}

// ---- cutterSupport ---------------------------------------------------------------

TEST(Cutter, SupportPointIsTheExtremePointOfTheSolid) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> U(0, 1);
  double worstValue = 0;
  for (int i = 0; i < 300; ++i) {
    const CutterType type = CutterType(i % 3);
    const double R = 0.5 + 7.5 * U(rng);
    const double r = R * (0.02 + 0.96 * U(rng));
    const double L = i % 2 ? 0 : R * (1 + 5 * U(rng));
    const Cutter cutter = Cutter::make(type, R, r, L);
    const ref::RefCutter rc = ref::makeRefCutter(type, R, r, L);
    const double th = i % 5 == 0 ? 0 : i % 5 == 1 ? kPi / 2 : kPi / 2 * U(rng);
    const double ph = 2 * kPi * U(rng);
    const Vec3 axis = th == 0      ? Vec3{0, 0, 1}
                      : i % 5 == 1 ? Vec3{std::cos(ph), std::sin(ph), 0}
                                   : normalize(Vec3{std::sin(th) * std::cos(ph),
                                                    std::sin(th) * std::sin(ph), std::cos(th)});
    // Directions: random, and the axis-aligned and straight-down ones that hit the flat
    // end faces and edges head-on. Scaled by up to 10: dir need not be unit.
    Vec3 dir;
    switch (i % 6) {
      case 0:
        dir = Vec3{0, 0, -1};
        break;
      case 1:
        dir = axis * -2.0;
        break;
      case 2:
        dir = axis * 0.5;
        break;
      default:
        dir = Vec3{U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5} * (0.1 + 10 * U(rng));
        break;
    }
    const Vec3 p = cutterSupport(cutter, axis, dir);
    ASSERT_TRUE(isFinite(p)) << "case " << i;
    const double scale = length(dir) * (rc.L + R);
    // On the solid (1e-9 mm of rounding) ...
    EXPECT_TRUE(ref::inside(rc, {0, 0, 0}, axis, p, 1e-9)) << "case " << i;
    // ... on its boundary: a step of 1e-6 mm further along dir leaves it ...
    EXPECT_FALSE(ref::inside(rc, {0, 0, 0}, axis, p + normalize(dir) * 1e-6)) << "case " << i;
    // ... and extreme: its value is the reference support value, and no sampled point
    // of the solid (surface of revolution, both end disks) does better.
    const double value = dot(dir, p);
    const double want = ref::supportValue(rc, axis, dir);
    EXPECT_NEAR(value, want, 1e-12 * scale + 1e-12) << "case " << i;
    worstValue = std::max(worstValue, std::fabs(value - want) / scale);
    const Vec3 u = std::fabs(axis.z) < 0.9 ? normalize(cross(axis, Vec3{0, 0, 1}))
                                           : normalize(cross(axis, Vec3{1, 0, 0}));
    const Vec3 v = cross(axis, u);
    for (int j = 0; j < 400; ++j) {
      const double s = j % 4 == 0 ? 0 : j % 4 == 1 ? rc.L : rc.L * U(rng);
      const double rho = j % 4 < 2 ? ref::profile(rc, s) * std::sqrt(U(rng)) : ref::profile(rc, s);
      const double ang = 2 * kPi * U(rng);
      const Vec3 q = axis * s + u * (rho * std::cos(ang)) + v * (rho * std::sin(ang));
      EXPECT_GE(value, dot(dir, q) - 1e-12 * scale) << "case " << i << " sample " << j;
    }
  }
  std::printf("cutterSupport: worst |value - reference| / (|dir| (L + R)) = %.3g\n", worstValue);
}

}  // namespace
}  // namespace scallop
