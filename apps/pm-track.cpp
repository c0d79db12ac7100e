//! pm-track: real-time pose tracking of a moving target (the paper's Sec. 6, Table 2, Figs. 12-14).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include <visp3/core/vpThetaUVector.h>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/report/Overlay.h"
#include "pm/report/LiveView.h"
#include "pm/app/Progress.h"
#include "pm/capture/ImageSequenceSource.h"
#include "pm/capture/VideoCaptureSource.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/PoseTableFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/io/ViewsFolder.h"
#include "pm/lab/LabSequence.h"
#include "pm/lab/RenderedScene.h"
#include "pm/lab/SilhouetteTruth.h"
#include "pm/lab/SurfaceTruth.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PassRig.h"
#include "pm/lab/RunFigures.h"
#include "pm/lab/TrackingReport.h"
#include "pm/lab/TrustCache.h"
#include "pm/tracker/TrackerConfigFile.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/sim/Trajectory.h"
#include "pm/tracker/PhotoModelTracker.h"
#include "pm/trust/PassCalibration.h"

namespace {

//! pm-track's options.
struct Options
{
  std::string out, target = "C12", trajectoryPath = pm::app::dataPath("trajectories/table2.csv");
  std::string rigPath = pm::app::dataPath("rig/pa10_stereo.json"), modelPath, truthPath;
  std::vector<std::string> leftImages, rightImages;
  std::vector<std::string> cameraImages, cameraSources; //!< any rig: one image pattern, or one live source, per camera
  double holdS = 1.5, moveS = 1.0, fps = 30, durationS = 0;
  int firstFrame = 0, steps = 0;
  bool quiet = false, display = false, savePairs = false;
  std::string leftSource, rightSource;
  std::string sceneDir;   //!< a scene rendered elsewhere (pm-export-scene, scripts/cycles)
  bool scenePeer = false; //!< ... through our own renderer instead (its lab_views/, lab_sequence/)
  int sceneCameras = 2;   //!< ... through its rig's first camera alone (1) or its pair (2)
  pm::capture::VideoCaptureParams vcp;
  pm::app::LabModelChoice labModel;
  pm::sim::SceneParams sp;
  bool live() const { return !leftSource.empty() || !cameraSources.empty(); }
  bool recorded() const { return !leftImages.empty() || !cameraImages.empty() || live(); }
  bool scene() const { return !sceneDir.empty(); }
  long maxFrames() const { return durationS > 0 ? static_cast<long>(std::floor(durationS * fps)) + 1 : 0; }
};

void addOptions(CLI::App &app, Options &o)
{
  app.add_option("--out", o.out, "output folder (created if missing)")->required();
  auto *optTarget = app.add_option("--target", o.target, "simulated target C01..C12 (the paper's sea creatures) or R1..R3 (relief: box, head, tower)");
  app.add_option("--trajectory", o.trajectoryPath, "waypoints (step,x,y,z,e1,e2,e3), the target's poses in the hand frame");
  app.add_option("--hold-s", o.holdS, "time each step is held (s)")->check(CLI::Range(0.0, 3600.0));
  app.add_option("--move-s", o.moveS, "duration of each move between steps (s)")->check(CLI::Range(0.01, 3600.0));
  app.add_option("--steps", o.steps, "use only the first N waypoints (0: all)")->check(CLI::Range(0, 100000));
  app.add_option("--duration-s", o.durationS, "stop after this long (0: the whole trajectory)")->check(CLI::Range(0.0, 1e6));
  app.add_option("--fps", o.fps, "camera frame rate")->check(CLI::Range(1.0, 1000.0));
  auto *optL = app.add_option("--left", o.leftImages, "recorded sequence: left images, a printf pattern (e.g. L_%04d.png, from --first-frame) or files in pair order");
  auto *optR = app.add_option("--right", o.rightImages, "recorded sequence: right images, the same way");
  auto *optM = app.add_option("--model", o.modelPath, "recorded sequence: photo-model file");
  auto *optT = app.add_option("--truth", o.truthPath, "recorded sequence: ground truth, rows frame,x,y,z,e1,e2,e3");
  auto *optLS = app.add_option("--left-source", o.leftSource, "live: the left camera through OpenCV's VideoCapture: a device "
                                                             "index, a V4L2 path, a video file or a GStreamer pipeline");
  auto *optRS = app.add_option("--right-source", o.rightSource, "live: the right camera, the same way");
  auto *optI = app.add_option("--camera-images", o.cameraImages, "recorded sequence of any rig: one printf pattern per camera of --rig, in "
                                                          "its order (e.g. C_%04d.png for a rig of one camera), from --first-frame");
  auto *optS = app.add_option("--camera-sources", o.cameraSources, "live, any rig: one source per camera of --rig, in its order, as "
                                                            "--left-source takes them");
  app.add_option("--max-skew-ms", o.vcp.maxSkewMs, "live: largest time difference of the cameras' frames taken together")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--stall-s", o.vcp.stallTimeoutS, "live: a camera silent this long is an error")->check(CLI::PositiveNumber);
  optLS->needs(optRS)->needs(optM)->excludes(optTarget)->excludes(optL)->excludes(optI)->excludes(optS);
  optRS->needs(optLS);
  optI->needs(optM)->excludes(optTarget)->excludes(optL)->excludes(optS);
  optS->needs(optM)->excludes(optTarget)->excludes(optL);
  app.add_flag("--display", o.display, "show both views with the model, the state and the frame time in a ViSP window "
                                       "(vpDisplayX; its last picture, read back from the X server, into display.png); "
                                       "without it, or without an X display, headless");
  optL->needs(optR)->needs(optM)->excludes(optTarget);
  optR->needs(optL);
  (void)optT;
  app.add_option("--first-frame", o.firstFrame, "recorded sequence: index of the first frame")->check(CLI::Range(0, 100000000));
  auto *optRig = app.add_option("--rig", o.rigPath, "rig file: a stereo rig, or one to four cameras (--camera-images, --camera-sources, the simulator)");
  auto *optScene = app.add_option("--scene", o.sceneDir, "a scene rendered by another renderer (pm-export-scene, then "
                                  "scripts/cycles/render.py): the model is built from its pass (views/), as pm-make-model --views "
                                  "builds it, and its sequence is tracked against its truth");
  app.add_flag("--peer", o.scenePeer, "with --scene: the same scene through our own renderer (lab_views/, lab_sequence/)")->needs(optScene);
  app.add_option("--scene-cameras", o.sceneCameras, "with --scene: 2, its stereo rig; 1, its left camera alone (the pass then reads as a "
                                                    "one-camera pass, each view's right image the camera after the hand's side step, "
                                                    "docs/camera-rigs.md; the sequence's left images)")
      ->check(CLI::Range(1, 2))
      ->needs(optScene);
  optScene->excludes(optTarget)->excludes(optL)->excludes(optLS)->excludes(optM)->excludes(optRig)->excludes(optI)->excludes(optS);
  pm::app::addLabModelOptions(app, o.labModel);
  pm::app::addModelOptions(app, o.labModel.photo);
  pm::app::addSceneOptions(app, o.sp);
}

//! The pairs to track, recorded, live or simulated, with the model and the truth of each frame where it is known.
struct Input
{
  pm::core::PhotoModel model;
  std::unique_ptr<pm::sim::Scene> scene;
  std::unique_ptr<pm::sim::Trajectory> trajectory;
  std::unique_ptr<pm::capture::StereoSource> source; //!< a pair's source, or one of any rig (nextFrame())
  const pm::lab::LabSequence *lab = nullptr; //!< the simulator's sequence (its truth), when simulated
  std::map<long, pm::core::Phi> truthByFrame;
  long frames = 0;                           //!< the frames expected (0: unknown, live)
  std::string description;
};

//! The source of --camera-images (one pattern per camera) or --camera-sources (one per camera), any rig.
std::unique_ptr<pm::capture::StereoSource> openCameras(const Options &o, const pm::core::CameraRig &rig)
{
  pm::capture::VideoCaptureParams vcp = o.vcp;
  vcp.maxPairs = o.maxFrames();
  const std::vector<std::string> &given = o.cameraSources.empty() ? o.cameraImages : o.cameraSources;
  if (given.size() != rig.size())
    throw CLI::ValidationError(o.cameraSources.empty() ? "--camera-images" : "--camera-sources",
                               std::to_string(given.size()) + " given for a rig of " + std::to_string(rig.size()) + " camera" +
                                   (rig.size() == 1 ? "" : "s") + " (one per camera, in the rig's order)");
  if (!o.cameraSources.empty())
    return std::make_unique<pm::capture::VideoCaptureSource>(o.cameraSources, vcp);
  for (const std::string &p : o.cameraImages)
    if (!pm::app::isImagePattern({p}))
      throw CLI::ValidationError("--camera-images", "'" + p + "' is not a printf pattern (e.g. C_%04d.png): one pattern per camera");
  return pm::capture::ImageSequenceSource::ofCameras(o.cameraImages, o.firstFrame, o.fps, 0, 0, o.maxFrames());
}

Input openRecordedOrLive(const Options &o, const pm::core::CameraRig &rig)
{
  Input in;
  in.model = pm::io::loadPhotoModel(o.modelPath);
  if (!o.truthPath.empty())
    for (const auto &[frame, pose] : pm::io::readPoseTable(o.truthPath, "frame"))
      in.truthByFrame[frame] = pose;
  if (!o.cameraImages.empty() || !o.cameraSources.empty()) {
    in.source = openCameras(o, rig);
  } else if (rig.size() != 2) {
    throw CLI::ValidationError("--left/--right", "a stereo pair, but the rig has " + std::to_string(rig.size()) +
                                                     " camera" + (rig.size() == 1 ? "" : "s") + ": give --camera-images (or --camera-sources), one per camera");
  } else if (o.live()) {
    pm::capture::VideoCaptureParams vcp = o.vcp;
    vcp.maxPairs = o.maxFrames();
    in.source = std::make_unique<pm::capture::VideoCaptureSource>(o.leftSource, o.rightSource, vcp);
  } else if (pm::app::isImagePattern(o.leftImages) && pm::app::isImagePattern(o.rightImages)) {
    in.source = std::make_unique<pm::capture::ImageSequenceSource>(o.leftImages.front(), o.rightImages.front(), o.firstFrame, o.fps,
                                                                   rig[0].width, rig[0].height, o.maxFrames());
  } else {
    in.source = std::make_unique<pm::capture::ImageSequenceSource>(pm::app::imageFiles(o.leftImages, o.firstFrame),
                                                                   pm::app::imageFiles(o.rightImages, o.firstFrame), o.fps,
                                                                   rig[0].width, rig[0].height, o.maxFrames());
  }
  if (const auto *seq = dynamic_cast<const pm::capture::ImageSequenceSource *>(in.source.get()))
    in.frames = seq->length();
  else
    in.frames = o.maxFrames();
  in.description = in.source->describe();
  return in;
}

/*!
  The rig a scene is tracked through: its stereo rig, or its left camera alone. A one-camera pass takes each
  view's second image after the hand's side step (pm::model::passRig()): the scene's right camera must
  sit there for its views to read as such a pass.
*/
pm::core::CameraRig sceneRig(const Options &o)
{
  const pm::core::StereoRig stereo = pm::io::loadRig(pm::lab::openRenderedScene(o.sceneDir, o.scenePeer).rigPath);
  if (o.sceneCameras == 2)
    return pm::core::CameraRig(stereo);
  const pm::core::CameraRig one(std::vector<pm::core::PinholeCamera>{stereo.left});
  const vpHomogeneousMatrix d = pm::model::passRig(one).right.hMc.inverse() * stereo.right.hMc;
  if (d.getTranslationVector().frobeniusNorm() > 1e-6 || vpThetaUVector(d).getTheta() > 1e-6)
    throw pm::core::Error("--scene-cameras 1: the scene's right camera is not where a one-camera pass's side step puts its left "
                          "one (docs/camera-rigs.md), so its views do not read as a one-camera pass");
  return one;
}

//! A scene rendered elsewhere: the model from its pass (taken by \e cameras), its sequence, its truth in the model's frame.
Input openScene(const Options &o, const pm::core::CameraRig &cameras)
{
  const pm::lab::RenderedScene scene = pm::lab::openRenderedScene(o.sceneDir, o.scenePeer);
  const pm::core::StereoRig rig = pm::model::passRig(cameras); // the pass's pairs (one camera: after the side step)
  const pm::model::AllAroundParams &ap = o.labModel.allAroundParams;
  const std::vector<pm::model::PassView> pass = pm::io::loadViewsFolder(scene.viewsDir, rig, ap.carving.minViews, ap.backdropHueDeg < 0);
  pm::model::PassMeasurements measured;
  pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass, ap, measured);
  if (o.labModel.calibrateTrust)
    b.model.trust = pm::lab::calibrateLabTrust(cameras, pass, ap, measured, b.model).trust;
  if (!o.quiet) { // the model against the toy it was made of (the renderer's truth)
    const pm::sim::Scene toy(pm::sim::makeTarget(scene.target));
    std::cout << "model of " << scene.description << " against the toy:\n"
              << pm::lab::checkSilhouettes(toy, pass, scene.fMo, b, rig).text
              << pm::lab::checkSurface(toy, b, scene.fMo.inverse() * b.fMm, rig.left.cam).text << "  " << pm::trust::describe(b.model.trust)
              << std::endl;
  }
  Input in;
  in.model = b.model;
  const std::vector<pm::core::Phi> truth = scene.truthInModelFrame(b.fMm);
  for (std::size_t k = 0; k < truth.size(); ++k)
    in.truthByFrame[static_cast<long>(k)] = truth[k];
  std::unique_ptr<pm::capture::ImageSequenceSource> source =
      cameras.size() == 1 ? pm::capture::ImageSequenceSource::ofCameras({scene.leftPattern}, 0, o.fps, rig.left.width, rig.left.height, o.maxFrames())
                          : std::make_unique<pm::capture::ImageSequenceSource>(scene.leftPattern, scene.rightPattern, 0, o.fps,
                                                                               rig.left.width, rig.left.height, o.maxFrames());
  in.frames = source->length();
  in.source = std::move(source);
  in.description = scene.description + (cameras.size() == 1 ? ", its left camera alone" : "");
  return in;
}

Input openSimulated(const Options &o, const pm::core::CameraRig &rig)
{
  Input in;
  in.trajectory = std::make_unique<pm::sim::Trajectory>(pm::io::readWaypoints(o.trajectoryPath, o.steps), o.holdS, o.moveS);
  in.scene = std::make_unique<pm::sim::Scene>(pm::sim::makeTarget(o.target), o.sp);
  const auto sm = pm::app::makeLabModel(*in.scene, rig, o.labModel);
  in.model = sm.build.model;
  const double d = o.durationS > 0 ? std::min(o.durationS, in.trajectory->duration()) : in.trajectory->duration();
  in.frames = static_cast<long>(std::floor(d * o.fps)) + 1;
  auto seq = std::make_unique<pm::lab::LabSequence>(*in.scene, rig, *in.trajectory, sm.oMm, o.fps, in.frames);
  in.lab = seq.get();
  in.source = std::move(seq);
  in.description = in.source->describe() + ", trajectory " + std::filesystem::path(o.trajectoryPath).filename().string();
  return in;
}

//! What the run recorded: every frame, and the last frame's images (for its picture).
struct Run
{
  std::vector<pm::lab::TrackedFrame> frames;
  std::vector<vpImage<vpRGBa>> last; //!< one per camera
};

//! What --save-pairs names camera \e k's image of frame \e frame: left_%04d.png and right_%04d.png for a pair, camera<k>_%04d.png otherwise.
std::string savedImageName(const pm::core::CameraRig &rig, std::size_t k, int frame)
{
  const std::string pattern = rig.size() == 2 ? (k ? "right_%04d.png" : "left_%04d.png") : "camera" + std::to_string(k) + "_%04d.png";
  return pm::app::frameFileName(pattern, frame);
}

//! The frame's truth, where the simulator or the truth file knows it.
void setTruth(const Input &in, long index, pm::lab::TrackedFrame &f)
{
  if (in.lab) {
    f.haveTruth = true;
    f.truth = in.lab->truth(index);
    f.moving = in.lab->moving(index);
  } else if (const auto it = in.truthByFrame.find(index); it != in.truthByFrame.end()) {
    f.haveTruth = true;
    f.truth = it->second;
  }
}

//! The frame's images against the rig's cameras' sizes; throws naming the first that differs.
void checkSizes(const pm::capture::CameraFrame &cf, const pm::core::CameraRig &rig)
{
  for (std::size_t k = 0; k < cf.images.size() && k < rig.size(); ++k)
    if (cf.images[k].getWidth() != rig[k].width || cf.images[k].getHeight() != rig[k].height)
      throw pm::core::Error("the cameras deliver " + std::to_string(cf.images[k].getWidth()) + "x" + std::to_string(cf.images[k].getHeight()) +
                            " images but the rig's are " + std::to_string(rig[k].width) + "x" + std::to_string(rig[k].height));
}

//! The live window's picture of the frame: every camera with the model's points, the state in words.
void showFrame(const pm::capture::CameraFrame &cf, const pm::lab::TrackedFrame &f, int k, const pm::tracker::PhotoModelTracker &tracker,
               pm::report::LiveView &view)
{
  std::ostringstream status;
  status << std::fixed << std::setprecision(2) << pm::tracker::toString(f.result.state) << ", q " << f.result.quality << ", "
         << std::setprecision(1) << f.result.computeMs << " ms, frame " << k << (f.result.trusted ? ", trusted" : ", held: ")
         << (f.result.heldBy && !f.result.trusted ? f.result.heldBy : "");
  std::vector<std::vector<pm::core::PointScore>> scores;
  for (std::size_t c = 0; c < cf.images.size(); ++c)
    scores.push_back(tracker.pointScores(static_cast<int>(c)));
  view.show(cf.view(), scores, status.str());
}

//! Tracks every frame of \e in; with --save-pairs, stages the images (and the simulator's truth.csv) in \e files.
Run track(const Options &o, const pm::core::CameraRig &rig, Input &in, pm::tracker::PhotoModelTracker &tracker, pm::io::StagedFiles &files,
          pm::report::LiveView &view)
{
  std::ofstream truthCsv;
  if (o.savePairs && in.lab)
    truthCsv.open(files.stage("truth.csv"));
  truthCsv << "frame,x,y,z,e1,e2,e3\n" << std::setprecision(10);
  Run run;
  run.frames.reserve(static_cast<std::size_t>(std::max(0L, in.frames)));
  pm::app::Progress progress("tracking", static_cast<std::size_t>(std::max(0L, in.frames)), o.quiet || in.frames <= 0);
  pm::capture::CameraFrame cf;
  for (int k = 0;; ++k) {
    const long skippedBefore = in.source->stats().skipped;
    if (!in.source->nextFrame(cf))
      break;
    for (long s2 = skippedBefore; s2 < in.source->stats().skipped; ++s2) {
      if (!o.quiet)
        std::cerr << "warning: " << in.source->stats().problems[static_cast<std::size_t>(s2)] << " (skipped)" << std::endl;
      progress.step();
    }
    checkSizes(cf, rig);
    pm::lab::TrackedFrame f;
    f.t = cf.timeS;
    setTruth(in, cf.index, f);
    if (o.savePairs) {
      for (std::size_t c = 0; c < cf.images.size(); ++c)
        pm::io::writeImage(cf.images[c], files.stage(savedImageName(rig, c, k)));
      if (in.lab)
        truthCsv << k << "," << f.truth[0] << "," << f.truth[1] << "," << f.truth[2] << "," << f.truth[3] << ","
                 << f.truth[4] << "," << f.truth[5] << "\n";
    }
    f.result = tracker.track(cf.view());
    run.frames.push_back(f);
    if (o.display)
      showFrame(cf, f, k, tracker, view);
    // Keep the images without copying them: ViSP's own swap() trades the pixel buffers (both images
    // own theirs). Not std::move: ViSP 3.5's vpImage loses ownership of its pixels when a moved-from
    // image is assigned again, and the source refills cf every frame.
    run.last.resize(cf.images.size());
    for (std::size_t c = 0; c < cf.images.size(); ++c)
      swap(run.last[c], cf.images[c]);
    progress.step();
  }
  progress.finish();
  if (run.frames.empty())
    throw pm::core::Error("no frame of the sequence could be read (" + std::to_string(in.source->stats().skipped) + " unreadable)");
  if (truthCsv.is_open() && !truthCsv.flush())
    throw pm::core::Error("cannot write " + files.finalPath("truth.csv"));
  return run;
}

//! frames.csv, the figures, the last frame's picture and summary.json; the summary on stdout.
void writeOutputs(const Options &o, const Input &in, Run &run, const pm::tracker::TrackerParams &tp, pm::tracker::PhotoModelTracker &tracker,
                  pm::io::StagedFiles &files, pm::report::LiveView &view)
{
  const pm::lab::TrackingReport report = pm::lab::reportTracking(run.frames, o.fps, pm::lab::table2Goals());
  {
    std::ofstream csv(files.stage("frames.csv"));
    pm::lab::writeFramesCsv(csv, run.frames);
  }
  // Figures like the paper's 13 (estimate against truth) and 14 (errors after convergence).
  pm::io::writeImage(pm::lab::drawTrackingTrajectory(run.frames, report, in.description), files.stage("trajectory.png"));
  if (report.haveTruth)
    pm::io::writeImage(pm::lab::drawTrackingErrors(run.frames, report), files.stage("errors.png"));
  const pm::tracker::TrackResult &last = run.frames.back().result;
  tracker.initFromPose(last.hMo); // to draw the last estimate
  std::vector<std::vector<pm::core::PointScore>> scores;
  for (std::size_t c = 0; c < run.last.size(); ++c)
    scores.push_back(tracker.fitness().pointScores(last.phi, static_cast<int>(c)));
  pm::io::writeImage(pm::report::drawCameras(pm::core::CameraImages::of(run.last), scores, pm::report::cameraLabels(run.last.size(), "last frame, ")),
                     files.stage("last_frame.png"));
  if (view.isOpen())
    view.capture(files.stage("display.png"));
  pm::lab::TrackingRunInfo info;
  info.source = in.description;
  info.frames = run.frames.size();
  info.fps = o.fps;
  info.stats = in.source->stats();
  info.live = o.live();
  info.trackerJson = pm::tracker::trackerConfigToJson(tp);
  info.budget = tp.search.budgetEvaluations > 0 ? std::to_string(tp.search.budgetEvaluations) + " evaluations"
                                                : std::to_string(tp.search.budgetMs) + " ms";
  pm::io::writeTextFile(files.stage("summary.json"), pm::lab::trackingSummaryJson(report, info));
  files.commit();
  if (!o.quiet)
    std::cout << pm::lab::trackingSummaryText(report, info) << "  written to " << files.dir() << "/" << std::endl;
}

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"Real-time tracking (the paper's Sec. 6): the PT-robot is fixed, the target moves through the 20 steps "
               "of Table 2 (smooth moves of bounded velocity and acceleration), the cameras run at 30 fps, and the "
               "tracker, started from a random population with no initial pose, gets --budget-ms (or --budget-evals) of "
               "compute per stereo frame. Also runs on a recorded stereo sequence (--left, --right) or live cameras (--left-source, "
               "--right-source). Writes frames.csv, trajectory.png (estimate against truth), errors.png and summary.json.",
               "pm-track"};
  app.option_defaults()->always_capture_default();
  Options o;
  addOptions(app, o);
  pm::app::TrackerOptions trackerOptions(app, pm::tracker::TrackerParams());
  app.add_flag("--save-pairs", o.savePairs, "also write every stereo pair tracked, left_%04d.png and right_%04d.png (a rig of "
                                            "other than two cameras: camera0_%04d.png, camera1_%04d.png ...; and, on the simulator, "
                                            "its truth in truth.csv): a recording that --left, --right (or --camera-images) and --truth replay");
  app.add_flag("--quiet", o.quiet, "no progress, no summary on stdout");

  return pm::app::run(app, argc, argv, [&] {
    const pm::tracker::TrackerParams tp = trackerOptions.resolve();
    if (!o.truthPath.empty() && (!o.recorded() || o.live()))
      throw CLI::ValidationError("--truth", "the truth of a recorded sequence (--left/--right or --camera-images)");
    // A scene rendered elsewhere is a stereo rig's (or its left camera's); the rest take any rig.
    const pm::core::CameraRig rig = o.scene() ? sceneRig(o) : pm::io::loadCameraRig(o.rigPath);
    if (pm::app::isImagePattern(o.leftImages)) // check both patterns before anything else
      pm::app::frameFileName(o.leftImages.front(), 0);
    if (pm::app::isImagePattern(o.rightImages))
      pm::app::frameFileName(o.rightImages.front(), 0);
    Input in = o.scene() ? openScene(o, rig) : o.recorded() ? openRecordedOrLive(o, rig) : openSimulated(o, rig);
    pm::tracker::PhotoModelTracker tracker(rig, in.model, tp);
    tracker.initialize(); // no initial pose: a random population
    pm::io::StagedFiles files(o.out);
    pm::report::LiveView view;
    if (o.display)
      view.open("pm-track: " + in.description);
    Run run = track(o, rig, in, tracker, files, view);
    writeOutputs(o, in, run, tp, tracker, files, view);
    return 0;
  }, {{"--left-images", "--left", {}}, {"--right-images", "--right", {}}});
}
