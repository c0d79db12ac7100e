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

namespace pm {

class UndistortMap;

class HuePlane
{
public:
  static constexpr std::uint16_t kNoHue = 0xFFFF;

  //! Fills the plane from \e I; pixels with saturation < \e minSaturation get kNoHue.
  void compute(const vpImage<vpRGBa> &I, float minSaturation = 0.f);
  //! The same in the ideal image of \e map's camera (\e I is the raw image, of the map's size).
  void compute(const vpImage<vpRGBa> &I, float minSaturation, const UndistortMap &map);

  unsigned width() const { return m_w; }
  unsigned height() const { return m_h; }
  //! Hue of pixel (u, v) in tenths of a degree, or kNoHue.
  std::uint16_t at(unsigned u, unsigned v) const { return m_hue[static_cast<std::size_t>(v) * m_w + u]; }
  const std::uint16_t *data() const { return m_hue.data(); }

private:
  unsigned m_w = 0, m_h = 0;
  std::vector<std::uint16_t> m_hue;
  std::vector<std::uint16_t> m_raw; //!< the raw image's hue when undistorting
};

//! Hue of one colour in tenths of a degree (same formula as rgbToHsv, rounded), or kNoHue.
std::uint16_t hueDeci(const vpRGBa &c, float minSaturation);

} // namespace pm
