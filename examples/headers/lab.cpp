// The usage examples of pm::lab's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/lab/ArmCameraSource.h"
#include "pm/lab/ClosedLoop.h"
#include "pm/lab/Convergence.h"
#include "pm/lab/FrequencyResponse.h"
#include "pm/lab/LabModel.h"
#include "pm/lab/LabSequence.h"
#include "pm/lab/LoopTable.h"
#include "pm/lab/RenderedScene.h"
#include "pm/lab/RunFigures.h"
#include "pm/lab/RunLog.h"
#include "pm/lab/RunRecorder.h"
#include "pm/lab/RunSummary.h"
#include "pm/lab/SceneExport.h"
#include "pm/lab/SimulatedHandEye.h"
#include "pm/lab/StillPair.h"
#include "pm/lab/TrackingReport.h"
#include "pm/lab/LabCache.h"
#include "pm/lab/ModelCache.h"
#include "pm/lab/TrustCache.h"

#include <fstream>
#include <iostream>
#include "pm/calib/ChessBoard.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/io/ViewsFolder.h"
#include "pm/robot/ArmCatalog.h"
#include "pm/robot/SteppedArm.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/sim/TcRobot.h"
#include "pm/trust/PassCalibration.h"
#include "pm/calib/RigComparison.h"
#include "pm/lab/LabPass.h"
#include "pm/lab/ModelMaking.h"
#include "pm/lab/SilhouetteTruth.h"
#include "pm/lab/SimulatedCalibration.h"
#include "pm/lab/SurfaceTruth.h"
#include "pm/lab/TargetRendering.h"
#include "pm/report/ModelOutputs.h"
namespace pm_examples {

// ArmCameraSource.h
void exampleArmCameraSource(const pm::sim::Scene &scene, const pm::core::StereoRig &rig)
{
  pm::robot::SteppedArm arm(pm::robot::makeArmModel("viper850"));
  const vpHomogeneousMatrix fMo = arm.fMh() * vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0); // 500 mm ahead
  pm::lab::ArmCameraSource cameras(scene, rig, arm, fMo, 30, 0);
  pm::capture::StereoFrame f;
  cameras.next(f);            // what the rig sees from the arm's hand, now
}

// ClosedLoop.h
void exampleClosedLoop()
{
  pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  const pm::core::StereoRig rig = pm::io::loadRig("data/rig/pa10_stereo.json");
  const pm::sim::SimulatedPhotoModel sm = pm::sim::makeSimulatedStereoPhotoModel(scene, rig);
  const std::vector<pm::core::Phi> steps{{0, 0, 500, 0, 0, 0}, {50, 0, 500, 0, 0, 0}}; // mm, quaternion vector, in h0
  auto makeTc = [&](const vpHomogeneousMatrix &wMh0) {
    return std::make_unique<pm::sim::TcRobot>(wMh0, pm::sim::Trajectory(steps, 1.5, 2.0));
  };
  pm::lab::ClosedLoop loop(rig, scene, sm, pm::tracker::TrackerParams(), pm::servo::ServoParams(), pm::lab::LoopParams(), makeTc);
  for (int k = 0; k < 150; ++k) {
    const pm::lab::LoopFrame f = loop.step();
    std::cout << f.t << " s: " << f.translationErrorMm << " mm, " << (f.servoing ? "servoing" : "held") << std::endl;
  }
}

// Convergence.h
void exampleConvergence(long n, const std::vector<double> &errMm, const std::vector<double> &errDeg)
{
  pm::lab::Convergence c(30); // 1 s at 30 fps
  for (long k = 0; k < n; ++k)
    c.add(k, static_cast<double>(k) / 30.0, errMm[k] <= pm::lab::kConvergedMm && errDeg[k] <= pm::lab::kConvergedDeg);
  c.finish();
  if (c.converged())
    std::cout << "converged after " << c.time() << " s (frame " << c.frame() << ")\n";
}

// FrequencyResponse.h
void exampleFrequencyResponse(const pm::core::StereoRig &rig, const pm::sim::Scene &scene, const pm::sim::SimulatedPhotoModel &model,
                              const pm::tracker::TrackerParams &tp, const pm::servo::ServoParams &servo, const pm::lab::LoopParams &lp)
{
  pm::lab::SweepParams sw;
  sw.maxVelocity = 250;
  sw.maxAcceleration = 1000;
  for (const pm::lab::BodePoint &p : pm::lab::frequencyResponse(rig, scene, model, tp, servo, lp, sw))
    std::cout << p.frequencyHz << " Hz: gain " << p.gain << ", lag " << p.phaseLagDeg << " deg\n";
}

// LabModel.h
void exampleLabModel(const pm::core::StereoRig &rig)
{
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  const pm::sim::SimulatedPhotoModel m = pm::lab::makeLabModel(scene, rig, pm::lab::LabModelChoice());
  pm::tracker::PhotoModelTracker tracker(rig, m.build.model);
}

// LabSequence.h
void exampleLabSequence(const pm::core::StereoRig &rig, pm::tracker::PhotoModelTracker &tracker)
{
  pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  const pm::sim::Trajectory trajectory({{0, 0, 500, 0, 0, 0}, {40, 0, 500, 0, 0, 0}}, 1.5, 1.0);
  pm::lab::LabSequence seq(scene, rig, trajectory, vpHomogeneousMatrix(), 30.0, 105);
  pm::capture::StereoFrame f;
  while (seq.next(f))
    tracker.track(f.left, f.right), std::cout << seq.truth(f.index).x << "\n";
}

// LoopTable.h
void exampleLoopTable(pm::lab::ClosedLoop &loop, long n)
{
  std::ofstream csv("frames.csv");
  pm::lab::writeLoopCsvHeader(csv, loop.arm().model().dof());
  for (long k = 0; k < n; ++k)
    pm::lab::writeLoopCsvRow(csv, loop.step(), false);
}

// RenderedScene.h
void exampleRenderedScene()
{
  const pm::lab::RenderedScene s = pm::lab::openRenderedScene("scenes/r2_sea");
  const pm::core::StereoRig rig = pm::io::loadRig(s.rigPath);
  const auto pass = pm::io::loadViewsFolder(s.viewsDir, rig, 6);
  const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass);
  const std::vector<pm::core::Phi> truth = s.truthInModelFrame(b.fMm); // frame k's hMm
}

// RunFigures.h
void exampleRunFigures(const std::vector<pm::lab::TrackedFrame> &frames)
{
  const pm::lab::TrackingReport r = pm::lab::reportTracking(frames, 30.0, pm::lab::table2Goals());
  pm::io::writeImage(pm::lab::drawTrackingTrajectory(frames, r, "simulator, C12"), "trajectory.png");
  if (r.haveTruth)
    pm::io::writeImage(pm::lab::drawTrackingErrors(frames, r), "errors.png");
}

// RunLog.h
void exampleRunLog(const pm::core::StereoRig &rig, const pm::sim::Scene &scene, const pm::sim::SimulatedPhotoModel &sm, const pm::tracker::TrackerParams &tp,
                   const pm::servo::ServoParams &sp, const pm::lab::LoopParams &lp,
                   const std::function<std::unique_ptr<pm::sim::TcRobot>(const vpHomogeneousMatrix &)> &makeTc)
{
  pm::lab::ClosedLoop loop(rig, scene, sm, tp, sp, lp, makeTc);
  const long n = static_cast<long>(60 * lp.fps) + 1; // one minute
  pm::lab::RunLog log(n, lp.fps, loop.arm().model());
  for (long k = 0; k < n; ++k)
    log.add(loop.step());
  log.finish();
  if (log.converged())
    std::cout << "converged after " << log.convergedAfterS() << " s, then " << log.atRest().rmsMm() << " mm rms at rest" << std::endl;
}

// RunRecorder.h
void exampleRunRecorder(pm::lab::ClosedLoop &loop, long n)
{
  pm::lab::RunRecorder rec("servo.avi", 30.0, 2 * 640, 480, 150, false); // a stereo rig of 640 x 480 cameras
  for (long k = 0; k < n; ++k) {
    const pm::lab::LoopFrame f = loop.step();
    rec.record(k, f, loop, [](const std::string &name) { return "out/" + name; });
  }
  rec.finish();
}

// RunSummary.h
void exampleRunSummary(pm::lab::RunLog &log)
{
  log.finish();
  pm::lab::RunInfo info;
  info.targetCode = "C12";
  pm::io::writeTextFile("summary.json", pm::lab::runSummaryJson(log, info));
  std::cout << pm::lab::runSummaryText(log, info);
}

// SceneExport.h
void exampleSceneExport()
{
  pm::lab::SceneExportParams p;
  p.target = "R2";
  p.stillBackdrop = true;   // the backdrop stands 100 mm behind the toy while the toy moves
  pm::lab::exportScene(p, pm::io::loadRig("data/rig/pa10_stereo.json"), "scenes/r2_still");
}

// SimulatedHandEye.h
void exampleSimulatedHandEye(const pm::core::StereoRig &rig)
{
  const pm::calib::ChessBoard board; // 6 x 9 inner corners, 20 mm squares
  pm::sim::Scene scene(pm::sim::flatPrint(board.render(8.0), board.widthMm(), "board"));
  const pm::lab::HandEyeResult r = pm::lab::simulatedHandEye(scene, rig, rig, board, 30, 1, 0.7);
  std::cout << r.left.translationErrorMm << " mm\n";
}

// StillPair.h
void exampleStillPair(const pm::core::StereoRig &rig)
{
  const pm::lab::StillPair user = pm::lab::loadStillPair({"L.png", "R.png"}, "model.json");
  const pm::lab::StillPair lab = pm::lab::renderStillPair(pm::sim::makeTarget("C12"), {0, 0, 500, 0, 0, 0}, rig,
                                                          pm::sim::SceneParams(), pm::lab::LabModelChoice());
  std::cout << lab.source << ": the model at " << lab.truth.toString() << "\n";
}

// TrackingReport.h
void exampleTrackingReport()
{
  std::vector<pm::lab::TrackedFrame> frames; // filled while tracking
  const pm::lab::TrackingReport r = pm::lab::reportTracking(frames, 30.0, pm::lab::table2Goals());
  std::cout << "converged after " << r.convergedS << " s, z rms " << r.errors[2].rms << " mm\n";
}

// TrustCache.h
void exampleTrustCache(const pm::core::StereoRig &rig, const std::vector<pm::model::PassView> &pass, const pm::model::AllAroundBuild &b,
                       const pm::model::AllAroundParams &params, const pm::model::PassMeasurements &measured)
{
  // what calibrateLabTrust() does:
  const pm::lab::TrustCache cache = pm::lab::TrustCache::fromEnvironment();
  const std::string key = pm::lab::TrustCache::keyOf(rig, pass, b.model);
  const pm::lab::LabTrust t = pm::lab::findOrMake<pm::lab::LabTrust>(
      cache.folder(), key, [&](const std::string &k) { return cache.find(k); },
      [&] {
        std::vector<pm::trust::PassTry> tries;
        pm::lab::LabTrust made;
        made.trust = pm::trust::calibrateFromPass(rig, pass, params, measured, pm::tracker::TrackerParams(),
                                                  pm::trust::CalibrationParams(), nullptr, nullptr, &tries);
        made.triesCsv = pm::trust::triesCsv(tries, made.trust);
        return made;
      },
      [&](const std::string &k, const pm::lab::LabTrust &made) { cache.store(k, made); });
}

// LabCache.h
void exampleLabCache(const pm::core::StereoRig &rig, const std::vector<pm::model::PassView> &pass)
{
  const pm::lab::LabCache cache = pm::lab::LabCache::fromEnvironment();
  const std::string key = pm::lab::CacheKey("my entry 1").rig(rig).pass(pass).hex();
  const std::string text = pm::lab::findOrMake<std::string>(
      cache, key, [&](const std::string &k) { return cache.read(k + ".txt"); },
      [] { return std::string("what was made"); },
      [&](const std::string &k, const std::string &made) { cache.write(k + ".txt", made); });
}

// ModelCache.h
void exampleModelCache(const pm::core::StereoRig &rig, const pm::lab::LabPass &pass, const pm::model::AllAroundParams &params,
                       bool calibrateTrust)
{
  // what makeSimulatedAllAroundModel() does:
  const pm::lab::ModelCache cache = pm::lab::ModelCache::fromEnvironment();
  const std::string key = pm::lab::ModelCache::keyOf(rig, pass.views, params, calibrateTrust);
  const pm::lab::CachedModel m = pm::lab::findOrMake<pm::lab::CachedModel>(
      cache.folder(), key, [&](const std::string &k) { return cache.find(k); },
      [&] {
        const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass.views, params);
        return pm::lab::CachedModel{b.model, b.fMm, b.silhouettes[0]};
      },
      [&](const std::string &k, const pm::lab::CachedModel &made) { cache.store(k, made); });
}

// LabPass.h
void exampleLabPass(const pm::sim::Scene &scene, const pm::core::StereoRig &rig)
{
  pm::robot::SteppedArm arm(pm::robot::makeArmModel("viper850"));
  const pm::lab::LabPass pass = pm::lab::runLabPass(scene, rig, pm::model::PassPlan(), arm);
  const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass.views);
  const vpHomogeneousMatrix oMm = pass.fMo.inverse() * b.fMm;   // ground truth of the model frame
}

// ModelMaking.h
void exampleModelMaking()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  pm::capture::ModelPairs pairs;
  pairs.background = {pm::io::readColorImage("bgL.png"), pm::io::readColorImage("bgR.png")};
  pairs.photo = {pm::io::readColorImage("toyL.png"), pm::io::readColorImage("toyR.png")};
  pm::report::ModelOutputs m = pm::lab::stereoModelFromPhotos(rig, pairs, pm::model::StereoModelParams(), "my toy");
  pm::report::writeModelOutputs("model", m, 0);
}

// SilhouetteTruth.h
void exampleSilhouetteTruth(const pm::sim::Scene &toyScene, const std::vector<pm::model::PassView> &pass, const vpHomogeneousMatrix &fMo,
                            const pm::model::AllAroundBuild &build, const pm::core::StereoRig &rig)
{
  const pm::lab::SilhouetteTruth t = pm::lab::checkSilhouettes(toyScene, pass, fMo, build, rig);
  std::cout << t.text;
}

// SimulatedCalibration.h
void exampleSimulatedCalibration(const pm::calib::Pattern &board)
{
  const pm::core::StereoRig truth = pm::lab::labRigWithLens(pm::core::LensDistortion{{-0.25, 0.08, 0.001, -0.0005, 0}});
  const auto pairs = pm::lab::renderCalibrationPairs(truth, board, 20, pm::lab::SimulatedCalibrationParams());
  const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, board);
  const pm::calib::CalibrationErrors e = pm::calib::compareRigs(c.rig, truth);
}

// SurfaceTruth.h
void exampleSurfaceTruth(const pm::sim::Scene &scene, const pm::model::AllAroundBuild &build, const vpHomogeneousMatrix &oMm, const pm::core::StereoRig &rig)
{
  const pm::lab::SurfaceTruth t = pm::lab::checkSurface(scene, build, oMm, rig.left.cam, 10);
  std::cout << "depth error median " << t.views[0].medianMm << " mm\n";
}

// TargetRendering.h
void exampleTargetRendering()
{
  const pm::core::StereoRig rig = pm::io::loadRig("data/rig/pa10_stereo.json");
  const pm::sim::TargetShape shape = pm::sim::makeTarget("C12");
  const pm::sim::Scene scene(shape);
  const pm::lab::RenderedTarget t = pm::lab::renderTarget(scene, shape, rig, pm::core::Phi{0, 0, 500, 0, 0, 0}, 5);
  pm::lab::writeRenderedTargets("render", {t}, pm::core::Phi{0, 0, 500, 0, 0, 0}, pm::sim::SceneParams(), false);
}

// SimulatedCalibration.h
void exampleSimulatedCalibration2(const pm::core::LensDistortion &lens, const pm::calib::Pattern &board)
{
  const pm::core::PinholeCamera truth = pm::lab::labRigWithLens(lens).left;
  const pm::lab::CalibrationPass pass = pm::lab::renderCalibrationViews(truth, board, 30, pm::lab::SimulatedCalibrationParams());
  const pm::calib::CameraCalibration c = pm::calib::calibrateCamera(pass.views, board);
}

} // namespace pm_examples
