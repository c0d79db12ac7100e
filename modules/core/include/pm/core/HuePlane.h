#pragma once
/*!
  \file HuePlane.h
  The hue of every pixel of an image, in tenths of a degree (0..3599) as 16-bit integers, the
  form the stereo fitness reads. Pixels whose saturation is below a threshold (grey, whose
  hue means nothing) get kNoHue, which matches no hue; with the threshold at 0 (the paper's
  reading) every pixel has a hue, a grey one 0.

  compute() is a vectorisable pass over the image (about 1 ms for 640x480 on one core, see
  pm-bench); it allocates only when the image size changes. The plane is padded so that
  32-bit gathers at its last pixel stay inside it.
  Given an UndistortMap, the plane is the camera's ideal (pinhole) image: the raw image's hue,
  then one gather per pixel through the map (pixels the raw image does not cover get kNoHue).
*/
#include <cstdint>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::core {

class UndistortMap;

/*!
  A rectangle of pixels: columns [u0, u1), rows [v0, v1). The default one is empty.
*/
struct PixelRect
{
  /*! \var PixelRect::u0
      \brief first column
      \var PixelRect::v0
      \brief first row
      \var PixelRect::u1
      \brief one past the last column
      \var PixelRect::v1
      \brief one past the last row */
  int u0 = 0, v0 = 0, u1 = 0, v1 = 0;
  //! True when it holds no pixel.
  bool empty() const { return u1 <= u0 || v1 <= v0; }
  //! The smallest rectangle holding both (an empty one adds nothing).
  PixelRect united(const PixelRect &o) const;
  //! Grown by \e m pixels on every side, then clipped to a w x h image.
  PixelRect grown(int m, int w, int h) const;
};

/*!
  The hue of every pixel of an image, as the stereo fitness reads it (see HuePlane.h). StereoFitness
  keeps one per camera; use one directly to inspect what the fitness sees. The plane copies what it
  needs: neither the image nor the UndistortMap is referenced after compute().
  \code
  vpImage<vpRGBa> I;
  vpImageIo::read(I, "left.png");
  pm::core::HuePlane plane;
  plane.compute(I, 0.1f);                        // pixels of saturation < 0.1 get kNoHue
  const std::uint16_t h = plane.at(320, 240);    // tenths of a degree
  if (h != pm::core::HuePlane::kNoHue)
    std::cout << "hue " << h / 10.0 << " deg\n";
  plane.compute(I, 0.1f, pm::core::PixelRect{100, 80, 300, 240}); // only columns [100, 300), rows [80, 240)
  \endcode
*/
class HuePlane
{
public:
  //! The value of a pixel without a hue (grey under the threshold, outside the window or the raw image): it matches no hue.
  static constexpr std::uint16_t kNoHue = 0xFFFF;

  //! Fills the plane from \e I; pixels with saturation < \e minSaturation get kNoHue.
  void compute(const vpImage<vpRGBa> &I, float minSaturation = 0.f);
  //! The same in the ideal image of \e map's camera (\e I is the raw image). Throws pm::core::Error if \e I is not of the map's size.
  void compute(const vpImage<vpRGBa> &I, float minSaturation, const UndistortMap &map);
  /*!
    The hue inside \e roi only (clipped to the image), kNoHue everywhere else: a point outside
    matches nothing. For a tracker that knows where the model can land this frame (about 1/3 of the
    cost for a third of the image). Only the pixels that held a hue before and now fall outside are
    reset, so a small window costs little whatever came before.
  */
  void compute(const vpImage<vpRGBa> &I, float minSaturation, const PixelRect &roi);
  /*!
    After a compute with a window: the hue of these pixels too (indices v * width + u of \e I, which
    must be the image of that compute), where the window left them out (see window()); the next
    compute resets them. Throws pm::core::Error for a pixel off the image or an image of another size.
  */
  void addPixels(const vpImage<vpRGBa> &I, float minSaturation, const std::int64_t *pixels, std::size_t n);

  //! Width of the last image computed (pixels).
  unsigned width() const { return m_w; }
  //! Height of the last image computed (pixels).
  unsigned height() const { return m_h; }
  //! Hue of pixel (u, v) in tenths of a degree, or kNoHue.
  std::uint16_t at(unsigned u, unsigned v) const { return m_hue[static_cast<std::size_t>(v) * m_w + u]; }
  //! The plane, row-major (pixel (u, v) at v * width() + u), padded past its end; valid until the next compute.
  const std::uint16_t *data() const { return m_hue.data(); }
  //! Where the last compute gave every pixel its hue (the whole image, or its window).
  const PixelRect &window() const { return m_valid; }

private:
  unsigned m_w = 0, m_h = 0;
  std::vector<std::uint16_t> m_hue;
  PixelRect m_valid; //!< where the plane may hold a hue (outside: kNoHue, but for m_extra)
  std::vector<std::int64_t> m_extra; //!< pixels outside m_valid given a hue by addPixels
  std::vector<std::uint16_t> m_raw; //!< the raw image's hue when undistorting
};

//! Hue of one colour in tenths of a degree (same formula as rgbToHsv, rounded), or kNoHue.
std::uint16_t hueDeci(const vpRGBa &c, float minSaturation);

} // namespace pm::core
