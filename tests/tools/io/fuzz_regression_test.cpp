// Replays every fuzzing input kept in the repository through the fuzz targets'
// functions (tests/fuzz/fuzz_targets.h) in the normal (and the sanitized) test suite:
// the seed corpus tests/fuzz/corpus/NAME/* and each finding, once fixed, saved as
// tests/fuzz/regressions/NAME/*. Each must return or throw InputError, nothing else.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "base/input_error.h"
#include "tests/fuzz/fuzz_targets.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

const fs::path kFuzzDir = fs::path(SCALLOP_SOURCE_DIR) / "tests" / "fuzz";

int replay(const std::string& folder) {
  int inputs = 0;
  for (const auto& [name, run] : fuzz::targets()) {
    const fs::path dir = kFuzzDir / folder / name;
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      SCOPED_TRACE(entry.path().string());
      std::ifstream in(entry.path(), std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      try {
        run(bytes.str());
      } catch (const InputError&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
      }
      ++inputs;
    }
  }
  return inputs;
}

TEST(FuzzRegression, SeedCorpusIsHandled) {
  EXPECT_GE(replay("corpus"), 10);
}

// tests/fuzz/CMakeLists.txt and scripts/fuzz.sh make a fuzzer of each corpus folder.
TEST(FuzzRegression, EachCorpusFolderNamesOneTarget) {
  std::set<std::string> folders;
  for (const auto& entry : fs::directory_iterator(kFuzzDir / "corpus")) {
    if (entry.is_directory()) folders.insert(entry.path().filename().string());
  }
  std::set<std::string> names;
  for (const auto& target : fuzz::targets()) names.insert(target.first);
  EXPECT_EQ(folders, names);
}

TEST(FuzzRegression, EveryFixedFindingIsHandled) {
  replay("regressions");
}

}  // namespace
}  // namespace scallop
