#include "tools/io/gcode_reader.h"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cmath>
#include <istream>
#include <vector>

#include "sweep/constants.h"
#include "sweep/input_error.h"

namespace scallop {

namespace {

// Start and end radii of an arc may differ by this much (mm) before it is an error;
// LinuxCNC uses the same bound. The chords interpolate the radius in between.
constexpr double kArcRadiusSlack = 0.002;

// The words of one block (line): letter values, G and M codes in order of appearance.
struct Block {
  std::array<bool, 26> has{};
  std::array<double, 26> value{};
  std::vector<double> g;
  std::vector<double> m;
  bool given(char c) const { return has[size_t(c - 'A')]; }
  double at(char c) const { return value[size_t(c - 'A')]; }
};

// Parses one line into `block`; returns false for a line without words.
bool parseBlock(const std::string& line, const std::string& where, Block& block) {
  std::string compact;
  for (size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (c == '(') {
      const size_t close = line.find(')', k);
      if (close == std::string::npos) throw InputError(where, "comment \"(\" is not closed");
      k = close;
    } else if (c == ';') {
      break;
    } else if (c == '%' && compact.empty() &&
               line.find_first_not_of(" \t\r%") == std::string::npos) {
      return false;  // program start/end marker
    } else if (c != ' ' && c != '\t' && c != '\r') {
      compact += char(std::toupper(static_cast<unsigned char>(c)));
    }
  }
  size_t k = 0;
  bool any = false;
  while (k < compact.size()) {
    const char letter = compact[k++];
    if (!std::isalpha(static_cast<unsigned char>(letter)))
      throw InputError(where, fmt::format("expected a word such as G1 or X2.5, got \"{}\"",
                                          compact.substr(k - 1)));
    const size_t start = k;
    while (k < compact.size() && (std::isdigit(static_cast<unsigned char>(compact[k])) ||
                                  compact[k] == '.' || compact[k] == '-' || compact[k] == '+'))
      ++k;
    const std::string digits = compact.substr(start, k - start);
    double v = 0;
    if (digits.empty())
      throw InputError(where, fmt::format("word {} has no number (truncated line?)", letter));
    if (!parseDecimal(digits, v))
      throw InputError(where,
                       fmt::format("word {}{}: expected a finite decimal number", letter, digits));
    any = true;
    const std::string word = std::string(1, letter) + digits;
    switch (letter) {
      case 'G':
        block.g.push_back(v);
        break;
      case 'M':
        block.m.push_back(v);
        break;
      case 'X':
      case 'Y':
      case 'Z':
      case 'I':
      case 'J':
      case 'K':
      case 'R':
      case 'F':
      case 'S':
      case 'N':
        if (block.given(letter))
          throw InputError(where, fmt::format("word {} appears twice in one line", letter));
        block.has[size_t(letter - 'A')] = true;
        block.value[size_t(letter - 'A')] = v;
        break;
      default:
        throw InputError(where, "unsupported word " + word +
                                    " (only G0-G3, G17-G21, G90, G91, X Y Z I J K R F S N and "
                                    "M spindle/coolant/stop words)");
    }
  }
  return any;
}

class GcodeInterpreter {
 public:
  GcodeInterpreter(const std::string& source, const PathFileOptions& options, ToolPathFile& out)
      : source_(source), options_(options), out_(out) {}

  void block(const Block& b, int64_t line) {
    where_ = source_ + ":" + std::to_string(line);
    line_ = line;
    int motion = -1, plane = -1, units = -1, distance = -1;
    auto setOnce = [&](int& slot, int code, const char* group) {
      if (slot != -1)
        throw InputError(where_,
                         fmt::format("two {} words (G{} and G{}) in one line", group, slot, code));
      slot = code;
    };
    // A word's number as a code: whole numbers 0..999 only (larger values would not
    // even fit an int; the fuzzer found G99999999999).
    auto wordCode = [](double v) { return v >= 0 && v < 1000 && v == std::floor(v) ? int(v) : -1; };
    for (double g : b.g) {
      const int code = wordCode(g);
      if (code < 0) throw InputError(where_, fmt::format("unsupported G-word G{:g}", g));
      if (code >= 0 && code <= 3)
        setOnce(motion, code, "motion");
      else if (code >= 17 && code <= 19)
        setOnce(plane, code, "plane");
      else if (code == 20 || code == 21)
        setOnce(units, code, "unit");
      else if (code == 90 || code == 91)
        setOnce(distance, code, "distance-mode");
      else if (code == 40 || code == 49 || code == 80 || code == 94)
        continue;
      else
        throw InputError(where_, fmt::format("unsupported G-word G{}", code));
    }
    for (double m : b.m) {
      const int code = wordCode(m);
      const bool harmless = (code >= 0 && code <= 5) || (code >= 7 && code <= 9) || code == 30;
      if (!harmless)
        throw InputError(where_, fmt::format("unsupported M-word M{:g}{}", m,
                                             m == 6 ? " (tool change: one tool per path)" : ""));
    }
    if (units != -1) {
      const double scale = units == 20 ? 25.4 : 1.0;
      if (scale != scale_ && firstMoveLine_ != 0)
        throw InputError(
            where_, fmt::format("mixed units: G{} after moves in {} since line {}; a "
                                "file must use one unit",
                                units, scale_ == 1 ? "mm (G21)" : "inches (G20)", firstMoveLine_));
      scale_ = scale;
    }
    if (plane != -1) plane_ = plane;
    if (distance != -1) absolute_ = distance == 90;
    if (motion != -1) motion_ = motion;

    const bool axes = b.given('X') || b.given('Y') || b.given('Z');
    const bool arcWords = b.given('I') || b.given('J') || b.given('K') || b.given('R');
    if (!axes && !arcWords) return;
    if (motion_ == -1)
      throw InputError(where_, "coordinates before any motion word (G0, G1, G2 or G3)");
    if (arcWords && motion_ < 2)
      throw InputError(where_,
                       fmt::format("I, J, K and R belong to arcs (G2/G3), not G{}", motion_));

    Vec3 target = pos_;
    std::array<bool, 3> knownAfter = known_;
    const char names[3] = {'X', 'Y', 'Z'};
    for (int a = 0; a < 3; ++a) {
      if (!b.given(names[a])) continue;
      const double v = b.at(names[a]) * scale_;
      if (!absolute_ && !known_[size_t(a)])
        throw InputError(where_,
                         fmt::format("incremental {} (G91) from an unknown position", names[a]));
      (a == 0   ? target.x
       : a == 1 ? target.y
                : target.z) = absolute_ ? v
                                        : (a == 0   ? pos_.x
                                           : a == 1 ? pos_.y
                                                    : pos_.z) +
                                              v;
      knownAfter[size_t(a)] = true;
    }
    const bool startKnown = known_[0] && known_[1] && known_[2];
    if (motion_ == 0) {
      if (startKnown && target != pos_) add(pos_, target, true);
    } else {
      if (!startKnown)
        throw InputError(where_,
                         "cutting move from an unknown position: give X, Y and Z first "
                         "(e.g. in a G0)");
      if (motion_ == 1) {
        if (target != pos_) add(pos_, target, false);
      } else {
        arc(b, target);
      }
    }
    pos_ = target;
    known_ = knownAfter;
  }

  void finish() {
    if (out_.path.moves.empty())
      throw InputError(source_, "no moves found (G0/G1/G2/G3 with X, Y, Z)");
  }

 private:
  void add(const Vec3& from, const Vec3& to, bool rapid) {
    out_.addMove({from, {0, 0, 1}}, {to, {0, 0, 1}}, rapid, line_);
    if (firstMoveLine_ == 0) firstMoveLine_ = line_;
  }

  // Arc in the active plane: (u, v) in-plane coordinates, w along the plane normal.
  void arc(const Block& b, const Vec3& target) {
    // G17: (x, y) normal z, offsets I J; G18: (z, x) normal y, K I; G19: (y, z) normal x, J K.
    const int iu = plane_ == 17 ? 0 : plane_ == 18 ? 2 : 1;
    const int iv = plane_ == 17 ? 1 : plane_ == 18 ? 0 : 2;
    const int iw = 3 - iu - iv;
    const char offU = "IJK"[iu], offV = "IJK"[iv], offW = "IJK"[iw];
    if (b.given(offW))
      throw InputError(where_, fmt::format("{} is not an offset in the G{} plane", offW, plane_));
    auto comp = [](const Vec3& p, int i) { return i == 0 ? p.x : i == 1 ? p.y : p.z; };
    const double su = comp(pos_, iu), sv = comp(pos_, iv);
    const double eu = comp(target, iu), ev = comp(target, iv);
    const bool ccw = motion_ == 3;
    double cu, cv;
    if (b.given('R')) {
      if (b.given(offU) || b.given(offV))
        throw InputError(where_, "an arc takes either R or I/J/K offsets, not both");
      const double radius = b.at('R') * scale_;
      const double du = eu - su, dv = ev - sv, chord = std::hypot(du, dv);
      if (chord == 0)
        throw InputError(where_,
                         "an R arc needs distinct start and end; use I/J/K for a full "
                         "circle");
      if (chord > 2 * std::fabs(radius) + kArcRadiusSlack)
        throw InputError(where_, fmt::format("arc radius R = {:g} mm is smaller than half the "
                                             "chord ({:g} mm)",
                                             std::fabs(radius), chord / 2));
      const double h = std::sqrt(std::max(0.0, radius * radius - chord * chord / 4));
      // Left of the chord for a counter-clockwise short arc; R < 0 asks for the long one.
      const double side = (ccw ? 1.0 : -1.0) * (radius < 0 ? -1.0 : 1.0);
      cu = (su + eu) / 2 - side * h * dv / chord;
      cv = (sv + ev) / 2 + side * h * du / chord;
    } else {
      if (!b.given(offU) && !b.given(offV))
        throw InputError(where_, fmt::format("arc (G{}) needs a centre offset {}/{} or a radius R",
                                             motion_, offU, offV));
      cu = su + (b.given(offU) ? b.at(offU) * scale_ : 0.0);
      cv = sv + (b.given(offV) ? b.at(offV) * scale_ : 0.0);
    }
    const double r0 = std::hypot(su - cu, sv - cv), r1 = std::hypot(eu - cu, ev - cv);
    if (r0 == 0) throw InputError(where_, "arc centre is at the start point (radius 0)");
    if (std::fabs(r0 - r1) > kArcRadiusSlack)
      throw InputError(where_, fmt::format("arc radii differ: {:.6g} mm at the start, {:.6g} mm at "
                                           "the end (more than {:g} mm)",
                                           r0, r1, kArcRadiusSlack));
    const double a0 = std::atan2(sv - cv, su - cu), a1 = std::atan2(ev - cv, eu - cu);
    double sweep = a1 - a0;
    if (ccw) {
      while (sweep <= 0) sweep += 2 * kPi;
    } else {
      while (sweep >= 0) sweep -= 2 * kPi;
    }
    // Chords with sagitta r (1 - cos(step / 2)) <= tolerance.
    const double rMax = std::max(r0, r1), tol = options_.arcTolerance;
    const double step = tol < rMax ? 2 * std::acos(1 - tol / rMax) : kPi / 2;
    const double pieces = std::ceil(std::fabs(sweep) / std::min(step, kPi / 2));
    if (pieces > 1e6)
      throw InputError(where_, fmt::format("arc needs {:g} chords for the tolerance {:g} mm; too "
                                           "many",
                                           pieces, tol));
    const int n = std::max(1, int(pieces));
    Vec3 from = pos_;
    for (int k = 1; k <= n; ++k) {
      Vec3 p = target;
      if (k < n) {
        const double f = double(k) / n, angle = a0 + sweep * f, rho = r0 + (r1 - r0) * f;
        double c[3];
        c[iu] = cu + rho * std::cos(angle);
        c[iv] = cv + rho * std::sin(angle);
        c[iw] = comp(pos_, iw) + (comp(target, iw) - comp(pos_, iw)) * f;
        p = {c[0], c[1], c[2]};
      }
      add(from, p, false);
      from = p;
    }
  }

  const std::string& source_;
  const PathFileOptions& options_;
  ToolPathFile& out_;
  std::string where_;
  int64_t line_ = 0, firstMoveLine_ = 0;
  int motion_ = -1, plane_ = 17;
  double scale_ = 1;  // mm per file unit
  bool absolute_ = true;
  Vec3 pos_{0, 0, 0};
  std::array<bool, 3> known_{};
};

}  // namespace

void readGcode(std::istream& in, const std::string& source, const PathFileOptions& options,
               ToolPathFile& out) {
  out.format = "gcode";
  out.arcTolerance = options.arcTolerance;
  GcodeInterpreter interpreter(source, options, out);
  std::string line;
  int64_t lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    Block block;
    if (parseBlock(line, source + ":" + std::to_string(lineNo), block))
      interpreter.block(block, lineNo);
  }
  interpreter.finish();
}

}  // namespace scallop
