#pragma once
/*!
  \file CameraXml.h
  Intrinsics from ViSP's camera XML (vpXmlParserCamera), without the parser's chatter on
  stdout, with errors that name the file and the camera.
*/
#include <string>

#include <visp3/core/vpCameraParameters.h>

namespace pm::io {

/*!
  Reads camera \e name (perspective projection without distortion) of size w x h from \e xml.
  Throws pm::Error if the file or the camera is missing, or a focal length is not positive.
*/
vpCameraParameters readCameraXml(const std::string &xml, const std::string &name, unsigned w, unsigned h);
//! Appends camera \e name to \e xml (created if missing). Throws pm::Error.
void writeCameraXml(const vpCameraParameters &cam, const std::string &xml, const std::string &name, unsigned w, unsigned h);

} // namespace pm::io
