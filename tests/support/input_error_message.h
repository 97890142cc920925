// The message of the InputError that `f` throws, or "" when it throws none: reader
// tests compare messages (file:line and what was expected) without repeating the
// try/catch in every file.
#pragma once

#include <string>

#include "base/input_error.h"

namespace scallop {

template <class F>
std::string inputErrorMessage(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace scallop
