#pragma once
/*!
  \file Trackers.h
  The trackers pm-compare runs side by side:
  - ours, the photo-model tracker (PhotoModelTracker), started with no initial pose;
  - ViSP's vpMbGenericTracker in stereo (Camera1 = left, Camera2 = right, the rig's cRMcL) as
    EDGE, KLT or EDGE|KLT on the outline's one-face .cao model, settings from an XML file,
    started from the true pose;
  - ViSP's vpTemplateTracker (SSD or ZNCC, inverse compositional, homography warp) on the left
    image, the template being the outline's inside in the first image; the pose comes from the
    homography and the plane known at the start (points of the plane warped, then vpPose).
*/
#include <memory>
#include <string>
#include <vector>

#include <visp3/core/vpPoint.h>

#include "pm/compare/ComparedTracker.h"
#include "pm/core/PhotoModel.h"
#include "pm/core/CameraRig.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::compare {

/*!
  Our PhotoModelTracker on \e rig and \e model, named \e name: start() searches from scratch
  (initialize(), no pose needed); an estimate is valid when the tracker's state is tracking.
*/
std::unique_ptr<ComparedTracker> makeOurTracker(const core::CameraRig &rig, const core::PhotoModel &model, const tracker::TrackerParams &params,
                                                const std::string &name = "photo-model (ours)");

/*!
  The features vpMbGenericTracker tracks: \e Edge, moving edges (EDGE_TRACKER); \e Klt, KLT
  points (KLT_TRACKER); \e EdgeKlt, both.
*/
enum class MbtFeatures { Edge, Klt, EdgeKlt };
/*!
  ViSP's vpMbGenericTracker on every camera of \e rig (one camera: its native monocular case; the
  pose is the first camera's). \e caoPath: the model file; \e xmlPath: vpMbGenericTracker's
  settings (moving edges, KLT, visibility), the same for every camera; the intrinsics come from the rig. Throws pm::core::Error if
  either file cannot be loaded.
*/
std::unique_ptr<ComparedTracker> makeMbtTracker(const core::CameraRig &rig, MbtFeatures features, const std::string &caoPath,
                                                const std::string &xmlPath);

/*!
  The template tracker's cost: \e Ssd, the sum of squared differences
  (vpTemplateTrackerSSDInverseCompositional); \e Zncc, the zero-mean normalised cross-correlation
  (vpTemplateTrackerZNCCInverseCompositional).
*/
enum class TemplateCost { Ssd, Zncc };
/*!
  \e polygon: the outline in the model frame (outlinePolygon()). It tracks in the rig's first camera
  alone. Its start() throws pm::core::Error if no template cell fits inside the outline there.
*/
std::unique_ptr<ComparedTracker> makeTemplateTracker(const core::CameraRig &rig, TemplateCost cost, const std::vector<vpPoint> &polygon);

} // namespace pm::compare
