// Random convex cutter profiles for the tests of the general kernel: tapered balls and
// bulls, cones (sharp and flat tips), barrels / ovals / lenses (arcs of 75 to 1000 mm
// whose centres lie across the axis) and free chains, each built by walking the chain's
// tangent angle, so every arc's centre is known here, independently of
// CutterProfile::make (which finds it again from the ends and the radius).
//
// ProfileCase::width is the reference's w(s), written from the definition: on a line
// the interpolation of its ends, on an arc centre + sqrt(radius^2 - (s - centre_s)^2).
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "base/constants.h"
#include "base/vec3.h"
#include "sweep/cutter.h"
#include "sweep/cutter_profile.h"
#include "sweep/cutter_shapes.h"

namespace scallop::test {

struct ProfilePiece {
  double r0, s0, r1, s1;
  double radius = 0;      // 0: a line
  double cr = 0, cs = 0;  // an arc's centre
};

struct ProfileCase {
  std::string name;
  std::vector<ProfilePiece> pieces;

  double fluteLength() const { return pieces.back().s1; }
  // max of w over [0, L], on a fine grid plus the pieces' ends (for the reference's reach).
  double width(double s) const {
    if (!(s >= 0 && s <= fluteLength())) return 0;
    double w = 0;
    for (const ProfilePiece& p : pieces) {
      if (s < std::min(p.s0, p.s1) || s > std::max(p.s0, p.s1)) continue;
      double rho;
      if (p.s0 == p.s1)
        rho = std::max(p.r0, p.r1);
      else if (p.radius > 0)
        rho = p.cr + std::sqrt(std::max(0.0, (p.radius - (s - p.cs)) * (p.radius + (s - p.cs))));
      else
        rho = p.r0 + (p.r1 - p.r0) * (s - p.s0) / (p.s1 - p.s0);
      w = std::max(w, rho);
    }
    return w;
  }
  double maxWidth() const {
    double w = 0;
    const int n = 20000;
    for (int i = 0; i <= n; ++i) w = std::max(w, width(fluteLength() * i / n));
    for (const ProfilePiece& p : pieces) w = std::max({w, p.r0, p.r1});
    return w;
  }

  std::vector<ProfileSegment> chain() const {
    std::vector<ProfileSegment> out;
    for (const ProfilePiece& p : pieces) out.push_back({p.r0, p.s0, p.r1, p.s1, p.radius});
    return out;
  }
  Cutter cutter() const { return cutterOfChain(CutterType::Profile, chain(), "tool"); }
};

// Walks a chain from the tip: the tangent angle (from +rho towards +s) only grows.
class ChainWalk {
 public:
  explicit ChainWalk(std::string name) { c_.name = std::move(name); }
  double rho() const { return r_; }
  double s() const { return s_; }
  double angle() const { return a_; }
  void turn(double angle) { a_ = std::max(a_, angle); }
  void line(double length) {
    const double r1 = r_ + length * std::cos(a_), s1 = s_ + length * std::sin(a_);
    c_.pieces.push_back({r_, s_, r1, s1});
    r_ = r1, s_ = s1;
  }
  // A line up to height s1 (the angle must point upwards).
  void lineTo(double s1) { line((s1 - s_) / std::sin(a_)); }
  // An arc of `radius` turning the tangent to `angle` (anticlockwise about its centre).
  void arc(double radius, double angle) {
    const double cr = r_ - radius * std::sin(a_), cs = s_ + radius * std::cos(a_);
    const double r1 = cr + radius * std::sin(angle), s1 = cs - radius * std::cos(angle);
    c_.pieces.push_back({r_, s_, r1, s1, radius, cr, cs});
    r_ = r1, s_ = s1, a_ = angle;
  }
  ProfileCase done() const { return c_; }

 private:
  ProfileCase c_;
  double r_ = 0, s_ = 0, a_ = 0;
};

// Kind k % 7: tapered ball, tapered bull, cone (sharp or flat tip), barrel, lens, oval,
// free chain. Radii about 1 to 6 mm, flutes up to ~25 mm.
inline ProfileCase randomProfileCase(std::mt19937_64& rng, int k) {
  std::uniform_real_distribution<double> u(0, 1);
  auto in = [&](double a, double b) { return a + (b - a) * u(rng); };
  switch (k % 7) {
    case 0: {  // tapered ball: ball tip, flank at a half-angle
      ChainWalk w("taper_ball");
      const double rt = in(0.5, 3), taper = degToRad(in(1, 15));
      w.arc(rt, kPi / 2 - taper);
      w.lineTo(in(8, 25));
      return w.done();
    }
    case 1: {  // tapered bull: flat bottom, corner, tapered flank
      ChainWalk w("taper_bull");
      const double rb = in(0.3, 3), rc = in(0.3, 2), taper = degToRad(in(1, 20));
      w.line(rb);
      w.arc(rc, kPi / 2 - taper);
      w.lineTo(in(8, 20));
      return w.done();
    }
    case 2: {  // cone: sharp (half the time) or flat tip, then maybe a shank-side cylinder
      ChainWalk w("cone");
      const double half = degToRad(in(15, 75));
      if (u(rng) < 0.5) w.line(in(0.1, 1));
      w.turn(kPi / 2 - half);
      w.line(in(2, 6));
      if (u(rng) < 0.5) {
        w.turn(kPi / 2);
        w.line(in(2, 8));
      }
      return w.done();
    }
    case 3: {  // barrel: ball tip, then a side arc of large radius bulging out
      ChainWalk w("barrel");
      const double rt = in(0.5, 2), rf = in(75, 1000);
      w.arc(rt, degToRad(in(70, 88)));
      const double h = in(4, 15), c = std::cos(w.angle()) - h / rf;
      w.arc(rf, std::acos(std::max(-1.0, c)));
      if (w.angle() < kPi / 2 && u(rng) < 0.5) w.line(in(1, 5));
      return w.done();
    }
    case 4: {  // lens: a large tip arc centred on the axis, a corner, a flank
      ChainWalk w("lens");
      const double rl = in(75, 1000), corner = in(0.3, 1.5);
      const double first = std::min(degToRad(in(0.2, 2)), std::asin(std::min(1.0, 5.0 / rl)));
      w.arc(rl, first);
      w.arc(corner, degToRad(in(80, 90)));
      w.lineTo(w.s() + in(3, 10));
      return w.done();
    }
    case 5: {  // oval / taper barrel: tip arc, a large side arc, then a taper line
      ChainWalk w("oval");
      const double rt = in(0.5, 2.5), rf = in(75, 1000);
      w.arc(rt, degToRad(in(60, 85)));
      const double h = in(3, 10), c = std::cos(w.angle()) - h / rf;
      w.arc(rf, std::min(degToRad(89), std::acos(std::max(-1.0, c))));
      w.line(in(2, 6));
      return w.done();
    }
    default: {  // a free convex chain: lines, arcs and corners in random order
      for (;;) {
        ChainWalk w("chain");
        if (u(rng) < 0.3) w.line(in(0.2, 2));
        w.turn(degToRad(in(0, 60)));
        const int n = 2 + int(u(rng) * 5);
        bool ok = true;
        for (int i = 0; i < n && ok; ++i) {
          if (u(rng) < 0.5) {
            w.turn(std::min(degToRad(150), w.angle() + degToRad(in(0, 35))));
            w.line(in(0.3, 4));
          } else {
            const double turn = degToRad(in(3, 35));
            const double next = std::min(degToRad(150), w.angle() + turn);
            if (next <= w.angle() + 1e-3) break;
            w.arc(std::min(in(0.2, 300), 5 / (next - w.angle())), next);
          }
          ok = w.rho() > 0.3;
        }
        if (!ok) continue;
        if (w.angle() < kPi / 2 && u(rng) < 0.5) {
          w.turn(kPi / 2);
          w.line(in(1, 6));
        }
        return w.done();
      }
    }
  }
}

// A move's end from a tip at the origin, by k % 4: a level feed, a ramp, a plunge or a
// standing tip (mm).
inline Vec3 randomMoveEnd(std::mt19937_64& rng, int k) {
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  switch (k % 4) {
    case 0:
      return {6 * u(rng), 6 * u(rng), 0};
    case 1:
      return {6 * u(rng), 6 * u(rng), 4 * u(rng)};
    case 2:
      return {0, 0, 4 * u(rng)};
    default:
      return {0, 0, 0};
  }
}

// The barrel the contact-curvature and profile-move tests share, from its definition: in
// the (rho, s) half-plane a line from the tip (0, 0) to P1, the form arc of radius 250 mm
// centred at (-245, 15) (across the axis) from P1 to (5, 15), whose normals span
// -3..0 deg from +rho, and the flank rho = 5 up to s = 30.
constexpr double kBarrelFormRadius = 250, kBarrelFormCentreRho = -245, kBarrelFormCentreS = 15;
constexpr double kBarrelFormSpanDeg = 3;

// P1: where the tip's line meets the form arc, mm.
inline void barrelP1(double* rho, double* s) {
  const double span = degToRad(kBarrelFormSpanDeg);
  *rho = kBarrelFormCentreRho + kBarrelFormRadius * std::cos(span);
  *s = kBarrelFormCentreS - kBarrelFormRadius * std::sin(span);
}

// The barrel as a cutter of the general kernel.
inline Cutter barrelCutter() {
  double p1Rho = 0, p1S = 0;
  barrelP1(&p1Rho, &p1S);
  std::vector<ProfileSegment> chain(3);
  chain[0] = {0, 0, p1Rho, p1S, 0};
  chain[1] = {p1Rho, p1S, 5, 15, kBarrelFormRadius};
  chain[2] = {5, 15, 5, 30, 0};
  return cutterOfChain(CutterType::Profile, chain, "test");
}

}  // namespace scallop::test
