// The one libFuzzer driver: each executable NAME_fuzz is this file compiled with
// SCALLOP_FUZZ_TARGET="NAME" (tests/fuzz/CMakeLists.txt) and feeds its bytes to the
// function tests/fuzz/fuzz_targets.h lists under NAME. InputError is the readers'
// contract for bad bytes, so it is swallowed; anything else reaches libFuzzer.
#include <cstddef>
#include <cstdint>
#include <string>

#include "base/input_error.h"
#include "tests/fuzz/fuzz_targets.h"

#ifndef SCALLOP_FUZZ_TARGET
#error "compile with -DSCALLOP_FUZZ_TARGET=\"NAME\" (a key of scallop::fuzz::targets())"
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto& run = scallop::fuzz::targets().at(SCALLOP_FUZZ_TARGET);
  try {
    run(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const scallop::InputError&) {
  }
  return 0;
}
