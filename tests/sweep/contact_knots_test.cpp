// Determinism of the rim contact's starts (sweep/contact_knots.h) and of the heights
// they lead to: contactStart(id, spacing, cutter, curve, x, y) is claimed to depend on
// the move's geometry, the knots' spacing and (x, y) alone, whatever the calling
// thread's knot cache held before, and so SweptMove::lowestPoint gives the same bits in
// any order, on any thread, for any copy of a move. Also what a start is: the contacts
// located at the four surrounding knots of the lattice (rim_contact.h from its default
// start) and how they move with the line, blended to second order; and the spacing a
// scene picks (contactKnotSpacingFor).
#include "sweep/contact_knots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <random>
#include <thread>
#include <vector>

#include "base/constants.h"
#include "sweep/pose_curve.h"
#include "sweep/rim_contact.h"
#include "sweep/swept_move.h"

namespace scallop {
namespace {

uint64_t bits(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

struct Move {
  uint64_t id;  // one for each move and spacing
  double spacing;
  Cutter cutter;
  PoseCurve curve;
};

// The spacings the moves cycle through: the default 1/64 mm, a fine and a coarse one.
constexpr double kSpacings[] = {kContactKnotSpacing, 1.0 / 256, 1.0 / 16};

// Turning moves of several kinds: CAM-like leaned bulls turning a little, a ball, a bull
// turning by 40 degrees on a ramp, one standing still while it turns; tips on both sides
// of the origin so that knots have negative indices too.
std::vector<Move> someMoves(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Move> out;
  for (int k = 0; k < count; ++k) {
    const CutterType type = k % 3 == 1 ? CutterType::Ball : CutterType::Bull;
    const double R = 2 + u(rng);
    const Cutter cutter = Cutter::make(type, R, R * (0.4 + 0.2 * u(rng)), 4 * R);
    const Vec3 a0 = normalize(Vec3{0.2 * u(rng), 0.2 * u(rng), 1});
    const double turn = k % 4 == 2 ? 0.7 : 0.02 * (1 + u(rng));
    const Vec3 w = normalize(cross(a0, Vec3{u(rng), u(rng), u(rng)}));
    const Vec3 a1 = a0 * std::cos(turn) + cross(w, a0) * std::sin(turn);
    const Vec3 p0{3 * u(rng), 3 * u(rng), 0.5 * u(rng)};
    const Vec3 p1 = k % 4 == 3 ? p0 : p0 + Vec3{2 * u(rng), 2 * u(rng), k % 4 == 2 ? 0.5 : 0.0};
    out.push_back(
        {newContactKnotsId(), kSpacings[k % 3], cutter, PoseCurve::linear({p0, a0}, {p1, a1})});
  }
  return out;
}

struct Query {
  int move;
  double x, y;
};

// Points around each move's tip path: random ones, exact knots (i h) and points on cell
// edges, out to beyond the cutter (where knots have no contact).
std::vector<Query> queriesFor(const std::vector<Move>& moves, std::mt19937_64& rng, int perMove) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Query> out;
  for (int m = 0; m < int(moves.size()); ++m) {
    const PoseCurve& c = moves[size_t(m)].curve;
    const double R = moves[size_t(m)].cutter.radius;
    for (int q = 0; q < perMove; ++q) {
      const Vec3 at = c.tip(u(rng));
      double x = at.x + 1.3 * R * (2 * u(rng) - 1), y = at.y + 1.3 * R * (2 * u(rng) - 1);
      if (q % 5 == 1) x = std::round(x * 64) / 64, y = std::round(y * 64) / 64;  // a knot
      if (q % 5 == 2) x = std::round(x * 64) / 64;                               // a cell edge
      out.push_back({m, x, y});
    }
  }
  return out;
}

struct StartBits {
  uint64_t t, cs, sn;
  bool direction;
  bool operator==(const StartBits& o) const {
    return t == o.t && cs == o.cs && sn == o.sn && direction == o.direction;
  }
};

StartBits startOf(const std::vector<Move>& moves, const Query& q) {
  const Move& m = moves[size_t(q.move)];
  const RimStart s = contactStart(m.id, m.spacing, m.cutter, m.curve, q.x, q.y);
  return {bits(s.t), bits(s.cosPhi), bits(s.sinPhi), s.hasDirection};
}

// Many queries of other moves and of these moves elsewhere: every cache slot is
// overwritten several times over (2 048 cells, 4 096 knots).
void pollute(const std::vector<Move>& others, const std::vector<Move>& moves, uint64_t seed,
             int count) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < count; ++i) {
    const bool own = i % 3 == 0;
    const std::vector<Move>& set = own ? moves : others;
    const Move& m = set[size_t(i) % set.size()];
    const Vec3 at = m.curve.tip(0.5 + 0.5 * u(rng));
    contactStart(m.id, m.spacing, m.cutter, m.curve, at.x + 3 * u(rng), at.y + 3 * u(rng));
  }
}

TEST(ContactKnots, StartDependsOnTheMoveAndPointAlone) {
  std::mt19937_64 rng(64);
  const std::vector<Move> moves = someMoves(rng, 6), others = someMoves(rng, 12);
  const std::vector<Query> queries = queriesFor(moves, rng, 150);
  const size_t n = queries.size();

  // A: on a new thread, its cache fresh, in order.
  std::vector<StartBits> fresh(n);
  std::thread([&] {
    for (size_t i = 0; i < n; ++i) fresh[i] = startOf(moves, queries[i]);
  }).join();

  // B: on this thread after 20 000 queries of other moves and other points, in a random
  // order, and then again at once (a warm cache).
  pollute(others, moves, 1, 20000);
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<StartBits> polluted(n), warm(n);
  for (size_t i : order) polluted[i] = startOf(moves, queries[i]);
  for (size_t i : order) warm[i] = startOf(moves, queries[i]);

  // C: on another thread, backwards, with other queries between every two.
  std::vector<StartBits> interleaved(n);
  std::thread([&] {
    pollute(others, moves, 2, 5000);
    for (size_t k = n; k-- > 0;) {
      interleaved[k] = startOf(moves, queries[k]);
      pollute(others, moves, 3 + k, 4);
    }
  }).join();

  int differ = 0, withDirection = 0;
  for (size_t i = 0; i < n; ++i) {
    withDirection += fresh[i].direction;
    const bool same = fresh[i] == polluted[i] && fresh[i] == warm[i] && fresh[i] == interleaved[i];
    if (!same) {
      ++differ;
      ADD_FAILURE() << "start differs: move " << queries[i].move << " (" << queries[i].x << ", "
                    << queries[i].y << ")";
    }
  }
  std::printf(
      "ContactKnots starts: %zu queries (%d with a blended direction), %d differ between a fresh "
      "cache, a polluted one, a warm one and another thread\n",
      n, withDirection, differ);
  EXPECT_EQ(differ, 0);
  EXPECT_GE(withDirection, int(n) / 3);  // the blend is exercised, not only the default
}

// What a start is: where the four knots of its cell all have a contact (located from
// the default start), the second-order blend of contact_knots.cpp, recomputed here from
// the knots' contacts and sensitivities (rim_contact.h); at an inside knot, its own
// contact (to the float it is kept in); otherwise the default start. And what it is for:
// it lands much nearer the line's own contact than the plain bilinear blend of the
// knots' t, so that Newton's method mostly converges at its first evaluation.
TEST(ContactKnots, StartIsTheSecondOrderBlendOfTheSurroundingKnots) {
  std::mt19937_64 rng(65);
  const std::vector<Move> moves = someMoves(rng, 6);
  const std::vector<Query> queries = queriesFor(moves, rng, 150);
  int blended = 0, defaults = 0, atKnots = 0, compared = 0, firstStep = 0, firstStepPlain = 0;
  double worstFormula = 0, worstKnot = 0;
  for (const Query& q : queries) {
    const Move& m = moves[size_t(q.move)];
    const double h = m.spacing;
    const RimStart s = contactStart(m.id, h, m.cutter, m.curve, q.x, q.y);
    const double i = std::floor(q.x / h), j = std::floor(q.y / h);
    const double wx = q.x / h - i, wy = q.y / h - j;
    RimContact k[4];
    RimSensitivity d[4];
    bool all = true;
    double t = 0, bilinear = 0, cs = 0, sn = 0, turn = 0;
    for (int c = 0; c < 4; ++c) {
      const double kx = (i + (c & 1)) * h, ky = (j + (c >> 1)) * h;
      k[c] = locateRimContact(m.cutter, m.curve, kx, ky, {}, &d[c]);
      all = all && k[c].found;
      const double w = ((c & 1) ? wx : 1 - wx) * ((c >> 1) ? wy : 1 - wy);
      // The direction past an end: turned by phiBeyond to first order, made unit.
      const double c1 = k[c].cosPhi - k[c].sinPhi * d[c].phiBeyond;
      const double s1 = k[c].sinPhi + k[c].cosPhi * d[c].phiBeyond;
      t += w * (k[c].t + d[c].tBeyond + 0.5 * (d[c].dtdx * (q.x - kx) + d[c].dtdy * (q.y - ky)));
      bilinear += w * k[c].t;
      cs += w * c1 / std::hypot(c1, s1), sn += w * s1 / std::hypot(c1, s1);
      turn += w * 0.5 * (d[c].dphidx * (q.x - kx) + d[c].dphidy * (q.y - ky));
    }
    if (!all || std::hypot(cs, sn) <= 0.5) {
      ++defaults;
      EXPECT_FALSE(s.hasDirection) << q.x << " " << q.y;
      EXPECT_EQ(s.t, RimStart{}.t) << q.x << " " << q.y;
      continue;
    }
    ASSERT_TRUE(s.hasDirection) << q.x << " " << q.y;
    ++blended;
    EXPECT_NEAR(std::hypot(s.cosPhi, s.sinPhi), 1, 1e-12);
    // The formula, from the knots' own doubles: the start keeps them as floats (6e-8
    // relative), so within 1e-6 in t and in the direction's angle.
    const double phi = std::atan2(sn, cs) + std::atan(turn);  // turned to first order
    const double e =
        std::max(std::fabs(s.t - std::clamp(t, 0.0, 1.0)),
                 std::fabs(std::remainder(std::atan2(s.sinPhi, s.cosPhi) - phi, 2 * kPi)));
    worstFormula = std::max(worstFormula, e);
    EXPECT_LE(e, 1e-6) << q.x << " " << q.y;
    if (q.x == i * h && q.y == j * h && d[0].tBeyond == 0) {
      ++atKnots;
      const double ek = std::max({std::fabs(s.t - k[0].t), std::fabs(s.cosPhi - k[0].cosPhi),
                                  std::fabs(s.sinPhi - k[0].sinPhi)});
      worstKnot = std::max(worstKnot, ek);
      EXPECT_LE(ek, 1e-6) << q.x << " " << q.y;
    }
    // Against the line's own contact, where it and every knot lie inside the move.
    const RimContact own = locateRimContact(m.cutter, m.curve, q.x, q.y);
    bool inside = own.found && own.t > 0 && own.t < 1;
    for (const RimSensitivity& dc : d) inside = inside && dc.tBeyond == 0;
    if (!inside || (q.x == i * h && q.y == j * h)) continue;
    ++compared;
    if (locateRimContact(m.cutter, m.curve, q.x, q.y, s).iterations == 0) ++firstStep;
    RimStart plain = s;
    plain.t = bilinear;
    if (locateRimContact(m.cutter, m.curve, q.x, q.y, plain).iterations == 0) ++firstStepPlain;
  }
  std::printf(
      "ContactKnots blend: %d blended starts (%d at knots, worst %.3g from the knot's contact; "
      "worst %.3g from the formula), %d default starts; of %d inside lines, Newton converged at "
      "its first evaluation on %d (from the bilinear blend of the knots' t: %d)\n",
      blended, atKnots, worstKnot, worstFormula, defaults, compared, firstStep, firstStepPlain);
  // Both kinds of start and starts at knots were seen (measured 351, 17 and 549), and
  // the second-order start converged at once on 128 of 139 inside lines (bilinear: 44).
  EXPECT_GE(blended, 300);
  EXPECT_GE(atKnots, 10);
  EXPECT_GE(defaults, 20);
  EXPECT_GE(compared, 100);
  EXPECT_GE(firstStep, compared * 8 / 10);
  EXPECT_GE(firstStep, firstStepPlain + compared / 10);
}

// Heights through the public API: copies of a move (which share its knots' identity)
// and a new move of the same geometry and spacing (which does not) give the same bits
// whether the grid is evaluated in raster order, in a random order, or split between two
// threads in interleaved order with cutoffs above the heights. A copy given another
// spacing (a new identity) gives its own heights, the same bits on another thread, and
// within the 1e-9 mm proof gap of the first.
TEST(ContactKnots, SweptMoveHeightsAreTheSameInAnyOrderAndOnAnyThread) {
  std::mt19937_64 rng(66);
  const std::vector<Move> geometry = someMoves(rng, 4);
  std::vector<SweptMove> originals, copies, rebuilt, respaced, respacedAgain;
  for (const Move& m : geometry) {
    originals.emplace_back(m.cutter, m.curve);
    originals.back().setContactKnotSpacing(m.spacing);
    ASSERT_TRUE(originals.back().turning());
    ASSERT_EQ(originals.back().contactKnotSpacing(), m.spacing);
  }
  for (const SweptMove& m : originals) copies.push_back(m);
  for (const Move& m : geometry) {
    rebuilt.emplace_back(m.cutter, m.curve);
    rebuilt.back().setContactKnotSpacing(m.spacing);
  }
  for (size_t k = 0; k < originals.size(); ++k) {
    const double other = geometry[k].spacing == kSpacings[1] ? kSpacings[2] : kSpacings[1];
    respaced.push_back(originals[k]);
    respaced.back().setContactKnotSpacing(other);
    respacedAgain.push_back(originals[k]);
    respacedAgain.back().setContactKnotSpacing(other);
  }
  struct Point {
    int move;
    double x, y;
  };
  std::vector<Point> grid;
  for (int m = 0; m < int(originals.size()); ++m) {
    const Box3 b = originals[size_t(m)].bounds();
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 40; ++j)
        grid.push_back({m, b.min.x + (b.max.x - b.min.x) * (i + 0.5) / 40,
                        b.min.y + (b.max.y - b.min.y) * (j + 0.5) / 40});
  }
  const size_t n = grid.size();
  struct Height {
    bool hit;
    uint64_t z, t, nx, ny, nz;
    bool operator==(const Height& o) const {
      return hit == o.hit && z == o.z && t == o.t && nx == o.nx && ny == o.ny && nz == o.nz;
    }
    double height() const {
      double v;
      std::memcpy(&v, &z, sizeof v);
      return v;
    }
  };
  auto height = [&](const std::vector<SweptMove>& set, const Point& p, double cutoff) {
    const LowestPoint lp = set[size_t(p.move)].lowestPoint(p.x, p.y, nullptr, cutoff);
    return Height{lp.hit,           bits(lp.z), bits(lp.t), bits(lp.normal.x), bits(lp.normal.y),
                  bits(lp.normal.z)};
  };

  std::vector<Height> raster(n), shuffled(n), threads(n), fresh(n), other(n), otherFresh(n);
  for (size_t i = 0; i < n; ++i) raster[i] = height(originals, grid[i], HUGE_VAL);

  // A random order over the copies, with the other spacing's copies in between.
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::shuffle(order.begin(), order.end(), rng);
  for (size_t i : order) {
    shuffled[i] = height(copies, grid[i], HUGE_VAL);
    other[i] = height(respaced, grid[i], HUGE_VAL);
  }

  // Two threads taking every other point of another random order, each with cutoffs
  // just above the raster heights (a hit must stay the same hit).
  std::shuffle(order.begin(), order.end(), rng);
  auto half = [&](size_t parity) {
    for (size_t k = parity; k < n; k += 2) {
      const size_t i = order[k];
      const double cutoff = raster[i].hit ? raster[i].height() + 1e-3 : HUGE_VAL;
      threads[i] = height(k % 4 < 2 ? copies : originals, grid[i], cutoff);
    }
  };
  std::thread a(half, size_t(0)), b(half, size_t(1));
  a.join(), b.join();

  // A new thread: moves built anew (new knot identities) and the other spacing's second
  // copies, raster order.
  std::thread([&] {
    for (size_t i = 0; i < n; ++i) {
      fresh[i] = height(rebuilt, grid[i], HUGE_VAL);
      otherFresh[i] = height(respacedAgain, grid[i], HUGE_VAL);
    }
  }).join();

  int hits = 0, differ = 0, otherDiffer = 0, otherBeyondGap = 0, otherBits = 0;
  double worstOther = 0;
  for (size_t i = 0; i < n; ++i) {
    hits += raster[i].hit;
    if (!(raster[i] == shuffled[i] && raster[i] == threads[i] && raster[i] == fresh[i])) {
      ++differ;
      ADD_FAILURE() << "height differs: move " << grid[i].move << " (" << grid[i].x << ", "
                    << grid[i].y << ")";
    }
    if (!(other[i] == otherFresh[i])) {
      ++otherDiffer;
      ADD_FAILURE() << "height at the other spacing differs: move " << grid[i].move << " ("
                    << grid[i].x << ", " << grid[i].y << ")";
    }
    if (other[i].hit != raster[i].hit) {
      ++otherBeyondGap;
      ADD_FAILURE() << "hit differs between spacings: move " << grid[i].move << " (" << grid[i].x
                    << ", " << grid[i].y << ")";
    } else if (raster[i].hit) {
      const double e = std::fabs(other[i].height() - raster[i].height());
      worstOther = std::max(worstOther, e);
      otherBits += other[i].z != raster[i].z;
      if (!(e <= 1e-9)) {
        ++otherBeyondGap;
        ADD_FAILURE() << "heights of two spacings differ by " << e << ": move " << grid[i].move
                      << " (" << grid[i].x << ", " << grid[i].y << ")";
      }
    }
  }
  std::printf(
      "ContactKnots heights: %zu lines (%d hits) on 4 moves; %d differ between raster, random, "
      "two-thread interleaved and rebuilt-move orders; another spacing: %d differ between "
      "threads, %d heights not the same bits, worst %.3g mm apart, %d beyond the proof gap\n",
      n, hits, differ, otherDiffer, otherBits, worstOther, otherBeyondGap);
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(otherDiffer, 0);
  EXPECT_EQ(otherBeyondGap, 0);
  EXPECT_GE(hits, int(n) / 3);
}

// The spacing a scene picks for its cells: the power of two nearest to 8 cells, within
// [1/1024, 1/4] mm; the default where the cell spacing is not positive.
TEST(ContactKnots, SpacingIsThePowerOfTwoNearestToEightCellsOrNone) {
  std::mt19937_64 rng(67);
  std::uniform_real_distribution<double> u(std::log(1e-6), std::log(10.0));
  int checked = 0, none = 0;
  for (int k = 0; k < 2000; ++k) {
    const double cell = std::exp(u(rng));
    const double h = contactKnotSpacingFor(cell);
    const double want = 8 * cell;
    if (h == 0) {
      // No knots only where the nearest power of two would be coarser than 1/32 mm.
      EXPECT_GT(std::log2(want), -5.5 - 1e-12) << cell;
      ++none;
      continue;
    }
    int e = 0;
    ASSERT_EQ(std::frexp(h, &e), 0.5) << cell;  // a power of two
    ASSERT_GE(h, 1.0 / 1024) << cell;
    ASSERT_LE(h, 1.0 / 32) << cell;
    if (want > 1.0 / 1024) {
      // Nearest in the ratio: within a factor sqrt(2) (to rounding) of 8 cells.
      EXPECT_LE(std::fabs(std::log2(h / want)), 0.5 + 1e-12) << cell;
      ++checked;
    } else {
      EXPECT_EQ(h, 1.0 / 1024) << cell;
    }
  }
  EXPECT_EQ(contactKnotSpacingFor(0), kContactKnotSpacing);
  EXPECT_EQ(contactKnotSpacingFor(-1), kContactKnotSpacing);
  EXPECT_EQ(contactKnotSpacingFor(std::nan("")), kContactKnotSpacing);
  EXPECT_EQ(contactKnotSpacingFor(0.002), 1.0 / 64);  // the default job's cells: 16 um
  EXPECT_EQ(contactKnotSpacingFor(0.02), 0.0);        // bench --quick's B3: no knots
  EXPECT_GE(checked, 200);
  EXPECT_GE(none, 200);
}

}  // namespace
}  // namespace scallop
