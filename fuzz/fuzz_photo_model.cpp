// Fuzz target: the photo-model file (pm::io::loadPhotoModel).
#include "FuzzFile.h"
#include "pm/io/PhotoModelFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::string path = pm::fuzz::writeScratch("model.json", data, size);
  pm::fuzz::loadOrRefuse([&] { (void)pm::io::loadPhotoModel(path); });
  return 0;
}
