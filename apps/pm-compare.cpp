//! pm-compare: our tracker side by side with ViSP's own trackers on the same rendered frames.
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/report/Overlay.h"
#include "pm/app/Progress.h"
#include "pm/report/TimePlot.h"
#include "pm/compare/Comparison.h"
#include "pm/compare/Metrics.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"

namespace {

using pm::compare::Summary;

nlohmann::json recoveryPerLoss(const Summary &s)
{
  nlohmann::json a = nlohmann::json::array();
  for (const auto &r : s.recovery)
    a.push_back(r ? nlohmann::json(*r) : nlohmann::json("never"));
  return a;
}

nlohmann::json recoveryJson(const Summary &s)
{
  if (s.recovery.empty())
    return nullptr;
  if (s.neverRecovered())
    return "never";
  return s.worstRecovery().value_or(0);
}

//! The scores of a summary, as summary.json gives them (per tracker, per scenario).
nlohmann::json scoresJson(const Summary &s)
{
  return {{"frames", s.frames},
          {"mean_frame_ms", s.meanMs},
          {"p99_frame_ms", s.p99Ms},
          {"mean_translation_error_mm", s.meanTranslationMm},
          {"max_translation_error_mm", s.maxTranslationMm},
          {"mean_rotation_error_deg", s.meanRotationDeg},
          {"max_rotation_error_deg", s.maxRotationDeg},
          {"success_5cm5deg", s.success5cm5deg},
          {"success_1cm2deg", s.success1cm2deg},
          {"recovery_frames", recoveryJson(s)},
          {"recovery_frames_per_loss", recoveryPerLoss(s)},
          {"claimed_pose_fraction", s.validFraction}};
}

//! pm-compare's options (the tracker's are TrackerOptions').
struct Options
{
  std::string out, rigPath = pm::app::dataPath("rig/pa10_stereo.json");
  pm::compare::ComparisonParams cp;
  bool quiet = false;
};

void addOptions(CLI::App &app, Options &o)
{
  pm::compare::ComparisonParams &cp = o.cp;
  cp.mbtXml = pm::app::dataPath("compare/mbt.xml");
  cp.trajectoryPath = pm::app::dataPath("trajectories/table2.csv");
  cp.scene.occluderSizeMm[0] = 40; // a wide strand: about a third of the crab in the occlusion scenario
  app.add_option("--out", o.out, "output folder (created if missing)")->required();
  app.add_option("--target", cp.target, "simulated target C01..C12 (the paper's sea creatures) or R1..R3 (relief: box, head, tower)");
  app.add_option("--scenarios", cp.scenarios, "which scenarios, in order")
      ->delimiter(',')
      ->check(CLI::IsMember(pm::compare::allScenarioNames()));
  app.add_option("--trackers", cp.trackers, "which trackers")->delimiter(',')->check(CLI::IsMember(pm::compare::comparedTrackerKeys()));
  app.add_option("--steps", cp.steps, "table2: only the first N steps (0: all 20)")->check(CLI::Range(0, 1000));
  app.add_option("--trajectory", cp.trajectoryPath, "table2: the waypoints (step,x,y,z,e1,e2,e3)");
  app.add_option("--rig", o.rigPath, "rig file: one camera or more (data/rig/pa10_mono.json: one; ViSP's MBT then runs in its monocular case)");
  app.add_option("--mbt-config", cp.mbtXml, "vpMbGenericTracker's XML settings (moving edges, KLT, visibility)");
  app.add_option("--mbt-mesh-cell-mm", cp.mbtMeshCellMm, "ViSP's MBT trackers' CAD model: the all-around model's surface "
                 "decimated to cells of this size (mm); 0: the flat model's outline, one face")
      ->check(CLI::Range(0.0, 100.0));
  app.add_flag("--no-trust-calibration", [&cp](std::int64_t) { cp.calibrateTrust = false; },
               "the all-around model's trust not calibrated from its pass (the shipped confidence and sigmas; faster)");
  app.add_flag("--refine-outlines", cp.refineOutlines, "the all-around model's outlines to a fraction of a pixel (sub-pixel "
               "silhouettes, the surface moved onto every view's outline; docs/model-outline.md)");
  app.add_option("--viewpoints", cp.viewpoints, "the all-around model's viewing directions (K)")->check(CLI::Range(1, 5000));
  app.add_option("--min-inside-px", cp.minInsidePx, "the all-around model's S_in points at least this far inside each viewpoint's outline through a sharp camera (px; raised by the blur the pass's photos show, docs/model-outline.md)")->check(CLI::Range(0.0, 50.0));
  app.add_option("--pass-views", cp.pass.views, "the all-around model's pass: hand poses, the rest view included")->check(CLI::Range(6, 200));
  app.add_option("--pass-rings-deg", cp.pass.ringsDeg, "the all-around model's pass: its rings' angles from the rest axis (deg; "
                 "views spread over them in proportion to the angle)")
      ->delimiter(',')
      ->check(CLI::Range(1.0, 80.0));
  app.add_flag("--mbt-true-cad", cp.mbtTrueCad, "ViSP's MBT trackers given the toy's true mesh (the lab knows it), decimated to "
               "--mbt-mesh-cell-mm, instead of the surface of our all-around photo-model: ours from photos against ViSP with the exact CAD");
  app.add_option("--outline-tolerance-px", cp.outlineTolPx, "simplification of the outline for ViSP's trackers (px of the photo)")
      ->check(CLI::Range(0.1, 50.0));
  app.add_option("--distance-mm", cp.distanceMm, "photo distance of the photo-model")->check(CLI::PositiveNumber);
  app.add_option("--view-turn-deg", cp.viewTurnDeg, "ours-3d: the stereo model's four further photo pairs, the hand "
                 "turned by this about its x and y axes around the toy (0: one pair)")
      ->check(CLI::Range(0.0, 45.0));
  app.add_option("--steady-variant", cp.steadyVariant, "ours-steady: ours with this fraction of the budget on steady frames "
                                                      "(see --steady-budget)")->check(CLI::Range(0.01, 1.0));
}

//! summary.json: every tracker's scores, overall and per scenario, with the run's settings.
nlohmann::json summaryJson(const pm::compare::ComparisonParams &cp, const pm::compare::ComparisonResult &r)
{
  const std::size_t nT = r.keys.size();
  nlohmann::json jt = nlohmann::json::array();
  for (std::size_t ti = 0; ti < nT; ++ti) {
    const Summary &s = r.overall[ti];
    nlohmann::json per = nlohmann::json::object();
    for (std::size_t si = 0; si < r.scenarios.size(); ++si)
      per[r.scenarios[si].name] = scoresJson(r.perScenario[si][ti]);
    nlohmann::json t = scoresJson(s);
    t["name"] = r.names[ti];
    t["key"] = r.keys[ti];
    t["time_ratio_to_ours"] = r.ours < nT ? nlohmann::json(s.meanMs / r.overall[r.ours].meanMs) : nlohmann::json();
    t["time_ratio_to_fastest_visp"] = r.fastest < nT ? nlohmann::json(s.meanMs / r.overall[r.fastest].meanMs) : nlohmann::json();
    t["needs_initial_pose"] = static_cast<bool>(r.needsPose[ti]);
    t["scenarios"] = per;
    jt.push_back(t);
  }
  nlohmann::json js = nlohmann::json::array();
  for (const auto &s : r.scenarios)
    js.push_back({{"name", s.name}, {"description", s.description}, {"frames", s.frames.size()}, {"loss_ends", s.lossEnds}});
  return nlohmann::json{{"target", cp.target},
                        {"scenarios", js},
                        {"trackers", jt},
                        {"success_thresholds", {{"rbot", "5 cm and 5 deg"}, {"strict", "1 cm and 2 deg"}}},
                        {"recovery", "frames from the end of a forced loss to the first of 5 frames in a row within 5 cm and 5 deg"},
                        {"our_tracker_budget_ms", cp.tracker.search.budget().milliseconds},
                        {"fastest_visp_tracker", r.fastest < nT ? nlohmann::json(r.names[r.fastest]) : nlohmann::json()},
                        {"mbt_config", cp.mbtXml}};
}

//! The figures: errors over time per scenario (clipped at 100 mm and 20 deg to stay readable), and the labelled snapshots.
void writeFigures(const pm::compare::ComparisonResult &r, pm::io::StagedFiles &files)
{
  const std::size_t nT = r.keys.size();
  for (std::size_t si = 0; si < r.scenarios.size(); ++si) {
    const pm::compare::Scenario &seq = r.scenarios[si];
    pm::report::Panel pt{"translation error (clipped at 100 mm)", "mm", {}, 0, {}}, pr{"rotation error (clipped at 20 deg)", "deg", {}, 0, {}};
    for (int e : seq.lossEnds) {
      pt.marks.push_back(e / seq.fps);
      pr.marks.push_back(e / seq.fps);
    }
    for (std::size_t ti = 0; ti < nT; ++ti) {
      pm::report::Series a{r.names[ti], pm::compare::trackerColor(ti), {}, {}, false}, b = a;
      for (std::size_t k = 0; k < r.scores[si][ti].size(); ++k) {
        a.t.push_back(static_cast<double>(k) / seq.fps);
        a.y.push_back(std::min(100.0, r.scores[si][ti][k].translationMm));
        b.t.push_back(static_cast<double>(k) / seq.fps);
        b.y.push_back(std::min(20.0, r.scores[si][ti][k].rotationDeg));
      }
      pt.series.push_back(a);
      pr.series.push_back(b);
    }
    pm::io::writeImage(pm::report::drawTimePlots({pt, pr}, 1, seq.name + ": " + seq.description, "time [s]", 1100),
                       files.stage("errors_" + seq.name + ".png"));
  }
  // Snapshots: the left image with every tracker's outline, two per scenario, labelled.
  std::vector<vpImage<vpRGBa>> shots = r.snapshots;
  for (std::size_t i = 0; i < shots.size(); ++i) {
    pm::report::drawLabel(shots[i], r.scenarios[i / 2].name + ", frame " + std::to_string(r.snapshotFrames[i]) + " (white: truth)", 8, 8,
                          vpRGBa(255, 255, 255));
    for (std::size_t ti = 0; ti < nT; ++ti)
      pm::report::drawLabel(shots[i], r.names[ti], 28 + 18 * static_cast<int>(ti), 8, pm::compare::trackerColor(ti));
  }
  for (std::size_t i = 0; i + 1 < shots.size(); i += 2)
    pm::io::writeImage(pm::report::sideBySide(shots[i], shots[i + 1]), files.stage("snapshots_" + r.scenarios[i / 2].name + ".png"));
}

//! The comparison run: every scenario through every tracker, model.cao and frames.csv as it goes.
pm::compare::ComparisonResult compareAll(const Options &o, pm::compare::Comparison &comparison, pm::io::StagedFiles &files)
{
  const std::string caoPath = files.stage("model.cao");
  pm::io::writeTextFile(caoPath, comparison.caoText());
  std::ofstream csv(files.stage("frames.csv"));
  pm::app::Progress progress("rendering and tracking", comparison.totalFrames(), o.quiet);
  pm::compare::ComparisonResult r = comparison.run(caoPath, csv, [&] { progress.step(); });
  progress.finish();
  csv.close();
  if (!csv)
    throw pm::core::Error("cannot write " + files.finalPath("frames.csv"));
  return r;
}

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"Runs our photo-model tracker and ViSP's own trackers on the same rendered stereo sequences, in the "
               "same process: ours started with no initial pose (flat, stereo and all-around models; ours-aa with the "
               "precise last stage, ours-aa-rmga without; ours-steady with a fraction of the budget on steady frames); "
               "vpMbGenericTracker (stereo, EDGE, KLT, EDGE|KLT) on the all-around model's surface decimated to a .cao "
               "mesh (--mbt-mesh-cell-mm; 0: a one-face outline), and vpTemplateTracker (SSD, ZNCC, homography) on the "
               "left image, both started from the true pose. Scenarios: table2, sinusoid, fast, occlusion, lighting, "
               "loss (random6dof on request). Writes summary.json (a 'trackers' list), table.md, frames.csv, model.cao "
               "and a PNG of the errors per scenario.",
               "pm-compare"};
  app.option_defaults()->always_capture_default();
  Options o;
  addOptions(app, o);
  pm::app::TrackerOptions trackerOptions(app, pm::tracker::TrackerParams());
  app.add_flag("--quiet", o.quiet, "no progress, no table on stdout");

  return pm::app::run(app, argc, argv, [&] {
    o.cp.tracker = trackerOptions.resolve();
    if (o.cp.trackers.empty())
      throw CLI::ValidationError("--trackers", "at least one tracker");
    const pm::core::CameraRig rig = pm::io::loadCameraRig(o.rigPath);
    pm::compare::Comparison comparison(rig, o.cp);
    pm::io::StagedFiles files(o.out);
    const pm::compare::ComparisonResult r = compareAll(o, comparison, files);
    pm::io::writeTextFile(files.stage("summary.json"), summaryJson(o.cp, r).dump(2) + "\n");
    const std::string table = pm::compare::comparisonTable(r);
    pm::io::writeTextFile(files.stage("table.md"), table);
    writeFigures(r, files);
    files.commit();
    if (!o.quiet)
      std::cout << "pm-compare, target " << o.cp.target << ", " << comparison.totalFrames() << " frames per tracker\n\n"
                << table << "\nwritten to " << files.dir() << "/" << std::endl;
    return 0;
  });
}
