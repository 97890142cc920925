// The hunt's adversarial draws and the files that state them (hunt_cases.h).
#include "hunt/hunt_cases.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "base/constants.h"

namespace scallop::hunt {

namespace {

// --- Numbers as a path file states them --------------------------------------------

// A plain decimal (G-code has no exponent), 12 decimals, trailing zeros dropped.
std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12f", v);
  std::string s = buf;
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}
// The value the file states: what both the reader and the reference start from.
double stated(double v) {
  return std::strtod(num(v).c_str(), nullptr);
}
Vec3 stated(const Vec3& v) {
  return {stated(v.x), stated(v.y), stated(v.z)};
}
// A number of the job file (JSON): every bit of it.
std::string json(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
std::string xyz(const Vec3& v, const char* sep = ",") {
  return num(v.x) + sep + num(v.y) + sep + num(v.z);
}

double radians(double deg) {
  return degToRad(deg);
}

// --- Draws --------------------------------------------------------------------------

double uniform(std::mt19937_64& rng, double a, double b) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}
int pick(std::mt19937_64& rng, int n) {
  return std::uniform_int_distribution<int>(0, n - 1)(rng);
}
Vec3 unitAcross(std::mt19937_64& rng, const Vec3& a) {
  // A random unit vector orthogonal to the unit a.
  const Vec3 helper = std::fabs(a.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalize(cross(a, helper)), v = cross(a, u);
  const double phi = uniform(rng, 0, 2 * kPi);
  return u * std::cos(phi) + v * std::sin(phi);
}
// The cosine of the angle between a move and the axis: mostly the degenerate ones.
double drawDirectionCosine(std::mt19937_64& rng) {
  static const double kCosines[] = {0, 1e-9, -1e-9, 1e-6, -1e-6, 1e-4, -1e-4};
  const int k = pick(rng, 10);
  return k < 7 ? kCosines[k] : uniform(rng, -1, 1);
}
// The axis' angle from vertical, radians: near 0, near 90 degrees, or any.
double drawTilt(std::mt19937_64& rng) {
  static const double kTilts[] = {0, 1e-9, 1e-6, 1e-3, kPi / 2 - 1e-6, kPi / 2};
  const int k = pick(rng, 9);
  return k < 6 ? kTilts[k] : uniform(rng, 0, kPi / 2);
}
double drawLength(std::mt19937_64& rng, double R, double spacing) {
  switch (pick(rng, 4)) {
    case 0: return spacing * uniform(rng, 0.01, 1);  // shorter than a cell
    case 1: return R * uniform(rng, 10, 20);        // longer than 10 R
    default: return R * uniform(rng, 0.05, 3);
  }
}

void drawCutter(std::mt19937_64& rng, HuntCase* c) {
  const double R = std::exp(uniform(rng, std::log(0.5), std::log(10.0)));
  const int type = pick(rng, 3);
  const double r = type == 0 ? R : type == 1 ? 0.0 : R * uniform(rng, 0.05, 0.95);
  const bool ownFlutes = pick(rng, 3) == 0;
  const double L = ownFlutes ? stated(std::max(r, R) * uniform(rng, 1.05, 3)) : 4 * stated(R);
  c->cutter = {stated(R), stated(r), L};
  const char* names[] = {"ball", "flat", "bull"};
  c->cutterJson = std::string("{\"type\": \"") + names[type] + "\", \"radius\": " + num(R);
  if (type == 2) c->cutterJson += ", \"corner_radius\": " + num(r);
  if (ownFlutes) c->cutterJson += ", \"flute_length\": " + num(L);
  c->cutterJson += "}";
  c->name = std::string(names[type]) + " R " + num(R) + (type == 2 ? " r " + num(r) : "");
}

// A machine's angles (degrees) for a wanted axis: xyzac-trt (sin C sin A, cos C sin A,
// cos A), xyzbc-trt (-cos C sin B, sin C sin B, cos B).
void anglesFor(bool tableAC, const Vec3& a, double* tilt, double* spin) {
  const double t = std::atan2(std::hypot(a.x, a.y), a.z);  // acos(a.z) loses tilts near 0
  *tilt = std::min(radToDeg(t), 89.999);
  *spin = radToDeg(tableAC ? std::atan2(a.x, a.y) : std::atan2(a.y, -a.x));
}

// A machine tilt turned by `turnDeg`, kept within [0, 89.999] degrees: the reader
// refuses a tool below the horizontal, and 90 itself rounds either way.
double tiltAfter(double tiltDeg, double turnDeg) {
  const double t = tiltDeg + turnDeg <= 89.999 ? tiltDeg + turnDeg : tiltDeg - turnDeg;
  return std::clamp(t, 0.0, 89.999);
}

// The interesting point the window is centred on: the tip, the corner or the rim of the
// cutter at the start, the middle or the end, or anywhere across it.
Vec3 drawAnchor(std::mt19937_64& rng, const HuntCase& c) {
  const HuntCurve& curve = c.curves.front();
  const double t = std::array<double, 3>{0, 0.5, 1}[size_t(pick(rng, 3))];
  const Vec3 a = curve.axis(t);
  const HuntCutter& k = c.cutter;
  const double radii[] = {0, k.Rb(), k.R, k.R * uniform(rng, 0, 1), k.R * (1 + 1e-7)};
  const double rho = radii[pick(rng, 5)];
  const double s = rho > k.Rb() && k.r > 0 ? k.r - std::sqrt(std::max(0.0, k.r * k.r -
                                                                      (rho - k.Rb()) * (rho - k.Rb())))
                                           : 0.0;
  return curve.tip(t) + a * s + unitAcross(rng, a) * rho;
}

}  // namespace

const char* pathKindName(PathKind kind) {
  switch (kind) {
    case PathKind::kClStraight: return "cl-straight";
    case PathKind::kClTurning: return "cl-turning";
    case PathKind::kTcpOn: return "gcode-tcp-on";
    case PathKind::kTcpOff: return "gcode-tcp-off";
    case PathKind::kArc: return "gcode-arc";
  }
  return "?";
}

std::string jobText(const HuntCase& c) {
  const double x1 = c.x0 + c.nx * c.spacing, y1 = c.y0 + c.ny * c.spacing;
  std::string job = "{\n  \"tool\": " + c.cutterJson + ",\n";
  if (!c.machineJson.empty()) job += "  \"machine\": " + c.machineJson + ",\n";
  job += "  \"stock\": {\"min\": [" + json(c.x0) + ", " + json(c.y0) + ", " + json(c.zBottom) +
         "], \"max\": [" + json(x1) + ", " + json(y1) + ", " + json(c.zTop) + "]},\n";
  job += "  \"grid\": {\"spacing\": " + json(c.spacing) + "},\n";
  job += "  \"path\": {\"file\": \"" + c.pathName + "\"}\n}\n";
  return job;
}

void writeMove(HuntCase* c) {
  MoveSpec& m = c->move;
  c->curves.clear();
  c->machineJson.clear();
  const char* machine = m.tableAC ? "xyzac-trt" : "xyzbc-trt";
  const char* rotary = m.tableAC ? " A" : " B";
  if (m.kind == PathKind::kClStraight || m.kind == PathKind::kClTurning) {
    m.p0 = stated(m.p0), m.p1 = stated(m.p1);
    m.a0 = stated(m.a0), m.a1 = stated(m.a1);
    if (m.kind == PathKind::kClStraight) m.a1 = m.a0;
    c->pathName = "move.apt";
    c->pathText = "MULTAX\nRAPID\nGOTO/" + xyz(m.p0) + "," + xyz(m.a0) + "\n";
    if (m.split) {
      const Vec3 mid = stated((m.p0 + m.p1) * 0.5);
      c->pathText += "GOTO/" + xyz(mid) + "," + xyz(m.a0) + "\n";
      c->curves.push_back(straightCurve(m.p0, mid, m.a0, m.a0));
      c->curves.push_back(straightCurve(mid, m.p1, m.a0, m.a0));
    } else {
      c->curves.push_back(straightCurve(m.p0, m.p1, m.a0, m.a1));
    }
    c->pathText += "GOTO/" + xyz(m.p1) + "," + xyz(m.a1) + "\n";
    return;
  }
  c->pathName = "move.ngc";
  c->machineJson = std::string("{\"kinematics\": \"") + machine +
                   "\", \"tcp_on\": [\"M428\"], \"tcp_off\": [\"M429\"]}";
  m.p0 = stated(m.p0), m.p1 = stated(m.p1);
  m.tilt0 = stated(m.tilt0), m.tilt1 = stated(m.tilt1);
  m.spin0 = stated(m.spin0), m.spin1 = stated(m.spin1);
  auto pose = [&](const Vec3& p, double tilt, double spin) {
    return "X" + num(p.x) + " Y" + num(p.y) + " Z" + num(p.z) + rotary + num(tilt) + " C" +
           num(spin);
  };
  std::string& g = c->pathText;
  g = "G21 G90 G94 G17\n";
  if (m.kind != PathKind::kTcpOff) g += "M428\n";
  g += "G0 " + pose(m.p0, m.tilt0, m.spin0) + "\n";
  if (m.kind == PathKind::kArc) {
    m.tilt1 = m.tilt0, m.spin1 = m.spin0;
    m.centre = stated(Vec3{m.centre.x, m.centre.y, m.p0.z});
    const Vec3 ij = stated(m.centre - m.p0);
    g += std::string(m.sweepDeg > 0 ? "G3" : "G2") + " X" + num(m.p1.x) + " Y" + num(m.p1.y) +
         " Z" + num(m.p1.z) + " I" + num(ij.x) + " J" + num(ij.y) + " F100\n";
    // The arc as the file states it: the centre the start plus I J, the end's angle.
    const Vec3 centre{m.p0.x + ij.x, m.p0.y + ij.y, m.p0.z};
    const double th0 = std::atan2(m.p0.y - centre.y, m.p0.x - centre.x);
    const double th1 = std::atan2(m.p1.y - centre.y, m.p1.x - centre.x);
    double sweep = th1 - th0;
    if (m.sweepDeg > 0 && sweep <= 0) sweep += 2 * kPi;
    if (m.sweepDeg < 0 && sweep >= 0) sweep -= 2 * kPi;
    const double rho = std::hypot(m.p0.x - centre.x, m.p0.y - centre.y);
    const Vec3 axis = hunt::rotaryCurve(m.tableAC, {}, {}, radians(m.tilt0), radians(m.tilt0),
                                        radians(m.spin0), radians(m.spin0))
                          .axis(0);
    c->curves.push_back(arcCurve(centre, rho, th0, sweep, m.p1.z - m.p0.z, axis));
  } else {
    g += "G1 " + pose(m.p1, m.tilt1, m.spin1) + " F100\n";
    if (m.kind == PathKind::kTcpOn) {
      c->curves.push_back(rotaryCurve(m.tableAC, m.p0, m.p1, radians(m.tilt0), radians(m.tilt1),
                                      radians(m.spin0), radians(m.spin1)));
    } else {
      c->curves.push_back(jointCurve(m.tableAC, m.p0, m.p1, radians(m.tilt0), radians(m.tilt1),
                                     radians(m.spin0), radians(m.spin1)));
    }
  }
  if (m.kind != PathKind::kTcpOff) g += "M429\n";
  g += "M30\n";
}

namespace {

// The move's direction and length for an axis a: at the drawn angle to it.
Vec3 drawMoveVector(std::mt19937_64& rng, const Vec3& a, double R, double spacing) {
  const double cosine = drawDirectionCosine(rng);
  const Vec3 u = unitAcross(rng, a);
  const Vec3 dir = u * std::sqrt(1 - cosine * cosine) + a * cosine;
  return dir * drawLength(rng, R, spacing);
}

void drawMove(std::mt19937_64& rng, HuntCase* c, double spacing) {
  MoveSpec& m = c->move;
  m.kind = PathKind(pick(rng, kPathKinds));
  m.tableAC = pick(rng, 2) == 0;
  const double R = c->cutter.R;
  const Vec3 origin{uniform(rng, -20, 20), uniform(rng, -20, 20), uniform(rng, -10, 10)};
  const double tilt = drawTilt(rng), azimuth = uniform(rng, 0, 2 * kPi);
  const Vec3 a{std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth),
               std::cos(tilt)};
  // Turns: none, tiny, small or large (radians).
  static const double kTurns[] = {0, 1e-9, 1e-6, 1e-3};
  const int turnKind = pick(rng, 6);
  const double turn = turnKind < 4 ? kTurns[turnKind] : uniform(rng, 0, 0.5);
  switch (m.kind) {
    case PathKind::kClStraight:
    case PathKind::kClTurning: {
      m.p0 = origin;
      m.p1 = origin + drawMoveVector(rng, a, R, spacing);
      m.a0 = a;
      Vec3 w = unitAcross(rng, a);
      if (w.z < 0) w = -w;  // turn upwards: the axis stays at or above the horizontal
      m.a1 = m.kind == PathKind::kClTurning ? a * std::cos(turn) + w * std::sin(turn) : a;
      m.split = m.kind == PathKind::kClStraight && pick(rng, 4) == 0;
      break;
    }
    case PathKind::kTcpOn:
    case PathKind::kArc: {
      anglesFor(m.tableAC, a, &m.tilt0, &m.spin0);
      m.tilt1 = tiltAfter(m.tilt0, pick(rng, 2) ? radToDeg(turn) : 0.0);
      m.spin1 = m.spin0 + (pick(rng, 2) ? radToDeg(uniform(rng, -1, 1) * turn) : 0.0);
      m.p0 = origin;
      if (m.kind == PathKind::kTcpOn) {
        m.p1 = origin + drawMoveVector(rng, a, R, spacing);
      } else {
        const double rho = R * std::exp(uniform(rng, std::log(0.2), std::log(12.0)));
        const double th0 = uniform(rng, -kPi, kPi);
        const double sweep = (pick(rng, 2) ? 1 : -1) * (pick(rng, 4) == 0 ? 1e-4 : uniform(rng, 0.05, 3));
        m.centre = origin - Vec3{rho * std::cos(th0), rho * std::sin(th0), 0};
        const double rise = pick(rng, 2) ? 0.0 : uniform(rng, -1, 1) * R;
        m.p1 = m.centre + Vec3{rho * std::cos(th0 + sweep), rho * std::sin(th0 + sweep), 0} +
               Vec3{0, 0, origin.z + rise};
        m.sweepDeg = radToDeg(sweep);
      }
      break;
    }
    case PathKind::kTcpOff: {
      // Joints: the tip's wanted motion taken back through the machine at the start
      // (with the pivot at the origin the forward kinematics is a rotation M: q = M^T tip).
      anglesFor(m.tableAC, a, &m.tilt0, &m.spin0);
      const bool turns = pick(rng, 2) == 0;
      m.tilt1 = tiltAfter(m.tilt0, turns ? radToDeg(turn) : 0.0);
      m.spin1 = m.spin0;
      const Vec3 tip1 = origin + drawMoveVector(rng, a, R, spacing);
      auto column = [&](const Vec3& e) {
        return jointCurve(m.tableAC, e, e, radians(m.tilt0), radians(m.tilt0), radians(m.spin0),
                          radians(m.spin0))
            .tip(0);
      };
      const Vec3 mx = column({1, 0, 0}), my = column({0, 1, 0}), mz = column({0, 0, 1});
      auto back = [&](const Vec3& tip) { return Vec3{dot(tip, mx), dot(tip, my), dot(tip, mz)}; };
      m.p0 = back(origin);
      m.p1 = back(tip1);
      break;
    }
  }
}

}  // namespace

HuntCase drawCase(std::mt19937_64& rng) {
  HuntCase c;
  drawCutter(rng, &c);
  // Cells of 2^-13 mm (0.12 um) up to R / 8, a power of two.
  const int kMax = int(std::floor(std::log2(c.cutter.R / 8)));
  const int k = std::max(-13, kMax - pick(rng, 14));
  c.spacing = std::ldexp(1.0, k);
  drawMove(rng, &c, c.spacing);
  writeMove(&c);
  c.name = std::string(pathKindName(c.move.kind)) + " " + c.name;
  // The window: 6 to 16 cells a side, on whole cells, about the anchor.
  const Vec3 anchor = drawAnchor(rng, c);
  c.nx = 6 + pick(rng, 11), c.ny = 6 + pick(rng, 11);
  c.x0 = (std::floor(anchor.x / c.spacing) - c.nx / 2) * c.spacing;
  c.y0 = (std::floor(anchor.y / c.spacing) - c.ny / 2) * c.spacing;
  // The stock from well below to well above everything the move can reach.
  double zLow = HUGE_VAL, zHigh = -HUGE_VAL;
  for (const HuntCurve& curve : c.curves)
    for (int i = 0; i <= 8; ++i) {
      const Vec3 tip = curve.tip(i / 8.0);
      zLow = std::min(zLow, tip.z), zHigh = std::max(zHigh, tip.z);
    }
  const double reach = c.cutter.reach() + 1;
  c.zBottom = std::floor(zLow - reach - 1);
  c.zTop = std::ceil(zHigh + reach + 1);
  return c;
}

bool makeVariant(const HuntCase& c, const std::string& kind, Variant* out) {
  const MoveSpec& m = c.move;
  const bool cl = m.kind == PathKind::kClStraight || m.kind == PathKind::kClTurning;
  HuntCase v = c;
  MoveSpec& w = v.move;
  out->mapCell = [](int i, int j) { return std::pair{i, j}; };
  if (kind == "reversed") {
    std::swap(w.p0, w.p1), std::swap(w.a0, w.a1);
    std::swap(w.tilt0, w.tilt1), std::swap(w.spin0, w.spin1);
    w.sweepDeg = -w.sweepDeg;
  } else if (kind == "split") {
    if (m.kind != PathKind::kClStraight || m.split) return false;
    w.split = true;
  } else if (kind == "rotated" || kind == "mirrored") {
    if (!cl) return false;
    const bool rotate = kind == "rotated";
    auto turn = [&](const Vec3& p) { return rotate ? Vec3{-p.y, p.x, p.z} : Vec3{-p.x, p.y, p.z}; };
    w.p0 = turn(m.p0), w.p1 = turn(m.p1), w.a0 = turn(m.a0), w.a1 = turn(m.a1);
    const int nx = c.nx, ny = c.ny;
    if (rotate) {
      v.x0 = -(c.y0 + ny * c.spacing), v.y0 = c.x0, v.nx = ny, v.ny = nx;
      out->mapCell = [ny](int i, int j) { return std::pair{j, ny - 1 - i}; };
    } else {
      v.x0 = -(c.x0 + nx * c.spacing);
      out->mapCell = [nx](int i, int j) { return std::pair{nx - 1 - i, j}; };
    }
  } else if (kind == "translated") {
    if (m.kind == PathKind::kTcpOff) return false;
    const Vec3 shift{3 * c.spacing * 64, -5 * c.spacing * 64, 2};
    w.p0 = w.p0 + shift, w.p1 = w.p1 + shift, w.centre = w.centre + shift;
    v.x0 += shift.x, v.y0 += shift.y, v.zBottom += shift.z, v.zTop += shift.z;
  } else if (kind == "gcode") {
    // The machine's tilt stays below 89.999 degrees (tiltAfter): a CL axis nearer the
    // horizontal has no G-code twin.
    if (m.kind != PathKind::kClStraight || m.split) return false;
    if (radToDeg(std::atan2(std::hypot(m.a0.x, m.a0.y), m.a0.z)) > 89.999) return false;
    w.kind = PathKind::kTcpOn;
    w.tableAC = true;
    anglesFor(true, m.a0, &w.tilt0, &w.spin0);
    w.tilt1 = w.tilt0, w.spin1 = w.spin0;
  } else {
    return false;
  }
  writeMove(&v);
  v.name = c.name + " [" + kind + "]";
  out->moved = std::move(v);
  return true;
}

}  // namespace scallop::hunt
