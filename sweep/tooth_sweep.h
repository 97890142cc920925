// ToothSweep: the cutting edges of one move, and the lowest point at which any of them
// crosses a vertical line (the "teeth" cutting model, cutting_model.h; derivation in
// tooth_sweep.cpp and docs/algorithm.md "Teeth").
//
// Frames. At pose(t) the cutter's axis a(t); the spindle frame (e1(t), e2(t), a(t)) has
// e1 = the world X axis made perpendicular to a(0) (world Y when a(0) is within 30
// degrees of X), carried with the axis's rotation (PoseCurve::carry), e2 = a x e1 when
// the spindle turns clockwise seen from the shank (M3), e2 = e1 x a counter-clockwise
// (M4): a body angle b sits at angle b - phi(t) from e1 towards e2, with
// phi(t) = phaseStart + phaseRate t (radians). Flipping e2 is the mirror image: the CCW
// move is the CW move mirrored in a vertical plane, mirrored back. Given the move
// mirrored in y = 0 (Mirror below), a CCW move is computed as exactly that: the CW
// search on the mirrored move at (x, -y), so its heights are bit for bit those of the
// mirrored CW job's cell (x, -y).
// Tooth k's edge point at height h above the tip (radius rho(h) on the profile, or on
// the flat bottom at radius rho <= Rb with h = 0), with its offsets (dr_k, da_k), is
//     tip(t) + runout (cos(psi_r - phi) e1 + sin(psi_r - phi) e2)
//            + (rho + dr_k) (cos(psi_k + h tan(beta) / R + lambda_k - phi) e1 + sin(...) e2)
//            + (h - da_k) a(t)
// with psi_k its body angle, psi_r the runout phase (CutterTeeth) and lambda_k(rho, h)
// its rake's lag (RakeLag; 0 without rake), at the nominal rho and h.
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include "sweep/cutter.h"
#include "sweep/pose_curve.h"
#include "sweep/swept_segment.h"
#include "sweep/tooth_groups.h"

namespace scallop {

class ToothSweep {
 public:
  // `cutter` carries its teeth; phi(t) = phaseStart + phaseRate t, radians. Moves whose
  // tip follows a machine's curve (TCP-off machine moves) are refused by sweepToolPath;
  // arcs are scanned as turning moves are (their envelope's height is not convex).
  // A CCW move's mirror image in y = 0: the curve as the mirrored job builds it, and for
  // a constant axis the swept envelope (lowered as sweepToolPath lowers it) whose
  // lowest point the mirrored job's search starts from.
  struct Mirror {
    PoseCurve curve;
    std::shared_ptr<const SweptSegment> envelope;
  };

  // `counterClockwise`: M4, computed on `mirror` when given (else with e2 = e1 x a on
  // `curve`: the same heights to round-off). A cutter whose teeth reach below the tip
  // (teeth.axialReach() > 0) needs a straight move with a constant axis.
  ToothSweep(const Cutter& cutter, const PoseCurve& curve, double phaseStart, double phaseRate,
             bool counterClockwise = false, const Mirror* mirror = nullptr);

  // The lowest point on the vertical line through (x, y) that an edge of the move
  // passes through, given the move's spindle-envelope height `envelope` there (a proven
  // lower bound, SweptMove::lowestPoint of the envelope cutter). A crossing at or above
  // `cutoff` may be reported as a miss; otherwise the height does not depend on it.
  LowestPoint lowestCrossing(double x, double y, const LowestPoint& envelope,
                             double cutoff = HUGE_VAL) const;

  // Tooth k's edge point at height h (on the flat bottom: h = 0 and radius rho <= Rb;
  // pass rho < 0 elsewhere to take the profile's; both nominal, before the tooth's
  // offsets), in the world, at t. For tests.
  Vec3 edgePoint(int k, double h, double rho, double t) const;

  // Searches, over all threads so far, whose halving budget ran out before every
  // interval was shown monotone (their height is still a real crossing). Tests expect
  // none on their cases.
  static unsigned long long unprovenSearches();

  const Cutter& cutter() const { return cutter_; }
  double phaseStart() const { return phaseStart_; }
  double phaseRate() const { return phaseRate_; }
  bool counterClockwise() const { return ccw_ || mirrored_; }

 private:
  struct Sample;
  using Group = ToothGroup;  // teeth with the same offsets (tooth_groups.h)
  struct Crossing {
    double z;  // the lowest crossing so far (or the cutoff), mm
    double t;
    Vec3 normal;
    int splitsLeft;  // of the search's budget of halvings
    bool unproven;   // the budget ran out before every interval was shown monotone
    double leaf;     // the shortest interval halved where the faces agree (in t)
  };
  LowestPoint clockwiseCrossing(double x, double y, const LowestPoint& envelope,
                                double cutoff) const;
  void frame(double t, Vec3& a, Vec3& e1, Vec3& e2) const;
  Sample pose(double t) const;
  double tangentBelow(const Sample* ref, double t) const;
  bool offSpanRing(const Group& g, const Sample& a, const Sample& b, double x, double y) const;
  void needEnvelope(const Group& g, Sample& s, double x, double y, const Sample* near1 = nullptr,
                    const Sample* near2 = nullptr) const;
  void needSide(const Group& g, Sample& s, int side, double x, double y,
                const Sample* near1 = nullptr, const Sample* near2 = nullptr) const;
  double exitLowerBound(const Group& g, const Vec3& tip, const Vec3& a, double shrink, double x,
                        double y) const;
  double exitBound(const Group& g, const Sample& a, const Sample& b, double x, double y) const;
  double deltaF(const Sample& a, const Sample& b, int side) const;
  double absoluteF(const Sample& s, int side) const;
  bool calm(const Sample& a, const Sample& b, int side) const;
  double envelopeBound(const Group& g, Sample& a, Sample& b, double x, double y, double best) const;
  void scanInterval(const Group& g, Sample& a, Sample& b, double x, double y, int depth,
                    Crossing& best) const;
  void solveCrossing(const Group& g, const Sample& a, const Sample& b, int side, double target,
                     double x, double y, Crossing& best) const;
  void scanGroup(const Group& g, double x, double y, double tStar, bool scanWhole,
                 Crossing& best) const;
  void keep(const Sample& s, int side, Crossing& best) const;

  Cutter cutter_;
  Cutter envelope_;            // cutter_.spindleEnvelope(), lowered by drop_ at each pose
  double drop_ = 0;            // cutter_.teeth.axialReach()
  std::vector<Group> groups_;  // the deepest-reaching first
  PoseCurve curve_;
  double phaseStart_ = 0, phaseRate_ = 0;
  bool ccw_ = false;  // counter-clockwise (M4) on curve_: e2 = e1 x a
  // Counter-clockwise, computed clockwise on the mirrored move (curve_ is the mirror's).
  bool mirrored_ = false;
  std::shared_ptr<const SweptSegment> mirroredEnvelope_;
  Vec3 axisStart_, e1Start_, e2Start_;  // the spindle frame at t = 0
  double helixSlope_ = 0;               // tan(beta) / R, rad per mm of height
  double runoutPhase_ = 0;              // psi_r, rad
  double tipSpeed_ = 0;                 // >= |tip'|, mm per unit t (tipSpeedBound)
  // The cutter translates along a line (constant axis, linear tip): the envelope's
  // height is then convex in t. Not on an arc.
  bool translates_ = false;
  bool vertical_ = false;  // translates_ with the axis along +z (a face mill)
  double reach_ = 0;       // the farthest edge point from the spindle tip, mm
};

}  // namespace scallop
