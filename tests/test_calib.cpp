// The stereo rig check with an AprilTag board: accuracy on rendered pairs, wrong rigs flagged,
// bad input refused.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "pm/calib/StereoBaseline.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/sim/Scene.h"

using pm::test::runProgram;
using pm::test::TempDir;

TEST(TagBoard, LayoutAndRendering)
{
  pm::calib::TagBoard b;
  EXPECT_DOUBLE_EQ(b.widthMm(), 3 * 55 + 20);
  const auto c = b.corners(4); // the centre tag
  EXPECT_NEAR(c[0].get_oX(), -0.02, 1e-12);
  EXPECT_NEAR(c[2].get_oY(), 0.02, 1e-12);
  const vpImage<vpRGBa> img = b.render(4.0);
  EXPECT_EQ(img.getWidth(), 740u);
  EXPECT_EQ(img[0][0].R, 255); // white margin
  EXPECT_EQ(img[370][370 - 78].R, 0); // the black border of the centre tag, 0.5 mm inside its edge at x = -19.5 mm
  pm::calib::TagBoard bad;
  bad.pitchMm = 45; // tags would overlap
  EXPECT_THROW(bad.validate(), pm::Error);
}

TEST(StereoBaseline, RenderedPairsGiveTheRigWithinHalfAMillimetreAndATenthOfADegree)
{
  TempDir d("calib");
  const auto r = runProgram("pm-calib-baseline", "--simulate 10 --quiet --out " + d.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto s = nlohmann::json::parse(pm::test::readText(d.file("summary.json")));
  EXPECT_LT(std::fabs(s.at("baseline_error_mm").get<double>()), 0.5);
  EXPECT_LT(s.at("translation_error_mm").get<double>(), 0.5);
  EXPECT_LT(s.at("rotation_error_deg").get<double>(), 0.1);
  EXPECT_LE(s.at("n_pairs_used").get<int>(), 10);
  EXPECT_GE(s.at("n_pairs_used").get<int>(), 8);
  EXPECT_LT(s.at("reprojection_rms_px").get<double>(), 0.5);
}

TEST(StereoBaseline, ARigFileOffByFiveMillimetresOrOneDegreeIsFlagged)
{
  TempDir d("calib");
  ASSERT_EQ(runProgram("pm-make-rig", "--quiet --baseline-mm 328 --out " + d.file("b")).status, 0);
  ASSERT_EQ(runProgram("pm-make-rig", "--quiet --toe-in-deg 18.4005 --out " + d.file("r")).status, 0); // 1 deg between the cameras
  const auto b = runProgram("pm-calib-baseline", "--simulate 6 --quiet --rig " + d.file("b/rig.json") + " --out " + d.file("ob"));
  EXPECT_EQ(b.status, 3) << b.err;
  const auto sb = nlohmann::json::parse(pm::test::readText(d.file("ob/summary.json")));
  EXPECT_NEAR(sb.at("baseline_error_mm").get<double>(), -5.0, 0.5);
  const auto r = runProgram("pm-calib-baseline", "--simulate 6 --quiet --rig " + d.file("r/rig.json") + " --out " + d.file("or"));
  EXPECT_EQ(r.status, 3) << r.err;
  const auto sr = nlohmann::json::parse(pm::test::readText(d.file("or/summary.json")));
  EXPECT_NEAR(sr.at("rotation_error_deg").get<double>(), 1.0, 0.1);
}

TEST(StereoBaseline, BadInputIsAClearError)
{
  TempDir d("calib");
  const pm::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  pm::calib::TagBoard board;
  // A pair with the board in the left image only, a pair with no board, a pair of different sizes.
  pm::sim::TargetShape shape = pm::sim::targetFromImage(board.render(8.0), board.widthMm(), 0, "board");
  shape.originCol = (shape.cols - 1) / 2.0;
  shape.originRow = (shape.rows - 1) / 2.0;
  pm::sim::SceneParams sp;
  sp.supersampling = 2;
  const pm::sim::Scene scene(shape, sp);
  const auto im = scene.renderStereo(rig, vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), 0);
  const vpImage<vpRGBa> blank(480, 640, vpRGBa(40, 90, 160)), small(240, 320, vpRGBa(40, 90, 160));
  pm::io::writeImage(im.left, d.file("L_0.png"));
  pm::io::writeImage(blank, d.file("R_0.png"));
  EXPECT_NE(pm::test::errorOf([&] { pm::calib::findBoard(blank, rig.left.cam, board, "test"); }).find("0 of its tags"),
            std::string::npos);
  auto run = [&](const std::string &l, const std::string &r, const std::string &extra = "") {
    return runProgram("pm-calib-baseline", "--left-images " + d.file(l) + " --right-images " + d.file(r) + extra + " --out " + d.file("o"));
  };
  auto expectError = [](const pm::test::RunResult &r, const std::string &fragment) {
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
  };
  expectError(run("L_%d.png", "R_%d.png"), "right image"); // the tag found in the left image only
  pm::io::writeImage(blank, d.file("L_0.png"));
  expectError(run("L_%d.png", "R_%d.png"), "0 of its tags");
  pm::io::writeImage(small, d.file("R_0.png"));
  expectError(run("L_%d.png", "R_%d.png"), "differ in size");
  expectError(run("X_%d.png", "Y_%d.png"), "no image pair");
  pm::test::writeText(d.file("norig.json"), R"({"format":"visp-photomodel-rig","version":1,"intrinsics_xml":"missing.xml","cameras":[]})");
  expectError(run("L_%d.png", "R_%d.png", " --rig " + d.file("norig.json")), "missing.xml");
  EXPECT_FALSE(std::filesystem::exists(d.file("o/summary.json")));
}

TEST(StereoBaseline, HandEyeFromThePA10MovingInFrontOfTheBoard)
{
  TempDir d("calib");
  const auto r = runProgram("pm-calib-baseline", "--simulate 4 --hand-eye 30 --quiet --out " + d.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto s = nlohmann::json::parse(pm::test::readText(d.file("summary.json")));
  for (const char *c : {"left", "right"}) {
    EXPECT_LT(s.at("hand_eye").at(c).at("translation_error_mm").get<double>(), 3.0) << c;
    EXPECT_LT(s.at("hand_eye").at(c).at("rotation_error_deg").get<double>(), 0.5) << c;
    EXPECT_GE(s.at("hand_eye").at(c).at("poses").get<int>(), 5) << c;
  }
}
