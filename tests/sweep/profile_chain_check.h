// A private check of CutterProfile's contract for the chains the shape builders make
// (sweep/cutter_shapes.h, sweep/apt_cutter.h), written from sweep/cutter_profile.h and
// independent of CutterProfile::make: the chain starts at the tip (0, 0), each segment
// starts where the last ended, each arc's ends lie at its radius from its centre, and
// the tangent turns only towards the solid (a convex profile), without a jump when
// `smooth`. Plus the error check every shape test uses.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "sweep/cutter_profile.h"

namespace scallop {

// The unit tangent (walking up the chain) at the start (`atEnd` false) or end of `seg`.
inline void chainTangent(const ProfileSegment& seg, bool atEnd, double& tRho, double& tS) {
  if (seg.arcRadius == 0) {
    const double len = std::hypot(seg.rho1 - seg.rho0, seg.s1 - seg.s0);
    tRho = (seg.rho1 - seg.rho0) / len, tS = (seg.s1 - seg.s0) / len;
    return;
  }
  // The solid lies to the left walking up, so arcs run counter-clockwise about the centre.
  const double pRho = atEnd ? seg.rho1 : seg.rho0, pS = atEnd ? seg.s1 : seg.s0;
  tRho = -(pS - seg.centreS) / seg.arcRadius, tS = (pRho - seg.centreRho) / seg.arcRadius;
}

inline void expectValidChain(const std::vector<ProfileSegment>& chain, bool smooth) {
  ASSERT_FALSE(chain.empty());
  EXPECT_EQ(chain.front().rho0, 0);
  EXPECT_EQ(chain.front().s0, 0);
  for (size_t i = 0; i < chain.size(); ++i) {
    const ProfileSegment& seg = chain[i];
    EXPECT_GT(std::hypot(seg.rho1 - seg.rho0, seg.s1 - seg.s0), 0) << "segment " << i;
    EXPECT_GE(std::min(seg.rho0, seg.rho1), 0) << "segment " << i;
    if (seg.arcRadius > 0) {
      const double tol = 1e-12 * std::max(1.0, seg.arcRadius);
      EXPECT_NEAR(std::hypot(seg.rho0 - seg.centreRho, seg.s0 - seg.centreS), seg.arcRadius, tol)
          << "arc " << i << " start";
      EXPECT_NEAR(std::hypot(seg.rho1 - seg.centreRho, seg.s1 - seg.centreS), seg.arcRadius, tol)
          << "arc " << i << " end";
      // The shorter arc, turning left: the end lies left of the start's tangent.
      double tRho, tS;
      chainTangent(seg, false, tRho, tS);
      EXPECT_GT(tRho * (seg.s1 - seg.s0) - tS * (seg.rho1 - seg.rho0), -tol) << "arc " << i;
    }
    if (i == 0) continue;
    const ProfileSegment& prev = chain[i - 1];
    EXPECT_EQ(seg.rho0, prev.rho1) << "segment " << i << " starts where " << i - 1 << " ended";
    EXPECT_EQ(seg.s0, prev.s1) << "segment " << i << " starts where " << i - 1 << " ended";
    double aRho, aS, bRho, bS;
    chainTangent(prev, true, aRho, aS);
    chainTangent(seg, false, bRho, bS);
    const double turn = aRho * bS - aS * bRho;  // sin of the turn, > 0 towards the solid
    const double along = aRho * bRho + aS * bS;
    EXPECT_GT(turn, -1e-12) << "the chain turns away from the solid at segment " << i;
    if (smooth) {
      EXPECT_NEAR(turn, 0, 1e-9) << "not tangent at segment " << i;
      EXPECT_GT(along, 0) << "reverses at segment " << i;
    }
  }
  // The last tangent no further round than the cap's (pointing towards the axis).
  double tRho, tS;
  chainTangent(chain.back(), true, tRho, tS);
  EXPECT_GE(tS, -1e-12);
}

// `f` throws an InputError whose where() names `field`.
template <class F>
void expectRejectedNaming(F&& f, const std::string& field) {
  try {
    f();
    ADD_FAILURE() << "accepted; expected an InputError naming " << field;
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), field) << e.what();
  }
}

}  // namespace scallop
