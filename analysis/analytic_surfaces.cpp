#include "analysis/analytic_surfaces.h"

#include <algorithm>
#include <cmath>

#include "base/constants.h"
#include "base/input_error.h"

namespace scallop {

const char* toString(SurfaceShape shape) {
  switch (shape) {
    case SurfaceShape::Plane:
      return "plane";
    case SurfaceShape::Dome:
      return "dome";
    case SurfaceShape::Bowl:
      return "bowl";
    case SurfaceShape::Saddle:
      return "saddle";
    case SurfaceShape::Wave:
      return "wave";
    case SurfaceShape::Trough:
      return "trough";
  }
  return "?";
}

SurfaceShape parseSurfaceShape(const std::string& name, const std::string& field) {
  for (SurfaceShape s : {SurfaceShape::Plane, SurfaceShape::Dome, SurfaceShape::Bowl,
                         SurfaceShape::Saddle, SurfaceShape::Wave, SurfaceShape::Trough})
    if (name == toString(s)) return s;
  throw InputError(
      field, "unknown shape '" + name + "', expected dome, bowl, saddle, wave, plane or trough");
}

double SurfaceSpec::heightOrDefault() const {
  return height > 0 ? height : 0.2 * std::min(sizeX, sizeY);
}
double SurfaceSpec::troughRadiusOrDefault() const {
  return troughRadius > 0 ? troughRadius : sizeX / 8;
}

double surfaceHeight(const SurfaceSpec& spec, double x, double y) {
  const double h = spec.heightOrDefault();
  const double u = 2 * x / spec.sizeX - 1, v = 2 * y / spec.sizeY - 1;
  switch (spec.shape) {
    case SurfaceShape::Plane:
      return 0;
    case SurfaceShape::Dome:
      return h * (1 - 0.5 * (u * u + v * v));
    case SurfaceShape::Bowl:
      return h * 0.5 * (u * u + v * v);
    case SurfaceShape::Saddle:
      return h * 0.5 * (1 + u * u - v * v);
    case SurfaceShape::Wave:
      return h * 0.5 * (1 + std::sin(1.5 * kPi * u) * std::cos(kPi * v));
    case SurfaceShape::Trough: {
      const double r = spec.troughRadiusOrDefault(), d = std::min(h, r);
      const double w = std::sqrt(r * r - (r - d) * (r - d));
      const double dx = x - 0.5 * spec.sizeX;
      return std::fabs(dx) >= w ? 0.0 : (r - d) - std::sqrt(r * r - dx * dx);
    }
  }
  return 0;
}

TriangleMesh makeAnalyticSurface(const SurfaceSpec& spec) {
  // Lengths beyond 1 km (1e6 mm) are refused, as everywhere in scallop: at such scales
  // the mesh's float coordinates (STL) lose every micrometre.
  if (!(spec.sizeX > 0) || !(spec.sizeY > 0) || !(spec.sizeX <= kMaxMagnitudeMm) ||
      !(spec.sizeY <= kMaxMagnitudeMm))
    throw InputError("--size", "both sizes must be lengths in (0, 1e6] mm");
  if (spec.facets < 2 || spec.facets > 50000000)
    throw InputError("--facets", "must be between 2 and 50000000");
  if (!std::isfinite(spec.height) || !std::isfinite(spec.troughRadius))
    throw InputError("--height", "must be finite");
  const double cells = double(spec.facets) / 2;
  const int64_t nx = std::max<int64_t>(1, std::llround(std::sqrt(cells * spec.sizeX / spec.sizeY)));
  const int64_t ny = std::max<int64_t>(1, std::llround(cells / double(nx)));
  std::vector<std::array<Vec3, 3>> soup;
  soup.reserve(size_t(2 * nx * ny));
  auto node = [&](int64_t i, int64_t j) {
    const double x = spec.sizeX * double(i) / double(nx), y = spec.sizeY * double(j) / double(ny);
    return Vec3{x, y, surfaceHeight(spec, x, y)};
  };
  for (int64_t j = 0; j < ny; ++j)
    for (int64_t i = 0; i < nx; ++i) {
      const Vec3 a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1), d = node(i, j + 1);
      soup.push_back({a, b, c});
      soup.push_back({a, c, d});
    }
  return meshFromTriangles(soup);
}

}  // namespace scallop
