#include "tools/cli/validate_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tools/cli/command.h"
#include "tools/run/validation_run.h"
#include "tools/run/validation_table.h"

namespace scallop {

namespace {

void printTable(const ValidationTable& t) {
  std::vector<size_t> width(t.columns.size());
  for (size_t c = 0; c < t.columns.size(); ++c) width[c] = t.columns[c].size();
  for (const auto& row : t.rows)
    for (size_t c = 0; c < row.size(); ++c)
      width[c] = std::max(width[c], tableCellText(row[c], t.columns[c]).size());
  std::printf("%s\n", t.title.c_str());
  for (size_t c = 0; c < t.columns.size(); ++c)
    std::printf("%s%-*s", c ? "  " : "", int(width[c]), t.columns[c].c_str());
  std::printf("\n");
  for (const auto& row : t.rows) {
    for (size_t c = 0; c < row.size(); ++c) {
      const std::string cell = tableCellText(row[c], t.columns[c]);
      const bool number = row[c].is_number();
      std::printf("%s%*s", c ? "  " : "", number ? int(width[c]) : -int(width[c]), cell.c_str());
    }
    std::printf("\n");
  }
  std::printf("\n");
}

// Runs the validation and prints every table (or the document with --json); returns the
// exit status.
int runValidateCommand(const ValidationSettings& settings, bool json) {
  const ValidationResult r = runValidation(settings);
  if (json) {
    std::printf("%s\n", r.document.dump(2).c_str());
    return 0;
  }
  for (const ValidationTable& t : r.tables) printTable(t);
  std::printf("wrote %zu CSV tables and %zu pictures into %s (profiles/*.svg)\n", r.tables.size(),
              r.pictures.size(), settings.outDir.c_str());
  return 0;
}

constexpr const char* kValidateHelp =
    "Reproduce the seeds' tables beside the simulated truth.\n"
    "The validation run: reproduces seed 000 Tables 2-5 and seed 001 Tables 1-4 with the\n"
    "simulated truth beside the printed values (the scallop each printed L/2 really\n"
    "leaves, um error against h; the exact L/2 for each h, mm). Writes DIR/seed000_table2.csv\n"
    "... seed000_table5.csv, DIR/seed001_table1.csv ... seed001_table4.csv (lengths in mm,\n"
    "errors in um) and one picture per condition, DIR/profiles/*.svg: the simulated\n"
    "cross-feed profile with the target h and each procedure's L/2 marked.";

}  // namespace

Command addValidateCommand(CLI::App& parent, CommonOptions& common) {
  auto args = std::make_shared<ValidationSettings>();
  auto json = std::make_shared<bool>(false);
  CLI::App* app = parent.add_subcommand("validate", kValidateHelp);
  app->add_option("-o,--output", args->outDir,
                  "Output folder, created if missing; other files in it are left alone")
      ->capture_default_str();
  app->add_flag("--json", *json,
                "Print every table as one JSON document on stdout (and nothing else there)");
  addThreadsOption(*app, common);
  return {app, [args, json]() { return runValidateCommand(*args, *json); }};
}

}  // namespace scallop
