#pragma once
/*!
  \file PoseUncertainty.h
  The pose's uncertainty a user can read: 1-sigma in mm along the hand frame's x, y, z and in
  degrees about them, from the precise stage's information (PreciseResult::information, the
  Gauss-Newton J^T J / variance of its finest lines).

  The lines' own covariance, the inverse of their information, is over-confident: the lines are
  not independent (neighbours see the same blur and the same patch of background) and the model's
  outline is itself a little off (the true errors against it: docs/trust.md). So each axis's sigma
  is that of the lines times the frame's residual (px, as least squares scales its covariance by the
  residual's variance) times a scale, with a floor and
  the model's own error near the view (ModelErrorFloor.h: what no line sees) added in quadrature;
  scales and floors are fitted by
  `pm-uncertainty --fit` (docs/trust.md) so that about 68 % of the true errors fall within 1 sigma
  on each axis.

  \code
    const pm::tracker::TrackResult r = tracker.track(left, right);
    if (r.uncertainty.known)
      std::cout << "1-sigma " << r.uncertainty.maxMm() << " mm, " << r.uncertainty.maxDeg() << " deg\n";
  \endcode
*/
#include <array>
#include <cmath>
#include <cstddef>

namespace pm::precise {

//! 1-sigma per axis of the hand frame (see PoseUncertainty.h); unknown when no precise stage measured the frame.
struct PoseUncertainty
{
  bool known = false;                //!< measured on this frame (the precise stage's pose is the frame's)
  std::array<double, 3> sigmaMm{};   //!< along the hand frame's x, y, z (mm)
  std::array<double, 3> sigmaDeg{};  //!< about the hand frame's x, y, z (deg)
  double maxMm() const;              //!< the largest of sigmaMm
  double maxDeg() const;             //!< the largest of sigmaDeg
};

/*!
  The lines' own 1-sigma per axis: the square roots of the diagonal of the inverse of
  \e information (6 x 6, row-major, twist in mm then rad), in mm then deg. Infinite on every axis
  when the information is singular or not finite.
*/
std::array<double, 6> lineSigmas(const std::array<double, 36> &information);

/*!
  From the lines' sigma to an honest one, per axis:
  sigma = sqrt((scale * residual * lines' sigma)^2 + floor^2), the residual in px.
  The default-constructed model is the shipped one (docs/trust.md says how it was fitted).

  \code
#include <iostream>
#include <pm/precise/PoseUncertainty.h>

int main()
{
  std::array<double, 36> information{};  // in a program: PreciseResult::information
  for (int i = 0; i < 6; ++i)
    information[7 * i] = i < 3 ? 4.0 : 4.0e6; // 0.5 mm and 0.5 mrad from the lines
  const pm::precise::UncertaintyModel model;       // the shipped scales and floors
  const pm::precise::PoseUncertainty u = model.uncertainty(information, 0.9); // a residual of 0.9 px
  std::cout << "x: " << u.sigmaMm[0] << " mm, about x: " << u.sigmaDeg[0] << " deg\n";
}
  \endcode
*/
struct UncertaintyModel
{
  std::array<double, 6> scale{};  //!< per axis (x, y, z, then about x, y, z): the lines' sigma times the residual times this (1/px)
  std::array<double, 6> floor{};  //!< per axis, added in quadrature (mm, then deg)
  /*!
    The model's own error near the view (ModelErrorFloor.h, from the model's pass landings) times
    this, added in quadrature too (0: left out); \e modelErrorWidthDeg: how far around the camera's
    direction the pass's views count.
  */
  double modelErrorGain = 1.0;
  double modelErrorWidthDeg = 10; //!< the Gaussian weights' width on the angle between directions (deg)
  /*!
    Each axis's sigma, all terms together, times this: 1 for the shipped model; a model calibrated from
    its pass sets it so that 68 % of its held-out views' true errors fall within 1 sigma through the
    user's own camera (core::TrustCalibration::sigmaGain).
  */
  std::array<double, 6> gain{1, 1, 1, 1, 1, 1};
  //! The shipped model.
  UncertaintyModel();
  /*!
    The uncertainty of a frame whose precise stage measured \e information and \e residualPx
    (PreciseResult::information and residualPx); known: false when the information is singular.
  */
  PoseUncertainty uncertainty(const std::array<double, 36> &information, double residualPx) const;
  //! The same from the lines' own sigmas (lineSigmas()); with \e modelError (ModelErrorFloor::at()) times modelErrorGain added in quadrature.
  PoseUncertainty uncertainty(const std::array<double, 6> &lineSigma, double residualPx,
                              const std::array<double, 6> &modelError = std::array<double, 6>{}) const;
  //! The sigma on \e axis (0..5: x, y, z, about x, y, z) of a line sigma \e lineSigma (mm or deg) and a residual \e residualPx.
  double sigma(std::size_t axis, double lineSigma, double residualPx) const { return std::hypot(scale[axis] * residualPx * lineSigma, floor[axis]); }
  //! Throws pm::core::Error if a scale or gain is not positive, a floor or the model error's gain negative or not finite, or its width not positive.
  void validate() const;
};

} // namespace pm::precise
