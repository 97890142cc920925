#include "tools/io/gcode_interpreter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/pose_curve.h"
#include "tools/io/gcode_arc.h"
#include "tools/io/gcode_cycles.h"
#include "tools/io/gcode_groups.h"

namespace scallop {

namespace {

double& component(Vec3& p, int i) {
  return i == 0 ? p.x : i == 1 ? p.y : p.z;
}
double component(const Vec3& p, int i) {
  return i == 0 ? p.x : i == 1 ? p.y : p.z;
}

std::string codeText(char letter, int tenths) {
  return gcodeWordText(letter, tenths / 10.0);
}

}  // namespace

GcodeInterpreter::GcodeInterpreter(const std::string& source, const PathFileOptions& options,
                                   ToolPathFile& out)
    : source_(source), options_(options), out_(out) {
  if (options_.machine) out_.path.machine = options_.machine->geometry;
}

void GcodeInterpreter::ignore(const std::string& word, const std::string& meaning) {
  out_.ignored.add(word, meaning, line_);
}

// --- Tools. ---------------------------------------------------------------------

void GcodeInterpreter::selectTool(const GcodeBlock& b, bool change) {
  const auto& tools = options_.tools;
  if (b.given('T')) {
    const double v = b.at('T');
    if (!(v >= 0 && v <= 1e9 && v == std::floor(v)))
      throw InputError(where_, fmt::format("T{:g}: expected a tool number (0, 1, 2, ...)", v));
    const int64_t n = int64_t(v);
    if (tools.empty()) {
      ignore("T", "tool select: the job has one \"tool\", which cuts every move");
    } else if (n != 0 && !tools.count(n)) {
      std::string have;
      for (const auto& [number, cutter] : tools)
        have += (have.empty() ? "" : ", ") + std::to_string(number);
      throw InputError(where_,
                       fmt::format("T{} is not in the job's \"tools\" (it has {})", n, have));
    }
    selected_ = n;
  }
  if (!change) return;
  if (tools.empty()) return ignore("M6", "tool change: the job has one \"tool\"");
  if (selected_ < 0) throw InputError(where_, "M6 (tool change) before any T word selects a tool");
  spindle_ = -1;
  if (selected_ == 0) return;  // T0 M6: the spindle is empty
  const auto& numbers = out_.toolNumbers;
  const auto it = std::find(numbers.begin(), numbers.end(), selected_);
  spindle_ = int(it - numbers.begin());
  if (it == numbers.end()) {
    if (numbers.size() >= 65535) throw InputError(where_, "more than 65535 tools in one program");
    out_.toolNumbers.push_back(selected_);
    out_.path.cutters.push_back(tools.at(selected_));
  }
}

int GcodeInterpreter::toolIndex() {
  if (options_.tools.empty()) return 0;
  if (spindle_ < 0 && options_.tools.size() == 1 && out_.toolNumbers.empty()) {
    out_.toolNumbers.push_back(options_.tools.begin()->first);
    out_.path.cutters.push_back(options_.tools.begin()->second);
    spindle_ = 0;
  }
  if (spindle_ < 0)
    throw InputError(where_, fmt::format("cutting move with no tool in the spindle: give T.. M6 "
                                         "first (the job's \"tools\" has {})",
                                         options_.tools.size()));
  return spindle_;
}

// --- Feeds. ---------------------------------------------------------------------

// Without the teeth model feeds change no geometry and are listed as ignored. With it,
// F (feed), S (rpm) and the feed mode are modal state: fz = F / (S flutes) in G94
// (F in file units per minute), F / flutes in G95 (per revolution); in G93 (inverse
// time) F depends on each move's length and no fz is read (the job's applies).
void GcodeInterpreter::feeds(const GcodeBlock& b, const GcodeGroups& g) {
  if (!options_.teeth) {
    if (b.given('F')) ignore("F", "feed rate (G93/G94/G95 feeds change no geometry)");
    if (b.given('S')) ignore("S", "spindle speed");
    if (g.feed != -1) ignore(codeText('G', g.feed), "feed mode");
    return;
  }
  if (g.feed != -1) feedMode_ = g.feed;
  if (b.given('F')) {
    feed_ = b.at('F');
    if (!(feed_ >= 0)) throw InputError(where_, fmt::format("F{:g}: a feed must be >= 0", feed_));
  }
  if (b.given('S')) {
    spindleRpm_ = b.at('S');
    if (!(spindleRpm_ >= 0))
      throw InputError(where_, fmt::format("S{:g}: a spindle speed must be >= 0 rpm", spindleRpm_));
  }
  // M3 / M4: the spindle's direction for the moves after them (Move::spindle).
  for (double m : b.m) {
    if (m == 3) spindleDirection_ = 1;
    if (m == 4) spindleDirection_ = -1;
  }
}

// The feed per tooth of a cutting move now, mm; 0 when the program gives none.
double GcodeInterpreter::feedPerTooth(int tool) const {
  if (!options_.teeth) return 0;
  const int flutes =
      options_.tools.empty() ? options_.flutes : out_.path.cutters[size_t(tool)].teeth.flutes;
  const double feed = feed_ * scale_;  // mm per minute, or per revolution in G95
  if (feedMode_ == 950) return feed / flutes;
  if (feedMode_ == 940 && spindleRpm_ > 0) return feed / (spindleRpm_ * flutes);
  return 0;
}

// --- A block. -------------------------------------------------------------------

bool GcodeInterpreter::block(const GcodeBlock& b, int64_t line) {
  where_ = source_ + ":" + std::to_string(line);
  line_ = line;
  if (b.kind == GcodeBlock::Kind::Percent) return ++percentLines_ < 2;  // the closing '%'
  if (b.kind == GcodeBlock::Kind::Empty) return true;
  GcodeGroups g = groupGcodeWords(b, options_.machine ? &*options_.machine : nullptr, where_);
  for (const auto& [word, meaning] : g.ignored)
    if (!(options_.teeth && (word == "M3" || word == "M4"))) ignore(word, meaning);
  for (const std::string& word : g.unknownM)
    out_.warnings.add(where_,
                      "M-code " + word + " ignored (machine-specific; nothing scallop simulates)");
  // In LinuxCNC's order of execution: feed, speed, tool, M words, modes, then motion.
  feeds(b, g);
  selectTool(b, g.change);
  if (g.plane != -1) plane_ = g.plane / 10;
  if (g.units != -1) {
    const double scale = g.units == 200 ? 25.4 : 1.0;
    if (scale != scale_ && firstMoveLine_ != 0)
      throw InputError(
          where_, fmt::format("mixed units: {} after moves in {} since line {}; a "
                              "file must use one unit",
                              codeText('G', g.units), scale_ == 1 ? "mm (G21)" : "inches (G20)",
                              firstMoveLine_));
    scale_ = scale;
  }
  if (g.compensation != -1) ignore("G40", "cutter compensation off (the default)");
  if (g.length != -1)
    ignore(codeText('G', g.length), "tool length compensation: Z is the tool tip already");
  if (b.given('H')) ignore("H", "tool length offset number");
  if (b.given('D')) ignore("D", "cutter radius offset number");
  if (g.tcp != -1 && (g.tcp == 1) != tcp_) {
    // X Y Z change meaning (tip or joints): they must be given again before cutting.
    tcp_ = g.tcp == 1;
    known_ = {};
  }
  if (g.offset != -1) workOffset_ = (g.offset - 540) / 10;
  if (g.pathMode == 640 && b.given('P'))
    out_.warnings.add(where_, fmt::format("G64 P{:g}: the machine may round corners by up to "
                                          "that; scallop follows the programmed path exactly",
                                          b.at('P')));
  else if (g.pathMode != -1)
    ignore(codeText('G', g.pathMode), "path control (exact stop or blending)");
  if (g.distance != -1) absolute_ = g.distance == 900;
  if (g.arcDistance != -1) arcAbsolute_ = g.arcDistance == 901;
  if (g.retract != -1) retractToInitial_ = g.retract == 980;
  if (g.nonModal == 40) ignore("G4", "dwell");
  if (g.nonModal == 280 || g.nonModal == 300)
    home(b, g.nonModal);
  else
    motion(b, g);
  if (g.end) {
    ignore(gcodeWordText('M', b.m.back()), "program end: the lines after it are not read");
    return false;
  }
  return true;
}

void GcodeInterpreter::finish() {
  if (out_.path.moves.empty())
    throw InputError(source_, "no moves found (G0/G1/G2/G3 or a drilling cycle with X, Y, Z)");
}

// --- Positions and moves. -------------------------------------------------------

GcodeInterpreter::State GcodeInterpreter::target(const GcodeBlock& b, bool machineFrame,
                                                 std::array<bool, 3>& known) const {
  State t = state_;
  known = known_;
  const Vec3& offset = options_.workOffsets[size_t(workOffset_)];
  for (int a = 0; a < 3; ++a) {
    const char letter = "XYZ"[a];
    if (!b.given(letter)) continue;
    const double v = b.at(letter) * scale_;
    double& c = component(t.pos, a);
    if (machineFrame) {
      c = v;
    } else if (absolute_) {
      c = v + component(offset, a);
    } else {
      if (!known_[size_t(a)])
        throw InputError(where_,
                         fmt::format("incremental {} (G91) from an unknown position", letter));
      c += v;
    }
    known[size_t(a)] = true;
  }
  const bool bc =
      options_.machine && options_.machine->geometry.kinematics == RotaryKinematics::TableBC;
  const char tiltLetter = bc ? 'B' : 'A';
  for (char letter : {'A', 'B', 'C'}) {
    if (!b.given(letter)) continue;
    if (!options_.machine)
      throw InputError(where_, fmt::format("rotary word {}{:g}: the job has no \"machine\" "
                                           "(5-axis kinematics, CONVENTIONS.md \"Machines\")",
                                           letter, b.at(letter)));
    if (letter != 'C' && letter != tiltLetter)
      throw InputError(where_, fmt::format("rotary word {}: the machine ({}) has axes {} and C",
                                           letter, bc ? "xyzbc-trt" : "xyzac-trt", tiltLetter));
    const double radians = degToRad(b.at(letter));
    double& angle = letter == 'C' ? t.spin : t.tilt;
    angle = absolute_ || machineFrame ? radians : angle + radians;
  }
  if (options_.machine && machineAxis(options_.machine->geometry.kinematics, t.tilt, t.spin).z < 0)
    throw InputError(where_, fmt::format("the tilt {:g} deg points the tool below the horizontal: "
                                         "a height map seen from above cannot show what it cuts",
                                         radToDeg(t.tilt)));
  return t;
}

Pose GcodeInterpreter::poseOf(const State& s) const {
  if (!options_.machine) return {s.pos, {0, 0, 1}};
  const TableMachine& m = options_.machine->geometry;
  return {tcp_ ? s.pos : machineTip(m, s.pos, s.tilt, s.spin),
          machineAxis(m.kinematics, s.tilt, s.spin)};
}

void GcodeInterpreter::moveTo(const State& to, bool rapid, const ArcMotion* arc) {
  const bool turns = to.tilt != state_.tilt || to.spin != state_.spin;
  // A full circle ends where it starts, and is a move all the same.
  if (to.pos == state_.pos && !turns && !arc) return;
  out_.addMove(poseOf(state_), poseOf(to), rapid, line_);
  Move& mv = out_.path.moves.back();
  mv.tool = uint16_t(rapid ? std::max(spindle_, 0) : toolIndex());
  if (!rapid) mv.feedPerTooth = feedPerTooth(mv.tool);
  mv.spindle = spindleDirection_;
  if (!rapid && turns) {
    out_.path.rotary.push_back(
        {state_.tilt, to.tilt, state_.spin, to.spin, tcp_, state_.pos, to.pos});
    mv.rotary = uint32_t(out_.path.rotary.size());
  }
  if (arc) {
    out_.path.arcs.push_back(*arc);
    mv.arc = uint32_t(out_.path.arcs.size());
  }
  if (firstMoveLine_ == 0) firstMoveLine_ = line_;
  state_ = to;
}

void GcodeInterpreter::motion(const GcodeBlock& b, const GcodeGroups& g) {
  const bool machineFrame = g.nonModal == 530;
  const bool axes =
      b.given('X') || b.given('Y') || b.given('Z') || b.given('A') || b.given('B') || b.given('C');
  if (g.motion == 800) {
    motion_ = -1;
    if (axes) throw InputError(where_, "axis words with G80 (cancel the cycle)");
    return;
  }
  if (g.motion != -1) motion_ = g.motion;
  if (motion_ >= 730) {
    if (machineFrame) throw InputError(where_, "G53 in a drilling cycle");
    if (g.motion != -1 || axes) cycle(b);
    return;
  }
  const bool arcWords = b.given('I') || b.given('J') || b.given('K') || b.given('R');
  if (!axes && !arcWords) {
    if (machineFrame) throw InputError(where_, "G53 without axis words");
    return;
  }
  if (motion_ == -1)
    throw InputError(where_, "coordinates before any motion word (G0, G1, G2 or G3)");
  if (arcWords && motion_ < 20)
    throw InputError(where_, fmt::format("I, J, K and R belong to arcs (G2/G3), not {}",
                                         codeText('G', motion_)));
  if (machineFrame && (motion_ > 10 || !absolute_))
    throw InputError(where_, "G53 (machine coordinates) needs G0 or G1 and G90");
  std::array<bool, 3> knownAfter;
  const State to = target(b, machineFrame, knownAfter);
  const bool startKnown = known_[0] && known_[1] && known_[2];
  if (motion_ == 0) {
    if (startKnown)
      moveTo(to, true);
    else
      state_ = to;
  } else {
    if (!startKnown)
      throw InputError(where_,
                       "cutting move from an unknown position: give X, Y and Z first "
                       "(e.g. in a G0)");
    if (motion_ == 10)
      moveTo(to, false);
    else
      arc(b, to);
  }
  known_ = knownAfter;
}

void GcodeInterpreter::home(const GcodeBlock& b, int code) {
  if (b.given('A') || b.given('B') || b.given('C'))
    throw InputError(where_, codeText('G', code) + " with rotary words is not supported");
  const bool named = b.given('X') || b.given('Y') || b.given('Z');
  const bool startKnown = known_[0] && known_[1] && known_[2];
  std::array<bool, 3> knownAfter = known_;
  // "G91 G28 Z0." opens many posts' programs, before any position is known: then the
  // intermediate point is unknown too, and the axes simply go home.
  if (absolute_ || startKnown) {
    const State via = target(b, false, knownAfter);
    if (named && startKnown) moveTo(via, true);
    state_ = via;
  }
  std::string axes;
  for (int a = 0; a < 3; ++a) {
    if (named && !b.given("XYZ"[a])) continue;
    knownAfter[size_t(a)] = false;
    axes += "XYZ"[a];
  }
  known_ = knownAfter;
  out_.warnings.add(where_,
                    fmt::format("{} (return home): followed as a rapid to the "
                                "intermediate point; home is the machine's own "
                                "position, so {} {} unknown until a move gives them",
                                codeText('G', code), axes, axes.size() == 1 ? "stays" : "stay"));
}

void GcodeInterpreter::arc(const GcodeBlock& b, const State& to) {
  if (to.tilt != state_.tilt || to.spin != state_.spin)
    throw InputError(where_, "an arc (G2/G3) cannot move the rotary axes");
  int iu, iv, iw;
  arcPlaneAxes(plane_, iu, iv, iw);
  const char offU = "IJK"[iu], offV = "IJK"[iv], offW = "IJK"[iw];
  if (b.given(offW))
    throw InputError(where_, fmt::format("{} is not an offset in the G{} plane", offW, plane_));
  ArcSpec a;
  a.start = state_.pos;
  a.end = to.pos;
  a.plane = plane_;
  a.ccw = motion_ == 30;
  if (b.given('R')) {
    if (b.given(offU) || b.given(offV))
      throw InputError(where_, "an arc takes either R or I/J/K offsets, not both");
    a.hasRadius = true;
    a.radius = b.at('R') * scale_;
  } else if (arcAbsolute_) {
    if (!b.given(offU) || !b.given(offV))
      throw InputError(
          where_, fmt::format("arc (G90.1, absolute centre) needs both {} and {}", offU, offV));
    const Vec3& offset = options_.workOffsets[size_t(workOffset_)];
    a.centreU = b.at(offU) * scale_ + component(offset, iu);
    a.centreV = b.at(offV) * scale_ + component(offset, iv);
  } else {
    if (!b.given(offU) && !b.given(offV))
      throw InputError(where_, fmt::format("arc ({}) needs a centre offset {}/{} or a radius R",
                                           codeText('G', motion_), offU, offV));
    a.centreU = component(a.start, iu) + (b.given(offU) ? b.at(offU) * scale_ : 0.0);
    a.centreV = component(a.start, iv) + (b.given(offV) ? b.at(offV) * scale_ : 0.0);
  }
  // One move along the arc, exact. With a machine and TCP off the tip in the part
  // frame is the forward kinematics of the joints, which the arc does not follow in
  // this form: chords there, as with the --arc-chords baseline.
  if (!options_.arcChords && (!options_.machine || tcp_)) {
    const ArcMotion arc = resolveArc(a, where_);
    moveTo(to, false, &arc);
    return;
  }
  for (const Vec3& p : arcChords(a, options_.arcTolerance, where_))
    moveTo({p, state_.tilt, state_.spin}, false);
}

// --- Canned cycles (gcode_cycles.h). ----------------------------------------------

void GcodeInterpreter::cycle(const GcodeBlock& b) {
  const std::string name = codeText('G', motion_);
  if (plane_ != 17) throw InputError(where_, name + ": drilling cycles are read in G17 only");
  if (b.given('A') || b.given('B') || b.given('C') || b.given('I') || b.given('J') || b.given('K'))
    throw InputError(where_, name + ": a drilling cycle takes X Y Z R Q P L F, not A B C I J K");
  if (!(known_[0] && known_[1] && known_[2]))
    throw InputError(where_, name + " from an unknown position: give X, Y and Z first");
  if (b.given('R')) cycleR_ = b.at('R'), haveR_ = true;
  if (b.given('Z')) cycleZ_ = b.at('Z'), haveZ_ = true;
  if (b.given('Q')) cycleQ_ = b.at('Q'), haveQ_ = true;
  if (!haveR_ || !haveZ_)
    throw InputError(where_, name + " needs Z (the hole bottom) and R (the retract level)");
  const bool pecks = motion_ == 730 || motion_ == 830;
  if (pecks && !(haveQ_ && cycleQ_ > 0))
    throw InputError(where_, name + " needs a peck depth Q > 0");
  double repeats = 1;
  if (b.given('L')) {
    repeats = b.at('L');
    if (!(repeats >= 0 && repeats <= 1e4 && repeats == std::floor(repeats)))
      throw InputError(where_, "L (repeats) must be a whole number in [0, 10000]");
  }
  const Vec3& offset = options_.workOffsets[size_t(workOffset_)];
  const double initialZ = state_.pos.z;
  DrillCycle c;
  c.code = motion_;
  c.clearZ = absolute_ ? cycleR_ * scale_ + offset.z : initialZ + cycleR_ * scale_;
  c.bottomZ = absolute_ ? cycleZ_ * scale_ + offset.z : c.clearZ + cycleZ_ * scale_;
  c.retractZ = retractToInitial_ ? std::max(initialZ, c.clearZ) : c.clearZ;
  c.peck = cycleQ_ * scale_;
  if (c.bottomZ > c.clearZ)
    throw InputError(where_, fmt::format("{}: the hole bottom Z = {:g} mm is above the R level "
                                         "{:g} mm",
                                         name, c.bottomZ, c.clearZ));
  // A line makes at most a million moves, as an arc does (gcode_arc.h).
  const double holeMoves = 4 + (pecks ? 3 * std::ceil((c.clearZ - c.bottomZ) / c.peck) : 2);
  if (holeMoves * repeats > 1e6)
    throw InputError(where_, name +
                                 ": more than a million moves in one line (pecks of Q times "
                                 "L repeats)");
  for (int rep = 0; rep < int(repeats); ++rep) {
    double x = state_.pos.x, y = state_.pos.y;
    if (absolute_) {
      if (b.given('X')) x = b.at('X') * scale_ + offset.x;
      if (b.given('Y')) y = b.at('Y') * scale_ + offset.y;
    } else {
      if (b.given('X')) x += b.at('X') * scale_;
      if (b.given('Y')) y += b.at('Y') * scale_;
    }
    drillHole(c, state_.pos, x, y, [&](const Vec3& p, bool rapid) {
      moveTo({p, state_.tilt, state_.spin}, rapid);
    });
  }
}

}  // namespace scallop
