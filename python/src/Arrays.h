#pragma once
/*!
  \file Arrays.h
  NumPy arrays and ViSP's types for the Python module: images (H x W x 4 RGBA seen as they are,
  H x W x 3 BGR converted once), 4 x 4 poses in metres, and the checks that turn a wrong array into
  a Python exception (ValueError / TypeError) rather than a crash.
*/
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pmpy {

namespace py = pybind11;

//! The layouts track() takes: as ViSP holds an image (RGBA) and as OpenCV gives one (BGR).
enum class PixelLayout { Rgba, Bgr };

/*!
  Checks \e a is a C-contiguous uint8 array of H x W x 4 or H x W x 3 and says which; throws
  pybind11::type_error / value_error naming \e what ("left image") and what is wrong.
*/
PixelLayout checkImage(const py::array &a, const char *what);

/*!
  One camera's image as the tracker reads it, \e a checked by checkImage() (which gave \e layout): an
  RGBA array is seen where it lies (\e view points at the array's own buffer: no copy); a BGR array
  is converted once into \e converted (kept and reused: no allocation after the first frame of a
  size). Returns the image to read. Calls nothing of Python's: it may run with the GIL released.
*/
const vpImage<vpRGBa> &imageOf(const py::array &a, PixelLayout layout, vpImage<vpRGBa> &view, vpImage<vpRGBa> &converted);

//! A copy of \e I as an H x W x 4 RGBA uint8 array.
py::array_t<std::uint8_t> toArray(const vpImage<vpRGBa> &I);
//! A copy of \e I as an H x W x 4 RGBA uint8 image (the layout checked as checkImage()).
vpImage<vpRGBa> toImage(const py::array &a, const char *what);

//! \e M as a 4 x 4 float64 array.
py::array_t<double> toArray(const vpHomogeneousMatrix &M);
//! A 4 x 4 array as a vpHomogeneousMatrix; value_error naming \e what if it is not 4 x 4 or not a rigid transform.
vpHomogeneousMatrix toMatrix(const py::array_t<double, py::array::c_style | py::array::forcecast> &a, const char *what);

} // namespace pmpy
