#include "tools/cli/collect_command.h"

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "base/input_error.h"
#include "tools/cli/command.h"
#include "tools/io/atomic_file.h"

namespace scallop {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// The measurement columns when --columns is not given; those that no report has (the
// scallop of a run that is not a raster, say) are left out.
const std::vector<std::string> kDefaultColumns = {
    "measurements.min_height",
    "measurements.max_height",
    "measurements.max_scallop_height",
    "measurements.floor_z",
    "measurements.exact_evaluations_per_cell",
    "surface_stats.Sa_mm",
    "surface_stats.Sq_mm",
    "surface_stats.Sz_mm",
    "feed_marks.peak_to_valley_um",
    "feed_marks.mean_spacing_mm",
    "feed_marks.predicted.peak_to_valley_um",
    "grid.nx",
    "grid.ny",
    "threads",
    "timings_s.total",
};

// A report flattened to its leaves, in document order: "tool.radius",
// "stock.min[0]", ...
using Flat = std::vector<std::pair<std::string, json>>;

void flatten(const json& value, const std::string& name, Flat& out) {
  if (value.is_object() && !value.empty()) {
    for (const auto& [key, child] : value.items())
      flatten(child, name.empty() ? key : name + "." + key, out);
  } else if (value.is_array() && !value.empty()) {
    for (size_t i = 0; i < value.size(); ++i)
      flatten(value[i], fmt::format("{}[{}]", name, i), out);
  } else {
    out.emplace_back(name, value);
  }
}

// `key` is `column` or lies beneath it (column.x, column[2]).
bool under(const std::string& key, const std::string& column) {
  if (column.empty()) return true;
  return key.compare(0, column.size(), column) == 0 &&
         (key.size() == column.size() || key[column.size()] == '.' || key[column.size()] == '[');
}

struct Run {
  std::string name;  // as given on the command line
  json report;
  Flat inputs, all;
};

Run readRun(const std::string& given) {
  const fs::path file = fs::is_directory(given) ? fs::path(given) / "report.json" : fs::path(given);
  std::ifstream in(file, std::ios::binary);
  if (!in || fs::is_directory(file))
    throw InputError(file.string(), fs::exists(file) ? "cannot read the report"
                                                     : "missing: no report.json (is it the "
                                                       "output folder of `scallop simulate`?)");
  Run run;
  run.name = given;
  try {
    run.report = json::parse(in);
  } catch (const json::exception& e) {
    throw InputError(file.string(), std::string("damaged report (not JSON): ") + e.what());
  }
  if (!run.report.is_object() || !run.report.contains("inputs") ||
      !run.report["inputs"].is_object())
    throw InputError(file.string(),
                     "not the report of a simulation run: expected an object with \"inputs\"");
  flatten(run.report["inputs"], "", run.inputs);
  flatten(run.report, "", run.all);
  return run;
}

// Column names in the order they first appear, over all runs.
void addColumns(const Flat& flat, const std::string& within, std::vector<std::string>& columns,
                std::set<std::string>& seen) {
  for (const auto& [key, value] : flat)
    if (under(key, within) && seen.insert(key).second) columns.push_back(key);
}

std::string csvCell(const json& value) {
  if (value.is_null()) return "";
  const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csvRow(const std::vector<std::string>& cells) {
  std::string line;
  for (size_t i = 0; i < cells.size(); ++i) line += (i ? "," : "") + cells[i];
  return line + "\n";
}

}  // namespace

int runCollect(const CollectArgs& args) {
  std::vector<Run> runs;
  for (const std::string& dir : args.dirs) runs.push_back(readRun(dir));

  // Inputs: every leaf of any run's "inputs". Measurements: the leaves beneath each
  // chosen report path that some run has.
  std::vector<std::string> inputColumns, measureColumns;
  std::set<std::string> seenInputs, seenMeasures;
  for (const Run& run : runs) addColumns(run.inputs, "", inputColumns, seenInputs);
  const bool chosen = !args.columns.empty();
  for (const std::string& column : chosen ? args.columns : kDefaultColumns) {
    bool found = false;
    for (const Run& run : runs) {
      addColumns(run.all, column, measureColumns, seenMeasures);
      for (const auto& leaf : run.all) found = found || under(leaf.first, column);
    }
    if (chosen && (column.empty() || !found))
      throw InputError("--columns",
                       fmt::format("'{}' is in none of the {} reports (a report.json path such as "
                                   "measurements.max_scallop_height or surface_stats.Sq_mm)",
                                   column, runs.size()));
  }

  std::vector<std::string> header = {"run", "job"};
  for (const std::string& c : inputColumns) header.push_back(c);
  for (const std::string& c : measureColumns) header.push_back(c);
  std::vector<std::string> quotedHeader;
  for (const std::string& h : header) quotedHeader.push_back(csvCell(h));
  std::string table = csvRow(quotedHeader);
  for (const Run& run : runs) {
    std::map<std::string, json> inputs(run.inputs.begin(), run.inputs.end());
    std::map<std::string, json> all(run.all.begin(), run.all.end());
    std::vector<std::string> cells = {csvCell(run.name),
                                      csvCell(run.report.value("job_source", json()))};
    for (const std::string& c : inputColumns) cells.push_back(csvCell(inputs[c]));
    for (const std::string& c : measureColumns) cells.push_back(csvCell(all[c]));
    table += csvRow(cells);
  }

  if (args.output.empty()) {
    std::fputs(table.c_str(), stdout);
  } else {
    writeTextAtomically(args.output, table, "the table");
    std::fprintf(stderr, "scallop: wrote %zu runs x %zu columns to %s\n", runs.size(),
                 header.size(), args.output.c_str());
  }
  return 0;
}

Command addCollectCommand(CLI::App& parent, CommonOptions&) {
  auto args = std::make_shared<CollectArgs>();
  auto columnsText = std::make_shared<std::string>();
  CLI::App* app = parent.add_subcommand(
      "collect",
      "Gather many runs' report.json files into one CSV table.\n"
      "Gather the report.json files of many runs (a parameter study: one output folder\n"
      "per job) into one CSV table, a row per run: run (the folder), job, the job's inputs\n"
      "flattened (tool.radius, stock.min[0], path.raster.step_over, ...; mm and degrees as\n"
      "in the job), then the measurements chosen with --columns. Every report is checked\n"
      "first: a folder without report.json, or a damaged one, fails (exit 1) naming it,\n"
      "and no table is written.");
  app->add_option("DIR", args->dirs, "Output folders of `scallop simulate` (or report.json files)")
      ->required();
  app->add_option("-o,--output", args->output,
                  "CSV file to write (atomically); default: the table on stdout");
  app->add_option("--columns", *columnsText,
                  "Comma-separated report.json paths to put after the inputs; an object gives\n"
                  "all its leaves (e.g. measurements,surface_stats.Sq_mm,timings_s.total).\n"
                  "Default: measurements min/max_height, max_scallop_height, floor_z,\n"
                  "exact_evaluations_per_cell, surface_stats Sa/Sq/Sz_mm, grid.nx/ny, threads,\n"
                  "timings_s.total (those some report has)");
  return {app, [args, columnsText]() {
            // One argument, split at commas, so that DIRs after it stay DIRs.
            std::string column;
            for (const char c : *columnsText + ",")
              if (c != ',') {
                column += c;
              } else if (!column.empty()) {
                args->columns.push_back(column);
                column.clear();
              }
            if (!columnsText->empty() && args->columns.empty())
              throw InputError("--columns", "'" + *columnsText + "': expected report.json paths");
            return runCollect(*args);
          }};
}

}  // namespace scallop
