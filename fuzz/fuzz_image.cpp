// Fuzz target: image decoding (pm::io::readColorImage: our PNG, JPEG and PGM/PPM readers).
#include "FuzzFile.h"
#include "pm/io/ImageFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  // No extension: the reader goes by the file's magic bytes, as for any file a user names.
  const std::string path = pm::fuzz::writeScratch("image", data, size);
  pm::fuzz::loadOrRefuse([&] { (void)pm::io::readColorImage(path); });
  return 0;
}
