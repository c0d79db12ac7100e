#include "pm/io/ImageFile.h"

#include <filesystem>

#include <visp3/core/vpException.h>
#include <visp3/io/vpImageIo.h>

#include "pm/core/Error.h"

namespace pm::io {

vpImage<vpRGBa> readColorImage(const std::string &path)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error("image '" + path + "' does not exist or is not a file");
  vpImage<vpRGBa> I;
  try {
    vpImageIo::read(I, path);
  } catch (const vpException &e) {
    throw Error("cannot read image '" + path + "': not a readable PNG/JPEG/PNM image (" + e.getStringMessage() + ")");
  } catch (const std::exception &e) {
    throw Error("cannot read image '" + path + "': " + e.what());
  }
  if (I.getSize() == 0)
    throw Error("cannot read image '" + path + "': it is empty or corrupt");
  return I;
}

namespace {
template <typename T> void writeAny(const vpImage<T> &I, const std::string &path)
{
  try {
    vpImageIo::write(I, path);
  } catch (const vpException &e) {
    throw Error("cannot write image '" + path + "': " + e.getStringMessage());
  }
}
} // namespace

void writeImage(const vpImage<vpRGBa> &I, const std::string &path) { writeAny(I, path); }
void writeImage(const vpImage<unsigned char> &I, const std::string &path) { writeAny(I, path); }

} // namespace pm::io
