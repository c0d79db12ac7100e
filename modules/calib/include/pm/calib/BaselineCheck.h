#pragma once
/*!
  \file BaselineCheck.h
  pm-calib-baseline's check of a rig file, pair by pair: the pattern found in both raw images of
  each pair gives that pair's cLMcR (StereoBaseline.h); result() aggregates them and compares the
  estimate with the rig. The first pair and the corners found in it are kept for a picture.

  \code
    const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
    const pm::calib::TagBoard board;
    pm::calib::BaselineCheck check(rig, board);
    for (int k = 0; k < 10; ++k)
      check.add(pm::io::readColorImage("L_" + std::to_string(k) + ".png"),
                pm::io::readColorImage("R_" + std::to_string(k) + ".png"), "pair " + std::to_string(k));
    const pm::calib::BaselineResult r = check.result();
    std::cout << r.baselineMm << " mm, " << r.rotationErrorDeg << " deg from the rig file" << std::endl;
  \endcode
*/
#include <string>
#include <vector>

#include "pm/calib/Pattern.h"
#include "pm/calib/StereoBaseline.h"

namespace pm::calib {

//! Pairs of images of a pattern, checked against a rig (see BaselineCheck.h).
class BaselineCheck
{
public:
  //! Checks \e rig with \e pattern, which must outlive this object.
  BaselineCheck(const core::StereoRig &rig, const Pattern &pattern);

  /*!
    Finds the pattern in \e left and \e right (raw images of the rig's cameras, their lenses
    corrected by the pattern's finder) and keeps the pair's cLMcR and reprojection RMS. Throws
    pm::core::Error, naming \e name, if the images differ in size from each other or from the rig's
    cameras, or the pattern is not found.
  */
  void add(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const std::string &name);

  //! The pairs aggregated and compared with the rig (aggregateBaseline()). Throws pm::core::Error before any pair.
  BaselineResult result() const;

  //! \name The first pair, for a picture
  //! @{
  const vpImage<vpRGBa> &firstLeft() const { return m_firstL; }               //!< its left image
  const vpImage<vpRGBa> &firstRight() const { return m_firstR; }              //!< its right image
  const std::vector<vpImagePoint> &firstLeftCorners() const { return m_cornersL; }  //!< the corners found in the left one (px)
  const std::vector<vpImagePoint> &firstRightCorners() const { return m_cornersR; } //!< in the right one (px)
  //! @}

private:
  core::StereoRig m_rig;
  const Pattern *m_pattern;
  std::vector<vpHomogeneousMatrix> m_perPair;
  std::vector<double> m_rms;
  vpImage<vpRGBa> m_firstL, m_firstR;
  std::vector<vpImagePoint> m_cornersL, m_cornersR;
};

} // namespace pm::calib
