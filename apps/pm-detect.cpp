//! pm-detect: static detection on one still stereo pair (the paper's Sec. 5, Table 1).
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/report/DetectionOutputs.h"
#include "pm/app/Progress.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/tracker/PhotoModelTracker.h"
#include "pm/tracker/StaticDetection.h"

int main(int argc, char **argv)
{
  CLI::App app{"Static detection (the paper's Sec. 5, Table 1): RM-GA searches one still stereo pair from a random "
               "population, frame after frame on the same pair, until its best pose stops improving. On the simulator "
               "(--target, or --all-targets for the table) or on a user's pair (--left, --right, --rig, --model). "
               "Writes detection.png (the model at the found pose on both images) and summary.json.",
               "pm-detect"};
  app.option_defaults()->always_capture_default();
  std::string out, target = "C12", left, right, modelPath, pose = "0,0,500,0,0,0", truthText;
  std::string rigPath = pm::app::dataPath("rig/pa10_stereo.json");
  bool quiet = false, allTargets = false;
  double maxTimeS = 10;
  pm::app::LabModelChoice lab;
  int patience = 20;
  pm::sim::SceneParams sp;
  app.add_option("--out", out, "output folder (created if missing)")->required();
  auto *optTarget = app.add_option("--target", target, "simulated target C01..C12 (the paper's sea creatures) or R1..R3 (relief: box, head, tower)");
  auto *optAll = app.add_flag("--all-targets", allTargets, "the 15 lab targets (C01..C12, R1..R3), each into DIR/<code>/, and table1.md / table1.csv");
  optAll->excludes(optTarget);
  auto *optL = app.add_option("--left", left, "left image of a user's stereo pair");
  auto *optR = app.add_option("--right", right, "right image of a user's stereo pair");
  auto *optM = app.add_option("--model", modelPath, "photo-model file (with --left/--right)");
  optL->needs(optR)->needs(optM)->excludes(optTarget)->excludes(optAll);
  optR->needs(optL);
  optM->needs(optL);
  app.add_option("--pose", pose, "simulator: the target's pose x,y,z,eps1,eps2,eps3 in the hand frame");
  app.add_option("--truth", truthText, "user's pair: the true pose, if known, for the errors")->needs(optL);
  app.add_option("--rig", rigPath, "stereo rig file");
  app.add_option("--max-time-s", maxTimeS, "give up after this long")->check(CLI::Range(0.001, 3600.0));
  app.add_option("--patience", patience, "stop when the best has not improved for this many frames")->check(CLI::Range(1, 100000));
  pm::app::addLabModelOptions(app, lab);
  pm::app::addModelOptions(app, lab.photo);
  pm::app::addSceneOptions(app, sp);
  pm::tracker::TrackerParams defaults;
  defaults.ga.population = 100;       // detection from scratch: a larger population ...
  defaults.ga.restartGenerations = 30; // ... restarted when stagnant ...
  defaults.ga.refineEvaluations = 200; // ... and the best refined (measured: README)
  defaults.ga.predictMotion = false;  // one still pair: nothing moves, and no frame is a steady one
  defaults.budgetEvaluations = 0;     // the paper's wall-time budget (24 ms) unless --budget-evals
  defaults.steadyBudgetFraction = 1.0;
  defaults.steadyHueMarginPx = 48;
  defaults.verifyEvaluations = 6000;
  pm::app::TrackerOptions trackerOptions(app, defaults);
  app.add_flag("--quiet", quiet, "no progress, no summary on stdout");

  return pm::app::run(app, argc, argv, [&] {
    const pm::tracker::TrackerParams tp = trackerOptions.resolve();
    const auto v = pm::app::parseNumbers(pose, 6, "--pose");
    const pm::core::Phi ref{v[0], v[1], v[2], v[3], v[4], v[5]};
    const pm::core::StereoRig rig = pm::io::loadRig(rigPath);

    auto runOne = [&](const std::string &code, const std::string &dir) {
      pm::core::PhotoModel model;
      vpImage<vpRGBa> IL, IR;
      bool haveTruth = true;
      pm::core::Phi truth = ref;
      std::string source;
      if (code.empty()) {
        IL = pm::io::readColorImage(left);
        IR = pm::io::readColorImage(right);
        model = pm::io::loadPhotoModel(modelPath);
        haveTruth = !truthText.empty();
        if (haveTruth) {
          const auto t = pm::app::parseNumbers(truthText, 6, "--truth");
          truth = {t[0], t[1], t[2], t[3], t[4], t[5]};
        }
        source = "stereo pair " + left + " + " + right + ", model " + modelPath;
      } else {
        const pm::sim::Scene scene(pm::sim::makeTarget(code), sp);
        const auto sm = pm::app::makeLabModel(scene, rig, lab);
        model = sm.build.model;
        const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix(ref);
        truth = sm.truth(hMo);
        const auto im = scene.renderStereo(rig, hMo, 0);
        IL = im.left;
        IR = im.right;
        source = "simulator, target " + scene.target().info.code + " (" + scene.target().info.name + ")";
      }
      pm::tracker::PhotoModelTracker tracker(rig, model, tp);
      tracker.initialize();
      pm::tracker::DetectionParams dp;
      dp.maxTimeS = maxTimeS;
      dp.patience = patience;
      const pm::tracker::Detection d = pm::tracker::detectStatic(tracker, IL, IR, dp);
      pm::report::DetectionOutputs o;
      o.source = source;
      o.detection = d;
      o.budget = tp.budgetEvaluations > 0 ? std::to_string(tp.budgetEvaluations) + " evaluations per frame"
                                          : std::to_string(tp.budgetMs) + " ms per frame";
      o.haveTruth = haveTruth;
      if (haveTruth) {
        o.truth = truth;
        o.peak = pm::tracker::nearestFitnessPeak(tracker.fitness(), truth, tp.space);
        o.fitnessAtPeak = tracker.fitness().evaluate(o.peak);
      }
      const nlohmann::json s = nlohmann::json::parse(pm::report::writeDetection(dir, o, tracker.fitness(), IL, IR));
      if (!allTargets && !quiet)
        std::cout << pm::report::describeDetection(o, dir) << std::flush;
      return s;
    };

    if (!allTargets) {
      runOne(left.empty() ? target : std::string(), out);
      return 0;
    }
    pm::io::StagedFiles files(out);
    std::ostringstream md, csv;
    md << "| target | dx | dy | dz | d eps1 | d eps2 | d eps3 | position error mm | rotation error deg | to peak mm | eps to peak | time s | evaluations |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    csv << "target,dx,dy,dz,de1,de2,de3,position_error_mm,orientation_error,rotation_error_deg,position_error_to_peak_mm,"
           "orientation_error_to_peak,time_s,evaluations\n";
    nlohmann::json all = nlohmann::json::array();
    pm::app::Progress progress("detecting", pm::sim::labTargetCatalog().size(), quiet);
    for (const auto &info : pm::sim::labTargetCatalog()) {
      nlohmann::json s;
      try {
        s = runOne(info.code, files.dir() + "/" + info.code);
      } catch (const pm::core::Error &err) {
        // A target whose model cannot be made (a stereo model refused for want of texture) is a
        // row of the table, not the end of the run.
        md << "| " << info.code << " " << info.name << " | model refused: " << err.what() << " ||||||||||||\n";
        csv << info.code << ",,,,,,,,,,,,,\n";
        all.push_back({{"target", info.code}, {"error", err.what()}});
        progress.step();
        continue;
      }
      const auto &e = s["error_vector"];
      char row[512];
      std::snprintf(row, sizeof row, "| %s %s | %+.1f | %+.1f | %+.1f | %+.3f | %+.3f | %+.3f | %.1f | %.2f | %.1f | %.3f | %.2f | %ld |\n",
                    info.code.c_str(), info.name.c_str(), e[0].get<double>(), e[1].get<double>(), e[2].get<double>(),
                    e[3].get<double>(), e[4].get<double>(), e[5].get<double>(), s["position_error_mm"].get<double>(),
                    s["rotation_error_deg"].get<double>(),
                    s["position_error_to_peak_mm"].get<double>(), s["orientation_error_to_peak"].get<double>(),
                    s["time_s"].get<double>(), s["evaluations"].get<long>());
      md << row;
      std::snprintf(row, sizeof row, "%s,%.3f,%.3f,%.3f,%.4f,%.4f,%.4f,%.3f,%.4f,%.3f,%.3f,%.4f,%.3f,%ld\n", info.code.c_str(),
                    e[0].get<double>(), e[1].get<double>(), e[2].get<double>(), e[3].get<double>(), e[4].get<double>(),
                    e[5].get<double>(), s["position_error_mm"].get<double>(), s["orientation_error"].get<double>(),
                    s["rotation_error_deg"].get<double>(), s["position_error_to_peak_mm"].get<double>(),
                    s["orientation_error_to_peak"].get<double>(), s["time_s"].get<double>(), s["evaluations"].get<long>());
      csv << row;
      all.push_back({{"target", info.code}, {"summary", s}});
      progress.step();
    }
    progress.finish();
    pm::io::writeTextFile(files.stage("table1.md"), md.str());
    pm::io::writeTextFile(files.stage("table1.csv"), csv.str());
    pm::io::writeTextFile(files.stage("summary.json"), nlohmann::json{{"targets", all}}.dump(2) + "\n");
    files.commit();
    if (!quiet)
      std::cout << "static detection of the 15 lab targets (errors: found minus truth, mm and quaternion vector):\n"
                << md.str() << std::flush;
    return 0;
  });
}
