// The lower envelope of the teeth's arcs: see tooth_mark_envelope.h.
#include "analysis/tooth_mark_envelope.h"

#include <algorithm>
#include <cmath>

namespace scallop {

namespace {

// One arc: its bottom at x = c, z = -lower.
struct Arc {
  double c, lower;
  int tooth;
};

// The circle of radius rho through its bottom (c, -lower): z(x) on its lower half.
double circleAt(const Arc& a, double rho, double x) {
  const double u = x - a.c;
  return -a.lower + rho - std::sqrt(rho * rho - u * u);
}

// Where the lower halves of two circles of radius rho meet (a.c < b.c, closer than 2
// rho): with centres A, B, D = B - A, the two meeting points are the midpoint
// -+ h (-D_z, D_x) / |D|, h = sqrt(rho^2 - |D|^2 / 4); the lower one is the one on the
// lower halves.
double circleMeet(const Arc& a, const Arc& b, double rho) {
  const double dx = b.c - a.c, dz = a.lower - b.lower;  // B - A (centres rho above bottoms)
  const double d = std::hypot(dx, dz);
  const double h = std::sqrt(std::max(0.0, rho * rho - 0.25 * d * d));
  // The lower point: midpoint - h (-dz, dx) / d, since dx > 0.
  return a.c + 0.5 * dx + h * dz / d;
}

// Parabolas z = (x - c)^2 / (2 rho) - lower: equal curvature, so they meet once, where
// (x - a.c)^2 - (x - b.c)^2 = 2 rho (a.lower - b.lower).
double parabolaAt(const Arc& a, double rho, double x) {
  return (x - a.c) * (x - a.c) / (2 * rho) - a.lower;
}
double parabolaMeet(const Arc& a, const Arc& b, double rho) {
  return (2 * rho * (a.lower - b.lower) + b.c * b.c - a.c * a.c) / (2 * (b.c - a.c));
}

// The envelope's peak-to-valley for one kind of curve, and which teeth reach it with
// their valleys' depths.
template <class At, class Meet>
double peakToValley(const std::vector<Arc>& arcs, size_t teeth, At at, Meet meet,
                    MarkEnvelope* cutting) {
  // Arcs of the middle period (indices [teeth, 2 teeth)) against all three periods.
  double top = -HUGE_VAL, bottom = HUGE_VAL;
  for (size_t k = teeth; k < 2 * teeth; ++k) {
    const Arc& a = arcs[k];
    double left = -HUGE_VAL, right = HUGE_VAL;
    bool hidden = false;
    for (size_t j = 0; j < arcs.size(); ++j) {
      if (j == k) continue;
      const Arc& b = arcs[j];
      if (b.c == a.c) {  // the same place: the deeper one (then the lower index) wins
        if (b.lower > a.lower || (b.lower == a.lower && b.tooth < a.tooth)) hidden = true;
      } else if (b.c < a.c) {
        left = std::max(left, meet(b, a));
      } else {
        right = std::min(right, meet(a, b));
      }
    }
    if (hidden || !(left < right)) continue;
    // Its part of the envelope: convex, lowest at its bottom if that lies in [left,
    // right], else at the nearer end.
    const double l = at(a, left), r = at(a, right), low = at(a, std::clamp(a.c, left, right));
    if (cutting) {
      cutting->cuttingTeeth.push_back(a.tooth);
      cutting->valleyDepthsMm.push_back(std::min(l, r) - low);
    }
    top = std::max({top, l, r});
    bottom = std::min(bottom, low);
  }
  return top - bottom;
}

}  // namespace

MarkEnvelope markEnvelope(const std::vector<ToothMark>& marks, double period, double rho) {
  MarkEnvelope e;
  const size_t n = marks.size();
  if (n == 0 || !(period > 0) || !(rho > 0)) return e;
  // Three periods, so each arc of the middle one sees its neighbours on both sides.
  std::vector<Arc> arcs;
  for (int copy = -1; copy <= 1; ++copy)
    for (size_t k = 0; k < n; ++k) {
      const double c = std::fmod(marks[k].positionMm, period);
      arcs.push_back({(c < 0 ? c + period : c) + copy * period, marks[k].lowerMm, int(k)});
    }
  std::vector<Arc> sorted = arcs;
  std::sort(sorted.begin(), sorted.end(), [](const Arc& a, const Arc& b) { return a.c < b.c; });
  for (size_t k = 1; k < sorted.size(); ++k)
    if (!(sorted[k].c - sorted[k - 1].c < 2 * rho)) return e;
  e.valid = true;
  e.peakToValleyMm = peakToValley(
      arcs, n, [rho](const Arc& a, double x) { return circleAt(a, rho, x); },
      [rho](const Arc& a, const Arc& b) { return circleMeet(a, b, rho); }, &e);
  e.peakToValleyParabolaMm = peakToValley(
      arcs, n, [rho](const Arc& a, double x) { return parabolaAt(a, rho, x); },
      [rho](const Arc& a, const Arc& b) { return parabolaMeet(a, b, rho); }, nullptr);
  return e;
}

}  // namespace scallop
