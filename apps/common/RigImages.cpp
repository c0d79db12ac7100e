#include "pm/app/RigImages.h"

#include <CLI/CLI.hpp>

namespace pm::app {

std::vector<std::string> stillImagesFor(const core::CameraRig &rig, const std::vector<std::string> &perCamera, const std::string &left,
                                        const std::string &right)
{
  const std::vector<std::string> files = perCamera.empty() ? std::vector<std::string>{left, right} : perCamera;
  if (files.size() != rig.size())
    throw CLI::ValidationError(perCamera.empty() ? "--left/--right" : "--camera-images",
                               std::to_string(files.size()) + " image" + (files.size() == 1 ? "" : "s") + " for a rig of " +
                                   std::to_string(rig.size()) + " camera" + (rig.size() == 1 ? "" : "s") + " (one per camera: --camera-images)");
  return files;
}

} // namespace pm::app
