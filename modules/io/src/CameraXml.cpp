#include "pm/io/CameraXml.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpXmlParserCamera.h>

#include "pm/core/Error.h"
#include "pm/io/QuietStdout.h"

namespace pm::io {

void refuseUnsafeCameraXml(const std::string &xml)
{
  std::ifstream f(xml, std::ios::binary);
  if (!f)
    throw core::Error("the intrinsics file '" + xml + "' does not exist or cannot be read");
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (text.find("KannalaBrandt") != std::string::npos)
    throw core::Error("the intrinsics file '" + xml + "' holds a Kannala-Brandt (fisheye) model, which this project does "
                "not support: calibrate with ViSP's perspective model with distortion, or give OpenCV's camera file");
  if (text.find("&#") != std::string::npos)
    throw core::Error("the intrinsics file '" + xml + "' holds a character reference (&#...;), which a camera file has no use for");
}

vpCameraParameters readCameraXml(const std::string &xml, const std::string &name, unsigned w, unsigned h)
{
  if (!std::filesystem::is_regular_file(xml))
    throw core::Error("the intrinsics file '" + xml + "' does not exist");
  refuseUnsafeCameraXml(xml);
  vpCameraParameters cam;
  int status = vpXmlParserCamera::SEQUENCE_ERROR;
  try {
    QuietStdout quiet;
    vpXmlParserCamera parser;
    status = parser.parse(cam, xml, name, vpCameraParameters::perspectiveProjWithoutDistortion, w, h);
  } catch (const vpException &e) {
    // ViSP refuses some values itself (e.g. "Camera parameter px = 0").
    throw core::Error("camera '" + name + "' in '" + xml + "' is invalid: " + e.getStringMessage() +
                " (focal lengths px, py must be positive)");
  }
  if (status != vpXmlParserCamera::SEQUENCE_OK)
    throw core::Error("no camera named '" + name + "' of size " + std::to_string(w) + "x" + std::to_string(h) +
                " without distortion in the intrinsics file '" + xml + "'");
  requireValidIntrinsics(cam, xml, name);
  return cam;
}

void requireValidIntrinsics(const vpCameraParameters &cam, const std::string &xml, const std::string &name)
{
  const double v[4] = {cam.get_px(), cam.get_py(), cam.get_u0(), cam.get_v0()};
  if (!(v[0] > 0 && v[1] > 0) || !std::isfinite(v[0] + v[1] + v[2] + v[3]))
    throw core::Error("camera '" + name + "' in '" + xml + "': px = " + std::to_string(v[0]) + ", py = " + std::to_string(v[1]) +
                ": focal lengths must be positive");
}

void writeCameraXml(const vpCameraParameters &cam, const std::string &xml, const std::string &name, unsigned w, unsigned h)
{
  int status = vpXmlParserCamera::SEQUENCE_ERROR;
  try {
    QuietStdout quiet;
    vpXmlParserCamera parser;
    status = parser.save(cam, xml, name, w, h, "visp-photomodel stereo rig");
  } catch (const vpException &e) {
    throw core::Error("cannot write the intrinsics file '" + xml + "': " + e.getStringMessage());
  }
  if (status != vpXmlParserCamera::SEQUENCE_OK)
    throw core::Error("cannot write the intrinsics file '" + xml + "'");
}

} // namespace pm::io
