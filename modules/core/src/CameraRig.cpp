#include "pm/core/CameraRig.h"

#include <string>

#include "pm/core/Error.h"

namespace pm::core {

namespace {

std::string cameraCount(std::size_t n) { return std::to_string(n) + (n == 1 ? " camera" : " cameras"); }

} // namespace

StereoRig CameraRig::stereo() const
{
  if (!isStereo())
    throw Error("the rig has " + cameraCount(cameras.size()) + "; a stereo rig has two (left, right)");
  StereoRig rig;
  rig.left = cameras[0];
  rig.right = cameras[1];
  return rig;
}

void CameraRig::validate() const
{
  if (cameras.empty() || cameras.size() > kMaxCameras)
    throw Error("a rig holds 1 to " + std::to_string(kMaxCameras) + " cameras, not " + std::to_string(cameras.size()));
  for (const PinholeCamera &c : cameras)
    c.validate();
}

} // namespace pm::core
