// Fuzz target: image decoding (pm::io::readColorImage: our PNG and JPEG readers, PNM through ViSP).
#include "FuzzFile.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  // No extension: the reader goes by the file's magic bytes, as for any file a user names.
  const std::string path = pm::fuzz::writeScratch("image", data, size);
  try {
    (void)pm::io::readColorImage(path);
  } catch (const pm::Error &) {
  }
  return 0;
}
