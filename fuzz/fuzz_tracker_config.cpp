// Fuzz target: the tracker's configuration file (pm::tracker::loadTrackerConfig).
#include "FuzzFile.h"
#include "pm/tracker/TrackerConfigFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  const std::string path = pm::fuzz::writeScratch("tracker.json", data, size);
  pm::fuzz::loadOrRefuse([&] { (void)pm::tracker::loadTrackerConfig(path); });
  return 0;
}
