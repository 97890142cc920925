#include "tools/render/relief_shading.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "base/constants.h"
#include "base/input_error.h"

namespace scallop {

namespace {

// x > 0 rounded to two significant digits (3.66 -> 3.7, 12.4 -> 12).
double twoDigits(double x) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1);
  return std::round(x / unit) * unit;
}

}  // namespace

HeightRaster reduceMap(const ZMap& map, int maxPixels) {
  const int64_t longSide = std::max(map.nx(), map.ny());
  const int64_t k = std::max<int64_t>(1, (longSide + maxPixels - 1) / maxPixels);
  HeightRaster p;
  p.w = int((map.nx() + k - 1) / k);
  p.h = int((map.ny() + k - 1) / k);
  p.cellMm = map.grid().spacing * double(k);
  p.z.assign(size_t(p.w) * size_t(p.h), HUGE_VAL);
  for (int64_t j = 0; j < map.ny(); ++j) {
    const size_t rowBase = size_t(p.h - 1 - j / k) * size_t(p.w);
    for (int64_t i = 0; i < map.nx(); ++i) {
      double& z = p.z[rowBase + size_t(i / k)];
      z = std::min(z, map.at(i, j));  // a cell without material (NaN) leaves z as it is
    }
  }
  // A block without material (still HUGE_VAL, or a pooled copy's HUGE_VAL) holds none.
  for (double& z : p.z)
    if (!std::isfinite(z)) z = NAN;
  return p;
}

Slopes slopes(const HeightRaster& p) {
  const size_t n = size_t(p.w) * size_t(p.h);
  Slopes s;
  s.dzdx.resize(n);
  s.dzdy.resize(n);
  for (int r = 0; r < p.h; ++r)
    for (int a = 0; a < p.w; ++a) {
      // A neighbour without material (NaN) is left out like one beyond the edge.
      int a0 = std::max(0, a - 1), a1 = std::min(p.w - 1, a + 1);
      int r0 = std::max(0, r - 1), r1 = std::min(p.h - 1, r + 1);  // r0 is north
      if (std::isnan(p.at(a0, r))) a0 = a;
      if (std::isnan(p.at(a1, r))) a1 = a;
      if (std::isnan(p.at(a, r0))) r0 = r;
      if (std::isnan(p.at(a, r1))) r1 = r;
      const size_t idx = size_t(r) * size_t(p.w) + size_t(a);
      if (std::isnan(p.at(a, r))) {
        s.dzdx[idx] = s.dzdy[idx] = 0;  // drawn as no material, not lit
        continue;
      }
      s.dzdx[idx] = a1 > a0 ? (p.at(a1, r) - p.at(a0, r)) / ((a1 - a0) * p.cellMm) : 0.0;
      s.dzdy[idx] = r1 > r0 ? (p.at(a, r0) - p.at(a, r1)) / ((r1 - r0) * p.cellMm) : 0.0;
    }
  return s;
}

double slopeQuantile(const Slopes& s, double q, double floor) {
  std::vector<double> steep;
  for (size_t i = 0; i < s.dzdx.size(); ++i) {
    const double g = std::hypot(s.dzdx[i], s.dzdy[i]);
    if (g > floor) steep.push_back(g);
  }
  if (steep.empty()) return 0;
  auto at = steep.begin() + long(double(steep.size()) * q);
  std::nth_element(steep.begin(), at, steep.end());
  return *at;
}

double automaticExaggeration(const Slopes& s) {
  const double typical = slopeQuantile(s, 0.75, 1e-9);  // below 1 nm per mm is round-off
  return typical > 0 ? twoDigits(std::tan(35.0 * kRadPerDeg) / typical) : 1.0;
}

Slopes textureSlopes(const HeightRaster& p, int radius) {
  // Box mean as running sums of the heights and of the cells with material (rows, then
  // columns), each window clamped at the edge; cells without material (NaN) count in
  // neither.
  const size_t w = size_t(p.w), h = size_t(p.h);
  std::vector<double> height(p.z.size()), count(p.z.size());
  for (size_t i = 0; i < p.z.size(); ++i) {
    const bool material = !std::isnan(p.z[i]);
    height[i] = material ? p.z[i] : 0.0;
    count[i] = material ? 1.0 : 0.0;
  }
  auto boxLine = [radius](std::vector<double>& v, size_t first, size_t n, size_t stride) {
    const long r = radius, last = long(n) - 1;
    auto in = [&](long k) { return v[first + size_t(std::clamp(k, 0L, last)) * stride]; };
    std::vector<double> out(n);
    double sum = 0;
    for (long k = -r; k <= r; ++k) sum += in(k);
    for (long i = 0; i <= last; ++i) {
      out[size_t(i)] = sum;
      sum += in(i + r + 1) - in(i - r);
    }
    for (size_t i = 0; i < n; ++i) v[first + i * stride] = out[i];
  };
  for (std::vector<double>* v : {&height, &count}) {
    for (size_t r = 0; r < h; ++r) boxLine(*v, r * w, w, 1);
    for (size_t a = 0; a < w; ++a) boxLine(*v, a, h, w);
  }
  HeightRaster local = p;
  for (size_t i = 0; i < local.z.size(); ++i) local.z[i] = p.z[i] - height[i] / count[i];
  return slopes(local);
}

double automaticTextureBoost(const Slopes& all, const Slopes& texture, double exaggeration) {
  const double form = slopeQuantile(all, 0.75, 1e-9);
  const double typical = form > 0 ? slopeQuantile(texture, 0.75, 0.01 * form) : 0.0;
  if (!(typical > 0)) return 1;
  const double factor = twoDigits(std::tan(10.0 * kRadPerDeg) / typical);
  const double boost = std::min(factor / exaggeration, 10.0);
  return boost >= 2 ? boost : 1.0;  // less would hardly show, and take a legend line
}

Slopes boosted(const Slopes& all, const Slopes& texture, double boost) {
  Slopes out = all;
  for (size_t i = 0; i < out.dzdx.size(); ++i) {
    out.dzdx[i] += (boost - 1) * texture.dzdx[i];
    out.dzdy[i] += (boost - 1) * texture.dzdy[i];
  }
  return out;
}

std::vector<double> lambert(const Slopes& s, double exaggeration, const Light& light) {
  const double el = light.elevationDeg * kRadPerDeg, az = light.azimuthDeg * kRadPerDeg;
  const double lx = std::cos(el) * std::sin(az), ly = std::cos(el) * std::cos(az);
  const double lz = std::sin(el);
  std::vector<double> out(s.dzdx.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const double nx = -exaggeration * s.dzdx[i], ny = -exaggeration * s.dzdy[i];
    out[i] = std::max(0.0, (nx * lx + ny * ly + lz) / std::sqrt(nx * nx + ny * ny + 1));
  }
  return out;
}

std::vector<std::string> reliefLegend(double exaggeration, const Light& light, double boost,
                                      double textureMm) {
  std::vector<std::string> lines = {
      fmt::format("relief shading: heights \u00d7 {:.3g}, light from {:g}\u00b0 at {:g}\u00b0",
                  exaggeration, light.azimuthDeg, light.elevationDeg)};
  if (boost > 1) {
    const std::string size = textureMm >= 1 ? fmt::format("{:.3g} mm", textureMm)
                                            : fmt::format("{:.3g} \u00b5m", textureMm * 1000);
    lines.push_back(
        fmt::format("texture finer than {}: heights \u00d7 {:.3g}", size, exaggeration * boost));
  }
  return lines;
}

ReliefGrid reliefGridOf(const ZMap& map, const std::string& path, int maxPixels, int minPixels,
                        double exaggeration) {
  if (map.nx() <= 0 || map.ny() <= 0) throw InputError(path, "cannot draw an empty height map");
  if (!(map.grid().spacing > 0) || !std::isfinite(map.grid().spacing))
    throw InputError(path, fmt::format("grid spacing {} mm is not positive", map.grid().spacing));
  ReliefGrid out;
  maxPixels = std::max(16, maxPixels);
  out.grid = reduceMap(map, maxPixels);
  const int gridLong = std::max(out.grid.w, out.grid.h);
  out.up = std::max(1, std::min((minPixels + gridLong - 1) / gridLong, maxPixels / gridLong));
  out.slope = slopes(out.grid);
  out.exaggeration = std::isnan(exaggeration) ? automaticExaggeration(out.slope) : exaggeration;
  return out;
}

}  // namespace scallop
