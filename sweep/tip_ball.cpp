// The ball tip of a general cutter and the bound of the rest of it: the argument is in
// tip_ball.h.
#include "sweep/tip_ball.h"

#include <algorithm>
#include <cmath>

namespace scallop {

namespace {

// mm: the ends of the tip arc and its centre must sit where a ball tip's do within this.
constexpr double kTipSlack = 1e-12;

}  // namespace

TipBall tipBallOf(const Cutter& c) {
  TipBall out;
  if (!c.general()) return out;
  const std::vector<ProfileSegment>& g = c.profile->segments();
  if (g.size() < 2) return out;
  const ProfileSegment& tip = g[0];
  const double r = tip.arcRadius;
  const double slack = kTipSlack * (1 + r);
  if (!(r > 0) || std::fabs(tip.rho0) > slack || std::fabs(tip.s0) > slack ||
      std::fabs(tip.centreRho) > slack || std::fabs(tip.centreS - r) > slack)
    return out;
  // The next segment: tangent to the ball where the arc ends, outside it (a line, or an
  // arc of radius >= r whose centre lies on the ball's radius through the join, beyond
  // the ball's centre), and reaching s = r.
  const ProfileSegment& next = g[1];
  if (!(next.s1 >= r) || !(tip.s1 <= r)) return out;
  const double jr = tip.rho1, js = tip.s1 - r;  // the join from the ball's centre
  if (next.arcRadius > 0) {
    if (!(next.arcRadius >= r)) return out;
    // The centre on the line from the join through the ball's centre, at arcRadius from
    // the join: then the two circles touch there, the larger one outside.
    const double ux = -jr / r, us = -js / r;
    const double cr = tip.rho1 + ux * next.arcRadius, cs = tip.s1 + us * next.arcRadius;
    if (!(std::hypot(next.centreRho - cr, next.centreS - cs) <= 1e-9 * (1 + next.arcRadius)))
      return out;
  } else {
    // A line through the join perpendicular to the ball's radius there.
    const double dr = next.rho1 - next.rho0, ds = next.s1 - next.s0;
    if (!(std::fabs(dr * jr + ds * js) <= 1e-9 * std::hypot(dr, ds) * r)) return out;
  }
  out.valid = true, out.radius = r, out.splitS = tip.s1, out.splitWidth = tip.rho1;
  return out;
}

Cutter tipBallCutter(const TipBall& ball) {
  return Cutter::make(CutterType::Ball, ball.radius, 0, ball.radius);
}

SweptRest::SweptRest(const Cutter& c, const TipBall& ball, const PoseCurve& curve)
    : profile_(c.profile.get()),
      ball_(ball),
      axis_(curve.axis(0.5)),
      tip0_(curve.tip(0)),
      tip1_(curve.tip(1)),
      turn_(c.profile->reach() * curve.turnRate() * 0.5),
      scale_(1 + c.profile->reach() + length(tip0_) + length(tip1_)) {
  floor_ = lowerBound({0, 0, -1}, 0, 0);
}

double SweptRest::lowerBound(const Vec3& n, double x, double y) const {
  const double nS = dot(n, axis_);
  const double nRho = length(n - axis_ * nS);
  // Directions between the tip's (-axis) and the join's normal have their support point
  // of K on the tip arc, so Rest's on its bottom disc (no search of the chain).
  const double joinS = ball_.splitS - ball_.radius;
  const bool onTipArc = ball_.splitWidth * nS - joinS * nRho <= 0;
  double hRest = nS * ball_.splitS + nRho * ball_.splitWidth;
  if (!onTipArc) {
    const ProfilePoint q = profile_->support(nRho, nS);
    if (q.s >= ball_.splitS) hRest = nRho * q.rho + nS * q.s;
  }
  const double len = length(n);
  // Round-off of the products above (the join's tangent continuity makes a support
  // point's side of it matter only to second order), scaled by n and the coordinates.
  const double slack = 1e-12 * len * (scale_ + std::fabs(x) + std::fabs(y));
  const double H = hRest + turn_ * len + std::max(dot(n, tip0_), dot(n, tip1_)) + slack;
  return (H - n.x * x - n.y * y) / n.z;
}

}  // namespace scallop
