// `scallop validate`: the validation run. Reproduces seed 000 Tables 2-5 and seed 001
// Tables 1-4 with the simulated truth beside the printed values, writes each table as
// CSV and one SVG picture per condition (the simulated cross-feed profile with every
// procedure's L/2 and the target h marked).
#pragma once

#include <string>

namespace scallop {

struct ValidateArgs {
  std::string outDir = "scallop-validation";
  bool json = false;  // print one JSON document with every table on stdout
};

// Returns the process exit status; throws InputError for bad input (the folder).
int runValidate(const ValidateArgs& args);

}  // namespace scallop
