#pragma once
/*!
  \file CameraFile.h
  One camera's intrinsics and lens distortion from the files calibration tools write, the
  format told by the content:
  - ViSP's camera XML (vpXmlParserCamera): the model with distortion when the file has one
    (k1 = kud), else the pinhole model; \e name picks the camera;
  - OpenCV's cv::FileStorage (YAML or XML): camera_matrix and distortion_coefficients (4, 5, 8,
    12 or 14), image_width and image_height if present (as cv::calibrateCamera's samples write);
  - ROS camera_info YAML: camera_matrix and distortion_coefficients as {rows, cols, data},
    distortion_model plumb_bob or rational_polynomial.

  \code
      const pm::io::CameraFile c = pm::io::readCameraFile("left.yml", "left", 640, 480);
      rig.left.cam = c.camera.cam;  rig.left.distortion = c.camera.distortion;
  \endcode
*/
#include <string>
#include <visp3/core/vpCameraParameters.h>
#include "pm/core/PinholeCamera.h"

namespace pm::io {

/*!
  What readCameraFile() found in a file: the camera (its name the one asked for, its intrinsics, its
  lens, its image size: the \e w, \e h asked for, else the file's, 0 if it gives none; its pose the
  identity) and the file's format.
*/
struct CameraFile
{
  core::PinholeCamera camera; //!< the camera the file describes
  std::string format;         //!< "visp-xml", "opencv", "ros"
};

/*!
  Reads \e path. \e name selects the camera in a ViSP XML (ignored otherwise); \e w, \e h the
  image size the camera must have (0: any). Throws pm::core::Error naming the file and what is wrong:
  missing, unknown format, no such camera, a matrix of the wrong shape, a focal length not
  positive, an image size that differs, a distortion that folds the image.

  \code
#include <iostream>

#include "pm/io/CameraFile.h"

int main()
{
  const pm::io::CameraFile c = pm::io::readCameraFile("left.yml", "left", 640, 480);
  std::cout << c.format << ": " << c.camera.cam << "distortion: " << c.camera.distortion.coefficients.size() << " coefficients"
            << std::endl;
}
  \endcode
*/
CameraFile readCameraFile(const std::string &path, const std::string &name, unsigned w, unsigned h);

//! Writes \e camera's intrinsics and distortion as an OpenCV YAML file (cv::FileStorage). Throws pm::core::Error.
void writeOpenCvCameraFile(const core::PinholeCamera &camera, const std::string &path);

} // namespace pm::io
