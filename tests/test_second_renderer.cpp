// The second renderer's scenes (Blender's Cycles, scripts/render-cycles.sh; kept outside the
// repository at $PM_CYCLES_DIR, else ~/.cache/visp-photomodel/cycles): a toy resting on its backdrop
// under an area light, its soft shadow along its outline. Its silhouettes hold no penumbra, the pass
// calibrates the trust, and the tracker is trusted on the right frames of its sequence and on no wrong
// one. Skipped, saying why, where the set was not rendered (CI: it takes hours to render).
#include <gtest/gtest.h>

#include <filesystem>

#include "TestSupport.h"
#include "pm/capture/ImageSequenceSource.h"
#include "pm/io/RigFile.h"
#include "pm/io/ViewsFolder.h"
#include "pm/lab/RenderedScene.h"
#include "pm/lab/SilhouetteTruth.h"
#include "pm/lab/TrackingReport.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/tracker/PhotoModelTracker.h"
#include "pm/trust/PassCalibration.h"

TEST(SecondRenderer, TheCrabRestingOnItsBackdropUnderASoftLightIsTrustedOnItsRightFramesOnly)
{
  const std::string dir = pm::lab::renderedScenesDir() + "/c12_sea";
  if (!std::filesystem::exists(dir + "/sequence/truth.csv"))
    GTEST_SKIP() << "the second renderer's set is not at " << dir << " (bash scripts/render-cycles.sh renders it, in hours)";
  const pm::lab::RenderedScene scene = pm::lab::openRenderedScene(dir);
  const pm::core::StereoRig rig = pm::io::loadRig(scene.rigPath);
  const std::vector<pm::model::PassView> pass = pm::io::loadViewsFolder(scene.viewsDir, rig, 6);
  pm::model::PassMeasurements measured;
  pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass, pm::model::AllAroundParams(), measured);
  // The silhouettes against the toy's outline: the umbra and penumbra where it rests are not the toy.
  const pm::lab::SilhouetteTruth sil = pm::lab::checkSilhouettes(pm::sim::Scene(pm::sim::makeTarget(scene.target)), pass, scene.fMo, b, rig);
  std::cout << sil.text;
  EXPECT_LT(std::fabs(sil.meanPx), 0.5);
  EXPECT_LT(sil.p95OutsidePx, 3.0);
  EXPECT_LT(sil.addedShare, 0.05);
  EXPECT_LT(sil.missedShare, 0.03);
  b.model.trust = pm::trust::calibrateFromPass(rig, pass, pm::model::AllAroundParams(), measured);
  std::cout << pm::trust::describe(b.model.trust) << "\n";
  ASSERT_TRUE(b.model.trust.measured);
  EXPECT_EQ(b.model.trust.wrongTrusted, 0);
  // The sequence, as pm-track --scene tracks it.
  const std::vector<pm::core::Phi> truth = scene.truthInModelFrame(b.fMm);
  pm::tracker::PhotoModelTracker tracker(rig, b.model);
  tracker.initialize();
  pm::capture::ImageSequenceSource source(scene.leftPattern, scene.rightPattern, 0, 30, rig.left.width, rig.left.height);
  pm::capture::StereoFrame f;
  std::vector<pm::lab::TrackedFrame> frames;
  while (source.next(f)) {
    pm::lab::TrackedFrame t;
    t.result = tracker.track(f.left, f.right);
    t.haveTruth = true;
    t.truth = truth.at(static_cast<std::size_t>(f.index));
    frames.push_back(t);
  }
  const pm::lab::TrackingReport r = pm::lab::reportTracking(frames, 30, pm::lab::table2Goals());
  std::cout << "right " << r.rightFrames << ", trusted " << r.rightTrusted << "; wrong " << r.wrongFrames << ", trusted " << r.wrongTrusted
            << "; rotation rms " << r.rotationRmsDeg << " deg\n";
  EXPECT_GT(r.rightFrames, 100);
  EXPECT_GE(static_cast<double>(r.rightTrusted), 0.8 * static_cast<double>(r.rightFrames));
  EXPECT_EQ(r.wrongTrusted, 0);
}
