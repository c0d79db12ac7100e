#include "pm/model/PassRig.h"

#include <cmath>
#include <string>

#include "pm/core/Error.h"

namespace pm::model {

namespace {

//! The right camera of the lab's symmetric stereo rig, in its left camera's frame.
vpHomogeneousMatrix leftMright(const core::PinholeCamera &c)
{
  const core::StereoRig s = core::StereoRig::symmetric(c.cam, c.width, c.height, kSideStepM, core::StereoRig::toeInFor(kSideStepM, kSideStepMeetM));
  return s.left.cMh() * s.right.hMc;
}

} // namespace

core::StereoRig passRig(const core::CameraRig &rig)
{
  rig.validate();
  core::StereoRig pair;
  pair.left = rig[0];
  if (rig.size() >= 2) {
    pair.right = rig[1];
    return pair;
  }
  pair.right = rig[0];
  pair.right.hMc = rig[0].hMc * leftMright(rig[0]);
  pair.right.name = rig[0].name.empty() ? "side step" : rig[0].name + " after the side step";
  return pair;
}

vpHomogeneousMatrix sideStep(const core::CameraRig &rig)
{
  rig.validate();
  if (rig.size() >= 2)
    return vpHomogeneousMatrix();
  return rig[0].hMc * leftMright(rig[0]) * rig[0].cMh();
}

core::CameraImages viewImages(const PassView &v, std::size_t cameras)
{
  if (cameras == 1)
    return core::CameraImages(v.left);
  if (cameras == 2)
    return core::CameraImages(v.left, v.right);
  throw core::Error(v.name + ": a pass view holds two images, and the rig has " + std::to_string(cameras) + " cameras");
}

} // namespace pm::model
