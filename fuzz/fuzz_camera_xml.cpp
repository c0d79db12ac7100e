// Fuzz target: a camera intrinsics file in ViSP's XML (pm::io::readCameraXml).
#include "FuzzFile.h"
#include "pm/io/CameraXml.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::string path = pm::fuzz::writeScratch("cameras.xml", data, size);
  pm::fuzz::loadOrRefuse([&] { (void)pm::io::readCameraXml(path, "left", 640, 480); });
  return 0;
}
