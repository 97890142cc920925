// Feed marks of a cutter with teeth on a plane, in closed form (docs/teeth.md).
//
// Along the centre line of a straight level pass whose axis leans by the lead lambda
// along the feed (0 < |lambda| < 90 deg, no tilt), each tooth leaves, at its pass over
// the contact point, the meridian section of the cutter there: a circle of the profile's
// radius rho_f at the contact (R for a ball, the corner radius r for a bull, the form
// arc of a barrel; analysis/contact_curvature.h). Consecutive teeth are fz apart, so
// without tooth errors the marks are circular arcs of chord fz and height
//     h_f = rho_f - sqrt(rho_f^2 - fz^2 / 4)  ~  fz^2 / (8 rho_f).
// Not covered: a contact at a corner or on a line of the profile (a flat end mill's
// rim, a cone), no lead (the contact is at the tip, on the axis, where every tooth
// passes), a tilt (not derived here).
//
// Tooth errors. With the contact direction r = (cos lambda, 0, -sin lambda) (across the
// axis, in the plane of axis and feed, pointing down) and the axis a, tooth k (body
// angle psi_k, offsets dr_k, da_k) passes the contact a fraction psi_k / 2 pi of a
// revolution after tooth 0, its edge moved by q_k = rho_run cos(psi_run - psi_k -
// h_c tan(beta) / R) + dr_k along r (the runout's share at that moment, h_c the
// contact's height above the tip, beta the helix angle) and by da_k along -a. So its
// arc lies lower by dz_k and further along the feed by sigma_k:
//     dz_k = q_k sin(lambda) + da_k cos(lambda),
//     sigma_k = q_k cos(lambda) - da_k sin(lambda),
//     position_k = z fz psi_k / (2 pi) + sigma_k,
// and the surface is the lower envelope of these arcs (analysis/tooth_mark_envelope.h):
// which teeth cut, the marks' peak-to-valley (exact for the circles, and for their
// parabolas). Two flutes with runout at phase 0: dz = 2 rho_run sin(lambda), sigma =
// 2 rho_run cos(lambda), and the higher tooth still cuts iff
//     dz < (fz - sigma)(fz + sigma) / (2 rho_f)   (parabolas),
// whose equality gives the threshold
//     rho* = (-rho_f sin(lambda) + sqrt(rho_f^2 sin^2(lambda) + fz^2 cos^2(lambda)))
//            / (2 cos^2(lambda))  ~  fz^2 / (4 rho_f sin(lambda)).
#pragma once

#include <string>
#include <vector>

#include "analysis/tooth_mark_envelope.h"
#include "sweep/cutter.h"

namespace scallop {

// h = rho - sqrt(rho^2 - chord^2 / 4): a circular arc's height over its chord, mm.
double circularMarkHeight(double profileRadiusMm, double chordMm);

// The arcs' positions along the feed and depths (above), mm, for one revolution.
std::vector<ToothMark> toothMarks(const CutterTeeth& teeth, double cutterRadiusMm,
                                  double contactHeightMm, double leadRad, double fz);

// rho*, mm, for the feed-direction profile radius rho_f, lead (deg) and fz (mm).
double runoutThreshold(double profileRadiusMm, double leadDeg, double feedPerToothMm);

struct FeedMarkPrediction {
  bool applicable = false;
  std::string reason;          // why not; empty when applicable
  double profileRadiusMm = 0;  // rho_f
  // Mean, between marks: z fz / (the teeth whose valleys are at least
  // kFeedMarkHysteresis of the peak-to-valley deep: the valleys that measureFeedMarks
  // counts; a tooth that barely cuts leaves a dip it does not).
  double spacingMm = 0;
  double heightMm = 0;                 // peak-to-valley of the circles' envelope
  double heightParabolaMm = 0;         // the same for the parabolas: spacing^2 / (8 rho_f)
                                       // without tooth errors
  std::vector<int> cuttingTeeth;       // whose arcs reach the surface
  std::vector<double> valleyDepthsMm;  // theirs, below the lower cusp beside each
  bool hasRunoutThreshold = false;     // 2 flutes
  double runoutThresholdMm = 0;        // rho*
  std::string regime;  // "no runout" (no tooth errors), "both teeth cut", "all teeth cut",
                       // "one tooth cuts", "N of M teeth cut"
};

// The feed marks `cutter` (its teeth: flutes, helix, runout, pitch, offsets, edge spans:
// a tooth whose span misses the contact leaves no mark; one whose span ends within the
// marks gives a reason instead) leaves along the
// centre line of a pass at `leadDeg`, `tiltDeg` with fz = `feedPerToothMm` (> 0).
FeedMarkPrediction predictFeedMarks(const Cutter& cutter, double leadDeg, double tiltDeg,
                                    double feedPerToothMm);

}  // namespace scallop
