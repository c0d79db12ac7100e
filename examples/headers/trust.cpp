// The usage examples of pm::trust's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/trust/HeldOutViews.h"
#include "pm/trust/PassCalibration.h"
#include "pm/trust/PassTries.h"
#include "pm/trust/RangeBias.h"
#include "pm/tracker/RangeCorrection.h"

#include <iostream>
namespace pm_examples {

// HeldOutViews.h
void exampleHeldOutViews(const pm::core::StereoRig &rig, const std::vector<pm::model::PassView> &pass, const pm::model::AllAroundParams &params)
{
  const std::vector<std::vector<std::size_t>> folds = pm::trust::heldOutFolds(pass.size(), 6); // 6 views, one a model
  pm::model::PassMeasurements measured;
  const pm::model::AllAroundBuild full = pm::model::buildAllAroundModel(rig, pass, params, measured);
  const pm::trust::FoldModel m = pm::trust::buildFoldModel(rig, pass, params, measured, folds[0]);
  const vpHomogeneousMatrix hMm = pass[folds[0][0]].fMh.inverse() * m.fMm; // the truth on that view
}

// PassCalibration.h
void examplePassCalibration(const pm::core::StereoRig &rig, const std::vector<pm::model::PassView> &pass)
{
  pm::model::PassMeasurements measured;
  pm::model::AllAroundBuild build = pm::model::buildAllAroundModel(rig, pass, pm::model::AllAroundParams(), measured);
  const pm::core::TrustCalibration t = pm::trust::calibrateFromPass(rig, pass, pm::model::AllAroundParams(), measured);
  build.model.trust = t;                      // stored in model.json (version 6)
  std::cout << pm::trust::describe(t) << "\n";
}

// PassTries.h
void examplePassTries(const pm::core::StereoRig &rig, const std::vector<pm::model::PassView> &pass, const pm::trust::FoldModel &fold, std::size_t k)
{
  pm::tracker::PhotoModelTracker tracker(rig, fold.model);
  const vpHomogeneousMatrix hMm = pass[k].fMh.inverse() * fold.fMm;
  for (const pm::trust::PassTry &t : pm::trust::tryView(tracker, pass[k], hMm, pm::trust::TryParams(), k))
    std::cout << t.start << ": " << t.errorMm << " mm, " << t.errorDeg << " deg\n";
}

// RangeBias.h
void exampleRangeBias(std::vector<pm::trust::PassTry> &tries, const pm::core::CameraRig &rig)
{
  const std::array<double, 3> centre = pm::tracker::cameraCentreMm(rig); // the rig's cameras' centre (mm)
  const pm::trust::RangeBias b = pm::trust::measureRangeBias(tries, centre);
  if (b.measured()) for (pm::trust::PassTry &t : tries) t = pm::trust::rangeCorrected(t, b.scale, centre);
}

} // namespace pm_examples
