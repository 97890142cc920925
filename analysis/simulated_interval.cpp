// The simulated truth of the path interval: see simulated_interval.h.
#include "analysis/simulated_interval.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "raycast/swept_scene.h"
#include "raycast/zmap.h"
#include "raycast/zmap_caster.h"
#include "sweep/profile_chain.h"
#include "sweep/raster.h"
#include "sweep/swept_move.h"

namespace scallop {

namespace {

// Below this gap (mm) between h and the height just inside a bracketed root, the
// root is a crossing of the profile; above it the profile jumps there: it is the
// vertical flank of the cutter's shadow, which never rises to h. (At a vertical
// tangent of a real crossing, e.g. the ellipse of an inclined flat end mill, the gap
// after bisection to 1e-12 mm is below 1e-6 mm.)
constexpr double kFlankGapMm = 1e-5;

// Golden-section search for the largest value of a unimodal f on [a, b]; returns the
// abscissa. Ties keep the left part, which is harmless: a tie between two interior
// probes of a unimodal function means the maximum lies between them or is flat.
double goldenMax(const std::function<double(double)>& f, double a, double b, double tol) {
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(c), fd = f(d);
  for (int iter = 0; iter < 200 && b - a > tol; ++iter) {
    if (fc >= fd) {
      b = d, d = c, fd = fc;
      c = b - g * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + g * (b - a), fd = f(d);
    }
  }
  return fc >= fd ? c : d;
}

// A one-cell-wide z-map along y at x = 0: cell centres y0, y0 + s, ..., count of them.
ZMap castColumn(const SweptScene& scene, double y0, double s, int64_t count, double ceiling) {
  GridSpec g;
  g.originX = -0.5 * s;
  g.originY = y0 - 0.5 * s;
  g.spacing = s;
  g.nx = 1;
  g.ny = count;
  ZMap map(g, ceiling);
  castZMap(scene, map);
  return map;
}

}  // namespace

SimulatedPass::SimulatedPass(const Cutter& cutter, double leadDeg, double tiltDeg,
                             const SimulatedIntervalOptions& options)
    : cutter_(cutter), leadDeg_(leadDeg), tiltDeg_(tiltDeg), options_(options) {
  requireAngle(leadDeg, "lead_deg");
  requireAngle(tiltDeg, "tilt_deg");
  const Vec3 feed{1, 0, 0};
  axis_ = leadTiltAxis(feed, leadDeg, tiltDeg);
  // Depth rule: the floor is the plane through the cutter's lowest point; put it at 0.
  tip_ = Vec3{0, 0, -cutterSupport(cutter, axis_, Vec3{0, 0, -1}).z};
  centreY_ = tip_.y + cutter.cornerRadius * axis_.y;
  ceiling_ = tip_.z + cutterSupport(cutter, axis_, Vec3{0, 0, 1}).z + 1.0;
  reachPlus_ = tip_.y + cutterSupport(cutter, axis_, Vec3{0, 1, 0}).y - centreY_;
  reachMinus_ = centreY_ - (tip_.y + cutterSupport(cutter, axis_, Vec3{0, -1, 0}).y);
  // The cutter meets the plane x = 0 for tip x in [-max x, -min x] of the cutter; a
  // pass longer than that on both sides leaves the full shadow at x = 0.
  const double xExtent =
      std::max(cutterSupport(cutter, axis_, feed).x, -cutterSupport(cutter, axis_, -feed).x);
  halfLength_ = xExtent + 1.0;
  std::vector<SweptMove> segments;
  segments.emplace_back(SweptSegment(cutter, tip_ - feed * halfLength_, tip_ + feed * halfLength_, axis_));
  SceneOptions sceneOptions;
  sceneOptions.stockTop = ceiling_;
  scene_ = std::make_unique<SweptScene>(std::move(segments), sceneOptions);

  // The floor contact: the lowest z-map sample, refined by golden section (convex).
  const double s = bracketSpacing();
  const ScallopProfile coarse = profile(-reachMinus_ - 2 * s, reachPlus_ + 2 * s, s);
  const size_t k =
      size_t(std::min_element(coarse.height.begin(), coarse.height.end()) - coarse.height.begin());
  const double a = coarse.position[k == 0 ? 0 : k - 1];
  const double b = coarse.position[std::min(k + 1, coarse.position.size() - 1)];
  floorY_ =
      goldenMax([this](double y) { return -heightAboveFloor(y); }, a, b, options_.toleranceMm);
}

SimulatedPass::~SimulatedPass() = default;

double SimulatedPass::bracketSpacing() const {
  return options_.bracketSpacingMm > 0 ? options_.bracketSpacingMm : cutter_.radius / 256;
}

double SimulatedPass::heightAboveFloor(double y) const {
  uint64_t evaluations = 0;
  return scene_->lowestHeight(0, centreY_ + y, ceiling_, evaluations);  // floor at z = 0
}

ScallopProfile SimulatedPass::profile(double fromMm, double toMm, double spacingMm) const {
  const int64_t count =
      std::max<int64_t>(1, int64_t(std::ceil((toMm - fromMm) / spacingMm - 1e-9)) + 1);
  const ZMap map = castColumn(*scene_, centreY_ + fromMm, spacingMm, count, ceiling_);
  ScallopProfile p;
  for (int64_t j = 0; j < count; ++j) {
    p.position.push_back(map.grid().cellCentreY(j) - centreY_);
    p.height.push_back(map.at(0, j));
  }
  return p;
}

bool SimulatedPass::sideRoot(double h, int sign, double* y, double* edgeHeight) const {
  // Bracket: the floor contact (height ~0 < h) and the first z-map sample outwards at
  // or above h. Beyond the shadow the samples hold the ceiling, so one always exists.
  const double s = bracketSpacing();
  const double reach = sign > 0 ? reachPlus_ : reachMinus_;
  const ScallopProfile samples =
      sign > 0 ? profile(floorY_, reach + 2 * s, s) : profile(-reach - 2 * s, floorY_, s);
  double a = floorY_, b = sign > 0 ? samples.position.back() : samples.position.front();
  const size_t n = samples.position.size();
  for (size_t m = 0; m < n; ++m) {
    const size_t k = sign > 0 ? m : n - 1 - m;
    if (sign * (samples.position[k] - floorY_) < 0) continue;  // the other side
    if (samples.height[k] >= h) {
      b = samples.position[k];
      break;
    }
    a = samples.position[k];
  }
  // Bisection on the exact height: a stays below h, b at or above it.
  double fa = heightAboveFloor(a);
  for (int iter = 0; iter < 200 && std::fabs(b - a) > options_.toleranceMm; ++iter) {
    const double mid = 0.5 * (a + b);
    if (mid == a || mid == b) break;
    const double fm = heightAboveFloor(mid);
    if (fm < h) {
      a = mid, fa = fm;
    } else {
      b = mid;
    }
  }
  *edgeHeight = fa;
  if (h - fa > kFlankGapMm) return false;
  *y = sign * 0.5 * (a + b);
  return true;
}

SideIntervals SimulatedPass::halfIntervals(double scallopHeightMm) const {
  SideIntervals out;
  const double h = scallopHeightMm;
  if (!std::isfinite(h) || h <= 0) {
    out.reason = "the scallop height h must be a number > 0 mm";
    return out;
  }
  double edgePlus = 0, edgeMinus = 0;
  const bool plus = sideRoot(h, +1, &out.plusMm, &edgePlus);
  const bool minus = sideRoot(h, -1, &out.minusMm, &edgeMinus);
  if (plus && minus) {
    out.reachable = true;
    return out;
  }
  const double edge = plus ? edgeMinus : minus ? edgePlus : std::min(edgePlus, edgeMinus);
  const double reach = plus ? reachMinus_ : reachPlus_;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "h = %g mm is beyond the cutter: a single pass's profile rises only %.6f mm "
                "above the floor before the cutter's flank (%.6f mm from the pass's centre "
                "line on the %s side)",
                h, edge, reach, plus ? "-c" : "+c");
  out.reason = buf;
  out.plusMm = out.minusMm = 0;
  return out;
}

SimulatedCusp SimulatedPass::cusp(double stepOverMm) const {
  SimulatedCusp out;
  if (!std::isfinite(stepOverMm) || stepOverMm <= 0) return out;
  const Vec3 feed{1, 0, 0}, cross{0, stepOverMm, 0};
  std::vector<SweptMove> segments;
  segments.emplace_back(SweptSegment(cutter_, tip_ - feed * halfLength_, tip_ + feed * halfLength_, axis_));
  segments.emplace_back(SweptSegment(cutter_, tip_ + cross - feed * halfLength_,
                        tip_ + cross + feed * halfLength_, axis_));
  SceneOptions sceneOptions;
  sceneOptions.stockTop = ceiling_;
  const SweptScene scene(std::move(segments), sceneOptions);
  auto height = [&](double y) {
    uint64_t evaluations = 0;
    return scene.lowestHeight(0, y, ceiling_, evaluations);
  };

  // From the floor contact of the first pass to that of the second: the union is
  // min(rising, falling) there, unimodal, so the highest sample's neighbours bracket
  // the cusp and golden section finds it exactly.
  const double y0 = centreY_ + floorY_;
  const int64_t n = std::max<int64_t>(64, int64_t(std::ceil(stepOverMm / bracketSpacing())));
  const double s = stepOverMm / double(n);
  const ZMap column = castColumn(scene, y0, s, n + 1, ceiling_);
  int64_t k = 0;
  for (int64_t j = 0; j <= n; ++j) {
    if (column.at(0, j) >= ceiling_) return out;  // a strip between the passes is uncut
    if (column.at(0, j) > column.at(0, k)) k = j;
  }
  const double a = column.grid().cellCentreY(std::max<int64_t>(0, k - 1));
  const double b = column.grid().cellCentreY(std::min(n, k + 1));
  const double y = goldenMax(height, a, b, options_.toleranceMm);
  out.covered = true;
  out.heightMm = std::max(height(y), column.at(0, k));
  out.positionMm = y - centreY_;
  return out;
}

}  // namespace scallop
