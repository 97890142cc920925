#include "tools/run/validation_table.h"

#include <fmt/core.h>

#include <cmath>

namespace scallop {

using nlohmann::json;

// Micrometre columns get 3 decimals, printed values their own digits, the rest 6.
std::string tableCellText(const json& v, const std::string& column) {
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  if (!v.is_number_float()) return v.dump();
  const double d = v.get<double>();
  if (column.size() > 3 && column.compare(column.size() - 3, 3, "_um") == 0)
    return fmt::format("{:+.3f}", std::fabs(d) < 5e-4 ? 0.0 : d);  // no "-0.000"
  if (column.rfind("printed", 0) == 0 || column == "rho_deg" || column == "h_mm" ||
      column.rfind("radius", 0) == 0 || column.rfind("corner", 0) == 0 || column == "lead_deg")
    return fmt::format("{:g}", d);
  return fmt::format("{:.6f}", d);
}

std::string tableCsv(const ValidationTable& t) {
  std::string s;
  for (size_t c = 0; c < t.columns.size(); ++c) s += (c ? "," : "") + t.columns[c];
  s += "\n";
  for (const auto& row : t.rows) {
    for (size_t c = 0; c < row.size(); ++c) {
      std::string cell = row[c].is_number_float() ? fmt::format("{:.9g}", row[c].get<double>())
                                                  : tableCellText(row[c], t.columns[c]);
      if (cell.find_first_of(",\"") != std::string::npos) cell = "\"" + cell + "\"";
      s += (c ? "," : "") + cell;
    }
    s += "\n";
  }
  return s;
}

}  // namespace scallop
