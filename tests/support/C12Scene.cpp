#include "C12Scene.h"

#include "TestSupport.h"
#include "pm/io/RigFile.h"
#include "pm/sim/TargetCatalog.h"

namespace pm::test {

C12Scene::C12Scene()
    : rig(io::loadRig(dataPath("rig/pa10_stereo.json"))), scene(sim::makeTarget("C12", 0.5)),
      sm(sim::makeSimulatedPhotoModel(scene, rig.left.cam, 640, 480, 500)), hMo(core::toHomogeneousMatrix({20, -10, 520, 0.03, -0.02, 0.05})),
      im(scene.renderStereo(rig, hMo, 0)), truth(sm.truth(hMo))
{
}

const C12Scene &c12()
{
  static const C12Scene s;
  return s;
}

} // namespace pm::test
