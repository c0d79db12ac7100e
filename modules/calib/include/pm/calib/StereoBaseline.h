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

//! The rig check's outcome (see StereoBaseline.h): the right camera's pose in the left one, and how it compares with a rig.
struct BaselineResult
{
  vpHomogeneousMatrix cLMcR;   //!< the estimate: the right camera's pose in the left camera frame (metres)
  double baselineMm = 0;       //!< |t| of cLMcR (mm)
  double spreadMm = 0;         //!< standard deviation of the inliers' translations (mm)
  double spreadDeg = 0;        //!< of their rotations (deg)
  //! \var pairsUsed
  //! Pairs kept (inliers) and averaged.
  int pairsUsed = 0, pairsRejected = 0; //!< pairs rejected as outliers
  double reprojectionRmsPx = 0; //!< quadratic mean of the inliers' \e rmsPx (px)
  //! \var baselineErrorMm
  //! Against the rig: this baseline's length minus the rig's (mm).
  //! \var translationErrorMm
  //! Against the rig: length of the difference between the two translations (mm).
  double baselineErrorMm = 0, translationErrorMm = 0, rotationErrorDeg = 0; //!< against the rig: angle of the rotation between the two cLMcR (deg)
};

/*!
  Aggregates the per-pair estimates \e perPair (each pair's cLMcR, metres) and compares the result
  with \e rig's cLMcR. \e rmsPx is each pair's reprojection RMS (px), in the same order, used only
  for the result's reprojectionRmsPx. Throws pm::core::Error if there is no pair.

  \code
#include <cmath>
#include <iostream>

#include "pm/calib/StereoBaseline.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const pm::calib::TagBoard board; // 3 x 3 tags of 40 mm, 55 mm apart
  std::vector<vpHomogeneousMatrix> perPair;
  std::vector<double> rms;
  for (int k = 0; k < 10; ++k) {
    const std::string L = "L_" + std::to_string(k) + ".png", R = "R_" + std::to_string(k) + ".png";
    const pm::calib::BoardView l = board.find(pm::io::readColorImage(L), rig.left.cam, rig.left.distortion, L);
    const pm::calib::BoardView r = board.find(pm::io::readColorImage(R), rig.right.cam, rig.right.distortion, R);
    perPair.push_back(l.cMb * r.cMb.inverse()); // cLMcR = cLMb * cRMb^-1
    rms.push_back(std::sqrt(0.5 * (l.reprojectionRmsPx * l.reprojectionRmsPx + r.reprojectionRmsPx * r.reprojectionRmsPx)));
  }
  const pm::calib::BaselineResult res = pm::calib::aggregateBaseline(perPair, rms, rig);
  std::cout << res.baselineMm << " mm (rig: " << res.baselineErrorMm << " mm off), rotation " << res.rotationErrorDeg
            << " deg off, " << res.pairsRejected << " pairs rejected" << std::endl;
}
  \endcode
*/
BaselineResult aggregateBaseline(const std::vector<vpHomogeneousMatrix> &perPair, const std::vector<double> &rmsPx,
                                 const core::StereoRig &rig);

} // namespace pm::calib
