#include "tools/render/render_camera.h"

#include <algorithm>
#include <cmath>

#include "base/constants.h"

namespace scallop {

Vec3 towards(const Direction& d) {
  const double az = d.azimuthDeg * kRadPerDeg, el = d.elevationDeg * kRadPerDeg;
  return {std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el)};
}

Camera::Camera(const Direction& view, Projection projection, const std::array<Vec3, 8>& corners,
               int widthPx, int heightPx)
    : projection_(projection) {
  const double az = view.azimuthDeg * kRadPerDeg;
  forward_ = -towards(view);
  // Horizontal and to the right of the horizontal view direction -(sin az, cos az): also
  // defined when the camera looks straight down.
  right_ = Vec3(-std::cos(az), std::sin(az), 0);
  up_ = cross(right_, forward_);
  Vec3 lo = corners[0], hi = corners[0];
  for (const Vec3& c : corners) {
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
    hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
  }
  centre_ = (lo + hi) * 0.5;
  const double radius = std::max(length(hi - lo) * 0.5, 1e-12);
  distance_ = 2.5 * radius;
  eye_ = centre_ - forward_ * distance_;

  // The corners' extent on the picture plane, and the scale that fits it.
  double aLo = HUGE_VAL, aHi = -HUGE_VAL, bLo = HUGE_VAL, bHi = -HUGE_VAL;
  for (const Vec3& c : corners) {
    const auto [a, b] = planeOf(c);
    aLo = std::min(aLo, a), aHi = std::max(aHi, a), bLo = std::min(bLo, b), bHi = std::max(bHi, b);
  }
  const double spanA = std::max(aHi - aLo, 1e-300), spanB = std::max(bHi - bLo, 1e-300);
  scale_ = std::min(widthPx / spanA, heightPx / spanB);
  midA_ = 0.5 * (aLo + aHi), midB_ = 0.5 * (bLo + bHi);
  pxX_ = 0.5 * widthPx, pxY_ = 0.5 * heightPx;
  mmPerPx_ = projection_ == Projection::kOrthographic ? 1 / scale_ : distance_ / scale_;
}

std::array<double, 2> Camera::planeOf(const Vec3& p) const {
  if (projection_ == Projection::kOrthographic) {
    const Vec3 d = p - centre_;
    return {dot(d, right_), dot(d, up_)};
  }
  const Vec3 d = p - eye_;
  const double depth = std::max(dot(d, forward_), 1e-300);
  return {dot(d, right_) / depth, dot(d, up_) / depth};
}

Ray Camera::rayThrough(double px, double py) const {
  const double a = midA_ + (px - pxX_) / scale_, b = midB_ - (py - pxY_) / scale_;
  if (projection_ == Projection::kOrthographic)
    return {centre_ - forward_ * distance_ + right_ * a + up_ * b, forward_};
  return {eye_, normalize(forward_ + right_ * a + up_ * b)};
}

std::array<double, 2> Camera::pixelOf(const Vec3& p) const {
  const auto [a, b] = planeOf(p);
  return {pxX_ + (a - midA_) * scale_, pxY_ - (b - midB_) * scale_};
}

double Camera::mmPerPxAt(const Vec3& p) const {
  if (projection_ == Projection::kOrthographic) return mmPerPx_;
  return std::max(dot(p - eye_, forward_), 0.0) / scale_;
}

double Camera::depthOf(const Vec3& p) const {
  if (projection_ == Projection::kOrthographic) return dot(p - centre_, forward_) + distance_;
  return length(p - eye_);
}

}  // namespace scallop
