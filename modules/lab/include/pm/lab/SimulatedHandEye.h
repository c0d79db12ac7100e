#pragma once
/*!
  \file SimulatedHandEye.h
  The hand-eye calibration in the lab (pm-calib-baseline --hand-eye): the PA-10 moves the rig
  around a board fixed in the world (each joint up to 0.12 rad from the start), each camera finds
  the board's pose, and ViSP's vpHandEyeCalibration gives each camera's pose on the hand (hMc),
  compared with the rig file's. Poses where the board leaves a view, or is found with a
  reprojection over 0.5 px, are left out.
*/
#include <cstdint>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/calib/Pattern.h"
#include "pm/core/StereoRig.h"
#include "pm/sim/Scene.h"

namespace pm::lab {

//! A camera's defocus: a Gaussian blur of sigma \e px (pixels, OpenCV; 0 or less: the image as it is).
vpImage<vpRGBa> defocused(const vpImage<vpRGBa> &image, double px);

//! One camera's hand-eye result: its pose on the hand as calibrated, and how far it lies from the rig file's.
struct HandEyeEstimate
{
  vpHomogeneousMatrix hMc;       //!< the camera's pose on the hand, as calibrated (metres)
  double translationErrorMm = 0; //!< its distance from the rig file's hMc (mm)
  double rotationErrorDeg = 0;   //!< the angle between them (deg)
};

//! The hand-eye calibration of both cameras.
struct HandEyeResult
{
  HandEyeEstimate left;            //!< the left camera's
  HandEyeEstimate right;           //!< the right camera's
  std::size_t poses = 0;         //!< arm poses used (the board seen well by both cameras)
};

/*!
  Moves the PA-10 through \e poses random poses (seed \e seed) with \e scene (the board) fixed in
  the world 0.5 m in front of the start, renders what \e truthRig's cameras see (blurred by
  \e blurPx), finds \e pattern with \e rig's intrinsics and calibrates each camera's hMc.
  Throws pm::core::Error when fewer than 3 poses are usable or ViSP's calibration fails.

  \code
    const pm::calib::ChessBoard board; // 6 x 9 inner corners, 20 mm squares
    pm::sim::Scene scene(pm::sim::flatPrint(board.render(8.0), board.widthMm(), "board"));
    const pm::lab::HandEyeResult r = pm::lab::simulatedHandEye(scene, rig, rig, board, 30, 1, 0.7);
    std::cout << r.left.translationErrorMm << " mm\n";
  \endcode
*/
HandEyeResult simulatedHandEye(const sim::Scene &scene, const core::StereoRig &truthRig, const core::StereoRig &rig, const calib::Pattern &pattern,
                               int poses, std::uint64_t seed, double blurPx);

} // namespace pm::lab
