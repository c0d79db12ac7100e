#pragma once
/*!
  \file UndistortMap.h
  Where each pixel of a camera's ideal (pinhole) image is seen in its raw image, computed once
  per camera (cv::initUndistortRectifyMap with the camera's own intrinsics as the new ones, so
  the ideal image has the raw image's size and the same px, py, u0, v0).
  - nearest(): the raw pixel index under each ideal pixel (-1 off the raw image), which the
    fitness's hue planes gather through (HuePlane::compute): one lookup per pixel per frame;
  - undistort(): the raw image resampled bilinearly into the ideal one, for the model builders
    and the calibration check, which work on whole photos once; undistortField() the same for a
    field of floats (a silhouette's signed distance, found in the raw image).
  With barrel distortion the raw image's corners fall outside the ideal image and are not used.

  \code
      const pm::core::UndistortMap map(rig.left);           // once
      vpImage<vpRGBa> ideal;
      map.undistort(rawLeft, ideal);                  // a photo for the builder
      plane.compute(rawLeft, 0.1f, map);              // the hue plane in the ideal image
  \endcode
*/
#include <cstdint>
#include <vector>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>
#include "pm/core/StereoRig.h"

namespace pm::core {

/*!
  Where each pixel of a camera's ideal (pinhole) image is seen in its raw image (see UndistortMap.h
  for an example). Built from a copy of what it needs: the PinholeCamera may go afterwards. A camera
  without distortion gets the identity map.
*/
class UndistortMap
{
public:
  //! Throws pm::core::Error if the camera's distortion is invalid (LensDistortion::validate).
  explicit UndistortMap(const PinholeCamera &camera);
  //! Width of both images, the camera's (pixels).
  unsigned width() const { return m_w; }
  //! Height of both images, the camera's (pixels).
  unsigned height() const { return m_h; }
  //! For each ideal pixel (row-major), the index of the nearest raw pixel, or -1 outside the raw image.
  const std::vector<std::int32_t> &nearest() const { return m_nearest; }
  /*!
    The raw image \e raw resampled into the ideal image \e ideal (bilinear; black where the ideal
    pixel falls off the raw image). Throws pm::core::Error if \e raw's size is not the camera's.
  */
  void undistort(const vpImage<vpRGBa> &raw, vpImage<vpRGBa> &ideal) const;
  //! The same, returned.
  vpImage<vpRGBa> undistorted(const vpImage<vpRGBa> &raw) const
  {
    vpImage<vpRGBa> ideal;
    undistort(raw, ideal);
    return ideal;
  }
  /*!
    A field of the raw image (\e raw: width() x height() floats, row-major, e.g. a silhouette's signed
    distance) resampled bilinearly into the ideal image (\e ideal, as many floats; \e outside where the
    ideal pixel falls off the raw image). A signed distance's zero line stays where it was: a mask
    resampled would move its edge by where the resampling's blur crosses its threshold (0.2-0.3 px
    outward through the lab's lens: docs/model-outline.md).
  */
  void undistortField(const float *raw, float *ideal, float outside) const;
  /*!
    Only the rectangle [\e u0, \e u1) x [\e v0, \e v1) of the ideal image (clamped to it) resampled
    from \e raw, the rest of \e ideal left as it was; \e ideal must be the camera's size. Bilinear
    through fixed-point maps (OpenCV's, 1/32 px): about 2.5 times faster a pixel than undistort()
    (what the precise stage reads near the target, frame after frame). Throws pm::core::Error for
    images of another size.
  */
  void undistortRegion(const vpImage<vpRGBa> &raw, vpImage<vpRGBa> &ideal, int u0, int v0, int u1, int v1) const;
  //! Fraction of the ideal image that the raw image covers.
  double coverage() const;

private:
  unsigned m_w = 0, m_h = 0;
  std::vector<float> m_mapU, m_mapV; //!< raw position of each ideal pixel
  std::vector<std::int16_t> m_fixedXY;  //!< the same in OpenCV's fixed point: integer x, y per pixel (CV_16SC2)
  std::vector<std::uint16_t> m_fixedA;  //!< ... and the index of its fraction (CV_16UC1)
  std::vector<std::int32_t> m_nearest;
};

} // namespace pm::core
