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

// A profile made directly (no map), samples `step` apart.
Profile syntheticProfile(double lengthMm, double step, const std::function<double(double)>& z) {
  Profile p{0, 0, lengthMm, 0, step, {}};
  const int64_t n = int64_t(std::floor(lengthMm / step + 1e-9)) + 1;
  for (int64_t k = 0; k < n; ++k) p.height.push_back(z(double(k) * step));
  return p;
}

// Unfiltered cosine on a tilt over whole periods: x cos(kx) sums to 0 over them, so the
// least-squares line is the tilt and r is the cosine. By hand, with M samples a period,
// N = 40 M intervals and the samples k = 0..N (the last one a crest again): the sum of
// cos^2 is N/2 + 1 and of |cos| is N (2/M) cot(pi/M) + 1 (|cos| at M/4 | M samples is
// |sin| shifted), so Ra and Rq follow; Rz = Rt = 2A (one sampling length: the whole
// profile); Rsm = the wavelength (the upward crossings are a wavelength apart).
TEST(ProfileMetrology, UnfilteredCosineByHand) {
  const double amp = 0.003, wavelength = 0.4, step = 0.0005, length = 40 * wavelength;
  const Profile p = syntheticProfile(
      length, step, [&](double x) { return 0.02 * x + amp * std::cos(2 * kPi * x / wavelength); });
  RoughnessFilter none;
  none.cutoffMm = 0;
  const RoughnessStats r = roughness(p, none, "--cutoff");
  EXPECT_EQ(r.samplingLengths, 1);
  EXPECT_NEAR(r.evaluationLengthMm, length, 1e-9);
  const double M = wavelength / step, N = 40 * M;
  // The extra crest leaves the samples' own least-squares line an offset and tilt of
  // order A / N (one sample of N + 1), which bounds the difference.
  const double tol = amp / N;
  EXPECT_NEAR(r.ra, amp * (N * (2 / M) / std::tan(kPi / M) + 1) / (N + 1), tol);
  EXPECT_NEAR(r.rq, amp * std::sqrt((N / 2 + 1) / (N + 1)), tol);
  EXPECT_NEAR(r.rt, 2 * amp, 2 * tol);
  EXPECT_EQ(r.rz, r.rt);
  EXPECT_NEAR(r.rsm, wavelength, 1e-9);
  EXPECT_NE(r.filter.name().find("unfiltered"), std::string::npos);
}

// A sawtooth of period P rising from -A to +A: Ra = A/2, Rq = A/sqrt(3), Rt = Rz = 2A,
// Rsm = P, by hand. Filtered with lc = 1 mm = 10 P the mean line is flat (transmission
// 2^-100 at P). Unfiltered, the least-squares line of N whole teeth over L = N P has
// slope 2AP/L^2 (x times the tooth integrates to AP^2/6 a tooth; var x = L^2/12): it
// tilts r by up to AP/L at the ends and moves the crossings by up to P^2/(2L), which is
// what the unfiltered tolerances are. (Unfiltered, the sampling length is the whole
// 8 mm, so Rsm's width discrimination is 0.08 mm: below P.)
TEST(ProfileMetrology, SawtoothByHandUnfilteredAndFiltered) {
  const double amp = 0.004, period = 0.1, step = 0.0001, length = 8.0;
  auto tooth = [&](double x) {
    const double f = x / period - std::floor(x / period);
    return amp * (2 * f - 1);
  };
  // Offset by half a step so no sample sits on a drop.
  const Profile p = syntheticProfile(length, step, [&](double x) { return tooth(x + step / 2); });
  RoughnessFilter none;
  none.cutoffMm = 0;
  RoughnessFilter gauss;
  gauss.cutoffMm = 1.0;
  const double sampling = 2 * amp * step / period;  // one sample's rise
  const double tilt = amp * period / length;
  for (const RoughnessFilter& f : {none, gauss}) {
    const RoughnessStats r = roughness(p, f, "--cutoff");
    const bool filtered = f.cutoffMm > 0;
    const double heightTol = sampling + (filtered ? 1e-6 * amp : tilt);
    EXPECT_NEAR(r.ra, amp / 2, heightTol) << f.name();
    EXPECT_NEAR(r.rq, amp / std::sqrt(3.0), heightTol) << f.name();
    EXPECT_NEAR(r.rt, 2 * amp, 2 * heightTol) << f.name();
    EXPECT_NEAR(r.rz, 2 * amp, 2 * heightTol) << f.name();
    const double widthTol = filtered ? 1e-9 : period * period / (2 * length);
    EXPECT_NEAR(r.rsm, period, widthTol) << f.name();
  }
  EXPECT_EQ(roughness(p, gauss, "--cutoff").samplingLengths, 5);
}

// Rsm's height discrimination: a ripple of 5 % of the amplitude (below 10 % of Rz) adds
// no elements.
TEST(ProfileMetrology, RsmIgnoresARippleBelowTheHeightDiscrimination) {
  const double amp = 0.002, wavelength = 0.25, ripple = 0.01, step = 0.0005;
  const Profile p = syntheticProfile(10.0, step, [&](double x) {
    return amp * std::sin(2 * kPi * x / wavelength) + 0.05 * amp * std::sin(2 * kPi * x / ripple);
  });
  const RoughnessStats r = roughness(p, 0.8, "--cutoff");
  EXPECT_NEAR(r.rsm, wavelength, 1e-3 * wavelength);
}

// The lambda-s filter is the Gaussian low-pass: a sine of wavelength l keeps
// T(l) = exp(-pi (alpha ls / l)^2) of its amplitude (alpha^2 = ln 2 / pi), so
// Rq = sqrt((A T(l1))^2 + (B T(l2))^2 / 2) for two sines far below lc.
TEST(ProfileMetrology, LambdaSAttenuatesByTheGaussianTransmission) {
  const double a = 0.002, l1 = 0.25, b = 0.001, l2 = 0.02, step = 0.0005, ls = 0.025;
  const Profile p = syntheticProfile(12.0, step, [&](double x) {
    return a * std::sin(2 * kPi * x / l1) + b * std::sin(2 * kPi * x / l2);
  });
  RoughnessFilter f;
  f.cutoffMm = 2.5;
  f.lambdaSMm = ls;
  const RoughnessStats r = roughness(p, f, "--lambda-s");
  auto T = [&](double l) { return std::exp(-std::log(2.0) * (ls / l) * (ls / l)); };
  const double want = std::sqrt((a * T(l1) * a * T(l1) + b * T(l2) * b * T(l2)) / 2);
  // lc = 2.5 mm passes l1 = 0.25 mm with 1 - 2^-100; the sum of sin^2 over the
  // evaluation length (not whole periods of both) is N/2 within 1e-3.
  EXPECT_NEAR(r.rq, want, 2e-3 * want);
  EXPECT_NE(r.filter.name().find("ls 0.025"), std::string::npos);
  EXPECT_EQ(r.samplingLengths, 2);  // 12 mm - 2 (2.5 + 0.025) mm run-in/out: 2 lengths
}

TEST(ProfileMetrology, BadFiltersAreRefusedWithTheirReason) {
  const Profile p = syntheticProfile(3.0, 0.001, [](double x) { return std::sin(x); });
  RoughnessFilter f;
  f.cutoffMm = 0.8;
  f.lambdaSMm = 0.0015;  // under two sample steps
  EXPECT_THROW(roughness(p, f, "--lambda-s"), InputError);
  f.lambdaSMm = 0.5;  // not below lc / 2
  EXPECT_THROW(roughness(p, f, "--lambda-s"), InputError);
  f.lambdaSMm = 0;
  f.cutoffMm = 2.5;  // 3 mm < 3 lc
  try {
    roughness(p, f, "--cutoff");
    ADD_FAILURE() << "accepted a 3 mm profile for lc 2.5 mm";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "--cutoff");
    EXPECT_NE(std::string(e.what()).find("7.5 mm"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("unfiltered"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace scallop
