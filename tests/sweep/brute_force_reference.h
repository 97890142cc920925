// Brute-force reference for the swept-solid heights, used only by the tests.
//
// It is written from the definition of the cutter solid in CONVENTIONS.md ("Cutters")
// and shares no code with sweep/*.cpp: the only things it takes from the project are
// Vec3 (a plain vector) and the CutterType enum. It is deliberately slow and simple:
//
//   * Point membership: tool frame s = (p - tip)·a, rho = |(p - tip) - s a|; inside iff
//     0 <= s <= L and rho <= prof(s) with prof(s) = Rb + sqrt(r^2 - (r - s)^2) for
//     s < r and R above.
//   * On a vertical line, depth(z) = prof(s(z)) - rho(z) is concave on the z interval
//     where 0 <= s <= L (prof is concave in s, rho is convex in z, s is affine in z).
//     So golden-section search finds the deepest z (an interior point if any), and
//     bisection between the bottom of that interval and the deepest z finds the
//     lowest boundary crossing. No dense scan that could step over a thin chord.
//   * Along a move, depth is jointly concave in (t, z) and the lowest z is jointly
//     convex, so the same two tools give the hit interval in t and the minimum over
//     t; a dense grid over t is evaluated as well and the answer is the smallest
//     height actually evaluated (every evaluated height is a real lowest point of a
//     real cutter position, so the reference can only err upwards, by the
//     golden-section resolution, which is far below 1e-9 mm).
#pragma once

#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include "base/vec3.h"
#include "sweep/cutter.h"

namespace scallop {
namespace ref {

// Cutter parameters as the definition uses them: ball r = R, flat r = 0.
struct RefCutter {
  double R = 0;  // radius, mm (a general profile: its largest width)
  double r = 0;  // corner radius, mm
  double L = 0;  // flute length, mm
  double Rb() const { return R - r; }
  // A cutter of any convex profile (CONVENTIONS.md "Cutter shapes"): its width w(s) for
  // s in [0, L], written by the test from the definition of its chain
  // (tests/sweep/profile_cases.h); empty for ball, flat and bull. prof(s) is then w(s).
  std::function<double(double)> width = {};
};

// `cornerRadius` is used for bull only; `fluteLength` <= 0 means 4 R.
RefCutter makeRefCutter(CutterType type, double radius, double cornerRadius = 0,
                        double fluteLength = 0);

// prof(s): radius of the solid at height s along the axis; only for 0 <= s <= L.
// Concave in s for every cutter, which the searches below rely on.
double profile(const RefCutter& c, double s);

// Point-in-solid test straight from the definition, for the cutter with its tip at
// `tip` and unit axis `axis`. `tol` (mm) widens the solid: s in [-tol, L + tol] and
// rho <= prof(clamp(s)) + tol.
bool inside(const RefCutter& c, const Vec3& tip, const Vec3& axis, const Vec3& p, double tol = 0);

struct RefHit {
  bool hit = false;
  double z = 0;  // mm, valid when hit
};

// Golden-section search for the maximum of a concave (unimodal) f on [a, b]. Returns
// the best (argument, value) over every point evaluated, endpoints included, so the
// value is always one that f really takes.
template <class F>
std::pair<double, double> goldenMax(F&& f, double a, double b) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  std::pair<double, double> best{a, f(a)};
  auto consider = [&](double x, double fx) {
    if (fx > best.second) best = {x, fx};
  };
  consider(b, f(b));
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = f(x1), f2 = f(x2);
  consider(x1, f1);
  consider(x2, f2);
  // 200 steps shrink any interval by 1e-41: the loop always ends on the resolution
  // test, when the probes stop being distinct doubles.
  for (int i = 0; i < 200 && b - a > 1e-15 * (1 + std::fabs(a) + std::fabs(b)); ++i) {
    if (f1 >= f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - g * (b - a);
      f1 = f(x1);
      consider(x1, f1);
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + g * (b - a);
      f2 = f(x2);
      consider(x2, f2);
    }
  }
  return best;
}

// Bisection of a predicate that is true at `in` and false at `out` (an interval's end):
// returns the last point known to satisfy it, to the last representable double.
// Lowest point of the stationary cutter (tip at `tip`) on the vertical line (x, y).
RefHit stationaryLowest(const RefCutter& c, const Vec3& tip, const Vec3& axis, double x, double y);

// The deepest penetration of the vertical line (x, y) into the stationary cutter (mm,
// negative: the line misses it by that much in the sense of the profile).
double deepestDepth(const RefCutter& c, const Vec3& tip, const Vec3& axis, double x, double y);

// The unit vector at polar angle `polar` from +Z and azimuth `azimuth` (radians): the
// random axes of the turning-move tests.
inline Vec3 unitFromAngles(double polar, double azimuth) {
  return {std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
          std::cos(polar)};
}

// Slerp as CONVENTIONS.md writes it ("Tool pose"): sin((1 - t) phi) a0 + sin(t phi) a1
// over sin(phi), for unit a0, a1 (a0 where they coincide).
inline Vec3 slerp(const Vec3& a0, const Vec3& a1, double t) {
  const double phi = std::acos(std::fmax(-1.0, std::fmin(1.0, dot(a0, a1))));
  if (phi < 1e-12) return a0;
  return (a0 * std::sin((1 - t) * phi) + a1 * std::sin(t * phi)) / std::sin(phi);
}

// A pose curve as the reference sees it: tip straight from p0 to p1 (or any function of
// t), the axis any function of t (the tests write slerp and the machines' formulas from
// CONVENTIONS.md themselves).
struct RefCurve {
  Vec3 p0, p1;
  std::function<Vec3(double)> axis;
  // The tip on a curve (a machine with TCP off, its forward kinematics written by the
  // test); empty: straight from p0 to p1.
  std::function<Vec3(double)> tip = {};
};

// Lowest point on the vertical line (x, y) of the solid swept along a curve whose axis
// turns: f(t) = stationaryLowest at pose(t) on `samples` evenly spaced t, then
// golden-section refinement around the three lowest local minima of the grid (every
// value is a real height, so the reference errs only upwards). `maxDepth`, if given,
// receives the deepest penetration seen (a line that grazes the solid has it near 0:
// hit or miss is then a matter of resolution).
RefHit turningLowest(const RefCutter& c, const RefCurve& curve, double x, double y,
                     int samples = 401, double* maxDepth = nullptr);

// Lowest point on the vertical line (x, y) of the solid swept by the cutter whose tip
// moves straight from `start` to `end` with the fixed unit axis `axis`.
RefHit sweptLowest(const RefCutter& c, const Vec3& start, const Vec3& end, const Vec3& axis,
                   double x, double y);

struct RefMove {
  Vec3 start, end, axis;
};

// Lowest point of the union of the swept solids of several moves (min over moves).
RefHit unionLowest(const RefCutter& c, const std::vector<RefMove>& moves, double x, double y);

// Support value of the stationary cutter (tip at origin): max over the solid of
// dot(dir, q). `dir` need not be unit.
double supportValue(const RefCutter& c, const Vec3& axis, const Vec3& dir);

// Support value of the swept solid: the move adds max(dot(dir, start), dot(dir, end)).
double sweptSupportValue(const RefCutter& c, const Vec3& start, const Vec3& end, const Vec3& axis,
                         const Vec3& dir);

// Cusp (scallop) height between passes: along the horizontal segment from (x0, y0) to
// (x1, y1), the highest lowest-point of the union of `moves` minus the lowest one.
// Dense sampling followed by golden-section refinement at both extremes. Returns a
// negative value if some sample misses the union (the segment is not fully cut).
double cuspHeight(const RefCutter& c, const std::vector<RefMove>& moves, double x0, double y0,
                  double x1, double y1, int samples = 2001);

}  // namespace ref
}  // namespace scallop
