// CutterProfile (sweep/cutter_profile.h): make()'s validation names the segment and
// what is wrong; of() gives ball, flat and bull their closed-form widths; width,
// support, signedDistance (and its gradient) and grown agree with dense sampling of the
// chains of tests/sweep/profile_cases.h, whose arcs' centres are known independently.
#include "sweep/cutter_profile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/cutter.h"
#include "sweep/profile_cases.h"

namespace scallop {
namespace {

using test::ProfileCase;

std::string makeError(const std::vector<ProfileSegment>& chain) {
  try {
    CutterProfile::make(chain, "tool.profile");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CutterProfile, MakeNamesTheSegmentAndTheReason) {
  // Not from the tip.
  EXPECT_NE(makeError({{0.5, 0, 1, 1}}).find("tool.profile[0]: starts at"), std::string::npos);
  // A gap between segments.
  EXPECT_NE(makeError({{0, 0, 1, 0}, {1.1, 0, 1.1, 3}}).find("tool.profile[1]: starts at"),
            std::string::npos);
  // Turns away from the solid (a concave corner).
  EXPECT_NE(makeError({{0, 0, 1, 1}, {1, 1, 1.5, 1.2}, {1.5, 1.2, 1.5, 3}}).find("tool.profile[1]"),
            std::string::npos);
  // A spike below the tip.
  EXPECT_NE(makeError({{0, 0, 1, -1}, {1, -1, 1, 2}}).find("tool.profile[0]"), std::string::npos);
  // An arc too small for its chord, a negative radius, zero length.
  EXPECT_NE(makeError({{0, 0, 2, 2, 1}}).find("cannot join"), std::string::npos);
  EXPECT_NE(makeError({{0, 0, 2, 2, -1}}).find("arc radius"), std::string::npos);
  EXPECT_NE(makeError({{0, 0, 0, 0}}).find("zero length"), std::string::npos);
  // Down past the horizontal at the top.
  EXPECT_NE(makeError({{0, 0, 1, 1}, {1, 1, 0.5, 0.9}}).find("tool.profile[1]"), std::string::npos);
  // Across the axis.
  EXPECT_NE(makeError({{0, 0, 1, 1}, {1, 1, -1, 3}}).find("across the axis"), std::string::npos);
  EXPECT_NE(makeError({}).find("tool.profile"), std::string::npos);
  EXPECT_EQ(makeError({{0, 0, 1, 0}, {1, 0, 1, 3}}), "");
}

TEST(CutterProfile, BallFlatBullWidthsAreTheirClosedForms) {
  const Cutter ball = Cutter::make(CutterType::Ball, 2, 0, 6);
  const Cutter bull = Cutter::make(CutterType::Bull, 3, 1, 9);
  const Cutter flat = Cutter::make(CutterType::Flat, 1.5, 0, 4);
  for (const Cutter* c : {&ball, &bull, &flat}) {
    const CutterProfile p = CutterProfile::of(*c);
    const double R = c->radius, r = c->cornerRadius, L = c->fluteLength;
    EXPECT_DOUBLE_EQ(p.fluteLength(), L);
    EXPECT_NEAR(p.maxRadius(), R, 1e-12);
    EXPECT_NEAR(p.bottomRadius(), R - r, 1e-12);
    for (int i = 0; i <= 400; ++i) {
      const double s = L * i / 400;
      const double want = s < r ? R - r + std::sqrt(r * r - (r - s) * (r - s)) : R;
      EXPECT_NEAR(p.width(s), want, 1e-12) << toString(c->type) << " s " << s;
    }
  }
}

// The boundary of P (chain and cap) as a dense polyline, from the case's own pieces.
std::vector<ProfilePoint> densePolyline(const ProfileCase& c, int perPiece) {
  std::vector<ProfilePoint> pts;
  for (const test::ProfilePiece& p : c.pieces) {
    for (int i = 0; i <= perPiece; ++i) {
      const double u = double(i) / perPiece;
      if (p.radius > 0) {
        const double a0 = std::atan2(p.s0 - p.cs, p.r0 - p.cr);
        double a1 = std::atan2(p.s1 - p.cs, p.r1 - p.cr);
        if (a1 < a0) a1 += 2 * kPi;
        const double a = a0 + (a1 - a0) * u;
        pts.push_back({p.cr + p.radius * std::cos(a), p.cs + p.radius * std::sin(a)});
      } else {
        pts.push_back({p.r0 + (p.r1 - p.r0) * u, p.s0 + (p.s1 - p.s0) * u});
      }
    }
  }
  const ProfilePoint top = pts.back();
  for (int i = 1; i <= perPiece; ++i) pts.push_back({top.rho * (1 - double(i) / perPiece), top.s});
  return pts;
}

double polylineDistance(const std::vector<ProfilePoint>& pts, double rho, double s) {
  double best = HUGE_VAL;
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    const double dr = pts[i + 1].rho - pts[i].rho, ds = pts[i + 1].s - pts[i].s;
    const double len2 = dr * dr + ds * ds;
    double u = len2 > 0 ? ((rho - pts[i].rho) * dr + (s - pts[i].s) * ds) / len2 : 0;
    u = std::clamp(u, 0.0, 1.0);
    best = std::min(best, std::hypot(rho - pts[i].rho - u * dr, s - pts[i].s - u * ds));
  }
  return best;
}

TEST(CutterProfile, RandomProfilesAgreeWithDenseSampling) {
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> u(0, 1);
  double worstWidth = 0, worstDistance = 0, worstSupport = 0, worstGrown = 0;
  for (int k = 0; k < 70; ++k) {
    const ProfileCase c = test::randomProfileCase(rng, k);
    const CutterProfile p = CutterProfile::make(c.chain(), "tool.profile");
    const double L = c.fluteLength(), W = c.maxWidth();
    ASSERT_NEAR(p.fluteLength(), L, 1e-12) << c.name;
    ASSERT_NEAR(p.maxRadius(), W, 1e-6) << c.name;
    // The reference's boundary point (w(s), s) lies on P's boundary. (Compared as a
    // distance: where the chain is horizontal, w(s) itself is sqrt-sensitive to the
    // arc centre's last bit.)
    for (int i = 0; i <= 200; ++i) {
      const double s = L * i / 200;
      worstWidth = std::max(worstWidth, std::fabs(p.signedDistance(c.width(s), s)));
    }
    // Arcs of up to 1000 mm: 4000 chords keep the polyline within ~1e-6 mm of them.
    const std::vector<ProfilePoint> pts = densePolyline(c, 4000);
    for (int i = 0; i < 40; ++i) {
      const double rho = W * 1.3 * u(rng), s = -1 + (L + 2) * u(rng);
      double dRho = 0, dS = 0;
      const double sd = p.signedDistance(rho, s, &dRho, &dS);
      const bool in = s >= 0 && s <= L && rho <= c.width(s);
      const double want = (in ? -1 : 1) * polylineDistance(pts, rho, s);
      worstDistance = std::max(worstDistance, std::fabs(sd - want));
      // The gradient is unit and leads to the nearest boundary point.
      EXPECT_NEAR(std::hypot(dRho, dS), 1, 1e-9) << c.name;
      EXPECT_NEAR(p.signedDistance(rho - sd * dRho, s - sd * dS), 0, 1e-9) << c.name;
      // grown(delta): the signed distance less delta, in the frame of a tip delta lower.
      const double delta = 0.05 + 0.5 * u(rng);
      const CutterProfile g = p.grown(delta);
      worstGrown = std::max(worstGrown, std::fabs(g.signedDistance(rho, s + delta) - (sd - delta)));
    }
    for (int i = 0; i < 40; ++i) {
      const double ang = kPi * (u(rng) - 0.5);
      const double nr = std::cos(ang), ns = std::sin(ang);
      const ProfilePoint q = p.support(nr, ns);
      double want = -HUGE_VAL;
      for (const ProfilePoint& pt : pts) want = std::max(want, nr * pt.rho + ns * pt.s);
      worstSupport = std::max(worstSupport, std::fabs(nr * q.rho + ns * q.s - want));
      EXPECT_LE(p.signedDistance(q.rho, q.s), 1e-9) << c.name;
    }
  }
  std::printf("profile vs sampling: width %.2e, distance %.2e, support %.2e, grown %.2e mm\n",
              worstWidth, worstDistance, worstSupport, worstGrown);
  EXPECT_LT(worstWidth, 1e-9);
  EXPECT_LT(worstDistance, 2e-6);  // the polyline's own chord error
  EXPECT_LT(worstSupport, 2e-6);
  EXPECT_LT(worstGrown, 1e-9);
}

}  // namespace
}  // namespace scallop
