// The surface the teeth leave (cutting model "teeth", sweep/tooth_sweep.h) against
// closed forms: the feed marks of one pass with lead, their convergence to the envelope
// as fz -> 0, the runout threshold above which one tooth does all the finishing; and
// the scene's heights with teeth (threads, bands, culling) against the moves' own.
//
// One pass along +X on y = 0 with the axis leaned by the lead lambda towards the feed,
// a = (sin lambda, 0, cos lambda), tip at z = 0. The spindle frame's e1 (world X made
// perpendicular to a) is then d = (cos lambda, 0, -sin lambda), the downhill direction
// across the axis. Helix 0: when tooth k's angle psi_k - phi is 0 its edge is the
// meridian section of the cutter in the plane y = 0, on the downhill side; at every other
// angle the edge's half-plane holds the axis, which lies in y = 0, so the edge meets
// y = 0 only at the tip, far above the contact. So the centre line's profile is the
// lower envelope of the downhill sections at the tooth passes, fz apart along X: circles
// of the feed-direction profile radius rho_f about the section's centre of curvature
// (the ball's centre, rho_f = R; a bull's corner centre, rho_f = r). Their bottoms are
// the envelope's height and adjacent circles meet fz / 2 from either bottom:
//     peak - valley = rho_f - sqrt(rho_f^2 - fz^2 / 4)  ~  fz^2 / (8 rho_f).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "base/constants.h"
#include "raycast/simulation.h"
#include "sweep/brute_force_reference.h"
#include "sweep/raster.h"
#include "sweep/tool_path_sweep.h"
#include "sweep/tooth_sweep.h"
#include "tests/support/band_check.h"

namespace scallop {
namespace {

CuttingModel teethModel(double fz, double phaseDeg = 0) {
  CuttingModel model;
  model.kind = CuttingModelKind::Teeth;
  model.feedPerTooth = fz;
  model.phaseDeg = phaseDeg;
  return model;
}

Vec3 leadAxis(double leadDeg) {
  const double l = degToRad(leadDeg);
  return {std::sin(l), 0, std::cos(l)};
}

// One pass along X from x0 to x1 on y = 0, tip at z = 0.
SweptMove pass(const Cutter& c, double leadDeg, double fz, double x0 = -8, double x1 = 8) {
  ToolPath path;
  const Vec3 a = leadAxis(leadDeg);
  path.moves.push_back(Move{{{x0, 0, 0}, a}, {{x1, 0, 0}, a}});
  std::vector<SweptMove> moves = sweepToolPath(c, path, teethModel(fz));
  EXPECT_EQ(moves.size(), 1u);
  return moves[0];
}

Cutter withTeeth(Cutter c, int flutes, double helixDeg = 0, double runout = 0,
                 double runoutPhaseDeg = 0) {
  c.teeth = CutterTeeth::make(flutes, helixDeg, runout, runoutPhaseDeg, c.radius);
  return c;
}

struct Extremum {
  double x, z;
};

struct Profile {
  std::vector<Extremum> peaks, valleys;
};

// The local maxima and minima of h on [xa, xb]: samples dx apart, each sampled extreme
// refined by golden section between its neighbours (a cusp is the maximum of a
// unimodal function there, a mark's bottom the minimum), so the grid does not bias
// the heights. dx must be well below the marks' spacing.
Profile extremes(const std::function<double(double)>& h, double xa, double xb, double dx) {
  const int n = int(std::ceil((xb - xa) / dx));
  std::vector<double> z(size_t(n) + 1);
  for (int i = 0; i <= n; ++i) z[size_t(i)] = h(xa + i * dx);
  Profile p;
  for (int i = 1; i < n; ++i) {
    const double zl = z[size_t(i - 1)], zi = z[size_t(i)], zr = z[size_t(i + 1)];
    const double lo = xa + (i - 1) * dx, hi = xa + (i + 1) * dx;
    if (zi >= zl && zi > zr) {
      const auto best = ref::goldenMax(h, lo, hi);
      p.peaks.push_back({best.first, best.second});
    } else if (zi <= zl && zi < zr) {
      const auto best = ref::goldenMax([&](double x) { return -h(x); }, lo, hi);
      p.valleys.push_back({best.first, -best.second});
    }
  }
  return p;
}

std::function<double(double)> centreLine(const SweptMove& move) {
  return [&move](double x) {
    const LowestPoint lp = move.lowestPoint(x, 0);
    EXPECT_TRUE(lp.hit) << x;
    return lp.z;
  };
}

// The closed form of the header comment on one pass: every valley at the envelope's
// height, every peak rho_f - sqrt(rho_f^2 - fz^2 / 4) above it, the marks fz apart.
void expectFeedMarks(const Cutter& c, double leadDeg, double fz, double rhoF, double exactTol,
                     const char* name) {
  const SweptMove move = pass(c, leadDeg, fz);
  const unsigned long long unproven = ToothSweep::unprovenSearches();
  const Profile p = extremes(centreLine(move), -0.5, 0.5, fz / 40);
  const double envelope = move.envelopeLowestPoint(0, 0).z;
  const double exact = rhoF - std::sqrt(rhoF * rhoF - fz * fz / 4), approx = fz * fz / (8 * rhoF);
  ASSERT_GE(p.peaks.size(), 9u);
  ASSERT_GE(p.valleys.size(), 9u);
  double peakMin = HUGE_VAL, peakMax = -HUGE_VAL, valleyMin = HUGE_VAL, valleyMax = -HUGE_VAL;
  for (const Extremum& e : p.peaks)
    peakMin = std::min(peakMin, e.z), peakMax = std::max(peakMax, e.z);
  for (const Extremum& e : p.valleys)
    valleyMin = std::min(valleyMin, e.z), valleyMax = std::max(valleyMax, e.z);
  const double pv = peakMax - valleyMin;
  std::printf(
      "%s: %zu marks, peak-to-valley %.6g um (fz^2/(8 rho_f) %.6g, circles %.6g); peaks "
      "spread %.2g mm, valleys %.2g mm above the envelope\n",
      name, p.valleys.size(), pv * 1e3, approx * 1e3, exact * 1e3, peakMax - peakMin,
      valleyMax - envelope);
  EXPECT_NEAR(pv, approx, 0.01 * approx) << name;
  EXPECT_NEAR(pv, exact, exactTol) << name;
  EXPECT_NEAR(valleyMin, envelope, exactTol) << name;
  EXPECT_NEAR(valleyMax, envelope, exactTol) << name;
  EXPECT_NEAR(peakMin, envelope + exact, exactTol) << name;
  for (size_t i = 1; i < p.valleys.size(); ++i)
    EXPECT_NEAR(p.valleys[i].x - p.valleys[i - 1].x, fz, 0.02 * fz) << name << " " << i;
  EXPECT_EQ(ToothSweep::unprovenSearches(), unproven) << name;
}

TEST(ToothSurface, BallWithLeadLeavesCirclesOfItsRadius) {
  // fz^2 / (8 R) = 0.4167 um.
  expectFeedMarks(withTeeth(Cutter::make(CutterType::Ball, 3), 2), 15, 0.1, 3, 1e-9,
                  "ball R3 lead 15 fz 0.1");
}

TEST(ToothSurface, BullWithLeadLeavesCirclesOfItsCorner) {
  // The contact is on the corner: fz^2 / (8 r) = 1.25 um.
  expectFeedMarks(withTeeth(Cutter::make(CutterType::Bull, 5, 1), 2), 10, 0.1, 1, 1e-9,
                  "bull R5 r1 lead 10 fz 0.1");
}

// A helix of angle beta moves the edge's crossing of y = 0 along the meridian circle as
// the spindle turns: the crossing's height is h = R (phi - psi_k) / tan(beta) (its angle
// psi_k + h tan(beta) / R - phi is 0), so the time of each point of the circle is linear
// in its h, and the cutter has moved kappa h along X by then, kappa = fz flutes tan(beta)
// / (2 pi R). In the circle's own coordinates (X, Z) about its centre (rho_f = R),
// h = R + X sin(lambda) + Z cos(lambda), so the mark is the affine image of the circle
//     x = (1 + eps) X + kappa cos(lambda) Z,   z = Z,   eps = kappa sin(lambda)
// (eps = 0.16 % here). A horizontal shear x += s z keeps every height and commutes with
// the marks' spacing (a shift of fz along X), so it changes neither the bottoms nor the
// heights where neighbouring marks meet: those are the circles stretched by 1 + eps,
//     peak - valley = R - sqrt(R^2 - fz^2 / (4 (1 + eps)^2))   (0.32 % below helix 0).
TEST(ToothSurface, HelixStretchesTheMarks) {
  const double R = 3, fz = 0.1, beta = degToRad(30), lambda = degToRad(15);
  const double eps = fz * 2 * std::tan(beta) * std::sin(lambda) / (2 * kPi * R);
  const double stretched = R - std::sqrt(R * R - fz * fz / (4 * (1 + eps) * (1 + eps)));
  const SweptMove move = pass(withTeeth(Cutter::make(CutterType::Ball, R), 2, 30), 15, fz);
  const Profile p = extremes(centreLine(move), -0.5, 0.5, fz / 40);
  ASSERT_GE(p.peaks.size(), 9u);
  ASSERT_GE(p.valleys.size(), 9u);
  const double envelope = move.envelopeLowestPoint(0, 0).z;
  double worst = 0;
  for (const Extremum& v : p.valleys) EXPECT_NEAR(v.z, envelope, 1e-9);
  for (const Extremum& e : p.peaks) {
    worst = std::max(worst, std::fabs(e.z - envelope - stretched) / stretched);
    EXPECT_NEAR(e.z - envelope, stretched, 1e-9);
  }
  std::printf(
      "ToothSurface helix 30: peak-to-valley %.6g um, stretched circles %.6g um "
      "(eps %.4g), worst relative difference %.2g\n",
      (p.peaks[0].z - envelope) * 1e3, stretched * 1e3, eps, worst);
}

// As fz -> 0 the teeth surface tends to the envelope: the largest teeth - envelope
// height on the centre line (the cusps) is rho_f - sqrt(rho_f^2 - fz^2 / 4), so it falls
// like fz^2 with the constant 1 / (8 rho_f).
TEST(ToothSurface, ConvergesToTheEnvelopeLikeFzSquared) {
  const Cutter c = withTeeth(Cutter::make(CutterType::Ball, 3), 2);
  std::vector<double> fzs{0.2, 0.1, 0.05, 0.025}, gaps;
  for (double fz : fzs) {
    const SweptMove move = pass(c, 15, fz);
    const Profile p = extremes(centreLine(move), -4 * fz, 4 * fz, fz / 40);
    double gap = 0;
    for (const Extremum& e : p.peaks) gap = std::max(gap, e.z - move.envelopeLowestPoint(e.x, 0).z);
    ASSERT_GE(p.peaks.size(), 6u) << fz;
    gaps.push_back(gap);
  }
  // Least-squares slope of log(gap) against log(fz).
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = double(fzs.size());
  for (size_t i = 0; i < fzs.size(); ++i) {
    const double lx = std::log(fzs[i]), ly = std::log(gaps[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  const double exponent = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  std::printf("ToothSurface convergence: max(teeth - envelope) =");
  for (size_t i = 0; i < fzs.size(); ++i) std::printf(" %.5g um (fz %g)", gaps[i] * 1e3, fzs[i]);
  std::printf("; exponent %.4f; constants", exponent);
  for (size_t i = 0; i < fzs.size(); ++i) std::printf(" %.5f", gaps[i] / (fzs[i] * fzs[i]));
  std::printf(" (1 / (8 R) = %.5f)\n", 1 / 24.0);
  EXPECT_GE(exponent, 1.9);
  EXPECT_LE(exponent, 2.1);
  for (size_t i = 0; i < fzs.size(); ++i) {
    EXPECT_NEAR(gaps[i] / (fzs[i] * fzs[i]), 1 / 24.0, 0.01 / 24.0) << fzs[i];
    if (i) {
      EXPECT_NEAR(gaps[i - 1] / gaps[i], 4, 0.04) << fzs[i];
    }
  }
}

// Runout rho at phase 0 pushes tooth 0 out: its body is displaced by rho along its own
// direction, so at its downhill pass the cutter (ball R3, lead 15, 2 flutes, fz 0.1) is
// shifted by +rho d = rho (cos lambda, 0, -sin lambda), and tooth 1 at its pass (half a
// turn later, the runout then pointing uphill) by -rho d. The two teeth's circles (radius
// rho_f = R) are dz = 2 rho sin(lambda) apart in height, and tooth 1's lie sigma =
// 2 rho cos(lambda) behind the even spacing: tooth 1's bottom is A = fz - sigma after the
// last tooth-0 bottom and B = fz + sigma before the next. With parabolic marks z = x^2 /
// (2 rho_f) about each bottom (tooth 1's at x = 0, tooth 0's at -A and B, dz lower),
// tooth 1's parabola is below tooth 0's left one for x > (2 rho_f dz - A^2) / (2 A) and
// below the right one for x < (B^2 - 2 rho_f dz) / (2 B): tooth 1 still cuts somewhere
// iff that interval is not empty,
//     dz (A + B) 2 rho_f < A B (A + B)   <=>   2 rho_f dz < (fz - sigma)(fz + sigma),
//     4 cos^2(lambda) rho^2 + 4 rho_f sin(lambda) rho - fz^2 < 0,
//     rho < rho* = (-rho_f sin(lambda) + sqrt(rho_f^2 sin^2(lambda) + fz^2 cos^2(lambda)))
//                  / (2 cos^2(lambda))            (3.2074 um; ~fz^2 / (4 rho_f sin(lambda))).
// With the circles themselves the threshold is 1.0003 rho* (bisection by hand on the two
// circles). Tooth 1's bottom itself survives (a local minimum of its own) while
// 2 rho_f dz < A^2, which holds at 0.5 and 0.7 rho*; between that and rho* it leaves only
// a facet between two cusps.
double runoutThreshold(double rhoF, double lambda, double fz) {
  const double s = std::sin(lambda), c = std::cos(lambda);
  return (-rhoF * s + std::sqrt(rhoF * rhoF * s * s + fz * fz * c * c)) / (2 * c * c);
}

TEST(ToothSurface, RunoutBelowTheThresholdBothTeethMarkAboveItOne) {
  const double R = 3, lambda = degToRad(15), fz = 0.1;
  const double rhoStar = runoutThreshold(R, lambda, fz);
  EXPECT_NEAR(rhoStar, 3.2074e-3, 1e-7);
  const double envelopeFree = R * std::cos(lambda) - R;  // the ball's lowest point, tip z = 0
  for (double k : {0.5, 0.7, 1.5, 3.0}) {
    const double rho = k * rhoStar;
    const Cutter c = withTeeth(Cutter::make(CutterType::Ball, R), 2, 0, rho, 0);
    const SweptMove move = pass(c, 15, fz);
    const unsigned long long unproven = ToothSweep::unprovenSearches();
    const Profile p = extremes(centreLine(move), -0.6, 0.6, fz / 100);
    const double dz = 2 * rho * std::sin(lambda), sigma = 2 * rho * std::cos(lambda);
    ASSERT_GE(p.valleys.size(), 5u) << k;
    double spacingMin = HUGE_VAL, spacingMax = 0;
    for (size_t i = 1; i < p.valleys.size(); ++i) {
      const double s = p.valleys[i].x - p.valleys[i - 1].x;
      spacingMin = std::min(spacingMin, s), spacingMax = std::max(spacingMax, s);
    }
    std::printf("ToothSurface runout %.2f rho* (%.3f um): %zu valleys, spacing %.5f to %.5f mm\n",
                k, rho * 1e3, p.valleys.size(), spacingMin, spacingMax);
    for (size_t i = 0; i < p.valleys.size(); ++i) {
      // Tooth 0's bottom at the spindle envelope's lowest point (dz / 2 below the
      // cutter's), tooth 1's dz / 2 above the cutter's.
      const bool low = p.valleys[i].z < envelopeFree;
      EXPECT_NEAR(p.valleys[i].z, envelopeFree + (low ? -0.5 : 0.5) * dz, 1e-9) << k << " " << i;
      if (k > 1) {
        EXPECT_TRUE(low) << k << " " << i;
      }
      if (i == 0) continue;
      const double s = p.valleys[i].x - p.valleys[i - 1].x;
      if (k < 1) {
        // Both teeth: after a tooth-0 bottom the next (tooth 1) is fz - sigma on.
        EXPECT_NEAR(s, p.valleys[i - 1].z < envelopeFree ? fz - sigma : fz + sigma, 2e-5)
            << k << " " << i;
      } else {
        EXPECT_NEAR(s, 2 * fz, 2e-5) << k << " " << i;
      }
    }
    EXPECT_EQ(ToothSweep::unprovenSearches(), unproven) << k;
  }
}

// The width of tooth 1's facet with the exact circles (radius rho_f, tooth 1's bottom
// at x = 0, tooth 0's dz lower at -A and B; see above): where its circle is below both
// of tooth 0's. Tooth 1's arc minus tooth 0's left one is decreasing in x (the slope
// u / sqrt(rho_f^2 - u^2) of a lower arc grows with the distance u past its bottom, and
// the left circle's u is larger), minus the right one increasing; both are positive at
// their own circle's bottom. So each has at most one root on [-A, B], found by bisection,
// and the facet is between them (0 when either has none).
double circleFacet(double rhoF, double lambda, double fz, double rho) {
  const double dz = 2 * rho * std::sin(lambda), sigma = 2 * rho * std::cos(lambda);
  const double A = fz - sigma, B = fz + sigma;
  auto arc = [&](double x, double centre, double bottom) {
    return bottom + rhoF - std::sqrt(rhoF * rhoF - (x - centre) * (x - centre));
  };
  auto left = [&](double x) { return arc(x, 0, dz) - arc(x, -A, 0); };
  auto right = [&](double x) { return arc(x, 0, dz) - arc(x, B, 0); };
  if (!(left(B) < 0) || !(right(-A) < 0)) return 0;
  auto root = [&](auto&& g) {  // g(-A) and g(B) of opposite signs
    double lo = -A, hi = B;
    const bool negativeAtLo = g(lo) < 0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      ((g(mid) < 0) == negativeAtLo ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  return std::max(0.0, root(right) - root(left));
}

// The threshold itself. With the circles (circleFacet) it is within 0.1 % of rho*; and
// the kernel's surface agrees: which tooth cut each point of the centre line (from the
// crossing's t, tooth k being downhill where phi(t) = psi_k mod 2 pi) just below rho*
// (tooth 1 owns one facet per 2 fz, 5 um wide at 0.95 rho*) and just above it (none).
TEST(ToothSurface, RunoutThresholdIsWhereTheSecondToothStopsCutting) {
  const double R = 3, lambda = degToRad(15), fz = 0.1;
  const double rhoStar = runoutThreshold(R, lambda, fz);
  double lo = 0.5 * rhoStar, hi = 1.5 * rhoStar;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (circleFacet(R, lambda, fz, mid) > 0 ? lo : hi) = mid;
  }
  std::printf("ToothSurface runout threshold: rho* %.5f um, with the circles %.5f um\n",
              rhoStar * 1e3, lo * 1e3);
  EXPECT_NEAR(lo, rhoStar, 1e-3 * rhoStar);
  for (double k : {0.95, 1.05}) {
    const Cutter c = withTeeth(Cutter::make(CutterType::Ball, R), 2, 0, k * rhoStar, 0);
    const SweptMove move = pass(c, 15, fz);
    const ToothSweep& teeth = *move.teeth();
    int byTooth[2] = {0, 0};
    const double dx = 2.5e-4;
    for (int i = 0; i < 800; ++i) {  // one period, 2 fz
      const LowestPoint lp = move.lowestPoint(-0.1 + (i + 0.5) * dx, 0);
      ASSERT_TRUE(lp.hit);
      const double phi = teeth.phaseStart() + teeth.phaseRate() * lp.t;
      ++byTooth[int(std::lround(phi / kPi)) & 1];
    }
    const double facet = circleFacet(R, lambda, fz, k * rhoStar);
    std::printf(
        "ToothSurface runout %.2f rho*: tooth 1 cut %d points of 0.25 um (%.3f um; "
        "the circles' facet %.3f um)\n",
        k, byTooth[1], byTooth[1] * dx * 1e3, facet * 1e3);
    EXPECT_NEAR(byTooth[1] * dx, facet, 2 * dx) << k;
    if (k > 1) {
      EXPECT_EQ(byTooth[1], 0);
    }
  }
}

// A small raster with teeth (ball R1, lead 10, two passes): 1 and 2 threads, bands and
// the whole map give the same bits, and every cell is the minimum of the stock top and
// every move's own teeth height (the scene's culling, made of the envelope's bounds,
// loses none).
struct RasterJob {
  Cutter cutter = withTeeth(Cutter::make(CutterType::Ball, 1), 2, 20, 0.01, 30);
  Box3 stock;
  ToolPath path;
  SimulationOptions options;
};

RasterJob rasterJob() {
  RasterJob job;
  job.stock = Box3({0, 0, -1}, {0.5, 0.3, 0});
  RasterSpec spec;
  spec.stepOver = 0.2;
  spec.depth = 0.05;
  spec.leadDeg = 10;
  spec.zigzag = true;
  job.path = makeRaster(job.cutter, job.stock, spec);
  job.options.cutting = teethModel(0.05, 12);
  return job;
}

ZMap simulateWith(const RasterJob& job, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
  const GridSpec grid =
      gridCovering(job.stock.min.x, job.stock.min.y, job.stock.max.x, job.stock.max.y, 0.01);
  return simulate(job.cutter, job.path, job.stock, grid, job.options).map;
}

TEST(ToothSurface, ThreadsAndBandsChangeNoBit) {
  const RasterJob job = rasterJob();
  const ZMap one = simulateWith(job, 1), two = simulateWith(job, 2);
  ASSERT_EQ(one.heights().size(), two.heights().size());
  EXPECT_EQ(one.heights(), two.heights());
  EXPECT_LT(one.maxHeight(), job.stock.max.z - 0.01);  // cut everywhere

  const std::unique_ptr<SweptScene> scene =
      buildScene(job.cutter, job.path, job.stock, one.grid().spacing, job.options);
  expectBandsEqualWhole(*scene, one, 7, job.stock.max.z);
}

TEST(ToothSurface, EveryCellIsTheLowestTeethHeightOfAllMoves) {
  const RasterJob job = rasterJob();
  const ZMap map = simulateWith(job, 2);
  const std::vector<SweptMove> moves = sweepToolPath(job.cutter, job.path, job.options.cutting);
  const GridSpec& g = map.grid();
  double teethAboveEnvelope = 0;
  for (int64_t j = 0; j < g.ny; j += 2) {
    for (int64_t i = 0; i < g.nx; i += 2) {
      double want = job.stock.max.z, envelope = job.stock.max.z;
      for (const SweptMove& m : moves) {
        const LowestPoint lp = m.lowestPoint(g.cellCentreX(i), g.cellCentreY(j));
        if (lp.hit) want = std::min(want, lp.z);
        const LowestPoint env = m.envelopeLowestPoint(g.cellCentreX(i), g.cellCentreY(j));
        if (env.hit) envelope = std::min(envelope, env.z);
      }
      ASSERT_EQ(map.at(i, j), want) << i << " " << j;
      teethAboveEnvelope = std::max(teethAboveEnvelope, want - envelope);
    }
  }
  // The teeth surface is really not the envelope (feed marks ~fz^2 / (8 R) = 0.3 um).
  EXPECT_GT(teethAboveEnvelope, 1e-4);
}

}  // namespace
}  // namespace scallop
