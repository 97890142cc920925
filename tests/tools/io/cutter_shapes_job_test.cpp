// The job keys of every cutter shape (tools/io/job_cutter_shapes.h): each type read
// into the chain its builder makes, echoed with its profile, a free profile read
// segment by segment, unknown keys and bad values refused naming the field; and a CL
// file with each kind of 7-value CUTTER giving the same Cutter as the job's "apt" tool.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "base/constants.h"
#include "base/input_error.h"
#include "sweep/apt_cutter.h"
#include "sweep/cutter_shapes.h"
#include "tests/support/input_error_message.h"
#include "tools/io/apt_reader.h"
#include "tools/io/job_cutters.h"

namespace scallop {
namespace {

using nlohmann::json;

Cutter parse(const std::string& text) {
  return parseCutter(json::parse(text), "tool");
}

std::string errorOf(const std::string& text) {
  return inputErrorMessage([&] { parse(text); });
}

void expectChain(const Cutter& cutter, const std::vector<ProfileSegment>& chain) {
  ASSERT_TRUE(cutter.general());
  const auto& got = cutter.profile->segments();
  ASSERT_EQ(got.size(), chain.size());
  for (size_t i = 0; i < got.size(); ++i) {
    EXPECT_NEAR(got[i].rho1, chain[i].rho1, 1e-9) << i;
    EXPECT_NEAR(got[i].s1, chain[i].s1, 1e-9) << i;
    EXPECT_EQ(got[i].arcRadius, chain[i].arcRadius) << i;
  }
}

TEST(CutterShapesJob, EachTypeReadsIntoItsChain) {
  const Cutter taperBall =
      parse(R"({"type": "taper_ball", "tip_radius": 2, "taper_deg": 5, "flute_length": 30})");
  EXPECT_EQ(taperBall.type, CutterType::TaperBall);
  TaperBallShape tb;
  tb.tipRadius = 2, tb.taperDeg = 5, tb.fluteLength = 30;
  expectChain(taperBall, taperBallChain(tb, "tool"));
  EXPECT_EQ(taperBall.fluteLength, 30);
  EXPECT_NEAR(taperBall.radius, taperBall.profile->segments().back().rho1, 1e-12);
  EXPECT_EQ(taperBall.cornerRadius, 0);

  const Cutter cone = parse(R"({"type": "cone", "angle_deg": 90, "diameter": 6, "flute_length": 10,
                "flutes": 3})");
  EXPECT_EQ(cone.type, CutterType::Cone);
  EXPECT_EQ(cone.teeth.flutes, 3);
  EXPECT_EQ(cone.radius, 3);

  BarrelShape barrel;
  barrel.diameter = 12, barrel.formRadius = 85, barrel.tipRadius = 1, barrel.fluteLength = 10;
  expectChain(parse(R"({"type": "barrel", "diameter": 12, "form_radius": 85, "tip_radius": 1,
                        "flute_length": 10})"),
              barrelChain(barrel, "tool"));
  TaperBarrelShape taperBarrel;
  taperBarrel.tipRadius = 2, taperBarrel.formRadius = 250, taperBarrel.taperDeg = 10;
  taperBarrel.referenceDiameter = 8, taperBarrel.fluteLength = 20;
  expectChain(parse(R"({"type": "taper_barrel", "tip_radius": 2, "form_radius": 250,
                        "taper_deg": 10, "reference_diameter": 8, "flute_length": 20})"),
              taperBarrelChain(taperBarrel, "tool"));
  EXPECT_EQ(parse(R"({"type": "oval", "diameter": 10, "form_radius": 30, "tip_radius": 2,
                      "flute_length": 12})")
                .type,
            CutterType::Oval);
  EXPECT_EQ(parse(R"({"type": "lens", "diameter": 10, "form_radius": 20, "corner_radius": 1,
                      "flute_length": 15})")
                .type,
            CutterType::Lens);
  EXPECT_EQ(parse(R"({"type": "taper_bull", "tip_diameter": 6, "corner_radius": 1,
                      "taper_deg": 10, "flute_diameter": 10})")
                .type,
            CutterType::TaperBull);
}

TEST(CutterShapesJob, FreeProfileAndEcho) {
  const Cutter c = parse(R"({"type": "profile", "segments": [
      {"to": [2, 0]}, {"to": [3, 1], "arc_radius": 1}, {"to": [3, 8]}]})");
  EXPECT_EQ(c.type, CutterType::Profile);
  ASSERT_EQ(c.profile->segments().size(), 3u);
  EXPECT_EQ(c.profile->segments()[1].rho0, 2);
  EXPECT_EQ(c.profile->segments()[1].arcRadius, 1);
  EXPECT_EQ(c.fluteLength, 8);
  EXPECT_EQ(c.radius, 3);
  const json echo = cutterToJson(c);
  EXPECT_EQ(echo["type"], "profile");
  ASSERT_EQ(echo["segments"].size(), 3u);
  EXPECT_EQ(echo["segments"][1]["from"], json({2, 0}));
  EXPECT_EQ(echo["segments"][1]["arc_radius"], 1);
  EXPECT_FALSE(echo["segments"][0].contains("arc_radius"));
  // Ball, flat and bull echo as before, without segments.
  EXPECT_FALSE(cutterToJson(Cutter::make(CutterType::Ball, 1)).contains("segments"));
}

TEST(CutterShapesJob, ErrorsNameTheField) {
  EXPECT_NE(errorOf(R"({"type": "taper_ball", "tip_radius": 2, "taper_deg": 5,
                        "flute_length": 30, "radius": 3})")
                .find("tool.radius"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "taper_ball", "tip_radius": 2, "flute_length": 30})")
                .find("tool.taper_deg"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "cone", "angle_deg": 0, "diameter": 6, "flute_length": 10})")
                .find("tool.angle_deg"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "cylinder", "radius": 3})").find("tool.type"), std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "profile", "segments": []})").find("tool.segments"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "profile", "segments": [{"to": [1, 0]}, {"to": [1]}]})")
                .find("tool.segments[1].to"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "profile", "segments": [{"to": [1, 0], "arc_radius": -1}]})")
                .find("tool.segments[0].arc_radius"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "apt", "d": 6, "r": 1, "e": 2.5, "f": 1, "a": 0, "b": 0,
                        "h": 20})")
                .find("tool.e"),
            std::string::npos);
  EXPECT_NE(
      errorOf(R"({"type": "apt", "d": 6, "r": 1, "e": 2, "f": 1, "a": 0, "h": 20})").find("tool.b"),
      std::string::npos);
}

// A CL file's 7-value CUTTER and the job's "apt" tool with the same values are the same
// cutter, for each kind the convention describes.
TEST(CutterShapesJob, AptCutterInAClFileEqualsTheJobs) {
  const double tbD = 2 * 1.5 * (1 - std::sin(degToRad(7))) / std::cos(degToRad(7));
  const std::vector<std::vector<double>> kinds = {
      {6, 3, 0, 3, 0, 0, 20},                            // ball
      {6, 0, 0, 0, 0, 0, 20},                            // flat
      {6, 1, 2, 1, 0, 0, 20},                            // bull
      {tbD, 1.5, 0, 1.5, 0, 7, 25},                      // tapered ball
      {6, 1, 3 - 0.8390996311772800, 1, 0, 10, 20},      // tapered bull
      {6, 0, 0, 0, 30, 0, 10},                           // 120-degree V-bit
      {6, 1, 2, 2 / std::cos(degToRad(30)), 30, 0, 10},  // bottom cone, rounded corner
  };
  for (const auto& v : kinds) {
    std::ostringstream cl;
    cl.precision(17);
    cl << "CUTTER/" << v[0] << "," << v[1] << "," << v[2] << "," << v[3] << "," << v[4] << ","
       << v[5] << "," << v[6] << "\nGOTO/0,0,0\n";
    std::istringstream in(cl.str());
    ToolPathFile file;
    readApt(in, "t.cl", file);
    json tool = {{"type", "apt"}, {"d", v[0]}, {"r", v[1]}, {"e", v[2]},
                 {"f", v[3]},     {"a", v[4]}, {"b", v[5]}, {"h", v[6]}};
    const Cutter fromJob = parseCutter(tool, "tool");
    ASSERT_TRUE(file.cutter.has_value()) << cl.str();
    EXPECT_TRUE(sameShape(*file.cutter, fromJob)) << cl.str();
  }
  // The end mills are their own types (their kernel, their heights).
  std::istringstream ball("CUTTER/6,3,0,3,0,0,20\nGOTO/0,0,0\n");
  ToolPathFile file;
  readApt(ball, "t.cl", file);
  EXPECT_EQ(file.cutter->type, CutterType::Ball);
}

TEST(CutterShapesJob, InvalidClCutterNamesTheLineAndValue) {
  auto error = [](const std::string& text) {
    return inputErrorMessage([&] {
      std::istringstream in(text);
      ToolPathFile file;
      readApt(in, "t.cl", file);
    });
  };
  const std::string notTangent = error("PARTNO/X\nCUTTER/6,1,2.5,1,0,0,20\nGOTO/0,0,0\n");
  EXPECT_NE(notTangent.find("t.cl:2"), std::string::npos) << notTangent;
  EXPECT_NE(notTangent.find("CUTTER.e"), std::string::npos) << notTangent;
  EXPECT_NE(error("CUTTER/6,1,2,1,50,45,20\nGOTO/0,0,0\n").find("CUTTER.b"), std::string::npos);
}

}  // namespace
}  // namespace scallop
