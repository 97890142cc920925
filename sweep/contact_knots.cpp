// The knots' contacts and their per-thread cache.
//
// A knot (i, j) of a move holds the rim contact (t, rim direction) of the vertical line
// through (i h, j h), h the move's knot spacing, located from the default start, and how
// that contact moves with the line (RimSensitivity, rim_contact.h). A line through
// (x, y) with i h <= x < (i + 1) h, j h <= y < (j + 1) h starts from the blend of its
// four knots: with bilinear weights w_k,
//     t = sum_k w_k (t_k + (1/2) grad t_k . (q - q_k)),
// the mean of the bilinear interpolant and of the corners' tangent planes blended alike.
// Why: along x (weights 1 - a, a at q = a h) a quadratic's bilinear interpolant is
// a (1 - a) h^2 f''/2 too high and the blended tangents are as much too low, and
// sum_k w_k (q - q_k) = 0 makes the tangents exact on x y; so the start is exact for
// quadratics, its error O(h^3) instead of bilinear's O(h^2), and Newton's method mostly
// converges at its first evaluation. The rim direction is blended as a vector, then
// turned by the same half-weighted tangents' angle.
// Every value here is a function of the move and the knot, and the cache only saves
// locating it again: whether an entry was there, or was evicted by another thread's
// order of work, cannot change a start, hence a height.
#include "sweep/contact_knots.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

namespace scallop {

namespace {

// Direct-mapped caches by (move, i, j). Cells: the cell [i, i + 1) x [j, j + 1) (in
// units of h) with what its starts need of its four corner knots, as floats (a start
// needs no more, and the rounding is the same on every thread), 96 bytes, so a line
// costs one lookup; 2048 entries hold the cells of every move a region of cells asks about.
// With corners k = a + 2 b at (i + a, j + b), local coordinates (wx, wy) in [0, 1)^2 and
// tx_k = (h/2) dt/dx there, the start's sum over the corners is
//     t = bilinear(t_k) + wx (1 - wx) ((1 - wy) (tx_0 - tx_1) + wy (tx_2 - tx_3))
//                       + wy (1 - wy) ((1 - wx) (ty_0 - ty_2) + wx (ty_1 - ty_3)),
// since w_k (q - q_k).x / h is wx (1 - wx) times (1 - wy) or wy, with the sign of a = 0;
// the same for phi. A cell keeps those differences.
struct KnotCell {
  uint64_t id;  // 0: empty
  int32_t i, j;
  float t[4], cs[4], sn[4];  // at the corners; t NaN: none
  float dtx[2], dty[2];      // tx_0 - tx_1, tx_2 - tx_3; ty_0 - ty_2, ty_1 - ty_3
  float dpx[2], dpy[2];      // the same for phi
};
static_assert(sizeof(KnotCell) == 96, "a cell in 96 bytes");

// Knots themselves, 48 bytes each, by (move, i, j): each is located once however many of
// its four cells are asked for.
struct Knot {
  uint64_t id;  // 0: empty
  int32_t i, j;
  float t, cs, sn;       // t NaN: no contact
  float tx, ty, px, py;  // h/2 times the derivatives of t and phi in x and y
};

uint64_t slotHash(uint64_t id, int32_t i, int32_t j) {
  uint64_t h = id * 0x9E3779B97F4A7C15ull ^ uint64_t(uint32_t(i)) * 0xC2B2AE3D27D4EB4Full ^
               uint64_t(uint32_t(j)) * 0x165667B19E3779F9ull;
  return h ^ (h >> 29);
}

struct KnotCache {
  static constexpr size_t kCells = 2048, kKnots = 4096;
  alignas(64) std::array<KnotCell, kCells> cells;
  alignas(64) std::array<Knot, kKnots> knots;

  const Knot& knot(uint64_t id, int32_t i, int32_t j, double h, const Cutter& cutter,
                   const PoseCurve& curve) {
    Knot& k = knots[slotHash(id, i, j) & (kKnots - 1)];
    if (k.id != id || k.i != i || k.j != j) {
      RimSensitivity d;
      const RimContact rim = locateRimContact(cutter, curve, double(i) * h, double(j) * h, {}, &d);
      k.id = id, k.i = i, k.j = j;
      // At a move's end, the smooth extension's minimum past it (RimSensitivity).
      k.t = rim.found ? float(rim.t + d.tBeyond) : std::numeric_limits<float>::quiet_NaN();
      const double cs = rim.cosPhi - rim.sinPhi * d.phiBeyond;
      const double sn = rim.sinPhi + rim.cosPhi * d.phiBeyond, n = std::hypot(cs, sn);
      k.cs = float(cs / n), k.sn = float(sn / n);
      const double half = 0.5 * h;
      k.tx = float(half * d.dtdx), k.ty = float(half * d.dtdy);
      k.px = float(half * d.dphidx), k.py = float(half * d.dphidy);
    }
    return k;
  }
  const KnotCell& cell(uint64_t id, int32_t i, int32_t j, double h, const Cutter& cutter,
                       const PoseCurve& curve) {
    KnotCell& c = cells[slotHash(id, i, j) & (kCells - 1)];
    if (c.id != id || c.i != i || c.j != j) {
      c.id = id, c.i = i, c.j = j;
      float tx[4], ty[4], px[4], py[4];
      for (int k = 0; k < 4; ++k) {
        const Knot& corner = knot(id, i + (k & 1), j + (k >> 1), h, cutter, curve);
        c.t[k] = corner.t, c.cs[k] = corner.cs, c.sn[k] = corner.sn;
        tx[k] = corner.tx, ty[k] = corner.ty, px[k] = corner.px, py[k] = corner.py;
      }
      c.dtx[0] = tx[0] - tx[1], c.dtx[1] = tx[2] - tx[3];
      c.dty[0] = ty[0] - ty[2], c.dty[1] = ty[1] - ty[3];
      c.dpx[0] = px[0] - px[1], c.dpx[1] = px[2] - px[3];
      c.dpy[0] = py[0] - py[2], c.dpy[1] = py[1] - py[3];
    }
    return c;
  }
};

std::atomic<uint64_t> nextId{1};

}  // namespace

uint64_t newContactKnotsId() {
  return nextId.fetch_add(1, std::memory_order_relaxed);
}

double contactKnotSpacingFor(double cellSpacing) {
  if (!(cellSpacing > 0)) return kContactKnotSpacing;
  const int e = int(std::lround(std::log2(8 * cellSpacing)));
  // Knots farther apart give starts too poor to pay for themselves: on B3 at 20 um cells
  // (knots 1/8 mm apart) castZMap ran 29 % more instructions with them than without.
  return e <= -5 ? std::ldexp(1.0, std::max(e, -10)) : 0.0;
}

RimStart contactStart(uint64_t id, double spacing, const Cutter& cutter, const PoseCurve& curve,
                      double x, double y) {
  // Trivially constructed (zeros: every entry empty), so no guard on each access.
  thread_local KnotCache cache;
  const double u = x / spacing, v = y / spacing;
  RimStart start;
  if (!(spacing > 0)) return start;                               // no knots
  if (!(std::fabs(u) < 1e9 && std::fabs(v) < 1e9)) return start;  // beyond 15 km
  // floor() without a library call (|w| < 1e9 here).
  const auto floorOf = [](double w) { return int32_t(w) - (w < double(int32_t(w))); };
  const int32_t i = floorOf(u), j = floorOf(v);
  const KnotCell& cell = cache.cell(id, i, j, spacing, cutter, curve);
  const double wx = u - i, wy = v - j, bx = wx * (1 - wx), by = wy * (1 - wy);
  auto bilinear = [&](const float* f) {
    const double lo = f[0] + wx * (double(f[1]) - f[0]), hi = f[2] + wx * (double(f[3]) - f[2]);
    return lo + wy * (hi - lo);
  };
  auto tangents = [&](const float* dx, const float* dy) {
    return bx * (dx[0] + wy * (double(dx[1]) - dx[0])) +
           by * (dy[0] + wx * (double(dy[1]) - dy[0]));
  };
  const double t = bilinear(cell.t) + tangents(cell.dtx, cell.dty);
  const double cs = bilinear(cell.cs), sn = bilinear(cell.sn);
  const double turn = tangents(cell.dpx, cell.dpy);
  const double n = std::sqrt(cs * cs + sn * sn);
  // A corner without a contact (NaN), or corners whose rim directions disagree: no blend.
  if (!(std::isfinite(t) && n > 0.5)) return start;
  // The blended direction turned by `turn` (radians, small: to first order, then unit).
  const double c1 = cs - sn * turn, s1 = sn + cs * turn, n1 = std::sqrt(c1 * c1 + s1 * s1);
  start.t = std::clamp(t, 0.0, 1.0), start.hasDirection = true;
  start.cosPhi = c1 / n1, start.sinPhi = s1 / n1;
  return start;
}

}  // namespace scallop
