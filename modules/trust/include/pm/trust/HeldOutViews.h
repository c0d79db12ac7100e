#pragma once
/*!
  \file HeldOutViews.h
  The pass's views held out of the models they are tried on: a few of the views but the first (the
  model's frame and its viewpoints' cap come from it), held out of models built from the pass without
  them (one a model by default, or a few far apart in the pass; model::buildAllAroundModelWithout(), the same
  parameters, the views' silhouettes and stereo depths measured once for all). A right
  pose tried on a held-out view is then tried as the tracker meets a new view at run time: through
  an outline and colours the model did not take from that view.

  \code
    const std::vector<std::vector<std::size_t>> folds = pm::trust::heldOutFolds(pass.size(), 6); // 6 views, one a model
    pm::model::PassMeasurements measured;
    const pm::model::AllAroundBuild full = pm::model::buildAllAroundModel(rig, pass, params, measured);
    const pm::trust::FoldModel m = pm::trust::buildFoldModel(rig, pass, params, measured, folds[0]);
    const vpHomogeneousMatrix hMm = pass[folds[0][0]].fMh.inverse() * m.fMm; // the truth on that view
  \endcode
*/
#include <cstddef>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/PhotoModel.h"
#include "pm/core/StereoRig.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PassView.h"

namespace pm::trust {

/*!
  min(\e count, views - 1) of views 1 .. \e views - 1, spread evenly over them, in groups of
  \e perModel (a model built without each group; the views of a group as far apart in the pass as
  the count allows, so that the model keeps the neighbours of each); view 0 is never held out.
  Empty for fewer than 2 views, a count of 0 or a group of 0.
*/
std::vector<std::vector<std::size_t>> heldOutFolds(std::size_t views, std::size_t count, std::size_t perModel = 1);

//! A model built without some of the pass's views, and its frame in the pass's world frame.
struct FoldModel
{
  core::PhotoModel model;       //!< the all-around model of the other views
  vpHomogeneousMatrix fMm;      //!< its frame in the world frame of the pass's hand poses (metres)
  std::vector<std::size_t> heldOut; //!< the views it did not see
};

/*!
  The all-around model of \e pass without the views \e heldOut, built with \e params from what the
  full build measured of the views (\e measured: model::buildAllAroundModel() with its measurements).
  Throws pm::core::Error as the builder does (too few views left, ...).
*/
FoldModel buildFoldModel(const core::StereoRig &rig, const std::vector<model::PassView> &pass, const model::AllAroundParams &params,
                         const model::PassMeasurements &measured, const std::vector<std::size_t> &heldOut);

} // namespace pm::trust
