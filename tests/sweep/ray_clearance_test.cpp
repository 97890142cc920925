// The ray-clearance proof (sweep/ray_clearance.h) against the brute-force reference:
// it must never clear a height at or above the true lowest point of a turning move
// (soundness, over every kind of move), and it must clear heights just below it on
// CAM-like moves (usefulness: what the turning-axis search relies on for speed).
#include "sweep/ray_clearance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "base/constants.h"
#include "sweep/brute_force_reference.h"
#include "sweep/pose_curve.h"
#include "tests/support/random_cases.h"

namespace scallop {
namespace {

using ref::unitFromAngles;

struct Move {
  Cutter cutter;
  ref::RefCutter refCutter;
  Vec3 p0, p1, a0, a1;
};

// Ball, flat and bull cutters; `camLike`: moves of 0.05 to 0.5 mm whose axis turns by up
// to about 1 degree and leans up to 30 degrees, as 5-axis finishing paths are; otherwise
// axes from vertical to horizontal, turns up to 90 degrees, feeds, ramps and plunges.
enum class Family { CamLike, Turning, Any };
Move randomMove(std::mt19937_64& rng, int k, Family family) {
  const bool camLike = family == Family::CamLike;
  std::uniform_real_distribution<double> u(0, 1);
  Move m;
  const test::CutterShape s = test::randomCutterShape(rng, k);
  m.cutter = Cutter::make(s.type, s.radius, s.cornerRadius, s.fluteLength);
  m.refCutter = ref::makeRefCutter(s.type, s.radius, s.cornerRadius, s.fluteLength);
  const double lean = (family == Family::Any ? kPi / 2 : kPi / 6) * u(rng);
  const double azimuth = 2 * kPi * u(rng);
  // The turn's scale: ~1 degree (CAM-like), up to ~15 degrees (turning).
  const double turn = camLike ? 0.017 : 0.26;
  m.a0 = unitFromAngles(lean, azimuth);
  for (;;) {
    m.a1 = family == Family::Any ? unitFromAngles(0.5 * kPi * u(rng), 2 * kPi * u(rng))
                                 : unitFromAngles(std::fabs(lean + turn * (u(rng) - 0.5)),
                                                  azimuth + 2 * turn * (u(rng) - 0.5));
    if (dot(m.a0, m.a1) >= 1e-3 && dot(m.a0, m.a1) < 1 - 1e-9) break;
  }
  const double len = camLike ? 0.05 + 0.45 * u(rng) * u(rng) : family == Family::Turning ? 0.5 : 3;
  const double heading = 2 * kPi * u(rng);
  m.p0 = {0, 0, 0};
  m.p1 = {len * std::cos(heading), len * std::sin(heading), 0};
  if (k % 4 == 1) m.p1.z = len * 0.5 * (u(rng) - 0.5);            // ramps
  if (!camLike && k % 4 == 2) m.p1 = {0, 0, 2 * (u(rng) - 0.5)};  // plunges
  if (!camLike && k % 4 == 3) m.p1 = m.p0;                        // pure turns about the tip
  return m;
}

// The reference's lowest point on the line and the t where it is attained (a dense grid
// of the reference's own stationary solver, refined by golden section).
struct RefMinimum {
  bool hit = false;
  double z = 0, t = 0;
};
RefMinimum referenceMinimum(const Move& m, double x, double y) {
  auto f = [&](double t) {
    const ref::RefHit h = ref::stationaryLowest(m.refCutter, m.p0 + (m.p1 - m.p0) * t,
                                                ref::slerp(m.a0, m.a1, t), x, y);
    return h.hit ? h.z : HUGE_VAL;
  };
  RefMinimum best;
  best.z = HUGE_VAL;
  constexpr int kGrid = 400;
  int kBest = -1;
  for (int k = 0; k <= kGrid; ++k) {
    const double z = f(double(k) / kGrid);
    if (z < best.z) best.z = z, kBest = k;
  }
  if (kBest < 0) return best;
  const auto refined =
      ref::goldenMax([&](double t) { return -f(t); }, std::max(0.0, (kBest - 1.0) / kGrid),
                     std::min(1.0, (kBest + 1.0) / kGrid));
  best.hit = true;
  best.t = double(kBest) / kGrid;
  if (-refined.second <= best.z) best.z = -refined.second, best.t = refined.first;
  return best;
}

// Lines over the move's footprint: the tip path widened by the cutter's reach.
void randomLine(std::mt19937_64& rng, const Move& m, double& x, double& y) {
  std::uniform_real_distribution<double> u(-1, 1);
  const double reach = 1.2 * m.cutter.radius;
  x = 0.5 * (m.p0.x + m.p1.x) + (0.5 * std::fabs(m.p1.x - m.p0.x) + reach) * u(rng);
  y = 0.5 * (m.p0.y + m.p1.y) + (0.5 * std::fabs(m.p1.y - m.p0.y) + reach) * u(rng);
}

// Three random lines over the move (randomLine); `visit(x, y, minimum)` for each that
// meets the solid, in the order drawn (visit may draw from rng too).
template <class Visit>
void forLinesThatMeetIt(std::mt19937_64& rng, const Move& m, Visit&& visit) {
  for (int q = 0; q < 3; ++q) {
    double x, y;
    randomLine(rng, m, x, y);
    const RefMinimum ref = referenceMinimum(m, x, y);
    if (ref.hit) visit(x, y, ref);
  }
}

// Soundness: a height at or above the true lowest point is never cleared, from any
// anchor, on CAM-like moves, moves that turn by up to ~15 degrees and any move: just above it
// (1e-8, 1e-6 mm), well above it, and above the whole cutter on that line (where only the
// argument's "below" half can refuse it).
TEST(RayClearance, NeverClearsAHeightAtOrAboveTheLowestPoint) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(0, 1);
  int checks = 0, hits = 0;
  for (int k = 0; k < 600; ++k) {
    const Family family = k % 5 == 0 ? Family::CamLike : k % 5 == 4 ? Family::Any : Family::Turning;
    const Move m = randomMove(rng, k, family);
    const PoseCurve curve = PoseCurve::linear({m.p0, m.a0}, {m.p1, m.a1});
    forLinesThatMeetIt(rng, m, [&](double x, double y, const RefMinimum& ref) {
      ++hits;
      const double above[] = {1e-8, 1e-6, 1e-3, 0.5, 2 * m.cutter.radius, 50};
      const double anchors[] = {0, 0.5, 1, ref.t, u(rng)};
      for (double dz : above) {
        for (double anchor : anchors) {
          ++checks;
          EXPECT_FALSE(rayClearsMove(m.cutter, curve, {x, y, ref.z + dz}, anchor, 0, 1))
              << "move " << k << " (" << toString(m.cutter.type) << ") line (" << x << ", " << y
              << ") cleared " << dz << " mm above its lowest point " << ref.z
              << " from t = " << anchor;
        }
      }
    });
  }
  std::printf("RayClearance soundness: %d lines that meet the solid, %d checks\n", hits, checks);
  EXPECT_GE(hits, 300);
}

// Usefulness: on CAM-like moves of ball and bull cutters, heights just below the lowest
// point are cleared from an anchor at the minimum (what step 4b of the search asks),
// and heights a few micrometres lower from the middle of the move (step 4a's cutoff
// test). The rates are what the search's speed rests on; a flat cutter is never cleared.
TEST(RayClearance, ClearsHeightsJustBelowTheLowestPointOfCamLikeMoves) {
  std::mt19937_64 rng(4242);
  int lines = 0, atMinimum = 0, fromMiddle = 0, flatCleared = 0, flatLines = 0;
  for (int k = 0; k < 300; ++k) {
    const Move m = randomMove(rng, k, Family::CamLike);
    const PoseCurve curve = PoseCurve::linear({m.p0, m.a0}, {m.p1, m.a1});
    forLinesThatMeetIt(rng, m, [&](double x, double y, const RefMinimum& ref) {
      if (m.cutter.type == CutterType::Flat) {
        ++flatLines;
        flatCleared += rayClearsMove(m.cutter, curve, {x, y, ref.z - 1e-3}, ref.t, 0, 1);
        return;
      }
      ++lines;
      atMinimum += rayClearsMove(m.cutter, curve, {x, y, ref.z - 1e-9}, ref.t, 0, 1);
      fromMiddle += rayClearsMove(m.cutter, curve, {x, y, ref.z - 5e-3}, 0.5, 0, 1);
    });
  }
  std::printf(
      "RayClearance on CAM-like moves: %d lines; cleared 1e-9 mm below from the minimum: %d, "
      "5 um below from the middle: %d; flat cutter: %d of %d\n",
      lines, atMinimum, fromMiddle, flatCleared, flatLines);
  ASSERT_GE(lines, 300);
  EXPECT_GE(atMinimum, lines * 8 / 10);
  EXPECT_GE(fromMiddle, lines * 8 / 10);
  EXPECT_EQ(flatCleared, 0);
}

// The lines of a disc: its centre, 12 on its rim and 12 inside.
std::vector<std::pair<double, double>> discLines(std::mt19937_64& rng, double x, double y,
                                                 double radius) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::pair<double, double>> lines{{x, y}};
  for (int k = 0; k < 12; ++k) {
    const double a = 2 * kPi * k / 12;
    lines.push_back({x + radius * std::cos(a), y + radius * std::sin(a)});
    const double b = 2 * kPi * u(rng), rr = radius * std::sqrt(u(rng));
    lines.push_back({x + rr * std::cos(b), y + rr * std::sin(b)});
  }
  return lines;
}

// The lowest point, over the lines of a disc (discLines), of the reference's minima on
// each (HUGE_VAL where no line meets the solid).
double lowestOnDisc(std::mt19937_64& rng, const Move& m, double x, double y, double radius) {
  double lowest = HUGE_VAL;
  for (const auto& [lx, ly] : discLines(rng, x, y, radius)) {
    const RefMinimum ref = referenceMinimum(m, lx, ly);
    if (ref.hit) lowest = std::min(lowest, ref.z);
  }
  return lowest;
}

// Soundness of the disc (what a block of cells asks, raysClearMove): a height at or
// above the lowest point of any line of the disc is never cleared, on every kind of
// move and for discs of 1 um to 0.2 mm.
TEST(RayClearance, DiscNeverClearsAHeightAtOrAboveTheLowestPointOfItsLines) {
  std::mt19937_64 rng(2718);
  int checks = 0, discs = 0;
  for (int k = 0; k < 360; ++k) {
    const Family family = k % 3 == 0 ? Family::CamLike : k % 3 == 1 ? Family::Turning : Family::Any;
    const Move m = randomMove(rng, k, family);
    const PoseCurve curve = PoseCurve::linear({m.p0, m.a0}, {m.p1, m.a1});
    double x, y;
    randomLine(rng, m, x, y);
    const double radius = k % 3 == 0 ? 1e-3 : k % 3 == 1 ? 0.02 : 0.2;
    const double lowest = lowestOnDisc(rng, m, x, y, radius);
    if (!(lowest < HUGE_VAL)) continue;
    ++discs;
    for (double dz : {1e-8, 1e-6, 1e-3, 0.5, 50.0}) {
      ++checks;
      EXPECT_FALSE(raysClearMove(m.cutter, curve, {x, y, lowest + dz}, radius))
          << "move " << k << " (" << toString(m.cutter.type) << ") disc (" << x << ", " << y
          << ") radius " << radius << " cleared " << dz << " mm above the lowest point " << lowest
          << " of one of its lines";
    }
  }
  std::printf("RayClearance of discs: %d discs that meet the solid, %d checks\n", discs, checks);
  EXPECT_GE(discs, 200);
}

// Usefulness of the disc, and its radius 0 is the single line's proof from the middle:
// on CAM-like moves of ball and bull cutters, a disc of 20 um (a block of 16 cells of
// 1.25 um) is cleared 0.1 mm below its lines' lowest point.
TEST(RayClearance, DiscClearsHeightsWellBelowItsLinesOnCamLikeMoves) {
  std::mt19937_64 rng(1618);
  int discs = 0, cleared = 0, sameAsLine = 0;
  for (int k = 0; k < 300; ++k) {
    const Move m = randomMove(rng, k, Family::CamLike);
    if (m.cutter.type == CutterType::Flat) continue;
    const PoseCurve curve = PoseCurve::linear({m.p0, m.a0}, {m.p1, m.a1});
    double x, y;
    randomLine(rng, m, x, y);
    const double lowest = lowestOnDisc(rng, m, x, y, 0.02);
    if (!(lowest < HUGE_VAL)) continue;
    ++discs;
    const Vec3 q{x, y, lowest - 0.1};
    cleared += raysClearMove(m.cutter, curve, q, 0.02);
    sameAsLine +=
        raysClearMove(m.cutter, curve, q, 0) == rayClearsMove(m.cutter, curve, q, 0.5, 0, 1);
  }
  std::printf("RayClearance of 20 um discs 0.1 mm below on CAM-like moves: %d of %d\n", cleared,
              discs);
  ASSERT_GE(discs, 100);
  EXPECT_GE(cleared, discs * 8 / 10);
  EXPECT_EQ(sameAsLine, discs);
}

// The search's Newton step: lowestPointCurvature is f'' of the lowest point, checked
// against central differences of the reference's own stationary solver on CAM-like
// moves (where the search uses it); lines whose contact changes face within the
// difference step are skipped (f'' jumps there).
TEST(RayClearance, LowestPointCurvatureIsTheSecondDerivative) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(0.1, 0.9);
  int compared = 0, worstCase = -1;
  double worst = 0;
  for (int k = 0; k < 480; ++k) {
    const Move m = randomMove(rng, k, Family::CamLike);
    if (m.cutter.type == CutterType::Flat) continue;
    const PoseCurve curve = PoseCurve::linear({m.p0, m.a0}, {m.p1, m.a1});
    double x, y;
    randomLine(rng, m, x, y);
    const double t = u(rng), h = 1e-3;
    auto f = [&](double s) {
      return ref::stationaryLowest(m.refCutter, m.p0 + (m.p1 - m.p0) * s, ref::slerp(m.a0, m.a1, s),
                                   x, y);
    };
    const ref::RefHit f0 = f(t), fm = f(t - h), fp = f(t + h), fm2 = f(t - 2 * h),
                      fp2 = f(t + 2 * h);
    if (!(f0.hit && fm.hit && fp.hit && fm2.hit && fp2.hit)) continue;
    const double fd = (fp.z - 2 * f0.z + fm.z) / (h * h);
    const double fd2 = (fp2.z - 2 * f0.z + fm2.z) / (4 * h * h);
    if (std::fabs(fd - fd2) > 1e-3 * (1e-3 + std::fabs(fd))) continue;  // a face changes nearby
    const double kernel = lowestPointCurvature(m.cutter, curve, t, {x, y, f0.z});
    if (!std::isfinite(kernel)) continue;
    ++compared;
    const double err = std::fabs(kernel - fd) / (1e-4 + std::fabs(fd));
    if (err > worst) worst = err, worstCase = k;
    EXPECT_LT(err, 1e-2) << "move " << k << ": kernel " << kernel << ", differences " << fd;
  }
  std::printf("lowestPointCurvature: %d lines, worst relative difference %.2g (move %d)\n",
              compared, worst, worstCase);
  EXPECT_GE(compared, 100);
}

}  // namespace
}  // namespace scallop
