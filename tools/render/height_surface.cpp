// The level a picture traces (block means of a map) and the exact ray-patch
// intersection inside one tile of it.
#include "tools/render/height_surface.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "base/input_error.h"

namespace scallop {

SurfaceGrid::SurfaceGrid(const ZMap& map, const CellRegion& region, int k, const char* where)
    : k_(std::max(1, k)) {
  const GridSpec& g = map.grid();
  const int64_t w = region.i1 - region.i0, h = region.j1 - region.j0;
  nx_ = w / k_, ny_ = h / k_;
  if (nx_ < 2 || ny_ < 2)
    throw InputError(where, fmt::format("the region is {} x {} cells: at least 2 a side are "
                                        "needed to draw a surface",
                                        w, h));
  step_ = double(k_) * g.spacing;
  x0_ = g.cellCentreX(region.i0) + 0.5 * double(k_ - 1) * g.spacing;
  y0_ = g.cellCentreY(region.j0) + 0.5 * double(k_ - 1) * g.spacing;
  if (k_ == 1) {
    z_ = map.heights().data() + region.j0 * g.nx + region.i0;
    stride_ = g.nx;
    return;
  }
  // Block means, a row of nodes per task: each node sums its block in one fixed order.
  owned_.assign(size_t(nx_ * ny_), NAN);
  const int64_t kk = k_;
  tbb::parallel_for(
      tbb::blocked_range<int64_t>(0, ny_), [&](const tbb::blocked_range<int64_t>& rows) {
        std::vector<double> sum(static_cast<size_t>(nx_)), count(static_cast<size_t>(nx_));
        for (int64_t b = rows.begin(); b < rows.end(); ++b) {
          std::fill(sum.begin(), sum.end(), 0.0), std::fill(count.begin(), count.end(), 0.0);
          for (int64_t jj = 0; jj < kk; ++jj) {
            const double* row = map.heights().data() + (region.j0 + b * kk + jj) * g.nx + region.i0;
            for (int64_t a = 0; a < nx_; ++a)
              for (int64_t ii = 0; ii < kk; ++ii) {
                const double z = row[a * kk + ii];
                if (!std::isnan(z)) sum[size_t(a)] += z, count[size_t(a)] += 1;
              }
          }
          for (int64_t a = 0; a < nx_; ++a)
            if (count[size_t(a)] > 0)
              owned_[size_t(b * nx_ + a)] = sum[size_t(a)] / count[size_t(a)];
        }
      });
  smoothBinomial();
  z_ = owned_.data();
  stride_ = nx_;
}

// The block means are a box filter, whose side lobes let marks a little finer than a
// block through at a tenth of their height, beating with the nodes into a moiré of a few
// nodes' period; [1 2 1] / 4 along x, then along y, damps that beat (a gain of cos^2(pi f)
// at f cycles a node: 0 at the nodes' Nyquist frequency). Cells without height keep NaN
// and drop out of their neighbours' weights.
void SurfaceGrid::smoothBinomial() {
  std::vector<double> pass(owned_.size());
  auto smooth = [&](const std::vector<double>& in, std::vector<double>& out, int64_t along,
                    int64_t count, int64_t lines, int64_t lineStride) {
    tbb::parallel_for(tbb::blocked_range<int64_t>(0, lines),
                      [&](const tbb::blocked_range<int64_t>& r) {
                        for (int64_t l = r.begin(); l < r.end(); ++l)
                          for (int64_t k = 0; k < count; ++k) {
                            const size_t at = size_t(l * lineStride + k * along);
                            if (std::isnan(in[at])) {
                              out[at] = NAN;
                              continue;
                            }
                            double sum = 2 * in[at], weight = 2;
                            if (k > 0 && !std::isnan(in[at - size_t(along)]))
                              sum += in[at - size_t(along)], weight += 1;
                            if (k + 1 < count && !std::isnan(in[at + size_t(along)]))
                              sum += in[at + size_t(along)], weight += 1;
                            out[at] = sum / weight;
                          }
                      });
  };
  smooth(owned_, pass, 1, nx_, ny_, nx_);
  smooth(pass, owned_, nx_, ny_, nx_, 1);
}

std::pair<double, double> SurfaceGrid::heightRange() const {
  using Range = std::pair<double, double>;
  const Range none{HUGE_VAL, -HUGE_VAL};
  const Range r = tbb::parallel_reduce(
      tbb::blocked_range<int64_t>(0, ny_), none,
      [&](const tbb::blocked_range<int64_t>& rows, Range acc) {
        for (int64_t j = rows.begin(); j < rows.end(); ++j)
          for (int64_t i = 0; i < nx_; ++i) {
            const double z = height(i, j);
            if (!std::isnan(z))
              acc.first = std::min(acc.first, z), acc.second = std::max(acc.second, z);
          }
        return acc;
      },
      [](const Range& a, const Range& b) {
        return Range{std::min(a.first, b.first), std::max(a.second, b.second)};
      });
  return r.first <= r.second ? r : Range{NAN, NAN};
}

namespace {

// The smallest root of A s^2 + B s + C in [lo, hi], or NaN. Roots of a quadratic whose
// s^2 term is negligible over the interval are the linear term's.
double firstRoot(double A, double B, double C, double lo, double hi) {
  const double span = std::max(std::abs(lo), std::abs(hi));
  if (std::abs(A) * span * span <= 1e-14 * (std::abs(B) * span + std::abs(C))) {
    if (B == 0) return NAN;
    const double s = -C / B;
    return s >= lo && s <= hi ? s : NAN;
  }
  const double disc = B * B - 4 * A * C;
  if (disc < 0) return NAN;
  // The numerically stable pair: q / A and C / q.
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  double r1 = q / A, r2 = q != 0 ? C / q : r1;
  if (r1 > r2) std::swap(r1, r2);
  if (r1 >= lo && r1 <= hi) return r1;
  if (r2 >= lo && r2 <= hi) return r2;
  return NAN;
}

}  // namespace

PatchHit firstHitInTile(const SurfaceGrid& s, int64_t i0, int64_t j0, int64_t i1, int64_t j1,
                        const Vec3& o, const Vec3& d, double tNear, double tFar, bool anyHit) {
  // The ray's part over the tile's footprint.
  double t0 = tNear, t1 = tFar;
  auto slab = [&](double origin, double dir, double lo, double hi) {
    if (dir == 0) {
      if (origin < lo || origin > hi) t1 = -HUGE_VAL;
      return;
    }
    double a = (lo - origin) / dir, b = (hi - origin) / dir;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a), t1 = std::min(t1, b);
  };
  slab(o.x, d.x, s.nodeX(i0), s.nodeX(i1));
  slab(o.y, d.y, s.nodeY(j0), s.nodeY(j1));
  if (!(t0 <= t1)) return {};

  // The patch the ray enters by, then a 2-D DDA over the patches in the ray's order.
  const double step = s.step();
  const double mid = t0 + 0.5 * std::min(t1 - t0, 1e-9 * step);
  int64_t i =
      std::clamp<int64_t>(int64_t(std::floor((o.x + d.x * mid - s.nodeX(0)) / step)), i0, i1 - 1);
  int64_t j =
      std::clamp<int64_t>(int64_t(std::floor((o.y + d.y * mid - s.nodeY(0)) / step)), j0, j1 - 1);
  const int stepI = d.x > 0 ? 1 : d.x < 0 ? -1 : 0, stepJ = d.y > 0 ? 1 : d.y < 0 ? -1 : 0;
  auto nextX = [&] { return stepI == 0 ? HUGE_VAL : (s.nodeX(i + (stepI > 0)) - o.x) / d.x; };
  auto nextY = [&] { return stepJ == 0 ? HUGE_VAL : (s.nodeY(j + (stepJ > 0)) - o.y) / d.y; };
  const double tol = 1e-9 * (std::abs(t1) + step);
  double ta = t0;
  PatchHit best;
  while (true) {
    const double tx = nextX(), ty = nextY();
    const double tb = std::min({tx, ty, t1});
    const double z00 = s.height(i, j), z10 = s.height(i + 1, j);
    const double z01 = s.height(i, j + 1), z11 = s.height(i + 1, j + 1);
    if (!std::isnan(z00 + z10 + z01 + z11)) {
      const double w00 = s.worldZ(z00), w10 = s.worldZ(z10), w01 = s.worldZ(z01),
                   w11 = s.worldZ(z11);
      const double lo = std::min({w00, w10, w01, w11}), hi = std::max({w00, w10, w01, w11});
      const double za = o.z + d.z * ta, zb = o.z + d.z * tb;
      const double zTol = 1e-9 * (std::abs(lo) + std::abs(hi) + std::abs(za) + std::abs(zb));
      if (std::max(za, zb) >= lo - zTol && std::min(za, zb) <= hi + zTol) {
        // Local to the patch at t = ta: the height along the ray minus the patch's,
        // f(s) = C + B s + A s^2.
        const Vec3 p = o + d * ta;
        const double u0 = (p.x - s.nodeX(i)) / step, v0 = (p.y - s.nodeY(j)) / step;
        const double du = d.x / step, dv = d.y / step;
        const double b = w10 - w00, c = w01 - w00, e = w00 - w10 - w01 + w11;
        const double C = p.z - (w00 + b * u0 + c * v0 + e * u0 * v0);
        const double B = d.z - (b * du + c * dv + e * (u0 * dv + v0 * du));
        const double A = -e * du * dv;
        const double lo_s = std::max(-tol, tNear - ta), hi_s = (tb - ta) + tol;
        const double root = firstRoot(A, B, C, lo_s, hi_s);
        if (!std::isnan(root)) {
          PatchHit h;
          h.t = ta + root;
          h.i = i, h.j = j;
          h.u = std::clamp(u0 + du * root, 0.0, 1.0);
          h.v = std::clamp(v0 + dv * root, 0.0, 1.0);
          if (h.before(best)) best = h;
          if (anyHit) return best;
        }
      }
    }
    // A hit found stands unless the next patch, entered within the tolerance, has one
    // before it (a ray through a shared edge).
    if (best.found() && best.t < tb - tol) return best;
    if (tb >= t1) break;
    if (tx <= ty) {
      i += stepI;
      if (i < i0 || i >= i1) break;
    } else {
      j += stepJ;
      if (j < j0 || j >= j1) break;
    }
    ta = tb;
  }
  return best;
}

double heightAt(const SurfaceGrid& s, const PatchHit& h) {
  const double z00 = s.height(h.i, h.j), z10 = s.height(h.i + 1, h.j);
  const double z01 = s.height(h.i, h.j + 1), z11 = s.height(h.i + 1, h.j + 1);
  return z00 * (1 - h.u) * (1 - h.v) + z10 * h.u * (1 - h.v) + z01 * (1 - h.u) * h.v +
         z11 * h.u * h.v;
}

Vec3 normalAt(const SurfaceGrid& s, const PatchHit& h) {
  const double w00 = s.worldZ(s.height(h.i, h.j)), w10 = s.worldZ(s.height(h.i + 1, h.j));
  const double w01 = s.worldZ(s.height(h.i, h.j + 1)), w11 = s.worldZ(s.height(h.i + 1, h.j + 1));
  const double e = w00 - w10 - w01 + w11;
  const double dzdx = (w10 - w00 + e * h.v) / s.step(), dzdy = (w01 - w00 + e * h.u) / s.step();
  return normalize(Vec3(-dzdx, -dzdy, 1));
}

}  // namespace scallop
