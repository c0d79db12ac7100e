#pragma once
/*!
  \file CameraRig.h
  The cameras on the robot's hand, one or more (PinholeCamera.h: each with its intrinsics, image
  size, lens and pose on the hand). One camera sees the target's outline at a size that gives its
  depth (the photo-model carries the target's metric shape); each further camera adds a view of the
  same pose. Two cameras are a StereoRig (StereoRig.h), which converts to a CameraRig of its left
  and right cameras, in that order.

  Frames as in StereoRig.h: the hand frame H (z forward, x right, y down); hMc each camera's pose
  in it, so that a model at hMo is seen by camera k at cMo = cameras[k].cMh() * hMo.
*/
#include <cstddef>
#include <vector>

#include "pm/core/PinholeCamera.h"
#include "pm/core/StereoRig.h"

namespace pm::core {

/*!
  One to kMaxCameras cameras on the hand, numbered in the order they are listed (a stereo rig's
  left is 0, its right 1). A plain value: whoever scores or draws copies what it needs.
  \code
  const pm::core::StereoRig stereo = pm::io::loadRig("data/rig/pa10_stereo.json");
  const pm::core::CameraRig both(stereo);                        // cameras[0] left, cameras[1] right
  const pm::core::CameraRig one(std::vector<pm::core::PinholeCamera>{stereo.left}); // the left camera alone
  one.validate();                                                // throws pm::core::Error naming what is wrong
  std::cout << one.size() << " camera, stereo: " << (one.isStereo() ? "yes" : "no") << "\n";
  const pm::core::StereoRig again = both.stereo();               // the two cameras as left and right
  \endcode
*/
class CameraRig
{
public:
  //! The most cameras a rig holds (the fitness keeps a fixed array of them: no allocation per frame).
  static constexpr std::size_t kMaxCameras = 4;

  std::vector<PinholeCamera> cameras; //!< camera k, as numbered everywhere (a stereo rig: 0 left, 1 right)

  CameraRig() = default;
  //! The rig of \e cams, in that order (validate() checks their number).
  explicit CameraRig(std::vector<PinholeCamera> cams) : cameras(std::move(cams)) {}
  //! A stereo rig's two cameras: 0 left, 1 right.
  CameraRig(const StereoRig &stereo) : cameras{stereo.left, stereo.right} {} // NOLINT: a stereo rig is a rig

  //! The number of cameras.
  std::size_t size() const { return cameras.size(); }
  //! Camera \e k (0-based; k < size()).
  const PinholeCamera &operator[](std::size_t k) const { return cameras[k]; }
  //! Exactly two cameras: what the stereo stages (depth, the stereo visibility) need.
  bool isStereo() const { return cameras.size() == 2; }
  /*!
    The two cameras as a StereoRig (0 left, 1 right). Throws pm::core::Error naming the number of
    cameras when there are not exactly two.
  */
  StereoRig stereo() const;
  /*!
    Throws pm::core::Error if the rig has no camera or more than kMaxCameras, or if a camera is
    invalid (PinholeCamera::validate(), naming it).
  */
  void validate() const;
};

} // namespace pm::core
