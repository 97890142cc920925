#include "sweep/pose.h"

#include <cmath>

namespace scallop {

Vec3 ArcMotion::at(double t) const {
  const double theta = angle0 + sweep * t, rho = radius0 + (radius1 - radius0) * t;
  return centre + u * (rho * std::cos(theta)) + v * (rho * std::sin(theta)) +
         cross(u, v) * (rise * t);
}

Box3 ArcMotion::bounds() const {
  // |u_i cos + v_i sin| <= hypot(u_i, v_i) on every coordinate i.
  const double rho = std::fmax(radius0, radius1);
  const Vec3 n = cross(u, v), top = centre + n * rise;
  const Vec3 r{rho * std::hypot(u.x, v.x), rho * std::hypot(u.y, v.y), rho * std::hypot(u.z, v.z)};
  Box3 box;
  for (const Vec3& c : {centre, top}) box.extend(c - r), box.extend(c + r);
  return box;
}

size_t ToolPath::cuttingMoves() const {
  size_t n = 0;
  for (const Move& m : moves) n += m.rapid ? 0 : 1;
  return n;
}

ToolPath ToolPath::single(size_t k) const {
  ToolPath one;
  one.moves.push_back(moves.at(k));
  Move& m = one.moves.back();
  if (m.tool < cutters.size()) {
    one.cutters.push_back(cutters[m.tool]);
    m.tool = 0;
  }
  if (m.rotary > 0 && m.rotary <= rotary.size()) {
    one.rotary.push_back(rotary[m.rotary - 1]);
    m.rotary = 1;
  }
  if (m.arc > 0 && m.arc <= arcs.size()) {
    one.arcs.push_back(arcs[m.arc - 1]);
    m.arc = 1;
  }
  one.machine = machine;
  return one;
}

}  // namespace scallop
