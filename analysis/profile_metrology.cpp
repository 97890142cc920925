// Profile extraction and roughness parameters (profile_metrology.h).
#include "analysis/profile_metrology.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"
#include "base/number_text.h"

namespace scallop {

namespace {

constexpr int kMaxSamplingLengths = 5;  // ISO 4288: evaluation length = 5 lr by default

std::string point(double x, double y) {
  return "(" + formatNumber(x) + ", " + formatNumber(y) + ")";
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

std::string RoughnessFilter::name() const {
  std::string m = cutoffMm > 0 ? "ISO 16610-21 Gaussian, lc " + formatNumber(cutoffMm) + " mm"
                               : "unfiltered (primary profile less its least-squares line)";
  m += lambdaSMm > 0 ? ", ls " + formatNumber(lambdaSMm) + " mm (Gaussian)" : ", no ls";
  return m;
}

namespace {

// The ISO 16610-21 Gaussian weights of cutoff `cutoffMm` at samples `dt` apart, truncated
// at |x| <= cutoff and normalised to sum 1; `half` gets the kernel's half-width in samples.
// eq. (1): s(x) = exp(-pi (x / (alpha lc))^2) / (alpha lc), alpha = sqrt(ln 2 / pi).
std::vector<double> gaussianWeights(double cutoffMm, double dt, int64_t& half) {
  const double alpha = std::sqrt(std::log(2.0) / kPi);
  half = int64_t(std::floor(cutoffMm / dt + 1e-9));
  std::vector<double> w(size_t(2 * half + 1));
  double sum = 0;
  for (int64_t k = -half; k <= half; ++k) {
    const double x = double(k) * dt / (alpha * cutoffMm);
    w[size_t(k + half)] = std::exp(-kPi * x * x);
    sum += w[size_t(k + half)];
  }
  for (double& v : w) v /= sum;
  return w;
}

// The weighted mean of z round sample k (the kernel fits there).
double filtered(const std::vector<double>& z, const std::vector<double>& w, int64_t half,
                int64_t k) {
  double mean = 0;
  for (int64_t m = -half; m <= half; ++m) mean += w[size_t(m + half)] * z[size_t(k + m)];
  return mean;
}

// z less its least-squares line over samples [first, first + count).
void removeLine(std::vector<double>& z, int64_t first, int64_t count) {
  double sx = 0, sz = 0, sxx = 0, sxz = 0;
  for (int64_t k = 0; k < count; ++k) {
    const double x = double(k), v = z[size_t(first + k)];
    sx += x, sz += v, sxx += x * x, sxz += x * v;
  }
  const double n = double(count), det = n * sxx - sx * sx;
  const double slope = det > 0 ? (n * sxz - sx * sz) / det : 0;
  const double offset = (sz - slope * sx) / n;
  for (int64_t k = 0; k < count; ++k) z[size_t(first + k)] -= offset + slope * double(k);
}

// Rsm over r[first, first + count), samples dt apart (the convention in the header).
double meanElementWidth(const std::vector<double>& r, int64_t first, int64_t count, double dt,
                        double rz, double samplingLengthMm) {
  const double level = 0.1 * rz, minWidth = 0.01 * samplingLengthMm;
  // state: 0 nothing yet, -1 a valley seen (r <= -level) since the last peak, +1 a peak.
  int state = 0;
  double crossing = NAN;  // the last upward crossing of the mean line after a valley
  std::vector<double> bounds;
  for (int64_t k = first; k < first + count; ++k) {
    const double v = r[size_t(k)];
    if (k > first) {
      const double u = r[size_t(k - 1)];
      if (state == -1 && u < 0 && v >= 0) crossing = (double(k - 1) + u / (u - v)) * dt;
    }
    if (v <= -level) {
      state = -1;
    } else if (v >= level && state == -1 && std::isfinite(crossing)) {
      if (bounds.empty() || crossing - bounds.back() >= minWidth) bounds.push_back(crossing);
      state = 1, crossing = NAN;
    } else if (v >= level && state == 0) {
      state = 1;
    }
  }
  if (bounds.size() < 2) return NAN;
  return (bounds.back() - bounds.front()) / double(bounds.size() - 1);
}

}  // namespace

RoughnessStats roughness(const Profile& profile, double cutoffMm, const char* where) {
  RoughnessFilter f;
  f.cutoffMm = cutoffMm;
  if (!(cutoffMm > 0) || !std::isfinite(cutoffMm))
    throw InputError(where, "the cutoff wavelength must be a positive length in mm");
  return roughness(profile, f, where);
}

RoughnessStats roughness(const Profile& profile, const RoughnessFilter& filter, const char* where) {
  RoughnessStats s;
  s.filter = filter;
  s.cutoffMm = filter.cutoffMm;
  const double dt = profile.stepMm, lc = filter.cutoffMm, ls = filter.lambdaSMm;
  const int64_t n = int64_t(profile.height.size());
  if (!(lc >= 0) || !std::isfinite(lc))
    throw InputError(where,
                     "the cutoff wavelength lc must be a positive length in mm, or 0 for "
                     "the unfiltered profile");
  if (!(ls >= 0) || !std::isfinite(ls) || (ls > 0 && ls < 2 * dt) || (lc > 0 && ls >= lc / 2)) {
    throw InputError(where, "the short-wave cutoff ls (" + formatNumber(ls) +
                                " mm) must be 0 (none) or at least two sample steps (" +
                                formatNumber(2 * dt) + " mm) and below lc / 2 (" +
                                formatNumber(lc / 2) + " mm)");
  }

  // The ls-smoothed profile where its kernel fits, z[k] for k in [lsHalf, n - lsHalf).
  int64_t lsHalf = 0;
  std::vector<double> z = profile.height;
  if (ls > 0) {
    const std::vector<double> w = gaussianWeights(ls, dt, lsHalf);
    for (int64_t k = lsHalf; k < n - lsHalf; ++k)
      z[size_t(k)] = filtered(profile.height, w, lsHalf, k);
  }
  const int64_t begin = lsHalf, end = n - lsHalf;  // valid samples of z

  int64_t half = 0, perLength = 0, lengths = 0, valid = 0;
  if (lc > 0) {
    perLength = std::max<int64_t>(1, std::llround(lc / dt));
    half = int64_t(std::floor(lc / dt + 1e-9));
    valid = (end - begin) - 2 * half;
    lengths = valid > 0 ? std::min<int64_t>(kMaxSamplingLengths, valid / perLength) : 0;
  } else {
    valid = end - begin;
    perLength = valid;
    lengths = valid >= 3 ? 1 : 0;
  }
  if (lengths < 1) {
    std::string m = "the profile is " + formatNumber(double(n - 1) * dt) + " mm long; ";
    if (lc > 0)
      m += "a cutoff of " + formatNumber(lc) + " mm needs at least " +
           formatNumber(3 * lc + 2 * ls) + " mm (run-in, one sampling length, run-out" +
           (ls > 0 ? ", and ls at each end" : "") +
           "): lengthen the line, lower --cutoff (ISO 4288: 0.08, 0.25, 0.8, 2.5, 8 mm) or "
           "evaluate it unfiltered";
    else
      m += "the unfiltered profile needs at least 3 samples after ls's run-in and run-out";
    throw InputError(where, m);
  }
  s.samplingLengths = int(lengths);
  s.sampleCount = lengths * perLength;
  s.firstSample = begin + half + (valid - s.sampleCount) / 2;
  s.evaluationStartMm = double(s.firstSample) * dt;
  s.evaluationLengthMm = double(s.sampleCount - (lc > 0 ? 0 : 1)) * dt;
  s.samplingLengthMm = lc > 0 ? lc : s.evaluationLengthMm;
  s.roughness.assign(size_t(n), NAN);
  if (lc > 0) {
    const std::vector<double> w = gaussianWeights(lc, dt, half);
    for (int64_t k = begin + half; k < end - half; ++k)
      s.roughness[size_t(k)] = z[size_t(k)] - filtered(z, w, half, k);
  } else {
    for (int64_t k = begin; k < end; ++k) s.roughness[size_t(k)] = z[size_t(k)];
    removeLine(s.roughness, begin, end - begin);
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
  s.rsm = meanElementWidth(s.roughness, s.firstSample, s.sampleCount, dt, s.rz, s.samplingLengthMm);
  return s;
}

}  // namespace scallop
