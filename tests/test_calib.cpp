// The stereo rig check with an AprilTag board: accuracy on rendered pairs, wrong rigs flagged,
// bad input refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "pm/calib/BaselineCheck.h"
#include "pm/calib/StereoBaseline.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/sim/Scene.h"

#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpIoTools.h>
#include <visp3/detection/vpDetectorAprilTag.h>

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
  EXPECT_THROW(bad.validate(), pm::core::Error);
}

namespace {
//! The pattern as a flat target of the simulator, its frame at the pattern's centre.
pm::sim::Scene patternScene(const pm::calib::Pattern &pattern, unsigned supersampling = 2)
{
  pm::sim::SceneParams sp;
  sp.supersampling = supersampling;
  return pm::sim::Scene(pm::sim::flatPrint(pattern.render(8.0), pattern.widthMm(), "board"), sp);
}

//! Translation (mm) and rotation (deg) between two poses.
std::pair<double, double> poseError(const vpHomogeneousMatrix &a, const vpHomogeneousMatrix &b)
{
  return {(a.getTranslationVector() - b.getTranslationVector()).frobeniusNorm() * 1e3,
          (a.inverse() * b).getThetaUVector().getTheta() * 180 / M_PI};
}

//! Renders \e pattern seen by the left camera at hMo turned by \e turnDeg about the board's
//! normal and checks the pose found against the truth.
void expectPoseFound(const pm::calib::Pattern &pattern, double turnDeg, double tolMm, double tolDeg)
{
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  const pm::sim::Scene scene = patternScene(pattern);
  const vpHomogeneousMatrix hMo = vpHomogeneousMatrix(0.01, -0.01, 0.5, 0.1, -0.15, 0) *
                                  vpHomogeneousMatrix(0, 0, 0, 0, 0, turnDeg * M_PI / 180);
  pm::sim::Rasterizer raster;
  vpImage<vpRGBa> I;
  scene.render(raster, rig.left, hMo, 0, 0, I);
  const pm::calib::BoardView view = pattern.find(I, rig.left.cam, "test");
  const auto [dt, dr] = poseError(view.cMb, rig.left.cMh() * hMo);
  EXPECT_LT(dt, tolMm) << pattern.describe() << ", turned " << turnDeg << " deg";
  EXPECT_LT(dr, tolDeg) << pattern.describe() << ", turned " << turnDeg << " deg";
  EXPECT_LT(view.reprojectionRmsPx, 0.3);
}
//! Runs pm-calib-baseline with \e args into \e d and checks the issue's goal: the baseline within
//! 0.5 mm, the translation within 0.5 mm and the rotation within 0.1 deg of the rig that took the pictures.
nlohmann::json expectRigWithinGoal(const std::string &args, const TempDir &d)
{
  const auto r = runProgram("pm-calib-baseline", args + " --quiet --out " + d.path());
  EXPECT_EQ(r.status, 0) << r.err;
  const auto s = nlohmann::json::parse(pm::test::readText(d.file("summary.json")));
  EXPECT_LT(std::fabs(s.at("baseline_error_mm").get<double>()), 0.5) << args;
  EXPECT_LT(s.at("translation_error_mm").get<double>(), 0.5) << args;
  EXPECT_LT(s.at("rotation_error_deg").get<double>(), 0.1) << args;
  return s;
}
} // namespace

TEST(ChessBoard, LayoutAndRendering)
{
  pm::calib::ChessBoard b; // 6 x 9 inner corners, 20 mm squares, 20 mm margin
  EXPECT_DOUBLE_EQ(b.widthMm(), 10 * 20 + 40);
  EXPECT_DOUBLE_EQ(b.heightMm(), 7 * 20 + 40);
  EXPECT_NEAR(b.corner(0, 0).get_oX(), -0.08, 1e-12);
  EXPECT_NEAR(b.corner(5, 8).get_oY(), 0.05, 1e-12);
  const vpImage<vpRGBa> img = b.render(2.0); // 480 x 360
  ASSERT_EQ(img.getWidth(), 480u);
  EXPECT_EQ(img[10][10].R, 255);             // margin
  EXPECT_EQ(img[60][60].R, 0);               // the top-left square is black
  EXPECT_EQ(img[60][100].R, 255);            // its right neighbour white
  EXPECT_EQ(img[300][420].R, 255);           // the bottom-right square (row 6, col 9): 6 + 9 odd, white
  pm::calib::ChessBoard symmetric;
  symmetric.innerRows = 7; // 7 x 9: the same board when turned by 180 degrees
  EXPECT_NE(pm::test::errorOf([&] { symmetric.validate(); }).find("180"), std::string::npos);
}

TEST(ChessBoard, PoseFoundWhicheverWayTheBoardIsTurned)
{
  // OpenCV may list the corners from either end; the squares' colours must settle it.
  const pm::calib::ChessBoard chess;
  for (double turn : {0.0, 30.0, 90.0, 150.0, 180.0, 200.0, 270.0})
    expectPoseFound(chess, turn, 1.0, 0.2);
}

TEST(TagBoard, PoseFoundWhicheverWayTheBoardIsTurned)
{
  const pm::calib::TagBoard tags;
  for (double turn : {0.0, 90.0, 180.0, 270.0})
    expectPoseFound(tags, turn, 1.0, 0.2);
}

/*
  The single-camera tag pose against ViSP's own AprilTag benchmark (Debian package
  visp-images-data: AprilTag/benchmark/640x480, tags of family 36h11 with ground-truth poses
  cMo_<id>.txt; 700 px focal length, 200 mm tags for ids 0..2, 100 mm for 3 and 4, as in
  ViSP's testAprilTag). Runs only where the package is installed (or VISP_INPUT_IMAGE_PATH
  points at the data).
*/
TEST(TagBoard, ViSPAprilTagBenchmarkPoses)
{
  const std::string dir = vpIoTools::createFilePath(vpIoTools::getViSPImagesDataPath(), "AprilTag/benchmark/640x480");
  if (vpIoTools::getViSPImagesDataPath().empty() || !std::filesystem::exists(dir + "/tag36_11_640x480.png"))
    GTEST_SKIP() << "ViSP's images are not installed (apt-get install visp-images-data)";
  const vpImage<vpRGBa> I = pm::io::readColorImage(dir + "/tag36_11_640x480.png");
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(700, 700, 320, 240);
  // ViSP's tag frame has z out of the tag; ours (setZAlignedWithCameraAxis) z into it.
  const vpHomogeneousMatrix flip(0, 0, 0, M_PI, 0, 0);
  for (int id = 0; id < 5; ++id) {
    std::ifstream f(dir + "/cMo_" + std::to_string(id) + ".txt");
    ASSERT_TRUE(f.good()) << "cMo_" << id;
    vpHomogeneousMatrix truth;
    truth.load(f);
    pm::calib::TagBoard tag;
    tag.rows = tag.cols = 1;
    tag.firstId = id;
    tag.tagSizeMm = id < 3 ? 200 : 100;
    tag.pitchMm = 1.25 * tag.tagSizeMm;
    tag.minTags = 1;
    const pm::calib::BoardView view = tag.find(I, cam, "benchmark");
    const auto [dt, dr] = poseError(view.cMb, truth * flip);
    const double depthMm = truth.getTranslationVector().frobeniusNorm() * 1e3;
    // The peer: ViSP's detector's own pose of the same tag.
    vpImage<unsigned char> grey;
    vpImageConvert::convert(I, grey);
    vpDetectorAprilTag det(vpDetectorAprilTag::TAG_36h11);
    det.detect(grey);
    double visp[2] = {-1, -1};
    for (std::size_t i = 0; i < det.getNbObjects(); ++i)
      if (det.getMessage(i) == "36h11 id: " + std::to_string(id)) {
        vpHomogeneousMatrix cMt;
        det.getPose(i, tag.tagSizeMm * 1e-3, cam, cMt);
        std::tie(visp[0], visp[1]) = poseError(cMt, truth);
      }
    std::cout << "  benchmark tag " << id << " at " << depthMm << " mm: ours " << dt << " mm, " << dr << " deg ("
              << view.reprojectionRmsPx << " px); vpDetectorAprilTag::getPose " << visp[0] << " mm, " << visp[1] << " deg\n";
    // The benchmark's corners are not exact: ViSP's own pose is off by up to 0.65 % of the
    // distance (tag 2 at 3 m). Ours: within 1 % and half a degree, and as good as ViSP's.
    EXPECT_LT(dt, 0.01 * depthMm) << "tag " << id;
    EXPECT_LT(dr, 0.5) << "tag " << id;
    ASSERT_GE(visp[0], 0) << "ViSP's detector did not find tag " << id;
    EXPECT_LT(dt, visp[0] + 0.5) << "tag " << id;
    EXPECT_LT(dr, visp[1] + 0.02) << "tag " << id;
  }
}

TEST(StereoBaseline, RenderedPairsGiveTheRigWithinHalfAMillimetreAndATenthOfADegree)
{
  TempDir d("calib");
  const auto s = expectRigWithinGoal("--simulate 10", d);
  EXPECT_LE(s.at("n_pairs_used").get<int>(), 10);
  EXPECT_GE(s.at("n_pairs_used").get<int>(), 8);
  EXPECT_LT(s.at("reprojection_rms_px").get<double>(), 0.5);
}

TEST(StereoBaseline, AChessboardGivesTheRigToo)
{
  TempDir d("calib");
  const auto s = expectRigWithinGoal("--simulate 10 --pattern chessboard", d);
  EXPECT_NE(s.at("pattern").get<std::string>().find("chessboard"), std::string::npos);
  // A wrong layout is an error, not a wrong answer.
  const auto bad = runProgram("pm-calib-baseline", "--simulate 2 --pattern chessboard --board 6,8,20 --quiet --out " + d.file("o"));
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("180 degrees"), std::string::npos) << bad.err;
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
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  pm::calib::TagBoard board;
  // A pair with the board in the left image only, a pair with no board, a pair of different sizes.
  const pm::sim::Scene scene = patternScene(board);
  const auto im = scene.renderStereo(rig, vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), 0);
  const vpImage<vpRGBa> blank(480, 640, vpRGBa(40, 90, 160)), small(240, 320, vpRGBa(40, 90, 160));
  pm::io::writeImage(im.left, d.file("L_0.png"));
  pm::io::writeImage(blank, d.file("R_0.png"));
  EXPECT_NE(pm::test::errorOf([&] { board.find(blank, rig.left.cam, "test"); }).find("0 of its tags"),
            std::string::npos);
  auto run = [&](const std::string &l, const std::string &r, const std::string &extra = "") {
    return runProgram("pm-calib-baseline", "--left " + d.file(l) + " --right " + d.file(r) + extra + " --out " + d.file("o"));
  };
  auto expectError = [](const pm::test::RunResult &r, const std::string &fragment) {
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
  };
  expectError(run("L_%d.png", "R_%d.png"), "right image"); // the tag found in the left image only
  pm::io::writeImage(blank, d.file("L_0.png"));
  expectError(run("L_%d.png", "R_%d.png"), "0 of its tags");
  expectError(run("L_%d.png", "R_%d.png", " --pattern chessboard"), "not all found in the pair 0 left image");
  const auto usage = run("L_%d.png", "R_%d.png", " --pattern chessboard --board 6,9");
  EXPECT_EQ(usage.status, 2);
  EXPECT_NE(usage.err.find("--board: expects 3 comma-separated numbers"), std::string::npos) << usage.err;
  pm::io::writeImage(small, d.file("R_0.png"));
  expectError(run("L_%d.png", "R_%d.png"), "differ in size");
  expectError(run("X_%d.png", "Y_%d.png"), "no image " + d.file("X_0.png"));
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

TEST(BaselineCheck, RenderedPairsGiveTheRigsBaselineAndBadPairsAreNamed)
{
  // Four pairs of the tag board seen by the lab's rig: the check finds its 323 mm baseline and
  // keeps the first pair's corners; a pair of another size is refused by its name.
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  const pm::calib::TagBoard board;
  const pm::sim::Scene scene = patternScene(board);
  pm::calib::BaselineCheck check(rig, board);
  EXPECT_THROW(check.result(), pm::core::Error); // no pair yet
  for (int k = 0; k < 4; ++k) {
    const vpHomogeneousMatrix hMo(0.01 * k, -0.01, 0.48 + 0.01 * k, 0.05 * k, -0.1, 0.1 * k);
    const pm::sim::StereoImages im = scene.renderStereo(rig, hMo, static_cast<std::uint64_t>(k));
    check.add(im.left, im.right, "pair " + std::to_string(k));
    if (k == 0) {
      EXPECT_EQ(check.firstLeft().getWidth(), rig.left.width);
      EXPECT_EQ(check.firstLeftCorners().size(), check.firstRightCorners().size());
      EXPECT_EQ(check.firstLeftCorners().size(), 36u); // 9 tags, 4 corners each
    }
  }
  const pm::calib::BaselineResult r = check.result();
  EXPECT_EQ(r.pairsUsed + r.pairsRejected, 4);
  EXPECT_NEAR(r.baselineMm, 323.0, 1.0);
  EXPECT_LT(r.rotationErrorDeg, 0.3);

  const vpImage<vpRGBa> small(240, 320, vpRGBa(128));
  const std::string e = pm::test::errorOf([&] { check.add(small, small, "pair 7"); });
  EXPECT_NE(e.find("pair 7"), std::string::npos) << e;
  EXPECT_NE(e.find("320x240"), std::string::npos) << e;
  EXPECT_EQ(check.result().pairsUsed + check.result().pairsRejected, 4); // the refused pair is not counted
}
