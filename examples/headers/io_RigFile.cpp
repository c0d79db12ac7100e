// The usage example of modules/io/include/pm/io/RigFile.h, a whole program (compiled, never linked).
#include <iostream>

#include "pm/io/RigFile.h"

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  std::cout << "baseline " << rig.baseline() * 1e3 << " mm, cLMcR:\n" << rig.cLMcR() << std::endl;
  const vpHomogeneousMatrix cLMh = rig.left.cMh(); // the hand frame in the left camera
  std::cout << rig.left.name << " " << rig.left.width << "x" << rig.left.height << ", cMh:\n" << cLMh << std::endl;
}
