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
#include "pm/lab/LabSequence.h"
#include "pm/lab/RunFigures.h"
#include "pm/lab/TrackingReport.h"
#include "pm/tracker/TrackerConfigFile.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/sim/Trajectory.h"
#include "pm/tracker/PhotoModelTracker.h"

int main(int argc, char **argv)
{
  CLI::App app{"Real-time tracking (the paper's Sec. 6): the PT-robot is fixed, the target moves through the 20 steps "
               "of Table 2 (smooth moves of bounded velocity and acceleration), the cameras run at 30 fps, and the "
               "tracker, started from a random population with no initial pose, gets --budget-ms (or --budget-evals) of "
               "compute per stereo frame. Also runs on a recorded stereo sequence (--left, --right) or live cameras (--left-source, "
               "--right-source). Writes frames.csv, trajectory.png (estimate against truth), errors.png and summary.json.",
               "pm-track"};
  app.option_defaults()->always_capture_default();
  std::string out, target = "C12", trajectoryPath = pm::app::dataPath("trajectories/table2.csv");
  std::string rigPath = pm::app::dataPath("rig/pa10_stereo.json"), modelPath, truthPath;
  std::vector<std::string> leftImages, rightImages;
  double holdS = 1.5, moveS = 1.0, fps = 30, durationS = 0;
  int firstFrame = 0, steps = 0;
  bool quiet = false, display = false, savePairs = false;
  std::string leftSource, rightSource;
  pm::capture::VideoCaptureParams vcp;
  pm::app::LabModelChoice labModel;
  pm::sim::SceneParams sp;
  app.add_option("--out", out, "output folder (created if missing)")->required();
  auto *optTarget = app.add_option("--target", target, "simulated target C01..C12 (the paper's sea creatures) or R1..R3 (relief: box, head, tower)");
  app.add_option("--trajectory", trajectoryPath, "waypoints (step,x,y,z,e1,e2,e3), the target's poses in the hand frame");
  app.add_option("--hold-s", holdS, "time each step is held (s)")->check(CLI::Range(0.0, 3600.0));
  app.add_option("--move-s", moveS, "duration of each move between steps (s)")->check(CLI::Range(0.01, 3600.0));
  app.add_option("--steps", steps, "use only the first N waypoints (0: all)")->check(CLI::Range(0, 100000));
  app.add_option("--duration-s", durationS, "stop after this long (0: the whole trajectory)")->check(CLI::Range(0.0, 1e6));
  app.add_option("--fps", fps, "camera frame rate")->check(CLI::Range(1.0, 1000.0));
  auto *optL = app.add_option("--left", leftImages, "recorded sequence: left images, a printf pattern (e.g. L_%04d.png, from --first-frame) or files in pair order");
  auto *optR = app.add_option("--right", rightImages, "recorded sequence: right images, the same way");
  auto *optM = app.add_option("--model", modelPath, "recorded sequence: photo-model file");
  auto *optT = app.add_option("--truth", truthPath, "recorded sequence: ground truth, rows frame,x,y,z,e1,e2,e3");
  auto *optLS = app.add_option("--left-source", leftSource, "live: the left camera through OpenCV's VideoCapture: a device "
                                                           "index, a V4L2 path, a video file or a GStreamer pipeline");
  auto *optRS = app.add_option("--right-source", rightSource, "live: the right camera, the same way");
  app.add_option("--max-skew-ms", vcp.maxSkewMs, "live: largest time difference of a left and a right frame paired")
      ->check(CLI::NonNegativeNumber)->needs(optLS);
  app.add_option("--stall-s", vcp.stallTimeoutS, "live: a camera silent this long is an error")->check(CLI::PositiveNumber)->needs(optLS);
  optLS->needs(optRS)->needs(optM)->excludes(optTarget)->excludes(optL);
  optRS->needs(optLS);
  app.add_flag("--display", display, "show both views with the model, the state and the frame time in a ViSP window "
                                     "(vpDisplayX; its last picture, read back from the X server, into display.png); "
                                     "without it, or without an X display, headless");
  optL->needs(optR)->needs(optM)->excludes(optTarget);
  optR->needs(optL);
  optT->needs(optL);
  app.add_option("--first-frame", firstFrame, "recorded sequence: index of the first frame")->check(CLI::Range(0, 100000000));
  app.add_option("--rig", rigPath, "stereo rig file");
  pm::app::addLabModelOptions(app, labModel);
  pm::app::addModelOptions(app, labModel.photo);
  pm::app::addSceneOptions(app, sp);
  pm::app::TrackerOptions trackerOptions(app, pm::tracker::TrackerParams());
  app.add_flag("--save-pairs", savePairs, "also write every stereo pair tracked, left_%04d.png and right_%04d.png (and, "
                                          "on the simulator, its truth in truth.csv): a recording that --left, --right and "
                                          "--truth replay");
  app.add_flag("--quiet", quiet, "no progress, no summary on stdout");

  return pm::app::run(app, argc, argv, [&] {
    const pm::tracker::TrackerParams tp = trackerOptions.resolve();
    const pm::core::StereoRig rig = pm::io::loadRig(rigPath);
    const bool live = !leftSource.empty();
    const bool recorded = !leftImages.empty() || live;
    if (pm::app::isImagePattern(leftImages)) // check both patterns before anything else
      pm::app::frameFileName(leftImages.front(), 0);
    if (pm::app::isImagePattern(rightImages))
      pm::app::frameFileName(rightImages.front(), 0);
    const long maxFrames = durationS > 0 ? static_cast<long>(std::floor(durationS * fps)) + 1 : 0;

    // The pairs: recorded, live or simulated, and the truth of each frame where it is known.
    pm::core::PhotoModel model;
    std::unique_ptr<pm::sim::Scene> scene;
    std::unique_ptr<pm::sim::Trajectory> trajectory;
    std::unique_ptr<pm::capture::StereoSource> input;
    const pm::lab::LabSequence *lab = nullptr;
    std::map<long, pm::core::Phi> truthByFrame;
    long nFrames = 0;
    std::string source;
    if (recorded) {
      model = pm::io::loadPhotoModel(modelPath);
      if (!truthPath.empty())
        for (const auto &[frame, pose] : pm::io::readPoseTable(truthPath, "frame"))
          truthByFrame[frame] = pose;
      if (live) {
        vcp.maxPairs = maxFrames;
        input = std::make_unique<pm::capture::VideoCaptureSource>(leftSource, rightSource, vcp);
      } else if (pm::app::isImagePattern(leftImages) && pm::app::isImagePattern(rightImages)) {
        input = std::make_unique<pm::capture::ImageSequenceSource>(leftImages.front(), rightImages.front(), firstFrame, fps,
                                                                   rig.left.width, rig.left.height, maxFrames);
      } else {
        input = std::make_unique<pm::capture::ImageSequenceSource>(pm::app::imageFiles(leftImages, firstFrame),
                                                                   pm::app::imageFiles(rightImages, firstFrame), fps,
                                                                   rig.left.width, rig.left.height, maxFrames);
      }
      if (const auto *seq = dynamic_cast<const pm::capture::ImageSequenceSource *>(input.get()))
        nFrames = seq->length();
      else
        nFrames = maxFrames;
      source = input->describe();
    } else {
      trajectory = std::make_unique<pm::sim::Trajectory>(pm::io::readWaypoints(trajectoryPath, steps), holdS, moveS);
      scene = std::make_unique<pm::sim::Scene>(pm::sim::makeTarget(target), sp);
      const auto sm = pm::app::makeLabModel(*scene, rig, labModel);
      model = sm.build.model;
      const double d = durationS > 0 ? std::min(durationS, trajectory->duration()) : trajectory->duration();
      nFrames = static_cast<long>(std::floor(d * fps)) + 1;
      auto seq = std::make_unique<pm::lab::LabSequence>(*scene, rig, *trajectory, sm.oMm, fps, nFrames);
      lab = seq.get();
      input = std::move(seq);
      source = input->describe() + ", trajectory " + std::filesystem::path(trajectoryPath).filename().string();
    }

    pm::tracker::PhotoModelTracker tracker(rig, model, tp);
    tracker.initialize(); // no initial pose: a random population
    pm::io::StagedFiles files(out);
    std::ofstream truthCsv;
    if (savePairs && lab)
      truthCsv.open(files.stage("truth.csv"));
    truthCsv << "frame,x,y,z,e1,e2,e3\n" << std::setprecision(10);
    std::vector<pm::lab::TrackedFrame> rec;
    rec.reserve(static_cast<std::size_t>(std::max(0L, nFrames)));
    vpImage<vpRGBa> lastL, lastR;
    pm::app::Progress progress("tracking", static_cast<std::size_t>(std::max(0L, nFrames)), quiet || nFrames <= 0);
    pm::report::LiveView view;
    if (display)
      view.open("pm-track: " + source);
    pm::capture::StereoFrame sf;
    for (int k = 0;; ++k) {
      const long skippedBefore = input->stats().skipped;
      if (!input->next(sf))
        break;
      for (long s2 = skippedBefore; s2 < input->stats().skipped; ++s2) {
        if (!quiet)
          std::cerr << "warning: " << input->stats().problems[static_cast<std::size_t>(s2)] << " (skipped)" << std::endl;
        progress.step();
      }
      if (sf.left.getWidth() != rig.left.width || sf.left.getHeight() != rig.left.height)
        throw pm::core::Error("the cameras deliver " + std::to_string(sf.left.getWidth()) + "x" + std::to_string(sf.left.getHeight()) +
                        " images but the rig's are " + std::to_string(rig.left.width) + "x" + std::to_string(rig.left.height));
      pm::lab::TrackedFrame f;
      f.t = sf.timeS;
      if (lab) {
        f.haveTruth = true;
        f.truth = lab->truth(sf.index);
        f.moving = lab->moving(sf.index);
      } else if (const auto it = truthByFrame.find(sf.index); it != truthByFrame.end()) {
        f.haveTruth = true;
        f.truth = it->second;
      }
      if (savePairs) {
        pm::io::writeImage(sf.left, files.stage(pm::app::frameFileName("left_%04d.png", k)));
        pm::io::writeImage(sf.right, files.stage(pm::app::frameFileName("right_%04d.png", k)));
        if (lab)
          truthCsv << k << "," << f.truth[0] << "," << f.truth[1] << "," << f.truth[2] << "," << f.truth[3] << ","
                   << f.truth[4] << "," << f.truth[5] << "\n";
      }
      f.result = tracker.track(sf.left, sf.right);
      rec.push_back(f);
      if (display) {
        std::ostringstream status;
        status << std::fixed << std::setprecision(2) << pm::tracker::toString(f.result.state) << ", q " << f.result.quality << ", "
               << std::setprecision(1) << f.result.computeMs << " ms, frame " << k;
        view.show(sf.left, sf.right, tracker.pointScores(0), tracker.pointScores(1), status.str());
      }
      // Keep the pair without copying it: ViSP's own swap() trades the pixel buffers (both images own
      // theirs). Not std::move: ViSP 3.5's vpImage loses ownership of its pixels when a moved-from
      // image is assigned again, and the source refills sf every frame.
      swap(lastL, sf.left);
      swap(lastR, sf.right);
      progress.step();
    }
    progress.finish();
    const pm::capture::SourceStats &st = input->stats();
    if (rec.empty())
      throw pm::core::Error("no frame of the sequence could be read (" + std::to_string(st.skipped) + " unreadable)");
    const pm::lab::TrackingReport report = pm::lab::reportTracking(rec, fps, pm::lab::table2Goals());

    if (truthCsv.is_open() && !truthCsv.flush())
      throw pm::core::Error("cannot write " + files.finalPath("truth.csv"));
    truthCsv.close();
    {
      std::ofstream csv(files.stage("frames.csv"));
      pm::lab::writeFramesCsv(csv, rec);
    }
    // Figures like the paper's 13 (estimate against truth) and 14 (errors after convergence).
    pm::io::writeImage(pm::lab::drawTrackingTrajectory(rec, report, source), files.stage("trajectory.png"));
    if (report.haveTruth)
      pm::io::writeImage(pm::lab::drawTrackingErrors(rec, report), files.stage("errors.png"));
    tracker.initFromPose(rec.back().result.hMo); // to draw the last estimate
    pm::io::writeImage(pm::report::sideBySide(pm::report::drawPointScores(lastL, tracker.fitness().pointScores(rec.back().result.phi, 0), "last frame, left"),
                                           pm::report::drawPointScores(lastR, tracker.fitness().pointScores(rec.back().result.phi, 1), "right")),
                       files.stage("last_frame.png"));
    if (view.isOpen())
      view.capture(files.stage("display.png"));
    pm::lab::TrackingRunInfo info;
    info.source = source;
    info.frames = rec.size();
    info.fps = fps;
    info.stats = st;
    info.live = live;
    info.trackerJson = pm::tracker::trackerConfigToJson(tp);
    info.budget = tp.budgetEvaluations > 0 ? std::to_string(tp.budgetEvaluations) + " evaluations" : std::to_string(tp.budgetMs) + " ms";
    pm::io::writeTextFile(files.stage("summary.json"), pm::lab::trackingSummaryJson(report, info));
    files.commit();
    if (!quiet)
      std::cout << pm::lab::trackingSummaryText(report, info) << "  written to " << files.dir() << "/" << std::endl;
    return 0;
  }, {{"--left-images", "--left", {}}, {"--right-images", "--right", {}}});
}
