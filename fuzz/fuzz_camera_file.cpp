// Fuzz target: one camera's intrinsics and lens in any format pm::io::readCameraFile knows
// (ViSP XML, OpenCV FileStorage YAML/XML, ROS camera_info YAML).
#include "FuzzFile.h"
#include "pm/io/CameraFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::string path = pm::fuzz::writeScratch("camera.yml", data, size);
  pm::fuzz::loadOrRefuse([&] { (void)pm::io::readCameraFile(path, "left", 640, 480); });
  return 0;
}
