#include "Arrays.h"
#include "Bindings.h"
#include "pm/io/ImageFile.h"

namespace pmpy {

void bindImages(py::module_ &m)
{
  m.def(
      "read_image", [](const std::string &path) { return toArray(pm::io::readColorImage(path)); }, py::arg("path"),
      "Reads a PNG, JPEG or PPM file as the programs do: an H x W x 4 RGBA uint8 array. Raises Error naming the file.");
  m.def(
      "write_image", [](const py::array &image, const std::string &path) { pm::io::writeImage(toImage(image, "image"), path); },
      py::arg("image"), py::arg("path"),
      "Writes an H x W x 4 RGBA or H x W x 3 BGR uint8 array as the programs do (PNG, JPEG or PPM by the name's extension).");
}

} // namespace pmpy
