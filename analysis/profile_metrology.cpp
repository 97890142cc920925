// Profile extraction and roughness parameters (profile_metrology.h).
#include "analysis/profile_metrology.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"

namespace scallop {

namespace {

constexpr int kMaxSamplingLengths = 5;  // ISO 4288: evaluation length = 5 lr by default

std::string point(double x, double y) {
  std::ostringstream s;
  s.precision(10);
  s << "(" << x << ", " << y << ")";
  return s.str();
}

// Position of coordinate `v` in cell-centre index units, 0 at the first centre; a
// position within 1e-9 of the span's ends is clamped onto it.
double centreIndex(double v, double origin, int64_t offset, double spacing, int64_t n, bool& ok) {
  double f = (v - origin) / spacing - 0.5 - double(offset);
  if (f < 0 && f > -1e-9) f = 0;
  if (f > double(n - 1) && f < double(n - 1) + 1e-9) f = double(n - 1);
  ok = f >= 0 && f <= double(n - 1);
  return f;
}

}  // namespace

double Profile::xAt(int64_t k) const {
  const double length = std::hypot(x1 - x0, y1 - y0);
  return x0 + (x1 - x0) * (double(k) * stepMm / length);
}

double Profile::yAt(int64_t k) const {
  const double length = std::hypot(x1 - x0, y1 - y0);
  return y0 + (y1 - y0) * (double(k) * stepMm / length);
}

Profile extractProfile(const ZMap& map, double x0, double y0, double x1, double y1, double stepMm,
                       const char* where) {
  const GridSpec& g = map.grid();
  Profile p{x0, y0, x1, y1, stepMm > 0 ? stepMm : g.spacing, {}};
  const double length = std::hypot(x1 - x0, y1 - y0);
  if (!std::isfinite(length) || !(length > 0) || !std::isfinite(p.stepMm))
    throw InputError(where, "expected two different finite points x0 y0 x1 y1 (mm), got " +
                                point(x0, y0) + " and " + point(x1, y1));
  const int64_t n = int64_t(std::floor(length / p.stepMm + 1e-9)) + 1;
  p.height.resize(size_t(n));
  for (int64_t k = 0; k < n; ++k) {
    const double x = p.xAt(k), y = p.yAt(k);
    bool okX = false, okY = false;
    const double fi = centreIndex(x, g.originX, g.offsetI, g.spacing, g.nx, okX);
    const double fj = centreIndex(y, g.originY, g.offsetJ, g.spacing, g.ny, okY);
    if (!okX || !okY)
      throw InputError(where, "the line from " + point(x0, y0) + " to " + point(x1, y1) +
                                  " mm leaves the map at " + point(x, y) +
                                  "; profiles must stay between the cell centres " +
                                  point(g.cellCentreX(0), g.cellCentreY(0)) + " and " +
                                  point(g.cellCentreX(g.nx - 1), g.cellCentreY(g.ny - 1)));
    // Bilinear interpolation in the cell-centre lattice; on the last centre of an
    // axis the upper neighbour gets weight 0 (and may be the same cell).
    const int64_t i = std::min<int64_t>(int64_t(fi), std::max<int64_t>(0, g.nx - 2));
    const int64_t j = std::min<int64_t>(int64_t(fj), std::max<int64_t>(0, g.ny - 2));
    const int64_t i1 = std::min(i + 1, g.nx - 1), j1 = std::min(j + 1, g.ny - 1);
    const double u = fi - double(i), v = fj - double(j);
    p.height[size_t(k)] = (1 - u) * (1 - v) * map.at(i, j) + u * (1 - v) * map.at(i1, j) +
                          (1 - u) * v * map.at(i, j1) + u * v * map.at(i1, j1);
    if (std::isnan(p.height[size_t(k)]))
      throw InputError(where, "the line from " + point(x0, y0) + " to " + point(x1, y1) +
                                  " mm crosses cells without material (NaN: lines of a frame "
                                  "that miss the stock) at " +
                                  point(x, y) + "; profiles need a height at every sample");
  }
  return p;
}

RoughnessStats roughness(const Profile& profile, double cutoffMm, const char* where) {
  RoughnessStats s;
  s.cutoffMm = cutoffMm;
  const double dt = profile.stepMm;
  const int64_t n = int64_t(profile.height.size());
  if (!(cutoffMm > 0) || !std::isfinite(cutoffMm))
    throw InputError(where, "the cutoff wavelength must be a positive length in mm");
  // ISO 16610-21 eq. (1): s(x) = exp(-pi (x / (alpha lc))^2) / (alpha lc).
  const double alpha = std::sqrt(std::log(2.0) / kPi);
  const int64_t half = int64_t(std::floor(cutoffMm / dt + 1e-9));
  const int64_t perLength = std::max<int64_t>(1, std::llround(cutoffMm / dt));
  const int64_t valid = n - 2 * half;
  const int64_t lengths = valid > 0 ? std::min<int64_t>(kMaxSamplingLengths, valid / perLength) : 0;
  if (lengths < 1) {
    std::ostringstream m;
    m.precision(10);
    m << "the profile is " << double(n - 1) * dt << " mm long; a cutoff of " << cutoffMm
      << " mm needs at least " << 3 * cutoffMm
      << " mm (run-in, one sampling length, run-out): lengthen the line or lower --cutoff";
    throw InputError(where, m.str());
  }
  std::vector<double> w(size_t(2 * half + 1));
  double sum = 0;
  for (int64_t k = -half; k <= half; ++k) {
    const double x = double(k) * dt / (alpha * cutoffMm);
    w[size_t(k + half)] = std::exp(-kPi * x * x);
    sum += w[size_t(k + half)];
  }
  for (double& v : w) v /= sum;

  s.samplingLengths = int(lengths);
  s.sampleCount = lengths * perLength;
  s.firstSample = half + (valid - s.sampleCount) / 2;
  s.evaluationStartMm = double(s.firstSample) * dt;
  s.evaluationLengthMm = double(s.sampleCount) * dt;
  s.roughness.assign(size_t(n), NAN);
  for (int64_t k = half; k < n - half; ++k) {
    double mean = 0;
    for (int64_t m = -half; m <= half; ++m)
      mean += w[size_t(m + half)] * profile.height[size_t(k + m)];
    s.roughness[size_t(k)] = profile.height[size_t(k)] - mean;
  }

  double sumAbs = 0, sumSq = 0, lo = HUGE_VAL, hi = -HUGE_VAL, rzSum = 0;
  for (int64_t l = 0; l < lengths; ++l) {
    double lLo = HUGE_VAL, lHi = -HUGE_VAL;
    for (int64_t k = 0; k < perLength; ++k) {
      const double r = s.roughness[size_t(s.firstSample + l * perLength + k)];
      sumAbs += std::abs(r);
      sumSq += r * r;
      lLo = std::min(lLo, r);
      lHi = std::max(lHi, r);
    }
    rzSum += lHi - lLo;
    lo = std::min(lo, lLo);
    hi = std::max(hi, lHi);
  }
  s.ra = sumAbs / double(s.sampleCount);
  s.rq = std::sqrt(sumSq / double(s.sampleCount));
  s.rt = hi - lo;
  s.rz = rzSum / double(lengths);
  return s;
}

}  // namespace scallop
