// The validation run: reproduces seed 000 Tables 2-5 and seed 001 Tables 1-4 with the
// simulated truth beside the printed values, writes each table as CSV and one SVG
// picture per condition (the simulated cross-feed profile with every procedure's L/2
// and the target h marked). `scallop validate` is this plus its command line
// (tools/cli/validate_command.cpp); the Python module's validate() calls it too.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tools/run/validation_table.h"

namespace scallop {

struct ValidationSettings {
  std::string outDir = "scallop-validation";  // created if missing; other files left alone
};

struct ValidationResult {
  std::vector<ValidationTable> tables;  // seed 000 Tables 2-5, then seed 001 Tables 1-4
  std::vector<std::string> pictures;    // written, relative to outDir: "profiles/....svg"
  // What `validate --json` prints: {"output_dir", "tables": {name: {"title", "file",
  // "rows": [{column: cell}]}}, "pictures", "units"}.
  nlohmann::json document;
};

// Writes outDir/NAME.csv for every table and outDir/profiles/*.svg. Throws InputError
// for a folder that cannot be made or written.
ValidationResult runValidation(const ValidationSettings& settings);

}  // namespace scallop
