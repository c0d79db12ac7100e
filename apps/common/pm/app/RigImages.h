#pragma once
/*!
  \file RigImages.h
  The still images a program was given for its rig: one per camera (--camera-images), or a pair's
  --left and --right (pm-detect, pm-fitness-map).
*/
#include <string>
#include <vector>

#include "pm/core/CameraRig.h"

namespace pm::app {

/*!
  \e perCamera (--camera-images, one per camera in the rig's order) when given, else the pair \e left,
  \e right. Throws CLI::ValidationError (a usage error) when their count is not \e rig's.
*/
std::vector<std::string> stillImagesFor(const core::CameraRig &rig, const std::vector<std::string> &perCamera, const std::string &left,
                                        const std::string &right);

} // namespace pm::app
