// A table of the validation run (tools/run/validation_run.h): named columns and rows of
// JSON cells (numbers, strings, null for "not applicable"), with the text of a cell as
// people read it and the table's CSV file.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace scallop {

struct ValidationTable {
  std::string name, title;  // name: the CSV file's stem, e.g. "seed000_table2"
  std::vector<std::string> columns;
  std::vector<std::vector<nlohmann::json>> rows;
};

// A cell as printed: micrometre columns ("..._um") with 3 decimals, printed values their
// own digits, other numbers 6 decimals, null empty.
std::string tableCellText(const nlohmann::json& value, const std::string& column);

// The CSV file's text: a header row, numbers with 9 significant digits, cells holding a
// comma or a quote quoted.
std::string tableCsv(const ValidationTable& table);

}  // namespace scallop
