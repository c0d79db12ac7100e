// The usage example of modules/model/include/pm/model/AllAroundModelBuilder.h, a whole program (compiled, never linked).
#include <iostream>
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/io/ViewsFolder.h>
#include <pm/model/AllAroundModelBuilder.h>

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const std::vector<pm::model::PassView> pass = pm::io::loadViewsFolder("views", rig, 6); // at least 6 views
  pm::model::AllAroundParams params;
  params.viewpoints.count = 120; // a lighter model: half the viewpoints
  const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass, params);
  for (const std::string &why : b.leftOut)
    std::cout << "left out: " << why << "\n";
  pm::io::savePhotoModel(b.model, "model.json");
  std::cout << b.nViewsUsed << " of " << b.nViews << " views, hull " << b.hullVolumeCm3 << " cm3\n";
}
