// The cutter-shape table (tools/io/job_cutter_shapes.h): every entry's examples build,
// through the job parser, a cutter whose CutterType has the entry's name (apt: the type
// its values describe); each required
// key left out and an unknown key are refused naming the field, and an unknown type
// lists every type of the table. `scallop cutter --list` and
// `--pictures` print the table.
#include "tools/io/job_cutter_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "tests/support/cli_harness.h"
#include "tests/support/input_error_message.h"
#include "tools/io/job_cutters.h"

namespace scallop::test {
namespace {

using nlohmann::json;

TEST(CutterShapeTable, EveryExampleBuildsItsType) {
  std::set<std::string> types;
  for (const CutterShape& shape : cutterShapes()) {
    EXPECT_TRUE(types.insert(shape.type).second) << shape.type << " twice";
    EXPECT_EQ(findCutterShape(shape.type), &shape);
    ASSERT_FALSE(shape.pictures.empty()) << shape.type;
    for (const CutterPicture& picture : shape.pictures) {
      const Cutter cutter = parseCutter(json::parse(picture.tool), "tool");
      // An APT CUTTER/ becomes the type it describes (ball, flat, bull or a profile).
      if (std::string(shape.type) != "apt") {
        EXPECT_STREQ(toString(cutter.type), shape.type) << picture.tool;
      }
      EXPECT_GT(cutter.radius, 0) << picture.tool;
      EXPECT_GT(cutter.fluteLength, 0) << picture.tool;
    }
  }
  EXPECT_EQ(findCutterShape("inserts"), nullptr);
}

TEST(CutterShapeTable, RequiredKeysAreRequiredAndOthersRefused) {
  for (const CutterShape& shape : cutterShapes()) {
    const json example = json::parse(shape.pictures.front().tool);
    for (const CutterKey& key : shape.keys) {
      if (!key.required) continue;
      json without = example;
      without.erase(key.name);
      expectRejected([&] { parseCutter(without, "tools.3"); },
                     std::string("tools.3.") + key.name);
    }
    json extra = example;
    extra["colour"] = "red";
    const std::string message = inputErrorMessage([&] { parseCutter(extra, "tool"); });
    EXPECT_NE(message.find("tool.colour: unknown key"), std::string::npos) << message;
    for (const CutterKey& key : shape.keys)
      EXPECT_NE(message.find(key.name), std::string::npos) << shape.type << ": " << message;
  }
}

TEST(CutterShapeTable, AnUnknownTypeListsEveryType) {
  const std::string message =
      inputErrorMessage([] { parseCutter(json{{"type", "drill"}}, "tool"); });
  EXPECT_NE(message.find("tool.type: unknown cutter type \"drill\", expected " + cutterTypeList()),
            std::string::npos)
      << message;
  for (const CutterShape& shape : cutterShapes())
    EXPECT_NE(cutterTypeList().find(shape.type), std::string::npos) << shape.type;
}

class CutterList : public CliFixture {};

TEST_F(CutterList, ListAndPicturesPrintTheTable) {
  const CliRun list = run("cutter --list --json");
  ASSERT_EQ(list.status, 0) << list.err;
  const json doc = json::parse(list.out);
  ASSERT_EQ(doc.size(), cutterShapes().size());
  size_t pictures = 0;
  for (size_t k = 0; k < doc.size(); ++k) {
    EXPECT_EQ(doc[k]["type"], cutterShapes()[k].type);
    EXPECT_EQ(doc[k]["keys"].size(), cutterShapes()[k].keys.size());
    pictures += cutterShapes()[k].pictures.size();
  }
  const CliRun lines = run("cutter --pictures");
  ASSERT_EQ(lines.status, 0) << lines.err;
  EXPECT_EQ(size_t(std::count(lines.out.begin(), lines.out.end(), '\n')), pictures);
  EXPECT_EQ(size_t(std::count(lines.out.begin(), lines.out.end(), '\t')), 2 * pictures);
  EXPECT_EQ(run("cutter").status, 2);
  EXPECT_EQ(run("cutter --list '{\"type\": \"ball\", \"radius\": 1}'").status, 2);
}

}  // namespace
}  // namespace scallop::test
