// pm-compare: the outline model given to ViSP's trackers, the scores, the scenarios, and the
// program run on the forced-loss scenario against ground truth; its runner (Comparison) and the
// confidence study's report on a set labelled by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "pm/compare/CadMesh.h"
#include "pm/compare/Comparison.h"
#include "pm/compare/ConfidenceFit.h"
#include "pm/compare/ConfidenceStudy.h"
#include "pm/compare/Metrics.h"
#include "pm/compare/OutlineModel.h"
#include "pm/compare/Roc.h"
#include "pm/compare/Scenario.h"
#include "pm/compare/Trackers.h"
#include "pm/core/Error.h"
#include "pm/io/RigFile.h"
#include "pm/sim/Rasterizer.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"

using pm::compare::FrameScore;
using pm::test::runProgram;
using pm::test::TempDir;

TEST(OutlineModel, ASquareRegionGivesItsFourCornersInTheModelFrameCounterClockwiseAsSeen)
{
  // A 100 x 60 px region photographed at 500 mm with px = py = 1000: 50 x 30 mm.
  vpImage<unsigned char> region(200, 300, 0);
  for (unsigned i = 70; i < 130; ++i)
    for (unsigned j = 100; j < 200; ++j)
      region[i][j] = 255;
  pm::core::PhotoModel m;
  m.distanceMm = 500;
  m.px = m.py = 1000;
  m.centroidU = 149.5;
  m.centroidV = 99.5;
  const auto poly = pm::compare::outlinePolygon(region, m, 1.0);
  ASSERT_EQ(poly.size(), 4u);
  double minX = 1, maxX = -1, minY = 1, maxY = -1, area2 = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const vpPoint &a = poly[i], &b = poly[(i + 1) % 4];
    minX = std::min(minX, a.get_oX());
    maxX = std::max(maxX, a.get_oX());
    minY = std::min(minY, a.get_oY());
    maxY = std::max(maxY, a.get_oY());
    EXPECT_EQ(a.get_oZ(), 0.0);
    area2 += a.get_oX() * b.get_oY() - b.get_oX() * a.get_oY();
  }
  // Contour pixels are the region's border pixels: 99 x 59 px between their centres.
  EXPECT_NEAR(maxX - minX, 0.0495, 1e-9);
  EXPECT_NEAR(maxY - minY, 0.0295, 1e-9);
  EXPECT_NEAR(minX + maxX, 0.0, 1e-9); // centred on the centroid
  // Seen from the camera (looking along +z, y down), counter-clockwise: negative signed area in (x, y).
  EXPECT_LT(area2, 0);
  const std::string cao = pm::compare::caoText(poly, "test");
  EXPECT_EQ(cao.rfind("V1\n", 0), 0u);
  EXPECT_NE(cao.find("\n4 0 1 2 3\n"), std::string::npos);
  EXPECT_THROW(pm::compare::outlinePolygon(vpImage<unsigned char>(10, 10, 0), m), pm::core::Error);
}

TEST(Metrics, ErrorsSuccessRatesAndRecoveryFromKnownScores)
{
  const vpHomogeneousMatrix truth(0.01, 0.02, 0.5, 0, 0, 0);
  const FrameScore s = pm::compare::scoreFrame(truth * vpHomogeneousMatrix(0.003, 0, 0.004, 0, 0, 0.1), truth);
  EXPECT_NEAR(s.translationMm, 5.0, 1e-9);
  EXPECT_NEAR(s.rotationDeg, 0.1 * 180 / M_PI, 1e-9);

  // 20 frames: fine, then lost at frame 8 (error 300 mm), back within 5 cm from frame 12 on,
  // and a second loss at 18 that never recovers.
  std::vector<FrameScore> f(20);
  for (std::size_t k = 0; k < f.size(); ++k) {
    f[k].translationMm = k < 8 ? 4 : k < 12 ? 300 : k < 18 ? 20 : 300;
    f[k].rotationDeg = 1;
    f[k].ms = static_cast<double>(k + 1);
  }
  const pm::compare::Summary r = pm::compare::summarize(f, {8, 18});
  EXPECT_DOUBLE_EQ(r.success5cm5deg, 14.0 / 20);
  EXPECT_DOUBLE_EQ(r.success1cm2deg, 8.0 / 20);
  EXPECT_DOUBLE_EQ(r.maxTranslationMm, 300);
  EXPECT_DOUBLE_EQ(r.meanMs, 10.5);
  EXPECT_DOUBLE_EQ(r.p99Ms, 20);
  ASSERT_EQ(r.recovery.size(), 2u);
  ASSERT_TRUE(r.recovery[0].has_value());
  EXPECT_EQ(*r.recovery[0], 4); // frames 8..11 lost, 12..16 the first 5 good frames in a row
  EXPECT_FALSE(r.recovery[1].has_value());
  EXPECT_TRUE(r.neverRecovered());
  EXPECT_FALSE(r.worstRecovery().has_value());
}

TEST(Roc, AreaAndCurveOfKnownScores)
{
  using pm::compare::auroc;
  // Right frames 0.9, 0.8, 0.4; wrong ones 0.7, 0.1: of the 6 (right, wrong) pairs 5 are in order.
  const std::vector<double> s{0.9, 0.7, 0.8, 0.1, 0.4};
  const std::vector<bool> r{true, false, true, false, true};
  EXPECT_NEAR(auroc(s, r), 5.0 / 6.0, 1e-12);
  const auto c = pm::compare::rocCurve(s, r);
  ASSERT_EQ(c.size(), 6u);
  EXPECT_DOUBLE_EQ(c[2].threshold, 0.8);
  EXPECT_NEAR(c[2].trueAcceptRate, 2.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(c[2].falseAcceptRate, 0.0);
  EXPECT_DOUBLE_EQ(c.back().trueAcceptRate, 1.0);
  EXPECT_DOUBLE_EQ(c.back().falseAcceptRate, 1.0);
  // The lowest threshold with no false accept keeps two of the three right frames.
  EXPECT_DOUBLE_EQ(pm::compare::thresholdFor(c, 0.0).threshold, 0.8);
  // Separated, reversed, all tied.
  EXPECT_DOUBLE_EQ(auroc({1, 2, 3, 4}, {false, false, true, true}), 1.0);
  EXPECT_DOUBLE_EQ(auroc({4, 3, 2, 1}, {false, false, true, true}), 0.0);
  EXPECT_DOUBLE_EQ(auroc({1, 1, 1, 1}, {false, true, false, true}), 0.5);
  // Bad input.
  EXPECT_THROW(auroc({1, 2}, {true}), pm::core::Error);
  EXPECT_THROW(auroc({1, 2}, {true, true}), pm::core::Error);
  EXPECT_THROW(auroc({1, NAN}, {true, false}), pm::core::Error);
}

TEST(ConfidenceStudy, TheReportCountsTheSetAsLabelledPerRunAndAmongTrackedFrames)
{
  // The scores of Roc.AreaAndCurveOfKnownScores as a labelled set of two runs: the report's counts
  // are the set's, the areas are auroc's over all frames and over the Tracking ones.
  pm::compare::ConfidenceStudy study;
  study.runNames = {"a", "b"};
  struct F { double conf; bool right, trusted; pm::tracker::TrackState state; std::size_t run; };
  const F fs[] = {{0.9, true, true, pm::tracker::TrackState::Tracking, 0},  {0.7, false, true, pm::tracker::TrackState::Tracking, 0},
                  {0.8, true, false, pm::tracker::TrackState::Tracking, 1}, {0.1, false, false, pm::tracker::TrackState::Searching, 1},
                  {0.4, true, false, pm::tracker::TrackState::Tracking, 1}};
  for (const F &f : fs) {
    pm::compare::LabelledFrame l;
    l.confidence = f.conf;
    l.right = f.right;
    l.trusted = f.trusted;
    l.state = f.state;
    l.run = f.run;
    study.frames.push_back(l);
    study.runOf.push_back(f.run);
  }
  const pm::compare::ConfidenceReport r = pm::compare::reportConfidence(study, 0.0, 0.85);
  EXPECT_EQ(r.frames, 5u);
  EXPECT_EQ(r.wrong, 2u);
  EXPECT_EQ(r.trackingWrong, 1u);   // the 0.7 frame; the wrong 0.1 one was searching
  EXPECT_EQ(r.trustedWrong, 1u);
  EXPECT_EQ(r.trustedRight, 1u);
  EXPECT_DOUBLE_EQ(r.threshold, 0.85);
  EXPECT_NEAR(r.auroc, 5.0 / 6.0, 1e-12);
  EXPECT_NEAR(r.aurocTracking, 2.0 / 3.0, 1e-12); // right 0.9, 0.8, 0.4 against wrong 0.7
  EXPECT_DOUBLE_EQ(r.atMaxFalseAccept.threshold, 0.8);
  EXPECT_NEAR(r.trueAcceptRate(), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(r.falseAcceptRate(), 1.0 / 2.0, 1e-12);
  ASSERT_EQ(r.perRun.size(), 2u);
  EXPECT_EQ(r.perRun[0], (std::array<std::size_t, 4>{2, 1, 1, 1}));
  EXPECT_EQ(r.perRun[1], (std::array<std::size_t, 4>{3, 1, 0, 0}));
  EXPECT_THROW(pm::compare::reportConfidence(pm::compare::ConfidenceStudy(), 0.0, 0.5), pm::core::Error);
}

TEST(Roc, TheLogisticFitRecoversTheModelItsLabelsWereDrawnFrom)
{
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double w0 = 2.0, w1 = -1.5, b = 0.5;
  std::vector<std::vector<double>> x;
  std::vector<bool> y;
  for (int i = 0; i < 20000; ++i) {
    const double a = g(rng), c = g(rng);
    x.push_back({a, c});
    y.push_back(u(rng) < 1.0 / (1.0 + std::exp(-(w0 * a + w1 * c + b))));
  }
  const auto fit = pm::compare::fitLogistic(x, y, 0.0);
  ASSERT_EQ(fit.weights.size(), 2u);
  // Standard errors are about 0.03 here.
  EXPECT_NEAR(fit.weights[0], w0, 0.12);
  EXPECT_NEAR(fit.weights[1], w1, 0.12);
  EXPECT_NEAR(fit.bias, b, 0.1);
  EXPECT_THROW(pm::compare::fitLogistic({{1.0}, {1.0, 2.0}}, {true, false}), pm::core::Error);
  EXPECT_THROW(pm::compare::fitLogistic({{1.0}, {2.0}}, {true, true}), pm::core::Error);
}

TEST(Roc, CrossValidationScoresEachFoldWithAModelThatNeverSawIt)
{
  // Labels drawn from a known logistic model; four folds. Each row's held-out score is the
  // probability under the model fitted on the other three, so it is close to the true one, and
  // its AUROC close to the in-sample fit's. A fold whose complement has one class only is named.
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::vector<double>> x;
  std::vector<bool> y;
  std::vector<int> fold;
  for (int i = 0; i < 8000; ++i) {
    const double a = g(rng), c = g(rng);
    x.push_back({a, c});
    y.push_back(u(rng) < 1.0 / (1.0 + std::exp(-(1.5 * a - c))));
    fold.push_back(i % 4);
  }
  const std::vector<double> held = pm::compare::crossValidatedLogistic(x, y, fold, 4, 0.0);
  ASSERT_EQ(held.size(), x.size());
  double worst = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    worst = std::max(worst, std::abs(held[i] - 1.0 / (1.0 + std::exp(-(1.5 * x[i][0] - x[i][1])))));
  EXPECT_LT(worst, 0.06);
  const auto all = pm::compare::fitLogistic(x, y, 0.0);
  std::vector<double> inSample;
  for (const auto &row : x)
    inSample.push_back(all.probability(row));
  EXPECT_NEAR(pm::compare::auroc(held, y), pm::compare::auroc(inSample, y), 0.005);
  // Fold 1 holds every wrong row: the training set of fold 1 has right rows only.
  std::vector<bool> skewed(x.size(), true);
  for (std::size_t i = 0; i < x.size(); ++i)
    skewed[i] = fold[i] != 1;
  try {
    pm::compare::crossValidatedLogistic(x, skewed, fold, 4);
    ADD_FAILURE() << "no error";
  } catch (const pm::core::Error &e) {
    EXPECT_NE(std::string(e.what()).find("fold 1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(pm::compare::crossValidatedLogistic(x, y, std::vector<int>(x.size(), 4), 4), pm::core::Error);
  EXPECT_THROW(pm::compare::crossValidatedLogistic(x, y, fold, 1), pm::core::Error);
}

TEST(Scenario, TheForcedLossBlanksTheFramesAndTheTargetJumps)
{
  const pm::compare::Scenario s = pm::compare::makeScenario("loss", {});
  ASSERT_EQ(s.lossEnds.size(), 2u);
  const int blankEnd = s.lossEnds[0], jump = s.lossEnds[1];
  EXPECT_TRUE(s.frames[static_cast<std::size_t>(blankEnd - 1)].blank);
  EXPECT_FALSE(s.frames[static_cast<std::size_t>(blankEnd)].blank);
  const vpHomogeneousMatrix a = s.frames[static_cast<std::size_t>(jump - 1)].hMo, b = s.frames[static_cast<std::size_t>(jump)].hMo;
  EXPECT_NEAR((a.getTranslationVector() - b.getTranslationVector()).frobeniusNorm(), 0.05, 1e-9);
  EXPECT_NEAR((a.inverse() * b).getThetaUVector().getTheta() * 180 / M_PI, 8.0, 1e-6);
  for (const auto &name : pm::compare::scenarioNames())
    EXPECT_FALSE(pm::compare::makeScenario(name, {pm::core::Phi{0, 0, 500, 0, 0, 0}, pm::core::Phi{20, 0, 500, 0, 0, 0}}).frames.empty()) << name;
  EXPECT_THROW(pm::compare::makeScenario("nope", {}), pm::core::Error);
}

TEST(Scenario, TheWorldAroundTheTargetOnRequestAStillBackdropClutterAndAGraspWithTheFingersInView)
{
  const std::vector<std::string> names{"still-backdrop", "clutter", "grasp"};
  for (const auto &name : names) { // on request only: the default comparison and its figures unchanged
    EXPECT_EQ(std::count(pm::compare::scenarioNames().begin(), pm::compare::scenarioNames().end(), name), 0) << name;
    EXPECT_EQ(std::count(pm::compare::allScenarioNames().begin(), pm::compare::allScenarioNames().end(), name), 1) << name;
  }
  const pm::compare::Scenario still = pm::compare::makeScenario("still-backdrop", {});
  const pm::compare::Scenario clutter = pm::compare::makeScenario("clutter", {});
  const pm::compare::Scenario grasp = pm::compare::makeScenario("grasp", {});
  for (const auto &f : still.frames)
    EXPECT_TRUE(f.stillBackdrop && !f.clutter && !f.gripper);
  for (const auto &f : clutter.frames)
    EXPECT_TRUE(f.clutter && !f.stillBackdrop && !f.gripper);
  for (const auto &f : grasp.frames)
    EXPECT_TRUE(f.gripper && !f.clutter && !f.stillBackdrop);
  EXPECT_NEAR(grasp.frames.front().hMo[2][3], 0.5, 1e-9); // from 500 to 300 mm ahead
  EXPECT_NEAR(grasp.frames.back().hMo[2][3], 0.3, 1e-9);
  // What they need: the clutter's toys built, a search that reaches 300 mm.
  pm::sim::SceneParams sp;
  sp.supersampling = 1;
  pm::rmga::SearchSpace space;
  pm::compare::prepareForScenarios({"table2"}, sp, space);
  EXPECT_FALSE(sp.clutter);
  EXPECT_DOUBLE_EQ(space.lo[2], pm::rmga::SearchSpace().lo[2]);
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  pm::sim::Scene plain(pm::sim::makeTarget("C12", 0.5), sp);
  EXPECT_THROW(pm::compare::renderScenarioFrame(plain, rig, clutter, 0), pm::core::Error);
  pm::compare::prepareForScenarios(names, sp, space);
  EXPECT_TRUE(sp.clutter);
  EXPECT_LE(space.lo[2], 250.0);
  pm::sim::Scene scene(pm::sim::makeTarget("C12", 0.5), sp);
  // Each scenario's frame differs from the same pose in the plain world where it should: the
  // clutter beside the target, the fingers at the bottom; the still backdrop stays in the images
  // while the target moves (the hand is held in pm-compare), where a resting one moves with it.
  auto render = [&](const pm::compare::Scenario &s, std::size_t k, bool plainWorld) {
    pm::compare::Scenario one = s;
    if (plainWorld) {
      one.frames[k] = pm::compare::ScenarioFrame();
      one.frames[k].hMo = s.frames[k].hMo;
    }
    return pm::compare::renderScenarioFrame(scene, rig, one, k).left;
  };
  auto changedShare = [](const vpImage<vpRGBa> &a, const vpImage<vpRGBa> &b, unsigned v0, unsigned v1) {
    long changed = 0, all = 0;
    for (unsigned v = v0; v < v1; ++v)
      for (unsigned u = 0; u < a.getWidth(); ++u, ++all)
        changed += std::abs(static_cast<int>(a[v][u].R) - static_cast<int>(b[v][u].R)) + std::abs(static_cast<int>(a[v][u].G) - static_cast<int>(b[v][u].G)) +
                           std::abs(static_cast<int>(a[v][u].B) - static_cast<int>(b[v][u].B)) > 60 ? 1 : 0; // well over the noise
    return static_cast<double>(changed) / static_cast<double>(all);
  };
  EXPECT_GT(changedShare(render(clutter, 60, false), render(clutter, 60, true), 0, 480), 0.03);
  const std::size_t last = grasp.frames.size() - 1;
  const vpImage<vpRGBa> withFingers = render(grasp, last, false), without = render(grasp, last, true);
  EXPECT_GT(changedShare(withFingers, without, 400, 480), 0.1);
  EXPECT_LT(changedShare(withFingers, without, 0, 240), 0.01); // the fingers stay in the lower half
  // The top rows, away from the target: the still backdrop's stay, the resting one's move.
  EXPECT_LT(changedShare(render(still, 0, false), render(still, 60, false), 0, 60), 0.01);
  EXPECT_GT(changedShare(render(still, 0, true), render(still, 60, true), 0, 60), 0.1);
}

TEST(CadMesh, TheToysOwnMeshCutAlongItsOutlineFacesOutAndCoversWhatTheRendererDraws)
{
  // pm-compare --mbt-true-cad: the crab's own mesh as ViSP's CAD model. Seen from the rig's left
  // camera near rest it covers the pixels the renderer covers with the toy (the mesh cut along the
  // toy's outline as the renderer cuts it); its faces turn out, toward the cameras above the toy
  // (the object frame's -z).
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  const pm::model::HullMesh cad = pm::compare::toyCadMesh(pm::sim::buildTargetMesh(scene.target(), 1.0));
  double up = 0, all = 0;
  for (std::size_t f = 0; f < cad.triangles.size(); ++f) {
    const auto &t = cad.triangles[f];
    const pm::model::hull::Vec3 c = pm::model::hull::cross(pm::model::hull::sub(cad.vertices[t[1]], cad.vertices[t[0]]),
                                                           pm::model::hull::sub(cad.vertices[t[2]], cad.vertices[t[0]]));
    const double area = 0.5 * std::sqrt(pm::model::hull::dot(c, c));
    all += area;
    up += cad.faceNormals[f][2] < 0 ? area : 0;
  }
  EXPECT_GT(up / all, 0.6);
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  const vpHomogeneousMatrix hMo(0.01, -0.005, 0.5, 0.1, 0.15, 0);
  pm::sim::Rasterizer r;
  vpImage<vpRGBa> photo;
  scene.render(r, rig.left, hMo, 1, 2, photo, true);
  std::vector<float> zbuf;
  cad.depthMap(pm::core::PinholeCamera::Projection(hMo.inverse() * rig.left.hMc, rig.left.cam, rig.left.width, rig.left.height), zbuf);
  long both = 0, either = 0;
  for (unsigned v = 0; v < rig.left.height; ++v)
    for (unsigned u = 0; u < rig.left.width; ++u) {
      const bool drawn = r.coverage(u, v, 2) >= 0.5, cadCovers = std::isfinite(zbuf[v * rig.left.width + u]);
      both += drawn && cadCovers;
      either += drawn || cadCovers;
    }
  ASSERT_GT(either, 5000);
  EXPECT_GT(static_cast<double>(both) / static_cast<double>(either), 0.98);
}

TEST(ComparedTrackers, ViSPsTrackersStartedAtTheTruthStayNearItOnSlowMotion)
{
  // The .cao model and the template are right if ViSP's trackers, started at the true pose,
  // follow a slow move: KLT (stereo, and in its monocular case on the left camera alone) and the
  // SSD template within 10 mm and 3 deg.
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  const pm::core::CameraRig mono = pm::io::loadCameraRig(pm::test::dataPath("rig/pa10_mono.json"));
  pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  const auto sm = pm::sim::makeSimulatedPhotoModel(scene, rig.left.cam, rig.left.width, rig.left.height, 500);
  const auto outline = pm::compare::outlinePolygon(sm.build.region, sm.build.model);
  TempDir d("compare");
  pm::test::writeText(d.file("model.cao"), pm::compare::caoText(outline, "test"));
  std::vector<std::unique_ptr<pm::compare::ComparedTracker>> ts;
  ts.push_back(pm::compare::makeMbtTracker(rig, pm::compare::MbtFeatures::Klt, d.file("model.cao"), pm::test::dataPath("compare/mbt.xml")));
  ts.push_back(pm::compare::makeTemplateTracker(rig, pm::compare::TemplateCost::Ssd, outline));
  ts.push_back(pm::compare::makeMbtTracker(mono, pm::compare::MbtFeatures::Klt, d.file("model.cao"), pm::test::dataPath("compare/mbt.xml")));
  for (int k = 0; k < 15; ++k) {
    const vpHomogeneousMatrix hMo(0.002 * k, 0.001 * k, 0.5, 0, 0, 0.004 * k);
    const auto im = scene.renderStereo(rig, hMo, static_cast<std::uint64_t>(k));
    for (std::size_t i = 0; i < ts.size(); ++i) {
      auto &t = ts[i];
      const pm::core::CameraImages frame = i == 2 ? pm::core::CameraImages(im.left) : pm::core::CameraImages(im.left, im.right);
      if (k == 0)
        t->start(frame, hMo * sm.oMm);
      const pm::compare::Estimate e = t->track(frame);
      const FrameScore s = pm::compare::scoreFrame(e.hMm, hMo * sm.oMm);
      EXPECT_TRUE(e.valid) << t->name() << " frame " << k;
      EXPECT_LT(s.translationMm, 10.0) << t->name() << " frame " << k;
      EXPECT_LT(s.rotationDeg, 3.0) << t->name() << " frame " << k;
    }
  }
}

//! Runs pm-compare with \e args into \e d; its summary.json (fails the test on a non-zero status).
nlohmann::json runCompare(const TempDir &d, const std::string &args)
{
  const auto r = runProgram("pm-compare", args + " --quiet --out " + d.path());
  EXPECT_EQ(r.status, 0) << r.err;
  return r.status == 0 ? nlohmann::json::parse(pm::test::readText(d.file("summary.json"))) : nlohmann::json::object();
}

TEST(PmCompare, OursRecoversFromTheForcedLossViSPsDoNot)
{
  // A deterministic run: our tracker on an evaluation budget (about its 5 ms) with a fixed seed.
  TempDir d("compare");
  const auto s = runCompare(d, "--scenarios loss --trackers ours,mbt-klt,template-ssd --budget-evals 1900 --ga-seed 1");
  ASSERT_TRUE(s.contains("trackers"));
  ASSERT_EQ(s.at("trackers").size(), 3u);
  for (const auto &t : s.at("trackers"))
    for (const char *key : {"name", "mean_frame_ms", "p99_frame_ms", "time_ratio_to_ours", "mean_translation_error_mm",
                            "max_translation_error_mm", "mean_rotation_error_deg", "success_5cm5deg", "success_1cm2deg",
                            "recovery_frames", "needs_initial_pose", "time_ratio_to_fastest_visp"})
      EXPECT_TRUE(t.contains(key)) << t.at("name") << " " << key;
  const auto &ours = s.at("trackers")[0];
  EXPECT_FALSE(ours.at("needs_initial_pose").get<bool>());
  EXPECT_DOUBLE_EQ(ours.at("time_ratio_to_ours").get<double>(), 1.0);
  // Held against ViSP's fastest of the run: its ratio is 1, the other's at least 1, ours' the ratio of the means.
  const auto &klt = s.at("trackers")[1], &ssd = s.at("trackers")[2];
  const bool kltFastest = klt.at("mean_frame_ms").get<double>() <= ssd.at("mean_frame_ms").get<double>();
  EXPECT_EQ(s.at("fastest_visp_tracker"), (kltFastest ? klt : ssd).at("name"));
  EXPECT_DOUBLE_EQ((kltFastest ? klt : ssd).at("time_ratio_to_fastest_visp").get<double>(), 1.0);
  EXPECT_GE((kltFastest ? ssd : klt).at("time_ratio_to_fastest_visp").get<double>(), 1.0);
  EXPECT_NEAR(ours.at("time_ratio_to_fastest_visp").get<double>(),
              ours.at("mean_frame_ms").get<double>() / (kltFastest ? klt : ssd).at("mean_frame_ms").get<double>(), 1e-9);
  // Back within 5 cm and 5 deg after the blank frames and after the jump: within 10 frames for at
  // least three of the four losses of two seeds, and within 20 for every one. (One seed's recovery
  // is one draw of a random search: issue 17 measured 22 of 24 seeds within 10 frames.)
  TempDir d2("compare2");
  const auto s2 = runCompare(d2, "--scenarios loss --trackers ours --budget-evals 1900 --ga-seed 2");
  int within10 = 0;
  for (const auto *summary : {&s, &s2}) {
    const auto &perLoss = summary->at("trackers")[0].at("scenarios").at("loss").at("recovery_frames_per_loss");
    ASSERT_EQ(perLoss.size(), 2u);
    for (const auto &frames : perLoss) {
      ASSERT_TRUE(frames.is_number()) << perLoss;
      EXPECT_LE(frames.get<int>(), 20) << perLoss;
      within10 += frames.get<int>() <= 10 ? 1 : 0;
    }
  }
  EXPECT_GE(within10, 3);
  for (std::size_t i = 1; i < 3; ++i) {
    EXPECT_TRUE(s.at("trackers")[i].at("needs_initial_pose").get<bool>());
    EXPECT_EQ(s.at("trackers")[i].at("recovery_frames"), "never") << s.at("trackers")[i].at("name");
  }
  for (const char *f : {"table.md", "frames.csv", "model.cao", "errors_loss.png", "snapshots_loss.png"})
    EXPECT_TRUE(std::filesystem::exists(d.file(f))) << f;
}

TEST(PmCompare, TheFlatAndTheThreeDModelSideBySideEachAgainstItsOwnTruth)
{
  // The crab's flat model is biased in depth by its relief (about 5 mm); its stereo model is not.
  // Each is scored against the truth of its own model frame.
  TempDir d("compare3d");
  const auto s = runCompare(d, "--scenarios table2 --steps 3 --trackers ours,ours-3d --budget-evals 1900 --ga-seed 1");
  ASSERT_TRUE(s.contains("trackers"));
  ASSERT_EQ(s.at("trackers").size(), 2u);
  const auto &flat = s.at("trackers")[0], &depth = s.at("trackers")[1];
  EXPECT_EQ(depth.at("key"), "ours-3d");
  EXPECT_FALSE(depth.at("needs_initial_pose").get<bool>());
  EXPECT_GT(depth.at("success_1cm2deg").get<double>(), 0.9);
  // (Its share within 1 cm / 2 deg is no longer above the flat model's: since issue 43's stereo
  // visibility the flat model's is 92.9 % here, 74.0 % with the paper's fitness; the stereo
  // model's 90.8 %, 91.8 %.) What the stereo model brings is the depth:
  EXPECT_LT(depth.at("mean_translation_error_mm").get<double>(), 0.5 * flat.at("mean_translation_error_mm").get<double>());
  // The flat model's depth bias (several mm, the crab's relief), which the stereo model removes.
  EXPECT_GT(flat.at("mean_translation_error_mm").get<double>(), 3.0);
  EXPECT_LT(depth.at("mean_translation_error_mm").get<double>(), 2.0);
}

TEST(PmCompare, BadInputIsAClearError)
{
  TempDir d("compare");
  const auto a = runProgram("pm-compare", "--scenarios nope --out " + d.file("o"));
  EXPECT_EQ(a.status, 2) << a.err;
  const auto b = runProgram("pm-compare", "--scenarios loss --mbt-config " + d.file("missing.xml") + " --out " + d.file("o"));
  EXPECT_EQ(b.status, 1);
  EXPECT_EQ(b.err.rfind("error: ", 0), 0u) << b.err;
  EXPECT_NE(b.err.find("missing.xml"), std::string::npos) << b.err;
  pm::test::writeText(d.file("bad.xml"), "<conf><ecm><mask><size>oops");
  // (--mbt-mesh-cell-mm 0: the one-face outline as ViSP's CAD model; the all-around model it spares is not what fails here.)
  const auto c = runProgram("pm-compare", "--scenarios loss --trackers mbt-edge --mbt-mesh-cell-mm 0 --mbt-config " + d.file("bad.xml") + " --out " + d.file("o"));
  EXPECT_EQ(c.status, 1) << c.err;
  EXPECT_EQ(c.err.rfind("error: ", 0), 0u) << c.err;
  EXPECT_FALSE(std::filesystem::exists(d.file("o/summary.json")));
  const auto e = runProgram("pm-compare", "--scenarios loss --trackers mbt-edge --mbt-true-cad --mbt-mesh-cell-mm 0 --out " + d.file("o"));
  EXPECT_EQ(e.status, 1) << e.err;
  EXPECT_NE(e.err.find("error: compare: the true CAD model is decimated"), std::string::npos) << e.err;
  EXPECT_FALSE(std::filesystem::exists(d.file("o/summary.json")));
}

TEST(PmConfidence, ItsFiguresOnASmallSetAndItsErrors)
{
  // Two runs on the loss scenario: the crab's own model, and the squid's model on the crab (every
  // frame wrong). The confidence ranks them (the squid's lock scores q 0.85 but its outline does
  // not fit: its confidence stays low), and the figures agree with the frames written.
  TempDir d("confidence");
  const auto r = runProgram("pm-confidence", "--quick --scenarios loss --quiet --out " + d.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto s = nlohmann::json::parse(pm::test::readText(d.file("summary.json")));
  for (const char *k : {"auroc", "threshold", "true_accept_rate", "false_accept_rate", "frames", "wrong_frames"})
    EXPECT_TRUE(s.contains(k)) << k;
  EXPECT_EQ(s.at("frames").get<int>(), 2 * 240);
  EXPECT_GE(s.at("wrong_frames").get<int>(), 240); // all of the squid model's
  EXPECT_GT(s.at("auroc").get<double>(), 0.95);
  EXPECT_LT(s.at("false_accept_rate").get<double>(), 0.01);
  EXPECT_GT(s.at("true_accept_rate").get<double>(), 0.8);
  // Run by run: the frames add up, and the squid's model has every frame wrong and none trusted.
  ASSERT_EQ(s.at("runs").size(), 2u);
  EXPECT_EQ(s.at("runs")[0].at("frames").get<int>() + s.at("runs")[1].at("frames").get<int>(), 2 * 240);
  EXPECT_EQ(s.at("runs")[1].at("wrong_frames").get<int>(), 240);
  EXPECT_EQ(s.at("runs")[1].at("trusted_wrong_frames").get<int>(), 0);
  EXPECT_EQ(s.at("runs")[0].at("trusted_right_frames").get<int>() + s.at("runs")[1].at("trusted_right_frames").get<int>(),
            static_cast<int>(std::lround(s.at("true_accept_rate").get<double>() * (2 * 240 - s.at("wrong_frames").get<int>()))));
  const std::string csv = pm::test::readText(d.file("frames.csv"));
  EXPECT_EQ(static_cast<int>(std::count(csv.begin(), csv.end(), '\n')), 2 * 240 + 1);
  EXPECT_TRUE(std::filesystem::exists(d.file("roc.png")));
  // Errors: an unknown scenario (usage), and --fit with a fold of one class only; nothing written.
  TempDir e("confidence-bad");
  EXPECT_EQ(runProgram("pm-confidence", "--quick --scenarios nope --out " + e.file("o")).status, 2);
  const auto f = runProgram("pm-confidence", "--quick --scenarios loss --fit --quiet --out " + e.file("o"));
  EXPECT_EQ(f.status, 1);
  EXPECT_NE(f.err.find("error: --fit"), std::string::npos) << f.err;
  EXPECT_FALSE(std::filesystem::exists(e.file("o") + "/summary.json"));
  // A camera held out of a fit that is not made, or that is not in the set; an unknown camera.
  for (const char *args : {"--hold-out jpeg --vary jpeg", "--fit --hold-out jpeg --vary defocus"}) {
    const auto h = runProgram("pm-confidence", std::string("--quick --scenarios loss --quiet ") + args + " --out " + e.file("o"));
    EXPECT_EQ(h.status, 1) << args;
    EXPECT_NE(h.err.find("error: --hold-out jpeg needs --fit and the same camera in --vary"), std::string::npos) << h.err;
  }
  EXPECT_EQ(runProgram("pm-confidence", "--quick --vary sepia --out " + e.file("o")).status, 2);
  EXPECT_FALSE(std::filesystem::exists(e.file("o") + "/summary.json"));
}

TEST(ConfidenceFit, TheRunsThroughAHeldOutCameraAreLeftOutOfTheFitAndScoredAfterIt)
{
  // Six runs of 200 frames: four through the renderer's camera, two through "jpeg", where the right
  // frames' cues sit lower (a softer outline) and the wrong ones as usual. Right frames: quality
  // and the worse camera's near 0.8, wrong ones near 0.3 (seeded noise).
  pm::compare::ConfidenceStudy st;
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 0.08);
  for (std::size_t run = 0; run < 6; ++run) {
    st.runNames.push_back("run " + std::to_string(run));
    st.runVariation.push_back(run >= 4 ? "jpeg" : "");
    for (int k = 0; k < 200; ++k) {
      pm::compare::LabelledFrame f;
      f.run = run;
      f.right = k % 4 != 0;
      const double q = (f.right ? (run >= 4 ? 0.65 : 0.8) : 0.3) + noise(rng);
      f.cues.quality = q;
      f.cues.qualityMin = q - 0.05;
      f.cues.inMatchMin = q;
      f.cues.outBackgroundMin = 0.9;
      f.cues.competitorMargin = f.right ? 0.3 : 0.0;
      f.cues.framesTracked = 30;
      f.cues.tracking = f.cues.verified = true;
      f.state = pm::tracker::TrackState::Tracking;
      st.frames.push_back(f);
      st.runOf.push_back(run);
    }
  }
  const auto kind = pm::tracker::ConfidenceKind::Flat;
  const pm::compare::ConfidenceFit all = pm::compare::fitConfidence(st, kind, 0.001);
  const pm::compare::ConfidenceFit held = pm::compare::fitConfidence(st, kind, 0.001, "jpeg");
  EXPECT_TRUE(all.heldOut.variation.empty());
  EXPECT_EQ(held.heldOut.variation, "jpeg");
  EXPECT_EQ(held.heldOut.runs, 2u);
  EXPECT_EQ(held.heldOut.frames, 400u);
  EXPECT_EQ(held.heldOut.wrong, 100u);
  // The fit's own figures are over the four other runs only (600 right frames), the held-out ones
  // counted by hand with the fitted model.
  EXPECT_LE(held.trustedRight, 600u);
  std::size_t right = 0, wrong = 0, rightOf[2] = {0, 0};
  std::vector<double> conf;
  std::vector<bool> label;
  for (std::size_t k = 0; k < st.frames.size(); ++k)
    if (st.runOf[k] >= 4) {
      const double c = held.model.confidence(st.frames[k].cues);
      conf.push_back(c);
      label.push_back(st.frames[k].right);
      right += st.frames[k].right && c >= held.model.threshold;
      rightOf[st.runOf[k] - 4] += st.frames[k].right && c >= held.model.threshold;
      wrong += !st.frames[k].right && c >= held.model.threshold;
    }
  EXPECT_EQ(held.heldOut.trustedRight, right);
  EXPECT_EQ(held.heldOut.trustedWrong, wrong);
  EXPECT_DOUBLE_EQ(held.heldOut.auroc, pm::compare::auroc(conf, label));
  EXPECT_GT(held.heldOut.auroc, 0.99);
  EXPECT_DOUBLE_EQ(held.heldOut.worstRunTrustedShare, static_cast<double>(std::min(rightOf[0], rightOf[1])) / 150.0); // 150 right frames a run
  // A camera no run was filmed through.
  const std::string e = pm::test::errorOf([&] { (void)pm::compare::fitConfidence(st, kind, 0.001, "defocus"); });
  EXPECT_NE(e.find("held-out camera 'defocus'"), std::string::npos) << e;
}

TEST(PmUncertainty, BadRunsAreRefusedAndNothingIsWritten)
{
  TempDir e("uncertainty-bad");
  for (const char *runs : {"C12:x", "Z9:1"}) {
    const auto r = runProgram("pm-uncertainty", std::string("--quiet --check-runs '' --fit-runs ") + runs + " --out " + e.file("o"));
    EXPECT_EQ(r.status, 1) << runs;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(e.file("o") + "/summary.json")) << runs;
  }
}

TEST(Comparison, OneRowPerFrameAndTrackerTheResultsShapeAndAClearErrorForAnUnknownTracker)
{
  // The runner behind pm-compare, on the first step of Table 2 with ours and ViSP's KLT tracker.
  TempDir d("comparison");
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  pm::compare::ComparisonParams p;
  p.scenarios = {"table2"};
  p.steps = 1;
  p.trackers = {"mbt-klt", "ours"};
  p.trajectoryPath = pm::test::dataPath("trajectories/table2.csv");
  p.mbtXml = pm::test::dataPath("compare/mbt.xml");
  p.tracker.search.budgetEvaluations = 800;
  pm::compare::Comparison c(rig, p);
  const std::string cao = d.file("model.cao");
  pm::test::writeText(cao, c.caoText());
  std::ostringstream csv;
  std::size_t calls = 0;
  const pm::compare::ComparisonResult r = c.run(cao, csv, [&] { ++calls; });
  const std::size_t n = c.totalFrames();
  ASSERT_GT(n, 10u);
  EXPECT_EQ(calls, n);
  ASSERT_EQ(r.scores.size(), 1u);
  ASSERT_EQ(r.scores[0].size(), 2u);
  EXPECT_EQ(r.scores[0][0].size(), n);
  EXPECT_EQ(r.scores[0][1].size(), n);
  EXPECT_EQ(r.keys, p.trackers);
  EXPECT_EQ(r.ours, 1u);
  EXPECT_EQ(r.fastest, 0u);
  EXPECT_TRUE(r.needsPose[0]);
  EXPECT_FALSE(r.needsPose[1]);
  EXPECT_EQ(r.snapshots.size(), 2u);
  EXPECT_FALSE(r.hadLoss);
  const std::string text = csv.str();
  EXPECT_EQ(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')), 1 + 2 * n); // header, then a row per frame and tracker
  const std::string table = pm::compare::comparisonTable(r);
  for (const std::string &name : r.names)
    EXPECT_NE(table.find(name), std::string::npos) << name;

  p.trackers = {"ours", "mbt-nothing"};
  const std::string e = pm::test::errorOf([&] { pm::compare::Comparison bad(rig, p); });
  EXPECT_NE(e.find("mbt-nothing"), std::string::npos) << e;
}
