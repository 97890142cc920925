// The effective-radius closed form for any cutter of revolution whose contact with the
// plane lies on an arc of its profile: the barrel family's (form arc), and the ball's
// and bull's (Redonnet et al., seed 000 Eq. (9), generalised to lead and tilt).
//
// Derivation. The inclined cutter touches the plane z = 0 at the point where its
// outward normal is -z. With psi the angle between the axis a and the vertical
// (cos psi = a_z) that point lies on the meridian through a and z, at the profile
// point whose normal makes psi with -a, on an arc of radius R_arc whose centre is
// rho0 from the axis (rho0 < 0: across it, as a barrel's form arc). Its principal
// curvatures are the meridian's, k_m = 1 / R_arc, and the parallel circle's,
// k_p = sin(psi) / rho_c with rho_c = rho0 + R_arc sin(psi) its distance from the axis
// (Meusnier), in the horizontal directions t_m (along the horizontal projection of a)
// and t_p across it. The surface a pass leaves is the cutter's shadow along the feed
// x, whose cross-feed outline at the contact has the apparent-contour curvature
// k = K / k_x (Koenderink: orthographic projection along x), K = k_m k_p the Gaussian
// curvature and k_x = k_m cos^2(beta) + k_p sin^2(beta) (Euler), beta the angle from x
// to t_m. Hence the effective (osculating) radius
//     R_eff = k_x / K = R_arc sin^2(beta) + (rho0 / sin(psi) + R_arc) cos^2(beta),
// sin^2(beta) = a_y^2 / (a_x^2 + a_y^2). Lead only (beta = 0): R_eff = rho0 / sin(psi)
// + R_arc, which for a bull (rho0 = Rb, R_arc = Rcr) is seed 000 Eq. (9); tilt only
// (beta = 90 deg): R_eff = R_arc, the barrel's form arc itself; a ball: R_eff = R.
// The path interval then follows the circle of seed 000 Eq. (8), L/2 = sqrt(2 R_eff h
// - h^2) (the parabola h ~ (2 L/2)^2 / (8 R_eff) to first order).
//
// Assumptions (why this is an approximation, measured in tests/analysis and in
// docs/validation.md): the contact is a single point inside an arc (not a corner, a
// line or a ring); the section is replaced by its osculating circle there, so the
// profile's higher-order terms (the rest of the arc, the parallel's change of radius
// away from the contact) and, with a tilt, its asymmetry about the contact are ignored;
// the scallop must stay on the contact arc.
#pragma once

#include <string>

#include "analysis/path_interval.h"
#include "sweep/cutter.h"

namespace scallop {

// The arc of the profile on which the cutter touches the plane z = 0 when its axis
// leans psi from the vertical (sinPsi >= 0): its radius and its centre (rho, s) in the
// meridian half-plane, mm (rho < 0: across the axis); not found (with the reason) when
// the contact is a corner, a line or a ring.
struct ContactArc {
  bool found = false;
  double radius = 0, centreRho = 0, centreS = 0;
  std::string reason;  // when not found
};
ContactArc contactArc(const Cutter& cutter, double sinPsi, double cosPsi);

// R_eff at the contact of `cutter` inclined by leadTiltAxis(+x, lead, tilt), mm; not
// applicable (with the reason) when the contact is a corner, a line or a ring.
ProcedureResult effectiveRadiusAtContact(const Cutter& cutter, double leadDeg, double tiltDeg);
// L/2 from h by Eq. (8) with that R_eff.
ProcedureResult halfIntervalEffectiveRadius(const Cutter& cutter, double leadDeg, double tiltDeg,
                                            double scallopHeightMm);
// h from L/2 by Eq. (12) with that R_eff.
ProcedureResult scallopHeightEffectiveRadius(const Cutter& cutter, double leadDeg, double tiltDeg,
                                             double halfIntervalMm);

}  // namespace scallop
