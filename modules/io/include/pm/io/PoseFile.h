#pragma once
/*!
  \file PoseFile.h
  A pose as ViSP writes a vpPoseVector to YAML (vpPoseVector::saveYAML, the format of ViSP's
  hand-eye calibration tutorials): translation in metres, then the theta-u rotation in radians,
  one value per line of a 6x1 array.

      rows: 6
      cols: 1
      data:
        - [0.1]
        - [0.0]
        - [0.5]
        - [0.0]
        - [0.0]
        - [1.5707963]

  ViSP's own reader (vpArray2D::loadYAML) checks neither the sizes nor the values; this one does
  (yaml-cpp), and refuses anything else with an error naming the file.

  \code
      const vpHomogeneousMatrix fMh = pm::io::readPoseYaml("views/pose_fPh_00.yaml");
      pm::io::writePoseYaml(fMh, "copy.yaml");
  \endcode
*/
#include <string>

#include <visp3/core/vpHomogeneousMatrix.h>

namespace pm::io {

//! Reads a vpPoseVector YAML file. Throws pm::core::Error for a missing file or anything that is not a finite 6x1 pose.
vpHomogeneousMatrix readPoseYaml(const std::string &path);
//! The same from the file's text (\e source names it in messages).
vpHomogeneousMatrix parsePoseYaml(const std::string &text, const std::string &source);
//! The text vpPoseVector::saveYAML writes for \e M (full double precision).
std::string poseYamlText(const vpHomogeneousMatrix &M);
//! Writes \e M through a temporary file and a rename. Throws pm::core::Error.
void writePoseYaml(const vpHomogeneousMatrix &M, const std::string &path);

} // namespace pm::io
