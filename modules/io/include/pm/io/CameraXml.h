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
  Throws pm::core::Error if the file or the camera is missing, or a focal length is not positive, or
  the file is one refuseUnsafeCameraXml() refuses.
*/
vpCameraParameters readCameraXml(const std::string &xml, const std::string &name, unsigned w, unsigned h);
/*!
  Refuses, with pm::core::Error, a camera XML file that ViSP 3.5's parser cannot read safely. Its
  Kannala-Brandt (fisheye) branch reads coefficients it does not have when one of k1..k5 is
  missing (fuzzing found the crash), and it reads every model of every camera in the file, so
  such a file is refused whole: the Kannala-Brandt model is not one this project supports. A
  character reference (\c &#...;) could spell the model's name, so none is accepted either.
  readCameraXml() and readCameraFile() call it before ViSP's parser.
*/
void refuseUnsafeCameraXml(const std::string &xml);
/*!
  Refuses, with pm::core::Error naming camera \e name of file \e xml, intrinsics whose focal lengths
  are not positive or whose values are not finite (ViSP's parser reads a negative px with a
  distortion model without a word).
*/
void requireValidIntrinsics(const vpCameraParameters &cam, const std::string &xml, const std::string &name);
//! Appends camera \e name to \e xml (created if missing). Throws pm::core::Error.
void writeCameraXml(const vpCameraParameters &cam, const std::string &xml, const std::string &name, unsigned w, unsigned h);

} // namespace pm::io
