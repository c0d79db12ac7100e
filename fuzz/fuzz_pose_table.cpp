// Fuzz target: trajectory and ground-truth tables (pm::io::readPoseTable, keyed by step or frame).
#include "FuzzFile.h"
#include "pm/io/PoseTableFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::string path = pm::fuzz::writeScratch("poses.csv", data, size);
  for (const char *key : {"step", "frame"}) {
    pm::fuzz::loadOrRefuse([&] { (void)pm::io::readPoseTable(path, key); });
  }
  return 0;
}
