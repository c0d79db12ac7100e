//! pm-compare: our tracker side by side with ViSP's own trackers on the same rendered frames.
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <sstream>

#include <nlohmann/json.hpp>

#include <visp3/core/vpImageDraw.h>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/app/Overlay.h"
#include "pm/app/Progress.h"
#include "pm/app/TimePlot.h"
#include "pm/compare/Metrics.h"
#include "pm/compare/OutlineModel.h"
#include "pm/compare/Scenario.h"
#include "pm/compare/Trackers.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/lab/ClosedLoop.h"
#include "pm/lab/LabPass.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"

namespace {

using pm::compare::FrameScore;
using pm::compare::Summary;

const char *kTrackerKeys[] = {"ours", "ours-3d", "ours-aa", "ours-steady", "mbt-edge", "mbt-klt", "mbt-edge-klt", "template-ssd", "template-zncc"};

const vpRGBa kColors[] = {vpRGBa(220, 50, 40), vpRGBa(240, 120, 150), vpRGBa(40, 90, 200), vpRGBa(40, 160, 80), vpRGBa(140, 60, 170),
                          vpRGBa(230, 150, 20), vpRGBa(90, 90, 90)};

std::string fmt(double v, int precision)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(precision) << v;
  return s.str();
}

std::string recoveryText(const Summary &s, bool hadLoss)
{
  if (!hadLoss)
    return "-";
  if (s.neverRecovered())
    return "never";
  return std::to_string(s.worstRecovery().value_or(0));
}

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

//! The outline at \e hMm drawn on the left image.
void drawOutline(vpImage<vpRGBa> &I, const std::vector<vpPoint> &outline, const vpHomogeneousMatrix &hMm, const pm::RigCamera &cam,
                 const vpRGBa &color)
{
  const auto px = pm::compare::projectPolygon(outline, cam.cMh() * hMm, cam.cam);
  for (std::size_t i = 0; i < px.size(); ++i) {
    const auto &a = px[i], &b = px[(i + 1) % px.size()];
    vpImageDraw::drawLine(I, vpImagePoint(a.first, a.second), vpImagePoint(b.first, b.second), vpColor(color.R, color.G, color.B), 2);
  }
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

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"Runs our photo-model tracker and ViSP's own trackers on the same rendered stereo sequences, in the "
               "same process: ours started with no initial pose (twice: with the whole budget on every frame, and with a "
               "fraction of it on steady frames, --steady-variant); vpMbGenericTracker (stereo, EDGE, KLT, EDGE|KLT) on a "
               "one-face .cao model of the target's outline from the photo-model, and vpTemplateTracker (SSD, ZNCC, "
               "homography) on the left image, both started from the true pose. Scenarios: table2, sinusoid, fast, "
               "occlusion, lighting, loss. Writes summary.json (a 'trackers' list), table.md, frames.csv, model.cao "
               "and a PNG of the errors per scenario.",
               "pm-compare"};
  app.option_defaults()->always_capture_default();
  std::string out, target = "C12", rigPath = pm::app::dataPath("rig/pa10_stereo.json");
  std::string mbtXml = pm::app::dataPath("compare/mbt.xml"), trajectoryPath = pm::app::dataPath("trajectories/table2.csv");
  std::vector<std::string> scenarios = pm::compare::scenarioNames();
  std::vector<std::string> trackers(std::begin(kTrackerKeys), std::end(kTrackerKeys));
  int steps = 0;
  double distanceMm = 500, outlineTolPx = 1.5, steadyVariant = 0.25;
  bool quiet = false;
  pm::sim::SceneParams sp;
  sp.occluderSizeMm[0] = 40; // a wide strand: about a third of the crab in the occlusion scenario
  app.add_option("--out", out, "output folder (created if missing)")->required();
  app.add_option("--target", target, "simulated target C01..C12 (the paper's sea creatures) or R1..R3 (relief: box, head, tower)");
  app.add_option("--scenarios", scenarios, "which scenarios, in order")
      ->delimiter(',')
      ->check(CLI::IsMember(pm::compare::allScenarioNames()));
  app.add_option("--trackers", trackers, "which trackers")
      ->delimiter(',')
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(kTrackerKeys), std::end(kTrackerKeys))));
  app.add_option("--steps", steps, "table2: only the first N steps (0: all 20)")->check(CLI::Range(0, 1000));
  app.add_option("--trajectory", trajectoryPath, "table2: the waypoints (step,x,y,z,e1,e2,e3)");
  app.add_option("--rig", rigPath, "stereo rig file");
  app.add_option("--mbt-config", mbtXml, "vpMbGenericTracker's XML settings (moving edges, KLT, visibility)");
  app.add_option("--outline-tolerance-px", outlineTolPx, "simplification of the outline for ViSP's trackers (px of the photo)")
      ->check(CLI::Range(0.1, 50.0));
  app.add_option("--distance-mm", distanceMm, "photo distance of the photo-model")->check(CLI::PositiveNumber);
  double viewTurnDeg = 0;
  app.add_option("--view-turn-deg", viewTurnDeg, "ours-3d: the stereo model's four further photo pairs, the hand "
                 "turned by this about its x and y axes around the toy (0: one pair)")
      ->check(CLI::Range(0.0, 45.0));
  app.add_option("--steady-variant", steadyVariant, "ours-steady: ours with this fraction of the budget on steady frames "
                                                   "(see --steady-budget)")->check(CLI::Range(0.01, 1.0));
  pm::app::TrackerOptions trackerOptions(app, pm::TrackerParams());
  app.add_flag("--quiet", quiet, "no progress, no table on stdout");

  return pm::app::run(app, argc, argv, [&] {
    const pm::TrackerParams tp = trackerOptions.resolve();
    const pm::StereoRig rig = pm::io::loadRig(rigPath);
    if (!std::ifstream(mbtXml))
      throw pm::Error("cannot read the MBT settings " + mbtXml);
    const std::vector<pm::compare::Scenario> seqs = pm::compare::makeScenarios(scenarios, trajectoryPath, steps);
    if (trackers.empty())
      throw CLI::ValidationError("--trackers", "at least one tracker");

    pm::sim::Scene scene(pm::sim::makeTarget(target), sp);
    const auto sm = pm::sim::makeSimulatedPhotoModel(scene, rig.left.cam, rig.left.width, rig.left.height, distanceMm);
    const std::vector<vpPoint> outline = pm::compare::outlinePolygon(sm.build.region, sm.build.model, outlineTolPx);
    // ours-3d: the stereo photo-model (with depth), made by the rig's two cameras at the same
    // distance; its model frame (the 3-D centroid of S_in) is not the flat model's, so each
    // tracker is scored against the truth of its own model frame.
    const bool want3d = std::find(trackers.begin(), trackers.end(), "ours-3d") != trackers.end();
    const pm::sim::SimulatedPhotoModel sm3d = want3d ? pm::sim::makeSimulatedStereoPhotoModel(scene, rig, distanceMm, pm::StereoModelParams(), viewTurnDeg)
                                                     : pm::sim::SimulatedPhotoModel();
    // ours-aa: the all-around model from the PA-10's pass around the toy (its own model frame too).
    const bool wantAA = std::find(trackers.begin(), trackers.end(), "ours-aa") != trackers.end();
    const pm::sim::SimulatedPhotoModel smAA =
        wantAA ? pm::lab::makeSimulatedAllAroundModel(scene, rig, pm::PassPlan(), pm::lab::LoopParams::startJoints(), distanceMm)
               : pm::sim::SimulatedPhotoModel();
    // The truth of a tracker's own model frame, and its model frame in the flat model's (for drawing).
    auto ownFrame = [&](const std::string &key) -> const vpHomogeneousMatrix & {
      return key == "ours-3d" ? sm3d.oMm : key == "ours-aa" ? smAA.oMm : sm.oMm;
    };

    pm::io::StagedFiles files(out);
    const std::string caoPath = files.stage("model.cao");
    pm::io::writeTextFile(caoPath, pm::compare::caoText(outline, "outline of " + target + " from its photo-model, " +
                                                                      std::to_string(outline.size()) + " vertices, metres, model frame"));
    auto makeTracker = [&](const std::string &key) -> std::unique_ptr<pm::compare::ComparedTracker> {
      if (key == "ours")
        return pm::compare::makeOurTracker(rig, sm.build.model, tp);
      if (key == "ours-3d")
        return pm::compare::makeOurTracker(rig, sm3d.build.model, tp, "photo-model with depth (ours, stereo model)");
      if (key == "ours-aa")
        return pm::compare::makeOurTracker(rig, smAA.build.model, tp, "all-around photo-model (ours, PA-10 pass)");
      if (key == "ours-steady") {
        pm::TrackerParams fast = tp;
        fast.steadyBudgetFraction = steadyVariant;
        return pm::compare::makeOurTracker(rig, sm.build.model, fast, "photo-model (ours, steady frames " +
                                                                         std::to_string(std::lround(100 * steadyVariant)) + " %)");
      }
      if (key == "mbt-edge")
        return pm::compare::makeMbtTracker(rig, pm::compare::MbtFeatures::Edge, caoPath, mbtXml);
      if (key == "mbt-klt")
        return pm::compare::makeMbtTracker(rig, pm::compare::MbtFeatures::Klt, caoPath, mbtXml);
      if (key == "mbt-edge-klt")
        return pm::compare::makeMbtTracker(rig, pm::compare::MbtFeatures::EdgeKlt, caoPath, mbtXml);
      if (key == "template-ssd")
        return pm::compare::makeTemplateTracker(rig, pm::compare::TemplateCost::Ssd, outline);
      return pm::compare::makeTemplateTracker(rig, pm::compare::TemplateCost::Zncc, outline);
    };

    std::size_t totalFrames = 0;
    for (const auto &s : seqs)
      totalFrames += s.frames.size();
    const std::size_t nT = trackers.size();
    std::vector<std::string> names(nT);
    std::vector<bool> needsPose(nT);
    // scores[scenario][tracker][frame]
    std::vector<std::vector<std::vector<FrameScore>>> scores(seqs.size(), std::vector<std::vector<FrameScore>>(nT));
    std::vector<std::vector<Summary>> perScenario(seqs.size(), std::vector<Summary>(nT));
    std::ofstream csv(files.stage("frames.csv"));
    csv << "scenario,frame,t,tracker,translation_error_mm,rotation_error_deg,frame_ms,valid\n" << std::setprecision(6);
    pm::app::Progress progress("rendering and tracking", totalFrames, quiet);
    // Snapshots: the left image with every tracker's outline, at a few frames of each scenario.
    std::vector<vpImage<vpRGBa>> snapshots;
    for (std::size_t si = 0; si < seqs.size(); ++si) {
      const pm::compare::Scenario &seq = seqs[si];
      std::vector<std::unique_ptr<pm::compare::ComparedTracker>> ts;
      for (std::size_t ti = 0; ti < nT; ++ti) {
        ts.push_back(makeTracker(trackers[ti]));
        names[ti] = ts.back()->name();
        needsPose[ti] = ts.back()->needsInitialPose();
      }
      for (std::size_t k = 0; k < seq.frames.size(); ++k) {
        const pm::compare::ScenarioFrame &f = seq.frames[k];
        const pm::sim::StereoImages im = pm::compare::renderScenarioFrame(scene, rig, seq, k);
        const vpHomogeneousMatrix hMm = f.hMo * sm.oMm;
        const bool snap = k + 1 == seq.frames.size() / 2 || k + 1 == seq.frames.size();
        vpImage<vpRGBa> shot;
        if (snap) {
          shot = im.left;
          drawOutline(shot, outline, hMm, rig.left, vpRGBa(255, 255, 255));
        }
        for (std::size_t ti = 0; ti < nT; ++ti) {
          const vpHomogeneousMatrix truth = f.hMo * ownFrame(trackers[ti]); // each tracker in its own model frame
          if (k == 0)
            ts[ti]->start(im.left, im.right, truth);
          const auto t0 = std::chrono::steady_clock::now();
          const pm::compare::Estimate e = ts[ti]->track(im.left, im.right);
          const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
          FrameScore sc = pm::compare::scoreFrame(e.hMm, truth);
          sc.ms = ms;
          sc.valid = e.valid;
          scores[si][ti].push_back(sc);
          if (snap)
            // The outline is in the flat model's frame: an estimate of the 3-D model's frame is moved to it.
            drawOutline(shot, outline, e.hMm * ownFrame(trackers[ti]).inverse() * sm.oMm, rig.left,
                        kColors[ti % std::size(kColors)]);
          csv << seq.name << "," << k << "," << static_cast<double>(k) / seq.fps << "," << trackers[ti] << "," << sc.translationMm << ","
              << sc.rotationDeg << "," << sc.ms << "," << (sc.valid ? 1 : 0) << "\n";
        }
        if (snap) {
          pm::app::drawLabel(shot, seq.name + ", frame " + std::to_string(k) + " (white: truth)", 8, 8, vpRGBa(255, 255, 255));
          for (std::size_t ti = 0; ti < nT; ++ti)
            pm::app::drawLabel(shot, names[ti], 28 + 18 * static_cast<int>(ti), 8, kColors[ti % std::size(kColors)]);
          snapshots.push_back(shot);
        }
        progress.step();
      }
      for (std::size_t ti = 0; ti < nT; ++ti)
        perScenario[si][ti] = pm::compare::summarize(scores[si][ti], seq.lossEnds);
    }
    progress.finish();
    if (!csv)
      throw pm::Error("cannot write " + files.finalPath("frames.csv"));
    csv.close();

    // Overall, per tracker.
    std::vector<Summary> overall(nT);
    for (std::size_t ti = 0; ti < nT; ++ti) {
      std::vector<Summary> parts;
      std::vector<std::vector<FrameScore>> frames;
      for (std::size_t si = 0; si < seqs.size(); ++si) {
        parts.push_back(perScenario[si][ti]);
        frames.push_back(scores[si][ti]);
      }
      overall[ti] = pm::compare::pool(parts, frames);
    }
    const std::size_t ours = static_cast<std::size_t>(std::find(trackers.begin(), trackers.end(), "ours") - trackers.begin());
    const bool haveOurs = ours < nT;
    bool hadLoss = false;
    for (const auto &s : seqs)
      hadLoss = hadLoss || !s.lossEnds.empty();

    // ViSP's fastest tracker in this run: what our time per frame is held against.
    std::size_t fastest = nT;
    for (std::size_t ti = 0; ti < nT; ++ti)
      if (needsPose[ti] && (fastest == nT || overall[ti].meanMs < overall[fastest].meanMs))
        fastest = ti;
    nlohmann::json jt = nlohmann::json::array();
    for (std::size_t ti = 0; ti < nT; ++ti) {
      const Summary &s = overall[ti];
      nlohmann::json per = nlohmann::json::object();
      for (std::size_t si = 0; si < seqs.size(); ++si)
        per[seqs[si].name] = scoresJson(perScenario[si][ti]);
      nlohmann::json t = scoresJson(s);
      t["name"] = names[ti];
      t["key"] = trackers[ti];
      t["time_ratio_to_ours"] = haveOurs ? nlohmann::json(s.meanMs / overall[ours].meanMs) : nlohmann::json();
      t["time_ratio_to_fastest_visp"] = fastest < nT ? nlohmann::json(s.meanMs / overall[fastest].meanMs) : nlohmann::json();
      t["needs_initial_pose"] = static_cast<bool>(needsPose[ti]);
      t["scenarios"] = per;
      jt.push_back(t);
    }
    nlohmann::json js = nlohmann::json::array();
    for (const auto &s : seqs)
      js.push_back({{"name", s.name}, {"description", s.description}, {"frames", s.frames.size()}, {"loss_ends", s.lossEnds}});
    const nlohmann::json summary{{"target", target},
                                 {"scenarios", js},
                                 {"trackers", jt},
                                 {"success_thresholds", {{"rbot", "5 cm and 5 deg"}, {"strict", "1 cm and 2 deg"}}},
                                 {"recovery", "frames from the end of a forced loss to the first of 5 frames in a row within 5 cm and 5 deg"},
                                 {"our_tracker_budget_ms", tp.budget().milliseconds},
                                 {"fastest_visp_tracker", fastest < nT ? nlohmann::json(names[fastest]) : nlohmann::json()},
                                 {"mbt_config", mbtXml}};
    pm::io::writeTextFile(files.stage("summary.json"), summary.dump(2) + "\n");

    // The table.
    std::ostringstream md;
    md << "| tracker | initial pose | ms/frame mean (p99) | time / ours | translation error mean (max) mm | rotation error mean (max) deg "
          "| success 5 cm 5 deg | success 1 cm 2 deg | recovery frames |\n|---|---|---|---|---|---|---|---|---|\n";
    for (std::size_t ti = 0; ti < nT; ++ti) {
      const Summary &s = overall[ti];
      md << "| " << names[ti] << " | " << (needsPose[ti] ? "needed" : "not needed") << " | " << fmt(s.meanMs, 2) << " ("
         << fmt(s.p99Ms, 2) << ") | " << (haveOurs ? fmt(s.meanMs / overall[ours].meanMs, 2) : "-") << " | "
         << fmt(s.meanTranslationMm, 1) << " (" << fmt(s.maxTranslationMm, 1) << ") | " << fmt(s.meanRotationDeg, 2) << " ("
         << fmt(s.maxRotationDeg, 1) << ") | " << fmt(100 * s.success5cm5deg, 1) << " % | " << fmt(100 * s.success1cm2deg, 1)
         << " % | " << recoveryText(s, hadLoss) << " |\n";
    }
    if (fastest < nT)
      for (std::size_t ti = 0; ti < nT; ++ti)
        if (!needsPose[ti])
          md << (ti == 0 ? "\n" : "") << "- " << names[ti] << ": " << fmt(overall[ti].meanMs, 2) << " ms per frame, "
             << fmt(overall[ti].meanMs / overall[fastest].meanMs, 2) << " times ViSP's fastest here (" << names[fastest] << ", "
             << fmt(overall[fastest].meanMs, 2) << " ms)\n";
    md << "\nPer scenario, success 5 cm 5 deg / 1 cm 2 deg (mean translation error):\n\n| tracker |";
    for (const auto &s : seqs)
      md << " " << s.name << " |";
    md << "\n|---|";
    for (std::size_t si = 0; si < seqs.size(); ++si)
      md << "---|";
    md << "\n";
    for (std::size_t ti = 0; ti < nT; ++ti) {
      md << "| " << names[ti] << " |";
      for (std::size_t si = 0; si < seqs.size(); ++si) {
        const Summary &p = perScenario[si][ti];
        md << " " << fmt(100 * p.success5cm5deg, 0) << " / " << fmt(100 * p.success1cm2deg, 0) << " % ("
           << fmt(p.meanTranslationMm, 1) << " mm) |";
      }
      md << "\n";
    }
    pm::io::writeTextFile(files.stage("table.md"), md.str());

    // Errors over time, one figure per scenario (clipped at 100 mm and 20 deg to stay readable).
    for (std::size_t si = 0; si < seqs.size(); ++si) {
      pm::app::Panel pt{"translation error (clipped at 100 mm)", "mm", {}, 0, {}}, pr{"rotation error (clipped at 20 deg)", "deg", {}, 0, {}};
      for (int e : seqs[si].lossEnds) {
        pt.marks.push_back(e / seqs[si].fps);
        pr.marks.push_back(e / seqs[si].fps);
      }
      for (std::size_t ti = 0; ti < nT; ++ti) {
        pm::app::Series a{names[ti], kColors[ti % std::size(kColors)], {}, {}, false}, b = a;
        for (std::size_t k = 0; k < scores[si][ti].size(); ++k) {
          a.t.push_back(static_cast<double>(k) / seqs[si].fps);
          a.y.push_back(std::min(100.0, scores[si][ti][k].translationMm));
          b.t.push_back(static_cast<double>(k) / seqs[si].fps);
          b.y.push_back(std::min(20.0, scores[si][ti][k].rotationDeg));
        }
        pt.series.push_back(a);
        pr.series.push_back(b);
      }
      pm::io::writeImage(pm::app::drawTimePlots({pt, pr}, 1, seqs[si].name + ": " + seqs[si].description, "time [s]", 1100),
                         files.stage("errors_" + seqs[si].name + ".png"));
    }
    for (std::size_t i = 0; i + 1 < snapshots.size(); i += 2)
      pm::io::writeImage(pm::app::sideBySide(snapshots[i], snapshots[i + 1]), files.stage("snapshots_" + seqs[i / 2].name + ".png"));
    files.commit();
    if (!quiet)
      std::cout << "pm-compare, target " << target << ", " << totalFrames << " frames per tracker\n\n"
                << md.str() << "\nwritten to " << files.dir() << "/" << std::endl;
    return 0;
  });
}
