#include "pm/lab/StillPair.h"

#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/PhotoModelFile.h"

namespace pm::lab {

StillPair loadStillPair(const std::vector<std::string> &images, const std::string &modelPath)
{
  StillPair p;
  for (const std::string &f : images)
    p.images.push_back(io::readColorImage(f));
  p.model = io::loadPhotoModel(modelPath);
  p.source = images.size() == 2 ? "stereo pair " + images[0] + " + " + images[1] : images.size() == 1 ? "image " + images[0] : "images";
  if (images.size() > 2)
    for (std::size_t k = 0; k < images.size(); ++k)
      p.source += (k ? " + " : " ") + images[k];
  p.source += ", model " + modelPath;
  return p;
}

void requireSameSize(const StillPair &p, const std::vector<std::string> &files)
{
  for (std::size_t k = 1; k < p.images.size() && k < files.size(); ++k) {
    const vpImage<vpRGBa> &a = p.images[0], &b = p.images[k];
    if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) {
      const bool pair = p.images.size() == 2;
      throw core::Error(std::string(pair ? "the left image '" : "the image '") + files[0] + (pair ? "' and the right image '" : "' and the image '") +
                        files[k] + "' differ in size (" + std::to_string(a.getWidth()) + "x" + std::to_string(a.getHeight()) + " and " +
                        std::to_string(b.getWidth()) + "x" + std::to_string(b.getHeight()) + ")");
    }
  }
}

StillPair renderStillPair(const sim::TargetShape &shape, const core::Phi &phi, const core::CameraRig &rig, const sim::SceneParams &sp,
                          const LabModelChoice &choice)
{
  StillPair p;
  const sim::Scene scene(shape, sp);
  const sim::SimulatedPhotoModel sm = makeLabModel(scene, rig, choice);
  p.model = sm.build.model;
  const vpHomogeneousMatrix hMo = core::toHomogeneousMatrix(phi);
  p.haveTruth = true;
  p.truth = sm.truth(hMo);
  p.images = scene.renderRig(rig, hMo, 0);
  p.source = "simulator, target " + scene.target().info.code + " (" + scene.target().info.name + ")";
  return p;
}

} // namespace pm::lab
