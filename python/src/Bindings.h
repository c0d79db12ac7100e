#pragma once
/*!
  \file Bindings.h
  The parts of the Python module visp_photomodel, one function each (Module.cpp calls them in order):
  the rig and camera files, image files, the photo-model, the tracker, the lab.
*/
#include <pybind11/pybind11.h>

namespace pmpy {

void bindRig(pybind11::module_ &m);     //!< StereoRig, Camera, load_rig, read_camera_file, write_camera_file
void bindImages(pybind11::module_ &m);  //!< read_image, write_image
void bindModel(pybind11::module_ &m);   //!< PhotoModel, PassView, load_model, build_model, build_model_from_folder
void bindTracker(pybind11::module_ &m); //!< Tracker, TrackResult
void bindLab(pybind11::module_ &lab);   //!< the submodule lab: render_pair, make_model, ServoLoop, ServoFrame

} // namespace pmpy
