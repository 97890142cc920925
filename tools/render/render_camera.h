// The camera of a 3-D picture of a surface (`scallop render`, `simulate --view`): where
// it stands, what it frames, and the ray through any point of the picture.
//
// World frame: x and y as the map's (mm), z up (the exaggerated height, mm). The camera
// stands towards `towards(azimuth, elevation)` from the middle of what it frames, in the
// map makers' convention of the light (relief_shading.h): azimuth clockwise from north
// (+y) towards east (+x), elevation above the horizon. Its picture's "right" is
// horizontal, so the vertical stays vertical; seen from straight above (elevation 90)
// from azimuth 180 the picture is the map north up, like preview.png.
#pragma once

#include <array>

#include "base/vec3.h"

namespace scallop {

enum class Projection { kOrthographic, kPerspective };

// Where a camera or a light stands, degrees (azimuth clockwise from +y, elevation above
// the xy plane, in (0, 90]).
struct Direction {
  double azimuthDeg = 0, elevationDeg = 90;
};

// The unit vector from the scene towards a direction.
Vec3 towards(const Direction& d);

struct Ray {
  Vec3 origin, direction;  // direction of unit length
};

class Camera {
 public:
  Camera() = default;
  // The camera that frames the points `corners` (world, mm: a box's eight corners) in a
  // `widthPx` x `heightPx` rectangle, centred, as large as fits. A perspective camera
  // looks at the box's middle from 2.5 times its circumscribed radius (a field of view
  // of about 23 degrees over the box).
  Camera(const Direction& view, Projection projection, const std::array<Vec3, 8>& corners,
         int widthPx, int heightPx);

  // The ray through the point (px, py) of the rectangle, px from its left edge, py down
  // from its top edge, in pixels (pixel (c, r) spans [c, c + 1) x [r, r + 1)).
  Ray rayThrough(double px, double py) const;
  // Where a world point lands on the rectangle, (px, py) as rayThrough takes them.
  std::array<double, 2> pixelOf(const Vec3& p) const;
  // The distance of a world point along the view direction from the camera's plane (or
  // its eye): what decides whether it is in front of a surface hit on the same pixel.
  double depthOf(const Vec3& p) const;

  const Vec3& forward() const { return forward_; }
  // Millimetres of the world per pixel at the middle of the frame, and at a point (the
  // same for an orthographic camera; nearer points are larger in perspective).
  double mmPerPx() const { return mmPerPx_; }
  double mmPerPxAt(const Vec3& p) const;

 private:
  std::array<double, 2> planeOf(const Vec3& p) const;  // (right, up) coordinates

  Projection projection_ = Projection::kOrthographic;
  Vec3 forward_, right_, up_, centre_, eye_;
  double distance_ = 0;  // from the centre back to the eye (or the ortho origin plane)
  double scale_ = 1;     // px per plane unit
  double midA_ = 0, midB_ = 0, pxX_ = 0, pxY_ = 0;
  double mmPerPx_ = 1;
};

}  // namespace scallop
