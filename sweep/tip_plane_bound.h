// TipPlaneBound: a proven lower bound of a move's heights over a rectangle of vertical
// lines from the plane of the cutter's tip, carried with the cutter as its axis turns.
//
// Every cutter lies on the upper side of the plane through its tip across its axis (its
// bottom face, for a bull or flat cutter). Where a line meets that face, the bound is
// the move's height to within E / 8 (tip_plane_bound.cpp): it follows the face as it
// turns, which the world-fixed culling planes (supporting planes of the whole swept
// solid) cannot, since a bottom face of radius Rb turning by dtheta raises them by
// about Rb dtheta (B3: ~15 um). The scene culls with it the moves that lose by microns
// where their bottom faces hover above a cell cut by another move's corner.
#pragma once

#include <algorithm>
#include <cmath>

#include "sweep/pose_curve.h"

namespace scallop {

// Two planes z = a + b x + c y, the tip planes at the move's two ends lowered by the
// turn's margin: at every (x, y) of the rectangle it was made for, no cutter of the move
// (any t in [0, 1]) has a point on the vertical line at or below the lower of the two.
struct TipPlaneBound {
  double a[2] = {-HUGE_VAL, -HUGE_VAL}, b[2] = {0, 0}, c[2] = {0, 0};
  // (No NaN arises: a is finite or -inf, b and c finite. std::min, unlike std::fmin, is
  // inlined: the branch and bound asks this for most candidates of every cell.)
  double at(double x, double y) const {
    return std::min(a[0] + b[0] * x + c[0] * y, a[1] + b[1] * x + c[1] * y);
  }
  // Its minimum over a rectangle inside the one it was made for.
  double minOver(double x0, double y0, double x1, double y1) const;
};

// The bound over [x0, x1] x [y0, y1] for any cutter shape; -inf everywhere where the
// axis may lean too far for the argument.
TipPlaneBound tipPlaneBound(const PoseCurve& curve, double x0, double y0, double x1, double y1);

}  // namespace scallop
