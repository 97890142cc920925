#include "tools/io/gcode_groups.h"

#include <fmt/format.h>

#include <algorithm>

#include "base/input_error.h"

namespace scallop {

namespace {

std::string codeText(char letter, int tenths) {
  return gcodeWordText(letter, tenths / 10.0);
}

bool listed(const std::vector<std::string>& codes, const std::string& word) {
  return std::find(codes.begin(), codes.end(), word) != codes.end();
}

}  // namespace

GcodeGroups groupGcodeWords(const GcodeBlock& b, const MachineSpec* machine,
                            const std::string& where) {
  GcodeGroups g;
  auto set = [&](int& slot, int code, const char* group) {
    if (slot != -1)
      throw InputError(where, fmt::format("two {} words ({} and {}) in one line", group,
                                          codeText('G', slot), codeText('G', code)));
    slot = code;
  };
  for (double v : b.g) {
    // The word's text only for a machine's codes (formatting a double costs).
    const std::string text = machine ? gcodeWordText('G', v) : std::string();
    if (machine && listed(machine->tcpOn, text)) {
      set(g.tcp, 1, "TCP");
      continue;
    }
    if (machine && listed(machine->tcpOff, text)) {
      set(g.tcp, 0, "TCP");
      continue;
    }
    const int c = gcodeTenths(v);
    if (c < 0) throw InputError(where, fmt::format("unsupported G-word G{:g}", v));
    if (c == 0 || c == 10 || c == 20 || c == 30 || c == 730 || c == 800 ||
        (c >= 810 && c <= 890 && c % 10 == 0 && c != 870)) {
      set(g.motion, c, "motion");
    } else if (c == 870) {
      throw InputError(where,
                       "G87 (back boring) is not supported: it cuts from below, which "
                       "a height map seen from above cannot show");
    } else if (c == 40 || c == 280 || c == 300 || c == 530) {
      set(g.nonModal, c, "non-modal");
    } else if (c == 170 || c == 180 || c == 190) {
      set(g.plane, c, "plane");
    } else if (c == 200 || c == 210) {
      set(g.units, c, "unit");
    } else if (c == 400) {
      set(g.compensation, c, "cutter compensation");
    } else if (c == 410 || c == 420) {
      throw InputError(where, fmt::format("{} (cutter radius compensation) is not supported: "
                                          "scallop sweeps the programmed tool centre; post the "
                                          "path with compensation done in the CAM system",
                                          gcodeWordText('G', v)));
    } else if (c == 430 || c == 434 || c == 490) {
      set(g.length, c, "tool length");
    } else if (c >= 540 && c <= 590 && c % 10 == 0) {
      set(g.offset, c, "work offset");
    } else if (c == 610 || c == 611 || c == 640) {
      set(g.pathMode, c, "path control");
    } else if (c == 900 || c == 910) {
      set(g.distance, c, "distance-mode");
    } else if (c == 901 || c == 911) {
      set(g.arcDistance, c, "arc distance-mode");
    } else if (c == 930 || c == 940 || c == 950) {
      set(g.feed, c, "feed-mode");
    } else if (c == 980 || c == 990) {
      set(g.retract, c, "retract-mode");
    } else if (c == 100 || c == 520 || c == 920 || c == 921 || c == 922 || c == 923) {
      throw InputError(where, fmt::format("{} (setting a coordinate system) is not supported; "
                                          "give the work offsets G54-G59 in the job "
                                          "(\"work_offsets\")",
                                          gcodeWordText('G', v)));
    } else {
      throw InputError(where, "unsupported G-word " + gcodeWordText('G', v));
    }
  }
  for (double v : b.m) {
    const std::string text = gcodeWordText('M', v);
    if (machine && listed(machine->tcpOn, text)) {
      g.tcp = 1;
      continue;
    }
    if (machine && listed(machine->tcpOff, text)) {
      g.tcp = 0;
      continue;
    }
    const int c = gcodeTenths(v);
    if (c < 0 || c % 10 != 0) throw InputError(where, fmt::format("unsupported M-word M{:g}", v));
    switch (c / 10) {
      case 0:
      case 1:
        g.ignored.emplace_back(text, "program stop");
        break;
      case 2:
      case 30:
        g.end = true;
        break;
      case 3:
      case 4:
      case 5:
        g.ignored.emplace_back(text, "spindle");
        break;
      case 6:
        g.change = true;
        break;
      case 7:
      case 8:
      case 9:
        g.ignored.emplace_back(text, "coolant");
        break;
      case 98:
      case 99:
        throw InputError(where, text +
                                    " (subprogram call/return) is not supported: post the "
                                    "program without subprograms");
      default:
        g.unknownM.push_back(text);
    }
  }
  return g;
}

}  // namespace scallop
