// The validation run (tools/run/validation_run.h) called directly: every table written
// as its CSV, the pictures, the document `validate --json` prints, the cell texts, and
// a folder that cannot be written.
#include "tools/run/validation_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "base/input_error.h"
#include "tests/support/temp_folder.h"
#include "tools/run/validation_table.h"

namespace scallop {
namespace {

namespace fs = std::filesystem;

std::string slurpFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

class ValidationRun : public test::TempFolderTest {
 protected:
  ValidationRun() : TempFolderTest("validation-run") {}
};

TEST_F(ValidationRun, WritesEveryTableAndPictureItReturns) {
  ValidationSettings s;
  s.outDir = (dir_ / "out").string();
  const ValidationResult r = runValidation(s);
  ASSERT_EQ(r.tables.size(), 9u);
  const char* const names[] = {"seed000_table2", "seed000_table3", "seed000_table4",
                               "seed000_table5", "seed001_table1", "seed001_table2",
                               "seed001_table3", "seed001_table4", "any_cutter"};
  for (size_t k = 0; k < r.tables.size(); ++k) {
    const ValidationTable& t = r.tables[k];
    EXPECT_EQ(t.name, names[k]);
    EXPECT_FALSE(t.rows.empty()) << t.name;
    for (const auto& row : t.rows) EXPECT_EQ(row.size(), t.columns.size()) << t.name;
    EXPECT_EQ(slurpFile(fs::path(s.outDir) / (t.name + ".csv")), tableCsv(t)) << t.name;
    const nlohmann::json& doc = r.document["tables"][t.name];
    EXPECT_EQ(doc["title"], t.title);
    EXPECT_EQ(doc["file"], t.name + ".csv");
    ASSERT_EQ(doc["rows"].size(), t.rows.size()) << t.name;
    EXPECT_EQ(doc["rows"][0][t.columns[0]], t.rows[0][0]) << t.name;
  }
  // any_cutter: the exact procedure's L/2 is the simulated one to 1e-9 mm and leaves h.
  const ValidationTable& any = r.tables.back();
  int exactRows = 0;
  for (const auto& row : any.rows) {
    if (row[7] != "exact") continue;
    ++exactRows;
    EXPECT_NEAR(row[10].get<double>(), 0, 1e-6) << row[0];  // um
    EXPECT_NEAR(row[12].get<double>(), 0, 1e-6) << row[0];  // um
  }
  EXPECT_EQ(exactRows, 5);
  EXPECT_EQ(r.pictures.size(), 24u);
  for (const std::string& p : r.pictures) {
    EXPECT_EQ(p.rfind("profiles/", 0), 0u) << p;
    EXPECT_EQ(slurpFile(fs::path(s.outDir) / p).rfind("<svg", 0), 0u) << p;
  }
  EXPECT_EQ(r.document["pictures"].size(), r.pictures.size());
  EXPECT_EQ(r.document["output_dir"], s.outDir);
  EXPECT_EQ(r.document["units"]["error"], "um");
}

TEST(ValidationTableText, CellsAsPeopleReadThemAndAsCsv) {
  EXPECT_EQ(tableCellText(nullptr, "h_mm"), "");
  EXPECT_EQ(tableCellText("sekine", "procedure"), "sekine");
  EXPECT_EQ(tableCellText(3, "condition"), "3");
  EXPECT_EQ(tableCellText(-0.0001, "scallop_error_um"), "+0.000");  // no "-0.000"
  EXPECT_EQ(tableCellText(1.23456, "scallop_error_um"), "+1.235");
  EXPECT_EQ(tableCellText(0.5, "printed_half_interval_mm"), "0.5");
  EXPECT_EQ(tableCellText(0.5, "computed_half_interval_mm"), "0.500000");

  ValidationTable t{"t", "a table", {"name", "value_um", "note"}, {}};
  t.rows.push_back({"a,b", 1.0 / 3, nullptr});
  t.rows.push_back({"c", 2, "n/a"});
  EXPECT_EQ(tableCsv(t), "name,value_um,note\n\"a,b\",0.333333333,\nc,2,n/a\n");
}

TEST_F(ValidationRun, AFolderThatCannotBeMadeIsBadInput) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "blocker") << "x";
  ValidationSettings s;
  s.outDir = (dir_ / "blocker" / "sub").string();
  try {
    runValidation(s);
    ADD_FAILURE() << "wrote into a file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("blocker"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace scallop
