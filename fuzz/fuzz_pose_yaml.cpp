// Fuzz target: a hand pose of a views folder (pm::io::readPoseYaml, vpPoseVector YAML).
#include "FuzzFile.h"
#include "pm/io/PoseFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::string path = pm::fuzz::writeScratch("pose_fPh_00.yaml", data, size);
  pm::fuzz::loadOrRefuse([&] { (void)pm::io::readPoseYaml(path); });
  return 0;
}
