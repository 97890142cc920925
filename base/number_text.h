// Numbers in messages for people (errors, the reasons a formula does not apply): one
// spelling everywhere, so that a value reads the same whichever check names it.
#pragma once

#include <cstdio>
#include <string>

namespace scallop {

// `value` with up to 10 significant digits and no trailing zeros ("%.10g"): 3, 0.125,
// 2.884, 1e+06; what the user typed, in practice.
inline std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

}  // namespace scallop
