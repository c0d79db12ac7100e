#include "pm/lab/StillPair.h"

#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PhotoModelFile.h"

namespace pm::lab {

StillPair loadStillPair(const std::string &left, const std::string &right, const std::string &modelPath)
{
  StillPair p;
  p.left = io::readColorImage(left);
  p.right = io::readColorImage(right);
  p.model = io::loadPhotoModel(modelPath);
  p.source = "stereo pair " + left + " + " + right + ", model " + modelPath;
  return p;
}

void requireSameSize(const StillPair &p, const std::string &left, const std::string &right)
{
  if (p.left.getWidth() != p.right.getWidth() || p.left.getHeight() != p.right.getHeight())
    throw core::Error("the left image '" + left + "' and the right image '" + right + "' differ in size (" +
                      std::to_string(p.left.getWidth()) + "x" + std::to_string(p.left.getHeight()) + " and " +
                      std::to_string(p.right.getWidth()) + "x" + std::to_string(p.right.getHeight()) + ")");
}

StillPair renderStillPair(const sim::TargetShape &shape, const core::Phi &phi, const core::StereoRig &rig, const sim::SceneParams &sp,
                          const LabModelChoice &choice)
{
  StillPair p;
  const sim::Scene scene(shape, sp);
  const sim::SimulatedPhotoModel sm = makeLabModel(scene, rig, choice);
  p.model = sm.build.model;
  const vpHomogeneousMatrix hMo = core::toHomogeneousMatrix(phi);
  p.haveTruth = true;
  p.truth = sm.truth(hMo);
  const sim::StereoImages im = scene.renderStereo(rig, hMo, 0);
  p.left = im.left;
  p.right = im.right;
  p.source = "simulator, target " + scene.target().info.code + " (" + scene.target().info.name + ")";
  return p;
}

} // namespace pm::lab
