// ISO 25178-2 height parameters (analysis/surface_metrology.h) against closed forms
// and brute-force sums on small synthetic fields: a cosine, a tilted plane with and
// without the cosine, a single spike; levelling, regions, merging and determinism.
#include "analysis/surface_metrology.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <random>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"
#include "raycast/zmap.h"
#include "tests/support/sampled_field.h"
#include "tools/io/height_images.h"

namespace scallop {
namespace {

constexpr double kRel = 1e-9;

ZMap field(int64_t nx, int64_t ny, double spacing, const std::function<double(double, double)>& z) {
  return sampledField(-1.0, 2.0, nx, ny, spacing, z);
}

// Brute force: mean |h - mean| and extremes of values h, in long double.
struct Naive {
  long double mean = 0, sa = 0, max = -HUGE_VALL, min = HUGE_VALL;
};
Naive naive(const std::vector<double>& h) {
  Naive r;
  for (double v : h) r.mean += v;
  r.mean /= h.size();
  for (double v : h) {
    r.sa += std::fabs(v - r.mean);
    r.max = std::max<long double>(r.max, v);
    r.min = std::min<long double>(r.min, v);
  }
  r.sa /= h.size();
  return r;
}

void expectRel(double actual, double expected, double rel, const char* what) {
  EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << what;
}

// A cosine of amplitude A along x with whole periods of N cells: sampled at the cell
// centres, sum cos^2 = N/2 and sum cos^4 = 3N/8 exactly (N > 4), and sum cos^3 = 0, so
// Sq = A/sqrt(2), Sku = 1.5, Ssk = 0 whatever the phase.
constexpr double kAmp = 0.0125;    // mm
constexpr double kSpacing = 0.01;  // mm
constexpr int64_t kPeriodCells = 16;
double wave(double x) {
  return kAmp * std::cos(2 * kPi * (x + 1.0) / (kPeriodCells * kSpacing));
}

TEST(SurfaceMetrology, CosineMatchesClosedForms) {
  const ZMap map = field(3 * kPeriodCells, 5, kSpacing, [](double x, double) { return wave(x); });
  std::vector<double> h(map.heights());
  const Naive ref = naive(h);
  for (Levelling level : {Levelling::kNone, Levelling::kPlane}) {
    const SurfaceStats s = surfaceStats(map, wholeMap(map.grid()), level);
    expectRel(s.sq, kAmp / std::sqrt(2.0), kRel, "Sq");
    expectRel(s.sku, 1.5, kRel, "Sku");
    EXPECT_NEAR(s.ssk, 0.0, kRel) << "Ssk";
    expectRel(s.sa, double(ref.sa), kRel, "Sa");
    expectRel(s.sp, double(ref.max), kRel, "Sp");
    expectRel(s.sv, -double(ref.min), kRel, "Sv");
    expectRel(s.sz, double(ref.max - ref.min), kRel, "Sz");
    EXPECT_EQ(s.cells, map.grid().cells());
    expectRel(s.areaMm2, 48 * 5 * kSpacing * kSpacing, 1e-12, "area");
  }
}

// The cosine's samples are symmetric about the centre of the region, so it is
// orthogonal to x and y: the least-squares plane of tilt + cosine is the tilt itself.
TEST(SurfaceMetrology, PlaneLevellingRemovesTiltExactly) {
  const double a = 0.03, b = -0.02, c = -0.5;
  const ZMap map = field(3 * kPeriodCells, 9, kSpacing,
                         [&](double x, double y) { return a * x + b * y + c + wave(x); });
  const SurfaceStats s = surfaceStats(map, wholeMap(map.grid()), Levelling::kPlane);
  EXPECT_NEAR(s.plane.slopeX, a, 1e-12);
  EXPECT_NEAR(s.plane.slopeY, b, 1e-12);
  EXPECT_NEAR(s.plane.at(0.3, 2.1), a * 0.3 + b * 2.1 + c, 1e-12);
  const ZMap pure = field(3 * kPeriodCells, 9, kSpacing, [](double x, double) { return wave(x); });
  const Naive ref = naive(pure.heights());
  expectRel(s.sq, kAmp / std::sqrt(2.0), kRel, "Sq");
  expectRel(s.sku, 1.5, kRel, "Sku");
  EXPECT_NEAR(s.ssk, 0.0, kRel);
  expectRel(s.sa, double(ref.sa), kRel, "Sa");
  expectRel(s.sp, double(ref.max), kRel, "Sp");
  expectRel(s.sv, -double(ref.min), kRel, "Sv");
}

// Unlevelled tilt a*x over n columns of spacing s: the heights are a discrete uniform
// distribution of n values a*s apart, so Sq = a s sqrt((n^2 - 1)/12), Sa = a s n / 4
// (n even), Ssk = 0, Sku = 3 - 6 (n^2 + 1) / (5 (n^2 - 1)), Sp = Sv = a s (n - 1) / 2.
TEST(SurfaceMetrology, UnlevelledTiltIsADiscreteUniformDistribution) {
  const double a = 0.04, s = 0.02, n = 40;
  const ZMap map = field(40, 3, s, [&](double x, double) { return a * x + 0.7; });
  const SurfaceStats st = surfaceStats(map, wholeMap(map.grid()), Levelling::kNone);
  expectRel(st.sq, a * s * std::sqrt((n * n - 1) / 12), kRel, "Sq");
  expectRel(st.sa, a * s * n / 4, kRel, "Sa");
  EXPECT_NEAR(st.ssk, 0.0, kRel);
  expectRel(st.sku, 3 - 6 * (n * n + 1) / (5 * (n * n - 1)), kRel, "Sku");
  expectRel(st.sp, a * s * (n - 1) / 2, kRel, "Sp");
  expectRel(st.sv, a * s * (n - 1) / 2, kRel, "Sv");
  // Levelled, nothing is left: every parameter is rounding noise.
  const SurfaceStats lev = surfaceStats(map, wholeMap(map.grid()), Levelling::kPlane);
  EXPECT_LT(lev.sq, 1e-14);
  EXPECT_LT(lev.sz, 1e-13);
}

// One cell of height h among n zeros: a Bernoulli distribution with p = 1/n.
// Sa = 2 h (n - 1)/n^2, Sq = h sqrt(n - 1)/n, Ssk = (n - 2)/sqrt(n - 1),
// Sku = (n^2 - 3n + 3)/(n - 1), Sp = h (n - 1)/n, Sv = h/n, Sz = h. In the centre of
// an odd grid the spike is orthogonal to x and y, so levelling does not change this.
TEST(SurfaceMetrology, SingleSpikeIsABernoulliDistribution) {
  const double h = 0.25;
  ZMap map = field(9, 7, 0.5, [](double, double) { return 0.0; });
  map.at(4, 3) = h;
  const double n = 63;
  for (Levelling level : {Levelling::kNone, Levelling::kPlane}) {
    const SurfaceStats s = surfaceStats(map, wholeMap(map.grid()), level);
    expectRel(s.sa, 2 * h * (n - 1) / (n * n), kRel, "Sa");
    expectRel(s.sq, h * std::sqrt(n - 1) / n, kRel, "Sq");
    expectRel(s.ssk, (n - 2) / std::sqrt(n - 1), kRel, "Ssk");
    expectRel(s.sku, (n * n - 3 * n + 3) / (n - 1), kRel, "Sku");
    expectRel(s.sp, h * (n - 1) / n, kRel, "Sp");
    expectRel(s.sv, h / n, kRel, "Sv");
    expectRel(s.sz, h, kRel, "Sz");
  }
}

TEST(SurfaceMetrology, RegionSelectsCellCentresInsideTheRectangle) {
  const ZMap map = field(10, 8, 0.5, [](double x, double y) { return x * y; });
  // Centres are at x = -0.75, -0.25, ..., 3.75 and y = 2.25, ..., 5.75.
  const CellRegion r = regionOfRectangle(map.grid(), -0.25, 2.3, 1.0, 3.25, "--region");
  EXPECT_EQ(r.i0, 1);
  EXPECT_EQ(r.i1, 4);  // -0.25, 0.25, 0.75
  EXPECT_EQ(r.j0, 1);
  EXPECT_EQ(r.j1, 3);  // 2.75, 3.25
  // The region's spike statistics are the region's alone.
  ZMap spiky = map;
  for (double& z : spiky.heights()) z = 0;
  spiky.at(2, 2) = 1.0;
  spiky.at(9, 7) = 100.0;  // outside the region
  const SurfaceStats s = surfaceStats(spiky, r, Levelling::kNone);
  EXPECT_EQ(s.cells, 6);
  expectRel(s.sz, 1.0, kRel, "Sz");
  const CellRegion all = regionOfRectangle(map.grid(), -100, -100, 100, 100, "--region");
  EXPECT_EQ(all.cells(), map.grid().cells());
}

TEST(SurfaceMetrology, BadRegionsAreRefusedWithTheField) {
  const ZMap map = field(10, 8, 0.5, [](double, double) { return 0.0; });
  for (auto rect : std::vector<std::array<double, 4>>{
           {1, 3, 0, 4}, {0, 3, 1, 3}, {50, 50, 60, 60}, {-0.4, 2.0, -0.3, 6}, {NAN, 0, 1, 1}}) {
    try {
      regionOfRectangle(map.grid(), rect[0], rect[1], rect[2], rect[3], "--region");
      ADD_FAILURE() << "accepted " << rect[0] << " " << rect[1] << " " << rect[2] << " " << rect[3];
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), "--region");
    }
  }
}

std::vector<double> randomHeights(size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(-0.3, 0.01);
  std::vector<double> v(n);
  for (double& x : v) x = normal(rng);
  return v;
}

// Merging two accumulators equals one pass over both sets (to rounding), as the
// tiled simulation's band-by-band statistics rely on.
TEST(SurfaceMetrology, MergedMomentsEqualOnePass) {
  const std::vector<double> v = randomHeights(1001, 7);
  HeightMoments all, a, b;
  for (size_t k = 0; k < v.size(); ++k) {
    all.add(v[k]);
    (k < 317 ? a : b).add(v[k]);
  }
  a.add(b);
  EXPECT_EQ(a.count(), all.count());
  EXPECT_NEAR(a.mean(), all.mean(), 1e-15);
  expectRel(a.m2(), all.m2(), 1e-12, "M2");
  EXPECT_NEAR(a.m3(), all.m3(), 1e-12 * std::pow(all.m2(), 1.5) / std::sqrt(1001.0));
  expectRel(a.m4(), all.m4(), 1e-12, "M4");
  EXPECT_EQ(a.min(), all.min());
  EXPECT_EQ(a.max(), all.max());
  // And the naive two-pass central moments agree.
  long double mean = 0, m2 = 0, m4 = 0;
  for (double x : v) mean += x;
  mean /= v.size();
  for (double x : v) {
    m2 += (x - mean) * (x - mean);
    m4 += (x - mean) * (x - mean) * (x - mean) * (x - mean);
  }
  expectRel(all.m2(), double(m2), 1e-12, "M2 naive");
  expectRel(all.m4(), double(m4), 1e-11, "M4 naive");
}

// Same bits on 1, 2 and 5 threads: fixed chunks, fixed reduction tree.
TEST(SurfaceMetrology, ResultDoesNotDependOnTheThreadCount) {
  const std::vector<double> v = randomHeights(301 * 157, 11);
  size_t k = 0;
  const ZMap map =
      field(301, 157, 0.003, [&](double x, double y) { return v[k++] + 0.1 * x - 0.2 * y; });
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return surfaceStats(map, wholeMap(map.grid()), Levelling::kPlane);
  };
  const SurfaceStats one = run(1);
  for (int threads : {2, 5}) {
    const SurfaceStats s = run(threads);
    EXPECT_EQ(s.sa, one.sa) << threads;
    EXPECT_EQ(s.sq, one.sq) << threads;
    EXPECT_EQ(s.ssk, one.ssk) << threads;
    EXPECT_EQ(s.sku, one.sku) << threads;
    EXPECT_EQ(s.sz, one.sz) << threads;
    EXPECT_EQ(s.plane.slopeX, one.plane.slopeX) << threads;
  }
  // A Gaussian surface has Sku near 3 (plain kurtosis) and Ssk near 0.
  EXPECT_NEAR(one.sku, 3.0, 0.1);
  EXPECT_NEAR(one.ssk, 0.0, 0.05);
  EXPECT_NEAR(one.sq, 0.01, 0.0005);
}

// Bands of raw heights merged in order give the unlevelled parameters (but Sa, which
// needs the mean before the pass) of the whole map.
TEST(SurfaceMetrology, BandMomentsGiveTheUnlevelledParameters) {
  const std::vector<double> v = randomHeights(64 * 50, 3);
  size_t k = 0;
  const ZMap map = field(64, 50, 0.01, [&](double, double) { return v[k++]; });
  HeightMoments merged;
  for (int64_t j0 = 0; j0 < 50; j0 += 16)
    merged.add(residualMoments(map, {0, j0, 64, std::min<int64_t>(50, j0 + 16)}, LevelPlane()));
  const SurfaceStats banded = statsFromMoments(merged, LevelPlane(), 1e-4, false);
  const SurfaceStats whole = surfaceStats(map, wholeMap(map.grid()), Levelling::kNone);
  EXPECT_TRUE(std::isnan(banded.sa));
  expectRel(banded.sq, whole.sq, 1e-12, "Sq");
  expectRel(banded.ssk, whole.ssk, 1e-9, "Ssk");
  expectRel(banded.sku, whole.sku, 1e-12, "Sku");
  expectRel(banded.sp, whole.sp, 1e-12, "Sp");
  expectRel(banded.sv, whole.sv, 1e-12, "Sv");
  expectRel(banded.plane.z0, whole.plane.z0, 1e-14, "mean");
}

// Read back from a float32 file, the parameters keep float precision: the heights
// change by at most half an ulp of float at their magnitude (|z| <= 0.52 mm here).
TEST(SurfaceMetrology, GsfRoundTripKeepsFloatPrecision) {
  const double a = 0.03, b = -0.02, c = -0.5;
  const ZMap map = field(3 * kPeriodCells, 9, kSpacing,
                         [&](double x, double y) { return a * x + b * y + c + wave(x); });
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("scallop-sm-" + std::to_string(::getpid()) + ".gsf"))
                               .string();
  writeHeightsGsf(map, path, "round trip");
  const ZMap back = readHeightsGsf(path);
  std::filesystem::remove(path);
  const SurfaceStats s = surfaceStats(back, wholeMap(back.grid()), Levelling::kPlane);
  const double tol = 4 * FLT_EPSILON * 0.52;  // mm: a few float ulps of the largest |z|
  const ZMap pure = field(3 * kPeriodCells, 9, kSpacing, [](double x, double) { return wave(x); });
  const Naive ref = naive(pure.heights());
  EXPECT_NEAR(s.sq, kAmp / std::sqrt(2.0), tol);
  EXPECT_NEAR(s.sa, double(ref.sa), tol);
  EXPECT_NEAR(s.sp, double(ref.max), tol);
  EXPECT_NEAR(s.sv, -double(ref.min), tol);
  EXPECT_NEAR(s.sku, 1.5, 1.5 * 4 * tol / (kAmp / std::sqrt(2.0)));
  EXPECT_NEAR(s.ssk, 0.0, 3 * tol / (kAmp / std::sqrt(2.0)));
  // And the file's numbers are not the double ones bit for bit (float32 storage).
  EXPECT_NE(s.sq, surfaceStats(map, wholeMap(map.grid()), Levelling::kPlane).sq);
}

}  // namespace
}  // namespace scallop
