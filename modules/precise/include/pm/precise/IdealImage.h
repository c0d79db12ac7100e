#pragma once
/*!
  \file IdealImage.h
  What the precise stage reads through a lens: the camera's raw image resampled bilinearly into
  the ideal (pinhole) image, only where the stage looks and only once a frame. Reading the raw
  image through the nearest raw pixel of each ideal pixel (core::UndistortMap::nearest(), what the
  fitness does) moves every sample by up to half a pixel in a pattern fixed to the lens; the
  interior term's colour gradients then point astray, and with one camera the pose's depth, which
  the outline's size and the texture's scale give, ended 2-3.5 mm off through the lab's lenses
  (0.5 mm through a pinhole; docs/camera-rigs.md).

  \code
      pm::precise::IdealImage ideal(std::make_shared<pm::core::UndistortMap>(camera));
      ideal.setRaw(raw);                                 // each frame: nothing resampled yet
      const vpRGBa *pixels = ideal.cover(100, 80, 420, 360); // the ideal image, right within that rectangle
  \endcode
*/
#include <memory>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/UndistortMap.h"

namespace pm::precise {

/*!
  One camera's ideal image, resampled from its raw image a rectangle at a time (see IdealImage.h).
  It owns its buffer (allocated once) and remembers the rectangle resampled from the current raw
  image; it keeps a pointer to that raw image until the next setRaw(). Outside the rectangle the
  buffer holds older frames' pixels: read only what cover() was asked for.
*/
class IdealImage
{
public:
  //! The camera's lens (its map); throws pm::core::Error for a null map.
  explicit IdealImage(std::shared_ptr<const core::UndistortMap> map);
  //! A new frame: \e raw (the camera's size, kept by pointer until the next call), nothing resampled from it yet.
  void setRaw(const vpImage<vpRGBa> &raw);
  /*!
    The ideal image (row-major, the camera's size), resampled from the raw image at least over
    [\e u0, \e u1) x [\e v0, \e v1) (clamped to the image): the rectangle is grown to hold what was
    resampled before in this frame, and only that is resampled again. Throws pm::core::Error before setRaw().
  */
  const vpRGBa *cover(int u0, int v0, int u1, int v1);
  //! The rectangle resampled from the current raw image (empty when u1 \<= u0).
  void covered(int &u0, int &v0, int &u1, int &v1) const { u0 = m_u0, v0 = m_v0, u1 = m_u1, v1 = m_v1; }

private:
  std::shared_ptr<const core::UndistortMap> m_map;
  vpImage<vpRGBa> m_ideal;            //!< the camera's size, allocated once
  const vpImage<vpRGBa> *m_raw = nullptr;
  int m_u0 = 0, m_v0 = 0, m_u1 = 0, m_v1 = 0; //!< resampled from m_raw
};

} // namespace pm::precise
