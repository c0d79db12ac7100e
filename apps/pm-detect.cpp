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
#include "pm/app/RigImages.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/lab/StillPair.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/tracker/PhotoModelTracker.h"
#include "pm/tracker/StaticDetection.h"

namespace {

//! pm-detect's options (the tracker's are TrackerOptions').
struct Options
{
  std::string out, target = "C12", left, right, modelPath, pose = "0,0,500,0,0,0", truthText;
  std::vector<std::string> images; //!< any rig: one image per camera
  std::string rigPath = pm::app::dataPath("rig/pa10_stereo.json");
  bool quiet = false, allTargets = false;
  double maxTimeS = 10;
  pm::app::LabModelChoice lab;
  int patience = 20;
  pm::sim::SceneParams sp;
};

void addOptions(CLI::App &app, Options &o)
{
  app.add_option("--out", o.out, "output folder (created if missing)")->required();
  auto *optTarget = app.add_option("--target", o.target, "simulated target C01..C12 (the paper's sea creatures) or R1..R3 (relief: box, head, tower)");
  auto *optAll = app.add_flag("--all-targets", o.allTargets, "the 15 lab targets (C01..C12, R1..R3), each into DIR/<code>/, and table1.md / table1.csv");
  optAll->excludes(optTarget);
  auto *optL = app.add_option("--left", o.left, "left image of a user's stereo pair");
  auto *optR = app.add_option("--right", o.right, "right image of a user's stereo pair");
  auto *optI = app.add_option("--camera-images", o.images, "a user's still frame of any rig: one image per camera of --rig, in its order");
  auto *optM = app.add_option("--model", o.modelPath, "photo-model file (with --left/--right or --camera-images)");
  optL->needs(optR)->needs(optM)->excludes(optTarget)->excludes(optAll)->excludes(optI);
  optR->needs(optL);
  optI->needs(optM)->excludes(optTarget)->excludes(optAll);
  app.add_option("--pose", o.pose, "simulator: the target's pose x,y,z,eps1,eps2,eps3 in the hand frame");
  app.add_option("--truth", o.truthText, "user's images: the true pose, if known, for the errors");
  app.add_option("--rig", o.rigPath, "rig file: a stereo rig, or one to four cameras");
  app.add_option("--max-time-s", o.maxTimeS, "give up after this long")->check(CLI::Range(0.001, 3600.0));
  app.add_option("--patience", o.patience, "stop when the best has not improved for this many frames")->check(CLI::Range(1, 100000));
  pm::app::addLabModelOptions(app, o.lab);
  pm::app::addModelOptions(app, o.lab.photo);
  pm::app::addSceneOptions(app, o.sp);
}

//! The tracker's settings for a detection from scratch on one still pair.
pm::tracker::TrackerParams detectionDefaults()
{
  pm::tracker::TrackerParams defaults;
  defaults.search.ga.population = 100;       // detection from scratch: a larger population ...
  defaults.search.ga.restartGenerations = 30; // ... restarted when stagnant
  defaults.search.ga.predictMotion = false;  // one still pair: nothing moves, and no frame is a steady one
  defaults.search.budgetEvaluations = 0;     // the paper's wall-time budget (24 ms) unless --budget-evals
  defaults.steady.budgetFraction = 1.0;
  defaults.steady.hueMarginPx = 48;
  defaults.verifier.evaluations = 6000;
  return defaults;
}

//! A user's pair (\e code empty, its truth --truth if given) or the simulator's of lab target \e code at \e ref.
pm::lab::StillPair loadPair(const Options &o, const std::string &code, const pm::core::Phi &ref, const pm::core::CameraRig &rig)
{
  if (!code.empty())
    return pm::lab::renderStillPair(pm::sim::makeTarget(code), ref, rig, o.sp, o.lab);
  pm::lab::StillPair p = pm::lab::loadStillPair(pm::app::stillImagesFor(rig, o.images, o.left, o.right), o.modelPath);
  p.haveTruth = !o.truthText.empty();
  p.truth = ref;
  if (p.haveTruth) {
    const auto t = pm::app::parseNumbers(o.truthText, 6, "--truth");
    p.truth = {t[0], t[1], t[2], t[3], t[4], t[5]};
  }
  return p;
}

//! Detects the target in pair \e code (see loadPair) into \e dir; returns its summary.
nlohmann::json detectOne(const Options &o, const pm::tracker::TrackerParams &tp, const pm::core::CameraRig &rig,
                         const pm::core::Phi &ref, const std::string &code, const std::string &dir)
{
  const pm::lab::StillPair p = loadPair(o, code, ref, rig);
  pm::tracker::PhotoModelTracker tracker(rig, p.model, tp);
  tracker.initialize();
  pm::tracker::DetectionParams dp;
  dp.maxTimeS = o.maxTimeS;
  dp.patience = o.patience;
  const pm::tracker::Detection d = pm::tracker::detectStatic(tracker, p.view(), dp);
  pm::report::DetectionOutputs out;
  out.source = p.source;
  out.detection = d;
  out.budget = tp.search.budgetEvaluations > 0 ? std::to_string(tp.search.budgetEvaluations) + " evaluations per frame"
                                               : std::to_string(tp.search.budgetMs) + " ms per frame";
  out.haveTruth = p.haveTruth;
  if (p.haveTruth) {
    out.truth = p.truth;
    out.peak = pm::tracker::nearestFitnessPeak(tracker.fitness(), p.truth, tp.search.space);
    out.fitnessAtPeak = tracker.fitness().evaluate(out.peak);
  }
  const nlohmann::json s = nlohmann::json::parse(pm::report::writeDetection(dir, out, tracker.fitness(), p.view()));
  if (!o.allTargets && !o.quiet)
    std::cout << pm::report::describeDetection(out, dir) << std::flush;
  return s;
}

//! The table's rows of one target (Markdown and CSV) from its summary \e s.
void addRow(const std::string &code, const std::string &name, const nlohmann::json &s, std::ostringstream &md, std::ostringstream &csv)
{
  const auto &e = s["error_vector"];
  char row[512];
  std::snprintf(row, sizeof row, "| %s %s | %+.1f | %+.1f | %+.1f | %+.3f | %+.3f | %+.3f | %.1f | %.2f | %.1f | %.3f | %.2f | %ld |\n",
                code.c_str(), name.c_str(), e[0].get<double>(), e[1].get<double>(), e[2].get<double>(),
                e[3].get<double>(), e[4].get<double>(), e[5].get<double>(), s["position_error_mm"].get<double>(),
                s["rotation_error_deg"].get<double>(),
                s["position_error_to_peak_mm"].get<double>(), s["orientation_error_to_peak"].get<double>(),
                s["time_s"].get<double>(), s["evaluations"].get<long>());
  md << row;
  std::snprintf(row, sizeof row, "%s,%.3f,%.3f,%.3f,%.4f,%.4f,%.4f,%.3f,%.4f,%.3f,%.3f,%.4f,%.3f,%ld\n", code.c_str(),
                e[0].get<double>(), e[1].get<double>(), e[2].get<double>(), e[3].get<double>(), e[4].get<double>(),
                e[5].get<double>(), s["position_error_mm"].get<double>(), s["orientation_error"].get<double>(),
                s["rotation_error_deg"].get<double>(), s["position_error_to_peak_mm"].get<double>(),
                s["orientation_error_to_peak"].get<double>(), s["time_s"].get<double>(), s["evaluations"].get<long>());
  csv << row;
}

//! --all-targets: every lab target into OUT/<code>/, and Table 1 (table1.md, table1.csv, summary.json).
int detectAll(const Options &o, const pm::tracker::TrackerParams &tp, const pm::core::CameraRig &rig, const pm::core::Phi &ref)
{
  pm::io::StagedFiles files(o.out);
  std::ostringstream md, csv;
  md << "| target | dx | dy | dz | d eps1 | d eps2 | d eps3 | position error mm | rotation error deg | to peak mm | eps to peak | time s | evaluations |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  csv << "target,dx,dy,dz,de1,de2,de3,position_error_mm,orientation_error,rotation_error_deg,position_error_to_peak_mm,"
         "orientation_error_to_peak,time_s,evaluations\n";
  nlohmann::json all = nlohmann::json::array();
  pm::app::Progress progress("detecting", pm::sim::labTargetCatalog().size(), o.quiet);
  for (const auto &info : pm::sim::labTargetCatalog()) {
    nlohmann::json s;
    try {
      s = detectOne(o, tp, rig, ref, info.code, files.dir() + "/" + info.code);
    } catch (const pm::core::Error &err) {
      // A target whose model cannot be made (a stereo model refused for want of texture) is a
      // row of the table, not the end of the run.
      md << "| " << info.code << " " << info.name << " | model refused: " << err.what() << " ||||||||||||\n";
      csv << info.code << ",,,,,,,,,,,,,\n";
      all.push_back({{"target", info.code}, {"error", err.what()}});
      progress.step();
      continue;
    }
    addRow(info.code, info.name, s, md, csv);
    all.push_back({{"target", info.code}, {"summary", s}});
    progress.step();
  }
  progress.finish();
  pm::io::writeTextFile(files.stage("table1.md"), md.str());
  pm::io::writeTextFile(files.stage("table1.csv"), csv.str());
  pm::io::writeTextFile(files.stage("summary.json"), nlohmann::json{{"targets", all}}.dump(2) + "\n");
  files.commit();
  if (!o.quiet)
    std::cout << "static detection of the 15 lab targets (errors: found minus truth, mm and quaternion vector):\n"
              << md.str() << std::flush;
  return 0;
}

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"Static detection (the paper's Sec. 5, Table 1): RM-GA searches one still stereo pair from a random "
               "population, frame after frame on the same pair, until its best pose stops improving. On the simulator "
               "(--target, or --all-targets for the table) or on a user's pair (--left, --right, --rig, --model). "
               "Writes detection.png (the model at the found pose on both images) and summary.json.",
               "pm-detect"};
  app.option_defaults()->always_capture_default();
  Options o;
  addOptions(app, o);
  pm::app::TrackerOptions trackerOptions(app, detectionDefaults());
  app.add_flag("--quiet", o.quiet, "no progress, no summary on stdout");

  return pm::app::run(app, argc, argv, [&] {
    const pm::tracker::TrackerParams tp = trackerOptions.resolve();
    const auto v = pm::app::parseNumbers(o.pose, 6, "--pose");
    const pm::core::Phi ref{v[0], v[1], v[2], v[3], v[4], v[5]};
    if (!o.truthText.empty() && o.left.empty() && o.images.empty())
      throw CLI::ValidationError("--truth", "the truth of a user's images (--left/--right or --camera-images)");
    const pm::core::CameraRig rig = pm::io::loadCameraRig(o.rigPath);
    if (o.allTargets)
      return detectAll(o, tp, rig, ref);
    detectOne(o, tp, rig, ref, o.left.empty() && o.images.empty() ? o.target : std::string(), o.out);
    return 0;
  });
}
