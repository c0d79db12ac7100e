#include "pm/compare/UncertaintyCalibration.h"

#include <algorithm>
#include <cmath>

#include "pm/compare/Scenario.h"
#include "pm/core/Error.h"
#include "pm/precise/ModelErrorFloor.h"
#include "pm/lab/LabModel.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::compare {

namespace {

constexpr int kFirstLockFrames = 10; //!< left out: the first lock

//! The share of \e samples within \e multiple times \e model's sigma on \e axis.
double within(const std::vector<UncertaintySample> &samples, const precise::UncertaintyModel &model, std::size_t axis, double multiple)
{
  if (samples.empty())
    return 0;
  std::size_t n = 0;
  for (const UncertaintySample &s : samples)
    n += std::fabs(s.error[axis]) <= multiple * std::hypot(model.sigma(axis, s.lineSigma[axis], s.residualPx), model.modelErrorGain * s.modelError[axis])
             ? 1
             : 0;
  return static_cast<double>(n) / static_cast<double>(samples.size());
}

} // namespace

std::vector<UncertaintySample> collectUncertaintySamples(const core::StereoRig &rig, const UncertaintyRun &run, const std::function<void()> &onFrame)
{
  sim::Scene scene(sim::makeTarget(run.target));
  const sim::SimulatedPhotoModel m = lab::makeLabModel(scene, rig, lab::LabModelChoice());
  const Scenario s = makeScenario("random6dof", {});
  tracker::TrackerParams p;
  p.search.ga.seed = run.seed;
  p.search.budgetEvaluations = run.budget;
  tracker::PhotoModelTracker tracker(rig, m.build.model, p);
  const precise::ModelErrorFloor modelError(m.build.model.passLandings, rig.left.hMc, p.judgement.uncertainty.modelErrorWidthDeg);
  if (!tracker.hasPreciseStage())
    throw core::Error("uncertainty calibration: the model of " + run.target + " has no outlines for the precise stage");
  std::vector<UncertaintySample> out;
  for (std::size_t k = 0; k < s.frames.size(); ++k) {
    const sim::StereoImages im = renderScenarioFrame(scene, rig, s, k);
    const tracker::TrackResult r = tracker.track(im.left, im.right);
    if (onFrame)
      onFrame();
    if (static_cast<int>(k) < kFirstLockFrames || !r.precise)
      continue;
    const vpHomogeneousMatrix hMt = s.frames[k].hMo * m.oMm, hMe = core::toHomogeneousMatrix(r.phi);
    UncertaintySample u;
    u.frame = static_cast<int>(k);
    vpRotationMatrix Re, Rt;
    hMe.extract(Re);
    hMt.extract(Rt);
    const vpThetaUVector tu(Re * Rt.t()); // the rotation error, about the hand frame's axes
    for (unsigned i = 0; i < 3; ++i) {
      u.error[i] = 1e3 * (hMe[i][3] - hMt[i][3]);
      u.error[3 + i] = tu[i] * 180.0 / M_PI;
    }
    u.lineSigma = precise::lineSigmas(r.preciseResult.information);
    u.residualPx = r.preciseResult.residualPx;
    u.modelError = modelError.at(r.phi);
    if (std::all_of(u.lineSigma.begin(), u.lineSigma.end(), [](double v) { return std::isfinite(v); }))
      out.push_back(u);
  }
  return out;
}

precise::UncertaintyModel fitUncertainty(const std::vector<std::vector<UncertaintySample>> &runs)
{
  if (runs.empty() || std::any_of(runs.begin(), runs.end(), [](const auto &r) { return r.empty(); }))
    throw core::Error("fitUncertainty: every run needs samples");
  precise::UncertaintyModel m, trial;
  for (std::size_t axis = 0; axis < 6; ++axis) {
    double largest = 0; // the floor's grid spans up to the largest median |error| of the runs
    for (const auto &r : runs) {
      std::vector<double> e;
      for (const UncertaintySample &s : r)
        e.push_back(std::fabs(s.error[axis]));
      std::nth_element(e.begin(), e.begin() + static_cast<long>(e.size() / 2), e.end());
      largest = std::max(largest, e[e.size() / 2]);
    }
    double best = 1e9;
    for (int i = 0; i <= 120; ++i) {
      trial.scale[axis] = 0.05 * std::pow(400.0, i / 120.0); // 0.05 to 20
      for (int j = 0; j <= 60; ++j) {
        trial.floor[axis] = largest * j / 30.0;
        double worst1 = 0, worst2 = 0;
        for (const auto &r : runs) {
          worst1 = std::max(worst1, std::fabs(within(r, trial, axis, 1.0) - 0.68));
          worst2 = std::max(worst2, std::fabs(within(r, trial, axis, 2.0) - 0.95));
        }
        const double cost = worst1 + 0.25 * worst2; // 1 sigma first; 2 sigmas settle the trade of scale and floor
        if (cost < best) {
          best = cost;
          m.scale[axis] = trial.scale[axis];
          m.floor[axis] = trial.floor[axis];
        }
      }
    }
  }
  return m;
}

std::array<double, 6> shareWithin(const std::vector<UncertaintySample> &samples, const precise::UncertaintyModel &model, double multiple)
{
  std::array<double, 6> w{};
  for (std::size_t axis = 0; axis < 6; ++axis)
    w[axis] = within(samples, model, axis, multiple);
  return w;
}

} // namespace pm::compare
