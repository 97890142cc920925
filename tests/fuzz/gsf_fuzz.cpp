// libFuzzer target "gsf": see tests/fuzz/fuzz_targets.h for what it runs.
#include <cstddef>
#include <cstdint>
#include <string>

#include "base/input_error.h"
#include "tests/fuzz/fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto& run = scallop::fuzz::targets().at("gsf");
  try {
    run(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const scallop::InputError&) {
  }
  return 0;
}
