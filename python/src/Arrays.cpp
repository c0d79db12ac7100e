#include "Arrays.h"

#include <cmath>
#include <cstring>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace pmpy {

PixelLayout checkImage(const py::array &a, const char *what)
{
  if (!a.dtype().is(py::dtype::of<std::uint8_t>()))
    throw py::type_error(std::string(what) + ": an array of uint8 is needed, not of " + std::string(py::str(a.dtype())));
  if (a.ndim() != 3 || (a.shape(2) != 3 && a.shape(2) != 4))
  {
    std::string shape;
    for (py::ssize_t i = 0; i < a.ndim(); ++i)
      shape += (i ? " x " : "") + std::to_string(a.shape(i));
    throw py::value_error(std::string(what) + ": an H x W x 3 (BGR) or H x W x 4 (RGBA) array is needed, not " + shape);
  }
  if (!(a.flags() & py::array::c_style))
    throw py::value_error(std::string(what) + ": a C-contiguous array is needed (numpy.ascontiguousarray() makes one)");
  if (a.shape(0) == 0 || a.shape(1) == 0)
    throw py::value_error(std::string(what) + ": an empty image");
  return a.shape(2) == 4 ? PixelLayout::Rgba : PixelLayout::Bgr;
}

const vpImage<vpRGBa> &imageOf(const py::array &a, PixelLayout layout, vpImage<vpRGBa> &view, vpImage<vpRGBa> &converted)
{
  const unsigned h = static_cast<unsigned>(a.shape(0)), w = static_cast<unsigned>(a.shape(1));
  if (layout == PixelLayout::Rgba) {
    // vpRGBa is four bytes R, G, B, A: the array's buffer is the bitmap. Only read by the tracker.
    view.init(reinterpret_cast<vpRGBa *>(const_cast<void *>(a.data())), h, w, false);
    return view;
  }
  if (converted.getHeight() != h || converted.getWidth() != w)
    converted.resize(h, w);
  const cv::Mat bgr(static_cast<int>(h), static_cast<int>(w), CV_8UC3, const_cast<void *>(a.data()));
  cv::Mat rgba(static_cast<int>(h), static_cast<int>(w), CV_8UC4, converted.bitmap);
  cv::cvtColor(bgr, rgba, cv::COLOR_BGR2RGBA);
  return converted;
}

py::array_t<std::uint8_t> toArray(const vpImage<vpRGBa> &I)
{
  py::array_t<std::uint8_t> a({static_cast<py::ssize_t>(I.getHeight()), static_cast<py::ssize_t>(I.getWidth()), py::ssize_t(4)});
  if (I.getSize() > 0)
    std::memcpy(a.mutable_data(), I.bitmap, static_cast<std::size_t>(I.getSize()) * 4);
  return a;
}

vpImage<vpRGBa> toImage(const py::array &a, const char *what)
{
  vpImage<vpRGBa> view, converted;
  const PixelLayout layout = checkImage(a, what);
  const vpImage<vpRGBa> &I = imageOf(a, layout, view, converted);
  if (layout == PixelLayout::Bgr)
    return converted;         // the conversion owns its pixels (moved out)
  return vpImage<vpRGBa>(I);  // a copy of the array's pixels
}

py::array_t<double> toArray(const vpHomogeneousMatrix &M)
{
  py::array_t<double> a({4, 4});
  auto r = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < 4; ++i)
    for (py::ssize_t j = 0; j < 4; ++j)
      r(i, j) = M[static_cast<unsigned>(i)][static_cast<unsigned>(j)];
  return a;
}

vpHomogeneousMatrix toMatrix(const py::array_t<double, py::array::c_style | py::array::forcecast> &a, const char *what)
{
  if (a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4)
    throw py::value_error(std::string(what) + ": a 4 x 4 array is needed");
  auto r = a.unchecked<2>();
  vpHomogeneousMatrix M;
  for (unsigned i = 0; i < 4; ++i)
    for (unsigned j = 0; j < 4; ++j) {
      if (!std::isfinite(r(i, j)))
        throw py::value_error(std::string(what) + ": a value that is not finite");
      M[i][j] = r(i, j);
    }
  if (!M.isAnHomogeneousMatrix(1e-6))
    throw py::value_error(std::string(what) + ": not a rigid transform (a rotation and a translation, last row 0 0 0 1)");
  return M;
}

} // namespace pmpy
