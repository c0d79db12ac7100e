#pragma once
/*!
  \file TargetHues.h
  The target's own hues: which hues the model's S_in points have (every view), per tenth of a
  degree. What tells an occluder from a wrong pose: a model point that misses on one of the
  target's own hues lies on the target elsewhere (a wrong pose), never behind something. Read by
  the fitness's stereo visibility (StereoFitness.h) and by the precise stage's hidden lines
  (precise::StereoOcclusion).

  \code
      const pm::core::TargetHues hues(model);
      if (hues.has(pm::core::hueDeci(pixel, 0.f)))
        std::cout << "a colour of the target's own\n";
  \endcode
*/
#include <cstdint>
#include <vector>

#include "pm/core/PhotoModel.h"

namespace pm::core {

/*!
  A table of the target's own hues (see TargetHues.h): a tenth of a degree is marked when the
  model's S_in points within kSpanDeg of it are at least kShare of all of them. Copyable; lookups
  allocate nothing.
  \code
  const pm::core::TargetHues hues(model);
  const std::uint16_t h = pm::core::hueDeci(vpRGBa(200, 40, 30), 0.f);
  std::cout << (hues.has(h) ? "the target's" : "not the target's") << "\n";
  \endcode
*/
class TargetHues
{
public:
  static constexpr double kSpanDeg = 6;     //!< the hues near a model point's own (deg)
  static constexpr double kShare = 0.005;   //!< the least share of the S_in points near a hue for it to be the target's
  TargetHues() = default;                   //!< no hue is the target's
  explicit TargetHues(const PhotoModel &model); //!< from the S_in of the model and of its views
  //! Whether hue \e h (tenths of a degree as HuePlane gives them, or HuePlane::kNoHue) is one of the target's.
  bool has(std::uint32_t h) const { return h < 3600 && m_table[h]; }
  //! The table: 1 byte per tenth of a degree (3600), padded by 4 bytes of 0 for the fitness's vector gathers.
  const std::uint8_t *data() const { return m_table.data(); }

private:
  std::vector<std::uint8_t> m_table = std::vector<std::uint8_t>(3600 + 4, 0);
};

} // namespace pm::core
