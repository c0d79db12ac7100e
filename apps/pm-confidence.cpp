//! pm-confidence: how well the tracker's confidence separates right estimates from wrong ones.
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/app/Progress.h"
#include "pm/report/TimePlot.h"
#include "pm/compare/LabelledFrames.h"
#include "pm/compare/Roc.h"
#include "pm/compare/Scenario.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"

namespace {

using pm::compare::LabelledFrame;

//! A scene and the runs on it: the toy, how it is rendered, and the trackers' models and parameters.
struct Pass
{
  std::string label;
  std::string target;
  unsigned supersampling = 2;
  struct Run
  {
    std::string model; //!< the toy the model is of
    long budget;
    std::uint64_t seed;
    double steady = 1.0;
    bool stereo = false; //!< the stereo photo-model (pm-make-model --stereo) instead of the flat one
  };
  std::vector<Run> runs;
  std::string distractor; //!< a look-alike beside the toy (empty: none), swaying 40 mm sideways at 0.2 Hz
  std::string rig = {};   //!< a rig file under data/ instead of --rig (e.g. one with a lens)
};

std::vector<Pass> passes(bool quick)
{
  if (quick)
    return {{"C12", "C12", 2, {{"C12", 1900, 1}, {"C05", 600, 2}}, ""}};
  return {{"C12", "C12", 2, {{"C12", 1900, 1}, {"C12", 600, 2}, {"C12", 300, 3}, {"C12", 1900, 4, 0.25}, {"C05", 1900, 5}}, ""},
          {"C12, supersampling 1", "C12", 1, {{"C12", 600, 6}, {"C12", 1900, 7}}, ""},
          {"C08", "C08", 2, {{"C08", 1900, 8}, {"C08", 600, 9}}, ""},
          {"C12 beside a C05 squid (similar hue)", "C12", 2, {{"C12", 1900, 10}, {"C12", 600, 11}}, "C05"},
          // Conditions the lab's kind toys do not show: steep relief with cast shadows and
          // highlights, the stereo model, a lens, an identical twin.
          {"R2 (relief, cast shadows, highlights)", "R2", 2, {{"R2", 1900, 12}, {"R2", 600, 13}}, ""},
          {"R1 (relief, cast shadows, highlights)", "R1", 2, {{"R1", 1900, 14, 1.0, true}, {"R1", 600, 15}}, ""},
          {"C12 through a lens (k1 -0.25, k2 0.08)", "C12", 2, {{"C12", 1900, 16}, {"C12", 600, 17}}, "", "rig/pa10_stereo_lens.json"},
          {"C12 beside its twin", "C12", 2, {{"C12", 1900, 18}, {"C12", 600, 19}}, "C12"}};
}

std::vector<double> featureRow(const LabelledFrame &f)
{
  const auto x = f.cues.features();
  return {x.begin(), x.end()};
}

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"Measures the tracker's confidence (TrackResult::confidence) on a labelled set of frames: every pm-compare "
               "scenario rendered once per scene and tracked by several runs (seeds, budgets from 300 evaluations, "
               "supersampling 1, a model of another toy, a look-alike of similar hue beside the toy, an identical twin beside it, the relief "
               "toys R1 and R2 with cast shadows and highlights, the stereo model, a lens; C12 and C08), each frame labelled right when the estimate is "
               "within 2 cm and 5 deg of the truth. Writes frames.csv (cues, confidence, label), roc.png and summary.json "
               "(auroc, threshold, accept rates); --fit also fits the logistic model anew (two-fold cross-validated by run) "
               "and prints its coefficients.",
               "pm-confidence"};
  app.option_defaults()->always_capture_default();
  std::string out, rigPath = pm::app::dataPath("rig/pa10_stereo.json"), trajectoryPath = pm::app::dataPath("trajectories/table2.csv");
  std::vector<std::string> scenarios = pm::compare::scenarioNames();
  int steps = 0;
  bool quick = false, fit = false, quiet = false, allAround = false;
  double maxFalseAccept = 0.001;
  app.add_option("--out", out, "output folder (created if missing)")->required();
  app.add_option("--scenarios", scenarios, "which scenarios")->delimiter(',')->check(CLI::IsMember(pm::compare::allScenarioNames()));
  app.add_option("--steps", steps, "table2: only the first N steps (0: all 20)")->check(CLI::Range(0, 1000));
  app.add_option("--rig", rigPath, "stereo rig file");
  app.add_option("--trajectory", trajectoryPath, "table2: the waypoints (step,x,y,z,e1,e2,e3)");
  app.add_option("--max-false-accept", maxFalseAccept, "the threshold reported is the lowest whose false accept rate is at most this")
      ->check(CLI::Range(0.0, 1.0));
  app.add_flag("--quick", quick, "two runs on C12 only (for tests)");
  app.add_flag("--fit", fit, "fit the logistic model on the set (two-fold by run for the cross-validated AUROC)");
  app.add_flag("--all-around", allAround, "every run's model is the all-around one (the PA-10's pass around its toy) "
               "instead of the flat or stereo one; the tracker then weighs the cues with the all-around coefficients");
  app.add_flag("--quiet", quiet, "no progress, no table on stdout");

  return pm::app::run(app, argc, argv, [&] {
    const pm::StereoRig defaultRig = pm::io::loadRig(rigPath);
    const std::vector<pm::compare::Scenario> seqs = pm::compare::makeScenarios(scenarios, trajectoryPath, steps);
    const std::vector<Pass> plan = passes(quick);
    std::size_t total = 0;
    for (const auto &s : seqs)
      total += s.frames.size() * plan.size();

    std::vector<LabelledFrame> set;
    std::vector<std::string> runNames;
    std::vector<std::size_t> runOf; // global run index of each frame
    pm::io::StagedFiles files(out);
    pm::app::Progress progress("rendering and tracking", total, quiet);
    for (const Pass &pass : plan) {
      const pm::StereoRig rig = pass.rig.empty() ? defaultRig : pm::io::loadRig(pm::app::dataPath(pass.rig));
      pm::sim::SceneParams sp;
      sp.supersampling = pass.supersampling;
      sp.occluderSizeMm[0] = 40; // pm-compare's strand
      pm::sim::Scene scene(pm::sim::makeTarget(pass.target), sp);
      std::function<void(pm::sim::Scene &, double)> sceneAt;
      if (!pass.distractor.empty()) {
        scene.setDistractor(pm::sim::makeTarget(pass.distractor));
        scene.params().distractor = true;
        sceneAt = [](pm::sim::Scene &sc, double t) { sc.params().distractorPose[0] = -190 + 40 * std::sin(2 * M_PI * 0.2 * t); };
      }
      std::deque<pm::sim::SimulatedPhotoModel> models; // never relocated: ViSP 3.5 copies an empty vpImage with memcpy(nullptr)
      for (const auto &r : pass.runs) {
        const pm::sim::Scene own(pm::sim::makeTarget(r.model));
        pm::app::LabModelChoice choice;
        choice.stereo = r.stereo && !allAround;
        choice.flat = !r.stereo && !allAround;
        models.push_back(pm::app::makeLabModel(own, rig, choice));
      }
      std::vector<pm::compare::ConfidenceRun> runs;
      const std::size_t first = runNames.size();
      for (std::size_t i = 0; i < pass.runs.size(); ++i) {
        const auto &r = pass.runs[i];
        pm::compare::ConfidenceRun c;
        c.model = &models[i].build.model;
        c.oMm = models[i].oMm;
        c.otherToy = r.model != pass.target;
        c.params = pm::TrackerParams();
        c.params.budgetEvaluations = r.budget;
        c.params.ga.seed = r.seed;
        c.params.steadyBudgetFraction = r.steady;
        c.name = pass.label + ": " + (allAround ? "all-around model of " : r.stereo ? "stereo model of " : "model of ") + r.model + ", " + std::to_string(r.budget) + " evaluations, seed " + std::to_string(r.seed) +
                 (r.steady < 1 ? ", steady frames 25 %" : "");
        runs.push_back(c);
        runNames.push_back(c.name);
      }
      for (const auto &s : seqs) {
        const std::size_t before = set.size();
        pm::compare::collectLabelledFrames(rig, scene, s, runs, set, [&] { progress.step(); }, sceneAt);
        for (std::size_t k = before; k < set.size(); ++k)
          runOf.push_back(first + set[k].run);
      }
    }
    progress.finish();

    std::vector<double> conf;
    std::vector<bool> right;
    std::size_t wrong = 0, trackingWrong = 0, trustedWrong = 0, trustedRight = 0;
    for (const auto &f : set) {
      conf.push_back(f.confidence);
      right.push_back(f.right);
      wrong += f.right ? 0 : 1;
      trackingWrong += !f.right && f.state == pm::TrackState::Tracking ? 1 : 0;
      trustedWrong += !f.right && f.trusted ? 1 : 0;
      trustedRight += f.right && f.trusted ? 1 : 0;
    }
    const pm::TrackerParams defaults = pm::TrackerParams();
    const double threshold = defaults.confidence.threshold;
    const auto curve = pm::compare::rocCurve(conf, right);
    const double area = pm::compare::auroc(conf, right);
    // Among the frames the tracker says it tracks (the hard part: the rest it does not claim).
    std::vector<double> confT;
    std::vector<bool> rightT;
    for (const auto &f : set)
      if (f.state == pm::TrackState::Tracking) {
        confT.push_back(f.confidence);
        rightT.push_back(f.right);
      }
    const bool bothT = std::count(rightT.begin(), rightT.end(), true) > 0 && std::count(rightT.begin(), rightT.end(), false) > 0;
    const double areaT = bothT ? pm::compare::auroc(confT, rightT) : 1.0;
    const pm::compare::RocPoint atFar = pm::compare::thresholdFor(curve, maxFalseAccept);
    const double nRight = static_cast<double>(set.size() - wrong), nWrong = static_cast<double>(wrong);

    nlohmann::json fitJson;
    if (fit) {
      // Two folds by run (even and odd run indices): each frame scored by the model fitted on the other fold.
      std::vector<std::vector<double>> rows;
      std::vector<int> fold;
      for (std::size_t k = 0; k < set.size(); ++k) {
        rows.push_back(featureRow(set[k]));
        fold.push_back(static_cast<int>(runOf[k] % 2));
      }
      std::vector<double> held;
      try {
        held = pm::compare::crossValidatedLogistic(rows, right, fold, 2);
      } catch (const pm::Error &e) {
        throw pm::Error(std::string("--fit (folds: runs of even and odd index): ") + e.what());
      }
      const auto all = pm::compare::fitLogistic(rows, right);
      fitJson = {{"auroc_cross_validated", pm::compare::auroc(held, right)}, {"weights", all.weights}, {"bias", all.bias},
                 {"features", pm::ConfidenceCues::featureNames()}, {"iterations", all.iterations}};
    }

    std::ofstream csv(files.stage("frames.csv"));
    csv << "run,scenario,frame,state";
    for (const char *n : pm::ConfidenceCues::featureNames())
      csv << "," << n;
    csv << ",confidence,trusted,error_mm,error_deg,right\n" << std::setprecision(6);
    for (std::size_t k = 0; k < set.size(); ++k) {
      const auto &f = set[k];
      csv << runOf[k] << "," << f.scenario << "," << f.frame << "," << pm::toString(f.state);
      for (double v : f.cues.features())
        csv << "," << v;
      csv << "," << f.confidence << "," << (f.trusted ? 1 : 0) << "," << f.errorMm << "," << f.errorDeg << "," << (f.right ? 1 : 0) << "\n";
    }
    if (!csv)
      throw pm::Error("cannot write " + files.finalPath("frames.csv"));
    csv.close();

    // The ROC, whole and near its left edge, in percent; the dotted line: the trusted frames' false accept rate.
    pm::report::Series whole{"confidence", vpRGBa(200, 40, 40), {}, {}, false}, edge = whole;
    for (const auto &p : curve) {
      whole.t.push_back(100 * p.falseAcceptRate);
      whole.y.push_back(100 * p.trueAcceptRate);
      if (p.falseAcceptRate <= 0.02) {
        edge.t.push_back(100 * p.falseAcceptRate);
        edge.y.push_back(100 * p.trueAcceptRate);
      }
    }
    const double trustedFar = 100.0 * static_cast<double>(trustedWrong) / nWrong;
    std::ostringstream title;
    title << "ROC of the confidence on " << set.size() << " frames (" << wrong << " wrong), AUROC " << std::fixed << std::setprecision(4) << area;
    pm::io::writeImage(pm::report::drawTimePlots({{"ROC", "TAR %", {whole}, 0, {trustedFar}},
                                               {"ROC up to 2 % false accepts", "TAR %", {edge}, 0, {trustedFar}}},
                                              2, title.str(), "false accept rate (%)", 560),
                       files.stage("roc.png"));

    // Each run's frames: what the confidence accepts, run by run (where the wrong frames it trusts come from).
    std::vector<std::array<std::size_t, 4>> perRun(runNames.size(), {0, 0, 0, 0}); // frames, wrong, trusted wrong, trusted right
    for (std::size_t k = 0; k < set.size(); ++k) {
      auto &c = perRun[runOf[k]];
      ++c[0];
      c[1] += set[k].right ? 0 : 1;
      c[2] += !set[k].right && set[k].trusted ? 1 : 0;
      c[3] += set[k].right && set[k].trusted ? 1 : 0;
    }
    nlohmann::json runsJson = nlohmann::json::array();
    for (std::size_t i = 0; i < runNames.size(); ++i)
      runsJson.push_back({{"name", runNames[i]}, {"frames", perRun[i][0]}, {"wrong_frames", perRun[i][1]},
                          {"trusted_wrong_frames", perRun[i][2]}, {"trusted_right_frames", perRun[i][3]}});
    const nlohmann::json summary{{"frames", set.size()},
                                 {"wrong_frames", wrong},
                                 {"wrong_frames_while_tracking", trackingWrong},
                                 {"wrong", "estimate more than 20 mm or 5 deg from the truth, or a model of another toy"},
                                 {"auroc", area},
                                 {"auroc_while_tracking", areaT},
                                 {"threshold", threshold},
                                 {"true_accept_rate", static_cast<double>(trustedRight) / nRight},
                                 {"false_accept_rate", static_cast<double>(trustedWrong) / nWrong},
                                 {"accept", "trusted: tracking, lock verified, confidence >= threshold"},
                                 {"threshold_for_max_false_accept", {{"max_false_accept_rate", maxFalseAccept},
                                                                     {"threshold", atFar.threshold},
                                                                     {"true_accept_rate", atFar.trueAcceptRate},
                                                                     {"false_accept_rate", atFar.falseAcceptRate}}},
                                 {"runs", runsJson},
                                 {"fit", fitJson}};
    pm::io::writeTextFile(files.stage("summary.json"), summary.dump(2) + "\n");
    files.commit();
    if (!quiet) {
      std::cout << std::fixed << std::setprecision(4) << "confidence on " << set.size() << " labelled frames, " << wrong
                << " wrong (" << trackingWrong << " of them while tracking), " << runNames.size() << " runs\n"
                << "  AUROC " << area << " (frames while tracking: " << areaT << ")\n"
                << "  trusted (threshold " << threshold << ", lock verified): true accept rate " << static_cast<double>(trustedRight) / nRight
                << ", false accept rate " << static_cast<double>(trustedWrong) / nWrong << " (" << trustedWrong << " frames)\n"
                << "  threshold for a false accept rate <= " << maxFalseAccept << ": " << atFar.threshold << " (true accept "
                << atFar.trueAcceptRate << ")\n";
      if (fit)
        std::cout << "  fitted: " << fitJson.dump() << "\n";
      std::cout << "  written to " << files.dir() << "/ (frames.csv, roc.png, summary.json)" << std::endl;
    }
    return 0;
  });
}
