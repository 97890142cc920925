// Normal deviation along lines in any direction (analysis/normal_deviation.h) against
// the independent brute-force reference (tests/sweep/brute_force_reference.h), for bull
// and flat cutters along arbitrary directions. Each case: a design triangle with a random
// normal n anywhere on the sphere (walls and overhangs included), straight moves with
// random constant axes on n's side, near its vertices. The reference sees the line only
// as a vertical one: the test turns the world by its own rotation taking n to +z about
// the vertex (Rodrigues, written here), and the deviation is the reference's lowest
// height of the union of the moves on that line.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "analysis/normal_deviation.h"
#include "analysis/triangle_mesh.h"
#include "base/constants.h"
#include "sweep/brute_force_reference.h"

namespace scallop {
namespace {

// The rotation taking unit n to +z: about n x z by the angle between them.
struct TurnToZ {
  Vec3 k;  // unit axis (any, when n is +-z)
  double c = 1, s = 0;
  explicit TurnToZ(const Vec3& n) {
    const Vec3 w = cross(n, Vec3{0, 0, 1});
    s = length(w), c = n.z;
    k = s > 1e-12 ? w / s : Vec3{1, 0, 0};
    if (s <= 1e-12 && c < 0) s = 0, c = -1;  // half a turn about x
  }
  Vec3 operator()(const Vec3& v) const {
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
  }
};

TEST(NormalDeviationReference, BullAndFlatAlongAnyDirection) {
  std::mt19937_64 rng(3434);
  std::uniform_real_distribution<double> u(0, 1);
  auto unit = [&] {
    const double z = 2 * u(rng) - 1, phi = 2 * kPi * u(rng), r = std::sqrt(1 - z * z);
    return Vec3{r * std::cos(phi), r * std::sin(phi), z};
  };
  int hits = 0, lines = 0;
  double worst = 0;
  for (int n = 0; n < 16; ++n) {
    const bool flat = n % 2 == 1;
    const double R = 0.8 + 1.5 * u(rng), r = flat ? 0 : (0.1 + 0.8 * u(rng)) * R;
    const Cutter cutter = Cutter::make(flat ? CutterType::Flat : CutterType::Bull, R, r, 4 * R);
    const ref::RefCutter rc =
        ref::makeRefCutter(flat ? CutterType::Flat : CutterType::Bull, R, r, 4 * R);
    // The design: one small triangle about V with normal nn.
    const Vec3 nn = unit(), V{1 + u(rng), -2 + u(rng), 0.5 * u(rng)};
    Vec3 e1 = normalize(cross(nn, std::fabs(nn.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    const Vec3 e2 = cross(nn, e1);
    const TriangleMesh design =
        meshFromTriangles({{V, V + e1 * 0.3, V + e2 * 0.3}});  // wound about nn
    ASSERT_EQ(design.triangles.size(), 1u);
    ASSERT_NEAR(dot(design.normals[0], nn), 1, 1e-12);
    // Moves: tips within the cutter's reach of the triangle, axes at most 70 deg from nn.
    ToolPath path;
    std::vector<ref::RefMove> moves;
    for (int m = 0; m < 3; ++m) {
      Vec3 a;
      do a = unit();
      while (dot(a, nn) < std::cos(degToRad(70)));
      const Vec3 p0 = V + e1 * (0.6 * R * (u(rng) - 0.5)) + e2 * (0.6 * R * (u(rng) - 0.5)) +
                      nn * (0.4 * u(rng) - 0.1);
      const Vec3 p1 = p0 + unit() * (1.5 * u(rng));
      Move move;
      move.from = {p0, a};
      move.to = {p1, a};
      path.moves.push_back(move);
      moves.push_back({p0, p1, a});
    }
    const Box3 stock{{-60, -60, -60}, {60, 60, 60}};  // its boundary is far on every line
    const double gougeDepth = 5;
    const NormalDeviation got = normalDeviation(cutter, path, stock, design, gougeDepth);
    ASSERT_EQ(got.unresolved, 0) << n;
    // The reference, the world turned so that nn is +z about each vertex.
    const TurnToZ turn(nn);
    for (size_t v = 0; v < design.vertices.size(); ++v) {
      const Vec3 P = design.vertices[v];
      std::vector<ref::RefMove> turned;
      for (const ref::RefMove& m : moves)
        turned.push_back({turn(m.start - P), turn(m.end - P), normalize(turn(m.axis))});
      const ref::RefHit want = ref::unionLowest(rc, turned, 0, 0);
      ++lines;
      ASSERT_TRUE(want.hit) << n << " " << v;  // the moves were placed to reach the line
      ASSERT_GT(want.z, -gougeDepth) << n << " " << v;
      const double w = got.deviation[v];
      worst = std::max(worst, std::fabs(w - want.z));
      EXPECT_NEAR(w, want.z, kHeightToleranceMm) << (flat ? "flat " : "bull ") << n << " " << v;
      ++hits;
    }
  }
  std::printf("NormalDeviationReference: %d lines, worst |deviation - reference| %.3g mm\n", lines,
              worst);
  EXPECT_EQ(hits, 48);
}

}  // namespace
}  // namespace scallop
