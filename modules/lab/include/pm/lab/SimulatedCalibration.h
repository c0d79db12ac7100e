#pragma once
/*!
  \file SimulatedCalibration.h
  The rig calibration in the lab: chessboard pairs rendered through a rig whose cameras have a
  known lens distortion; how far a calibration of them lands from that rig is
  pm::calib::compareRigs().

  \code
      const pm::core::StereoRig truth = pm::lab::labRigWithLens(pm::core::LensDistortion{{-0.25, 0.08, 0.001, -0.0005, 0}});
      const auto pairs = pm::lab::renderCalibrationPairs(truth, board, 20, pm::lab::SimulatedCalibrationParams());
      const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, board);
      const pm::calib::CalibrationErrors e = pm::calib::compareRigs(c.rig, truth);
  \endcode
*/
#include <functional>
#include <vector>
#include "pm/calib/CameraCalibration.h"
#include "pm/calib/RigCalibration.h"

namespace pm::lab {

//! The simulated calibration's settings: a lens for labRigWithLens(), and renderCalibrationPairs()'s sensor noise and random seed.
struct SimulatedCalibrationParams
{
  //! The lens of both cameras when no rig is given: strong barrel distortion, as OpenCV's sample cameras.
  core::LensDistortion distortion{{-0.25, 0.08, 0.001, -0.0005, 0.0}};
  double noiseSigma = 2.0;  //!< sensor noise (grey levels)
  std::uint64_t seed = 1;   //!< the board's poses and the noise
};

//! The lab's rig (data/rig/pa10_stereo.json's geometry: 754 px, 640x480, 323 mm, toed in at 500 mm) with \e lens on both cameras.
core::StereoRig labRigWithLens(const core::LensDistortion &lens);

/*!
  \e n stereo pairs of \e board seen by \e rig at random poses around 500 mm (spread so that the
  corners cover the images, where the distortion is strongest). \e step is called after each pair.
*/
std::vector<calib::StereoImagePair> renderCalibrationPairs(const core::StereoRig &rig, const calib::Pattern &board, int n,
                                                           const SimulatedCalibrationParams &params,
                                                           const std::function<void()> &step = {});

/*!
  One camera's calibration in the lab: the images of a board fixed in the world and the hand poses
  they were taken at (renderCalibrationViews()).
*/
struct CalibrationPass
{
  std::vector<calib::CalibrationView> views; //!< the camera's images of the board
  std::vector<vpHomogeneousMatrix> fMh;      //!< the hand in the world (the board's frame) at each view
};

/*!
  \e n images of \e board, fixed in the world, seen by \e camera on the hand at random poses around
  500 mm (every other one off-centre and tilted, so that the corners reach the image's edges), and
  the hand's pose at each: a one-camera rig's calibration images with its robot's poses, for the
  intrinsics (calib::calibrateCamera()) and the camera's pose on the hand (calib::solveHandEye()).
  \e step is called after each view.
  \code
      const pm::core::PinholeCamera truth = pm::lab::labRigWithLens(lens).left;
      const pm::lab::CalibrationPass pass = pm::lab::renderCalibrationViews(truth, board, 30, pm::lab::SimulatedCalibrationParams());
      const pm::calib::CameraCalibration c = pm::calib::calibrateCamera(pass.views, board);
  \endcode
*/
CalibrationPass renderCalibrationViews(const core::PinholeCamera &camera, const calib::Pattern &board, int n,
                                       const SimulatedCalibrationParams &params, const std::function<void()> &step = {});

} // namespace pm::lab
