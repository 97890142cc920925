// The certified search over t for the lowest point of a turning move's swept solid on a
// vertical line: what decides where swept_move.cpp's fast paths (the cutoff's ray
// clearance, the rim contact, its steps 4 and 6) do not, with the bounds that prove it.
//
// Notation as in swept_move.cpp: pose(t) = (tip(t), axis(t)), t in [0, 1], K(t) the
// cutter at pose(t), f(t) its lowest point on the vertical line l through q = (x, y),
// F = min over t of f(t), each f(t) exact (cutterLowestPoint, swept_segment.cpp):
//
//   1. Upper bound. Every f(t) evaluated is the height of a real point of S, so the
//      smallest one evaluated, U, satisfies U >= F.
//   2. Lower bounds of f over an interval I = [ta, tb], each proven (interval_bounds.cpp):
//      2a a world-fixed plane, 2b a plane fixed to the cutter, 2c a grown cutter, 2d the
//      Taylor form of 2b at a sample, 2e the flute top's plane with the flank's (a miss,
//      tried last, where the line passes beside the flank and over the top's rim).
//   3. Search. First the minimum of f: an interval whose end slopes f' = (N.v) / N.z
//      (v: velocity of the contact point) change sign is split at the secant root until
//      the best sample is flat (|f'| <= 1e-8 mm per unit t). Then best first: the
//      interval with the lowest bound is split (from its lower end, at the width its
//      bound's second-order loss can prove, w sqrt(allowed / loss)) until every
//      interval's bound is at least U - 1e-9 mm, so that F lies in [U - 1e-9, U] and U
//      is returned, or at least the caller's cutoff (a miss). Bounds near the minimum
//      meet f quadratically and f rises quadratically away from it, so intervals
//      growing geometrically from the minimum are proven: 3 to 15 samples typically.
//   5. Before step 3, the minimum of f is located without any bound (below) and the
//      whole move proven at once by ray clearance (swept_move.cpp step 4b) or, where
//      tangent lines cannot see the curvature (a flat bottom face), the Taylor form 2d
//      from the best sample over [0, 1].
#include "sweep/certified_search.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <new>

#include "sweep/interval_bounds.h"
#include "sweep/ray_clearance.h"

namespace scallop {

namespace {

constexpr int kMaxSamples = 1024;    // a guard: typical searches take 2 to 40
constexpr double kFlatSlope = 1e-8;  // mm per unit t: a sample at a minimum of f
// mm per unit t: a sample near enough to a minimum of f for step 4b to be worth trying
// (within s^2 / (2 f'') = 2e-10 mm of F for the f'' ~ 2.5e-3 mm of B3's moves).
constexpr double kClearanceSlope = 1e-6;
constexpr int kNewtonSteps = 4;  // step 5a's probes after the middle (B3: 1)
constexpr int kLocateSteps = 8;  // step 5b's secant steps in the ends' bracket

struct Interval {
  int a, b;      // samples at its ends (ta < tb)
  double lower;  // its proven lower bound of f
  double U;      // the best height when it was bounded (a lower one may prove more)
};

// Whether two samples' lowest points lie on faces of the cutter that meet at an edge
// (a flat end mill's rim: the bottom's normal is the axis, the flank's at right angles
// to it): their normals more than 60 degrees apart. f then has a kink between them,
// where its slope jumps (-0.05 to +32 mm per unit t on the line of certified_search_
// test's FlatCutterLineNearItsRimClosesItsProof), and the secant root of f' hugs the
// gentler end: a step of w/950 a sample, so that 1 024 samples crawled 0.37 of the way
// to the minimum and returned a height 5.5 um too high. Bisection finds the kink in
// ~50 samples. On smooth faces the normals of a bracket's ends turn by far less.
inline bool acrossEdge(const SearchSample& a, const SearchSample& b) {
  return dot(a.normal, b.normal) < 0.5;
}

// Searches that hit kMaxSamples before their proof closed (expected: none).
std::atomic<unsigned long long> unprovenSearchCount{0};
// The same count for this thread alone: a caster's tile, which runs on one thread without
// yielding, attributes its searches to its own run by the difference across it.
thread_local unsigned long long unprovenOnThisThread = 0;

// One search on the line l through (x, y): the samples of f taken so far, the best of
// them (step 1's U) and the open intervals of step 3, with one method per step of the
// derivation above. run() orders them: step 5, then step 3.
class CertifiedSearch {
 public:
  CertifiedSearch(const Cutter& c, const PoseCurve& curve, const TurningBounds& bounds, double x,
                  double y, double cutoff)
      : c_(c),
        curve_(curve),
        bounds_(bounds),
        x_(x),
        y_(y),
        cutoff_(cutoff),
        intervalBounds_(c, curve, bounds, x, y),
        samples_(reinterpret_cast<SearchSample*>(sampleStorage_)) {}

  LowestPoint run();

 private:
  // Whether a sample met K(t) where it has a plane that is not near vertical: the
  // cutter-fixed planes of steps 2b and 2d apply from it.
  static bool smooth(const SearchSample& s) { return s.z < HUGE_VAL && s.normal.z <= -1e-3; }
  // Step 1.
  int sampleAt(double t, double zBelow);
  int take(double t);
  LowestPoint result() const;
  // Step 2 (the bounds themselves: intervalBounds_).
  void supportOf(int i);
  Interval boundOf(int ia, int ib);
  // Steps 5 and 4b.
  void locateFromMiddle();
  void locateInEndsBracket();
  bool cleared();
  // Step 3.
  bool done(const Interval& iv) const;
  void push(const Interval& iv);
  bool bracketsMinimum(const Interval& iv) const;
  void openBetweenSamples();
  int pickInterval(bool polish) const;
  bool clearanceSettles(const Interval& picked);
  double splitPoint(const Interval& iv) const;
  LowestPoint branchAndBound();

  const Cutter& c_;
  const PoseCurve& curve_;
  const TurningBounds& bounds_;
  const double x_, y_, cutoff_;
  const IntervalBounds intervalBounds_;  // step 2's bounds on this line

  alignas(SearchSample) unsigned char sampleStorage_[kMaxSamples * sizeof(SearchSample)];
  SearchSample* const samples_;
  int count_ = 0;
  int best_ = -1;        // the lowest sample so far: U's
  double U_ = HUGE_VAL;  // step 1's upper bound of F

  Interval open_[kMaxSamples];  // step 3's intervals not yet proven
  int openCount_ = 0;
  int clearanceFrom_ = -1, clearanceTries_ = 0;  // step 4b: the last sample it started from
};

// Step 1: f(t), with a proven lower bound zBelow of it to start Newton from (step 2's
// bound of the interval being split), and the plane and slope that bound and steer the
// search from it.
inline int CertifiedSearch::sampleAt(double t, double zBelow) {
  SearchSample& s = *new (&samples_[count_]) SearchSample;
  s.t = t;
  s.z = HUGE_VAL;
  s.normal = {};
  s.slope = std::numeric_limits<double>::quiet_NaN();
  s.tip = curve_.tip(t);
  s.vel = curve_.tipVelocity(t);
  s.acc = curve_.tipAcceleration(t);
  s.axis = curve_.axis(t);
  const LowestPoint lp =
      cutterLowestPoint(c_, s.axis, x_ - s.tip.x, y_ - s.tip.y, zBelow - s.tip.z);
  if (lp.hit) s.z = lp.z + s.tip.z;
  if (lp.hit && lp.normal.z <= -1e-3) {
    s.normal = lp.normal;
    // f' = (N . v) / N.z, v the velocity of the cutter point at the lowest point.
    const Vec3 spin = curve_.spin(t);
    const Vec3 v = s.vel + cross(spin, Vec3{x_, y_, s.z} - s.tip);
    s.slope = dot(s.normal, v) / s.normal.z;
    s.dn = cross(spin, s.normal);
    s.ddn = cross(curve_.spinRate(t), s.normal) + cross(spin, s.dn);
  } else {
    s.normal = steepNormal(c_, s.tip, s.axis, x_, y_);
  }
  s.hOwn = std::numeric_limits<double>::quiet_NaN();  // supportOf(), when a bound needs it
  return count_++;
}

// Step 1: a sample of f without a bound below it, kept as U where it is the lowest.
inline int CertifiedSearch::take(double t) {
  const int i = sampleAt(t, -HUGE_VAL);
  if (best_ < 0 || samples_[i].z < U_) U_ = samples_[i].z, best_ = i;
  return i;
}

// U and its sample's plane, or a miss where U is not below the cutoff.
inline LowestPoint CertifiedSearch::result() const {
  if (!(U_ < cutoff_)) return {};
  LowestPoint out;
  out.hit = true;
  out.z = U_;
  out.normal = samples_[best_].normal;
  out.t = samples_[best_].t;
  if (out.normal.z == 0) out.normal = {0, 0, -1};
  return out;
}

// Step 2: the support of K(t) - tip(t) in the sample's plane normal, which every bound
// of step 2 needs and step 5 does not: computed once, on first use.
inline void CertifiedSearch::supportOf(int i) {
  SearchSample& s = samples_[i];
  if (std::isnan(s.hOwn))
    s.hOwn = s.normal.z != 0 ? dot(s.normal, cutterSupport(c_, s.axis, s.normal)) : 0;
}

// Step 2: the interval between two samples with its lower bound, the bounds tried
// from the cheapest and tightest until one proves it cannot improve U.
inline Interval CertifiedSearch::boundOf(int ia, int ib) {
  supportOf(ia), supportOf(ib);
  const SearchSample &a = samples_[ia], &b = samples_[ib];
  if (a.t == b.t) return Interval{ia, ib, std::min(a.z, b.z), U_};  // both ends are known
  const double enough = std::min(U_ - kProofGap, bounds_.zTop);
  // The cutter-fixed planes first (tight wherever the line meets the cutters' lower
  // faces); the world-fixed planes where those do not settle it; where the line
  // leaves or grazes a cutter, planes say little and the grown cutter decides.
  double lower = std::max(intervalBounds_.cutterPlane(a, b, a, b, U_),
                          intervalBounds_.cutterPlane(b, a, a, b, U_));
  if (!(lower >= enough))
    lower =
        std::max({lower, intervalBounds_.worldPlane(a, a, b), intervalBounds_.worldPlane(b, a, b)});
  if (!(lower >= enough) && U_ < HUGE_VAL &&
      (intervalBounds_.taylorProves(a, a, b, U_ - kProofGap) ||
       intervalBounds_.taylorProves(b, a, b, U_ - kProofGap)))
    lower = U_ - kProofGap;
  if (!(lower >= enough) && !(smooth(a) && smooth(b)))
    lower = std::max(lower, intervalBounds_.grownCutter(a, b));
  if (!(lower >= enough) && !(smooth(a) && smooth(b)) && intervalBounds_.missesBesideFluteTop(a, b))
    lower = HUGE_VAL;
  return Interval{ia, ib, lower, U_};
}

// Step 4b, and where it fails the Taylor form of step 2d from the best sample over the
// whole move: on a flat face (the bottom of a bull or flat cutter) g curves away from
// the line only through f'', which tangent lines cannot see, while 2d proves it at once.
inline bool CertifiedSearch::cleared() {
  if (!(U_ < HUGE_VAL)) return false;
  if (rayClearsMove(c_, curve_, {x_, y_, U_ - kProofGap}, samples_[best_].t, 0, 1)) return true;
  if (!smooth(samples_[best_])) return false;
  supportOf(best_);
  SearchSample whole[2];
  whole[0].t = 0, whole[0].tip = curve_.tip(0);
  whole[1].t = 1, whole[1].tip = curve_.tip(1);
  return intervalBounds_.taylorProves(samples_[best_], whole[0], whole[1], U_ - kProofGap);
}

// Step 5a: the minimum of f located without any bound: from the middle, Newton's step
// with f'' from the cutter's curvature there (lowestPointCurvature), then secant steps,
// clamped to [0, 1]. On CAM paths two samples.
inline void CertifiedSearch::locateFromMiddle() {
  int prev = -1, cur = take(0.5);
  for (int step = 0; step < kNewtonSteps; ++step) {
    const SearchSample& s = samples_[cur];
    if (!std::isfinite(s.slope) || std::fabs(samples_[best_].slope) <= kClearanceSlope) break;
    double next;
    if (prev < 0) {
      const double fpp = lowestPointCurvature(c_, curve_, s.t, Vec3{x_, y_, s.z});
      if (!(fpp > 0)) break;
      next = s.t - s.slope / fpp;
    } else {
      const SearchSample& p = samples_[prev];
      if (!std::isfinite(p.slope) || p.slope == s.slope) break;
      next = s.t - s.slope * (s.t - p.t) / (s.slope - p.slope);
    }
    next = std::clamp(next, 0.0, 1.0);
    if (!(next != s.t)) break;
    prev = cur, cur = take(next);
  }
}

// Step 5b, where 5a's minimum does not close the proof: f at the ends, then secant steps
// inside the bracket of the ends' slopes (bisection where the secant root hugs an end).
inline void CertifiedSearch::locateInEndsBracket() {
  int lo = take(0), hi = take(1);
  for (int step = 0; step < kLocateSteps; ++step) {
    const SearchSample &A = samples_[lo], &B = samples_[hi];
    if (std::fabs(samples_[best_].slope) <= kClearanceSlope || !(A.slope < 0 && B.slope > 0)) break;
    const double w = B.t - A.t, r = A.t + w * (-A.slope / (B.slope - A.slope));
    const double ts =
        r > A.t + w / 1024 && r < B.t - w / 1024 && !acrossEdge(A, B) ? r : A.t + 0.5 * w;
    if (!(ts > A.t && ts < B.t)) break;
    const int is = take(ts);
    if (samples_[is].slope < 0) {
      lo = is;
    } else if (samples_[is].slope > 0) {
      hi = is;
    } else {
      break;
    }
  }
}

// Step 3: an interval is done when its bound proves it cannot improve U (to the gap) or
// when the bound lies above the whole solid's top: the line meets no cutter there.
inline bool CertifiedSearch::done(const Interval& iv) const {
  return iv.lower >= std::min(U_ - kProofGap, bounds_.zTop);
}

inline void CertifiedSearch::push(const Interval& iv) {
  if (!done(iv)) open_[openCount_++] = iv;
}

inline bool CertifiedSearch::bracketsMinimum(const Interval& iv) const {
  return samples_[iv.a].slope < 0 && samples_[iv.b].slope > 0;
}

// Step 3's start: the intervals between the samples so far, in order of t.
inline void CertifiedSearch::openBetweenSamples() {
  int order[kMaxSamples];  // every sample so far
  for (int i = 0; i < count_; ++i) order[i] = i;
  std::sort(order, order + count_, [&](int i, int j) { return samples_[i].t < samples_[j].t; });
  for (int i = 0; i + 1 < count_; ++i) push(boundOf(order[i], order[i + 1]));
}

// Step 3's choice of the interval to split: until the best sample is a minimum of f to
// round-off (`polish`: f' not yet ~ 0, where step 2d would prove the intervals beside it
// at once), an interval whose ends bracket a root of f' first; otherwise best first:
// the lowest bound (ties: the earlier in t).
inline int CertifiedSearch::pickInterval(bool polish) const {
  int k = -1;
  for (int i = 0; i < openCount_; ++i) {
    const Interval& p = open_[i];
    if (polish && k >= 0 && bracketsMinimum(open_[k]) && !bracketsMinimum(p)) continue;
    if (k < 0 || (polish && bracketsMinimum(p) && !bracketsMinimum(open_[k])) ||
        p.lower < open_[k].lower ||
        (p.lower == open_[k].lower && samples_[p.a].t < samples_[open_[k].a].t))
      k = i;
  }
  return k;
}

// Step 4b inside step 3: once the minimum is nearly located (the best sample's slope
// small enough for U to lie within the gap of F where f curves as on CAM paths, or the
// picked interval does not bracket a minimum), the ray-clearance proof from the best
// sample may settle the whole move at once: every f(t) > U - 1e-9. Tried from a new best
// sample at most three times.
inline bool CertifiedSearch::clearanceSettles(const Interval& picked) {
  if (best_ != clearanceFrom_ && clearanceTries_ < 3 && U_ < HUGE_VAL &&
      (std::fabs(samples_[best_].slope) <= kClearanceSlope || !bracketsMinimum(picked))) {
    clearanceFrom_ = best_, ++clearanceTries_;
    return rayClearsMove(c_, curve_, {x_, y_, U_ - kProofGap}, samples_[best_].t, 0, 1);
  }
  return false;
}

// Step 3's split point of an interval: the secant root of f' where its ends bracket a
// minimum; otherwise from the lower end, the width its plane can prove (the loss of the
// current bound is second order in the width near a minimum); else the middle.
inline double CertifiedSearch::splitPoint(const Interval& iv) const {
  const SearchSample &A = samples_[iv.a], &B = samples_[iv.b];
  const double w = B.t - A.t;
  double ts = A.t + 0.5 * w;
  bool chosen = false;
  if (bracketsMinimum(iv)) {  // f' changes sign inside: its secant root, or a kink's middle
    if (acrossEdge(A, B)) return ts;
    const double r = A.t + w * (-A.slope / (B.slope - A.slope));
    if (r > A.t + w / 1024 && r < B.t - w / 1024) ts = r, chosen = true;
  }
  if (!chosen && (std::isfinite(A.z) || std::isfinite(B.z))) {
    const bool fromA = A.z <= B.z;
    const SearchSample& low = fromA ? A : B;
    const double loss = low.z - iv.lower;
    const double allowed = low.z - (U_ - kProofGap);
    double step = 0.5;
    if (loss > 0 && allowed > 0) step = std::clamp(0.8 * std::sqrt(allowed / loss), 1.0 / 64, 0.5);
    ts = fromA ? A.t + step * w : B.t - step * w;
  }
  return ts;
}

// Step 3: branch and bound over t from every sample so far, until every interval's
// bound is at least U - 1e-9 mm (F in [U - 1e-9, U]) or the cutoff, or step 4b settles
// the whole move.
inline LowestPoint CertifiedSearch::branchAndBound() {
  clearanceFrom_ = best_, clearanceTries_ = 1;  // step 5 tried it from the best sample
  openBetweenSamples();
  while (openCount_ > 0 && count_ < kMaxSamples) {
    const bool polish = !(std::fabs(samples_[best_].slope) <= kFlatSlope);
    const int k = pickInterval(polish);
    if (clearanceSettles(open_[k])) {
      openCount_ = 0;
      break;
    }
    Interval iv = open_[k];
    if (iv.U > U_) {  // bounded before U fell: bound it again, and pick anew
      open_[k] = boundOf(iv.a, iv.b);
      if (done(open_[k])) open_[k] = open_[--openCount_];
      continue;
    }
    if (done(iv)) {
      if (!(polish && bracketsMinimum(iv))) break;  // proven: F >= U - 1e-9, or no hit
      open_[k] = open_[--openCount_];
      continue;
    }
    if (iv.lower >= cutoff_) return {};  // proven: F >= cutoff
    open_[k] = open_[--openCount_];

    const double ts = splitPoint(iv);
    if (!(ts > samples_[iv.a].t && ts < samples_[iv.b].t)) continue;  // below double resolution
    const int is = sampleAt(ts, iv.lower);
    if (samples_[is].z < U_) U_ = samples_[is].z, best_ = is;
    // Children that the new U already proves are dropped by push(), as are open
    // intervals, lazily, when picked.
    push(boundOf(iv.a, is));
    push(boundOf(is, iv.b));
  }
  if (openCount_ > 0 && count_ >= kMaxSamples) {
    unprovenSearchCount.fetch_add(1, std::memory_order_relaxed);
    ++unprovenOnThisThread;
  }
  return result();
}

// Step 5, then step 3: the minimum located without any bound and the whole move proven
// at once (step 4b, or 2d over [0, 1]); where f' is unknown, nothing brackets a root, or
// the proof still fails, the branch and bound takes over with every sample so far.
inline LowestPoint CertifiedSearch::run() {
  locateFromMiddle();
  if (cleared()) return result();
  locateInEndsBracket();
  if (cleared()) return result();
  return branchAndBound();
}

}  // namespace

unsigned long long unprovenCertifiedSearches() {
  return unprovenSearchCount.load();
}

unsigned long long unprovenCertifiedSearchesOnThisThread() {
  return unprovenOnThisThread;
}

LowestPoint certifiedLowestPoint(const Cutter& c, const PoseCurve& curve,
                                 const TurningBounds& bounds, double x, double y, double cutoff) {
  CertifiedSearch search(c, curve, bounds, x, y, cutoff);
  return search.run();
}

}  // namespace scallop
