// The usage example of modules/model/include/pm/model/PhotoModelBuilder.h, a whole program (compiled, never linked).
#include <iostream>
#include <pm/io/ImageFile.h>
#include <pm/io/PhotoModelFile.h>
#include <pm/model/PhotoModelBuilder.h>
#include <visp3/core/vpCameraParameters.h>

int main()
{
  const vpImage<vpRGBa> background = pm::io::readColorImage("background.png");
  const vpImage<vpRGBa> photo = pm::io::readColorImage("target.png"); // same camera, same place
  const vpCameraParameters cam(800, 800, 320, 240);                   // px, py, u0, v0
  pm::model::PhotoModelParams params;
  params.stepPx = 6; // a denser S_in
  const pm::model::PhotoModelBuild b = pm::model::buildPhotoModel(background, photo, cam, 500, params); // 500 mm
  pm::io::savePhotoModel(b.model, "model.json");
  std::cout << b.model.inner.size() << " S_in, " << b.model.outer.size() << " S_out points\n";
}
