//! pm-track: real-time pose tracking of a moving target (the paper's Sec. 6, Table 2, Figs. 12-14).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/app/Overlay.h"
#include "pm/app/LiveView.h"
#include "pm/app/Progress.h"
#include "pm/capture/ImageSequenceSource.h"
#include "pm/capture/VideoCaptureSource.h"
#include "pm/app/TimePlot.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/PoseTableFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/tracker/TrackerConfigFile.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/sim/Trajectory.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace {

const char *kNames[6] = {"x", "y", "z", "eps1", "eps2", "eps3"};

struct FrameRecord
{
  double t = 0;
  bool haveTruth = false, moving = false;
  pm::Phi truth, estimate;
  pm::TrackResult r;
};

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
  std::string out, target = "C12", trajectoryPath = pm::app::dataPath("trajectories/table2.csv");
  std::string rigPath = pm::app::dataPath("rig/pa10_stereo.json"), modelPath, truthPath;
  std::vector<std::string> leftImages, rightImages;
  double holdS = 1.5, moveS = 1.0, fps = 30, durationS = 0;
  int firstFrame = 0, steps = 0;
  bool quiet = false, display = false, savePairs = false;
  std::string leftSource, rightSource;
  pm::capture::VideoCaptureParams vcp;
  pm::app::LabModelChoice lab;
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
  pm::app::addLabModelOptions(app, lab);
  pm::app::addModelOptions(app, lab.photo);
  pm::app::addSceneOptions(app, sp);
  pm::app::TrackerOptions trackerOptions(app, pm::TrackerParams());
  app.add_flag("--save-pairs", savePairs, "also write every stereo pair tracked, left_%04d.png and right_%04d.png (and, "
                                          "on the simulator, its truth in truth.csv): a recording that --left, --right and "
                                          "--truth replay");
  app.add_flag("--quiet", quiet, "no progress, no summary on stdout");

  return pm::app::run(app, argc, argv, [&] {
    const pm::TrackerParams tp = trackerOptions.resolve();
    const pm::StereoRig rig = pm::io::loadRig(rigPath);
    const bool live = !leftSource.empty();
    const bool recorded = !leftImages.empty() || live;
    if (pm::app::isImagePattern(leftImages)) // check both patterns before anything else
      pm::app::frameFileName(leftImages.front(), 0);
    if (pm::app::isImagePattern(rightImages))
      pm::app::frameFileName(rightImages.front(), 0);

    pm::PhotoModel model;
    std::unique_ptr<pm::sim::Scene> scene;
    std::unique_ptr<pm::sim::Trajectory> trajectory;
    vpHomogeneousMatrix oMm;
    std::map<int, pm::Phi> truthByFrame;
    std::unique_ptr<pm::capture::StereoSource> input; // recorded or live pairs (the simulator renders its own)
    std::string source;
    int nFrames = 0;
    if (recorded) {
      model = pm::io::loadPhotoModel(modelPath);
      if (!truthPath.empty())
        for (const auto &[frame, pose] : pm::io::readPoseTable(truthPath, "frame"))
          truthByFrame[frame] = pose;
      if (live) {
        vcp.maxPairs = durationS > 0 ? static_cast<long>(std::floor(durationS * fps)) + 1 : 0;
        input = std::make_unique<pm::capture::VideoCaptureSource>(leftSource, rightSource, vcp);
        nFrames = static_cast<int>(vcp.maxPairs);
      } else {
        const long maxFrames = durationS > 0 ? static_cast<long>(std::floor(durationS * fps)) + 1 : 0;
        auto seq = pm::app::isImagePattern(leftImages) && pm::app::isImagePattern(rightImages)
                       ? std::make_unique<pm::capture::ImageSequenceSource>(leftImages.front(), rightImages.front(), firstFrame,
                                                                            fps, rig.left.width, rig.left.height, maxFrames)
                       : std::make_unique<pm::capture::ImageSequenceSource>(pm::app::imageFiles(leftImages, firstFrame),
                                                                            pm::app::imageFiles(rightImages, firstFrame), fps,
                                                                            rig.left.width, rig.left.height, maxFrames);
        nFrames = static_cast<int>(seq->length());
        input = std::move(seq);
      }
      source = input->describe();
    } else {
      std::vector<pm::Phi> w;
      for (const auto &row : pm::io::readPoseTable(trajectoryPath, "step"))
        w.push_back(row.second);
      if (steps > 0 && steps < static_cast<int>(w.size()))
        w.resize(static_cast<std::size_t>(steps));
      trajectory = std::make_unique<pm::sim::Trajectory>(w, holdS, moveS);
      scene = std::make_unique<pm::sim::Scene>(pm::sim::makeTarget(target), sp);
      const auto sm = pm::app::makeLabModel(*scene, rig, lab);
      model = sm.build.model;
      oMm = sm.oMm;
      const double d = durationS > 0 ? std::min(durationS, trajectory->duration()) : trajectory->duration();
      nFrames = static_cast<int>(std::floor(d * fps)) + 1;
      source = "simulator, target " + scene->target().info.code + " (" + scene->target().info.name + "), trajectory " +
               std::filesystem::path(trajectoryPath).filename().string();
    }

    pm::PhotoModelTracker tracker(rig, model, tp);
    tracker.initialize(); // no initial pose: a random population
    pm::io::StagedFiles files(out);
    std::ofstream truthCsv;
    if (savePairs && !recorded)
      truthCsv.open(files.stage("truth.csv"));
    truthCsv << "frame,x,y,z,e1,e2,e3\n" << std::setprecision(10);
    std::vector<FrameRecord> rec;
    rec.reserve(static_cast<std::size_t>(nFrames));
    vpImage<vpRGBa> firstL, firstR, lastL, lastR;
    pm::app::Progress progress("tracking", static_cast<std::size_t>(nFrames), quiet || nFrames <= 0);
    pm::app::LiveView view;
    if (display)
      view.open("pm-track: " + source);
    pm::capture::StereoFrame sf;
    for (int k = 0; input || k < nFrames; ++k) {
      FrameRecord f;
      f.t = k / fps;
      vpImage<vpRGBa> IL, IR;
      if (input) {
        const long skippedBefore = input->stats().skipped;
        if (!input->next(sf))
          break;
        for (long s2 = skippedBefore; s2 < input->stats().skipped; ++s2) {
          if (!quiet)
            std::cerr << "warning: " << input->stats().problems[static_cast<std::size_t>(s2)] << " (skipped)" << std::endl;
          progress.step();
        }
        if (sf.left.getWidth() != rig.left.width || sf.left.getHeight() != rig.left.height)
          throw pm::Error("the cameras deliver " + std::to_string(sf.left.getWidth()) + "x" + std::to_string(sf.left.getHeight()) +
                          " images but the rig's are " + std::to_string(rig.left.width) + "x" + std::to_string(rig.left.height));
        IL = std::move(sf.left);
        IR = std::move(sf.right);
        f.t = sf.timeS;
        const auto it = truthByFrame.find(static_cast<int>(sf.index));
        if (it != truthByFrame.end()) {
          f.haveTruth = true;
          f.truth = it->second;
        }
      } else {
        const pm::Phi p = trajectory->at(f.t);
        const vpHomogeneousMatrix hMo = pm::toHomogeneousMatrix(p);
        const pm::sim::StereoImages im = scene->renderStereo(rig, hMo, static_cast<std::uint64_t>(k));
        IL = im.left;
        IR = im.right;
        f.haveTruth = true;
        f.truth = pm::fromHomogeneousMatrix(hMo * oMm);
        f.moving = trajectory->moving(f.t);
      }
      if (savePairs) {
        char name[32];
        std::snprintf(name, sizeof name, "left_%04d.png", k);
        pm::io::writeImage(IL, files.stage(name));
        std::snprintf(name, sizeof name, "right_%04d.png", k);
        pm::io::writeImage(IR, files.stage(name));
        if (f.haveTruth && !recorded)
          truthCsv << k << "," << f.truth[0] << "," << f.truth[1] << "," << f.truth[2] << "," << f.truth[3] << ","
                   << f.truth[4] << "," << f.truth[5] << "\n";
      }
      f.r = tracker.track(IL, IR);
      f.estimate = f.r.phi;
      if (rec.empty()) {
        firstL = IL;
        firstR = IR;
      }
      lastL = IL;
      lastR = IR;
      rec.push_back(f);
      if (display) {
        std::ostringstream status;
        status << std::fixed << std::setprecision(2) << pm::toString(f.r.state) << ", q " << f.r.quality << ", "
               << std::setprecision(1) << f.r.computeMs << " ms, frame " << k;
        view.show(IL, IR, tracker.pointScores(0), tracker.pointScores(1), status.str());
      }
      progress.step();
    }
    progress.finish();
    const int unreadable = input ? static_cast<int>(input->stats().skipped) : 0;
    std::vector<std::string> unreadableList;
    if (input)
      for (long i = 0; i < unreadable; ++i)
        unreadableList.push_back(input->stats().problems[static_cast<std::size_t>(i)]);
    if (rec.empty())
      throw pm::Error("no frame of the sequence could be read (" + std::to_string(unreadable) + " unreadable)");

    // Convergence: the first frame from which, for 1 s, the tracker is tracking with errors under
    // 10 mm in x, y, z and 0.05 in eps.
    const std::size_t window = static_cast<std::size_t>(std::lround(fps));
    auto withinLoose = [&](const FrameRecord &f) {
      if (f.r.state != pm::TrackState::Tracking)
        return false;
      if (!f.haveTruth)
        return true;
      for (std::size_t i = 0; i < 6; ++i)
        if (std::fabs(f.estimate[i] - f.truth[i]) > (i < 3 ? 10.0 : 0.05))
          return false;
      return true;
    };
    long converged = -1;
    for (std::size_t k = 0; k < rec.size() && converged < 0; ++k) {
      bool ok = true;
      for (std::size_t j = k; j < std::min(rec.size(), k + window) && ok; ++j)
        ok = withinLoose(rec[j]);
      if (ok)
        converged = static_cast<long>(k);
    }
    // Errors after convergence.
    nlohmann::json errors;
    const double goal[6] = {5, 5, 8, 0.02, 0.02, 0.02};
    bool goalsMet = converged >= 0;
    for (std::size_t i = 0; i < 6; ++i) {
      double s2 = 0, mx = 0, mxMoving = 0, mxRest = 0;
      std::size_t n = 0;
      for (std::size_t k = converged < 0 ? 0 : static_cast<std::size_t>(converged); k < rec.size(); ++k)
        if (rec[k].haveTruth) {
          const double e = rec[k].estimate[i] - rec[k].truth[i];
          s2 += e * e;
          mx = std::max(mx, std::fabs(e));
          (rec[k].moving ? mxMoving : mxRest) = std::max(rec[k].moving ? mxMoving : mxRest, std::fabs(e));
          ++n;
        }
      if (n > 0) {
        errors[kNames[i]] = {{"rms_error", std::sqrt(s2 / static_cast<double>(n))},
                             {"max_abs_error", mx},
                             {"max_abs_error_moving", mxMoving},
                             {"max_abs_error_at_rest", mxRest},
                             {"goal", goal[i]}};
        goalsMet = goalsMet && mx <= goal[i];
      }
    }
    std::vector<double> ms;
    for (const auto &f : rec)
      ms.push_back(f.r.computeMs);
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    const double meanMs = std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(ms.size());
    const double p99Ms = sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(sorted.size()))) - 1)];
    long evals = 0;
    std::map<std::string, int> states;
    for (const auto &f : rec) {
      evals += f.r.evaluations;
      ++states[pm::toString(f.r.state)];
    }

    if (truthCsv.is_open() && !truthCsv.flush())
      throw pm::Error("cannot write " + files.finalPath("truth.csv"));
    truthCsv.close();
    {
      std::ofstream csv(files.stage("frames.csv"));
      csv << "t,true_x,true_y,true_z,true_e1,true_e2,true_e3,est_x,est_y,est_z,est_e1,est_e2,est_e3,err_x,err_y,err_z,"
             "err_e1,err_e2,err_e3,fitness,quality,state,evaluations,generations,compute_ms,moving\n";
      csv << std::setprecision(8);
      for (const auto &f : rec) {
        csv << f.t;
        for (std::size_t i = 0; i < 6; ++i)
          csv << "," << (f.haveTruth ? f.truth[i] : NAN);
        for (std::size_t i = 0; i < 6; ++i)
          csv << "," << f.estimate[i];
        for (std::size_t i = 0; i < 6; ++i)
          csv << "," << (f.haveTruth ? f.estimate[i] - f.truth[i] : NAN);
        csv << "," << f.r.fitness << "," << f.r.quality << "," << pm::toString(f.r.state) << "," << f.r.evaluations << ","
            << f.r.generations << "," << f.r.computeMs << "," << (f.moving ? 1 : 0) << "\n";
      }
      if (!csv)
        throw pm::Error("cannot write " + files.finalPath("frames.csv"));
    }
    // Figures like the paper's 13 (estimate against truth) and 14 (errors).
    std::vector<pm::app::Panel> traj, errs;
    const std::vector<double> marks = converged >= 0 ? std::vector<double>{rec[static_cast<std::size_t>(converged)].t}
                                                     : std::vector<double>{};
    for (std::size_t i = 0; i < 6; ++i) {
      pm::app::Series truthS{"truth", vpRGBa(40, 40, 40), {}, {}, true}, estS{"estimate", vpRGBa(220, 60, 40), {}, {}, false};
      pm::app::Series errS{"error", vpRGBa(40, 90, 200), {}, {}, false};
      for (const auto &f : rec) {
        estS.t.push_back(f.t);
        estS.y.push_back(f.estimate[i]);
        if (f.haveTruth) {
          truthS.t.push_back(f.t);
          truthS.y.push_back(f.truth[i]);
          errS.t.push_back(f.t);
          errS.y.push_back(f.estimate[i] - f.truth[i]);
        }
      }
      const std::string unit = i < 3 ? "mm" : "";
      pm::app::Panel a{std::string(kNames[i]), unit, {}, 0, marks};
      if (!truthS.t.empty())
        a.series.push_back(truthS);
      a.series.push_back(estS);
      traj.push_back(a);
      if (!errS.t.empty()) {
        // Errors after convergence, the goal as a band (before, the random start dwarfs the scale).
        pm::app::Series after{"error", errS.color, {}, {}, false};
        for (std::size_t k = 0; k < errS.t.size(); ++k)
          if (converged < 0 || errS.t[k] >= rec[static_cast<std::size_t>(converged)].t) {
            after.t.push_back(errS.t[k]);
            after.y.push_back(errS.y[k]);
          }
        errs.push_back({std::string("error of ") + kNames[i] + " after convergence", unit, {after}, goal[i], {}});
      }
    }
    pm::io::writeImage(pm::app::drawTimePlots(traj, 2, "estimate (red) against truth (dashed), " + source), files.stage("trajectory.png"));
    if (!errs.empty())
      pm::io::writeImage(pm::app::drawTimePlots(errs, 2, "errors after convergence; green band: the goal"), files.stage("errors.png"));
    tracker.initFromPose(rec.back().r.hMo); // to draw the last estimate
    pm::io::writeImage(pm::app::sideBySide(pm::app::drawPointScores(lastL, tracker.fitness().pointScores(rec.back().estimate, 0), "last frame, left"),
                                           pm::app::drawPointScores(lastR, tracker.fitness().pointScores(rec.back().estimate, 1), "right")),
                       files.stage("last_frame.png"));
    nlohmann::json summary{{"source", source},
                           {"frames", rec.size()},
                           {"unreadable_frames", unreadable},
                           {"unreadable", unreadableList},
                           {"fps", fps},
                           {"converged_after_s", converged >= 0 ? nlohmann::json(rec[static_cast<std::size_t>(converged)].t) : nlohmann::json()},
                           {"errors", errors},
                           {"errors_over", converged >= 0 ? "frames after convergence" : "all frames (never converged)"},
                           {"goals_met", goalsMet},
                           {"mean_frame_ms", meanMs},
                           {"p99_frame_ms", p99Ms},
                           {"mean_evaluations_per_frame", static_cast<double>(evals) / static_cast<double>(rec.size())},
                           {"states", states},
                           {"tracker", nlohmann::json::parse(pm::trackerConfigToJson(tp))}};
    if (view.isOpen())
      view.capture(files.stage("display.png"));
    if (live) {
      const pm::capture::SourceStats &st = input->stats();
      summary["capture"] = {{"pairs", st.pairs},
                            {"frames_read", {st.framesRead[0], st.framesRead[1]}},
                            {"unpaired", {st.unpaired[0], st.unpaired[1]}},
                            {"largest_skew_ms", st.maxSkewMs},
                            {"notes", st.problems}};
    }
    pm::io::writeTextFile(files.stage("summary.json"), summary.dump(2) + "\n");
    files.commit();
    if (!quiet) {
      std::cout << std::fixed << "tracked " << rec.size() << " frames of " << source << "\n";
      if (converged >= 0)
        std::cout << std::setprecision(2) << "  converged after " << rec[static_cast<std::size_t>(converged)].t << " s\n";
      else
        std::cout << "  never converged (errors under 10 mm / 0.05 for 1 s)\n";
      for (std::size_t i = 0; i < 6 && !errors.empty(); ++i)
        if (errors.contains(kNames[i]))
          std::cout << std::setprecision(i < 3 ? 2 : 4) << "  " << std::setw(4) << kNames[i] << ": rms "
                    << errors[kNames[i]]["rms_error"].get<double>() << ", max " << errors[kNames[i]]["max_abs_error"].get<double>()
                    << " (goal " << goal[i] << ")\n";
      std::cout << std::setprecision(2) << "  compute per frame: mean " << meanMs << " ms, p99 " << p99Ms << " ms ("
                << (tp.budgetEvaluations > 0 ? std::to_string(tp.budgetEvaluations) + " evaluations"
                                             : std::to_string(tp.budgetMs) + " ms")
                << " budget)\n"
                << "  written to " << files.dir() << "/" << std::endl;
    }
    return 0;
  }, {{"--left-images", "--left", {}}, {"--right-images", "--right", {}}});
}
