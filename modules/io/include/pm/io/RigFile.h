#pragma once
/*!
  \file RigFile.h
  Rig files: one camera or more on the hand (1 to CameraRig::kMaxCameras), a stereo rig's two
  listed left then right. A rig is two files:
  - the intrinsics, in ViSP's camera XML (vpXmlParserCamera), one \<camera\> per camera,
    perspective projection without distortion;
  - the rig file (JSON), which names that XML and gives, for each camera, its name in the
    XML, its image size and its pose in the hand frame:

        {
          "format": "visp-photomodel-rig", "version": 1,
          "intrinsics_xml": "pa10_cameras.xml",          // relative to the rig file
          "cameras": [
            { "name": "left", "image_width": 640, "image_height": 480,
              "hMc": { "translation_mm": [-161.5, 0, 0], "thetau_deg": [0, 17.9, 0] } },
            { "name": "right", ... } ]
        }

  A camera may name its own intrinsics file instead, "intrinsics": "left.yml" (version 2):
  any format pm::io::readCameraFile knows (ViSP XML, OpenCV YAML/XML, ROS camera_info), with the
  lens distortion it holds. ViSP's XML may hold ViSP's distortion model (kud), read as k1.
  hMc is the camera's pose in the hand frame: translation in millimetres, rotation as a
  theta-u vector in degrees (ViSP's vpThetaUVector).
*/
#include <string>

#include "pm/core/CameraRig.h"
#include "pm/core/StereoRig.h"

namespace pm::io {

/*!
  Reads a rig of any number of cameras (1 to CameraRig::kMaxCameras; version 1 or 2; hMc comes out in
  metres), numbered as listed; throws pm::core::Error naming the file and the field that is missing or
  wrong.
  \code
  const pm::core::CameraRig rig = pm::io::loadCameraRig("data/rig/pa10_mono.json");
  std::cout << rig.size() << " camera(s), the first " << rig[0].name << " " << rig[0].width << "x" << rig[0].height << "\n";
  \endcode
*/
core::CameraRig loadCameraRig(const std::string &rigJsonPath);
/*!
  Reads a stereo rig: a rig file of exactly two cameras, left then right (loadCameraRig()); throws
  pm::core::Error naming the file, and the number of cameras when it is not two.

  \code
#include <iostream>

#include "pm/io/RigFile.h"

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  std::cout << "baseline " << rig.baseline() * 1e3 << " mm, cLMcR:\n" << rig.cLMcR() << std::endl;
  const vpHomogeneousMatrix cLMh = rig.left.cMh(); // the hand frame in the left camera
  std::cout << rig.left.name << " " << rig.left.width << "x" << rig.left.height << ", cMh:\n" << cLMh << std::endl;
}
  \endcode
*/
core::StereoRig loadRig(const std::string &rigJsonPath);
/*!
  Writes the rig JSON (its cameras in order; a StereoRig converts: left, right) and its intrinsics
  XML (name relative to the JSON's folder). A camera with a lens ViSP's model cannot hold exactly
  (more than k1) also gets an OpenCV YAML file
  (\<rig stem\>_\<camera\>.yml), which the JSON names (version 2); the XML then holds ViSP's model
  fitted to the lens, for ViSP programs. Throws pm::core::Error; nothing is left half-written.
*/
void saveRig(const core::CameraRig &rig, const std::string &rigJsonPath, const std::string &xmlName,
             const std::string &description = "");

//! ViSP's one-coefficient model (kud, kdu) of \e camera's lens: exact for k1 alone, else a least-squares fit over the image.
vpCameraParameters vispDistortionModel(const core::PinholeCamera &camera);

} // namespace pm::io
