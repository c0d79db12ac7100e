#include "pm/calib/BaselineCheck.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::calib {

BaselineCheck::BaselineCheck(const core::StereoRig &rig, const Pattern &pattern) : m_rig(rig), m_pattern(&pattern) {}

void BaselineCheck::add(const vpImage<vpRGBa> &L, const vpImage<vpRGBa> &R, const std::string &name)
{
  if (L.getWidth() != R.getWidth() || L.getHeight() != R.getHeight())
    throw core::Error(name + ": the left and right images differ in size (" + std::to_string(L.getWidth()) + "x" +
                std::to_string(L.getHeight()) + " and " + std::to_string(R.getWidth()) + "x" +
                std::to_string(R.getHeight()) + ")");
  if (L.getWidth() != m_rig.left.width || L.getHeight() != m_rig.left.height)
    throw core::Error(name + ": the images are " + std::to_string(L.getWidth()) + "x" + std::to_string(L.getHeight()) +
                " but the rig's cameras are " + std::to_string(m_rig.left.width) + "x" + std::to_string(m_rig.left.height));
  const BoardView vl = m_pattern->find(L, m_rig.left.cam, m_rig.left.distortion, name + " left");
  const BoardView vr = m_pattern->find(R, m_rig.right.cam, m_rig.right.distortion, name + " right");
  m_perPair.push_back(vl.cMb * vr.cMb.inverse()); // cLMcR = cLMb * cRMb^-1
  m_rms.push_back(std::sqrt(0.5 * (vl.reprojectionRmsPx * vl.reprojectionRmsPx + vr.reprojectionRmsPx * vr.reprojectionRmsPx)));
  if (m_firstL.getSize() == 0) {
    m_firstL = L;
    m_firstR = R;
    m_cornersL = vl.corners;
    m_cornersR = vr.corners;
  }
}

BaselineResult BaselineCheck::result() const { return aggregateBaseline(m_perPair, m_rms, m_rig); }

} // namespace pm::calib
