#pragma once
/*!
  \file CameraImages.h
  One frame's images, one per camera of a CameraRig (CameraRig.h), in the rig's order: what the
  tracker, the fitness and the precise stage are given each frame, with one camera or several.
*/
#include <array>
#include <cstddef>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/CameraRig.h"

namespace pm::core {

/*!
  One frame's images, camera k's at [k] (see CameraImages.h). A plain value of pointers: it owns
  nothing, and the images must outlive whoever is given it for the frame. No allocation.
  \code
  vpImage<vpRGBa> IL, IR;
  const pm::core::CameraImages pair(IL, IR);        // a stereo rig's frame: 0 left, 1 right
  const pm::core::CameraImages one(IL);             // a one-camera rig's frame
  std::vector<vpImage<vpRGBa>> views(3);
  const pm::core::CameraImages three = pm::core::CameraImages::of(views); // camera k's image views[k]
  std::cout << pair.size() << " " << one.size() << " " << three.size() << "\n"; // 2 1 3
  \endcode
*/
class CameraImages
{
public:
  //! No image (size() 0).
  CameraImages() = default;
  //! One camera's image.
  explicit CameraImages(const vpImage<vpRGBa> &only) : m_images{&only}, m_count(1) {}
  //! A stereo pair: 0 left, 1 right.
  CameraImages(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right) : m_images{&left, &right}, m_count(2) {}
  /*!
    Camera k's image \e images[k]. Throws pm::core::Error for none or more than
    CameraRig::kMaxCameras.
  */
  static CameraImages of(const std::vector<vpImage<vpRGBa>> &images);
  //! \e image as the next camera's. Throws pm::core::Error past CameraRig::kMaxCameras.
  CameraImages &add(const vpImage<vpRGBa> &image);

  //! The number of images.
  std::size_t size() const { return m_count; }
  //! Camera \e k's image (k < size()).
  const vpImage<vpRGBa> &operator[](std::size_t k) const { return *m_images[k]; }
  //! The images as an array of size() pointers (StereoScorer::setImages()).
  const vpImage<vpRGBa> *const *data() const { return m_images.data(); }
  /*!
    Throws pm::core::Error unless there is one image per camera of \e rig, each of its camera's
    size (the message begins with \e who).
  */
  void checkFor(const CameraRig &rig, const char *who) const;
  //! Throws pm::core::Error unless \e images equals \e cameras (one image per camera; the message begins with \e who).
  static void checkCount(std::size_t images, std::size_t cameras, const char *who);

private:
  std::array<const vpImage<vpRGBa> *, CameraRig::kMaxCameras> m_images{};
  std::size_t m_count = 0;
};

} // namespace pm::core
