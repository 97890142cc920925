#include "tools/run/bench_cases.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/pass_section.h"
#include "base/constants.h"
#include "base/fnv1a.h"
#include "base/input_error.h"
#include "sweep/cutter_shapes.h"
#include "sweep/raster.h"
#include "sweep/swept_segment.h"
#include "tools/io/gcode_reader.h"
#include "tools/io/tool_path_file.h"

namespace scallop {

namespace {

constexpr double kStockSide = 20;        // mm, the standard cases' stock
constexpr double kQuickTeethSide = 4;    // mm, B5's stock with --quick
constexpr double kFinishingWidth = 100;  // mm, B9's stock (x; y is half of it)
constexpr double kFaceMillSide = 5;      // mm, B8's stock: surf-topo's case A2's grid

RasterSpec b1Raster() {
  RasterSpec spec;
  spec.direction = 'x';
  spec.stepOver = 0.8;
  spec.depth = 0.5;
  spec.leadDeg = 5;
  return spec;
}

// B6's taper barrel: form radius 250 mm, tip radius 2 mm, taper 10 deg (a catalogue
// tool's figures), reference diameter 8 mm (where the form arc's tangent makes the taper with
// the axis), flute length 20 mm.
Cutter b6TaperBarrel() {
  TaperBarrelShape shape;
  shape.tipRadius = 2, shape.formRadius = 250, shape.taperDeg = 10;
  shape.referenceDiameter = 8, shape.fluteLength = 20;
  return cutterOfChain(CutterType::TaperBarrel, taperBarrelChain(shape, "B6"), "B6");
}

// B7's tapered ball: tip radius 1 mm, taper 5 deg per side, flute length 12 mm (B1's
// bull's 4 R). The tip radius is B1's corner radius, so at B1's 0.8 mm step-over the
// cusps (0.4 mm across the feed from each pass) lie on the tip ball, 24 deg from its
// bottom and far below the taper's tangent point at 85 deg: the tool a rib or blade
// finish would run, on B1's raster unchanged.
Cutter b7TaperBall() {
  TaperBallShape shape;
  shape.tipRadius = 1, shape.taperDeg = 5, shape.fluteLength = 12;
  return cutterOfChain(CutterType::TaperBall, taperBallChain(shape, "B7"), "B7");
}

// B3's passes are 0.5 mm apart; B6's are as far apart as leaves the same scallop on a
// plane at B3's lead (5 deg) with the taper barrel (analysis/pass_section.h, exact).
double b6PassGap(const Cutter& barrel) {
  constexpr double kB3PassGap = 0.5, kB3LeadDeg = 5;
  const Cutter bull = Cutter::make(CutterType::Bull, 3, 1);
  double scallop = 0;
  std::string reason;
  if (!PassSection::of(bull, kB3LeadDeg, 0).scallop(kB3PassGap, &scallop, &reason))
    throw InputError("--case", "B6: no scallop for B3's bull: " + reason);
  Enclosure width;
  if (!PassSection::of(barrel, kB3LeadDeg, 0).stepOver(scallop, &width))
    throw InputError("--case", "B6: the taper barrel leaves no scallop of B3's height");
  return width.low;
}

}  // namespace

const std::vector<std::string>& benchCaseNames() {
  static const std::vector<std::string> names{"B1", "B2", "B3", "B3c", "B4",
                                              "B5", "B6", "B7", "B8",  "B9"};
  return names;
}

const std::vector<std::string>& defaultBenchCaseNames() {
  static const std::vector<std::string> names{"B1", "B2", "B3", "B3c", "B4", "B5"};
  return names;
}

double finishingHeight(double x, double y) {
  return 0.3 * std::sin(x / 3) * std::sin(y / 4) - 0.5;
}

std::string finishingGcode(const Cutter& cutter, const Box3& stock, double passGap,
                           double pointGap) {
  // The passes' extent and points as B3's (freeformPasses), written as a CAM post would:
  // 4 decimals, one G1 a point, a rapid over the stock between passes.
  const double x0 = stock.min.x - cutter.radius - 1, x1 = stock.max.x + cutter.radius + 1;
  const int points = std::max(1, int(std::ceil((x1 - x0) / pointGap - 1e-9))) + 1;
  const int passes = int(std::floor((stock.max.y - stock.min.y) / passGap + 1e-9)) + 1;
  const double clear = stock.max.z + 5;
  std::string text = "(scallop bench B9: 3-axis ball finishing, passes along X)\nG21 G90 G17\n";
  text.reserve(size_t(passes) * size_t(points) * 34);
  char line[96];
  for (int k = 0; k < passes; ++k) {
    const double y = stock.min.y + k * passGap;
    std::snprintf(line, sizeof line, "G0 Z%.4f\nG0 X%.4f Y%.4f\nG0 Z%.4f\n", clear, x0, y,
                  finishingHeight(x0, y) + 1);
    text += line;
    for (int i = 0; i < points; ++i) {
      const double x = x0 + (x1 - x0) * double(i) / double(points - 1);
      std::snprintf(line, sizeof line, "G1 X%.4f Y%.4f Z%.4f\n", x, y, finishingHeight(x, y));
      text += line;
    }
  }
  text += "G0 Z" + std::to_string(clear) + "\nM30\n";
  return text;
}

double freeformHeight(double x, double y) {
  return 0.5 * std::sin(2 * kPi * x / 10) * std::cos(2 * kPi * y / 14);
}

namespace {

// The freeform paths' shared geometry: tips on the surface, the leaned normal as axis,
// passes and CL points as freeformClText's comment says.
struct FreeformPasses {
  double x0, x1;  // feed range, mm
  int points;     // CL points per pass (moves + 1)
  std::vector<double> ys;
  Vec3 tip(double x, double y) const { return {x, y, freeformHeight(x, y)}; }
  double x(int i) const { return x0 + (x1 - x0) * double(i) / double(points - 1); }
};

FreeformPasses freeformPasses(const Cutter& cutter, const Box3& stock, double passGap,
                              double pointGap) {
  FreeformPasses p;
  p.x0 = stock.min.x - cutter.radius - 1, p.x1 = stock.max.x + cutter.radius + 1;
  p.points = std::max(1, int(std::ceil((p.x1 - p.x0) / pointGap - 1e-9))) + 1;
  const int passes = int(std::floor((stock.max.y - stock.min.y) / passGap + 1e-9)) + 1;
  for (int k = 0; k < passes; ++k) p.ys.push_back(stock.min.y + k * passGap);
  return p;
}

Vec3 leanedNormal(double x, double y, double leanDeg) {
  const double lean = degToRad(leanDeg);
  // Unit normal of z = f(x, y): (-f_x, -f_y, 1) normalised.
  const double fx = 0.5 * (2 * kPi / 10) * std::cos(2 * kPi * x / 10) * std::cos(2 * kPi * y / 14);
  const double fy = -0.5 * (2 * kPi / 14) * std::sin(2 * kPi * x / 10) * std::sin(2 * kPi * y / 14);
  const Vec3 n = normalize(Vec3{-fx, -fy, 1});
  const Vec3 feed{1, 0, 0};
  const Vec3 along = normalize(feed - n * dot(feed, n));  // the feed, in the tangent plane
  return normalize(n * std::cos(lean) + along * std::sin(lean));
}

}  // namespace

std::string freeformClText(const Cutter& cutter, const Box3& stock, double passGap, double pointGap,
                           double leanDeg) {
  const FreeformPasses p = freeformPasses(cutter, stock, passGap, pointGap);
  std::string text = "# scallop bench B3: freeform 5-axis finish, x y z i j k per CL point\n";
  char line[160];
  for (double y : p.ys) {
    for (int i = 0; i < p.points; ++i) {
      const Vec3 tip = p.tip(p.x(i), y), a = leanedNormal(p.x(i), y, leanDeg);
      std::snprintf(line, sizeof line, "%.6f %.6f %.6f %.9f %.9f %.9f\n", tip.x, tip.y, tip.z, a.x,
                    a.y, a.z);
      text += line;
    }
    text += "\n";  // a pass break: the link to the next pass is a rapid
  }
  return text;
}

ToolPath makeFreeformPath(const Cutter& cutter, const Box3& stock, double passGap,
                          double moveLength, double leanDeg) {
  const FreeformPasses p = freeformPasses(cutter, stock, passGap, moveLength);
  ToolPath path;
  for (double y : p.ys) {
    for (int i = 0; i + 1 < p.points; ++i) {
      const double xa = p.x(i), xb = p.x(i + 1);
      const Vec3 axis = leanedNormal(0.5 * (xa + xb), y, leanDeg);
      Move mv;
      mv.from = {p.tip(xa, y), axis};
      mv.to = {p.tip(xb, y), axis};
      if (i == 0 && !path.moves.empty()) {  // rapid from the previous pass, not simulated
        Move rapid;
        rapid.from = path.moves.back().to;
        rapid.to = mv.from;
        rapid.rapid = true;
        path.moves.push_back(rapid);
      }
      path.moves.push_back(mv);
    }
  }
  return path;
}

namespace {

// B8, surf-topo's face-milling case A2 (cases/single/config_test_A2.json: Td 10 mm, two
// round inserts ri 5 mm, fz 0.4 mm, ap 0.4 mm, the second insert's errors eps_r -26 um
// and eps_a 9 um, its tool starting at (5, -5) and feeding along +y, tooth 1 at 90 deg,
// a 5 x 5 mm grid of 200 steps): the inserts' lowest points on a 10 mm circle (bull R 10,
// r 5, the corner arc its edge), the second insert 26 um nearer the axis and 9 um higher
// (surf-topo adds eps_a to the edge's z), the spindle counter-clockwise seen from above
// as surf-topo turns it, one pass over the grid from a cutter radius before it to one
// past it.
void b8FaceMill(BenchCase& b, double side, double coarse) {
  const double ri = 5, rb = 5;
  b.cutter = Cutter::make(CutterType::Bull, rb + ri, ri, 6);
  b.cutter.teeth = CutterTeeth::make(2, 0, 0, 0, b.cutter.radius);
  b.cutter.teeth.editEdgeSpans().assign(2, EdgeSpan{rb, rb + ri * kPi / 2});
  b.cutter.teeth.editToothOffsets() = {{0, 0}, {-0.026, -0.009}};
  b.stock.extend({0, 0, -2});
  b.stock.extend({side, side, 0});
  const Vec3 axis{0, 0, 1};
  const double r = b.cutter.radius;
  Move pass;
  pass.from = {{side, -r - 1, -0.4}, axis};
  pass.to = {{side, side + r + 1, -0.4}, axis};
  b.path.moves.push_back(pass);
  b.grid = gridCovering(0, 0, side, side, 0.025 * coarse);
  b.cutting.kind = CuttingModelKind::Teeth;
  b.cutting.feedPerTooth = 0.4;
  b.cutting.counterClockwise = true;
  // surf-topo's first edge points at gamma_f - phi = 0.6 - 90 deg from +x; counter-
  // clockwise, scallop's body angle 0 points at phi0 from +x (tooth_sweep.h).
  b.cutting.phaseDeg = 0.6 - 90;
  b.description =
      "surf-topo's face mill A2: bull R10 r5, 2 round inserts (edge_span), one -26/+9 um, "
      "fz 0.4 mm, ap 0.4 mm, CCW, 25 um";
}

}  // namespace

BenchCase makeBenchCase(const std::string& name, const BenchCaseOptions& options) {
  if (!(options.area >= 0) || !std::isfinite(options.area) ||
      (options.area > 0 && options.area < 0.1))
    throw InputError("--area", "must be a stock side >= 0.1 mm (0: the standard 20 mm)");
  const double side = options.area > 0 ? options.area : kStockSide;
  const double coarse = options.quick ? 10 : 1;

  BenchCase b;
  b.name = name;
  b.cutter = Cutter::make(CutterType::Bull, 3, 1);
  if (name == "B1" || name == "B2" || name == "B5" || name == "B7") {
    const double square = name == "B5" && options.quick ? std::min(side, kQuickTeethSide) : side;
    b.stock.extend({0, 0, -5});
    b.stock.extend({square, square, 0});
    RasterSpec spec = b1Raster();
    if (name == "B2") spec.segmentLength = 0.05;
    if (name == "B7") b.cutter = b7TaperBall();
    b.path = makeRaster(b.cutter, b.stock, spec);
    b.grid = gridCovering(0, 0, square, square, 0.001 * coarse);
    b.description = name == "B1"
                        ? "raster, bull R3 r1, lead 5 deg, step-over 0.8 mm, one move per pass"
                    : name == "B2" ? "B1 with every pass cut into 0.05 mm moves (CAM-like)"
                    : name == "B7" ? "B1's raster with a tapered ball: tip R1, taper 5 deg"
                                   : "B1 with teeth: 2 flutes, fz 0.1 mm (cutting model \"teeth\")";
    if (name == "B5") {
      b.cutting.kind = CuttingModelKind::Teeth;
      b.cutting.feedPerTooth = 0.1;
    }
  } else if (name == "B3" || name == "B3c") {
    // The surface spans z in [-0.5, 0.5]; a stock top at 0.6 mm is cut everywhere.
    b.stock.extend({0, 0, -2});
    b.stock.extend({side, side, 0.6});
    if (name == "B3") {
      b.path = parseToolPath(freeformClText(b.cutter, b.stock, 0.5, 0.05, 5), "B3 CL text");
      b.description = "freeform 5-axis CL text, axis at every point turning inside each move";
    } else {
      b.path = makeFreeformPath(b.cutter, b.stock, 0.5, 0.05, 5);
      b.description = "B3's tips with one constant axis per move (the axis jumps between moves)";
    }
    b.grid = gridCovering(0, 0, side, side, 0.002 * coarse);
  } else if (name == "B6") {
    // B3's surface and lead with a taper barrel, its passes as far apart as B3's scallop
    // allows (b6PassGap).
    b.cutter = b6TaperBarrel();
    b.stock.extend({0, 0, -2});
    b.stock.extend({side, side, 0.6});
    b.path = parseToolPath(freeformClText(b.cutter, b.stock, b6PassGap(b.cutter), 0.05, 5),
                           "B6 CL text");
    b.grid = gridCovering(0, 0, side, side, 0.002 * coarse);
    b.description = "B3's freeform 5-axis path with a taper barrel (form R250, tip R2, 10 deg)";
  } else if (name == "B4") {
    // OpenCAMLib's drop-cutter raster over the mount_rush relief (tests/data/mount_rush/
    // README.md), over its own stock as examples/mount_rush_ball.json has it.
    const std::string file = std::string(SCALLOP_DATA_DIR) + "/mount_rush/ball_raster.cl.txt";
    b.cutter = Cutter::make(CutterType::Ball, 3);
    b.path = readToolPathFile(file).path;
    b.stock.extend({-41, -25, -27});
    b.stock.extend({45, 18.5, 2});
    if (options.area > 0) {  // a square of that side at the relief's centre
      b.stock.min = {2 - 0.5 * side, -3.25 - 0.5 * side, -27};
      b.stock.max = {2 + 0.5 * side, -3.25 + 0.5 * side, 2};
    }
    b.grid =
        gridCovering(b.stock.min.x, b.stock.min.y, b.stock.max.x, b.stock.max.y, 0.01 * coarse);
    b.description = "mount_rush ball R3 drop-cutter raster (OpenCAMLib), 3-axis CAM output";
  } else if (name == "B8") {
    b8FaceMill(b, options.area > 0 ? options.area : kFaceMillSide, coarse);
  } else if (name == "B9") {
    // A 100 x 50 mm freeform part (--area A: A x A/2) finished with a ball R1: about 10^6
    // G1 lines, read through the G-code reader as a user's file would be (the reading is
    // not timed: it happens here, before simulate()).
    const double width = options.area > 0 ? options.area : kFinishingWidth;
    b.cutter = Cutter::make(CutterType::Ball, 1);
    b.stock.extend({0, 0, -5});
    b.stock.extend({width, 0.5 * width, 0});
    std::istringstream in(finishingGcode(b.cutter, b.stock, 0.1, 0.05));
    ToolPathFile file;
    readGcode(in, "B9 G-code", PathFileOptions(), file);
    b.path = std::move(file.path);
    b.grid = gridCovering(0, 0, width, 0.5 * width, 0.02 * coarse);
    b.description = "ball R1 finishing G-code, passes 0.1 mm apart, a point every 0.05 mm";
  } else {
    throw InputError("--case", "unknown case \"" + name +
                                   "\"; expected B1, B2, B3, B3c, B4, B5, B6, B7, B8 or B9");
  }
  return b;
}

GridSpec stampWindow(const BenchCase& bench, double side) {
  const double w = std::min(
      {side, bench.stock.max.x - bench.stock.min.x, bench.stock.max.y - bench.stock.min.y});
  const double cx = 0.5 * (bench.stock.min.x + bench.stock.max.x);
  const double cy = 0.5 * (bench.stock.min.y + bench.stock.max.y);
  return gridCovering(cx - 0.5 * w, cy - 0.5 * w, cx + 0.5 * w, cy + 0.5 * w, bench.grid.spacing);
}

uint64_t heightsHash(const ZMap& map) {
  Fnv1a hash;
  for (double z : map.heights()) hash.addBytesOf(z);
  return hash.value;
}

}  // namespace scallop
