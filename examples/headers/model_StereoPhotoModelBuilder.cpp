// The usage example of modules/model/include/pm/model/StereoPhotoModelBuilder.h, a whole program (compiled, never linked).
#include <iostream>
#include <pm/io/ImageFile.h>
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/model/StereoPhotoModelBuilder.h>

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  // From one hand pose: the backdrop alone, then the target on it.
  const vpImage<vpRGBa> bgL = pm::io::readColorImage("background_left.png");
  const vpImage<vpRGBa> bgR = pm::io::readColorImage("background_right.png");
  const vpImage<vpRGBa> L = pm::io::readColorImage("left.png");
  const vpImage<vpRGBa> R = pm::io::readColorImage("right.png");
  pm::model::StereoModelParams params;
  params.backdropMm = 700; // a plain backdrop, too smooth to match: its depth given (mm)
  const pm::model::StereoPhotoModelBuild b = pm::model::buildStereoPhotoModel(rig, bgL, bgR, L, R, params);
  pm::io::savePhotoModel(b.model, "model.json");
  std::cout << b.model.inner.size() << " S_in points, " << b.model.nInDropped << " dropped\n";
}
