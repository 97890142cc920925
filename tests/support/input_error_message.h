// The message of the InputError that `f` throws, or "" when it throws none: reader
// tests compare messages (file:line and what was expected) without repeating the
// try/catch in every file.
#pragma once

#include <gtest/gtest.h>

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

// Expects `make` to throw an InputError whose message names `field`.
template <class F>
void expectRejected(F&& make, const std::string& field) {
  const std::string message = inputErrorMessage(make);
  EXPECT_NE(message.find(field), std::string::npos)
      << (message.empty() ? "accepted, expected an InputError naming " + field : message);
}

}  // namespace scallop
