#include "tools/run/bench_cases.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "sweep/constants.h"
#include "sweep/input_error.h"
#include "sweep/raster.h"
#include "sweep/swept_segment.h"

namespace scallop {

namespace {

constexpr double kStockSide = 20;  // mm, the standard cases' stock

RasterSpec b1Raster() {
  RasterSpec spec;
  spec.direction = 'x';
  spec.stepOver = 0.8;
  spec.depth = 0.5;
  spec.leadDeg = 5;
  return spec;
}

}  // namespace

const std::vector<std::string>& benchCaseNames() {
  static const std::vector<std::string> names{"B1", "B2", "B3"};
  return names;
}

double freeformHeight(double x, double y) {
  return 0.5 * std::sin(2 * kPi * x / 10) * std::cos(2 * kPi * y / 14);
}

ToolPath makeFreeformPath(const Cutter& cutter, const Box3& stock, double passGap,
                          double moveLength, double leanDeg) {
  const double lean = leanDeg * kPi / 180;
  const Vec3 feed{1, 0, 0};
  // Unit normal of z = f(x, y): (-f_x, -f_y, 1) normalised.
  auto normal = [](double x, double y) {
    const double fx =
        0.5 * (2 * kPi / 10) * std::cos(2 * kPi * x / 10) * std::cos(2 * kPi * y / 14);
    const double fy =
        -0.5 * (2 * kPi / 14) * std::sin(2 * kPi * x / 10) * std::sin(2 * kPi * y / 14);
    return normalize(Vec3{-fx, -fy, 1});
  };
  auto leanedAxis = [&](double x, double y) {
    const Vec3 n = normal(x, y);
    const Vec3 along = normalize(feed - n * dot(feed, n));  // the feed, in the tangent plane
    return normalize(n * std::cos(lean) + along * std::sin(lean));
  };
  auto tipAt = [](double x, double y) { return Vec3{x, y, freeformHeight(x, y)}; };

  const double x0 = stock.min.x - cutter.radius - 1, x1 = stock.max.x + cutter.radius + 1;
  const int moves = std::max(1, int(std::ceil((x1 - x0) / moveLength - 1e-9)));
  const int passes = int(std::floor((stock.max.y - stock.min.y) / passGap + 1e-9)) + 1;
  ToolPath path;
  for (int k = 0; k < passes; ++k) {
    const double y = stock.min.y + k * passGap;
    for (int i = 0; i < moves; ++i) {
      const double xa = x0 + (x1 - x0) * double(i) / moves;
      const double xb = x0 + (x1 - x0) * double(i + 1) / moves;
      const Vec3 axis = leanedAxis(0.5 * (xa + xb), y);
      Move mv;
      mv.from = {tipAt(xa, y), axis};
      mv.to = {tipAt(xb, y), axis};
      if (i == 0 && !path.moves.empty()) {  // rapid from the previous pass, not simulated
        Move rapid;
        rapid.from = path.moves.back().to;
        rapid.to = mv.from;
        rapid.rapid = true;
        path.moves.push_back(rapid);
      }
      path.moves.push_back(mv);
    }
  }
  return path;
}

BenchCase makeBenchCase(const std::string& name, const BenchCaseOptions& options) {
  if (!(options.area >= 0) || !std::isfinite(options.area) ||
      (options.area > 0 && options.area < 0.1))
    throw InputError("--area", "must be a stock side >= 0.1 mm (0: the standard 20 mm)");
  const double side = options.area > 0 ? options.area : kStockSide;
  const double coarse = options.quick ? 10 : 1;

  BenchCase b;
  b.name = name;
  b.cutter = Cutter::make(CutterType::Bull, 3, 1);
  if (name == "B1" || name == "B2") {
    b.stock.extend({0, 0, -5});
    b.stock.extend({side, side, 0});
    RasterSpec spec = b1Raster();
    if (name == "B2") spec.segmentLength = 0.05;
    b.path = makeRaster(b.cutter, b.stock, spec);
    b.grid = gridCovering(0, 0, side, side, 0.001 * coarse);
    b.description = name == "B1"
                        ? "raster, bull R3 r1, lead 5 deg, step-over 0.8 mm, one move per pass"
                        : "B1 with every pass cut into 0.05 mm moves (CAM-like)";
  } else if (name == "B3") {
    // The surface spans z in [-0.5, 0.5]; a stock top at 0.6 mm is cut everywhere.
    b.stock.extend({0, 0, -2});
    b.stock.extend({side, side, 0.6});
    b.path = makeFreeformPath(b.cutter, b.stock, 0.5, 0.05, 5);
    b.grid = gridCovering(0, 0, side, side, 0.002 * coarse);
    b.description =
        "freeform 5-axis, tip on z = 0.5 sin(2 pi x/10) cos(2 pi y/14), axis = normal leaned 5 deg";
  } else {
    throw InputError("--case", "unknown case \"" + name + "\"; expected B1, B2 or B3");
  }
  return b;
}

GridSpec stampWindow(const BenchCase& bench, double side) {
  const double w = std::min(
      {side, bench.stock.max.x - bench.stock.min.x, bench.stock.max.y - bench.stock.min.y});
  const double cx = 0.5 * (bench.stock.min.x + bench.stock.max.x);
  const double cy = 0.5 * (bench.stock.min.y + bench.stock.max.y);
  return gridCovering(cx - 0.5 * w, cy - 0.5 * w, cx + 0.5 * w, cy + 0.5 * w, bench.grid.spacing);
}

uint64_t heightsHash(const ZMap& map) {
  uint64_t h = 1469598103934665603ull;
  for (double z : map.heights()) {
    uint64_t bits;
    std::memcpy(&bits, &z, sizeof bits);
    for (int k = 0; k < 8; ++k) {
      h ^= (bits >> (8 * k)) & 0xff;
      h *= 1099511628211ull;
    }
  }
  return h;
}

}  // namespace scallop
