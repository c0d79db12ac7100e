#pragma once
/*!
  \file LabelledFrames.h
  The labelled set the tracker's confidence is measured on (pm-confidence): every frame of a
  scenario rendered once and given to several tracker runs (seeds, budgets, models, a model of
  another toy); each frame of each run is labelled right when the estimate is within 2 cm and
  5 degrees of the truth (never for a model of another toy), with the tracker's cues and
  confidence beside it.

  \code
    std::vector<pm::compare::LabelledFrame> set;
    pm::compare::collectLabelledFrames(rig, scene, scenario, runs, set, [&] { progress.step(); });
  \endcode
*/
#include <functional>
#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/compare/Scenario.h"
#include "pm/core/PhotoModel.h"
#include "pm/core/StereoRig.h"
#include "pm/sim/Scene.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::compare {

/*!
  One tracker run on a scenario: a model, where its frame lies on the toy, the tracker's parameters.

  \code
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
  \endcode
*/
struct ConfidenceRun
{
  std::string name;              //!< the run's name (in reports, and in the error for a missing model)
  const core::PhotoModel *model = nullptr; //!< the tracker's model (not owned; it must outlive collectLabelledFrames())
  vpHomogeneousMatrix oMm;       //!< the model's frame in the toy's frame (the truth is hMo * oMm)
  tracker::TrackerParams params;          //!< the tracker's parameters
  bool otherToy = false;         //!< the model is of another toy: every frame is wrong
};

//! One frame of one run, labelled right or wrong, with what the tracker said about it (see LabelledFrames.h).
struct LabelledFrame
{
  std::size_t run = 0;           //!< index in the runs
  std::string scenario;          //!< the Scenario's name
  int frame = 0;                 //!< the frame's index in the scenario
  tracker::TrackState state = tracker::TrackState::Searching; //!< the tracker's state after the frame
  tracker::ConfidenceCues cues;           //!< the cues the confidence is computed from (TrackResult::cues)
  double confidence = 0;         //!< the tracker's confidence (TrackResult::confidence)
  bool trusted = false;          //!< the tracker trusted its estimate (TrackResult::trusted)
  //! Translation error of the estimate against the truth hMo * oMm (mm).
  double errorMm = 0, errorDeg = 0; //!< rotation error of the estimate against the truth (deg)
  bool right = false;            //!< within kRightMm and kRightDeg of the truth (and the model is of this toy)
};

//! A frame is right when its translation error is at most kRightMm (mm) ...
constexpr double kRightMm = 20, kRightDeg = 5; //!< ... and its rotation error at most kRightDeg (deg)

/*!
  Renders every frame of \e s once, gives it to a fresh tracker per run (started with no pose) and
  appends one LabelledFrame per frame and run to \e out; \e sceneAt (if any) sets the scene for
  the frame's time before it is rendered (e.g. moves a look-alike), \e onFrame is called after each
  frame. Throws pm::core::Error if a run has no model.
*/
void collectLabelledFrames(const core::StereoRig &rig, sim::Scene &scene, const Scenario &s, const std::vector<ConfidenceRun> &runs,
                           std::vector<LabelledFrame> &out, const std::function<void()> &onFrame = {},
                           const std::function<void(sim::Scene &, double t)> &sceneAt = {});

} // namespace pm::compare
