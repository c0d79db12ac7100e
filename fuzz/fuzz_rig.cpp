// Fuzz target: the rig file (pm::io::loadCameraRig, any number of cameras, and pm::io::loadRig, a stereo one), its intrinsics file next to it being valid.
#include "FuzzFile.h"
#include "pm/io/CameraXml.h"
#include "pm/io/RigFile.h"

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
  // The intrinsics the seed rigs name: a valid file, so that the fuzzer gets past it.
  const std::string xml = (pm::fuzz::scratchDir() / "rig_cameras.xml").string();
  const vpCameraParameters cam(800, 800, 320, 240);
  pm::io::writeCameraXml(cam, xml, "left", 640, 480);
  pm::io::writeCameraXml(cam, xml, "right", 640, 480);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::string path = pm::fuzz::writeScratch("rig.json", data, size);
  pm::fuzz::loadOrRefuse([&] { (void)pm::io::loadCameraRig(path); });
  pm::fuzz::loadOrRefuse([&] { (void)pm::io::loadRig(path); });
  return 0;
}
