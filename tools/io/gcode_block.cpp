#include "tools/io/gcode_block.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "base/input_error.h"
#include "tools/io/tool_path_file.h"

namespace scallop {

namespace {

bool isNumberChar(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+';
}

// An E written straight after a word's number ("X1e300", "Y2E5") is an exponent in
// other languages; G-code has none (LinuxCNC reads X1 and a word E300). Refused naming
// the text as written, from the word's letter to the exponent's last digit, before the
// lexer would take the E for a word of its own. `e` is the E's index in `line`.
void refuseExponent(const std::string& line, size_t e, const std::string& where) {
  size_t start = e;
  while (start > 0 && isNumberChar(line[start - 1])) --start;
  if (start == 0 || !std::isalpha(static_cast<unsigned char>(line[start - 1]))) return;
  --start;  // the word's letter
  if (std::toupper(static_cast<unsigned char>(line[start])) == 'O') return;  // O-words: below
  size_t end = e + 1;
  while (end < line.size() && isNumberChar(line[end])) ++end;
  throw InputError(where, fmt::format("\"{}\": G-code numbers have no exponent; write the "
                                      "number in plain decimals (scallop reads no E word)",
                                      line.substr(start, end - start)));
}

}  // namespace

int gcodeTenths(double v) {
  if (!(v >= 0 && v < 1000)) return -1;
  const double tenths = std::round(v * 10);
  return std::fabs(tenths - v * 10) <= 1e-9 ? int(tenths) : -1;
}

std::string gcodeWordText(char letter, double value) {
  return fmt::format("{}{:g}", letter, value);
}

GcodeBlock lexGcodeBlock(const std::string& line, const std::string& where, bool blockDelete) {
  GcodeBlock block;
  // --- Comments and block delete away, the rest upper case without spaces. ---
  std::string compact;
  const size_t first = line.find_first_not_of(" \t\r");
  size_t k = first == std::string::npos ? line.size() : first;
  if (k < line.size() && line[k] == '/') {
    if (blockDelete) return block;
    ++k;
  }
  for (; k < line.size(); ++k) {
    const char c = line[k];
    if (c == '(') {
      const size_t close = line.find(')', k);
      if (close == std::string::npos) throw InputError(where, "comment \"(\" is not closed");
      k = close;
    } else if (c == ';') {
      break;
    } else if (c == '#') {
      throw InputError(where,
                       "parameters (\"#\" variables) are not supported: scallop reads "
                       "G-code with plain numbers, as CAM posts write it");
    } else if (c == '[') {
      throw InputError(where, "expressions (\"[...]\") are not supported");
    } else if ((c == 'e' || c == 'E') && k > 0 &&
               (std::isdigit(static_cast<unsigned char>(line[k - 1])) || line[k - 1] == '.')) {
      refuseExponent(line, k, where);
      compact += 'E';
    } else if (c != ' ' && c != '\t' && c != '\r') {
      compact += c >= 'a' && c <= 'z' ? char(c - 'a' + 'A') : c;  // ASCII: no locale call
    }
  }
  if (compact.empty()) return block;
  if (compact.find_first_not_of('%') == std::string::npos) {
    block.kind = GcodeBlock::Kind::Percent;
    return block;
  }
  // --- A program number, or O-word control flow (refused). ---
  if (compact[0] == 'O') {
    size_t e = 1;
    while (e < compact.size() && std::isdigit(static_cast<unsigned char>(compact[e]))) ++e;
    if (e == 1 || e != compact.size())
      throw InputError(where, fmt::format("O-word \"{}\": subprograms and flow control (sub, "
                                          "call, if, while, O<name>) are not supported; only a "
                                          "program number (O1000) alone on its line",
                                          compact));
    return block;
  }
  // --- Words. ---
  k = 0;
  while (k < compact.size()) {
    const char letter = compact[k++];
    if (!std::isalpha(static_cast<unsigned char>(letter)))
      throw InputError(where, fmt::format("expected a word such as G1 or X2.5, got \"{}\"",
                                          compact.substr(k - 1)));
    const size_t start = k;
    while (k < compact.size() && isNumberChar(compact[k])) ++k;
    const std::string digits = compact.substr(start, k - start);
    double v = 0;
    if (digits.empty())
      throw InputError(where, fmt::format("word {} has no number (truncated line?)", letter));
    if (!parseDecimal(digits, v))
      throw InputError(where,
                       fmt::format("word {}{}: expected a finite decimal number", letter, digits));
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
      case 'A':
      case 'B':
      case 'C':
      case 'I':
      case 'J':
      case 'K':
      case 'R':
      case 'F':
      case 'S':
      case 'N':
      case 'T':
      case 'P':
      case 'Q':
      case 'L':
      case 'H':
      case 'D':
        if (block.given(letter))
          throw InputError(where, fmt::format("word {} appears twice in one line", letter));
        block.has[size_t(letter - 'A')] = true;
        block.value[size_t(letter - 'A')] = v;
        break;
      case 'O':
        throw InputError(where, fmt::format("O-word O{} inside a line: subprograms and flow "
                                            "control are not supported",
                                            digits));
      default:
        throw InputError(where, fmt::format("unsupported word {}{} (scallop reads G M T S F N X "
                                            "Y Z A B C I J K R P Q L H D)",
                                            letter, digits));
    }
  }
  block.kind = GcodeBlock::Kind::Words;
  return block;
}

}  // namespace scallop
