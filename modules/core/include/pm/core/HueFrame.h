#pragma once
/*!
  \file HueFrame.h
  What one stereo pair (a set of images, one per camera of the rig) shows the fitness: each camera's hue plane (in its window) and the
  background's hue the scores compare with. A StereoScorer fills it from the pair
  (StereoScorer::setImages) and reads it in every score; the scorer never keeps one, so that what a
  frame sees is a value passed to whoever scores it (see StereoScorer.h).

  \code
  pm::core::HueFrame frame = scorer.newFrame(); // the model's background hue, no images yet
  scorer.setImages(frame, IL, IR);               // this pair's hue planes
  frame.setBackgroundHue(200);                   // a background that changed since the photos
  const double F = scorer.evaluate(frame, phi);
  \endcode
*/
#include <array>
#include <cstdint>
#include <vector>

#include "pm/core/CameraRig.h"
#include "pm/core/HuePlane.h"

namespace pm::core {

/*!
  The hue planes of a stereo pair (of each camera's image) and the background's hue in use (see
  HueFrame.h). Made by StereoScorer::newFrame(); its planes only by StereoScorer::setImages() and
  addHueUnder(). Cameras are numbered as on the rig (a stereo rig: 0 left, 1 right).
  \code
  pm::core::HueFrame frame = scorer.newFrame();
  scorer.setImages(frame, IL, IR);
  std::cout << frame.plane(0).width() << " px wide, background hue " << frame.backgroundHue() << " deg\n";
  \endcode
*/
class HueFrame
{
public:
  //! True once a pair was given (StereoScorer::setImages): before, nothing can be scored.
  bool hasImages() const { return m_hasImages; }
  //! Camera \e camera's hue plane (a stereo rig: 0 left, 1 right).
  const HuePlane &plane(int camera) const { return m_planes[static_cast<std::size_t>(camera)]; }
  //! The background's hue H_B the scores compare with (deg, in [0, 360)).
  double backgroundHue() const { return m_bgHue / 10.0; }
  /*!
    The background's hue H_B from now on (deg): the tracker sets the hue it learnt on trusted
    frames (tracker::BackgroundLearning: a background that changed since the photos). Throws
    pm::core::Error outside [0, 360).
  */
  void setBackgroundHue(double deg);
  //! H_B in tenths of a degree, as the kernels compare it.
  std::int32_t backgroundHueDeci() const { return m_bgHue; }

private:
  friend class StereoScorer;
  explicit HueFrame(std::int32_t bgHueDeci) : m_bgHue(bgHueDeci) {}
  std::array<HuePlane, CameraRig::kMaxCameras> m_planes;
  std::int32_t m_bgHue;
  bool m_hasImages = false;
  std::array<std::vector<std::int64_t>, CameraRig::kMaxCameras> m_pixelScratch; //!< addHueUnder's pixels per camera (kept: no allocation once grown)
};

} // namespace pm::core
