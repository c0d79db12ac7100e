//! pm-confidence: how well the tracker's confidence separates right estimates from wrong ones.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/app/Progress.h"
#include "pm/report/TimePlot.h"
#include "pm/compare/ConfidenceFit.h"
#include "pm/compare/ConfidenceStudy.h"
#include "pm/compare/LabelledFrames.h"
#include "pm/compare/Roc.h"
#include "pm/compare/Scenario.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/sim/ImageVariation.h"

using pm::compare::LabelledFrame;

namespace {

//! pm-confidence's options.
struct Options
{
  std::string out, rigPath = pm::app::dataPath("rig/pa10_stereo.json"), trajectoryPath = pm::app::dataPath("trajectories/table2.csv");
  std::vector<std::string> scenarios = pm::compare::scenarioNames();
  std::vector<std::string> variations;
  std::string heldOut;
  int steps = 0;
  bool quick = false, fit = false, quiet = false, allAround = false, stereo = false, precise = true;
  double maxFalseAccept = 0.001;
};

void addOptions(CLI::App &app, Options &o)
{
  app.add_option("--out", o.out, "output folder (created if missing)")->required();
  app.add_option("--scenarios", o.scenarios, "which scenarios")->delimiter(',')->check(CLI::IsMember(pm::compare::allScenarioNames()));
  app.add_option("--steps", o.steps, "table2: only the first N steps (0: all 20)")->check(CLI::Range(0, 1000));
  app.add_option("--rig", o.rigPath, "stereo rig file");
  app.add_option("--trajectory", o.trajectoryPath, "table2: the waypoints (step,x,y,z,e1,e2,e3)");
  app.add_option("--max-false-accept", o.maxFalseAccept, "the threshold reported is the lowest whose false accept rate is at most this")
      ->check(CLI::Range(0.0, 1.0));
  app.add_flag("--quick", o.quick, "two runs on C12 only (for tests)");
  app.add_flag("--fit", o.fit, "fit the logistic model on the set (two-fold by run for the cross-validated AUROC)");
  auto *aa = app.add_flag("--all-around", o.allAround, "every run's model is the all-around one (the PA-10's pass around its toy) "
                          "instead of the flat one; the tracker then weighs the cues with the all-around coefficients");
  app.add_flag("--stereo", o.stereo, "every run's model is the stereo one (the rig's two photos, with their relief) instead of the flat "
               "one; the tracker weighs the cues with the stereo coefficients")->excludes(aa);
  app.add_flag("--precise,!--no-precise", o.precise, "the tracker's precise last stage after RM-GA (all-around models: --all-around)");
  app.add_option("--vary", o.variations, "also the crab and the head through these other cameras, one pass each "
                 "(the model made through the same camera): defocus, motion-blur, vignetting, shot-noise, white-balance, gamma, jpeg, camera")
      ->delimiter(',')
      ->check(CLI::IsMember(pm::sim::imageVariationNames()));
  app.add_option("--hold-out", o.heldOut, "with --fit: leave the runs through this camera (one of --vary) out of the fit, and report "
                 "how the fitted confidence does on them")
      ->check(CLI::IsMember(pm::sim::imageVariationNames()));
  app.add_flag("--quiet", o.quiet, "no progress, no table on stdout");
}

//! The frames the study tracks in all (for the progress bar).
std::size_t totalFrames(const Options &o)
{
  std::size_t total = 0;
  for (const auto &s : pm::compare::makeScenarios(o.scenarios, o.trajectoryPath, o.steps))
    total += s.frames.size() * pm::compare::confidencePasses(o.quick, o.variations).size();
  return total;
}

//! The labelled set: every scenario tracked by every run of the study.
pm::compare::ConfidenceStudy study(const Options &o, const pm::core::StereoRig &defaultRig, std::size_t total)
{
  pm::compare::ConfidenceStudyParams cs;
  cs.scenarios = o.scenarios;
  cs.trajectoryPath = o.trajectoryPath;
  cs.steps = o.steps;
  cs.quick = o.quick;
  cs.allAround = o.allAround;
  cs.stereo = o.stereo;
  cs.precise = o.precise;
  cs.variations = o.variations;
  cs.dataDir = pm::app::dataDir();
  pm::app::Progress progress("rendering and tracking", total, o.quiet);
  pm::compare::ConfidenceStudy st = pm::compare::runConfidenceStudy(defaultRig, cs, [&] { progress.step(); });
  progress.finish();
  return st;
}

//! --hold-out: how the fitted confidence does on the runs left out of the fit (null: none).
nlohmann::json heldOutJson(const pm::compare::ConfidenceFit::HeldOut &h)
{
  if (h.variation.empty())
    return nullptr;
  const std::size_t rightFrames = h.frames - h.wrong;
  return {{"camera", h.variation}, {"runs", h.runs}, {"frames", h.frames}, {"wrong_frames", h.wrong}, {"auroc", h.auroc},
          {"trusted_right_frames", h.trustedRight}, {"trusted_wrong_frames", h.trustedWrong},
          {"true_accept_rate", rightFrames ? static_cast<double>(h.trustedRight) / static_cast<double>(rightFrames) : 0.0},
          {"worst_run_true_accept_rate", h.worstRunTrustedShare}};
}

//! --fit: the logistic model of the run's kind of photo-model fitted anew, as JSON.
nlohmann::json fitJson(const Options &o, const pm::compare::ConfidenceStudy &st)
{
  const pm::tracker::ConfidenceKind kind = o.allAround ? pm::tracker::ConfidenceKind::AllAround
                                           : o.stereo  ? pm::tracker::ConfidenceKind::Stereo
                                                       : pm::tracker::ConfidenceKind::Flat;
  pm::compare::ConfidenceFit f;
  try {
    f = pm::compare::fitConfidence(st, kind, o.maxFalseAccept, o.heldOut);
  } catch (const pm::core::Error &e) {
    throw pm::core::Error(std::string("--fit: ") + e.what());
  }
  return {{"kind", pm::tracker::toString(kind)}, {"auroc_cross_validated", f.aurocCrossValidated}, {"auroc", f.auroc},
          {"weights", f.model.weights}, {"bias", f.model.bias}, {"threshold", f.model.threshold},
          {"operating_threshold_unshifted", f.operatingThreshold}, {"trusted_right_frames", f.trustedRight},
          {"trusted_wrong_frames", f.trustedWrong}, {"features", pm::tracker::ConfidenceCues::featureNames()}, {"iterations", f.iterations},
          {"held_out", heldOutJson(f.heldOut)}};
}

//! The ROC, whole and near its left edge, in percent; the dotted line: the trusted frames' false accept rate.
vpImage<vpRGBa> drawRoc(const pm::compare::ConfidenceReport &rep, std::size_t frames)
{
  pm::report::Series whole{"confidence", vpRGBa(200, 40, 40), {}, {}, false}, edge = whole;
  for (const auto &p : rep.curve) {
    whole.t.push_back(100 * p.falseAcceptRate);
    whole.y.push_back(100 * p.trueAcceptRate);
    if (p.falseAcceptRate <= 0.02) {
      edge.t.push_back(100 * p.falseAcceptRate);
      edge.y.push_back(100 * p.trueAcceptRate);
    }
  }
  const double trustedFar = 100.0 * rep.falseAcceptRate();
  std::ostringstream title;
  title << "ROC of the confidence on " << frames << " frames (" << rep.wrong << " wrong), AUROC " << std::fixed << std::setprecision(4) << rep.auroc;
  return pm::report::drawTimePlots({{"ROC", "TAR %", {whole}, 0, {trustedFar}}, {"ROC up to 2 % false accepts", "TAR %", {edge}, 0, {trustedFar}}},
                                   2, title.str(), "false accept rate (%)", 560);
}

nlohmann::json summaryJson(const Options &o, const pm::compare::ConfidenceStudy &st, const pm::compare::ConfidenceReport &rep,
                           const nlohmann::json &fit)
{
  nlohmann::json runsJson = nlohmann::json::array();
  for (std::size_t i = 0; i < st.runNames.size(); ++i)
    runsJson.push_back({{"name", st.runNames[i]}, {"frames", rep.perRun[i][0]}, {"wrong_frames", rep.perRun[i][1]},
                        {"trusted_wrong_frames", rep.perRun[i][2]}, {"trusted_right_frames", rep.perRun[i][3]}});
  return nlohmann::json{{"frames", st.frames.size()},
                        {"wrong_frames", rep.wrong},
                        {"wrong_frames_while_tracking", rep.trackingWrong},
                        {"wrong", "estimate more than 20 mm or 5 deg from the truth, or a model of another toy"},
                        {"auroc", rep.auroc},
                        {"auroc_while_tracking", rep.aurocTracking},
                        {"threshold", rep.threshold},
                        {"true_accept_rate", rep.trueAcceptRate()},
                        {"false_accept_rate", rep.falseAcceptRate()},
                        {"accept", "trusted: tracking, lock verified, confidence >= threshold"},
                        {"threshold_for_max_false_accept", {{"max_false_accept_rate", o.maxFalseAccept},
                                                            {"threshold", rep.atMaxFalseAccept.threshold},
                                                            {"true_accept_rate", rep.atMaxFalseAccept.trueAcceptRate},
                                                            {"false_accept_rate", rep.atMaxFalseAccept.falseAcceptRate}}},
                        {"runs", runsJson},
                        {"fit", fit}};
}

void printSummary(const Options &o, const pm::compare::ConfidenceStudy &st, const pm::compare::ConfidenceReport &rep,
                  const nlohmann::json &fit, const std::string &dir)
{
  std::cout << std::fixed << std::setprecision(4) << "confidence on " << st.frames.size() << " labelled frames, " << rep.wrong
            << " wrong (" << rep.trackingWrong << " of them while tracking), " << st.runNames.size() << " runs\n"
            << "  AUROC " << rep.auroc << " (frames while tracking: " << rep.aurocTracking << ")\n"
            << "  trusted (threshold " << rep.threshold << ", lock verified): true accept rate " << rep.trueAcceptRate()
            << ", false accept rate " << rep.falseAcceptRate() << " (" << rep.trustedWrong << " frames)\n"
            << "  threshold for a false accept rate <= " << o.maxFalseAccept << ": " << rep.atMaxFalseAccept.threshold
            << " (true accept " << rep.atMaxFalseAccept.trueAcceptRate << ")\n";
  if (o.fit)
    std::cout << "  fitted: " << fit.dump() << "\n";
  if (o.fit && !fit["held_out"].is_null()) {
    const nlohmann::json &h = fit["held_out"];
    std::cout << "  held out of the fit, the runs through " << h["camera"].get<std::string>() << ": " << h["frames"].get<std::size_t>()
              << " frames (" << h["wrong_frames"].get<std::size_t>() << " wrong), AUROC " << h["auroc"].get<double>()
              << ", right frames trusted " << h["true_accept_rate"].get<double>() << " (worst run "
              << h["worst_run_true_accept_rate"].get<double>() << "), wrong frames trusted " << h["trusted_wrong_frames"].get<std::size_t>() << "\n";
  }
  std::cout << "  written to " << dir << "/ (frames.csv, roc.png, summary.json)" << std::endl;
}

} // namespace

int main(int argc, char **argv)
{
  CLI::App app{"Measures the tracker's confidence (TrackResult::confidence) on a labelled set of frames: every pm-compare "
               "scenario rendered once per scene and tracked by several runs (seeds, budgets from 300 evaluations, "
               "supersampling 1, a model of another toy, a look-alike of similar hue beside the toy, an identical twin beside it, the relief "
               "toys R1 and R2 with cast shadows and highlights, the stereo model, a lens, a strand of seaweed in front of C12 and R2; C12 and C08), each frame labelled right when the estimate is "
               "within 2 cm and 5 deg of the truth. Writes frames.csv (cues, confidence, label), roc.png and summary.json "
               "(auroc, threshold, accept rates); --fit also fits the logistic model of the run's kind of photo-model anew (two-fold cross-validated by run, "
               "its bias placed so that the threshold 0.95 trusts at most --max-false-accept of the wrong frames) and prints its coefficients.",
               "pm-confidence"};
  app.option_defaults()->always_capture_default();
  Options o;
  addOptions(app, o);

  return pm::app::run(app, argc, argv, [&] {
    if (!o.heldOut.empty() && (!o.fit || std::find(o.variations.begin(), o.variations.end(), o.heldOut) == o.variations.end()))
      throw pm::core::Error("--hold-out " + o.heldOut + " needs --fit and the same camera in --vary");
    const pm::core::StereoRig rig = pm::io::loadRig(o.rigPath);
    const std::size_t total = totalFrames(o);
    pm::io::StagedFiles files(o.out);
    const pm::compare::ConfidenceStudy st = study(o, rig, total);
    const pm::compare::ConfidenceReport rep =
        pm::compare::reportConfidence(st, o.maxFalseAccept, pm::tracker::TrackerParams().judgement.confidence.threshold);
    const nlohmann::json fit = o.fit ? fitJson(o, st) : nlohmann::json();
    std::ofstream csv(files.stage("frames.csv"));
    pm::compare::writeConfidenceCsv(csv, st);
    csv.close();
    pm::io::writeImage(drawRoc(rep, st.frames.size()), files.stage("roc.png"));
    pm::io::writeTextFile(files.stage("summary.json"), summaryJson(o, st, rep, fit).dump(2) + "\n");
    files.commit();
    if (!o.quiet)
      printSummary(o, st, rep, fit, files.dir());
    return 0;
  });
}
