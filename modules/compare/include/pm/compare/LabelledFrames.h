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
    pm::compare::collectLabelledFrames(rig, scene, scenario, runs, set, [] { progress.step(); });
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

//! One tracker run on a scenario: a model, where its frame lies on the toy, the tracker's parameters.
struct ConfidenceRun
{
  std::string name;
  const PhotoModel *model = nullptr;
  vpHomogeneousMatrix oMm;       //!< the model's frame in the toy's frame (the truth is hMo * oMm)
  TrackerParams params;
  bool otherToy = false;         //!< the model is of another toy: every frame is wrong
};

struct LabelledFrame
{
  std::size_t run = 0;           //!< index in the runs
  std::string scenario;
  int frame = 0;
  TrackState state = TrackState::Searching;
  ConfidenceCues cues;
  double confidence = 0;
  bool trusted = false;
  double errorMm = 0, errorDeg = 0;
  bool right = false;            //!< within kRightMm and kRightDeg of the truth (and the model is of this toy)
};

constexpr double kRightMm = 20, kRightDeg = 5;

/*!
  Renders every frame of \e s once, gives it to a fresh tracker per run (started with no pose) and
  appends one LabelledFrame per frame and run to \e out; \e sceneAt (if any) sets the scene for
  the frame's time before it is rendered (e.g. moves a look-alike), \e onFrame is called after each
  frame. Throws pm::Error if a run has no model.
*/
void collectLabelledFrames(const StereoRig &rig, sim::Scene &scene, const Scenario &s, const std::vector<ConfidenceRun> &runs,
                           std::vector<LabelledFrame> &out, const std::function<void()> &onFrame = {},
                           const std::function<void(sim::Scene &, double t)> &sceneAt = {});

} // namespace pm::compare
