// The flute top's bound (interval_bounds.cpp step 2e) on its own: on vertical lines that
// touch a turning cutter's flute-top rim where its flank faces down, it must prove the
// miss of intervals on the side where the line passes beside the cutter (including
// those a few micro-units of t from the touch), and every interval it proves (of those
// beside or across the touch) must be a miss in the brute-force reference (each of 65
// poses across it, written from the definition: brute_force_reference.h).
#include "sweep/interval_bounds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "base/constants.h"
#include "sweep/brute_force_reference.h"
#include "sweep/pose_curve.h"

namespace scallop {
namespace {

TEST(IntervalBounds, FluteTopMissAgreesWithTheBruteForce) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(0, 1);
  const CutterType types[] = {CutterType::Ball, CutterType::Bull, CutterType::Flat};
  int proven = 0, tried = 0, wrong = 0, nearTouch = 0;
  for (int k = 0; k < 18; ++k) {
    const CutterType type = types[k % 3];
    const double R = 1 + 2 * u(rng), r = type == CutterType::Bull   ? R * (0.2 + 0.5 * u(rng))
                                         : type == CutterType::Ball ? R
                                                                    : 0;
    const double L = R * (2 + 2 * u(rng));
    const Cutter cutter = Cutter::make(type, R, r, L);
    const ref::RefCutter refCutter = ref::makeRefCutter(type, R, r, L);
    // Axes leaned 0.15 to 0.8 rad, turned by up to ~0.2 rad; a level or ramping feed.
    const double polar = 0.15 + 0.65 * u(rng), azimuth = 2 * kPi * u(rng);
    const Vec3 a0 = ref::unitFromAngles(polar, azimuth);
    const Vec3 a1 = ref::unitFromAngles(polar + 0.2 * (u(rng) - 0.5),
                                        azimuth + 0.2 * (u(rng) - 0.5) / std::sin(polar));
    const Vec3 p0{u(rng), u(rng), u(rng)};
    const Vec3 p1 = p0 + Vec3{2 * u(rng) - 1, 2 * u(rng) - 1, 0.3 * (u(rng) - 0.5)};
    const PoseCurve curve = PoseCurve::linear({p0, a0}, {p1, a1});
    TurningBounds bounds;
    bounds.reach = std::hypot(L, R);
    bounds.tipSpeed = curve.tipSpeedBound();
    // The line through a point of the flute top's rim whose flank faces down, at t*:
    // it touches K(t*) there alone.
    const double ts = 0.2 + 0.6 * u(rng), psi = 2 * u(rng) - 1;
    const Vec3 a = ref::slerp(a0, a1, ts), tip = p0 + (p1 - p0) * ts;
    const Vec3 down = normalize(Vec3{0, 0, -1} + a * a.z), side = cross(a, down);
    const Vec3 rim = tip + a * L + (down * std::cos(psi) + side * std::sin(psi)) * R;
    const IntervalBounds ib(cutter, curve, bounds, rim.x, rim.y);
    for (double d : {1e-6, 1e-4, 1e-2}) {
      for (double wOverD : {0.25, 1.0, 4.0}) {
        for (double sign : {-1.0, 0.0, 1.0}) {
          // Beside the touch on either side, or across it (sign 0: mostly before it).
          const double near = sign == 0 ? ts + d : ts + sign * d;
          const double far = sign == 0 ? ts - d * wOverD : ts + sign * d * (1 + wOverD);
          SearchSample ends[2];
          ends[0].t = std::clamp(std::min(near, far), 0.0, 1.0);
          ends[1].t = std::clamp(std::max(near, far), 0.0, 1.0);
          if (!(ends[0].t < ends[1].t)) continue;
          for (SearchSample& e : ends) e.tip = curve.tip(e.t);
          ++tried;
          if (!ib.missesBesideFluteTop(ends[0], ends[1])) continue;
          ++proven;
          if (d == 1e-6) ++nearTouch;
          for (int i = 0; i <= 64; ++i) {
            const double t = ends[0].t + (ends[1].t - ends[0].t) * i / 64;
            const ref::RefHit hit = ref::stationaryLowest(refCutter, p0 + (p1 - p0) * t,
                                                          ref::slerp(a0, a1, t), rim.x, rim.y);
            if (hit.hit) {
              ++wrong;
              std::printf("  case %d: [%.9g, %.9g] proven a miss, hit at t = %.9g (z %.9g)\n", k,
                          ends[0].t, ends[1].t, t, hit.z);
              break;
            }
          }
        }
      }
    }
  }
  std::printf(
      "IntervalBounds flute top: %d of %d intervals proven misses (%d within 1e-6 of "
      "the touch), %d wrong\n",
      proven, tried, nearTouch, wrong);
  EXPECT_EQ(wrong, 0);
  EXPECT_GE(proven, 60);
  EXPECT_GE(nearTouch, 10);
}

}  // namespace
}  // namespace scallop
