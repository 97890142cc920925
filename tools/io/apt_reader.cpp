#include "tools/io/apt_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <istream>
#include <vector>

#include "base/input_error.h"
#include "sweep/apt_cutter.h"
#include "sweep/cutter_shapes.h"

namespace scallop {

namespace {

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const size_t b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// One statement: its first line, major word and comma-separated arguments.
struct Statement {
  int64_t line = 0;
  std::string major;
  std::vector<std::string> args;
  bool hasSlash = false;
};

// Reads the next statement, joining "$" continuation lines; false at the end.
bool nextStatement(std::istream& in, const std::string& source, int64_t& lineNo, Statement& st) {
  std::string text, line;
  int64_t first = 0;
  bool continued = false;
  while (std::getline(in, line)) {
    ++lineNo;
    const size_t comment = line.find("$$");
    if (comment != std::string::npos) line.erase(comment);
    line = trim(line);
    if (line.empty() && !continued) continue;
    if (!continued) first = lineNo;
    continued = !line.empty() && line.back() == '$';
    if (continued) line.pop_back();
    text += line;
    if (!continued) break;
  }
  if (continued)
    throw InputError(source + ":" + std::to_string(first),
                     "the statement continues (\"$\") past the end of the file");
  if (first == 0) return false;
  st = Statement();
  st.line = first;
  const size_t slash = text.find('/');
  st.hasSlash = slash != std::string::npos;
  st.major = upper(trim(text.substr(0, slash)));
  if (st.hasSlash) {
    const std::string rest = text.substr(slash + 1);
    size_t start = 0;
    while (true) {
      const size_t comma = rest.find(',', start);
      st.args.push_back(trim(rest.substr(start, comma - start)));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return true;
}

bool isIdentifier(const std::string& word) {
  if (word.empty() || !std::isalpha(static_cast<unsigned char>(word[0]))) return false;
  for (char c : word)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

class AptParser {
 public:
  AptParser(const std::string& source, const PathFileOptions& options, ToolPathFile& out)
      : source_(source), options_(options), out_(out) {}

  void statement(const Statement& st) {
    where_ = source_ + ":" + std::to_string(st.line);
    if (!isIdentifier(st.major))
      throw InputError(where_, "expected an APT statement such as GOTO/x,y,z, got \"" + st.major +
                                   (st.hasSlash ? "/...\"" : "\""));
    const std::string& m = st.major;
    if (m == "GOTO" || m == "FROM") {
      location(st, m == "FROM");
    } else if (m == "RAPID") {
      rapidNext_ = true;
    } else if (m == "CUTTER") {
      cutter(st);
    } else if (m == "UNITS") {
      units(st);
    } else if (m == "LOADTL") {
      loadTool(st);
    } else if (m == "MULTAX" || m == "FEDRAT" || m == "PARTNO" || m == "PPRINT" || m == "SPINDL" ||
               m == "COOLNT" || m == "CLPRNT" || m == "FINI" || m == "END") {
      // No effect on the swept geometry (MULTAX only announces i, j, k on GOTO).
    } else {
      out_.warnings.add(where_, "unknown statement \"" + m + "\" ignored");
    }
  }

  void finish() {
    if (!havePose_) throw InputError(source_, "no GOTO statement found");
    if (out_.path.moves.empty()) addMove(pose_, pose_, false, poseLine_);
    if (options_.tools.empty() && cutters_.size() > 1) {
      out_.path.cutters = cutters_;
      out_.toolNumbers = numbers_;
    }
  }

 private:
  double number(const std::string& token, const char* what) const {
    double v;
    if (!parseDecimal(token, v))
      throw InputError(
          where_, fmt::format("{}: expected a finite decimal number, got \"{}\"", what, token));
    return v;
  }

  void location(const Statement& st, bool from) {
    const char* name = from ? "FROM" : "GOTO";
    if (st.args.size() != 3 && st.args.size() != 6)
      throw InputError(where_, fmt::format("{} expects 3 values (x,y,z) or 6 (x,y,z,i,j,k), got {}",
                                           name, st.args.size()));
    static const char* kNames[] = {"x", "y", "z", "i", "j", "k"};
    double v[6];
    for (size_t k = 0; k < st.args.size(); ++k) v[k] = number(st.args[k], kNames[k]);
    Pose pose{{v[0] * scale_, v[1] * scale_, v[2] * scale_},
              havePose_ ? pose_.axis : Vec3{0, 0, 1}};
    if (st.args.size() == 6) {
      pose.axis = fileAxis({v[3], v[4], v[5]}, where_, options_.axesFromAbove);
    }
    if (havePose_ && !from) {
      addMove(pose_, pose, rapidNext_, st.line);
      if (firstMoveLine_ == 0) firstMoveLine_ = st.line;
    }
    if (!from) rapidNext_ = false;
    pose_ = pose;
    poseLine_ = st.line;
    havePose_ = true;
  }

  void cutter(const Statement& st) {
    const size_t n = st.args.size();
    if (n != 1 && n != 2 && n != 7)
      throw InputError(where_,
                       fmt::format("CUTTER expects d, d,r or d,r,e,f,a,b,h; got {} values", n));
    std::vector<double> raw, v;
    for (size_t k = 0; k < n; ++k) raw.push_back(number(st.args[k], "CUTTER value"));
    for (double value : raw) v.push_back(value * scale_);
    Cutter c;
    if (n == 7) {
      // APT's generalized cutter (CONVENTIONS.md "Cutter shapes"); a and b are degrees.
      const AptCutterValues apt{v[0], v[1], v[2], v[3], raw[4], raw[5], v[6]};
      c = aptCutter(apt, where_ + ": CUTTER");
    } else {
      const double radius = v[0] / 2, corner = n >= 2 ? v[1] : 0;
      if (!(radius > 0)) throw InputError(where_, "CUTTER diameter must be > 0 mm");
      if (corner < 0 || corner > radius)
        throw InputError(where_, fmt::format("CUTTER corner radius must be in [0, d/2 = {:g}] mm, "
                                             "got {:g}",
                                             radius, corner));
      const CutterType type = corner == 0        ? CutterType::Flat
                              : corner == radius ? CutterType::Ball
                                                 : CutterType::Bull;
      c = Cutter::make(type, radius, corner, 0, where_ + ": CUTTER");
    }
    if (!out_.cutter) out_.cutter = c;
    if (!options_.tools.empty()) return;  // LOADTL picks the job's cutter
    // A new cutter is a new tool for the moves after it (the first serves those before).
    auto same = [&](const Cutter& o) { return sameShape(o, c); };
    const auto it = std::find_if(cutters_.begin(), cutters_.end(), same);
    tool_ = uint16_t(it - cutters_.begin());
    if (it == cutters_.end()) {
      if (cutters_.size() >= 65535) throw InputError(where_, "more than 65535 cutters in one file");
      cutters_.push_back(c);
      numbers_.push_back(loaded_ >= 0 ? loaded_ : int64_t(cutters_.size()));
    }
    loaded_ = -1;  // a LOADTL numbers the one CUTTER/ after it
  }

  void loadTool(const Statement& st) {
    double v = -1;
    if (st.args.empty() || !parseDecimal(st.args[0], v) || !(v >= 0 && v <= 1e9) ||
        v != std::floor(v))
      throw InputError(where_, "LOADTL expects a tool number, e.g. LOADTL/1");
    loaded_ = int64_t(v);
    const auto& tools = options_.tools;
    if (tools.empty()) return;
    if (!tools.count(loaded_)) {
      std::string have;
      for (const auto& [number, cutter] : tools)
        have += (have.empty() ? "" : ", ") + std::to_string(number);
      throw InputError(where_, fmt::format("LOADTL/{}: tool {} is not in the job's \"tools\" (it "
                                           "has {})",
                                           loaded_, loaded_, have));
    }
    const auto it = std::find(out_.toolNumbers.begin(), out_.toolNumbers.end(), loaded_);
    tool_ = uint16_t(it - out_.toolNumbers.begin());
    if (it == out_.toolNumbers.end()) {
      out_.toolNumbers.push_back(loaded_);
      out_.path.cutters.push_back(tools.at(loaded_));
    }
    haveTool_ = true;
  }

  void addMove(const Pose& from, const Pose& to, bool rapid, int64_t line) {
    const auto& tools = options_.tools;
    if (!tools.empty() && !haveTool_ && !rapid) {
      if (tools.size() != 1)
        throw InputError(where_, fmt::format("a cutting move before any LOADTL/: the job's "
                                             "\"tools\" has {}",
                                             tools.size()));
      out_.toolNumbers.push_back(tools.begin()->first);
      out_.path.cutters.push_back(tools.begin()->second);
      haveTool_ = true;
    }
    out_.addMove(from, to, rapid, line);
    out_.path.moves.back().tool = tool_;
  }

  void units(const Statement& st) {
    const std::string u = st.args.size() == 1 ? upper(st.args[0]) : "";
    double scale = 0;
    if (u == "MM") scale = 1;
    if (u == "INCHES" || u == "INCH") scale = 25.4;
    if (scale == 0) throw InputError(where_, "expected UNITS/MM or UNITS/INCHES");
    if (scale != scale_ && firstMoveLine_ != 0)
      throw InputError(where_, fmt::format("mixed units: UNITS/{} after moves in {} since line {}; "
                                           "a file must use one unit",
                                           u, scale_ == 1 ? "mm" : "inches", firstMoveLine_));
    scale_ = scale;
  }

  const std::string& source_;
  const PathFileOptions& options_;
  ToolPathFile& out_;
  // Tools: the cutters met (without the job's tools) with their numbers, the tool index
  // of the moves now, the LOADTL number in effect.
  std::vector<Cutter> cutters_;
  std::vector<int64_t> numbers_;
  uint16_t tool_ = 0;
  int64_t loaded_ = -1;
  bool haveTool_ = false;
  std::string where_;
  double scale_ = 1;  // mm per file unit
  bool rapidNext_ = false;
  bool havePose_ = false;
  Pose pose_;
  int64_t poseLine_ = 0, firstMoveLine_ = 0;
};

}  // namespace

void readApt(std::istream& in, const std::string& source, ToolPathFile& out) {
  readApt(in, source, PathFileOptions(), out);
}

void readApt(std::istream& in, const std::string& source, const PathFileOptions& options,
             ToolPathFile& out) {
  out.format = "apt";
  AptParser parser(source, options, out);
  Statement st;
  int64_t lineNo = 0;
  while (nextStatement(in, source, lineNo, st)) parser.statement(st);
  parser.finish();
}

}  // namespace scallop
