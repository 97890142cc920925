// Profile extraction and roughness (analysis/profile_metrology.h): bilinear sampling
// is exact on planes, a short-wave sine passes the Gaussian filter untouched, a long
// wave is attenuated by the ISO 16610-21 transmission 1 - exp(-pi (alpha lc / l)^2),
// a tilt never reaches the roughness profile, and bad lines are refused.
#include "analysis/profile_metrology.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "base/constants.h"
#include "base/input_error.h"
#include "raycast/zmap.h"
#include "tests/support/sampled_field.h"

namespace scallop {
namespace {

ZMap field(int64_t nx, int64_t ny, double spacing, const std::function<double(double, double)>& z) {
  return sampledField(0.5, -0.25, nx, ny, spacing, z);
}

TEST(ProfileMetrology, BilinearSamplesOfAPlaneAreExact) {
  auto plane = [](double x, double y) { return 0.3 * x - 0.7 * y + 0.125; };
  const ZMap map = field(20, 15, 0.1, plane);
  // A diagonal between arbitrary points inside the centres' span, odd step.
  const Profile p = extractProfile(map, 0.61, -0.1, 2.3, 1.1, 0.037, "--profile");
  const double length = std::hypot(2.3 - 0.61, 1.1 + 0.1);
  ASSERT_EQ(p.height.size(), size_t(std::floor(length / 0.037)) + 1);
  for (size_t k = 0; k < p.height.size(); ++k)
    EXPECT_NEAR(p.height[k], plane(p.xAt(int64_t(k)), p.yAt(int64_t(k))), 1e-14) << k;
  // Samples on the cell centres are the cells' heights themselves.
  const Profile row = extractProfile(map, 0.55, 0.3, 2.45, 0.3, 0, "--profile");
  ASSERT_EQ(row.height.size(), 20u);
  for (int64_t i = 0; i < 20; ++i) EXPECT_NEAR(row.height[size_t(i)], map.at(i, 5), 1e-15);
}

TEST(ProfileMetrology, LinesLeavingTheMapAreRefused) {
  const ZMap map = field(20, 15, 0.1, [](double, double) { return 0.0; });
  for (auto line : {std::array<double, 4>{0.5, 0.25, 2.45, 0.25},  // starts before 1st centre
                    {0.55, 0.25, 2.6, 0.25},
                    {0.6, 0.2, 0.6, 0.2},
                    {0.6, 0.2, NAN, 1}}) {
    try {
      extractProfile(map, line[0], line[1], line[2], line[3], 0, "--profile");
      ADD_FAILURE() << "accepted " << line[0] << " " << line[1] << " " << line[2];
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), "--profile");
    }
  }
}

// A sine of wavelength lc/10 on a tilt: the mean line is the tilt (the filter's
// transmission at lc/10 is 2^-100), so r is the sine: Rq = A/sqrt(2) over whole
// periods, Rz = Rt = 2A with the crests on samples, Ra = the samples' mean |A sin|.
TEST(ProfileMetrology, ShortWaveSinePassesUntouchedAndTiltIsRemoved) {
  const double amp = 0.002, wavelength = 0.08, step = 0.002, cutoff = 0.8;
  const double xStart = 0.501;
  auto z = [&](double x, double) {
    return 0.05 * x - 0.3 + amp * std::sin(2 * kPi * (x - xStart) / wavelength);
  };
  const ZMap map = field(4000, 3, step, z);
  const Profile p = extractProfile(map, xStart, 0.001 - 0.25 + 0.002, xStart + 7.0,
                                   0.001 - 0.25 + 0.002, 0, "--profile");
  const RoughnessStats r = roughness(p, cutoff, "--cutoff");
  EXPECT_EQ(r.samplingLengths, 5);
  EXPECT_NEAR(r.evaluationLengthMm, 5 * cutoff, 1e-12);
  EXPECT_GE(r.evaluationStartMm, cutoff - 1e-12);
  EXPECT_LE(r.evaluationStartMm + r.evaluationLengthMm, 7.0 - cutoff + 1e-12);
  double sumAbs = 0;
  for (int64_t k = r.firstSample; k < r.firstSample + r.sampleCount; ++k)
    sumAbs += std::abs(amp * std::sin(2 * kPi * double(k) * step / wavelength));
  const double tol = 1e-6 * amp;  // the kernel's truncation and sampling
  EXPECT_NEAR(r.ra, sumAbs / double(r.sampleCount), tol);
  EXPECT_NEAR(r.rq, amp / std::sqrt(2.0), tol);
  EXPECT_NEAR(r.rz, 2 * amp, tol);
  EXPECT_NEAR(r.rt, 2 * amp, tol);
  // Closed form: N samples a period from phase 0, mean |sin| = (2 / N) cot(pi / N).
  const double perPeriod = wavelength / step;
  EXPECT_NEAR(r.ra, amp * 2 / perPeriod / std::tan(kPi / perPeriod), tol);
}

// A sine of wavelength 10 lc keeps only 1 - H of its amplitude, H = exp(-pi (alpha
// lc / l)^2) = 2^(-1/100) being the Gaussian mean line's transmission (ISO 16610-21
// eq. 2). The evaluation length 5 lc is half a period: sum sin^2 = N/2 still holds.
TEST(ProfileMetrology, LongWaveIsAttenuatedByTheGaussianTransmission) {
  const double amp = 0.05, cutoff = 0.8, wavelength = 10 * cutoff, step = 0.004;
  const ZMap map = field(
      2000, 2, step, [&](double x, double) { return amp * std::sin(2 * kPi * x / wavelength); });
  const Profile p = extractProfile(map, 0.502, -0.248, 0.502 + 7.2, -0.248, 0, "--profile");
  const RoughnessStats r = roughness(p, cutoff, "--cutoff");
  ASSERT_EQ(r.samplingLengths, 5);
  const double transmission = std::exp(-kPi * std::log(2.0) / kPi / 100.0);  // 2^-0.01
  const double expected = amp * (1 - transmission) / std::sqrt(2.0);
  EXPECT_NEAR(r.rq, expected, 1e-3 * expected);
}

TEST(ProfileMetrology, TooShortProfilesAndBadCutoffsAreRefused) {
  const ZMap map = field(100, 2, 0.01, [](double x, double) { return x * x; });
  const Profile p = extractProfile(map, 0.505, -0.245, 1.495, -0.245, 0, "--profile");
  EXPECT_THROW(roughness(p, 0.8, "--cutoff"), InputError);  // 0.99 mm < 3 x 0.8 mm
  EXPECT_THROW(roughness(p, 0, "--cutoff"), InputError);
  EXPECT_THROW(roughness(p, -1, "--cutoff"), InputError);
  const RoughnessStats ok = roughness(p, 0.25, "--cutoff");
  EXPECT_EQ(ok.samplingLengths, 2);  // 100 samples: 2 x 25 run-in/out, 2 x 25 evaluated
  // x^2 has constant curvature: r = -(Gaussian variance) * 1 everywhere, Rt ~ 0.
  EXPECT_LT(ok.rt, 1e-12);
}

}  // namespace
}  // namespace scallop
