#include "sweep/raster.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/profile_chain.h"
#include "sweep/swept_segment.h"

namespace scallop {

namespace {

// A raster of more passes is refused up front: every move is held in memory.
constexpr double kMaxPasses = 1e6;

}  // namespace

Vec3 leadTiltAxis(const Vec3& feed, double leadDeg, double tiltDeg) {
  const Vec3 c = cross(Vec3{0, 0, 1}, feed);
  return normalize(feed * std::tan(leadDeg * kRadPerDeg) + c * std::tan(tiltDeg * kRadPerDeg) +
                   Vec3{0, 0, 1});
}

ToolPath makeRaster(const Cutter& cutter, const Box3& stock, const RasterSpec& spec) {
  const std::string f = "path.raster.";
  if (spec.direction != 'x' && spec.direction != 'y')
    throw InputError(f + "direction", "must be \"x\" or \"y\"");
  if (!std::isfinite(spec.stepOver) || spec.stepOver <= 0)
    throw InputError(f + "step_over", "must be > 0 mm, got " + std::to_string(spec.stepOver));
  if (!std::isfinite(spec.depth) || spec.depth < 0)
    throw InputError(f + "depth", "must be >= 0 mm, got " + std::to_string(spec.depth));
  requireAngle(spec.leadDeg, f + "lead_deg");
  requireAngle(spec.tiltDeg, f + "tilt_deg");
  if (!std::isfinite(spec.segmentLength) || spec.segmentLength < 0)
    throw InputError(f + "segment_length", "must be >= 0 mm");

  const bool alongX = spec.direction == 'x';
  const double crossMin = alongX ? stock.min.y : stock.min.x;
  const double crossMax = alongX ? stock.max.y : stock.max.x;
  const double feedMin = (alongX ? stock.min.x : stock.min.y) - cutter.radius - 1;
  const double feedMax = (alongX ? stock.max.x : stock.max.y) + cutter.radius + 1;
  const double passes = std::floor((crossMax - crossMin) / spec.stepOver + 1e-9) + 1;
  if (passes > kMaxPasses)
    throw InputError(f + "step_over", "gives " + std::to_string(passes) + " passes; too many");
  const double floorZ = stock.max.z - spec.depth;
  // Every move is kept in memory: refuse a path that could not be held, up front.
  const double movesPerPass =
      spec.segmentLength > 0 ? std::ceil((feedMax - feedMin) / spec.segmentLength) : 1;
  if (movesPerPass * passes > 5e7)
    throw InputError(f + "segment_length", "gives " + std::to_string(movesPerPass * passes) +
                                               " moves; at most 5e7 are supported");

  ToolPath path;
  for (int k = 0; k < int(passes); ++k) {
    const bool reversed = spec.zigzag && (k % 2 == 1);
    const Vec3 feed =
        alongX ? Vec3{reversed ? -1.0 : 1.0, 0, 0} : Vec3{0, reversed ? -1.0 : 1.0, 0};
    const Vec3 axis = leadTiltAxis(feed, spec.leadDeg, spec.tiltDeg);
    // depth is measured to the lowest point of the tilted cutter, not to the tip.
    const double tipZ = floorZ - cutterSupport(cutter, axis, Vec3{0, 0, -1}).z;
    const double cr = crossMin + k * spec.stepOver;
    const double a = reversed ? feedMax : feedMin, b = reversed ? feedMin : feedMax;
    auto at = [&](double s) { return alongX ? Vec3{s, cr, tipZ} : Vec3{cr, s, tipZ}; };

    if (!path.moves.empty()) {  // rapid from the previous pass's end, above the stock
      Move rapid;
      rapid.from = path.moves.back().to;
      rapid.to = {at(a), axis};
      rapid.rapid = true;
      path.moves.push_back(rapid);
    }
    const int pieces = spec.segmentLength > 0
                           ? std::max(1, int(std::ceil((feedMax - feedMin) / spec.segmentLength)))
                           : 1;
    for (int i = 0; i < pieces; ++i) {
      Move mv;
      mv.from = {at(a + (b - a) * double(i) / pieces), axis};
      mv.to = {at(a + (b - a) * double(i + 1) / pieces), axis};
      path.moves.push_back(mv);
    }
  }
  return path;
}

}  // namespace scallop
