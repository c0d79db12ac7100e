#pragma once
/*!
  \file RigFile.h
  Stereo rig files. A rig is two files:
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

#include "pm/core/StereoRig.h"

namespace pm::io {

/*!
  Reads a rig (version 1 or 2; hMc comes out in metres); throws pm::core::Error naming the file and the
  field that is missing or wrong.

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
  Writes the rig JSON and its intrinsics XML (name relative to the JSON's folder). A camera with
  a lens ViSP's model cannot hold exactly (more than k1) also gets an OpenCV YAML file
  (\<rig stem\>_\<camera\>.yml), which the JSON names (version 2); the XML then holds ViSP's model
  fitted to the lens, for ViSP programs. Throws pm::core::Error; nothing is left half-written.
*/
void saveRig(const core::StereoRig &rig, const std::string &rigJsonPath, const std::string &xmlName,
             const std::string &description = "");

//! ViSP's one-coefficient model (kud, kdu) of \e camera's lens: exact for k1 alone, else a least-squares fit over the image.
vpCameraParameters vispDistortionModel(const core::PinholeCamera &camera);

} // namespace pm::io
