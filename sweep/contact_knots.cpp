// The knots' contacts and their per-thread cache.
//
// A knot (i, j) of a move holds the rim contact (t, rim direction) of the vertical line
// through (i h, j h), h the move's knot spacing, located from the default start; a line
// through (x, y) with i h <= x < (i + 1) h, j h <= y < (j + 1) h starts from the bilinear
// blend of its four knots. Every value here is a function of the move and the knot, and
// the cache only saves locating it again: whether an entry was there, or was evicted by
// another thread's order of work, cannot change a start, hence a height.
#include "sweep/contact_knots.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

namespace scallop {

namespace {

// Direct-mapped caches by (move, i, j). Cells: the cell [i, i + 1) x [j, j + 1) (in
// units of h) with its four corner knots, as floats (a start needs no more, and the
// rounding is the same on every thread), one 64-byte entry, so a line costs one lookup;
// 2048 entries hold the cells of every move a 64-cell tile asks about.
struct KnotCell {
  uint64_t id;  // 0: empty
  int32_t i, j;
  float t[4], cs[4], sn[4];  // corners (i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1); t NaN: none
};
static_assert(sizeof(KnotCell) == 64, "one cache line a cell");

// Knots themselves, 32 bytes each, by (move, i, j): each is located once however many of
// its four cells are asked for.
struct Knot {
  uint64_t id;  // 0: empty
  int32_t i, j;
  float t, cs, sn;  // t NaN: no contact
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
      const RimContact rim = locateRimContact(cutter, curve, double(i) * h, double(j) * h);
      k.id = id, k.i = i, k.j = j;
      k.t = rim.found ? float(rim.t) : std::numeric_limits<float>::quiet_NaN();
      k.cs = float(rim.cosPhi), k.sn = float(rim.sinPhi);
    }
    return k;
  }
  const KnotCell& cell(uint64_t id, int32_t i, int32_t j, double h, const Cutter& cutter,
                       const PoseCurve& curve) {
    KnotCell& c = cells[slotHash(id, i, j) & (kCells - 1)];
    if (c.id != id || c.i != i || c.j != j) {
      c.id = id, c.i = i, c.j = j;
      for (int k = 0; k < 4; ++k) {
        const Knot& corner = knot(id, i + (k & 1), j + (k >> 1), h, cutter, curve);
        c.t[k] = corner.t, c.cs[k] = corner.cs, c.sn[k] = corner.sn;
      }
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
  const double fi = std::floor(u), fj = std::floor(v);
  RimStart start;
  if (!(spacing > 0)) return start;                                 // no knots
  if (!(std::fabs(fi) < 1e9 && std::fabs(fj) < 1e9)) return start;  // beyond 15 km
  const int32_t i = int32_t(fi), j = int32_t(fj);
  const KnotCell& cell = cache.cell(id, i, j, spacing, cutter, curve);
  const double wx = u - fi, wy = v - fj;
  const double w[4] = {(1 - wx) * (1 - wy), wx * (1 - wy), (1 - wx) * wy, wx * wy};
  double t = 0, cs = 0, sn = 0;
  for (int k = 0; k < 4; ++k)
    t += w[k] * cell.t[k], cs += w[k] * cell.cs[k], sn += w[k] * cell.sn[k];
  const double n = std::sqrt(cs * cs + sn * sn);
  // A corner without a contact (NaN), or corners whose rim directions disagree: no blend.
  if (!(std::isfinite(t) && n > 0.5)) return start;
  start.t = t, start.hasDirection = true, start.cosPhi = cs / n, start.sinPhi = sn / n;
  return start;
}

}  // namespace scallop
