#include "tests/support/random_cases.h"

#include "tests/sweep/machine_reference.h"

namespace scallop::test {

CutterShape randomCutterShape(std::mt19937_64& rng, int k) {
  std::uniform_real_distribution<double> u(0, 1);
  CutterShape s;
  s.radius = 1 + 4 * u(rng);
  s.type = k % 3 == 0 ? CutterType::Ball : (k % 3 == 1 ? CutterType::Flat : CutterType::Bull);
  s.cornerRadius = s.type == CutterType::Bull ? s.radius * (0.15 + 0.7 * u(rng)) : 0;
  s.fluteLength = s.radius * (2 + 3 * u(rng));
  return s;
}

MachineMove randomMachineMove(std::mt19937_64& rng, RotaryKinematics kinematics,
                              const MachineMoveRanges& r) {
  std::uniform_real_distribution<double> u(-1, 1);
  MachineMove c;
  c.machine.kinematics = kinematics;
  c.machine.pivot = {r.pivot * u(rng), r.pivot * u(rng), r.pivot * u(rng)};
  c.machine.offset = {r.offsetXY * u(rng), r.offsetXY * u(rng), r.offsetZ0 + r.offsetZ * u(rng)};
  RotaryMotion& m = c.motion;
  m.tcp = false;
  m.tilt0 = r.tilt * u(rng);
  m.tilt1 = m.tilt0 + r.tiltStep * u(rng);
  m.spin0 = r.spin * u(rng);
  m.spin1 = m.spin0 + r.spinStep * u(rng);
  m.joints0 = {r.joints * u(rng), r.joints * u(rng), r.joints * u(rng)};
  m.joints1 = m.joints0 + Vec3{r.jointStep * u(rng), r.jointStep * u(rng), r.jointStep * u(rng)};
  return c;
}

CheckedCurve jointLinearCurve(const std::string& name, const MachineMove& move) {
  const TableMachine m = move.machine;
  const RotaryMotion mo = move.motion;
  auto tilt = [=](double t) { return mo.tilt0 + (mo.tilt1 - mo.tilt0) * t; };
  auto spin = [=](double t) { return mo.spin0 + (mo.spin1 - mo.spin0) * t; };
  return {name, PoseCurve::jointLinear(m, mo),
          [=](double t) {
            return trtForward(m, mo.joints0 + (mo.joints1 - mo.joints0) * t, tilt(t), spin(t));
          },
          [=](double t) { return conventionAxis(m.kinematics, tilt(t), spin(t)); }};
}

CheckedCurve randomRotaryCurve(const std::string& name, std::mt19937_64& rng,
                               RotaryKinematics kinematics, const RotaryRanges& r) {
  std::uniform_real_distribution<double> u(-1, 1);
  const double b0 = r.tilt * u(rng), b1 = r.tiltStands ? b0 : b0 + r.tiltStep * u(rng);
  const double c0 = r.spin * u(rng), c1 = r.spinStands ? c0 : c0 + r.spinStep * u(rng);
  const Vec3 p0{u(rng), u(rng), u(rng)}, p1{2 * u(rng), 2 * u(rng), u(rng)};
  return {
      name, PoseCurve::rotary(kinematics, p0, p1, b0, b1, c0, c1),
      [=](double t) { return p0 + (p1 - p0) * t; },
      [=](double t) { return conventionAxis(kinematics, b0 + (b1 - b0) * t, c0 + (c1 - c0) * t); }};
}

}  // namespace scallop::test
