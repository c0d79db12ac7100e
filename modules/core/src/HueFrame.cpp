#include "pm/core/HueFrame.h"

#include "FitnessKernels.h"
#include "pm/core/Error.h"

namespace pm::core {

void HueFrame::setBackgroundHue(double deg)
{
  if (!(deg >= 0 && deg < 360))
    throw Error("the background's hue must lie in [0, 360) degrees");
  m_bgHue = kernels::deci(deg) % 3600;
}

} // namespace pm::core
