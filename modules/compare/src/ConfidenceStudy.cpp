#include "pm/compare/ConfidenceStudy.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <iomanip>
#include <ostream>

#include "pm/core/Error.h"
#include "pm/io/RigFile.h"
#include "pm/lab/LabModel.h"
#include "pm/sim/ImageVariation.h"
#include "pm/sim/TargetCatalog.h"

namespace pm::compare {

namespace {

//! The study's scenes and runs through the renderer's own camera.
std::vector<ConfidencePass> mainPasses()
{
  return {{"C12", "C12", 2, {{"C12", 1900, 1}, {"C12", 600, 2}, {"C12", 300, 3}, {"C12", 1900, 4, 0.25}, {"C05", 1900, 5}}, "", "", false, ""},
          {"C12, supersampling 1", "C12", 1, {{"C12", 600, 6}, {"C12", 1900, 7}}, "", "", false, ""},
          {"C08", "C08", 2, {{"C08", 1900, 8}, {"C08", 600, 9}}, "", "", false, ""},
          {"C12 beside a C05 squid (similar hue)", "C12", 2, {{"C12", 1900, 10}, {"C12", 600, 11}}, "C05", "", false, ""},
          // Conditions the lab's kind toys do not show: steep relief with cast shadows and
          // highlights, the stereo model, a lens, an identical twin.
          {"R2 (relief, cast shadows, highlights)", "R2", 2, {{"R2", 1900, 12}, {"R2", 600, 13}}, "", "", false, ""},
          {"R1 (relief, cast shadows, highlights)", "R1", 2, {{"R1", 1900, 14, 1.0, true}, {"R1", 600, 15}}, "", "", false, ""},
          {"C12 through a lens (k1 -0.25, k2 0.08)", "C12", 2, {{"C12", 1900, 16}, {"C12", 600, 17}}, "", "rig/pa10_stereo_lens.json", false, ""},
          {"C12 beside its twin", "C12", 2, {{"C12", 1900, 18}, {"C12", 600, 19}}, "C12", "", false, ""},
          // A strand of seaweed in front of the toy all along (pm-servo --occluder), since issue 37.
          {"C12 behind a strand of seaweed", "C12", 2, {{"C12", 1900, 20}, {"C12", 600, 21}}, "", "", true, ""},
          {"R2 behind a strand of seaweed", "R2", 2, {{"R2", 1900, 22}}, "", "", true, ""}};
}

} // namespace

std::vector<ConfidencePass> confidencePasses(bool quick, const std::vector<std::string> &variations)
{
  std::vector<ConfidencePass> passes = quick ? std::vector<ConfidencePass>{{"C12", "C12", 2, {{"C12", 1900, 1}, {"C05", 600, 2}}, "", "", false, ""}}
                                             : mainPasses();
  std::uint64_t seed = 40;
  for (const std::string &v : variations) {
    (void)sim::imageVariation(v); // an unknown name: the error names the presets
    for (const char *toy : {"C12", "R2"})
      passes.push_back({std::string(toy) + " through another camera (" + v + ")", toy, 2, {{toy, 1900, seed++}}, "", "", false, v});
  }
  return passes;
}

ConfidenceStudy runConfidenceStudy(const core::StereoRig &defaultRig, const ConfidenceStudyParams &params, const std::function<void()> &onFrame)
{
  const std::vector<Scenario> seqs = makeScenarios(params.scenarios, params.trajectoryPath, params.steps);
  ConfidenceStudy study;
  for (const ConfidencePass &pass : confidencePasses(params.quick, params.variations)) {
    const core::StereoRig rig = pass.rig.empty() ? defaultRig : io::loadRig(params.dataDir + "/" + pass.rig);
    sim::SceneParams sp;
    sp.supersampling = pass.supersampling;
    if (!pass.variation.empty())
      sp.variation = sim::imageVariation(pass.variation);
    if (!pass.strand)
      sp.occluderSizeMm[0] = 40; // pm-compare's strand
    rmga::SearchSpace space;
    prepareForScenarios(params.scenarios, sp, space);
    sim::Scene scene(sim::makeTarget(pass.target), sp);
    std::function<void(sim::Scene &, double)> sceneAt;
    if (!pass.distractor.empty()) {
      scene.setDistractor(sim::makeTarget(pass.distractor));
      scene.params().distractor = true;
      sceneAt = [](sim::Scene &sc, double t) { sc.params().distractorPose[0] = -190 + 40 * std::sin(2 * M_PI * 0.2 * t); };
    }
    std::deque<sim::SimulatedPhotoModel> models; // never relocated: ViSP 3.5 copies an empty vpImage with memcpy(nullptr)
    for (const auto &r : pass.runs) {
      sim::SceneParams ownParams;
      ownParams.variation = sp.variation; // the model through the same camera
      const sim::Scene own(sim::makeTarget(r.model), ownParams);
      lab::LabModelChoice choice;
      choice.stereo = (r.stereo || params.stereo) && !params.allAround;
      choice.flat = !choice.stereo && !params.allAround;
      models.push_back(lab::makeLabModel(own, rig, choice));
    }
    std::vector<ConfidenceRun> runs;
    const std::size_t first = study.runNames.size();
    for (std::size_t i = 0; i < pass.runs.size(); ++i) {
      const auto &r = pass.runs[i];
      ConfidenceRun c;
      c.model = &models[i].build.model;
      c.oMm = models[i].oMm;
      c.otherToy = r.model != pass.target;
      c.params = tracker::TrackerParams();
      c.params.search.budgetEvaluations = r.budget;
      c.params.search.ga.seed = r.seed;
      c.params.steady.budgetFraction = r.steady;
      c.params.refinement.precise.enabled = params.precise;
      c.params.search.space = space;
      c.name = pass.label + ": " + (params.allAround ? "all-around model of " : r.stereo || params.stereo ? "stereo model of " : "model of ") + r.model +
               ", " + std::to_string(r.budget) + " evaluations, seed " + std::to_string(r.seed) + (r.steady < 1 ? ", steady frames 25 %" : "");
      runs.push_back(c);
      study.runNames.push_back(c.name);
      study.runVariation.push_back(pass.variation);
    }
    for (Scenario s : seqs) {
      for (ScenarioFrame &f : s.frames)
        f.occluded = f.occluded || pass.strand;
      const std::size_t before = study.frames.size();
      collectLabelledFrames(rig, scene, s, runs, study.frames, onFrame, sceneAt);
      for (std::size_t k = before; k < study.frames.size(); ++k)
        study.runOf.push_back(first + study.frames[k].run);
    }
  }
  return study;
}

double ConfidenceReport::trueAcceptRate() const
{
  return static_cast<double>(trustedRight) / static_cast<double>(frames - wrong);
}

double ConfidenceReport::falseAcceptRate() const { return static_cast<double>(trustedWrong) / static_cast<double>(wrong); }

ConfidenceReport reportConfidence(const ConfidenceStudy &study, double maxFalseAccept, double threshold)
{
  const std::vector<LabelledFrame> &set = study.frames;
  if (set.empty())
    throw core::Error("reportConfidence: no frame");
  ConfidenceReport r;
  r.frames = set.size();
  r.threshold = threshold;
  std::vector<double> conf, confT;
  std::vector<bool> right, rightT;
  for (const auto &f : set) {
    conf.push_back(f.confidence);
    right.push_back(f.right);
    r.wrong += f.right ? 0 : 1;
    r.trackingWrong += !f.right && f.state == tracker::TrackState::Tracking ? 1 : 0;
    r.trustedWrong += !f.right && f.trusted ? 1 : 0;
    r.trustedRight += f.right && f.trusted ? 1 : 0;
    if (f.state == tracker::TrackState::Tracking) { // the hard part: the frames the tracker claims
      confT.push_back(f.confidence);
      rightT.push_back(f.right);
    }
  }
  r.curve = rocCurve(conf, right);
  r.auroc = auroc(conf, right);
  const bool bothT = std::count(rightT.begin(), rightT.end(), true) > 0 && std::count(rightT.begin(), rightT.end(), false) > 0;
  r.aurocTracking = bothT ? auroc(confT, rightT) : 1.0;
  r.atMaxFalseAccept = thresholdFor(r.curve, maxFalseAccept);
  r.perRun.assign(study.runNames.size(), {0, 0, 0, 0});
  for (std::size_t k = 0; k < set.size(); ++k) {
    auto &c = r.perRun.at(study.runOf.at(k));
    ++c[0];
    c[1] += set[k].right ? 0 : 1;
    c[2] += !set[k].right && set[k].trusted ? 1 : 0;
    c[3] += set[k].right && set[k].trusted ? 1 : 0;
  }
  return r;
}

void writeConfidenceCsv(std::ostream &csv, const ConfidenceStudy &study)
{
  csv << "run,scenario,frame,state";
  for (const char *n : tracker::ConfidenceCues::featureNames())
    csv << "," << n;
  csv << ",confidence,trusted,error_mm,error_deg,right\n" << std::setprecision(6);
  for (std::size_t k = 0; k < study.frames.size(); ++k) {
    const auto &f = study.frames[k];
    csv << study.runOf[k] << "," << f.scenario << "," << f.frame << "," << toString(f.state);
    for (double v : f.cues.features())
      csv << "," << v;
    csv << "," << f.confidence << "," << (f.trusted ? 1 : 0) << "," << f.errorMm << "," << f.errorDeg << "," << (f.right ? 1 : 0) << "\n";
  }
  if (!csv)
    throw core::Error("cannot write the labelled frames' table");
}

} // namespace pm::compare
