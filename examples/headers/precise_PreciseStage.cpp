// The usage example of modules/precise/include/pm/precise/PreciseStage.h, a whole program (compiled, never linked).
#include <iostream>
#include <pm/io/ImageFile.h>
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/precise/PreciseStage.h>

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const pm::core::PhotoModel model = pm::io::loadPhotoModel("model.json"); // an all-around model
  pm::precise::PreciseStage precise(rig, model);
  const vpImage<vpRGBa> IL = pm::io::readColorImage("left.png"), IR = pm::io::readColorImage("right.png");
  precise.setImages({IL, IR});            // one image per camera of the rig
  pm::core::Phi phi;                      // a pose within a few degrees and millimetres
  phi.z = 500;
  const pm::precise::PreciseResult r = precise.refine(phi);
  std::cout << r.phi.toString() << " from " << r.totalLines() << " lines\n";
}
