// trust: the pass's calibration of the confidence and the uncertainty (issue 56): the held-out views, the shifts that read the cues as the lab's right poses read them, the guard that keeps every
// wrong try away from the threshold, the sigmas' gains, the calibration in model.json, and what the
// tracker reads of it (the shifted confidence, the gained sigmas, the cue that holds a frame). The whole
// calibration on the lab's crab pass is in test_allaround.cpp (its costly fixture).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <thread>
#include <chrono>
#include <atomic>
#include <cmath>
#include <random>
#include <set>

#include "TestSupport.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/lab/ModelCache.h"
#include "pm/lab/TrustCache.h"
#include "pm/tracker/Judgement.h"
#include "pm/trust/HeldOutViews.h"
#include "pm/trust/PassCalibration.h"
#include "pm/trust/RangeBias.h"
#include "pm/tracker/RangeCorrection.h"

namespace {

using pm::tracker::ConfidenceCues;

//! A steady lock's cues as the precise stage reads them: \e residualPx, \e separation, \e outBackground.
ConfidenceCues cues(double residualPx, double separation, double outBackground, double quality = 0.995)
{
  ConfidenceCues c;
  c.quality = c.qualityMin = c.inMatchMin = quality;
  c.outBackgroundMin = outBackground;
  c.competitorMargin = 0.3;
  c.framesTracked = 30;
  c.verified = c.tracking = c.precise = true;
  c.preciseResidualPx = residualPx;
  c.preciseSigmaMm = 0.2;
  c.preciseSigmaDeg = 0.3;
  c.separation = separation;
  c.cameraDisagreementPx = 0.5;
  return c;
}

pm::trust::PassTry tryOf(const ConfidenceCues &c, double errorMm, std::size_t view)
{
  pm::trust::PassTry t;
  t.view = view;
  t.start = "near";
  t.cues = c;
  t.errorMm = errorMm;
  t.error[0] = errorMm;
  return t;
}

//! The smallest all-around model a file writes as version 5: 17 viewpoints, each a point of S_in and S_out and an outline point.
pm::core::PhotoModel smallAllAroundModel()
{
  pm::core::PhotoModel m;
  m.distanceMm = 500;
  m.px = m.py = 754;
  m.u0 = 320, m.v0 = 240;
  m.photoWidth = 640, m.photoHeight = 480;
  m.centroidU = 320, m.centroidV = 240;
  m.backgroundHue = 205;
  m.targetHue = 10;
  m.inner.push_back({0.f, 0.f, -5.f, 10.f, 0.f, 0.f});
  m.inner.back().r = 200;
  m.outer.push_back({40.f, 0.f, 0.f, 205.f, 0.f, 0.f});
  m.contour.push_back({30.f, 0.f, 0.f, 1.f, 0.f, 0.f, 5.f, 5.f});
  m.cameraMm[2] = -500;
  m.hasColours = true;
  for (int k = 0; k < 17; ++k) {
    pm::core::ModelView v;
    v.cameraMm[0] = 10.0 * k;
    v.cameraMm[2] = -500;
    v.inner = m.inner;
    v.outer = m.outer;
    v.contour = m.contour;
    m.views.push_back(v);
  }
  return m;
}

double shiftOf(const pm::core::TrustCalibration &t, const std::string &name)
{
  for (const auto &[n, v] : t.cueShifts)
    if (n == name)
      return v;
  return 0;
}

//! The lab's rig (as data/rig/pa10_stereo.json: 323 mm baseline, toed in on 500 mm).
pm::core::StereoRig labRig()
{
  return pm::core::StereoRig::symmetric(vpCameraParameters(754, 754, 320, 240), 640, 480, 0.323, pm::core::StereoRig::toeInFor(0.323, 0.5));
}

//! A pass of two small plain views at two hand poses (what a cache's key reads, not a model's).
std::vector<pm::model::PassView> plainPass()
{
  std::vector<pm::model::PassView> pass(2);
  for (std::size_t k = 0; k < pass.size(); ++k) {
    pm::model::PassView &v = pass[k];
    v.name = "view " + std::to_string(k);
    v.fMh = vpHomogeneousMatrix(0.01 * static_cast<double>(k), 0, 0, 0, 0.1, 0);
    for (vpImage<vpRGBa> *I : {&v.left, &v.right, &v.backgroundLeft, &v.backgroundRight})
      I->resize(48, 64, vpRGBa(40, 90, 160));
  }
  return pass;
}

} // namespace

TEST(HeldOutViews, AFewViewsSpreadOverThePassHeldOutInPairsFarApart)
{
  const auto alone = pm::trust::heldOutFolds(16, 6);
  ASSERT_EQ(alone.size(), 6u);
  for (const auto &f : alone)
    EXPECT_EQ(f.size(), 1u); // a model built without that view alone
  const auto folds = pm::trust::heldOutFolds(16, 6, 2);
  ASSERT_EQ(folds.size(), 3u);
  std::set<std::size_t> seen;
  for (std::size_t i = 0; i < folds.size(); ++i) {
    ASSERT_EQ(folds[i].size(), 2u);
    EXPECT_EQ(folds[i][0], alone[i][0]); // the same views as one a model ...
    EXPECT_EQ(folds[i][1], alone[i + 3][0]);
    EXPECT_GE(folds[i][1] - folds[i][0], 6u); // ... two a model, far apart: each keeps its neighbours
    seen.insert(folds[i].begin(), folds[i].end());
  }
  EXPECT_EQ(seen.size(), 6u);
  EXPECT_EQ(seen.count(0), 0u); // the model's frame and viewpoints come from view 0
  EXPECT_LE(*seen.begin(), 3u);  // spread from the first ring ...
  EXPECT_GE(*seen.rbegin(), 13u); // ... to the last views
  EXPECT_EQ(pm::trust::heldOutFolds(4, 8).size(), 3u); // at most every view but the first
  EXPECT_EQ(pm::trust::heldOutFolds(16, 5, 2).size(), 3u); // an odd count: the last model holds one out
  EXPECT_TRUE(pm::trust::heldOutFolds(1, 4).empty());
  EXPECT_TRUE(pm::trust::heldOutFolds(16, 0).empty());
  EXPECT_TRUE(pm::trust::heldOutFolds(16, 6, 0).empty());
  EXPECT_EQ(pm::trust::calibrationSteps(16), 6u + 6u); // a step a model built and one a view tried
}

TEST(PassCalibration, ACameraThatReadsRightPosesWorseIsReadAsTheLabWithoutTrustingAWrongTry)
{
  // Right tries through a soft camera: a residual of 1.4 px, a separation of 0.85, S_out 97 % on the
  // background (the lab's toys read 0.71 px, 0.91, 100 %); wrong tries far below.
  std::vector<pm::trust::PassTry> tries;
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0, 1);
  for (std::size_t k = 0; k < 40; ++k)
    tries.push_back(tryOf(cues(1.4 + 0.1 * n(rng), 0.85 + 0.01 * n(rng), 0.97 + 0.005 * n(rng)), 1.0, k % 15 + 1));
  for (std::size_t k = 0; k < 60; ++k)
    tries.push_back(tryOf(cues(3.6 + 0.2 * n(rng), 0.70 + 0.02 * n(rng), 0.72 + 0.03 * n(rng), 0.85), 35.0, k % 15 + 1));
  const pm::tracker::ConfidenceModel shipped = pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::AllAround);
  const pm::core::TrustCalibration t = pm::trust::calibrateTrust(tries, shipped, pm::trust::CalibrationParams());
  ASSERT_TRUE(t.measured);
  EXPECT_EQ(t.rightExamples, 40);
  EXPECT_EQ(t.wrongExamples, 60);
  EXPECT_EQ(t.heldOutViews, 15);
  // Each deficit made up, within the spread of its median; the shape's cues never moved.
  EXPECT_NEAR(shiftOf(t, "precise_residual_px"), shipped.reference[13] - 1.4, 0.05);
  EXPECT_NEAR(shiftOf(t, "separation"), shipped.reference[16] - 0.85, 0.005);
  EXPECT_NEAR(shiftOf(t, "out_background_min"), shipped.reference[3] - 0.97, 0.003);
  EXPECT_EQ(shiftOf(t, "competitor_margin"), 0.0);
  EXPECT_EQ(shiftOf(t, "log1p_precise_sigma_mm"), 0.0);
  EXPECT_EQ(shiftOf(t, "quality"), 0.0); // it reads 0.995, over the lab's
  EXPECT_EQ(t.guard, 1.0);
  // The right tries read as the lab's worst toy reads right poses: their confidence that one's, not the soft camera's.
  std::vector<double> before, after;
  for (const auto &x : tries)
    if (x.right()) {
      before.push_back(shipped.confidence(x.cues));
      after.push_back(shipped.calibrated(t).confidence(x.cues));
    }
  std::sort(before.begin(), before.end());
  std::sort(after.begin(), after.end());
  const double atReference = shipped.confidence(cues(shipped.reference[13], shipped.reference[16], shipped.reference[3]));
  EXPECT_LT(before[before.size() / 2], shipped.threshold);
  EXPECT_GT(atReference, 0.9);
  EXPECT_NEAR(after[after.size() / 2], atReference, 0.01);
  EXPECT_GE(t.rightTrusted, t.rightTrustedShipped);
  EXPECT_EQ(t.wrongTrusted, 0);
  EXPECT_GT(t.auroc, 0.99);
  // A camera far worse: the shifts scaled down together, adding no more than maxLogitGain to the logit.
  std::vector<pm::trust::PassTry> worse = tries;
  for (auto &x : worse)
    if (x.right())
      x.cues.preciseResidualPx += 1.5;
  const pm::core::TrustCalibration capped = pm::trust::calibrateTrust(worse, shipped, pm::trust::CalibrationParams());
  double gain = 0;
  for (const auto &[name, v] : capped.cueShifts)
    gain += shipped.weights[static_cast<std::size_t>(std::find(pm::tracker::ConfidenceCues::featureNames().begin(),
                                                               pm::tracker::ConfidenceCues::featureNames().end(), name) -
                                                     pm::tracker::ConfidenceCues::featureNames().begin())] * v;
  EXPECT_NEAR(gain, pm::trust::CalibrationParams().maxLogitGain * capped.guard, 1e-9);
  // The tracker reads the same shifts from the model: a right try's confidence as the calibration said.
  pm::core::PhotoModel m;
  m.trust = t;
  const pm::tracker::JudgementParams jp = pm::tracker::JudgementParams().forModel(m);
  EXPECT_DOUBLE_EQ(jp.confidence.shift[13], shiftOf(t, "precise_residual_px"));
  EXPECT_GT(jp.confidence.confidence(tries[0].cues), shipped.confidence(tries[0].cues));
}

TEST(PassCalibration, TheGuardShrinksTheShiftsUntilNoWrongTryComesNearTheThreshold)
{
  // As above, and one wrong try that reads almost as a right one (a near miss 25 mm off): the full
  // shifts would lift it over the ceiling, so they are shrunk until it stays under.
  std::vector<pm::trust::PassTry> tries;
  for (std::size_t k = 0; k < 30; ++k)
    tries.push_back(tryOf(cues(1.4, 0.85, 0.97), 1.0, k % 10 + 1));
  tries.push_back(tryOf(cues(1.5, 0.85, 0.97), 25.0, 3));
  const pm::tracker::ConfidenceModel shipped = pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::AllAround);
  const pm::trust::CalibrationParams p;
  const pm::core::TrustCalibration t = pm::trust::calibrateTrust(tries, shipped, p);
  ASSERT_TRUE(t.measured);
  EXPECT_LT(t.guard, 1.0);
  EXPECT_LE(t.wrongMaxConfidence, std::max(p.wrongCeiling, shipped.confidence(tries.back().cues)) + 1e-12);
  EXPECT_EQ(t.wrongTrusted, 0);
  // No right try: nothing is measured, the shipped confidence stays.
  const pm::core::TrustCalibration none = pm::trust::calibrateTrust({tries.back()}, shipped, p);
  EXPECT_FALSE(none.measured);
}

TEST(PassCalibration, ANearMissIsHeldUnderItsCeilingAndAPlainlyWrongTryUnderTheLowerOne)
{
  // Right tries through a soft camera and one near miss (25 mm off) that reads a shade worse: the
  // guard lets the shifts lift the near miss up to wrongCeiling (0.9), no higher. A plainly wrong try
  // (50 mm off) reading the same is held under plainlyWrongCeiling (0.8): the shifts shrink further.
  std::vector<pm::trust::PassTry> tries;
  for (std::size_t k = 0; k < 30; ++k)
    tries.push_back(tryOf(cues(1.4, 0.85, 0.97), 1.0, k % 10 + 1));
  const ConfidenceCues nearMiss = cues(2.3, 0.85, 0.97);
  tries.push_back(tryOf(nearMiss, 25.0, 3));
  const pm::tracker::ConfidenceModel shipped = pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::AllAround);
  const pm::trust::CalibrationParams p;
  ASSERT_LT(shipped.confidence(nearMiss), p.plainlyWrongCeiling); // the case: both ceilings above what the shipped confidence reads
  const pm::core::TrustCalibration t = pm::trust::calibrateTrust(tries, shipped, p);
  ASSERT_TRUE(t.measured);
  EXPECT_GT(t.wrongMaxConfidence, p.plainlyWrongCeiling); // lifted past the lower ceiling ...
  EXPECT_LE(t.wrongMaxConfidence, p.wrongCeiling + 1e-12); // ... not past its own
  EXPECT_GT(t.rightTrusted, t.rightTrustedShipped);
  // The same cues 50 mm off: plainly wrong, held at the lower ceiling, the shifts shrunk further.
  tries.push_back(tryOf(nearMiss, 50.0, 4));
  ASSERT_TRUE(tries.back().plainlyWrong());
  const pm::core::TrustCalibration held = pm::trust::calibrateTrust(tries, shipped, p);
  EXPECT_LE(held.wrongMaxConfidence, p.plainlyWrongCeiling + 1e-12);
  EXPECT_LT(held.guard, t.guard);
  EXPECT_EQ(held.wrongTrusted, 0);
  // Ceilings out of order are refused.
  pm::trust::CalibrationParams bad;
  bad.plainlyWrongCeiling = 0.95;
  EXPECT_THROW(bad.validate(), pm::core::Error);
}

TEST(PassCalibration, WhereWrongTriesReadRightThroughThisCameraEveryConfidenceIsLoweredUntilNoneIsTrusted)
{
  // A camera through which wrong poses read as right ones (one camera on the head: its turned poses):
  // right tries and 50 mm-off tries (plainly wrong) with the lab's cues, the wrong ones a shade lower. The shipped
  // confidence trusts wrong tries; the calibration lowers every confidence on its logit until the
  // highest wrong one sits at the ceiling, so that none is trusted, and the tracker reads it so.
  std::vector<pm::trust::PassTry> tries;
  for (std::size_t k = 0; k < 20; ++k)
    tries.push_back(tryOf(cues(0.7, 0.91, 1.0), 1.0, k % 10 + 1));
  for (std::size_t k = 0; k < 10; ++k)
    tries.push_back(tryOf(cues(0.75 + 0.01 * static_cast<double>(k), 0.91, 1.0, 0.99), 50.0, k + 1));
  const pm::tracker::ConfidenceModel shipped = pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::AllAround);
  int wrongShipped = 0;
  double highestShipped = 0;
  for (const auto &x : tries)
    if (x.wrong()) {
      wrongShipped += shipped.confidence(x.cues) >= shipped.threshold;
      highestShipped = std::max(highestShipped, shipped.confidence(x.cues));
    }
  ASSERT_GT(wrongShipped, 0); // the case: the shipped confidence trusts wrong tries
  const pm::trust::CalibrationParams p;
  const pm::core::TrustCalibration t = pm::trust::calibrateTrust(tries, shipped, p);
  ASSERT_TRUE(t.measured);
  EXPECT_LT(t.confidenceOffset, 0);
  EXPECT_EQ(t.wrongTrusted, 0);
  EXPECT_NEAR(t.wrongMaxConfidence, p.plainlyWrongCeiling, 1e-9);
  EXPECT_LT(t.rightTrusted, t.rightTrustedShipped); // fewer right frames trusted: the price, said
  const pm::tracker::ConfidenceModel read = shipped.calibrated(t); // as the tracker reads a model of this kind
  for (const auto &x : tries) {
    if (x.wrong()) {
      EXPECT_LT(read.confidence(x.cues), read.threshold);
    }
  }
  pm::core::PhotoModel m; // a plain model: the offset joins its kind's bias
  m.trust = t;
  const pm::tracker::JudgementParams jp = pm::tracker::JudgementParams().forModel(m);
  EXPECT_DOUBLE_EQ(jp.confidence.bias, pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::Flat).bias + t.confidenceOffset);
  EXPECT_NE(pm::trust::describe(t).find("every confidence lowered by"), std::string::npos);
  // A camera through which no wrong try reads right: no offset; nor where the wrong tries that read
  // right are near misses (25 mm: the guard's business, as before).
  std::vector<pm::trust::PassTry> clear(tries.begin(), tries.begin() + 20);
  clear.push_back(tryOf(cues(3.6, 0.7, 0.72, 0.85), 35.0, 3));
  EXPECT_EQ(pm::trust::calibrateTrust(clear, shipped, p).confidenceOffset, 0.0);
  std::vector<pm::trust::PassTry> nearMisses = tries;
  for (auto &x : nearMisses)
    if (x.wrong())
      x.errorMm = x.error[0] = 25.0;
  EXPECT_EQ(pm::trust::calibrateTrust(nearMisses, shipped, p).confidenceOffset, 0.0);
}

TEST(PassCalibration, TheSigmasWidenToHoldTheHeldOutErrorsAndNeverNarrow)
{
  std::vector<pm::trust::PassTry> tries;
  std::mt19937 rng(9);
  std::normal_distribution<double> n(0, 1);
  for (std::size_t k = 0; k < 400; ++k) {
    pm::trust::PassTry t = tryOf(cues(1.0, 0.9, 1.0), 1.0, k % 15 + 1);
    t.uncertainty.known = true;
    t.uncertainty.sigmaMm = {1.0, 1.0, 1.0};
    t.uncertainty.sigmaDeg = {0.5, 0.5, 0.5};
    t.error = {2.0 * n(rng), 0.3 * n(rng), 1.0 * n(rng), 0.5 * n(rng), 0.1 * n(rng), 1.5 * n(rng)};
    t.errorMm = 0.5;
    tries.push_back(t);
  }
  const pm::core::TrustCalibration t =
      pm::trust::calibrateTrust(tries, pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::AllAround), pm::trust::CalibrationParams());
  EXPECT_NEAR(t.sigmaGain[0], 2.0, 0.2); // errors twice the sigma: widened twice
  EXPECT_EQ(t.sigmaGain[1], 1.0);        // errors well within: never narrowed
  EXPECT_NEAR(t.sigmaGain[2], 1.0, 0.1);
  EXPECT_NEAR(t.sigmaGain[5], 3.0, 0.3);
  for (std::size_t a : {0u, 2u, 5u})
    EXPECT_NEAR(t.withinSigma[a], 0.6827, 0.05) << a;
  EXPECT_GT(t.withinSigma[1], 0.99);
  pm::core::PhotoModel m;
  m.trust = t;
  EXPECT_EQ(pm::tracker::JudgementParams().forModel(m).uncertainty.gain, t.sigmaGain);
}

TEST(PassCalibration, TheModelFileKeepsItAndAnOlderModelLoadsWithNone)
{
  pm::test::TempDir dir("trust_file");
  const pm::core::PhotoModel m = smallAllAroundModel();
  pm::io::savePhotoModel(m, dir.file("v5.json"));
  EXPECT_NE(pm::test::readText(dir.file("v5.json")).find("\"version\":5"), std::string::npos);
  EXPECT_FALSE(pm::io::loadPhotoModel(dir.file("v5.json")).trust.measured);
  pm::core::PhotoModel c = m;
  c.trust.measured = true;
  c.trust.cueShifts = {{"precise_residual_px", -0.4}, {"separation", 0.02}};
  c.trust.rightReadings = {{"quality", 0.98}};
  c.trust.sigmaGain = {1.5, 1, 1, 1.2, 1, 1};
  c.trust.guard = 0.7;
  c.trust.confidenceOffset = -1.25;
  c.trust.auroc = 0.99;
  pm::io::savePhotoModel(c, dir.file("v6.json"));
  const std::string text = pm::test::readText(dir.file("v6.json"));
  EXPECT_NE(text.find("\"version\":6"), std::string::npos);
  const pm::core::PhotoModel back = pm::io::loadPhotoModel(dir.file("v6.json"));
  ASSERT_TRUE(back.trust.measured);
  EXPECT_EQ(back.trust.sigmaGain, c.trust.sigmaGain);
  EXPECT_DOUBLE_EQ(back.trust.guard, 0.7);
  EXPECT_DOUBLE_EQ(back.trust.confidenceOffset, -1.25);
  ASSERT_EQ(back.trust.cueShifts.size(), 2u);
  EXPECT_DOUBLE_EQ(shiftOf(back.trust, "precise_residual_px"), -0.4);
  // A cue the confidence does not know, and a gain out of range, are refused naming them.
  std::string bad = text;
  bad.replace(bad.find("precise_residual_px"), 19, "precise_resdual_px!");
  pm::test::writeText(dir.file("bad.json"), bad);
  EXPECT_NE(pm::test::errorOf([&] { pm::tracker::JudgementParams().forModel(pm::io::loadPhotoModel(dir.file("bad.json"))); }).find("precise_resdual_px!"),
            std::string::npos);
  bad = text;
  bad.replace(bad.find("\"sigma_gain\":[1.5"), 17, "\"sigma_gain\":[-1.5");
  pm::test::writeText(dir.file("bad2.json"), bad);
  EXPECT_NE(pm::test::errorOf([&] { pm::io::loadPhotoModel(dir.file("bad2.json")); }).find("sigma_gain"), std::string::npos);
  // A confidence raised rather than lowered is refused; a file from before the offset reads as none.
  bad = text;
  bad.replace(bad.find("\"confidence_offset\":-1.25"), 25, "\"confidence_offset\":1.25");
  pm::test::writeText(dir.file("bad3.json"), bad);
  EXPECT_NE(pm::test::errorOf([&] { pm::io::loadPhotoModel(dir.file("bad3.json")); }).find("confidence_offset"), std::string::npos);
  std::string older = text;
  older.erase(older.find("\"confidence_offset\":-1.25,"), 26);
  pm::test::writeText(dir.file("older.json"), older);
  EXPECT_EQ(pm::io::loadPhotoModel(dir.file("older.json")).trust.confidenceOffset, 0.0);
  // The range's correction: kept; a file from before it reads as none; a scale past 10 % refused.
  c.trust.rangeScale = 0.9973;
  c.trust.rangeCameras = 1;
  c.trust.rangeErrorPct = 0.27;
  c.trust.rangeViews = 6;
  pm::io::savePhotoModel(c, dir.file("range.json"));
  const pm::core::TrustCalibration r = pm::io::loadPhotoModel(dir.file("range.json")).trust;
  EXPECT_DOUBLE_EQ(r.rangeScale, 0.9973);
  EXPECT_EQ(r.rangeCameras, 1);
  EXPECT_DOUBLE_EQ(r.rangeErrorPct, 0.27);
  EXPECT_EQ(r.rangeViews, 6);
  EXPECT_EQ(back.trust.rangeScale, 1.0); // saved without it
  std::string ranged = pm::test::readText(dir.file("range.json"));
  std::string noRange = ranged; // keys of a file from before the range: unknown ones, ignored
  noRange.replace(noRange.find("\"range_cameras\""), 15, "\"range_camerax\"");
  noRange.replace(noRange.find("\"range_scale\""), 13, "\"range_scalx\"");
  pm::test::writeText(dir.file("norange.json"), noRange);
  const pm::core::TrustCalibration none = pm::io::loadPhotoModel(dir.file("norange.json")).trust;
  EXPECT_EQ(none.rangeScale, 1.0);
  EXPECT_EQ(none.rangeCameras, 0);
  ranged.replace(ranged.find("\"range_scale\":0.9973"), 20, "\"range_scale\":0.8000");
  pm::test::writeText(dir.file("bad4.json"), ranged);
  EXPECT_NE(pm::test::errorOf([&] { pm::io::loadPhotoModel(dir.file("bad4.json")); }).find("range_scale"), std::string::npos);
}

namespace {

//! A right try on \e view whose estimate lies \e pct % of its range too far from the cameras' centre (the hand's origin) and 1 mm across the range.
pm::trust::PassTry rangedTry(std::size_t view, double pct, bool precise = true, double rangeMm = 500)
{
  pm::trust::PassTry t = tryOf(cues(1.0, 0.9, 1.0), 0, view);
  t.cues.precise = precise;
  t.originMm = {0.06 * rangeMm, -0.04 * rangeMm, rangeMm};
  const double across[3] = {1 / std::hypot(1.0, 0.06), 0, -0.06 / std::hypot(1.0, 0.06)}; // a unit vector square to the range
  for (std::size_t i = 0; i < 3; ++i)
    t.error[i] = t.originMm[i] * pct / 100 + across[i];
  t.errorMm = std::hypot(t.error[0], t.error[1], t.error[2]);
  return t;
}

} // namespace

TEST(RangeBias, TheViewsAgreeingOnHowFarTheirPosesLieGiveTheScaleThatBringsThemBack)
{
  const std::array<double, 3> centre{0, 0, 0};
  std::vector<pm::trust::PassTry> tries;
  for (std::size_t v = 1; v <= 5; ++v)
    for (double pct : {0.25, 0.3, 0.35})
      tries.push_back(rangedTry(v, pct + 0.01 * static_cast<double>(v)));
  tries.push_back(rangedTry(6, -3.0, false)); // without the precise stage: not counted
  pm::trust::PassTry wrong = rangedTry(7, 5.0);
  wrong.errorMm = 30; // a wrong try: not counted
  tries.push_back(wrong);
  const pm::trust::RangeBias b = pm::trust::measureRangeBias(tries, centre);
  EXPECT_EQ(b.views, 5);
  EXPECT_EQ(b.agreeing, 5);
  EXPECT_NEAR(b.errorPct, 0.33, 1e-3); // the median of the views' medians (0.31 .. 0.35; the 1 mm across adds 2e-4 %)
  ASSERT_TRUE(b.measured());
  EXPECT_NEAR(b.scale, 1 / (1 + b.errorPct / 100), 1e-12);
  // Corrected, a try of the median's range lies at the truth's range; the error across it stays.
  const pm::trust::PassTry c = pm::trust::rangeCorrected(rangedTry(3, 0.33), b.scale, centre);
  EXPECT_NEAR(pm::trust::relativeRangeError(c, centre), 0.0, 1e-5);
  EXPECT_NEAR(std::hypot(c.error[0], c.error[1], c.error[2]), 1.0, 0.01); // what lay across the range
  EXPECT_NEAR(c.errorMm, std::hypot(c.error[0], c.error[1], c.error[2]), 1e-12);
  // No bias to correct: the views disagree, too few views, or under 0.1 %.
  std::vector<pm::trust::PassTry> split;
  for (std::size_t v = 1; v <= 4; ++v)
    split.push_back(rangedTry(v, v % 2 ? 0.3 : -0.3));
  EXPECT_FALSE(pm::trust::measureRangeBias(split, centre).measured());
  EXPECT_FALSE(pm::trust::measureRangeBias({rangedTry(1, 0.3), rangedTry(2, 0.3)}, centre).measured());
  EXPECT_FALSE(pm::trust::measureRangeBias({rangedTry(1, 0.05), rangedTry(2, 0.06), rangedTry(3, 0.07)}, centre).measured());
  EXPECT_TRUE(pm::trust::measureRangeBias({rangedTry(1, -0.3), rangedTry(2, -0.25), rangedTry(3, 0.1)}, centre).measured()); // one view off: still agreed
  // At most 2 % (right tries, within 5 mm, reach it only near the cameras: 2.3 % at 200 mm).
  EXPECT_NEAR(pm::trust::measureRangeBias({rangedTry(1, 2.3, true, 200), rangedTry(2, 2.3, true, 200), rangedTry(3, 2.3, true, 200)}, centre).scale, 1 / 1.02, 1e-12);
}

TEST(RangeCorrection, ScalesTheRangeFromTheRigsCamerasOnARigOfTheCountMeasuredOnly)
{
  pm::core::PinholeCamera left, right;
  left.hMc.buildFrom(-0.16, 0, 0, 0, 0.3, 0);
  right.hMc.buildFrom(0.16, 0, 0.02, 0, -0.3, 0);
  const pm::core::CameraRig one(std::vector<pm::core::PinholeCamera>{left}), pair(std::vector<pm::core::PinholeCamera>{left, right});
  pm::core::TrustCalibration t;
  t.measured = true;
  t.rangeScale = 0.99;
  t.rangeCameras = 1;
  const pm::tracker::RangeCorrection onOne(one, t), onPair(pair, t), none;
  EXPECT_TRUE(onOne.active());
  EXPECT_FALSE(onPair.active()); // measured through one camera: a pair reads its own range
  EXPECT_FALSE(none.active());
  EXPECT_EQ(pm::tracker::cameraCentreMm(pair), (std::array<double, 3>{0, 0, 10}));
  const pm::core::Phi phi{40, -30, 520, 0.1, -0.05, 0.2};
  const pm::core::Phi c = onOne.corrected(phi);
  const std::array<double, 3> o = onOne.centreMm();
  EXPECT_EQ(o, (std::array<double, 3>{-160, 0, 0}));
  const double before = std::hypot(phi.x - o[0], phi.y - o[1], phi.z - o[2]), after = std::hypot(c.x - o[0], c.y - o[1], c.z - o[2]);
  EXPECT_NEAR(after, 0.99 * before, 1e-9); // the range scaled ...
  EXPECT_NEAR((c.x - o[0]) * (phi.y - o[1]) - (c.y - o[1]) * (phi.x - o[0]), 0.0, 1e-9); // ... along the line from the centre
  EXPECT_EQ(c.e1, phi.e1);
  EXPECT_EQ(c.e2, phi.e2);
  EXPECT_EQ(c.e3, phi.e3);
  const pm::core::Phi same = onPair.corrected(phi);
  EXPECT_EQ(same.x, phi.x);
  EXPECT_EQ(same.z, phi.z);
  pm::core::TrustCalibration older = t; // a model from before the range: none on any rig
  older.rangeScale = 1;
  older.rangeCameras = 0;
  EXPECT_FALSE(pm::tracker::RangeCorrection(one, older).active());
}

TEST(TrustCache, GivesBackWhatWasStoredForTheSamePassRigAndModelOnlyAndNeverFails)
{
  pm::test::TempDir dir("trust_cache");
  const pm::core::StereoRig rig = labRig();
  const std::vector<pm::model::PassView> pass = plainPass();
  const pm::core::PhotoModel model = smallAllAroundModel();
  pm::lab::LabTrust t;
  t.trust.measured = true;
  t.trust.cueShifts = {{"separation", 0.1 / 3}, {"precise_residual_px", -0.4}}; // not in the names' order
  t.trust.rightReadings = {{"quality", 0.98}, {"in_match_min", 0.9}};
  t.trust.sigmaGain = {1.5, 1, 1, 1.2, 1, 1};
  t.trust.guard = 0.7;
  t.trust.auroc = 1 / 3.0;
  t.triesCsv = "view,start\n3,near\n";
  const pm::lab::TrustCache cache(pm::lab::LabCache(dir.file("cache")));
  const std::string key = pm::lab::TrustCache::keyOf(rig, pass, model);
  EXPECT_EQ(key.size(), 16u);
  EXPECT_FALSE(cache.find(key));
  cache.store(key, t);
  const std::optional<pm::lab::LabTrust> back = cache.find(key);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->trust.cueShifts, t.trust.cueShifts); // to the last bit, in its order
  EXPECT_EQ(back->trust.rightReadings, t.trust.rightReadings);
  EXPECT_EQ(back->trust.sigmaGain, t.trust.sigmaGain);
  EXPECT_EQ(back->trust.auroc, t.trust.auroc);
  EXPECT_EQ(back->triesCsv, t.triesCsv);
  // Anything the calibration reads changes the key: a pixel, a hand pose, the rig, the model.
  std::vector<pm::model::PassView> other = pass;
  other[1].backgroundRight[47][63] = vpRGBa(40, 90, 161);
  EXPECT_NE(pm::lab::TrustCache::keyOf(rig, other, model), key);
  other = pass;
  other[0].fMh[0][3] += 1e-9;
  EXPECT_NE(pm::lab::TrustCache::keyOf(rig, other, model), key);
  pm::core::StereoRig soft = rig;
  soft.right.distortion.coefficients = {-0.01, 0, 0, 0, 0};
  EXPECT_NE(pm::lab::TrustCache::keyOf(soft, pass, model), key);
  pm::core::PhotoModel moved = model;
  moved.views[16].inner[0].x += 0.5f;
  EXPECT_NE(pm::lab::TrustCache::keyOf(rig, pass, moved), key);
  // The model's own trust is not part of what it was calibrated from.
  pm::core::PhotoModel trusted = model;
  trusted.trust = t.trust;
  EXPECT_EQ(pm::lab::TrustCache::keyOf(rig, pass, trusted), key);
  // An entry that does not read is none; a calibration that found no right pose is not kept; no
  // folder, or one that cannot be made, is a cache that finds and keeps nothing.
  pm::test::writeText(dir.file("cache/" + key + ".trust.json"), "{\"trust_calibration\": 3}");
  EXPECT_FALSE(cache.find(key));
  pm::lab::LabTrust none;
  cache.store("00000000000000aa", none);
  EXPECT_FALSE(cache.find("00000000000000aa"));
  const pm::lab::TrustCache off;
  EXPECT_FALSE(off.folder().enabled());
  off.store(key, t);
  EXPECT_FALSE(off.find(key));
  pm::test::writeText(dir.file("a_file"), "x");
  const pm::lab::TrustCache blocked(pm::lab::LabCache(dir.file("a_file/cache")));
  EXPECT_NO_THROW(blocked.store(key, t));
  EXPECT_FALSE(blocked.find(key));
}

TEST(ModelCache, GivesBackTheModelItsFrameAndSilhouetteForTheSamePassRigAndParametersOnly)
{
  pm::test::TempDir dir("model_cache");
  const pm::core::StereoRig rig = labRig();
  const std::vector<pm::model::PassView> pass = plainPass();
  pm::lab::CachedModel m;
  m.model = smallAllAroundModel();
  m.fMm = vpHomogeneousMatrix(0.1 / 3, -0.2, 0.5, 0.1, 1 / 7.0, -0.3);
  m.region.resize(48, 64, 0);
  for (unsigned i = 10; i < 30; ++i)
    for (unsigned j = 20 + i % 3; j < 50; ++j)
      m.region[i][j] = 255;
  m.region[0][0] = 7;
  const pm::model::AllAroundParams params;
  const pm::lab::ModelCache cache(pm::lab::LabCache(dir.file("cache")));
  const std::string key = pm::lab::ModelCache::keyOf(rig, pass, params, true);
  EXPECT_EQ(key.size(), 16u);
  EXPECT_FALSE(cache.find(key));
  cache.store(key, m);
  const std::optional<pm::lab::CachedModel> back = cache.find(key);
  ASSERT_TRUE(back);
  EXPECT_EQ(pm::io::photoModelToJson(back->model, pm::io::ModelDigits::Exact), pm::io::photoModelToJson(m.model, pm::io::ModelDigits::Exact)); // to the last bit
  for (unsigned k = 0; k < 16; ++k)
    EXPECT_EQ(back->fMm[k / 4][k % 4], m.fMm[k / 4][k % 4]);
  ASSERT_EQ(back->region.getSize(), m.region.getSize());
  EXPECT_TRUE(std::equal(m.region.bitmap, m.region.bitmap + m.region.getSize(), back->region.bitmap));
  // A pixel of the pass, a field of any section of the parameters, the trust's choice change the key.
  std::vector<pm::model::PassView> other = pass;
  other[0].right[3][4] = vpRGBa(41, 90, 160);
  EXPECT_NE(pm::lab::ModelCache::keyOf(rig, other, params, true), key);
  EXPECT_NE(pm::lab::ModelCache::keyOf(rig, pass, params, false), key);
  pm::model::AllAroundParams p = params;
  p.fusion.blockPx += 2;
  EXPECT_NE(pm::lab::ModelCache::keyOf(rig, pass, p, true), key);
  p = params;
  p.silhouette.background.darkRatio += 1e-12;
  EXPECT_NE(pm::lab::ModelCache::keyOf(rig, pass, p, true), key);
  p = params;
  p.surface.outline.rounds += 1;
  EXPECT_NE(pm::lab::ModelCache::keyOf(rig, pass, p, true), key);
  p = params;
  p.carving.finestMm += 1e-9;
  EXPECT_NE(pm::lab::ModelCache::keyOf(rig, pass, p, true), key);
  p = params;
  p.colour.maxHueSpreadDeg += 1;
  EXPECT_NE(pm::lab::ModelCache::keyOf(rig, pass, p, true), key);
  p = params;
  p.viewpoints.nContour += 1;
  EXPECT_NE(pm::lab::ModelCache::keyOf(rig, pass, p, true), key);
  // A silhouette that does not read, or no model file, is no entry; no folder finds and keeps nothing.
  pm::test::writeText(dir.file("cache/" + key + ".frame.json"), "{\"fMm\": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], \"region_runs\": [64, 48, 0, 5]}");
  EXPECT_FALSE(cache.find(key));
  cache.store(key, m);
  std::filesystem::remove(dir.file("cache/" + key + ".model.json"));
  EXPECT_FALSE(cache.find(key));
  const pm::lab::ModelCache off;
  off.store(key, m);
  EXPECT_FALSE(off.find(key));
}

TEST(LabCache, AKeysLockMakesASecondMakerOfTheSameEntryWait)
{
  pm::test::TempDir dir("cache_lock");
  const pm::lab::LabCache cache(dir.file("cache"));
  std::atomic<bool> firstDone{false}, secondIn{false};
  bool secondSawFirstDone = false;
  std::thread second;
  {
    const pm::lab::LabCache::KeyLock first(cache, "00000000000000ab");
    second = std::thread([&] {
      const pm::lab::LabCache::KeyLock mine(cache, "00000000000000ab"); // waits for the first
      secondSawFirstDone = firstDone.load();
      secondIn = true;
    });
    // Another key is not held by it.
    { const pm::lab::LabCache::KeyLock other(cache, "00000000000000cd"); }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_FALSE(secondIn.load());
    firstDone = true;
  }
  second.join();
  EXPECT_TRUE(secondSawFirstDone);
  // A cache with no folder locks nothing (and never blocks).
  const pm::lab::LabCache off("");
  const pm::lab::LabCache::KeyLock a(off, "k"), b(off, "k");
}

TEST(LabCache, FindOrMakeMakesAnEntryOnceWhoeverAsksAndOnlyWithAFolder)
{
  pm::test::TempDir dir("cache_find_or_make");
  const pm::lab::LabCache cache(dir.file("cache"));
  std::atomic<int> made{0}, stored{0};
  const auto find = [&](const std::string &k) { return cache.read(k + ".txt"); };
  const auto make = [&] {
    ++made;
    std::this_thread::sleep_for(std::chrono::milliseconds(30)); // long enough for the others to ask meanwhile
    return std::string("entry ") + std::to_string(made.load());
  };
  const auto store = [&](const std::string &k, const std::string &text) {
    ++stored;
    cache.write(k + ".txt", text);
  };
  // Four askers at once: one makes and stores, the three others find what it stored.
  std::vector<std::string> got(4);
  std::vector<std::thread> askers;
  for (std::size_t i = 0; i < got.size(); ++i)
    askers.emplace_back([&, i] { got[i] = pm::lab::findOrMake<std::string>(cache, "00000000000000ef", find, make, store); });
  for (std::thread &t : askers)
    t.join();
  EXPECT_EQ(made.load(), 1);
  EXPECT_EQ(stored.load(), 1);
  for (const std::string &g : got)
    EXPECT_EQ(g, "entry 1");
  // Later: found, not made. Another key: made.
  EXPECT_EQ(pm::lab::findOrMake<std::string>(cache, "00000000000000ef", find, make, store), "entry 1");
  EXPECT_EQ(made.load(), 1);
  EXPECT_EQ(pm::lab::findOrMake<std::string>(cache, "00000000000000f0", find, make, store), "entry 2");
  // Without a folder: made every time, never stored.
  const pm::lab::LabCache off("");
  EXPECT_EQ(pm::lab::findOrMake<std::string>(off, "00000000000000ef", find, make, store), "entry 3");
  EXPECT_EQ(made.load(), 3);
  EXPECT_EQ(stored.load(), 2);
}

TEST(Judgement, AFrameNotTrustedNamesTheCueThatHeldIt)
{
  const pm::tracker::ConfidenceModel m = pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::AllAround);
  ConfidenceCues c = cues(0.6, 0.95, 1.0);
  EXPECT_STREQ(m.weakestCueName(c), "confidence"); // reads as well as a right pose on every cue
  c.preciseResidualPx = 2.5;
  EXPECT_STREQ(m.weakestCueName(c), "precise_residual_px");
  c.preciseResidualPx = 1.5;
  c.outBackgroundMin = 0.3;
  EXPECT_STREQ(m.weakestCueName(c), "out_background_min"); // 4.34 x 0.7 outweighs 2.19 x 0.79
  c = cues(0.6, 0.95, 1.0);
  c.framesTracked = 2;
  EXPECT_STREQ(m.weakestCueName(c), "frames_tracked");
  // A frame without the precise stage's pose: its cues are not read (nor shifted).
  c = cues(0.6, 0.95, 1.0);
  c.precise = false;
  pm::tracker::ConfidenceModel shifted = m;
  shifted.shift[13] = -1;
  EXPECT_DOUBLE_EQ(shifted.confidence(c), m.confidence(c));
  EXPECT_STREQ(m.weakestCueName(c), "precise");
}
