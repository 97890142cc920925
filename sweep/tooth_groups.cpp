#include "sweep/tooth_groups.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace scallop {

namespace {

// The solid of revolution of a tooth's edge about the cutter's axis: the profile moved
// out by its radial offset (its flat bottom's radius Rb + dr >= 0). The axial offset is
// the group's drop, applied to the tip.
Cutter toothCutter(const Cutter& nominal, const ToothOffset& offset) {
  Cutter c = nominal;
  c.teeth = CutterTeeth{};
  if (offset.radial == 0) return c;
  c.radius = nominal.radius + offset.radial;
  if (c.general()) {
    c.profile = std::make_shared<const CutterProfile>(c.profile->widened(offset.radial));
    return c;
  }
  if (c.cornerRadius <= 0) return c;  // a flat end mill stays flat
  if (c.radius - c.cornerRadius <= 0) {
    c.radius = c.cornerRadius;
    c.type = CutterType::Ball;
  } else {
    c.type = CutterType::Bull;
  }
  return c;
}

}  // namespace

// A group's roots are its teeth's body angles in units of F. Its scan step is a quarter
// tooth period when the group is every tooth at equal pitch, else half the smallest gap
// between its roots (fewer, longer intervals: counted by callgrind on B5 with one tooth
// offset, a quarter of the gap cost 10 % more, a quarter tooth period 20 % more; the
// calm test keeps any step exact).
std::vector<ToothGroup> makeToothGroups(const Cutter& cutter, double equalPitchStep) {
  std::vector<ToothGroup> groups;
  const CutterTeeth& teeth = cutter.teeth;
  const int n = teeth.flutes;
  for (int k = 0; k < n; ++k) {
    const ToothOffset o = teeth.toothOffset(k);
    // A tooth moved out (dr > 0) has its edge's inner end dr from the axis: the group's
    // solid (the profile widened by dr) has a flat disc of radius dr inside it that no edge
    // crosses, so its edge is the span [0, U] of the nominal edge (a plunge leaves a
    // pillar of radius dr there). Moved in (dr < 0), the edge ends at the axis (the
    // narrowed solid's flat bottom reaches it; nothing passes to the other side).
    const bool spanned = !teeth.edgeSpans().empty() || o.radial > 0;
    const EdgeSpan span = !teeth.edgeSpans().empty() ? teeth.edgeSpans()[size_t(k)]
                          : spanned                  ? EdgeSpan{0, cutter.edgeLength()}
                                                     : EdgeSpan{};
    const ToothRake rake = teeth.toothRake(k);
    auto same = [&](const ToothGroup& g) {
      return g.radial == o.radial && g.drop == o.axial && g.span == span && g.rake == rake;
    };
    auto it = std::find_if(groups.begin(), groups.end(), same);
    if (it == groups.end()) {
      ToothGroup g;
      g.cutter = toothCutter(cutter, o);
      Cutter turning = g.cutter;
      turning.teeth.runout = teeth.runout;
      g.envelope = turning.spindleEnvelope();
      g.radial = o.radial;
      g.drop = o.axial;
      g.flutes = n;
      g.spanned = spanned;
      g.span = span;
      g.rake = rake;
      g.lag = cutter.rakeLag(k);
      if (spanned) {
        cutter.edgeSpanRadii(span, &g.spanRadiusMin, &g.spanRadiusMax);
        g.spanRadiusMin += o.radial;
        g.spanRadiusMax += o.radial;
      }
      groups.push_back(g);
      it = groups.end() - 1;
    }
    // In degrees, so that equal pitch given as angles (0, 120, 240) gives integers.
    it->roots.push_back(
        teeth.toothAnglesDeg().empty() ? double(k) : teeth.toothAnglesDeg()[size_t(k)] * n / 360);
  }
  for (ToothGroup& g : groups) {
    g.everyInteger = g.roots.size() == size_t(n);
    for (int k = 0; k < n && g.everyInteger; ++k) g.everyInteger = g.roots[size_t(k)] == k;
    double gap = n + g.roots.front() - g.roots.back();
    if (g.roots.size() == 1) gap = n;
    for (size_t i = 1; i < g.roots.size(); ++i) gap = std::min(gap, g.roots[i] - g.roots[i - 1]);
    g.step = equalPitchStep;
    if (!g.everyInteger) g.step *= 2 * gap;
    g.leaf = g.step / 64;
    g.quarterPeriod = equalPitchStep;
  }
  // The deepest-reaching teeth first: their crossings prune the others' search.
  std::stable_sort(groups.begin(), groups.end(), [](const ToothGroup& a, const ToothGroup& b) {
    return a.drop + a.radial > b.drop + b.radial;
  });
  return groups;
}

bool ToothGroup::isRoot(double f) const {
  if (everyInteger) return std::floor(f) == f;
  const double n = flutes;
  for (double r : roots) {
    const double q = (f - r) / n;
    if (std::floor(q) == q) return true;
  }
  return false;
}

bool ToothGroup::hasRootIn(double lo, double hi) const {
  if (everyInteger) return std::ceil(lo) <= hi;
  const double n = flutes;
  for (double r : roots)
    if (r + n * std::ceil((lo - r) / n) <= hi) return true;
  return false;
}

// The solid's profile is the nominal one moved out by the radial offset (a general
// chain gains a flat bottom that much wider: CutterProfile::widened), so its arc length
// runs `radial` ahead of the nominal edge's.
bool ToothGroup::onSpan(double h, double rho) const {
  if (!spanned) return true;
  // A ball, flat or bull profile widens from the axis up (its radius is non-decreasing in
  // u): a point whose radius lies strictly between the span's end radii has u strictly
  // between its ends (u <= from would give rho <= rho(from)), so it lies on the span
  // without its arc length (an atan2 on the corner; a tooth moved out is spanned [0, U],
  // and this is most of its points). The margin keeps the flank, whose radius is the
  // largest all the way up, out of it whatever the rounding of rho.
  const double margin = 1e-9 * (1 + spanRadiusMax);
  if (!cutter.general() && rho > spanRadiusMin + margin && rho < spanRadiusMax - margin)
    return true;
  const double u = cutter.edgeArcLength(h, rho) - radial;
  return u >= span.from && u <= span.to;
}

}  // namespace scallop
