// Path interval procedures of seed 000 (Sekine & Kameya) and seed 001 Eq. (1).
// See path_interval.h for the overview; equation numbers refer to seed 000 unless
// stated otherwise, line numbers to its Fig. 1 pseudo-code.
#include "analysis/path_interval.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <utility>

#include "base/constants.h"
#include "base/number_text.h"

namespace scallop {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double radians(double deg) {
  return deg * kRadPerDeg;
}

ProcedureResult ok(double valueMm) {
  return {true, valueMm, {}};
}
ProcedureResult notApplicable(std::string reason) {
  return {false, 0.0, std::move(reason)};
}

// ---- Domain checks: each returns an empty string when the input is valid ------------

std::string checkLength(const char* name, double v) {
  if (!std::isfinite(v)) return std::string(name) + " is not a finite number";
  if (v <= 0) return std::string(name) + " = " + formatNumber(v) + " mm must be > 0";
  return {};
}

std::string checkBull(double radius, double cornerRadius) {
  if (auto why = checkLength("tool radius R", radius); !why.empty()) return why;
  if (!std::isfinite(cornerRadius)) return "corner radius Rcr is not a finite number";
  if (cornerRadius <= 0)
    return "corner radius Rcr = " + formatNumber(cornerRadius) +
           " mm must be > 0 (a flat end mill has no fillet)";
  if (cornerRadius >= radius)
    return "corner radius Rcr = " + formatNumber(cornerRadius) +
           " mm must be < R = " + formatNumber(radius) + " mm (Rcr = R is a ball end mill)";
  return {};
}

std::string checkLead(double leadDeg) {
  if (!std::isfinite(leadDeg)) return "lead angle rho is not a finite number";
  if (std::fabs(leadDeg) >= 90)
    return "lead angle rho = " + formatNumber(leadDeg) + " deg must satisfy |rho| < 90 deg";
  return {};
}

// The 2D procedures divide by sin(rho) (Eqs. 5, 9, 11, 13).
std::string checkSinRho(const char* equation, double leadDeg) {
  if (std::sin(radians(std::fabs(leadDeg))) <= 0)
    return std::string(equation) + " divides by sin(rho); rho = " + formatNumber(leadDeg) +
           " deg has no such projection";
  return {};
}

// A tool inclined only along the feed has |Y| <= R everywhere: no L/2 exceeds R.
std::string checkWithinRadius(double halfInterval, double radius) {
  if (halfInterval > radius)
    return "L/2 = " + formatNumber(halfInterval) +
           " mm exceeds the tool radius R = " + formatNumber(radius) +
           " mm: h is larger than this tool can make";
  return {};
}

// ---- Small vector algebra for Fig. 1 ----------------------------------------------------

struct V3 {
  double x, y, z;
  V3 operator+(V3 b) const { return {x + b.x, y + b.y, z + b.z}; }
  V3 operator-(V3 b) const { return {x - b.x, y - b.y, z - b.z}; }
  friend V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
  friend double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
  friend V3 cross(V3 a, V3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  }
  friend V3 normalize(V3 a) { return (1.0 / std::sqrt(dot(a, a))) * a; }
};

// The inclined torus of Fig. 3. Global frame: X = feed, Y = cross-feed, Z = up; the
// tool centre (centre of the circle of radius Rb) at the origin. The tool axis ZT is
// Z rotated by rho towards +X; XT = (cos rho, 0, -sin rho) points to the lowest point
// of the Rb circle; YT = Y (line 1). The angle gamma runs on the Rb circle from XT
// towards YT, so gamma = 0 is the base section that touches the designed surface.
struct InclinedTorus {
  double rb;   // Rb, mm (0: the sphere of a ball end mill)
  double rcr;  // Rcr, mm
  double rho;  // lead, rad, >= 0
  double h;    // scallop height, mm
  double sinRho = std::sin(rho), cosRho = std::cos(rho);
  V3 xt{cosRho, 0, -sinRho}, yt{0, 1, 0}, zt{sinRho, 0, cosRho};  // tool axes (line 1)
  V3 nh{0, 0, 1};  // normal of the h pseudo plane (line 1)

  V3 radial(double g) const { return std::cos(g) * xt + std::sin(g) * yt; }
  V3 centre(double g) const { return rb * radial(g); }                        // P_ap
  V3 tangent(double g) const { return std::cos(g) * yt - std::sin(g) * xt; }  // t_ap

  // Eq. (2): eta = t . {(n_h x t) x n_h}. The bracket is t's projection onto the h
  // plane; we normalise it so that eta is the direction cosine between t and the plane,
  // as the text names it (the bare product would be its square, cos^2).
  double eta(double g) const {
    V3 t = tangent(g);
    return dot(t, normalize(cross(cross(nh, t), nh)));
  }
  // Height of P_ap above the h pseudo plane, the numerator of Eq. (3).
  double heightAboveHPlane(double g) const {
    return rcr - h + rb * sinRho - rb * std::cos(g) * sinRho;
  }
  // Eq. (3): distance d_s, inside the section (the plane normal to t), from P_ap to the
  // h pseudo plane along the steepest descent u of line 12.
  double ds(double g) const { return heightAboveHPlane(g) / eta(g); }
  // d(d_s)/d(gamma), for the update of line 7.
  double dsDerivative(double g) const {
    double e = eta(g);
    double dH = rb * sinRho * std::sin(g);
    double dEta = -std::sin(g) * std::cos(g) * sinRho * sinRho / e;
    return (dH * e - heightAboveHPlane(g) * dEta) / (e * e);
  }
  // Line 12: m = t x n_h, u = t x m (unit; points down within the section).
  V3 descent(double g) const {
    V3 t = tangent(g);
    return normalize(cross(t, cross(t, nh)));
  }

  // The point of section gamma on the h plane with the largest Y (line 21): the chord
  // of the section circle (centre P_ap, radius Rcr) cut by the h plane has its midpoint
  // P_ap + d_s u and runs along w = t x u; returns false if the section misses the plane.
  bool farthestOnPlane(double g, V3* p) const {
    double d = ds(g);
    if (!(d <= rcr)) return false;
    V3 t = tangent(g), u = descent(g), w = cross(t, u);
    double q = std::sqrt(std::max(0.0, rcr * rcr - d * d));
    V3 mid = centre(g) + d * u;
    V3 a = mid + q * w, b = mid - q * w;
    *p = a.y >= b.y ? a : b;
    return true;
  }

  // True if p (on section gamma) lies on the cutting quarter of the fillet: below the
  // plane of the Rb circle and outside the Rb cylinder.
  bool onFilletQuarter(double g, V3 p) const {
    V3 r = p - centre(g);
    const double tol = 1e-12 * (rb + rcr);
    return dot(r, radial(g)) >= -tol && dot(r, zt) <= tol;
  }
};

// Lines 5-11: the single contact gamma_scp where the section is tangent to the h plane,
// R_cr - d_s = 0. Line 7's "update gamma according to R_cr - d_s" is a Newton step on
// that residual, kept inside a bracket (bisection when Newton leaves it). The bracket is
// the first sign change on a coarse scan of [0, pi], so gamma_scp is the first tangency
// from the base section. Returns false if every section crosses the plane.
bool singleContact(const InclinedTorus& torus, double gammaStart, double eps, double* gScp) {
  auto residual = [&](double g) { return torus.rcr - torus.ds(g); };
  constexpr int kScan = 64;
  double lo = 0, hi = -1;
  for (int k = 1; k <= kScan; ++k) {
    double g = kPi * k / kScan;
    if (residual(g) <= 0) {
      lo = kPi * (k - 1) / kScan;
      hi = g;
      break;
    }
  }
  if (hi < 0) return false;
  double g = (gammaStart > lo && gammaStart < hi) ? gammaStart : 0.5 * (lo + hi);
  for (int iter = 0; iter < 200; ++iter) {  // lines 6-11
    double f = residual(g);
    if (std::fabs(f) < eps) break;  // line 11
    (f > 0 ? lo : hi) = g;
    double slope = torus.dsDerivative(g);
    double next = slope > 0 ? g + f / slope : lo - 1;  // line 7
    g = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
    if (hi - lo < 1e-15) break;
  }
  *gScp = g;  // line 14
  return true;
}

// Fig. 1 on a torus with Rb >= 0 (Rb = 0: the sphere of a ball end mill).
ProcedureResult computational(double rb, double rcr, double rho, double h, double eps) {
  InclinedTorus torus{rb, rcr, std::fabs(rho), h};
  const double radius = rb + rcr;

  // Line 2, Eq. (1): Rb sin(rho) - Rb cos(gamma) sin(rho) = h/2, the section whose
  // centre has risen by h/2; the start of the first iteration (gamma = pi/2 when the
  // centre never rises, rho = 0 or Rb = 0).
  double rise = rb * torus.sinRho;
  double gammaAp = rise > 0 ? std::acos(std::max(-1.0, 1.0 - 0.5 * h / rise)) : 0.5 * kPi;

  // Lines 5-15. With a single contact P_hp = P_scp + Rcr u_scp (line 13) lies on the
  // intersection, so L/2 >= Y(P_hp). Line 15 derives the lower end of the search range
  // from the Y component of that contact: a point of section gamma has
  // Y = (Rb + Rcr cos(phi)) sin(gamma) <= R sin(gamma), so only sections with
  // R sin(gamma) >= Y(P_hp) can hold a farther point. (The text names P_scp, the
  // section's centre; Y(P_scp) <= Y(P_hp) for gamma_scp <= 90 deg, so P_hp is the
  // tighter, still safe, bound.) If no section is tangent (every section crosses the h
  // plane, e.g. rho = 0), the range is the whole half circle [0, pi].
  double gLow = 0, gHigh = kPi;
  double gScp = 0;
  if (singleContact(torus, gammaAp, eps, &gScp)) {
    V3 pHp = torus.centre(gScp) + rcr * torus.descent(gScp);  // lines 12-13
    gHigh = gScp;
    if (pHp.y > 0) gLow = std::min(gScp, std::asin(std::min(1.0, pHp.y / radius)));
  }

  // Lines 16-25: sample the range at n even steps, keep the neighbours of the sample
  // with the largest Y as the new range, repeat until that sample differs from its
  // neighbours by less than eps in Y.
  // The range always keeps the best sample, so the last one is the best found.
  constexpr int n = 32;
  double g[n], y[n];
  V3 p[n];
  int iMax = 0;
  for (int iter = 0; iter < 200; ++iter) {
    for (int i = 0; i < n; ++i) {  // lines 17-22
      g[i] = gLow + (gHigh - gLow) * i / (n - 1);
      y[i] = torus.farthestOnPlane(g[i], &p[i]) ? p[i].y : -kInf;
    }
    iMax = static_cast<int>(std::max_element(y, y + n) - y);  // line 23
    double diff = std::max(iMax > 0 ? y[iMax] - y[iMax - 1] : 0.0,
                           iMax < n - 1 ? y[iMax] - y[iMax + 1] : 0.0);  // line 24
    gLow = g[std::max(0, iMax - 1)];                                     // second line 23
    gHigh = g[std::min(n - 1, iMax + 1)];
    if (!(diff >= eps) || gHigh - gLow < 1e-15) break;  // line 25
  }
  if (!std::isfinite(y[iMax]))
    return notApplicable("computational: no section of the torus reaches the h plane");
  if (!torus.onFilletQuarter(g[iMax], p[iMax]))
    return notApplicable("computational: at h = " + formatNumber(h) +
                         " mm the farthest point of the torus lies off the fillet's cutting "
                         "quarter (the flank or the inner half would be cut): h is larger "
                         "than the torus model of Fig. 1 covers");
  return ok(y[iMax]);  // line 26
}

// The first non-empty reason, prefixed with the procedure's name; empty if none.
std::string firstReason(const char* name, std::initializer_list<std::string> reasons) {
  for (const std::string& r : reasons)
    if (!r.empty()) return std::string(name) + ": " + r;
  return {};
}

// Fig. 1 after the input checks; rb = 0 is the ball's sphere.
ProcedureResult checkedComputational(double rb, double rcr, double leadDeg, double h, double eps) {
  std::string why =
      firstReason("computational", {checkLead(leadDeg), checkLength("scallop height h", h),
                                    checkLength("convergence epsilon", eps)});
  return why.empty() ? computational(rb, rcr, radians(leadDeg), h, eps) : notApplicable(why);
}

}  // namespace

// Eq. (8): L/2 = sqrt(2 R_eff h - h^2), shared by sekine, redonnet and
// the effective radius at the contact (analysis/contact_curvature.h).
ProcedureResult circularHalfInterval(const char* name, const ProcedureResult& reff, double h,
                                     double radius) {
  if (!reff.applicable) return reff;
  if (auto why = checkLength("scallop height h", h); !why.empty())
    return notApplicable(std::string(name) + ": " + why);
  if (h > reff.value)
    return notApplicable(std::string(name) + ": h = " + formatNumber(h) + " mm exceeds R_eff = " +
                         formatNumber(reff.value) + " mm, beyond the circle of Eq. (8)");
  double halfInterval = std::sqrt(2 * reff.value * h - h * h);
  if (auto why = checkWithinRadius(halfInterval, radius); !why.empty())
    return notApplicable(std::string(name) + ": " + why);
  return ok(halfInterval);
}

// Eq. (12): h = R_eff - sqrt(R_eff^2 - L^2/4), shared by sekine, redonnet and
// the effective radius at the contact (analysis/contact_curvature.h).
ProcedureResult circularScallopHeight(const char* name, const ProcedureResult& reff,
                                      double halfInterval, double radius) {
  if (!reff.applicable) return reff;
  std::string why = checkLength("half interval L/2", halfInterval);
  if (why.empty()) why = checkWithinRadius(halfInterval, radius);
  if (why.empty() && halfInterval > reff.value)
    why = "L/2 = " + formatNumber(halfInterval) +
          " mm exceeds R_eff = " + formatNumber(reff.value) + " mm (Eq. 12)";
  if (!why.empty()) return notApplicable(std::string(name) + ": " + why);
  return ok(reff.value - std::sqrt(reff.value * reff.value - halfInterval * halfInterval));
}

// ---- Radii of the 2D procedures ---------------------------------------------------------

ProcedureResult effectiveRadiusSekine(double radiusMm, double cornerRadiusMm, double leadDeg) {
  std::string why = firstReason("sekine", {checkBull(radiusMm, cornerRadiusMm), checkLead(leadDeg),
                                           checkSinRho("Eq. (5)", leadDeg)});
  if (!why.empty()) return notApplicable(why);
  const double rho = radians(leadDeg);
  const double rb = radiusMm - cornerRadiusMm;
  const double rcr = cornerRadiusMm;
  double zTc = std::fabs(rb * std::sin(rho)) + rcr;             // Eq. (7)
  double rShort = zTc - rcr * std::cos(rho);                    // Eq. (6)
  double rLong = rShort / std::fabs(std::sin(rho));             // Eq. (5)
  return ok((rLong * rLong + rShort * rShort) / (2 * rShort));  // Eq. (4)
}

ProcedureResult effectiveRadiusRedonnet(double radiusMm, double cornerRadiusMm, double leadDeg) {
  std::string why = firstReason("redonnet", {checkBull(radiusMm, cornerRadiusMm),
                                             checkLead(leadDeg), checkSinRho("Eq. (9)", leadDeg)});
  if (!why.empty()) return notApplicable(why);
  const double rb = radiusMm - cornerRadiusMm;
  // Eq. (9): R_eff = Rb / sin(rho) + Rcr; |sin| because the lead's sign is a mirror.
  return ok(rb / std::fabs(std::sin(radians(leadDeg))) + cornerRadiusMm);
}

ProcedureResult longRadiusBedi(double radiusMm, double cornerRadiusMm, double leadDeg) {
  std::string why = firstReason("bedi", {checkBull(radiusMm, cornerRadiusMm), checkLead(leadDeg)});
  if (!why.empty()) return notApplicable(why);
  const double rb = radiusMm - cornerRadiusMm;
  // Eq. (10): R_long = Rb + Rcr sin(rho).
  return ok(rb + cornerRadiusMm * std::fabs(std::sin(radians(leadDeg))));
}

// ---- L/2 from h ----------------------------------------------------------------------------

ProcedureResult halfIntervalComputational(double radiusMm, double cornerRadiusMm, double leadDeg,
                                          double scallopHeightMm, double epsilonMm) {
  std::string why = firstReason("computational", {checkBull(radiusMm, cornerRadiusMm)});
  if (!why.empty()) return notApplicable(why);
  return checkedComputational(radiusMm - cornerRadiusMm, cornerRadiusMm, leadDeg, scallopHeightMm,
                              epsilonMm);
}

ProcedureResult halfIntervalSekine(double radiusMm, double cornerRadiusMm, double leadDeg,
                                   double scallopHeightMm) {
  return circularHalfInterval("sekine", effectiveRadiusSekine(radiusMm, cornerRadiusMm, leadDeg),
                              scallopHeightMm, radiusMm);
}

ProcedureResult halfIntervalRedonnet(double radiusMm, double cornerRadiusMm, double leadDeg,
                                     double scallopHeightMm) {
  return circularHalfInterval("redonnet",
                              effectiveRadiusRedonnet(radiusMm, cornerRadiusMm, leadDeg),
                              scallopHeightMm, radiusMm);
}

ProcedureResult halfIntervalBedi(double radiusMm, double cornerRadiusMm, double leadDeg,
                                 double scallopHeightMm) {
  ProcedureResult rLong = longRadiusBedi(radiusMm, cornerRadiusMm, leadDeg);
  if (!rLong.applicable) return rLong;
  std::string why = firstReason(
      "bedi", {checkSinRho("Eq. (11)", leadDeg), checkLength("scallop height h", scallopHeightMm)});
  if (!why.empty()) return notApplicable(why);
  // Eq. (11): an ellipse of semi-axes R_long (cross-feed) and R_long sin(rho) (depth);
  // past its half depth the formula folds back, so h <= R_long sin(rho).
  const double depth = rLong.value * std::fabs(std::sin(radians(leadDeg)));
  const double h = scallopHeightMm;
  if (h > depth)
    return notApplicable("bedi: h = " + formatNumber(h) + " mm exceeds R_long sin(rho) = " +
                         formatNumber(depth) + " mm, the half depth of the ellipse of Eq. (11)");
  double ratio = (depth - h) / depth;
  return ok(rLong.value * std::sqrt(1 - ratio * ratio));
}

ProcedureResult halfIntervalBall(double radiusMm, double scallopHeightMm) {
  std::string why = firstReason("ball", {checkLength("tool radius R", radiusMm),
                                         checkLength("scallop height h", scallopHeightMm)});
  if (!why.empty()) return notApplicable(why);
  const double r = radiusMm, h = scallopHeightMm;
  if (h > r)
    return notApplicable("ball: h = " + formatNumber(h) + " mm exceeds the ball radius R = " +
                         formatNumber(r) + " mm (the hemisphere ends there)");
  return ok(std::sqrt(2 * r * h - h * h));  // seed 001 Eq. (1)
}

// ---- h from L/2 ----------------------------------------------------------------------------

ProcedureResult scallopHeightComputational(double radiusMm, double cornerRadiusMm, double leadDeg,
                                           double halfIntervalMm, double epsilonMm) {
  std::string why =
      firstReason("computational", {checkBull(radiusMm, cornerRadiusMm), checkLead(leadDeg),
                                    checkLength("half interval L/2", halfIntervalMm),
                                    checkLength("convergence epsilon", epsilonMm),
                                    checkWithinRadius(halfIntervalMm, radiusMm)});
  if (!why.empty()) return notApplicable(why);
  // L/2 grows with h (sections of a convex cutter below its widest point); bisect on h,
  // treating heights outside the torus model as too high.
  auto lPerH = [&](double h) {
    return halfIntervalComputational(radiusMm, cornerRadiusMm, leadDeg, h, epsilonMm);
  };
  double lo = 0, hi = radiusMm + cornerRadiusMm;
  for (int iter = 0; iter < 200 && hi - lo > epsilonMm; ++iter) {
    double mid = 0.5 * (lo + hi);
    ProcedureResult r = lPerH(mid);
    (r.applicable && r.value < halfIntervalMm ? lo : hi) = mid;
  }
  double h = 0.5 * (lo + hi);
  ProcedureResult check = lPerH(h);
  if (!check.applicable || std::fabs(check.value - halfIntervalMm) > 1e-6)
    return notApplicable("computational: L/2 = " + formatNumber(halfIntervalMm) +
                         " mm is wider than the fillet makes at any h the torus model covers");
  return ok(h);
}

ProcedureResult scallopHeightSekine(double radiusMm, double cornerRadiusMm, double leadDeg,
                                    double halfIntervalMm) {
  return circularScallopHeight("sekine", effectiveRadiusSekine(radiusMm, cornerRadiusMm, leadDeg),
                               halfIntervalMm, radiusMm);
}

ProcedureResult scallopHeightRedonnet(double radiusMm, double cornerRadiusMm, double leadDeg,
                                      double halfIntervalMm) {
  return circularScallopHeight("redonnet",
                               effectiveRadiusRedonnet(radiusMm, cornerRadiusMm, leadDeg),
                               halfIntervalMm, radiusMm);
}

ProcedureResult scallopHeightBedi(double radiusMm, double cornerRadiusMm, double leadDeg,
                                  double halfIntervalMm) {
  ProcedureResult rLong = longRadiusBedi(radiusMm, cornerRadiusMm, leadDeg);
  if (!rLong.applicable) return rLong;
  std::string why = firstReason(
      "bedi", {checkSinRho("Eq. (13)", leadDeg), checkLength("half interval L/2", halfIntervalMm)});
  if (!why.empty()) return notApplicable(why);
  if (halfIntervalMm > rLong.value)
    return notApplicable("bedi: L/2 = " + formatNumber(halfIntervalMm) +
                         " mm exceeds R_long = " + formatNumber(rLong.value) + " mm (Eq. 13)");
  // Eq. (13): h = R_long sin(rho) (1 - sqrt(1 - (L / (2 R_long))^2)).
  double ratio = halfIntervalMm / rLong.value;
  return ok(rLong.value * std::fabs(std::sin(radians(leadDeg))) *
            (1 - std::sqrt(1 - ratio * ratio)));
}

ProcedureResult scallopHeightBall(double radiusMm, double halfIntervalMm) {
  std::string why = firstReason("ball", {checkLength("tool radius R", radiusMm),
                                         checkLength("half interval L/2", halfIntervalMm),
                                         checkWithinRadius(halfIntervalMm, radiusMm)});
  if (!why.empty()) return notApplicable(why);
  // Seed 001 Eq. (1) solved for h on the lower branch (h <= R).
  return ok(radiusMm - std::sqrt(radiusMm * radiusMm - halfIntervalMm * halfIntervalMm));
}

// ---- All procedures --------------------------------------------------------------------------

const ProcedureInfo kProcedures[kProcedureCount] = {
    {Procedure::kComputational, "computational", "seed 000 Fig. 1, Eqs. (1)-(3)",
     [](double r, double rcr, double rho, double h, double eps) {
       return halfIntervalComputational(r, rcr, rho, h, eps);
     },
     [](double r, double rcr, double rho, double l2, double eps) {
       return scallopHeightComputational(r, rcr, rho, l2, eps);
     }},
    {Procedure::kSekine, "sekine", "seed 000 Eqs. (4)-(8), (12)",
     [](double r, double rcr, double rho, double h, double) {
       return halfIntervalSekine(r, rcr, rho, h);
     },
     [](double r, double rcr, double rho, double l2, double) {
       return scallopHeightSekine(r, rcr, rho, l2);
     }},
    {Procedure::kRedonnet, "redonnet", "seed 000 Eqs. (9), (8), (12)",
     [](double r, double rcr, double rho, double h, double) {
       return halfIntervalRedonnet(r, rcr, rho, h);
     },
     [](double r, double rcr, double rho, double l2, double) {
       return scallopHeightRedonnet(r, rcr, rho, l2);
     }},
    {Procedure::kBedi, "bedi", "seed 000 Eqs. (10), (11), (13)",
     [](double r, double rcr, double rho, double h, double) {
       return halfIntervalBedi(r, rcr, rho, h);
     },
     [](double r, double rcr, double rho, double l2, double) {
       return scallopHeightBedi(r, rcr, rho, l2);
     }},
    {Procedure::kBall, "ball", "seed 001 Eq. (1)",
     [](double r, double, double, double h, double) { return halfIntervalBall(r, h); },
     [](double r, double, double, double l2, double) { return scallopHeightBall(r, l2); }},
};

namespace {

// Procedure `index` of kProcedures; `inverse` selects h from L/2.
ProcedureResult runProcedure(int index, const ProcedureTool& tool, double leadDeg, double x,
                             double eps, bool inverse) {
  const double r = tool.radiusMm, rcr = tool.cornerRadiusMm;
  const bool ball = tool.type == ProcedureToolType::Ball;
  const Procedure id = kProcedures[index].id;
  const bool filleted = id != Procedure::kComputational && id != Procedure::kBall;
  if (ball && filleted)
    return notApplicable(std::string(kProcedures[index].name) +
                         ": a filleted end mill procedure; the tool is a ball end mill");
  if (!ball && id == Procedure::kBall)
    return notApplicable("ball: the ball end mill formula; the tool is a filleted end mill");
  if (ball && id == Procedure::kComputational) {
    if (auto why = firstReason("computational", {checkLength("tool radius R", r)}); !why.empty())
      return notApplicable(why);
    // Fig. 1 on the degenerate torus Rb = 0, Rcr = R, the ball's sphere, whose
    // section is exactly Eq. (1) of seed 001; its inverse is that equation's.
    return inverse ? scallopHeightBall(r, x) : checkedComputational(0.0, r, leadDeg, x, eps);
  }
  const ProcedureInfo& p = kProcedures[index];
  return inverse ? p.scallopHeight(r, rcr, leadDeg, x, eps)
                 : p.halfInterval(r, rcr, leadDeg, x, eps);
}

std::vector<NamedProcedureResult> runAll(const ProcedureTool& tool, double leadDeg, double x,
                                         double eps, bool inverse) {
  std::vector<NamedProcedureResult> out;
  for (int i = 0; i < kProcedureCount; ++i)
    out.push_back({kProcedures[i].name, kProcedures[i].source,
                   runProcedure(i, tool, leadDeg, x, eps, inverse)});
  return out;
}

}  // namespace

std::vector<NamedProcedureResult> halfIntervalProcedures(const ProcedureTool& tool, double leadDeg,
                                                         double scallopHeightMm, double epsilonMm) {
  return runAll(tool, leadDeg, scallopHeightMm, epsilonMm, false);
}

std::vector<NamedProcedureResult> scallopHeightProcedures(const ProcedureTool& tool, double leadDeg,
                                                          double halfIntervalMm, double epsilonMm) {
  return runAll(tool, leadDeg, halfIntervalMm, epsilonMm, true);
}

}  // namespace scallop
