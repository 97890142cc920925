#include "analysis/drop_cutter.h"

#include <algorithm>
#include <cmath>

namespace scallop {

namespace {

// The lower profile h(d) and its slope h'(d) (HUGE_VAL at the rim of a round corner).
struct Profile {
  double R, Rb, r;
  double h(double d) const {
    if (d <= Rb) return 0;
    const double e = std::min(d - Rb, r);
    return r - std::sqrt(std::max(0.0, r * r - e * e));
  }
  double slope(double d) const {
    if (d <= Rb) return 0;
    const double e = d - Rb, q = r * r - e * e;
    return q > 0 ? e / std::sqrt(q) : HUGE_VAL;
  }
};

// Best contact on the edge a-b: max of z(s) - h(d(s)) over s in [0, 1] with d <= R.
void dropOnEdge(const Profile& p, const Vec3& a, const Vec3& b, double x, double y,
                DropContact& best) {
  const double ex = b.x - a.x, ey = b.y - a.y, ez = b.z - a.z;
  const double ox = a.x - x, oy = a.y - y;
  // d(s)^2 = A s^2 + B s + C
  const double A = ex * ex + ey * ey, B = 2 * (ox * ex + oy * ey), C = ox * ox + oy * oy;
  double s0 = 0, s1 = 1;
  const double R2 = p.R * p.R;
  if (A == 0) {
    if (C > R2) return;
  } else {
    const double disc = B * B - 4 * A * (C - R2);
    if (disc < 0) return;
    const double sq = std::sqrt(disc);
    // Stable roots of the quadratic.
    const double q = -0.5 * (B + std::copysign(sq, B));
    double r0 = q / A, r1 = q != 0 ? (C - R2) / q : r0;
    if (r0 > r1) std::swap(r0, r1);
    s0 = std::max(0.0, r0), s1 = std::min(1.0, r1);
    if (s0 > s1) return;
  }
  auto dist = [&](double s) { return std::sqrt(std::max(0.0, (A * s + B) * s + C)); };
  auto value = [&](double s) { return a.z + s * ez - p.h(dist(s)); };
  // g'(s) = ez - h'(d) d'(s), d'(s) = (2 A s + B) / (2 d); g' decreases (g is concave).
  auto derivative = [&](double s) {
    const double d = dist(s), dd = d > 0 ? (2 * A * s + B) / (2 * d) : 0.0;
    const double hs = p.slope(d);
    if (dd == 0) return ez;
    return hs == HUGE_VAL ? (dd > 0 ? -HUGE_VAL : HUGE_VAL) : ez - hs * dd;
  };
  double lo = s0, hi = s1, s;
  if (derivative(lo) <= 0) {
    s = lo;
  } else if (derivative(hi) >= 0) {
    s = hi;
  } else {
    for (int k = 0; k < 200 && hi - lo > 0; ++k) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (derivative(mid) > 0 ? lo : hi) = mid;
    }
    s = value(lo) >= value(hi) ? lo : hi;
  }
  // The ends are candidates too (a rounding guard; for a concave g they never win).
  for (double t : {s, s0, s1}) {
    const double z = value(t);
    if (!best.hit || z > best.tipZ) {
      best.hit = true;
      best.tipZ = z;
      best.point = {a.x + t * ex, a.y + t * ey, a.z + t * ez};
    }
  }
}

}  // namespace

DropContact dropOnTriangle(const Cutter& cutter, const std::array<Vec3, 3>& tri, double x,
                           double y) {
  const Profile p{cutter.radius, cutter.bottomRadius(), cutter.cornerRadius};
  DropContact best;
  for (int e = 0; e < 3; ++e) dropOnEdge(p, tri[size_t(e)], tri[size_t((e + 1) % 3)], x, y, best);

  // Facet: the plane touches the cutter at its point with outward normal -n (n up):
  // on the corner torus at Rb from the axis towards -n_xy, r above the tip, minus r n.
  Vec3 n = cross(tri[1] - tri[0], tri[2] - tri[0]);
  const double len = length(n);
  if (!(len > 0)) return best;
  n = n / len;
  if (n.z < 0) n = -n;
  if (n.z <= 1e-12) return best;  // vertical: its edges hold the maximum
  const double nh = std::hypot(n.x, n.y);
  const double ux = nh > 0 ? n.x / nh : 0, uy = nh > 0 ? n.y / nh : 0;
  const double cx = x - p.Rb * ux - p.r * n.x, cy = y - p.Rb * uy - p.r * n.y;
  // Inside the triangle's xy projection (barycentric signs, edges included).
  auto side = [](const Vec3& a, const Vec3& b, double px, double py) {
    return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
  };
  const double s0 = side(tri[0], tri[1], cx, cy), s1 = side(tri[1], tri[2], cx, cy),
               s2 = side(tri[2], tri[0], cx, cy);
  const bool inside = (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
  if (!inside) return best;
  const double cz = tri[0].z - (n.x * (cx - tri[0].x) + n.y * (cy - tri[0].y)) / n.z;
  const double tipZ = cz - p.r * (1 - n.z);
  if (!best.hit || tipZ > best.tipZ) best = {true, tipZ, {cx, cy, cz}};
  return best;
}

DropCutter::DropCutter(const Cutter& cutter, const TriangleMesh& mesh)
    : cutter_(cutter), mesh_(mesh) {
  const Box3 b = mesh.bounds();
  cell_ = std::max(cutter.radius / 2, 1e-3);
  x0_ = b.min.x, y0_ = b.min.y;
  nx_ = std::max<int64_t>(1, int64_t((b.max.x - b.min.x) / cell_) + 1);
  ny_ = std::max<int64_t>(1, int64_t((b.max.y - b.min.y) / cell_) + 1);
  while (nx_ * ny_ > 4'000'000) {
    cell_ *= 2;
    nx_ = int64_t((b.max.x - b.min.x) / cell_) + 1, ny_ = int64_t((b.max.y - b.min.y) / cell_) + 1;
  }
  buckets_.resize(size_t(nx_ * ny_));
  topZ_.resize(mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto c = mesh.corners(t);
    topZ_[t] = std::max({c[0].z, c[1].z, c[2].z});
    const double lx = std::min({c[0].x, c[1].x, c[2].x}), hx = std::max({c[0].x, c[1].x, c[2].x});
    const double ly = std::min({c[0].y, c[1].y, c[2].y}), hy = std::max({c[0].y, c[1].y, c[2].y});
    for (int64_t j = int64_t((ly - y0_) / cell_); j <= int64_t((hy - y0_) / cell_); ++j)
      for (int64_t i = int64_t((lx - x0_) / cell_); i <= int64_t((hx - x0_) / cell_); ++i)
        buckets_[size_t(std::min(j, ny_ - 1) * nx_ + std::min(i, nx_ - 1))].push_back(uint32_t(t));
  }
}

DropContact DropCutter::drop(double x, double y) const {
  const double R = cutter_.radius;
  auto index = [&](double v, double v0, int64_t n) {
    return std::clamp<int64_t>(int64_t(std::floor((v - v0) / cell_)), 0, n - 1);
  };
  std::vector<uint32_t> candidates;
  if (x + R >= x0_ && y + R >= y0_)
    for (int64_t j = index(y - R, y0_, ny_); j <= index(y + R, y0_, ny_); ++j)
      for (int64_t i = index(x - R, x0_, nx_); i <= index(x + R, x0_, nx_); ++i)
        for (uint32_t t : buckets_[size_t(j * nx_ + i)]) candidates.push_back(t);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  // Highest triangles first: a contact can never be above a triangle's top vertex.
  std::sort(candidates.begin(), candidates.end(),
            [&](uint32_t a, uint32_t b) { return topZ_[a] > topZ_[b]; });
  DropContact best;
  for (uint32_t t : candidates) {
    if (best.hit && topZ_[t] <= best.tipZ) break;
    const DropContact c = dropOnTriangle(cutter_, mesh_.corners(t), x, y);
    if (c.hit && (!best.hit || c.tipZ > best.tipZ)) best = c;
  }
  return best;
}

}  // namespace scallop
