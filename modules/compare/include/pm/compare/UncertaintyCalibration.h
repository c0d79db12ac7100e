#pragma once
/*!
  \file UncertaintyCalibration.h
  Is the tracker's reported uncertainty (TrackResult::uncertainty, 1-sigma per axis) honest?
  pm-uncertainty's experiment: random 6-DoF runs (pm-compare's random6dof: 600 frames, each at a
  random pose) of chosen toys and RM-GA seeds with the all-around model; on every frame whose pose
  is the precise stage's (the first 10 left out: the first lock), the true error per axis (mm
  along the hand frame's x, y, z, deg about them) beside the precise stage's own line sigmas and
  residual. Of an honest 1-sigma, about 68 % of the true errors fall within it (95 % within two).
  fitUncertainty() finds, per axis, the UncertaintyModel's scale and floor that come nearest to
  that on the worst of the runs given.

  \code
    const auto c12 = pm::compare::collectUncertaintySamples(rig, {"C12", 1});
    const auto r2 = pm::compare::collectUncertaintySamples(rig, {"R2", 1});
    const pm::precise::UncertaintyModel m = pm::compare::fitUncertainty({c12, r2});
    const std::array<double, 6> within = pm::compare::shareWithin(c12, m, 1.0); // about 0.68 each
  \endcode
*/
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pm/core/StereoRig.h"
#include "pm/precise/PoseUncertainty.h"

namespace pm::compare {

//! One frame: the true error and what the precise stage measured.
struct UncertaintySample
{
  int frame = 0;                      //!< the frame's index in the run
  std::array<double, 6> error{};      //!< estimate minus truth: mm along x, y, z, then deg about them (hand frame)
  std::array<double, 6> lineSigma{};  //!< the lines' own 1-sigma (lineSigmas()), mm then deg
  double residualPx = 0;              //!< PreciseResult::residualPx
  std::array<double, 6> modelError{}; //!< the model's own error near the view (ModelErrorFloor::at(), from its pass landings), mm then deg
};

//! One random 6-DoF run.
struct UncertaintyRun
{
  std::string target = "C12";   //!< the toy (catalogue code)
  std::uint64_t seed = 1;       //!< RM-GA's seed
  long budget = 1900;           //!< evaluations per frame
};

//! The run's samples (see UncertaintyCalibration.h); \e onFrame after each frame. Throws pm::core::Error.
std::vector<UncertaintySample> collectUncertaintySamples(const core::StereoRig &rig, const UncertaintyRun &run,
                                                         const std::function<void()> &onFrame = {});

/*!
  Per axis, the scale and floor (on a grid; the model's own error added in quadrature with the
  shipped model's gain, as the tracker adds it) whose share of errors within 1 sigma is nearest 68 % on
  the worst of \e runs, a quarter of the worst distance of the share within 2 sigma from 95 %
  added (it settles the trade between scale and floor). Throws pm::core::Error if a run has no sample.
*/
precise::UncertaintyModel fitUncertainty(const std::vector<std::vector<UncertaintySample>> &runs);

//! Per axis, the share of \e samples whose |error| is within \e multiple times \e model's sigma (0 for no sample).
std::array<double, 6> shareWithin(const std::vector<UncertaintySample> &samples, const precise::UncertaintyModel &model, double multiple);

} // namespace pm::compare
