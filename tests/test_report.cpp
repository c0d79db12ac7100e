// The report module's writers of the calibration programs, and the lab's model-making runner:
// what they write is what was measured, a verdict follows its tolerances, a bad folder leaves
// nothing behind, a lens is corrected before a flat model is built.
#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "pm/core/Error.h"
#include "pm/io/RigFile.h"
#include "pm/lab/ModelMaking.h"
#include "pm/lab/SimulatedCalibration.h"
#include "pm/report/CalibrationOutputs.h"
#include "pm/report/PlotUtil.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetCatalog.h"

using pm::test::errorOf;
using pm::test::TempDir;

namespace {

//! A calibration as calibrateRig() would report it: the lab's rig with a lens, its baseline 2 mm
//! longer than the true one, one pair used and one left out.
pm::report::RigCalibrationOutputs calibrationOutputs()
{
  pm::report::RigCalibrationOutputs o;
  o.truth = pm::lab::labRigWithLens(pm::core::LensDistortion{{-0.25, 0.08, 0.001, -0.0005, 0}});
  pm::core::StereoRig est = *o.truth;
  vpHomogeneousMatrix hMcR = est.right.hMc;
  const vpTranslationVector t = est.right.hMc.getTranslationVector() - est.left.hMc.getTranslationVector();
  const vpTranslationVector longer = est.left.hMc.getTranslationVector() + t * ((t.frobeniusNorm() + 0.002) / t.frobeniusNorm());
  hMcR.insert(longer);
  est.right.hMc = hMcR;
  o.calibration.rig = est;
  o.calibration.baselineMm = 325;
  o.calibration.pairsUsed = 1;
  o.calibration.viewsUsed[0] = o.calibration.viewsUsed[1] = 1;
  pm::calib::PairReport used, left;
  used.name = "a.png + b.png";
  used.used = used.usedBy[0] = used.usedBy[1] = true;
  used.corners[0] = used.projected[0] = {vpImagePoint(100, 100), vpImagePoint(120, 140)};
  used.corners[1] = used.projected[1] = {vpImagePoint(100, 80), vpImagePoint(120, 120)};
  left.name = "c.png + d.png";
  left.reason = "the board is blurred in the right image";
  o.calibration.pairs = {used, left};
  o.source = "2 image pairs";
  o.board = "chessboard 6x9";
  return o;
}

} // namespace

TEST(PlotUtil, AxisNumbersKeepTheirDigits)
{
  EXPECT_EQ(pm::report::tickLabel(250), "250");
  EXPECT_EQ(pm::report::tickLabel(3), "3");
  EXPECT_EQ(pm::report::tickLabel(0.25), "0.25");
  EXPECT_EQ(pm::report::tickLabel(0.005), "0.005"); // a quaternion component's ticks ("0.00" before)
  EXPECT_EQ(pm::report::tickLabel(-0.0025), "-0.0025");
  const std::vector<double> t = pm::report::niceTicks(-0.004, 0.012, 5);
  for (std::size_t k = 1; k < t.size(); ++k) // every tick named apart from the next
    EXPECT_NE(pm::report::tickLabel(t[k]), pm::report::tickLabel(t[k - 1]));
}

TEST(RigCalibrationOutputs, TheRigItsErrorsToTheTruthAndTheLeftOutPairAreWritten)
{
  TempDir d("report-cal");
  const pm::report::RigCalibrationOutputs o = calibrationOutputs();
  const nlohmann::json s = nlohmann::json::parse(pm::report::writeRigCalibration(d.file("rig"), o));
  for (const char *f : {"rig.json", "cameras.xml", "rig_left.yml", "rig_right.yml", "coverage.png", "summary.json"})
    EXPECT_TRUE(std::filesystem::exists(d.file("rig/") + f)) << f;
  EXPECT_FALSE(std::filesystem::exists(d.file("rig/.partial-rig")));
  EXPECT_NEAR(s["truth"]["baseline_error_mm"].get<double>(), 2.0, 1e-6);
  EXPECT_NEAR(s["truth"]["rotation_error_deg"].get<double>(), 0.0, 1e-9);
  EXPECT_EQ(s["pairs_rejected"], 1);
  EXPECT_EQ(s["pairs"][1]["reason"], "the board is blurred in the right image");
  // The rig written is the rig calibrated, lens and all.
  const pm::core::StereoRig back = pm::io::loadRig(d.file("rig/rig.json"));
  EXPECT_NEAR(pm::calib::compareRigs(back, o.calibration.rig).translationErrorMm, 0.0, 1e-6);
  EXPECT_EQ(back.right.distortion.coefficients, o.calibration.rig.right.distortion.coefficients);
  const std::string text = pm::report::describeRigCalibration(o, "rig");
  EXPECT_NE(text.find("c.png + d.png not in the stereo pose: the board is blurred"), std::string::npos) << text;
  EXPECT_NE(text.find("against the true rig: baseline 2.0000 mm"), std::string::npos) << text;

  // A folder that cannot be made: an error, and nothing left where it was asked for.
  pm::test::writeText(d.file("file"), "x");
  EXPECT_THROW(pm::report::writeRigCalibration(d.file("file/rig"), o), pm::core::Error);
  EXPECT_FALSE(std::filesystem::exists(d.file("file/rig")));
}

TEST(BaselineCheckOutputs, TheVerdictFollowsTheTolerancesAndTheSummarySaysIt)
{
  pm::report::BaselineCheckOutputs o;
  o.result.baselineErrorMm = -0.8;
  o.result.translationErrorMm = 0.9;
  o.result.rotationErrorDeg = 0.2;
  EXPECT_TRUE(o.agrees());
  EXPECT_TRUE(o.handEyeAgrees()); // no hand-eye check made
  o.result.baselineErrorMm = -1.2; // a baseline too short counts as much as one too long
  EXPECT_FALSE(o.agrees());
  o.toleranceMm = 1.5;
  EXPECT_TRUE(o.agrees());
  o.result.rotationErrorDeg = 0.31;
  EXPECT_FALSE(o.agrees());
  o.handEyePoses = 12;
  o.handEye[1].rotationErrorDeg = 0.6; // over the 0.5 deg tolerance, in one camera
  EXPECT_FALSE(o.handEyeAgrees());

  TempDir d("report-check");
  o.left = o.right = vpImage<vpRGBa>(48, 64, vpRGBa(90));
  o.cornersLeft = {vpImagePoint(20, 20)};
  const nlohmann::json s = nlohmann::json::parse(pm::report::writeBaselineCheck(d.file("c"), o));
  EXPECT_FALSE(s["agrees"].get<bool>());
  EXPECT_FALSE(s["hand_eye_agrees"].get<bool>());
  EXPECT_EQ(s["hand_eye"]["right"]["poses"], 12);
  EXPECT_TRUE(std::filesystem::exists(d.file("c/detections.png")));
  EXPECT_NE(pm::report::describeBaselineCheck(o).find("THE RIG FILE DOES NOT AGREE"), std::string::npos);
}

TEST(ModelMaking, AFlatModelFromPhotosThroughALensIsTheIdealCamerasModel)
{
  // The lab's crab 100 mm right of the optical axis of a camera 500 mm away, photographed once by
  // the ideal camera, once through a strong barrel lens. Given with its lens, the bent pair gives
  // the ideal pair's outline; given without it, the outline's far edge is pulled inward.
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  pm::core::PinholeCamera ideal{"photo", rig.left.cam, rig.left.width, rig.left.height, vpHomogeneousMatrix(), pm::core::LensDistortion()};
  pm::core::PinholeCamera bent = ideal;
  bent.distortion = pm::core::LensDistortion{{-0.4, 0.0, 0, 0, 0}};
  const vpHomogeneousMatrix hMo(0.1, 0, 0.5, 0, 0, 0);
  pm::sim::Rasterizer r;
  vpImage<vpRGBa> bg[2], toy[2];
  for (int k = 0; k < 2; ++k) {
    scene.render(r, k ? bent : ideal, hMo, 0, 2, bg[k], false);
    scene.render(r, k ? bent : ideal, hMo, 0, 3, toy[k], true);
  }
  const pm::model::PhotoModelParams mp;
  const pm::report::ModelOutputs a = pm::lab::flatModelFromPhotos(bg[0], toy[0], ideal, 500, mp, "bg.png", "toy.png");
  EXPECT_EQ(a.source, "photos bg.png + toy.png");
  EXPECT_FALSE(a.writePhotos);
  const pm::report::ModelOutputs b = pm::lab::flatModelFromPhotos(bg[1], toy[1], bent, 500, mp, "bg.png", "toy.png");
  const pm::report::ModelOutputs c = pm::lab::flatModelFromPhotos(bg[1], toy[1], ideal, 500, mp, "bg.png", "toy.png");
  const auto rightEdge = [](const pm::report::ModelOutputs &o) { // the region's rightmost column
    int right = -1;
    for (unsigned v = 0; v < o.build.region.getHeight(); ++v)
      for (unsigned u = 0; u < o.build.region.getWidth(); ++u)
        if (o.build.region[v][u])
          right = std::max(right, static_cast<int>(u));
    return right;
  };
  const int edge = rightEdge(a);
  ASSERT_GT(edge, 500); // the crab is right of the centre, inside the image
  ASSERT_LT(edge, 630);
  EXPECT_NEAR(rightEdge(b), edge, 2);  // the lens corrected: the ideal camera's outline
  EXPECT_LT(rightEdge(c), edge - 8);   // not corrected: the barrel lens pulls the edge inward

  const vpImage<vpRGBa> small(240, 320);
  const std::string e = errorOf([&] { pm::lab::flatModelFromPhotos(bg[0], small, ideal, 500, mp, "bg.png", "small.png"); });
  EXPECT_NE(e.find("'small.png' is 320x240"), std::string::npos) << e;
}
