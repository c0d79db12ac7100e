// The usage examples of pm::compare's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/compare/CadMesh.h"
#include "pm/compare/ComparedTracker.h"
#include "pm/compare/Comparison.h"
#include "pm/compare/ConfidenceFit.h"
#include "pm/compare/ConfidenceStudy.h"
#include "pm/compare/LabelledFrames.h"
#include "pm/compare/Metrics.h"
#include "pm/compare/Roc.h"
#include "pm/compare/Scenario.h"
#include "pm/compare/UncertaintyCalibration.h"

#include <fstream>
#include <iostream>
#include "pm/compare/Trackers.h"
#include "pm/io/StagedFiles.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/Mesh.h"
namespace pm_examples {

// What an example leaves to its reader (declared, never defined: this file is compiled, never linked).
struct Progress
{
  void step();
};

// CadMesh.h
void exampleCadMesh(const pm::model::AllAroundBuild &build)
{
  std::ofstream("model.cao") << pm::compare::meshCaoText(build.mesh.decimated(6.0), "all-around surface");
}

// ComparedTracker.h
void exampleComparedTracker(const pm::core::StereoRig &rig, const pm::core::PhotoModel &model, const vpImage<vpRGBa> &left0, const vpImage<vpRGBa> &right0,
                            const vpHomogeneousMatrix &hMmTrue0)
{
  std::unique_ptr<pm::compare::ComparedTracker> t = pm::compare::makeOurTracker(rig, model, pm::tracker::TrackerParams());
  t->start({left0, right0}, hMmTrue0); // one image per camera; hMmTrue0 is ignored here: ours needs no initial pose
  const pm::compare::Estimate e = t->track({left0, right0});
}

// Comparison.h
void exampleComparison(const pm::core::StereoRig &rig)
{
  pm::compare::ComparisonParams p;
  p.scenarios = {"table2"};
  p.trackers = {"ours-aa", "mbt-klt"};
  p.trajectoryPath = "data/trajectories/table2.csv";
  p.mbtXml = "data/compare/mbt.xml";
  pm::compare::Comparison c(rig, p);
  pm::io::writeTextFile("model.cao", c.caoText());
  std::ofstream csv("frames.csv");
  const pm::compare::ComparisonResult r = c.run("model.cao", csv);
  std::cout << pm::compare::comparisonTable(r);
}

// ConfidenceFit.h
void exampleConfidenceFit(const pm::core::StereoRig &rig, const pm::compare::ConfidenceStudyParams &params)
{
  const pm::compare::ConfidenceStudy s = pm::compare::runConfidenceStudy(rig, params);
  const pm::compare::ConfidenceFit f = pm::compare::fitConfidence(s, pm::tracker::ConfidenceKind::AllAround, 0.001);
  std::cout << "cross-validated AUROC " << f.aurocCrossValidated << "\n";
  pm::tracker::TrackerParams p;
  p.judgement.confidence = f.model; // kind Custom: used as it is
}

// ConfidenceStudy.h
void exampleConfidenceStudy(const pm::core::StereoRig &rig)
{
  pm::compare::ConfidenceStudyParams p;
  p.quick = true;
  p.trajectoryPath = "data/trajectories/table2.csv";
  p.dataDir = "data";
  const pm::compare::ConfidenceStudy s = pm::compare::runConfidenceStudy(rig, p);
  const pm::compare::ConfidenceReport r = pm::compare::reportConfidence(s, 0.001, 0.95);
  std::cout << "AUROC " << r.auroc << "\n";
}

// LabelledFrames.h
void exampleLabelledFrames(const pm::core::StereoRig &rig, pm::sim::Scene &scene, const pm::compare::Scenario &scenario,
                            const std::vector<pm::compare::ConfidenceRun> &runs, Progress &progress)
{
  std::vector<pm::compare::LabelledFrame> set;
  pm::compare::collectLabelledFrames(rig, scene, scenario, runs, set, [&] { progress.step(); });
}

// LabelledFrames.h
void exampleLabelledFrames2(const pm::core::StereoRig &rig, pm::sim::Scene &scene)
{
  const pm::sim::SimulatedPhotoModel sm =
      pm::sim::makeSimulatedPhotoModel(scene, rig.left.cam, rig.left.width, rig.left.height, 500);
  pm::compare::ConfidenceRun run;
  run.name = "flat model, default parameters";
  run.model = &sm.build.model; // not owned: sm must outlive the collection
  run.oMm = sm.oMm;
  std::vector<pm::compare::LabelledFrame> set;
  pm::compare::collectLabelledFrames(rig, scene, pm::compare::makeScenario("sinusoid", {}), {run}, set);
  std::vector<double> confidence;
  std::vector<bool> right;
  for (const pm::compare::LabelledFrame &f : set) {
    confidence.push_back(f.confidence);
    right.push_back(f.right);
  }
  const double a = pm::compare::auroc(confidence, right); // needs right and wrong frames
}

// Metrics.h
void exampleMetrics(const pm::core::StereoRig &rig, pm::sim::Scene &scene, const pm::compare::Scenario &s, const vpHomogeneousMatrix &oMm,
                    pm::compare::ComparedTracker *tracker)
{
  std::vector<pm::compare::FrameScore> scores;
  for (std::size_t k = 0; k < s.frames.size(); ++k) {
    const pm::sim::StereoImages im = pm::compare::renderScenarioFrame(scene, rig, s, k);
    const vpHomogeneousMatrix truth = s.frames[k].hMo * oMm; // hMm: the model in the hand frame
    if (k == 0)
      tracker->start({im.left, im.right}, truth);
    const pm::compare::Estimate e = tracker->track({im.left, im.right});
    pm::compare::FrameScore f = pm::compare::scoreFrame(e.hMm, truth);
    f.valid = e.valid;
    scores.push_back(f);
  }
  const pm::compare::Summary sum = pm::compare::summarize(scores, s.lossEnds);
  std::cout << 100 * sum.success5cm5deg << " % within 5 cm and 5 deg" << std::endl;
}

// Roc.h
void exampleRoc(const std::vector<double> &scores, const std::vector<bool> &right, const std::vector<std::vector<double>> &features)
{
  const std::vector<pm::compare::RocPoint> curve = pm::compare::rocCurve(scores, right);
  const double a = pm::compare::auroc(scores, right);
  const pm::compare::LogisticFit fit = pm::compare::fitLogistic(features, right);
}

// Roc.h
void exampleRoc2(const std::vector<std::vector<double>> &features, const std::vector<bool> &right, const std::vector<int> &runIndexMod2)
{
  const std::vector<double> held = pm::compare::crossValidatedLogistic(features, right, runIndexMod2, 2);
  const double heldOutAuroc = pm::compare::auroc(held, right);
}

// Scenario.h
void exampleScenario(const pm::core::StereoRig &rig, pm::sim::Scene &scene, const vpHomogeneousMatrix &oMm)
{
  const std::vector<pm::compare::Scenario> seqs =
      pm::compare::makeScenarios(pm::compare::scenarioNames(), "data/trajectories/table2.csv");
  for (const pm::compare::Scenario &s : seqs)
    for (std::size_t k = 0; k < s.frames.size(); ++k) {
      const pm::sim::StereoImages im = pm::compare::renderScenarioFrame(scene, rig, s, k);
      const vpHomogeneousMatrix hMmTrue = s.frames[k].hMo * oMm; // oMm: the model frame in the toy's frame
      // track im.left, im.right at t = k / s.fps and score against hMmTrue
    }
}

// UncertaintyCalibration.h
void exampleUncertaintyCalibration(const pm::core::StereoRig &rig)
{
  const auto c12 = pm::compare::collectUncertaintySamples(rig, {"C12", 1});
  const auto r2 = pm::compare::collectUncertaintySamples(rig, {"R2", 1});
  const pm::precise::UncertaintyModel m = pm::compare::fitUncertainty({c12, r2});
  const std::array<double, 6> within = pm::compare::shareWithin(c12, m, 1.0); // about 0.68 each
}

// CadMesh.h
void exampleCadMeshFile(const pm::model::AllAroundBuild &build, const pm::sim::TargetShape &target)
{
  const std::string cao = pm::compare::meshCaoText(build.mesh.decimated(6.0), "C12, all-around surface");
  const std::string exact = pm::compare::meshCaoText(pm::compare::toyCadMesh(pm::sim::buildTargetMesh(target, 1.0)).decimated(6.0), "C12, true");
}

} // namespace pm_examples
