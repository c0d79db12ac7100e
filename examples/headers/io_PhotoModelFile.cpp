// The usage example of modules/io/include/pm/io/PhotoModelFile.h, a whole program (compiled, never linked).
#include <iostream>

#include "pm/io/PhotoModelFile.h"

int main()
{
  const pm::core::PhotoModel m = pm::io::loadPhotoModel("model.json");
  std::cout << m.inner.size() << " S_in and " << m.outer.size() << " S_out points, " << m.views.size()
            << " further views, photo distance " << m.distanceMm << " mm" << std::endl;
  pm::io::savePhotoModel(m, "copy.json");
}
