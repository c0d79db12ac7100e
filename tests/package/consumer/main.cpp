// A ViSP program using the installed visp-photomodel: loads the installed rig and renders a target.
#include <iostream>

#include <pm/core/Pose.h>
#include <pm/io/RigFile.h>
#include <pm/sim/Scene.h>
#include <pm/sim/TargetCatalog.h>

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig(VISP_PHOTOMODEL_RIG);
  const pm::sim::Scene scene(pm::sim::makeTarget("C04", 1.0));
  const auto im = scene.renderStereo(rig, pm::core::toHomogeneousMatrix({0, 0, 500, 0, 0, 0}), 0);
  std::cout << "rendered " << im.left.getWidth() << "x" << im.left.getHeight() << " with baseline "
            << rig.baseline() * 1e3 << " mm" << std::endl;
  return im.left.getWidth() == 640 ? 0 : 1;
}
