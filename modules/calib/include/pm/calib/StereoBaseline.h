#pragma once
/*!
  \file StereoBaseline.h
  The stereo rig's check from pairs of images of a calibration pattern (pm::calib::Pattern: an
  AprilTag board or a chessboard): the pattern's pose in each camera gives, for a pair,
  cLMcR = cLMb * cRMb^-1. Over N pairs, those farther than 3 median deviations from the median
  are rejected and the others averaged (translation; rotation by theta-u about the first).
*/
#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/core/vpRGBa.h>

#include "pm/calib/ChessBoard.h"
#include "pm/calib/TagBoard.h"
#include "pm/core/StereoRig.h"

namespace pm::calib {

struct BaselineResult
{
  vpHomogeneousMatrix cLMcR;   //!< the estimate
  double baselineMm = 0;       //!< |t|
  double spreadMm = 0;         //!< standard deviation of the inliers' translations
  double spreadDeg = 0;        //!< of their rotations
  int pairsUsed = 0, pairsRejected = 0;
  double reprojectionRmsPx = 0;
  //! Against a rig: baseline length difference (mm), translation difference (mm), rotation (deg).
  double baselineErrorMm = 0, translationErrorMm = 0, rotationErrorDeg = 0;
};

//! Aggregates the per-pair estimates (throws pm::Error if there is none) and compares with \e rig.
BaselineResult aggregateBaseline(const std::vector<vpHomogeneousMatrix> &perPair, const std::vector<double> &rmsPx,
                                 const StereoRig &rig);

} // namespace pm::calib
