#include "analysis/feed_marks.h"

#include <algorithm>
#include <cmath>

namespace scallop {

namespace {

// The valley at sample v refined by the parabola through v - 1, v, v + 1 (its vertex,
// kept within half a sample of v), in samples.
double refinedValley(const std::vector<double>& z, size_t v) {
  if (v == 0 || v + 1 >= z.size()) return double(v);
  const double a = z[v - 1], b = z[v], c = z[v + 1];
  const double curvature = a - 2 * b + c;
  if (!(curvature > 0)) return double(v);
  return double(v) + std::clamp(0.5 * (a - c) / curvature, -0.5, 0.5);
}

}  // namespace

FeedMarks measureFeedMarks(const Profile& profile, double hysteresis) {
  const std::vector<double>& z = profile.height;
  FeedMarks m;
  m.samples = int64_t(z.size());
  if (z.empty()) return m;
  const auto [lo, hi] = std::minmax_element(z.begin(), z.end());
  m.peakToValleyMm = *hi - *lo;
  if (z.size() < 3 || !(profile.stepMm > 0) || !(m.peakToValleyMm > 0)) return m;
  const double threshold = hysteresis * m.peakToValleyMm;

  // Turning points by hysteresis: `dir` +1 while rising (tracking a maximum), -1 while
  // falling (tracking a minimum), 0 until the first move of `threshold` either way.
  std::vector<size_t> valleys;
  int dir = 0;
  size_t top = 0, bottom = 0;
  for (size_t k = 1; k < z.size(); ++k) {
    if (dir >= 0 && z[k] > z[top]) top = k;
    if (dir <= 0 && z[k] < z[bottom]) bottom = k;
    if (dir >= 0 && z[top] - z[k] >= threshold) {
      dir = -1;  // the maximum at `top` is a peak; now falling towards a valley
      bottom = k;
    } else if (dir <= 0 && z[k] - z[bottom] >= threshold) {
      if (dir < 0) valleys.push_back(bottom);  // fallen to it from a peak, risen after it
      dir = 1;
      top = k;
    }
  }
  for (size_t v : valleys) m.valleysMm.push_back(refinedValley(z, v) * profile.stepMm);
  if (m.valleysMm.size() >= 2)
    m.meanSpacingMm = (m.valleysMm.back() - m.valleysMm.front()) / double(m.valleysMm.size() - 1);
  return m;
}

}  // namespace scallop
